// bench_render_bench: whole-process `bezel render` of a page of text against HarfBuzz's hb-view on
// the same font, text and size. The page (tools/bench/render_page.txt, ~8.5 KB of our own prose)
// is pre-wrapped at <= 81 columns, because hb-view does not wrap; both tools therefore break lines
// at the same places and draw the same glyphs at 16 px with DejaVu Sans and a 16 px margin, and
// both write a PNG. Reported: the minimum wall time of N runs of each (the figure least disturbed
// by other load), run alternately, and the ratio hb-view / bezel.
//
//   bench_render_bench [RUNS]      (default 15)
#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

extern char** environ;

namespace {

namespace fs = std::filesystem;

// Runs argv to completion with stdout/stderr to /dev/null; returns seconds, or -1 on failure.
double run_once(const std::vector<std::string>& args) {
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    auto start = std::chrono::steady_clock::now();
    pid_t pid;
    int rc = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (rc != 0) return -1;
    int status = 0;
    waitpid(pid, &status, 0);
    double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? s : -1;
}

std::uintmax_t file_size(const std::string& f) {
    std::error_code ec;
    auto n = fs::file_size(f, ec);
    return ec ? 0 : n;
}

}  // namespace

int main(int argc, char** argv) {
    const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 15;
    // build/<tree>/tools/bench/bench_render_bench → build/<tree>/tools/bezel/bezel
    const fs::path self = fs::read_symlink("/proc/self/exe");
    const std::string bezel = (self.parent_path().parent_path() / "bezel" / "bezel").string();
    const std::string hb_view = "/usr/bin/hb-view";
    const std::string font = BEZEL_FONTS_DIR "/dejavu-sans/DejaVuSans.ttf";
    const std::string text = BEZEL_FONTS_DIR "/../tools/bench/render_page.txt";
    const fs::path tmp = fs::temp_directory_path() / ("bezel_render_bench_" + std::to_string(getpid()));
    fs::create_directories(tmp);
    const std::string out_bezel = (tmp / "bezel.png").string(), out_hb = (tmp / "hb-view.png").string();

    if (access(bezel.c_str(), X_OK) != 0) {
        std::printf("render_bench: %s not built (BEZEL_BUILD_TOOLS=ON needed)\n", bezel.c_str());
        return 1;
    }
    const std::vector<std::string> bezel_cmd = {bezel, "render", font, "--text-file", text,
                                                "--font-size", "16", "--margin", "16", "-o", out_bezel};
    const std::vector<std::string> hb_cmd = {hb_view, font, "--text-file=" + text, "--font-size=16",
                                             "--margin=16", "--output-format=png",
                                             "--output-file=" + out_hb};
    const bool have_hb = access(hb_view.c_str(), X_OK) == 0;

    double best_bezel = 1e9, best_hb = 1e9;
    for (int i = 0; i < runs; ++i) {
        double b = run_once(bezel_cmd);
        if (b < 0) {
            std::printf("render_bench: bezel render failed\n");
            return 1;
        }
        best_bezel = std::min(best_bezel, b);
        if (have_hb) {
            double h = run_once(hb_cmd);
            if (h < 0) {
                std::printf("render_bench: hb-view failed\n");
                return 1;
            }
            best_hb = std::min(best_hb, h);
        }
    }
    std::printf("page: %s (%ju bytes), DejaVu Sans 16 px, min of %d runs, whole process\n",
                text.c_str(), file_size(text), runs);
    std::printf("  bezel render  %8.2f ms   PNG %ju bytes\n", best_bezel * 1e3, file_size(out_bezel));
    if (have_hb) {
        std::printf("  hb-view       %8.2f ms   PNG %ju bytes\n", best_hb * 1e3, file_size(out_hb));
        std::printf("  ratio hb-view / bezel: %.2fx\n", best_hb / best_bezel);
    } else {
        std::printf("  hb-view not installed (Debian libharfbuzz-bin): no comparison\n");
    }
    fs::remove_all(tmp);
    return 0;
}
