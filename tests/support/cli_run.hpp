// tests/support/cli_run.hpp — running the `bezel` binary from end-to-end tests.
//
// Every CLI test needs the same three things: a scratch directory that disappears afterwards, a
// way to run the binary with an argv (no shell, so arguments need no quoting) and capture its
// exit code, stdout and stderr, and a way to read a file back. They live here once.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace bezel::test {

struct CliRun {
    int exit_code = -1;   // 128 + signal number if the process was killed by a signal
    std::string out, err;
};

// Runs `exe args…` with the working directory `cwd`, stdin from /dev/null, stdout and stderr
// captured through files in `cwd` (removed afterwards), the environment this process's plus `env`
// (NAME=VALUE entries, each replacing a variable of that name). Never goes through a shell.
CliRun run_program(const std::string& exe, const std::vector<std::string>& args,
                   const std::filesystem::path& cwd, const std::vector<std::string>& env = {});

// Splits a command line written as in a POSIX shell, for tests that read better that way:
// words separated by spaces, '…' quotes a word verbatim (no escapes, no double quotes).
std::vector<std::string> split_args(const std::string& line);

// The whole content of `file` ("" if it cannot be read).
std::string slurp(const std::filesystem::path& file);

// A fresh directory under the system's temp directory, removed with everything in it on
// destruction. `prefix` names it for whoever finds a leftover one.
class TempDir {
public:
    explicit TempDir(const std::string& prefix = "bezel-test");
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const std::filesystem::path& path() const { return path_; }
    // Names other than the capture files that exist in the directory (sorted): for checking that
    // a failing command left no output or temporary file behind.
    std::vector<std::string> entries() const;

private:
    std::filesystem::path path_;
};

#ifdef BEZEL_CLI_PATH
// The CLI binary; tests/CMakeLists.txt defines BEZEL_CLI_PATH for *cli* tests.
inline std::string cli_path() { return BEZEL_CLI_PATH; }
// run_program of the bezel binary.
// `env`: NAME=VALUE entries added to (or replacing in) the test's environment.
inline CliRun run_bezel(const std::vector<std::string>& args, const std::filesystem::path& cwd,
                        const std::vector<std::string>& env = {}) {
    return run_program(cli_path(), args, cwd, env);
}
#endif

}  // namespace bezel::test
