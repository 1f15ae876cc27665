// bench_colour_bench: what a colour glyph costs, against an outline glyph of the same box, in one
// process. Chromium draws COLRv1 too but cannot be run in-process, so the yardstick is bezel's
// own outline path:
//   colr      40 emoji of Twitter's COLRv1 set (fonts-test/colour/twemoji-glyf_colr_1.ttf, the
//             first 40 of U+1F600..) drawn cold (GlyphRasterizer::prepare + draw_rgba: the paint
//             graph read through FreeType, every clip outline rasterized, layers composited);
//   cbdt      the Noto Color Emoji subset's U+1F600 (a 136-px PNG strike, decoded and box-scaled);
//   outline   DejaVu Sans's 'M', '@' and 'W' at the size that gives them the emoji's box height,
//             drawn cold the same way (prepare + draw);
//   hit       GlyphCache::get of an already cached glyph: the emoji, and the outline glyphs.
// at 16, 32 and 128 px. Reported: the median per glyph over RUNS rounds (interleaved), and the
// ratios colr / outline, cbdt / outline and hit(colr) / hit(outline) (the bar for hits: 1).
//
//   bench_colour_bench [RUNS]      (default 15)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "bezel/text.hpp"

namespace {

using Clock = std::chrono::steady_clock;
const std::string kFonts = BEZEL_FONTS_DIR;

bezel::Font open_font(const std::string& file) {
    auto font = bezel::Font::open(file);
    if (!font) {
        std::fprintf(stderr, "%s\n", font.error().message.c_str());
        std::exit(1);
    }
    return std::move(font).value();
}

void check(const bezel::Status& s) {
    if (!s) {
        std::fprintf(stderr, "bench_colour_bench: %s\n", s.error().message.c_str());
        std::exit(1);
    }
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// Draws each glyph cold: prepare + draw (RGBA for colour, coverage otherwise). Returns seconds.
double draw_cold(bezel::GlyphRasterizer& r, const std::vector<bezel::GlyphId>& gids,
                 const bezel::GlyphRenderOptions& o, std::vector<std::uint8_t>& scratch) {
    const auto t0 = Clock::now();
    for (bezel::GlyphId gid : gids) {
        auto g = r.prepare(gid, o);
        if (!g) check(g.error());
        const bezel::GlyphBox& box = g->box;
        scratch.resize(4 * static_cast<std::size_t>(box.width) * box.height + 1);
        if (box.color)
            check(r.draw_rgba(*g, bezel::RgbaView{scratch.data(), box.width, box.height,
                                                  4 * std::ptrdiff_t{box.width}}));
        else
            check(r.draw(*g, bezel::MaskView{scratch.data(), box.width, box.height, box.width}));
    }
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

// `reps` rounds of cache hits over the glyphs (already cached). Returns seconds.
double hits(bezel::GlyphCache& cache, bezel::GlyphRasterizer& r,
            const std::vector<bezel::GlyphId>& gids, const bezel::GlyphRenderOptions& o, int reps) {
    std::size_t sink = 0;
    const auto t0 = Clock::now();
    for (int k = 0; k < reps; ++k)
        for (bezel::GlyphId gid : gids) {
            auto c = cache.get(r, gid, o);
            if (!c) check(c.error());
            sink += static_cast<std::size_t>((*c)->box.width);
        }
    const double t = std::chrono::duration<double>(Clock::now() - t0).count();
    if (sink == 0) std::fprintf(stderr, "(no pixels)\n");
    return t;
}

}  // namespace

int main(int argc, char** argv) {
    const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 15;
    bezel::Font emoji = open_font(kFonts + "/colour/twemoji-glyf_colr_1.ttf");
    bezel::Font cbdt = open_font(kFonts + "/noto-color-emoji/NotoColorEmoji-subset.ttf");
    bezel::Font latin = open_font(kFonts + "/dejavu-sans/DejaVuSans.ttf");
    bezel::GlyphRasterizer re(emoji), rc(cbdt), rl(latin);

    std::vector<bezel::GlyphId> colr;
    for (char32_t c = 0x1F600; colr.size() < 40 && c < 0x1F700; ++c)
        if (auto gid = emoji.glyph_for_char(c)) colr.push_back(*gid);
    const std::vector<bezel::GlyphId> cbdt_gids = {*cbdt.glyph_for_char(0x1F600)};
    const std::vector<bezel::GlyphId> outline = {*latin.glyph_for_char(U'M'),
                                                 *latin.glyph_for_char(U'@'),
                                                 *latin.glyph_for_char(U'W')};
    std::vector<std::uint8_t> scratch;

    std::printf("%-6s %12s %12s %12s %10s %10s %12s %12s %10s\n", "size", "colr us", "cbdt us",
                "outline us", "colr/out", "cbdt/out", "hit colr ns", "hit out ns", "hit ratio");
    for (double size : {16.0, 32.0, 128.0}) {
        bezel::GlyphRenderOptions o;
        o.size_px = size;
        // The outline glyphs at the size that gives 'M' the emoji's box height.
        auto em = re.prepare(colr.front(), o);
        auto m = rl.prepare(outline.front(), o);
        if (!em) check(em.error());
        if (!m) check(m.error());
        bezel::GlyphRenderOptions ol = o;
        ol.size_px = size * em->box.height / std::max(1, m->box.height);

        bezel::GlyphCache ce, cl;
        for (bezel::GlyphId gid : colr)
            if (auto got = ce.get(re, gid, o); !got) check(got.error());
        for (bezel::GlyphId gid : outline)
            if (auto got = cl.get(rl, gid, ol); !got) check(got.error());
        const int hit_reps = 2000;
        std::vector<double> t_colr, t_cbdt, t_out, t_hit_colr, t_hit_out;
        for (int run = 0; run < runs; ++run) {
            t_colr.push_back(draw_cold(re, colr, o, scratch) / colr.size());
            t_cbdt.push_back(draw_cold(rc, cbdt_gids, o, scratch) / cbdt_gids.size());
            t_out.push_back(draw_cold(rl, outline, ol, scratch) / outline.size());
            t_hit_colr.push_back(hits(ce, re, colr, o, hit_reps / 10) /
                                 (colr.size() * (hit_reps / 10)));
            t_hit_out.push_back(hits(cl, rl, outline, ol, hit_reps) / (outline.size() * hit_reps));
        }
        const double c = median(t_colr), b = median(t_cbdt), l = median(t_out);
        const double hc = median(t_hit_colr), hl = median(t_hit_out);
        std::printf("%-6g %12.2f %12.2f %12.2f %10.2f %10.2f %12.1f %12.1f %10.2f\n", size,
                    c * 1e6, b * 1e6, l * 1e6, c / l, b / l, hc * 1e9, hl * 1e9, hc / hl);
    }
    return 0;
}
