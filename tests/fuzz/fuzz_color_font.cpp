// fuzz_color_font — colour font bytes (COLR/CPAL/CBDT/sbix fonts, mutated) → Font::open →
// color_tables, palettes, and for up to 48 glyphs spread over the font color_format,
// load_color_glyph (two palettes, a custom entry) and load_color_bitmap at two sizes. Font opens
// files only, so each input is written to one per-process file in /dev/shm (or $TMPDIR).
// Properties: no crash, hang or sanitizer report; every error names the font file; every
// ColorGlyph holds paint.hpp's invariants (indices in range, no cycle, at most kMaxPaintDepth deep
// and kMaxPaintNodes visited, stops sorted and non-empty, finite outlines and geometry); every
// ColorBitmap is premultiplied RGBA of its stated size. Each glyph is then drawn end to end at
// 24 px through GlyphRasterizer (the box, the painter or the bitmap scaling): an error names the
// glyph, and drawn pixels are premultiplied.
//
// Seeds (corpus/fuzz_color_font): fonts-test/colour's small COLRv1 and sbix fonts and
// fonts-test/noto-color-emoji's CBDT subset (Apache-2.0 and OFL, see their folders), and the COLR
// test fonts of tests/data/colour (make_bad_colr_fonts.py).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <variant>
#include <vector>

#include "bezel/color_glyph.hpp"
#include "bezel/glyph.hpp"
#include "bezel/limits.hpp"
#include "fuzz_font_file.hpp"
#include "fuzz_reader.hpp"

namespace {

bool finite(bezel::Point p) { return std::isfinite(p.x) && std::isfinite(p.y); }

void check_line(const bezel::ColorLine& line) {
    BEZEL_FUZZ_CHECK(!line.stops.empty());
    for (std::size_t i = 1; i < line.stops.size(); ++i)
        BEZEL_FUZZ_CHECK(line.stops[i - 1].offset <= line.stops[i].offset);
    for (const bezel::ColorStop& s : line.stops) {
        BEZEL_FUZZ_CHECK(std::isfinite(s.offset));
        BEZEL_FUZZ_CHECK(s.color.alpha >= 0 && s.color.alpha <= 1);
    }
}

// Walks the graph from `i` as the painter would: every index in range, depth and visits bounded
// (which also rules out a cycle: a cycle would nest without end).
struct Walk {
    const bezel::ColorGlyph& g;
    std::size_t visits = 0;

    void node(bezel::PaintIndex i, int depth) {
        BEZEL_FUZZ_CHECK(i < g.nodes.size());
        BEZEL_FUZZ_CHECK(depth <= bezel::kMaxPaintDepth);
        BEZEL_FUZZ_CHECK(++visits <= bezel::kMaxPaintNodes);
        std::visit([&](const auto& n) { visit(n, depth); }, g.nodes[i]);
    }
    void visit(const bezel::PaintLayers& n, int depth) {
        for (bezel::PaintIndex c : n.layers) node(c, depth + 1);
    }
    void visit(const bezel::PaintSolid& n, int) {
        BEZEL_FUZZ_CHECK(n.color.alpha >= 0 && n.color.alpha <= 1);
    }
    void visit(const bezel::PaintLinearGradient& n, int) {
        check_line(n.line);
        BEZEL_FUZZ_CHECK(finite(n.p0) && finite(n.p1) && finite(n.p2));
    }
    void visit(const bezel::PaintRadialGradient& n, int) {
        check_line(n.line);
        BEZEL_FUZZ_CHECK(finite(n.c0) && finite(n.c1) && n.r0 >= 0 && n.r1 >= 0);
    }
    void visit(const bezel::PaintSweepGradient& n, int) {
        check_line(n.line);
        BEZEL_FUZZ_CHECK(finite(n.center) && std::isfinite(n.start_deg) && std::isfinite(n.end_deg));
    }
    void visit(const bezel::PaintGlyph& n, int depth) {
        BEZEL_FUZZ_CHECK(n.outline < g.outlines.size());
        node(n.paint, depth + 1);
    }
    void visit(const bezel::PaintTransform& n, int depth) {
        BEZEL_FUZZ_CHECK(n.transform.is_finite());
        node(n.paint, depth + 1);
    }
    void visit(const bezel::PaintColrGlyph& n, int depth) { node(n.paint, depth + 1); }
    void visit(const bezel::PaintComposite& n, int depth) {
        BEZEL_FUZZ_CHECK(static_cast<int>(n.mode) < bezel::kCompositeModeCount);
        node(n.source, depth + 1);
        node(n.backdrop, depth + 1);
    }
};

void check_glyph(const bezel::ColorGlyph& g) {
    for (const bezel::Path& p : g.outlines) BEZEL_FUZZ_CHECK(p.is_finite());
    Walk walk{g};
    walk.node(g.root, 1);
}

void check_bitmap(const bezel::ColorBitmap& b) {
    BEZEL_FUZZ_CHECK(b.width >= 0 && b.height >= 0);
    BEZEL_FUZZ_CHECK(b.rgba.size() == std::size_t(b.width) * std::size_t(b.height) * 4);
    BEZEL_FUZZ_CHECK(b.rgba.size() <= bezel::kMaxColorBitmapBytes);
    for (std::size_t i = 0; i < b.rgba.size(); i += 4) {
        const std::uint8_t a = b.rgba[i + 3];
        BEZEL_FUZZ_CHECK(b.rgba[i] <= a && b.rgba[i + 1] <= a && b.rgba[i + 2] <= a);
    }
    BEZEL_FUZZ_CHECK(b.strike_px > 0 && std::isfinite(b.advance_px));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::string file = bezel::fuzz::scratch_font_file("color-font");
    if (!bezel::fuzz::write_font_file(file, data, size)) std::abort();
    auto opened = bezel::Font::open(file, 0);
    if (!opened) {
        BEZEL_FUZZ_CHECK(opened.error().message.find(file) != std::string::npos);
        return 0;
    }
    bezel::Font& font = *opened;
    (void)bezel::color_tables(font);
    const std::vector<bezel::Palette> palettes = bezel::palettes(font);

    const std::size_t glyphs = font.glyph_count();
    constexpr std::size_t kGlyphs = 48;
    const std::size_t step = std::max<std::size_t>(1, glyphs / kGlyphs);
    std::vector<bezel::GlyphId> gids;
    for (std::size_t g = 0; g < glyphs && gids.size() < kGlyphs; g += step)
        gids.push_back(static_cast<bezel::GlyphId>(g));
    gids.push_back(static_cast<bezel::GlyphId>(glyphs));   // one past the end: errors

    bezel::GlyphRasterizer rasterizer(font);
    bezel::GlyphRenderOptions drawn_at;
    drawn_at.size_px = 24;
    std::vector<std::uint8_t> pixels;
    bezel::ColorGlyphOptions second;
    second.palette = 1;
    second.custom.push_back({0, bezel::Rgba8{1, 2, 3, 4}});
    for (bezel::GlyphId gid : gids) {
        const bezel::ColorFormat format = bezel::color_format(font, gid);
        if (gid >= glyphs) BEZEL_FUZZ_CHECK(format == bezel::ColorFormat::None);
        const bezel::ColorGlyphOptions* const choices[] = {nullptr, &second};
        for (const bezel::ColorGlyphOptions* options : choices) {
            auto g = bezel::load_color_glyph(font, gid, options ? *options : bezel::ColorGlyphOptions{});
            if (g) {
                check_glyph(*g);
            } else {
                BEZEL_FUZZ_CHECK(g.error().message.find(file) != std::string::npos);
            }
            if (palettes.size() < 2) break;   // palette 1 would be an error: the default is enough
        }
        if (auto prepared = rasterizer.prepare(gid, drawn_at)) {
            const bezel::GlyphBox& box = prepared->box;
            // A mutated font may box a glyph up to kMaxBitmapDim a side; 512 × 512 is plenty here.
            if (box.color && box.width <= 512 && box.height <= 512) {
                pixels.assign(4 * std::size_t(box.width) * std::size_t(box.height), 0);
                const bezel::RgbaView view{pixels.data(), box.width, box.height, 4 * box.width};
                if (rasterizer.draw_rgba(*prepared, view)) {
                    for (std::size_t i = 0; i < pixels.size(); i += 4)
                        BEZEL_FUZZ_CHECK(pixels[i] <= pixels[i + 3] &&
                                         pixels[i + 1] <= pixels[i + 3] &&
                                         pixels[i + 2] <= pixels[i + 3]);
                }
            }
        } else {
            BEZEL_FUZZ_CHECK(prepared.error().message.find("glyph") != std::string::npos);
        }
        if (format == bezel::ColorFormat::Bitmap || gid < 4) {
            for (double size : {16.0, 300.0}) {
                auto b = bezel::load_color_bitmap(font, gid, size);
                if (b) {
                    check_bitmap(*b);
                } else {
                    BEZEL_FUZZ_CHECK(b.error().message.find(file) != std::string::npos);
                }
            }
        }
    }
    return 0;
}
