// tests/fuzz/fuzz_font_file.hpp — a fuzz input as a font file: Font opens files only, so each input
// is written to one file per process and target, in /dev/shm when it is writable (no disk traffic
// at tens of thousands of inputs a minute), else $TMPDIR or /tmp.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace bezel::fuzz {

// The scratch file of this process for target `name` ("font", "color-font").
inline std::string scratch_font_file(const std::string& name) {
    const char* dir = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : std::getenv("TMPDIR");
    return std::string(dir ? dir : "/tmp") + "/bezel-fuzz-" + name + "-" +
           std::to_string(getpid()) + ".bin";
}

// Writes the input to `file` (replacing it); false when the file cannot be written whole.
inline bool write_font_file(const std::string& file, const std::uint8_t* data, std::size_t size) {
    std::FILE* f = std::fopen(file.c_str(), "wb");
    if (!f) return false;
    const bool ok = std::fwrite(data, 1, size, f) == size;
    return std::fclose(f) == 0 && ok;
}

}  // namespace bezel::fuzz
