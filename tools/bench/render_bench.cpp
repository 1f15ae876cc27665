// bench_render_bench: whole-process `bezel render` against HarfBuzz's hb-view on the same font,
// text and size, both writing a PNG: start-up (one letter), a paragraph (the page's first eight
// lines) and a page (tools/bench/render_page.txt, ~8.5 KB of our own prose, pre-wrapped at <= 81
// columns because hb-view does not wrap, so both tools break lines at the same places), all in
// DejaVu Sans at 16 px with a 16 px margin. The page is also run at each --compression level,
// since bezel's default trades file size for time where hb-view deflates with zlib's default
// level (the sizes are printed beside the times). The runs of all commands are interleaved
// (run i of each, then run i + 1), so a change in the machine's load hits them alike; reported:
// the median wall time and the median CPU time (user + system, from wait4, which a loaded
// machine disturbs less than wall time) of each, and the ratios hb-view / bezel.
//
//   bench_render_bench [RUNS]      (default 21)
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
#include <utility>
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

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The first `lines` lines of `file` (without the last newline), "" if it cannot be read.
std::string first_lines(const std::string& file, int lines) {
    std::FILE* f = std::fopen(file.c_str(), "rb");
    if (!f) return "";
    std::string text;
    for (int c; (c = std::fgetc(f)) != EOF;) {
        if (c == '\n' && --lines == 0) break;
        text.push_back(static_cast<char>(c));
    }
    std::fclose(f);
    return text;
}

struct Job {
    std::string name;            // what the row says
    std::vector<std::string> argv;
    std::string output;          // the PNG it writes
    std::vector<double> wall, cpu;
};

}  // namespace

int main(int argc, char** argv) {
    const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 21;
    // build/<tree>/tools/bench/bench_render_bench → build/<tree>/tools/bezel/bezel
    const fs::path self = fs::read_symlink("/proc/self/exe");
    const std::string bezel = (self.parent_path().parent_path() / "bezel" / "bezel").string();
    const std::string hb_view = "/usr/bin/hb-view";
    const std::string font = BEZEL_FONTS_DIR "/dejavu-sans/DejaVuSans.ttf";
    const std::string page = BEZEL_FONTS_DIR "/../tools/bench/render_page.txt";
    const fs::path tmp = fs::temp_directory_path() / ("bezel_render_bench_" + std::to_string(getpid()));
    fs::create_directories(tmp);

    if (access(bezel.c_str(), X_OK) != 0) {
        std::printf("render_bench: %s not built (BEZEL_BUILD_TOOLS=ON needed)\n", bezel.c_str());
        return 1;
    }
    const bool have_hb = access(hb_view.c_str(), X_OK) == 0;
    const std::string paragraph = first_lines(page, 8);
    if (paragraph.empty()) {
        std::printf("render_bench: cannot read %s\n", page.c_str());
        return 1;
    }

    // Each case: bezel's argv (text options) and hb-view's; the page also at every level.
    struct Case {
        std::string name;
        std::vector<std::string> bezel_text, hb_text;
        std::vector<std::string> levels;   // --compression values ("" = bezel's default)
    };
    const std::vector<Case> cases = {
        {"letter", {"--text", "A"}, {"--text=A"}, {""}},
        {"paragraph", {"--text", paragraph}, {"--text=" + paragraph}, {""}},
        {"page", {"--text-file", page}, {"--text-file=" + page}, {"", "fast", "small"}},
    };
    std::vector<std::pair<std::size_t, std::size_t>> rows;   // (bezel job, hb-view job) per row
    std::vector<Job> jobs;
    for (const Case& c : cases) {
        std::size_t hb_job = 0;
        if (have_hb) {
            Job hb{"hb-view", {hb_view, font}, (tmp / (c.name + "-hb.png")).string(), {}, {}};
            for (const std::string& a : c.hb_text) hb.argv.push_back(a);
            for (const std::string& a : {std::string("--font-size=16"), std::string("--margin=16"),
                                         std::string("--output-format=png"),
                                         "--output-file=" + hb.output})
                hb.argv.push_back(a);
            hb_job = jobs.size();
            jobs.push_back(std::move(hb));
        }
        for (const std::string& level : c.levels) {
            Job b{level.empty() ? "bezel" : "bezel --compression " + level,
                  {bezel, "render", font},
                  (tmp / (c.name + "-" + (level.empty() ? "default" : level) + ".png")).string(),
                  {},
                  {}};
            for (const std::string& a : c.bezel_text) b.argv.push_back(a);
            for (const char* a : {"--font-size", "16", "--margin", "16", "-o"})
                b.argv.push_back(a);
            b.argv.push_back(b.output);
            if (!level.empty()) {
                b.argv.push_back("--compression");
                b.argv.push_back(level);
            }
            rows.emplace_back(jobs.size(), hb_job);
            jobs.push_back(std::move(b));
        }
    }

    for (int i = 0; i < runs; ++i)
        for (Job& j : jobs) {
            Timing t = run_once(j.argv);
            if (t.wall < 0) {
                std::printf("render_bench: %s failed: %s ...\n", j.name.c_str(), j.argv[0].c_str());
                return 1;
            }
            j.wall.push_back(t.wall);
            j.cpu.push_back(t.cpu);
        }

    std::printf("DejaVu Sans 16 px, margin 16; medians of %d interleaved runs, whole process\n",
                runs);
    std::printf("%-10s %-28s %9s %9s %9s   %s\n", "case", "command", "wall ms", "cpu ms", "PNG B",
                "hb-view / bezel (wall, cpu)");
    std::size_t row = 0;
    for (const Case& c : cases) {
        if (have_hb) {
            const Job& hb = jobs[rows[row].second];
            std::printf("%-10s %-28s %9.2f %9.2f %9ju\n", c.name.c_str(), hb.name.c_str(),
                        median(hb.wall) * 1e3, median(hb.cpu) * 1e3, file_size(hb.output));
        }
        for (std::size_t k = 0; k < c.levels.size(); ++k, ++row) {
            const Job& b = jobs[rows[row].first];
            std::printf("%-10s %-28s %9.2f %9.2f %9ju", c.name.c_str(), b.name.c_str(),
                        median(b.wall) * 1e3, median(b.cpu) * 1e3, file_size(b.output));
            if (have_hb) {
                const Job& hb = jobs[rows[row].second];
                std::printf("   %.2fx, %.2fx", median(hb.wall) / median(b.wall),
                            median(hb.cpu) / median(b.cpu));
            }
            std::printf("\n");
        }
    }
    if (!have_hb) std::printf("hb-view not installed (Debian libharfbuzz-bin): no comparison\n");
    fs::remove_all(tmp);
    return 0;
}
