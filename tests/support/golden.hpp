// tests/support/golden.hpp — when a test rewrites its golden files instead of comparing with them.
#pragma once

#include <cstdlib>
#include <cstring>
#include <filesystem>

namespace bezel::test {

// True only when BEZEL_UPDATE_GOLDEN is exactly "1" (after a deliberate change; say why in the
// commit). Unset, "0" or any other value compares with the goldens. A test in update mode writes
// the golden and compares nothing with it: a file compared with itself proves nothing.
inline bool update_golden() {
    const char* v = std::getenv("BEZEL_UPDATE_GOLDEN");
    return v != nullptr && std::strcmp(v, "1") == 0;
}

// Copies a freshly made output over its golden (update mode).
inline void replace_golden(const std::filesystem::path& made, const std::filesystem::path& golden) {
    std::filesystem::copy_file(made, golden, std::filesystem::copy_options::overwrite_existing);
}

}  // namespace bezel::test
