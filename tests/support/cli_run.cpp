#include "cli_run.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <system_error>

namespace fs = std::filesystem;

extern char** environ;  // POSIX: the process environment, for posix_spawnp

namespace bezel::test {

namespace {
// Capture file names, hidden so entries() can leave them out.
constexpr const char* kOut = ".bezel-test-stdout";
constexpr const char* kErr = ".bezel-test-stderr";

// The words a cross build runs its target programs through (CMAKE_CROSSCOMPILING_EMULATOR,
// say "qemu-aarch64 -L /usr/aarch64-linux-gnu", separated by spaces), or none.
std::vector<std::string> emulator_words() {
    std::vector<std::string> words;
#ifdef BEZEL_TEST_EMULATOR
    std::istringstream in(BEZEL_TEST_EMULATOR);
    for (std::string w; in >> w;) words.push_back(w);
#endif
    return words;
}
}  // namespace

// posix_spawn rather than fork + exec: the test process may have threads, and under qemu-user a
// forked child of a dynamically linked program never reaches exec (qemu 7.2 spins in it), where
// posix_spawn's clone runs.
CliRun run_program(const std::string& exe, const std::vector<std::string>& args,
                   const fs::path& cwd, const std::vector<std::string>& env) {
    const fs::path out_file = fs::absolute(cwd / kOut), err_file = fs::absolute(cwd / kErr);
    CliRun r;
    std::vector<std::string> words = emulator_words();
    words.push_back(exe);
    words.insert(words.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);

    posix_spawn_file_actions_t actions;
    if (::posix_spawn_file_actions_init(&actions) != 0) return r;
    const int mode = O_WRONLY | O_CREAT | O_TRUNC;
    const bool ready =
        ::posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0) == 0 &&
        ::posix_spawn_file_actions_addopen(&actions, 1, out_file.c_str(), mode, 0600) == 0 &&
        ::posix_spawn_file_actions_addopen(&actions, 2, err_file.c_str(), mode, 0600) == 0 &&
        ::posix_spawn_file_actions_addchdir_np(&actions, cwd.c_str()) == 0;
    // The environment: this process's, with `env`'s NAME=VALUE entries added or replacing.
    std::vector<std::string> variables = env;
    for (char** e = environ; *e != nullptr; ++e) {
        const std::string entry = *e;
        const std::string name = entry.substr(0, entry.find('=') + 1);
        bool replaced = false;
        for (const std::string& v : env) replaced |= v.compare(0, name.size(), name) == 0;
        if (!replaced) variables.push_back(entry);
    }
    std::vector<char*> envp;
    for (std::string& v : variables) envp.push_back(v.data());
    envp.push_back(nullptr);
    pid_t pid = -1;
    const int spawned =
        ready ? ::posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), envp.data()) : -1;
    ::posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) {
        r.exit_code = 127;  // what a shell reports for a program it cannot start
        r.err = "cannot start " + words.front() + ": " +
                (spawned > 0 ? std::system_category().message(spawned) : "file actions failed");
        return r;
    }
    int status = 0;
    if (::waitpid(pid, &status, 0) != pid) return r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.out = slurp(out_file);
    r.err = slurp(err_file);
    std::error_code ec;
    fs::remove(out_file, ec);
    fs::remove(err_file, ec);
    return r;
}

std::vector<std::string> split_args(const std::string& line) {
    std::vector<std::string> words;
    std::string word;
    bool in_word = false, quoted = false;
    for (char c : line) {
        if (quoted) {
            if (c == '\'') quoted = false;
            else word += c;
        } else if (c == '\'') {
            quoted = in_word = true;
        } else if (c == ' ') {
            if (in_word) words.push_back(word);
            word.clear();
            in_word = false;
        } else {
            word += c;
            in_word = true;
        }
    }
    if (in_word) words.push_back(word);
    return words;
}

std::string slurp(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

TempDir::TempDir(const std::string& prefix) {
    std::string tmpl = (fs::temp_directory_path() / (prefix + "-XXXXXX")).string();
    if (::mkdtemp(tmpl.data()) == nullptr) std::abort();  // a test machine without /tmp
    path_ = tmpl;
}

TempDir::~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
}

std::vector<std::string> TempDir::entries() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(path_)) {
        std::string name = e.path().filename().string();
        if (name != kOut && name != kErr) names.push_back(name);
    }
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace bezel::test
