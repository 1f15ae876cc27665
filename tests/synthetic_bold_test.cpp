// Synthetic bold (GlyphRenderOptions::bold, ShapeOptions::bold): the emboldened ink against the
// area of the exact dilation in closed form, the placement rule, bold = 0 drawing as before, the
// advances widened by exactly bold · size in shaping, layout and the glyph box, the glyph cache
// keeping bold and regular apart, and the values it refuses.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "bezel/text.hpp"

namespace bezel {
namespace {

const std::string kDejaVu = BEZEL_FONTS_DIR "/dejavu-sans/DejaVuSans.ttf";
constexpr double kPi = 3.14159265358979323846;

// Exact-area coverage: the sum of a glyph's coverage / 255 is its ink area in px², up to the
// 8-bit rounding of each edge pixel (±1/510 px² each) and the fill's flattening (0.01 px).
struct Ink {
    GlyphBox box;
    Mask mask;
    double area_px2 = 0;
};

Ink render(GlyphRasterizer& rasterizer, GlyphId gid, const GlyphRenderOptions& o) {
    Ink ink;
    auto box = rasterizer.measure(gid, o);
    EXPECT_TRUE(box) << box.error().message;
    if (!box) return ink;
    ink.box = *box;
    ink.mask = Mask(box->width, box->height);
    EXPECT_TRUE(rasterizer.render(gid, o, ink.mask.view()));
    for (std::uint8_t v : ink.mask.pixels()) ink.area_px2 += v / 255.0;
    return ink;
}

// A contour's length: each segment sampled at 512 chords (the chords of a glyph's gentle curves
// at 64 px fall short of the arc by far less than 1e-4 of it).
double perimeter(const Path& path) {
    double length = 0;
    for (const PathSeg& seg : path.segments()) {
        Point prev = seg.eval(0);
        for (int i = 1; i <= 512; ++i) {
            const Point p = seg.eval(i / 512.0);
            length += std::hypot(p.x - prev.x, p.y - prev.y);
            prev = p;
        }
    }
    return length;
}

TEST(SyntheticBold, RectangularStemGrowsByTheRoundCorneredOffsetArea) {
    // DejaVu Sans 'l' is one rectangle w × h. Dilated by a disk of radius d it is the rectangle
    // (w + 2d) × (h + 2d) with its four corners rounded: (w + 2d)(h + 2d) − (4 − π)d².
    auto font = Font::open(kDejaVu);
    ASSERT_TRUE(font);
    const GlyphId l = *font->glyph_for_char(U'l');
    GlyphRasterizer rasterizer(*font);
    for (double bold : {0.02, 0.05, 0.1}) {
        GlyphRenderOptions o;
        o.size_px = 64;
        auto outline = font->outline(l, {o.size_px, Hinting::None});
        ASSERT_TRUE(outline);
        ASSERT_EQ(outline->points.size(), 4u) << "the test needs DejaVu's rectangular l";
        const Rect r = outline->path.bounds();
        const double w = r.x1 - r.x0, h = r.y1 - r.y0;
        ASSERT_NEAR(std::fabs(outline->path.signed_area()), w * h, 1e-9 * w * h);
        const double d = bold * o.size_px / 2;
        const double expected = (w + 2 * d) * (h + 2 * d) - (4 - kPi) * d * d;
        o.bold = bold;
        const Ink ink = render(rasterizer, l, o);
        EXPECT_NEAR(ink.area_px2 / expected, 1.0, 0.01) << "bold " << bold;
        // Tighter than the 1 % the issue asks: the construction is exact up to 0.01 px.
        EXPECT_NEAR(ink.area_px2, expected, 0.02 * (2 * (w + h) + 8 * d)) << "bold " << bold;
    }
}

TEST(SyntheticBold, RingGrowsOutsideAndShrinksItsHoleBySteinersFormula) {
    // 'o' is a ring between two convex contours. Steiner: dilating the outer convex region by d
    // adds P_out·d + πd²; eroding the convex hole by d (its curvature radius is everywhere far
    // above d) removes P_hole·d − πd² from it. The ring's ink area becomes A + (P_out + P_hole)·d:
    // the hole must shrink, so a hole wound like the ink (cancelled by non-zero) would fail here.
    auto font = Font::open(kDejaVu);
    ASSERT_TRUE(font);
    const GlyphId o_gid = *font->glyph_for_char(U'o');
    GlyphRasterizer rasterizer(*font);
    GlyphRenderOptions o;
    o.size_px = 64;
    auto outline = font->outline(o_gid, {o.size_px, Hinting::None});
    ASSERT_TRUE(outline);
    ASSERT_EQ(outline->path.contour_count(), 2u);
    const double area = std::fabs(outline->path.signed_area());
    const double p = perimeter(outline->path);
    const Ink plain = render(rasterizer, o_gid, o);
    EXPECT_NEAR(plain.area_px2 / area, 1.0, 0.001) << "coverage sums to the area";
    for (double bold : {0.02, 0.04}) {
        o.bold = bold;
        const double d = bold * o.size_px / 2;
        const Ink ink = render(rasterizer, o_gid, o);
        // The issue asks for 1 %; the dilation is within 0.01 px, which gives about 0.03 %.
        EXPECT_NEAR(ink.area_px2 / (area + p * d), 1.0, 0.002) << "bold " << bold;
    }
}

TEST(SyntheticBold, InkKeepsItsLeftEdgeAndBottomAndGrowsRightAndUp) {
    // glyph.hpp's placement: dilated by d, then moved by (d, −d). The ink's left edge and bottom
    // (found from the coverage: the area of the first column / last row's partial pixels) stay;
    // its right edge and top move out by 2d.
    auto font = Font::open(kDejaVu);
    ASSERT_TRUE(font);
    const GlyphId l = *font->glyph_for_char(U'l');
    GlyphRasterizer rasterizer(*font);
    GlyphRenderOptions o;
    o.size_px = 64;
    const Ink plain = render(rasterizer, l, o);
    o.bold = 0.05;
    const double d = o.bold * o.size_px / 2;
    const Ink bold = render(rasterizer, l, o);
    // Edges in pen coordinates (x right, y down): the box plus the partial coverage of the
    // middle row / column.
    auto edges = [](const Ink& ink, double& left, double& right, double& top, double& bottom) {
        const int mid_y = ink.box.height / 2, mid_x = ink.box.width / 2;
        double row = 0, column = 0;
        for (int x = 0; x < ink.box.width; ++x) row += ink.mask.at(x, mid_y) / 255.0;
        for (int y = 0; y < ink.box.height; ++y) column += ink.mask.at(mid_x, y) / 255.0;
        double lead = 0;
        for (int x = 0; x < ink.box.width && ink.mask.at(x, mid_y) < 255; ++x)
            lead += 1 - ink.mask.at(x, mid_y) / 255.0;
        double over = 0;
        for (int y = 0; y < ink.box.height && ink.mask.at(mid_x, y) < 255; ++y)
            over += 1 - ink.mask.at(mid_x, y) / 255.0;
        left = ink.box.left + lead;
        right = left + row;
        top = -ink.box.top + over;
        bottom = top + column;
    };
    double pl, pr, pt, pb, bl, br, bt, bb;
    edges(plain, pl, pr, pt, pb);
    edges(bold, bl, br, bt, bb);
    EXPECT_NEAR(bl, pl, 0.02);
    EXPECT_NEAR(bb, pb, 0.02);
    EXPECT_NEAR(br, pr + 2 * d, 0.02);
    EXPECT_NEAR(bt, pt - 2 * d, 0.02);
    EXPECT_DOUBLE_EQ(bold.box.advance_px, plain.box.advance_px + o.bold * o.size_px);
    EXPECT_EQ(bold.box.overlap, OverlapMode::Accurate);
}

TEST(SyntheticBold, EmboldensAfterHintingSoEveryHintedEdgeMovesByTheSameAmount) {
    // The dilation comes after the hinter, so it moves the hinted edges themselves: with
    // d = 0.5 px and the move right by d, the left edge of 'l' stays exactly where the hinter put
    // it and the right edge moves by exactly 1 px. The middle row of the bold stem is then the
    // hinted row with one more fully covered column, the partial edge pixels unchanged.
    auto font = Font::open(kDejaVu);
    ASSERT_TRUE(font);
    const GlyphId l = *font->glyph_for_char(U'l');
    GlyphRasterizer rasterizer(*font);
    for (Hinting hinting : {Hinting::Full, Hinting::Auto, Hinting::None}) {
        GlyphRenderOptions o;
        o.size_px = 20;
        o.hinting = hinting;
        const Ink plain = render(rasterizer, l, o);
        o.bold = 1.0 / 20;   // 2d = 1 px
        const Ink bold = render(rasterizer, l, o);
        ASSERT_EQ(bold.box.left, plain.box.left);
        ASSERT_EQ(bold.box.width, plain.box.width + 1);
        const int py = plain.box.height / 2, by = py + (bold.box.top - plain.box.top);
        std::vector<int> expected, got;
        for (int x = 0; x < plain.box.width; ++x) expected.push_back(plain.mask.at(x, py));
        for (int x = 0; x < bold.box.width; ++x) got.push_back(bold.mask.at(x, by));
        const auto full = std::find(expected.begin(), expected.end(), 255);
        ASSERT_NE(full, expected.end());
        expected.insert(full, 255);
        // Coverage is 8-bit: an edge pixel may round one step either way.
        ASSERT_EQ(got.size(), expected.size()) << static_cast<int>(hinting);
        for (std::size_t x = 0; x < got.size(); ++x)
            EXPECT_NEAR(got[x], expected[x], 1) << static_cast<int>(hinting) << " column " << x;
    }
}

TEST(SyntheticBold, ZeroBoldDrawsBitForBitAsWithoutIt) {
    auto font = Font::open(kDejaVu);
    ASSERT_TRUE(font);
    GlyphRasterizer rasterizer(*font);
    for (char32_t c : std::u32string(U"aghoW&@")) {
        const GlyphId gid = *font->glyph_for_char(c);
        for (GlyphBoxMode mode : {GlyphBoxMode::Tight, GlyphBoxMode::FreeType}) {
            GlyphRenderOptions plain;
            plain.size_px = 21.5;
            plain.offset_px = {0.25, 0};
            plain.box = mode;
            plain.slant = 0.2;
            GlyphRenderOptions zero = plain;
            zero.bold = 0.0;
            const Ink a = render(rasterizer, gid, plain), b = render(rasterizer, gid, zero);
            EXPECT_EQ(a.box.left, b.box.left);
            EXPECT_EQ(a.box.top, b.box.top);
            EXPECT_EQ(a.box.advance_px, b.box.advance_px);
            EXPECT_EQ(a.box.overlap, b.box.overlap);
            EXPECT_TRUE(a.mask.pixels() == b.mask.pixels()) << static_cast<int>(c);
        }
    }
}

TEST(SyntheticBold, SlantAfterBoldKeepsTheEmboldenedArea) {
    // The shear comes after the dilation and keeps areas, so the area is the bold one.
    auto font = Font::open(kDejaVu);
    ASSERT_TRUE(font);
    const GlyphId gid = *font->glyph_for_char(U'H');
    GlyphRasterizer rasterizer(*font);
    GlyphRenderOptions o;
    o.size_px = 48;
    o.bold = 0.05;
    const Ink bold = render(rasterizer, gid, o);
    o.slant = 0.3;
    const Ink both = render(rasterizer, gid, o);
    EXPECT_NEAR(both.area_px2 / bold.area_px2, 1.0, 0.002);
    o.bold = 0;
    const Ink slanted = render(rasterizer, gid, o);
    EXPECT_GT(both.area_px2, slanted.area_px2 * 1.1);
}

TEST(SyntheticBold, ShapingWidensEveryNonzeroAdvanceByBoldTimesSize) {
    auto shaper = Shaper::open(kDejaVu);
    ASSERT_TRUE(shaper);
    ShapeOptions o;
    o.size_px = 20;
    // A combining acute after x (no precomposed form) is a mark with no advance; it stays 0.
    const std::string text = "Wafer x\u0301 \u05e9\u05dc";
    auto plain = shaper->shape(text, o);
    ASSERT_TRUE(plain);
    o.bold = 0.05;
    auto bold = shaper->shape(text, o);
    ASSERT_TRUE(bold);
    ASSERT_EQ(plain->glyphs.size(), bold->glyphs.size());
    int widened = 0, marks = 0;
    for (std::size_t i = 0; i < plain->glyphs.size(); ++i) {
        const ShapedGlyph &p = plain->glyphs[i], &b = bold->glyphs[i];
        EXPECT_EQ(p.gid, b.gid);
        EXPECT_EQ(p.x_offset_px, b.x_offset_px);
        if (p.x_advance_px == 0) {
            EXPECT_EQ(b.x_advance_px, 0.0);
            ++marks;
        } else {
            EXPECT_NEAR(b.x_advance_px, p.x_advance_px + 1.0, 1e-12);
            ++widened;
        }
    }
    EXPECT_GT(widened, 5);
    EXPECT_EQ(marks, 1);
    EXPECT_NEAR(bold->advance_px, plain->advance_px + widened * 1.0, 1e-9);
}

TEST(SyntheticBold, LayoutLineIsWiderByBoldTimesSizePerGlyph) {
    auto renderer = TextRenderer::open(kDejaVu);
    ASSERT_TRUE(renderer);
    ShapeOptions shape;
    shape.size_px = 30;
    LayoutOptions layout;
    const std::string text = "Hamburgefonts";
    auto plain = layout_text(renderer->shaper(), renderer->font().metrics(), text, shape, layout);
    shape.bold = 0.04;
    auto bold = layout_text(renderer->shaper(), renderer->font().metrics(), text, shape, layout);
    ASSERT_TRUE(plain && bold);
    ASSERT_EQ(plain->glyphs.size(), text.size());
    ASSERT_EQ(bold->glyphs.size(), text.size());
    const double step = 0.04 * 30;
    for (std::size_t i = 0; i < text.size(); ++i)
        EXPECT_NEAR(bold->glyphs[i].x_px, plain->glyphs[i].x_px + step * i, 1e-9) << i;
    EXPECT_NEAR(bold->width_px, plain->width_px + step * text.size(), 1e-9);
}

TEST(SyntheticBold, CacheKeepsBoldAndRegularApart) {
    auto font = Font::open(kDejaVu);
    ASSERT_TRUE(font);
    GlyphRasterizer rasterizer(*font);
    GlyphCache cache;
    const GlyphId gid = *font->glyph_for_char(U'e');
    GlyphRenderOptions regular;
    regular.size_px = 24;
    GlyphRenderOptions bold = regular;
    bold.bold = 0.05;
    auto r = cache.get(rasterizer, gid, regular);
    ASSERT_TRUE(r);
    const GlyphBox regular_box = (*r)->box;
    const std::vector<std::uint8_t> regular_pixels((*r)->mask.data,
                                                   (*r)->mask.data + (*r)->mask.height *
                                                                         (*r)->mask.stride);
    auto b = cache.get(rasterizer, gid, bold);
    ASSERT_TRUE(b);
    EXPECT_EQ(cache.stats().misses, 2u);
    EXPECT_EQ(cache.stats().entries, 2u);
    EXPECT_GT((*b)->box.width, regular_box.width);
    EXPECT_DOUBLE_EQ((*b)->box.advance_px, regular_box.advance_px + 1.2);
    // Each is found again, the regular one unchanged.
    auto r2 = cache.get(rasterizer, gid, regular);
    auto b2 = cache.get(rasterizer, gid, bold);
    ASSERT_TRUE(r2 && b2);
    EXPECT_EQ(cache.stats().hits, 2u);
    EXPECT_EQ((*r2)->box.width, regular_box.width);
    EXPECT_TRUE(std::vector<std::uint8_t>((*r2)->mask.data,
                                          (*r2)->mask.data + (*r2)->mask.height *
                                                                 (*r2)->mask.stride) ==
                regular_pixels);
    EXPECT_GT((*b2)->box.width, regular_box.width);
}

TEST(SyntheticBold, RefusesBoldOutOfRangeAndEvenOddFill) {
    auto font = Font::open(kDejaVu);
    ASSERT_TRUE(font);
    GlyphRasterizer rasterizer(*font);
    const GlyphId gid = *font->glyph_for_char(U'a');
    for (double bad : {-0.01, kMaxSyntheticBold * 1.01, std::nan(""), HUGE_VAL}) {
        GlyphRenderOptions o;
        o.bold = bad;
        auto box = rasterizer.measure(gid, o);
        ASSERT_FALSE(box) << bad;
        EXPECT_NE(box.error().message.find("bold"), std::string::npos);
        auto shaper = Shaper::open(kDejaVu);
        ASSERT_TRUE(shaper);
        ShapeOptions s;
        s.bold = bad;
        auto run = shaper->shape("a", s);
        ASSERT_FALSE(run) << bad;
        EXPECT_NE(run.error().message.find("bold"), std::string::npos);
    }
    GlyphRenderOptions o;
    o.bold = kMaxSyntheticBold;
    EXPECT_TRUE(rasterizer.measure(gid, o));
    o.fill.rule = FillRule::EvenOdd;
    auto box = rasterizer.measure(gid, o);
    ASSERT_FALSE(box);
    EXPECT_NE(box.error().message.find("nonzero"), std::string::npos);
}

}  // namespace
}  // namespace bezel
