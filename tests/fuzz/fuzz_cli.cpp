// fuzz_cli — the bezel command line, in-process: the input is split into arguments (at NUL and
// newline bytes) and handed to bezel::cli::run_cli. Properties: no crash, no uncaught exception,
// no sanitizer report, every run bounded (libFuzzer's -timeout), and the exit code is 0, 1 or 2.
// `bench` is left out (see below).
//
// Containment: the run happens in a private scratch directory that is emptied after every input;
// an argument containing '/' is dropped, so nothing outside it is read or written; "@font" and
// "@edge" stand for the bundled DejaVu Sans and the edge-case font. stdout and stderr go to a
// null stream (fd 2 itself stays open for the sanitizers' reports).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <streambuf>
#include <string>
#include <vector>

#include "fuzz_reader.hpp"

namespace bezel::cli {
int run_cli(int argc, char** argv);  // tools/bezel/main.cpp
}

namespace {

namespace fs = std::filesystem;

constexpr std::size_t kMaxArgs = 24;
constexpr std::size_t kMaxArgBytes = 256;

class NullBuffer : public std::streambuf {
protected:
    int overflow(int c) override { return traits_type::not_eof(c); }
    std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
};

fs::path g_scratch;
fs::path g_home;  // libFuzzer's own working directory: its corpus paths are relative to it

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    std::string tmpl = (access("/dev/shm", W_OK) == 0 ? std::string("/dev/shm") : fs::temp_directory_path().string()) +
                       "/bezel-fuzz-cli-XXXXXX";
    if (!mkdtemp(tmpl.data())) std::abort();
    g_scratch = tmpl;
    g_home = fs::current_path();
    // Never destroyed: the streams flush their buffer at exit, after function statics are gone.
    static NullBuffer* const null = new NullBuffer;
    std::cout.rdbuf(null);
    std::cerr.rdbuf(null);
    std::atexit([] {
        std::error_code ec;
        fs::remove_all(g_scratch, ec);
    });
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::vector<std::string> args{"bezel"};
    std::string current;
    auto finish = [&] {
        if (current.find('/') == std::string::npos && args.size() < kMaxArgs) {
            if (current == "@font") current = BEZEL_FONTS_DIR "/dejavu-sans/DejaVuSans.ttf";
            else if (current == "@edge") current = BEZEL_FONTS_DIR "/edge-cases/EdgeCases.ttf";
            args.push_back(current);
        }
        current.clear();
    };
    for (std::size_t i = 0; i < size; ++i) {
        const char c = static_cast<char>(data[i]);
        if (c == '\0' || c == '\n') finish();
        else if (current.size() < kMaxArgBytes) current += c;
    }
    if (!current.empty()) finish();

    // `bench` times every glyph of a font at up to 64 sizes: seconds in a Release build, minutes
    // under the sanitizers, by design rather than by a hang (a fuzz_cli "timeout" of `bezel
    // bench` alone). Its arguments are tested in bench_cli_test; here it is left out.
    if (args.size() > 1 && args[1] == "bench") return 0;

    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    std::cout.clear();
    std::cerr.clear();
    if (chdir(g_scratch.c_str()) != 0) std::abort();
    const int code = bezel::cli::run_cli(static_cast<int>(args.size()), argv.data());
    if (chdir(g_home.c_str()) != 0) std::abort();
    BEZEL_FUZZ_CHECK(code == 0 || code == 1 || code == 2);

    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(g_scratch, ec)) fs::remove_all(entry.path(), ec);
    return 0;
}
