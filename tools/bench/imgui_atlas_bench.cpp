// bench_imgui_atlas_bench: building a Dear ImGui font atlas with bezel_imgui's builder against
// ImGui's own stb_truetype builder (ImFontAtlasGetBuilderForStbTruetype), in one process.
// DejaVu Sans, ImGui's default ranges (GetGlyphRangesDefault: ASCII and Latin-1, U+0020-00FF),
// at 13, 16 and 24 px, each at ImGui's default oversampling (3×1) and without (1×1); bezel
// unhinted (the work stb_truetype does) and with ImGui-freetype's default flags (full hinting).
// Each build is one ImFontAtlas::Build() of a fresh atlas (the font bytes read once, outside the
// timing). Reported: the median over RUNS rounds (the builders interleaved within each round, so
// a change in the machine's load hits them alike) and bezel / stb.
//
//   bench_imgui_atlas_bench [RUNS]      (default 21)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <imgui.h>
#include <imgui_internal.h>

#include "bezel_imgui.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// One atlas build, milliseconds.
double build_ms(std::vector<char>& font, float size, int oversample, const ImFontBuilderIO* io,
                unsigned flags) {
    ImFontAtlas atlas;
    ImFontConfig cfg;
    cfg.FontDataOwnedByAtlas = false;
    cfg.OversampleH = oversample;
    cfg.FontBuilderFlags = flags;
    atlas.AddFontFromMemoryTTF(font.data(), static_cast<int>(font.size()), size, &cfg);
    atlas.FontBuilderIO = io;
    const auto t0 = Clock::now();
    const bool ok = atlas.Build();
    const auto t1 = Clock::now();
    if (!ok) {
        std::fprintf(stderr, "bench_imgui_atlas_bench: build failed: %s\n",
                     bezel_imgui::last_build_error().c_str());
        std::exit(1);
    }
    return std::chrono::duration<double, std::milli>(t1 - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
    const int runs = argc > 1 ? std::atoi(argv[1]) : 21;
    if (runs < 1) {
        std::fprintf(stderr, "usage: bench_imgui_atlas_bench [RUNS ≥ 1]\n");
        return 2;
    }
    const std::string file = std::string(BEZEL_FONTS_DIR) + "/dejavu-sans/DejaVuSans.ttf";
    std::ifstream in(file, std::ios::binary);
    std::vector<char> font((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (font.empty()) {
        std::fprintf(stderr, "bench_imgui_atlas_bench: cannot read %s\n", file.c_str());
        return 1;
    }
    std::printf("ImGui %s atlas build, DejaVu Sans, U+0020-00FF, median of %d (ms)\n",
                IMGUI_VERSION, runs);
    std::printf("%5s %10s %10s %12s %10s %12s %12s\n", "size", "oversample", "stb", "bezel-none",
                "ratio", "bezel-full", "ratio");
    for (float size : {13.0f, 16.0f, 24.0f}) {
        for (int oversample : {3, 1}) {
            std::vector<double> stb, none, full;
            for (int r = 0; r < runs; ++r) {
                stb.push_back(build_ms(font, size, oversample,
                                       ImFontAtlasGetBuilderForStbTruetype(), 0));
                none.push_back(build_ms(font, size, oversample, bezel_imgui::builder(),
                                        bezel_imgui::NoHinting));
                full.push_back(build_ms(font, size, oversample, bezel_imgui::builder(), 0));
            }
            const double s = median(stb), n = median(none), f = median(full);
            std::printf("%5.0f %8dx1 %10.3f %12.3f %10.2f %12.3f %12.2f\n", size, oversample, s,
                        n, n / s, f, f / s);
        }
    }
    return 0;
}
