// bench_render_bench: whole-process `bezel render` of a page of text against HarfBuzz's hb-view on
// the same font, text and size. The page (tools/bench/render_page.txt, ~8.5 KB of our own prose)
// is pre-wrapped at <= 81 columns, because hb-view does not wrap; both tools therefore break lines
// at the same places and draw the same glyphs at 16 px with DejaVu Sans and a 16 px margin, and
// both write a PNG. Reported: the minimum wall time of N runs of each (the figure least disturbed
// by other load), run alternately, and the ratio hb-view / bezel; the same for CPU time (user +
// system, from wait4), which a loaded machine disturbs less than wall time.
//
//   bench_render_bench [RUNS]      (default 15)
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
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

struct Timing {
    double wall = -1, cpu = -1;   // seconds; -1 when the run failed
};

// Runs argv to completion with stdout/stderr to /dev/null.
Timing run_once(const std::vector<std::string>& args) {
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
    if (rc != 0) return {};
    int status = 0;
    rusage usage{};
    wait4(pid, &status, 0, &usage);
    double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return {};
    auto seconds = [](timeval t) { return static_cast<double>(t.tv_sec) + t.tv_usec * 1e-6; };
    return {s, seconds(usage.ru_utime) + seconds(usage.ru_stime)};
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

    Timing best_bezel{1e9, 1e9}, best_hb{1e9, 1e9};
    auto keep_min = [](Timing& best, Timing t) {
        best.wall = std::min(best.wall, t.wall);
        best.cpu = std::min(best.cpu, t.cpu);
    };
    for (int i = 0; i < runs; ++i) {
        Timing b = run_once(bezel_cmd);
        if (b.wall < 0) {
            std::printf("render_bench: bezel render failed\n");
            return 1;
        }
        keep_min(best_bezel, b);
        if (have_hb) {
            Timing h = run_once(hb_cmd);
            if (h.wall < 0) {
                std::printf("render_bench: hb-view failed\n");
                return 1;
            }
            keep_min(best_hb, h);
        }
    }
    std::printf("page: %s (%ju bytes), DejaVu Sans 16 px, min of %d runs, whole process\n",
                text.c_str(), file_size(text), runs);
    std::printf("  bezel render  wall %8.2f ms  cpu %8.2f ms   PNG %ju bytes\n",
                best_bezel.wall * 1e3, best_bezel.cpu * 1e3, file_size(out_bezel));
    if (have_hb) {
        std::printf("  hb-view       wall %8.2f ms  cpu %8.2f ms   PNG %ju bytes\n",
                    best_hb.wall * 1e3, best_hb.cpu * 1e3, file_size(out_hb));
        std::printf("  ratio hb-view / bezel: wall %.2fx, cpu %.2fx\n", best_hb.wall / best_bezel.wall,
                    best_hb.cpu / best_bezel.cpu);
    } else {
        std::printf("  hb-view not installed (Debian libharfbuzz-bin): no comparison\n");
    }
    fs::remove_all(tmp);
    return 0;
}
