// Stroking speed against FreeType's stroker (FT_Stroker), the peer every bench links.
//
// Workload: the outlines of the printable ASCII glyphs of DejaVu Sans and Cantarell at 96 px,
// stroked 3 px wide with round joins and round caps (the stroked-glyph use of issue 7), each
// glyph stroked `kReps` times; the best of 5 runs is reported per glyph. FreeType parses the
// same unhinted outline (26.6 fixed point) with FT_Stroker_ParseOutline and exports it into a
// fresh FT_Outline (FT_Stroker_GetCounts + FT_Outline_New + FT_Stroker_Export), which is the
// work bezel::stroke() does into a fresh Path. FreeType's stroker has no tolerance: it offsets
// each conic/cubic piece by its own subdivision (ftstroke.c, FT_SMALL_CUBIC_THRESHOLD ≈ π/6
// turning per piece), so bezel is shown at two tolerances. Segment counts are the outputs'.
#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_GLYPH_H
#include FT_STROKER_H

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "bezel/font.hpp"
#include "bezel/stroke.hpp"

namespace {

constexpr int kReps = 20;
constexpr double kSizePx = 96;
constexpr double kWidthPx = 3;

template <typename F>
double best_seconds(F&& f) {
    double best = 1e300;
    for (int run = 0; run < 5; ++run) {
        auto t0 = std::chrono::steady_clock::now();
        f();
        best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    return best;
}

void bench_font(const std::string& file) {
    auto font = bezel::Font::open(file);
    if (!font) {
        std::printf("%s\n", font.error().message.c_str());
        return;
    }
    std::vector<bezel::Path> paths;
    std::vector<bezel::GlyphId> gids;
    bezel::OutlineOptions oo;
    oo.size_px = kSizePx;
    for (char32_t ch = 33; ch < 127; ++ch) {
        auto gid = font->glyph_for_char(ch);
        if (!gid) continue;
        auto g = font->outline(*gid, oo);
        if (!g || g->path.empty()) continue;
        paths.push_back(g->path);
        gids.push_back(*gid);
    }

    FT_Library lib;
    FT_Face face;
    FT_Init_FreeType(&lib);
    FT_New_Face(lib, file.c_str(), 0, &face);
    FT_Set_Pixel_Sizes(face, 0, static_cast<FT_UInt>(kSizePx));
    std::vector<FT_Glyph> ft_glyphs;
    for (bezel::GlyphId gid : gids) {
        FT_Load_Glyph(face, gid, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP);
        FT_Glyph g;
        FT_Get_Glyph(face->glyph, &g);
        ft_glyphs.push_back(g);
    }
    FT_Stroker stroker;
    FT_Stroker_New(lib, &stroker);
    FT_Stroker_Set(stroker, static_cast<FT_Fixed>(kWidthPx / 2 * 64), FT_STROKER_LINECAP_ROUND,
                   FT_STROKER_LINEJOIN_ROUND, 4 << 16);
    std::size_t ft_segments = 0;
    double ft = best_seconds([&] {
        ft_segments = 0;
        for (int r = 0; r < kReps; ++r)
            for (FT_Glyph g : ft_glyphs) {
                FT_Outline* src = &reinterpret_cast<FT_OutlineGlyph>(g)->outline;
                FT_Stroker_ParseOutline(stroker, src, 0);
                FT_UInt np = 0, nc = 0;
                FT_Stroker_GetCounts(stroker, &np, &nc);
                FT_Outline out;
                FT_Outline_New(lib, np, static_cast<FT_Int>(nc), &out);
                out.n_points = 0;
                out.n_contours = 0;
                FT_Stroker_Export(stroker, &out);
                ft_segments += static_cast<std::size_t>(out.n_points);
                FT_Outline_Done(lib, &out);
            }
    });
    ft_segments /= kReps;

    std::printf("%s, %zu glyphs at %g px, width %g, round joins and caps (per glyph):\n",
                file.substr(file.find_last_of('/') + 1).c_str(), paths.size(), kSizePx, kWidthPx);
    std::printf("  FreeType FT_Stroker      %8.1f us   %6.0f points out\n",
                ft / (kReps * paths.size()) * 1e6, double(ft_segments) / paths.size());
    for (double tol : {0.01, 0.1}) {
        bezel::StrokeStyle s;
        s.width = kWidthPx;
        s.join = bezel::LineJoin::Round;
        s.cap = bezel::LineCap::Round;
        s.tolerance = tol;
        std::size_t segments = 0;
        double t = best_seconds([&] {
            segments = 0;
            for (int r = 0; r < kReps; ++r)
                for (const bezel::Path& p : paths) {
                    auto out = bezel::stroke(p, s);
                    segments += out ? out->segment_count() : 0;
                }
        });
        segments /= kReps;
        std::printf("  bezel stroke tol %-5g   %8.1f us   %6.0f segments out   (%.2fx FreeType's time)\n",
                    tol, t / (kReps * paths.size()) * 1e6, double(segments) / paths.size(), t / ft);
    }
    FT_Stroker_Done(stroker);
    for (FT_Glyph g : ft_glyphs) FT_Done_Glyph(g);
    FT_Done_Face(face);
    FT_Done_FreeType(lib);
}

}  // namespace

int main() {
    bench_font(std::string(BEZEL_FONTS_DIR) + "/dejavu-sans/DejaVuSans.ttf");
    bench_font(std::string(BEZEL_FONTS_DIR) + "/cantarell/Cantarell-Regular.otf");
    return 0;
}
