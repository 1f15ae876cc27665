// GlyphRasterizer: FreeType's box convention, pixels equal to FreeType's own rasterizer at that
// box, subpixel offsets, LCD boxes, and the input it refuses.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "bezel/freetype_reference.hpp"
#include "bezel/text.hpp"
#include "support/allocation_counter.hpp"

namespace bezel {
namespace {

using bezel::test::g_allocations;

const std::string kDejaVu = BEZEL_FONTS_DIR "/dejavu-sans/DejaVuSans.ttf";
const std::string kCantarell = BEZEL_FONTS_DIR "/cantarell/Cantarell-Regular.otf";

struct FtBox {
    char ch;
    int left, top, width, height;
};

// FreeType 2.12's bitmap_left / bitmap_top / width / rows for FT_LOAD_NO_HINTING | FT_LOAD_RENDER
// at FT_Set_Pixel_Sizes(0, 24) (a 20-line C program against libfreetype). These glyphs have
// points at their extrema, so FreeType's control box is the tight box bezel uses.
void expect_boxes_match_freetype(const std::string& file, const std::vector<FtBox>& expected) {
    auto font = Font::open(file);
    ASSERT_TRUE(font) << font.error().message;
    GlyphRasterizer rasterizer(*font);
    GlyphRenderOptions o;
    o.size_px = 24;
    for (const FtBox& e : expected) {
        GlyphId gid = font->glyph_for_char(static_cast<char32_t>(e.ch)).value();
        auto box = rasterizer.measure(gid, o);
        ASSERT_TRUE(box) << box.error().message;
        EXPECT_EQ(box->left, e.left) << e.ch;
        EXPECT_EQ(box->top, e.top) << e.ch;
        EXPECT_EQ(box->width, e.width) << e.ch;
        EXPECT_EQ(box->height, e.height) << e.ch;
    }
}

TEST(GlyphRasterizer, BoxMatchesFreeTypeBitmapLeftTop) {
    expect_boxes_match_freetype(kDejaVu, {{'H', 2, 18, 14, 18}, {'o', 1, 14, 13, 15},
                                          {'g', 1, 14, 13, 19}, {'W', 0, 18, 23, 18},
                                          {'&', 1, 18, 17, 19}});
    expect_boxes_match_freetype(kCantarell, {{'H', 2, 17, 14, 17}, {'o', 1, 12, 12, 13},
                                             {'W', 0, 17, 24, 17}});
}

TEST(GlyphRasterizer, FreeTypeBoxHoldsTheTightBoxAndTheSameInk) {
    // The control box holds the curves, so the FreeType box holds the tight one, up to FreeType's
    // rounding of both to 1/64 px (a tight edge a hair past a pixel boundary can fall inside it
    // in 26.6). Where it holds it, the ink drawn in either is the same (the glyph at its pen,
    // whatever the box): pixel (i, j) of the tight box is pixel (i + dl, j + dt) of the other.
    int larger = 0, compared = 0, glyphs = 0;
    for (const std::string& file : {kCantarell, kDejaVu}) {
        auto font = Font::open(file);
        ASSERT_TRUE(font);
        GlyphRasterizer rasterizer(*font);
        for (GlyphId gid = 0; gid < font->glyph_count(); gid += 2) {
            for (CoverageFormat format : {CoverageFormat::Gray, CoverageFormat::Lcd}) {
                GlyphRenderOptions tight;
                tight.size_px = 37;
                tight.offset_px = {0.3, 0.6};
                tight.fill.format = format;
                GlyphRenderOptions ft = tight;
                ft.box = GlyphBoxMode::FreeType;
                auto t = rasterizer.measure(gid, tight);
                auto f = rasterizer.measure(gid, ft);
                ASSERT_TRUE(t && f);
                if (t->width == 0) continue;
                ++glyphs;
                EXPECT_LE(f->left, t->left + 1) << gid;
                EXPECT_GE(f->top, t->top - 1) << gid;
                EXPECT_GE(f->left + f->width, t->left + t->width - 1) << gid;
                EXPECT_GE(f->height - f->top, t->height - t->top - 1) << gid;
                const bool holds = f->left <= t->left && f->top >= t->top &&
                                   f->left + f->width >= t->left + t->width &&
                                   f->height - f->top >= t->height - t->top;
                if (!holds) continue;
                ++compared;
                larger += f->width * f->height > t->width * t->height;
                const int bpp = format == CoverageFormat::Gray ? 1 : 3;
                Mask tm(t->width * bpp, t->height), fm(f->width * bpp, f->height);
                ASSERT_TRUE(rasterizer.render(gid, tight, tm.view()));
                ASSERT_TRUE(rasterizer.render(gid, ft, fm.view()));
                const int dx = (t->left - f->left) * bpp, dy = f->top - t->top;
                EXPECT_EQ(tm, to_mask(fm.view().sub(dx, dy, tm.width(), tm.height()))) << gid;
            }
        }
    }
    EXPECT_GT(compared, glyphs * 9 / 10);
    EXPECT_GT(larger, 0);   // the two conventions do differ on some glyphs
}

TEST(GlyphRasterizer, WholePixelOffsetMovesTheBoxNotThePixels) {
    auto font = Font::open(kDejaVu);
    ASSERT_TRUE(font);
    GlyphRasterizer rasterizer(*font);
    const GlyphId gid = *font->glyph_for_char(U'&');
    for (GlyphBoxMode box_mode : {GlyphBoxMode::Tight, GlyphBoxMode::FreeType}) {
        GlyphRenderOptions a;
        a.size_px = 19;
        a.box = box_mode;
        a.offset_px = {0.25, 0.5};
        GlyphRenderOptions b = a;
        b.offset_px = {-6.75, 3.5};   // 7 px left, 3 px down
        auto pa = rasterizer.prepare(gid, a);
        auto pb = rasterizer.prepare(gid, b);
        ASSERT_TRUE(pa && pb);
        EXPECT_EQ(pb->box.left, pa->box.left - 7);
        EXPECT_EQ(pb->box.top, pa->box.top - 3);
        EXPECT_EQ(pb->box.width, pa->box.width);
        EXPECT_EQ(pb->box.height, pa->box.height);
        Mask ma(pa->box.width, pa->box.height), mb(pb->box.width, pb->box.height);
        ASSERT_TRUE(rasterizer.draw(*pa, ma.view()));
        ASSERT_TRUE(rasterizer.draw(*pb, mb.view()));
        EXPECT_EQ(ma, mb);
    }
}

// Max and mean |a − b| over a box.
struct Diff {
    int max = 0;
    double mean = 0;
};
Diff diff(ConstMaskView a, ConstMaskView b) {
    Diff d;
    long sum = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            int e = std::abs(a.at(x, y) - b.at(x, y));
            d.max = std::max(d.max, e);
            sum += e;
        }
    d.mean = static_cast<double>(sum) / (a.width * a.height);
    return d;
}

TEST(GlyphRasterizer, PixelsAgreeWithFreeTypeAtTheSameBox) {
    // FreeType rasterizes the same outline at the box's pen position. Its own curve flattening
    // errs by up to 16-54/255 (raster_glyph_test); measured here: max <= 16, mean <= 1.9. So
    // max <= 20 and mean <= 3 levels. A box or pen off by one pixel would cost ~255 along every
    // edge and a mean of tens of levels.
    auto font = Font::open(kDejaVu);
    ASSERT_TRUE(font);
    GlyphRasterizer rasterizer(*font);
    for (char32_t ch : {U'g', U'W', U'&', U'e'}) {
        for (double sx : {0.0, 0.25, 0.5, 0.75}) {
            GlyphRenderOptions o;
            o.size_px = 24;
            o.offset_px.x = sx;
            GlyphId gid = *font->glyph_for_char(ch);
            auto box = rasterizer.measure(gid, o);
            ASSERT_TRUE(box);
            Mask ours(box->width, box->height), theirs(box->width, box->height);
            ASSERT_TRUE(rasterizer.render(gid, o, ours.view()));
            ASSERT_TRUE(render_with_freetype(*font, gid, {24}, theirs.view(),
                                                   {sx - box->left, static_cast<double>(box->top)}));
            Diff d = diff(ours.view(), theirs.view());
            EXPECT_LE(d.max, 20) << char(ch) << " at +" << sx;
            EXPECT_LE(d.mean, 3.0) << char(ch) << " at +" << sx;
        }
    }
}

TEST(GlyphRasterizer, RendersIntoTheCornerAndLeavesTheRestAlone) {
    auto font = Font::open(kDejaVu);
    ASSERT_TRUE(font);
    GlyphRasterizer rasterizer(*font);
    GlyphId gid = *font->glyph_for_char(U'o');
    GlyphRenderOptions o;
    o.size_px = 20;
    std::vector<std::uint8_t> buffer(40 * 30, 0x77);
    MaskView target{buffer.data(), 35, 30, 40};   // stride wider than the view
    auto box = rasterizer.render(gid, o, target);
    ASSERT_TRUE(box);
    for (int y = 0; y < 30; ++y)
        for (int x = 0; x < 40; ++x) {
            bool inside = x < box->width && y < box->height;
            if (!inside) {
                EXPECT_EQ(buffer[static_cast<std::size_t>(y * 40 + x)], 0x77) << x << "," << y;
            }
        }
    // The glyph touches every edge of its box (it is the smallest covering box).
    int top = 0, bottom = 0, left = 0, right = 0;
    for (int x = 0; x < box->width; ++x) {
        top += target.at(x, 0);
        bottom += target.at(x, box->height - 1);
    }
    for (int y = 0; y < box->height; ++y) {
        left += target.at(0, y);
        right += target.at(box->width - 1, y);
    }
    EXPECT_GT(top, 0);
    EXPECT_GT(bottom, 0);
    EXPECT_GT(left, 0);
    EXPECT_GT(right, 0);
}

long coverage_sum(ConstMaskView m) {
    long sum = 0;
    for (int y = 0; y < m.height; ++y)
        for (int x = 0; x < m.width; ++x) sum += m.at(x, y);
    return sum;
}

TEST(GlyphRasterizer, SubpixelOffsetMovesInkNotArea) {
    auto font = Font::open(kDejaVu);
    ASSERT_TRUE(font);
    GlyphRasterizer rasterizer(*font);
    GlyphId gid = *font->glyph_for_char(U'l');
    GlyphRenderOptions o;
    o.size_px = 30;
    std::vector<double> centroids;
    long area0 = -1;
    for (double sx : {0.0, 0.25, 0.5, 0.75}) {
        o.offset_px.x = sx;
        auto box = rasterizer.measure(gid, o);
        ASSERT_TRUE(box);
        Mask m(box->width, box->height);
        ASSERT_TRUE(rasterizer.render(gid, o, m.view()));
        long area = coverage_sum(m.view());
        if (area0 < 0) area0 = area;
        EXPECT_NEAR(area, area0, area0 / 200.0);
        double cx = 0;
        for (int y = 0; y < m.height(); ++y)
            for (int x = 0; x < m.width(); ++x) cx += (x + 0.5 + box->left) * m.at(x, y);
        centroids.push_back(cx / static_cast<double>(area));
    }
    // Pixel sampling of the box-filtered bar biases the centroid by a few hundredths of a pixel
    // (it is not shift-invariant), so each quarter step moves it 0.25 ± 0.08.
    for (std::size_t i = 1; i < centroids.size(); ++i)
        EXPECT_NEAR(centroids[i] - centroids[i - 1], 0.25, 0.08) << i;
}

TEST(GlyphRasterizer, LcdBoxIsPaddedAndKeepsTheInk) {
    auto font = Font::open(kDejaVu);
    ASSERT_TRUE(font);
    GlyphRasterizer rasterizer(*font);
    GlyphId gid = *font->glyph_for_char(U'a');
    GlyphRenderOptions gray;
    gray.size_px = 18;
    GlyphRenderOptions lcd = gray;
    lcd.fill.format = CoverageFormat::Lcd;
    auto g = rasterizer.measure(gid, gray);
    auto l = rasterizer.measure(gid, lcd);
    ASSERT_TRUE(g && l);
    EXPECT_EQ(l->left, g->left - kLcdPaddingPx);
    EXPECT_EQ(l->width, g->width + 2 * kLcdPaddingPx);
    EXPECT_EQ(l->top, g->top);
    Mask gm(g->width, g->height), lm(3 * l->width, l->height);
    ASSERT_TRUE(rasterizer.render(gid, gray, gm.view()));
    auto drawn = rasterizer.render(gid, lcd, lm.view());
    ASSERT_TRUE(drawn) << drawn.error().message;
    // Three subpixels per pixel, a filter of unit sum: three times the gray ink, within rounding.
    double ratio = static_cast<double>(coverage_sum(lm.view())) / static_cast<double>(coverage_sum(gm.view()));
    EXPECT_NEAR(ratio, 3.0, 0.05);
}

TEST(GlyphRasterizer, BlankGlyphHasAnAdvanceAndNoBox) {
    auto font = Font::open(kDejaVu);
    ASSERT_TRUE(font);
    GlyphRasterizer rasterizer(*font);
    GlyphRenderOptions o;
    o.size_px = 24;
    auto box = rasterizer.render(*font->glyph_for_char(U' '), o, MaskView{});
    ASSERT_TRUE(box) << box.error().message;
    EXPECT_EQ(box->width, 0);
    EXPECT_EQ(box->height, 0);
    EXPECT_NEAR(box->advance_px, 24 * 651.0 / 2048.0, 1e-6);   // DejaVu's space: 651 units of 2048
}

TEST(GlyphRasterizer, RefusesBadInput) {
    auto font = Font::open(kDejaVu);
    ASSERT_TRUE(font);
    GlyphRasterizer rasterizer(*font);
    GlyphId gid = *font->glyph_for_char(U'g');
    GlyphRenderOptions o;
    for (double bad : {std::nan(""), HUGE_VAL, -HUGE_VAL, 2 * kMaxGlyphOffsetPx}) {
        o.offset_px.x = bad;
        auto box = rasterizer.measure(gid, o);
        ASSERT_FALSE(box);
        EXPECT_NE(box.error().message.find("glyph " + std::to_string(gid)), std::string::npos);
    }
    o.offset_px.x = 0;
    o.fill.origin = {0.5, 0};   // the pen is offset_px's to place, not the fill's
    auto moved = rasterizer.measure(gid, o);
    ASSERT_FALSE(moved);
    EXPECT_NE(moved.error().message.find("fill.origin"), std::string::npos);
    o.fill.origin = {};
    o.fill.combine = CoverageCombine::Over;   // a glyph bitmap is its own coverage
    auto combined = rasterizer.measure(gid, o);
    ASSERT_FALSE(combined);
    EXPECT_NE(combined.error().message.find("fill.combine"), std::string::npos);
    o.fill.combine = CoverageCombine::Replace;
    std::uint8_t small[4] = {};
    auto box = rasterizer.render(gid, o, MaskView{small, 2, 2, 2});
    ASSERT_FALSE(box);
    EXPECT_NE(box.error().message.find("smaller"), std::string::npos);
    EXPECT_FALSE(rasterizer.measure(static_cast<GlyphId>(font->glyph_count()), o));
    o.size_px = 0;
    EXPECT_FALSE(rasterizer.measure(gid, o));
}

// The coverage-weighted mean column of row y (−1 for an empty row).
double row_centroid(const Mask& m, int y) {
    double sum = 0, weighted = 0;
    for (int x = 0; x < m.width(); ++x) {
        sum += m.at(x, y);
        weighted += m.at(x, y) * (x + 0.5);
    }
    return sum > 0 ? weighted / sum : -1;
}

TEST(GlyphRasterizer, SlantShearsTheInkAndKeepsItsArea) {
    auto font = Font::open(kDejaVu);
    ASSERT_TRUE(font);
    GlyphRasterizer rasterizer(*font);
    const GlyphId l = *font->glyph_for_char(U'l');   // one vertical stem
    GlyphRenderOptions upright;
    upright.size_px = 64;
    GlyphRenderOptions slanted = upright;
    slanted.slant = 0.25;
    auto render = [&](const GlyphRenderOptions& o, GlyphBox& box) {
        auto b = rasterizer.measure(l, o);
        EXPECT_TRUE(b);
        box = *b;
        Mask m(box.width, box.height);
        EXPECT_TRUE(rasterizer.render(l, o, m.view()));
        return m;
    };
    GlyphBox ub, sb;
    const Mask u = render(upright, ub), s = render(slanted, sb);
    double ink_u = 0, ink_s = 0;
    for (std::uint8_t v : u.pixels()) ink_u += v;
    for (std::uint8_t v : s.pixels()) ink_s += v;
    EXPECT_NEAR(ink_s / ink_u, 1.0, 0.01) << "a shear keeps areas";
    EXPECT_EQ(sb.top, ub.top);
    EXPECT_EQ(sb.height, ub.height);
    EXPECT_GT(sb.width, ub.width);
    // The stem's centre moves right by slant × height: compare the rows 4 px inside the top and
    // the bottom of the ink, in page columns (box.left + column).
    const int top = 4, bottom = sb.height - 5;
    const double rise = bottom - top;
    const double shift_top = (sb.left + row_centroid(s, top)) - (ub.left + row_centroid(u, top));
    const double shift_bottom =
        (sb.left + row_centroid(s, bottom)) - (ub.left + row_centroid(u, bottom));
    EXPECT_NEAR(shift_top - shift_bottom, 0.25 * rise, 0.1);
    // Out of range or not a number: an error naming the slant.
    for (double bad : {1.5, -1.01, std::nan("")}) {
        GlyphRenderOptions o = upright;
        o.slant = bad;
        auto box = rasterizer.measure(l, o);
        ASSERT_FALSE(box) << bad;
        EXPECT_NE(box.error().message.find("slant"), std::string::npos);
    }
}

// Issue 38 asked for hinting in the glyph path: GlyphRenderOptions::hinting reaches the outline
// the rasterizer fills (the Font's, loaded with that mode), and light hinting changes the pixels
// of 13 px UI text.
TEST(GlyphRasterizerHinting, EveryModeFillsTheOutlineTheFontLoadsWithIt) {
    auto font = Font::open(kDejaVu);
    ASSERT_TRUE(font);
    GlyphRasterizer r(*font);
    const GlyphId e = font->glyph_for_char(U'e').value();
    std::vector<std::vector<std::uint8_t>> masks;
    for (Hinting mode : {Hinting::None, Hinting::Light, Hinting::Full, Hinting::Auto}) {
        GlyphRenderOptions o;
        o.size_px = 13;
        o.hinting = mode;
        auto prepared = r.prepare(e, o);
        auto outline = font->outline(e, {13, mode});
        ASSERT_TRUE(prepared && outline);
        const Rect a = prepared->path.bounds(), b = outline->path.bounds();
        EXPECT_EQ(a.x0, b.x0) << hinting_name(mode);
        EXPECT_EQ(a.y0, b.y0) << hinting_name(mode);
        EXPECT_EQ(a.x1, b.x1) << hinting_name(mode);
        EXPECT_EQ(a.y1, b.y1) << hinting_name(mode);
        std::vector<std::uint8_t> pixels(
            static_cast<std::size_t>(prepared->box.width) * static_cast<std::size_t>(prepared->box.height));
        ASSERT_TRUE(r.draw(*prepared, {pixels.data(), prepared->box.width, prepared->box.height,
                                       prepared->box.width}));
        masks.push_back(pixels);
    }
    EXPECT_NE(masks[0], masks[1]) << "light hinting must change 13 px pixels";
}

// --- Embedded bitmap strikes (fonts-test/bitmap-strike: a 16 ppem 1-bit strike with A and B, a
// 20 ppem 8-bit strike with A; the bitmaps are patterns, not the outlines' rectangles) -----------

const std::string kStrikeFont = BEZEL_FONTS_DIR "/bitmap-strike/BitmapStrike.ttf";

// The make_font.py patterns: A at 16 ppem an 8x10 checkerboard, A at 20 ppem a 10x12 ramp.
std::vector<std::uint8_t> checkerboard() {
    std::vector<std::uint8_t> v;
    for (int y = 0; y < 10; ++y)
        for (int x = 0; x < 8; ++x) v.push_back((x + y) % 2 ? 255 : 0);
    return v;
}
std::vector<std::uint8_t> ramp() {
    std::vector<std::uint8_t> v;
    for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 10; ++x) v.push_back(static_cast<std::uint8_t>(x * 255 / 9));
    return v;
}

TEST(BitmapStrikes, FontReadsMonochromeAndGrayStrikesAtTheirOwnSize) {
    auto font = Font::open(kStrikeFont);
    ASSERT_TRUE(font) << font.error().message;
    EXPECT_TRUE(font->has_bitmap_strikes());
    const GlyphId a = font->glyph_for_char(U'A').value(), b = font->glyph_for_char(U'B').value();
    auto mono = font->strike_bitmap(a, 16);
    ASSERT_TRUE(mono) << mono.error().message;
    ASSERT_TRUE(mono->has_value());
    const StrikeBitmap& m = **mono;
    EXPECT_EQ(m.bit_depth, 1);
    EXPECT_EQ(m.ppem, 16);
    EXPECT_EQ(m.width, 8);
    EXPECT_EQ(m.height, 10);
    EXPECT_EQ(m.left, 1);
    EXPECT_EQ(m.top, 10);
    EXPECT_EQ(m.advance_px, 11);
    EXPECT_EQ(m.coverage, checkerboard());
    auto gray = font->strike_bitmap(a, 20);
    ASSERT_TRUE(gray && gray->has_value());
    EXPECT_EQ((*gray)->bit_depth, 8);
    EXPECT_EQ((*gray)->coverage, ramp());
    // No strike of 17 ppem (never a scaled strike), no image of B in the 20 ppem strike.
    auto none = font->strike_bitmap(a, 17);
    ASSERT_TRUE(none);
    EXPECT_FALSE(none->has_value());
    auto missing = font->strike_bitmap(b, 20);
    ASSERT_TRUE(missing);
    EXPECT_FALSE(missing->has_value());
    auto bad = font->strike_bitmap(a, -3);
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().message, kStrikeFont + ": font size -3 px out of range (0, 16384]");
    auto dejavu = Font::open(kDejaVu);
    ASSERT_TRUE(dejavu);
    EXPECT_FALSE(dejavu->has_bitmap_strikes());
}

TEST(BitmapStrikes, RasterizerDrawsTheStrikeOnlyWhenAsked) {
    auto font = Font::open(kStrikeFont);
    ASSERT_TRUE(font);
    GlyphRasterizer r(*font);
    const GlyphId a = font->glyph_for_char(U'A').value();
    GlyphRenderOptions o;
    o.size_px = 16;
    // Off by default: the outline (a 500x700-unit rectangle, 8x11.2 px: solid ink).
    auto outline = r.prepare(a, o);
    ASSERT_TRUE(outline);
    EXPECT_FALSE(outline->box.bitmap_strike);
    EXPECT_EQ(outline->box.height, 12);
    o.embedded_bitmaps = true;
    auto strike = r.prepare(a, o);
    ASSERT_TRUE(strike) << strike.error().message;
    EXPECT_TRUE(strike->box.bitmap_strike);
    EXPECT_EQ(strike->box.left, 1);
    EXPECT_EQ(strike->box.top, 10);
    EXPECT_EQ(strike->box.advance_px, 11);
    std::vector<std::uint8_t> pixels(80, 7);
    ASSERT_TRUE(r.draw(*strike, {pixels.data(), 8, 10, 8}));
    EXPECT_EQ(pixels, checkerboard());
    // The whole pixel nearest the pen; hinting and slant do not apply to it.
    o.offset_px = {0.6, 0.4};
    o.hinting = Hinting::Full;
    o.slant = 0.3;
    auto moved = r.prepare(a, o);
    ASSERT_TRUE(moved);
    EXPECT_EQ(moved->box.left, 2);
    EXPECT_EQ(moved->box.top, 10);
    // LCD: each coverage byte on all three subpixels, no padding.
    o.offset_px = {};
    o.fill.format = CoverageFormat::Lcd;
    std::vector<std::uint8_t> lcd(3 * 80, 7);
    auto box = r.render(a, o, {lcd.data(), 24, 10, 24});
    ASSERT_TRUE(box) << box.error().message;
    EXPECT_EQ(box->width, 8);
    for (std::size_t i = 0; i < 80; ++i) {
        EXPECT_EQ(lcd[3 * i], checkerboard()[i]);
        EXPECT_EQ(lcd[3 * i + 2], checkerboard()[i]);
    }
    // At a size without a strike, and for a glyph not in the strike: the outline.
    o = GlyphRenderOptions{};
    o.embedded_bitmaps = true;
    o.size_px = 20;
    auto b = r.prepare(font->glyph_for_char(U'B').value(), o);
    ASSERT_TRUE(b);
    EXPECT_FALSE(b->box.bitmap_strike);
    o.size_px = 16.5;
    auto between = r.prepare(a, o);
    ASSERT_TRUE(between);
    EXPECT_FALSE(between->box.bitmap_strike);
}

TEST(BitmapStrikes, CacheKeysTheStrikeChoice) {
    auto font = Font::open(kStrikeFont);
    ASSERT_TRUE(font);
    GlyphRasterizer r(*font);
    GlyphCache cache;
    const GlyphId a = font->glyph_for_char(U'A').value();
    GlyphRenderOptions o;
    o.size_px = 20;
    auto outline = cache.get(r, a, o);
    o.embedded_bitmaps = true;
    auto strike = cache.get(r, a, o);
    ASSERT_TRUE(outline && strike);
    EXPECT_EQ(cache.stats().misses, 2u);
    EXPECT_FALSE((*outline)->box.bitmap_strike);
    EXPECT_TRUE((*strike)->box.bitmap_strike);
    EXPECT_EQ(std::vector<std::uint8_t>((*strike)->mask.data, (*strike)->mask.data + 120), ramp());
}

// --- Glyph sets: GlyphRasterizer::prepare_set / draw_set and Rasterizer::fill_paths on glyphs ---

std::vector<GlyphId> ascii_glyphs(const Font& font) {
    std::vector<GlyphId> gids;
    for (char32_t c = 33; c < 127; ++c) gids.push_back(font.glyph_for_char(c).value());
    return gids;
}

// Each glyph of `glyphs` drawn by draw() into its own buffer, and by one draw_set call into
// another buffer and into an atlas: the same bytes, three ways.
void expect_set_equals_draw(GlyphRasterizer& rasterizer, const std::vector<PreparedGlyph>& glyphs,
                            const std::string& what) {
    const int bpp = glyphs.front().options.fill.format == CoverageFormat::Lcd ? 3 : 1;
    std::vector<Mask> alone, in_set;
    std::vector<GlyphDrawJob> jobs, atlas_jobs;
    int atlas_w = 0, atlas_h = 0;
    for (const PreparedGlyph& g : glyphs) {
        atlas_w += bpp * g.box.width + 1;   // one row of glyphs, a gap byte after each
        atlas_h = std::max(atlas_h, g.box.height);
    }
    Mask atlas(atlas_w, atlas_h, 0x5A);
    int x = 0;
    for (const PreparedGlyph& g : glyphs) {
        alone.emplace_back(bpp * g.box.width + 2, g.box.height + 1, 0xAB);   // a margin too
        in_set.emplace_back(bpp * g.box.width + 2, g.box.height + 1, 0xAB);
    }
    for (std::size_t k = 0; k < glyphs.size(); ++k) {
        const PreparedGlyph& g = glyphs[k];
        ASSERT_TRUE(rasterizer.draw(g, alone[k].view()).ok()) << what;
        jobs.push_back({&g, in_set[k].view()});
        atlas_jobs.push_back({&g, atlas.view().sub(x, 0, bpp * g.box.width, g.box.height)});
        x += bpp * g.box.width + 1;
    }
    ASSERT_TRUE(rasterizer.draw_set(jobs).ok()) << what;
    ASSERT_TRUE(rasterizer.draw_set(atlas_jobs).ok()) << what;
    x = 0;
    for (std::size_t k = 0; k < glyphs.size(); ++k) {
        const PreparedGlyph& g = glyphs[k];
        ASSERT_EQ(in_set[k].pixels(), alone[k].pixels()) << what << ", glyph " << g.gid;
        for (int y = 0; y < atlas_h; ++y)
            for (int i = 0; i <= bpp * g.box.width && x + i < atlas_w; ++i) {
                const bool in_box = i < bpp * g.box.width && y < g.box.height;
                ASSERT_EQ(atlas.view().at(x + i, y), in_box ? alone[k].view().at(i, y) : 0x5A)
                    << what << ", glyph " << g.gid << " atlas byte " << i << "," << y;
            }
        x += bpp * g.box.width + 1;
    }
}

TEST(GlyphSet, DrawSetGivesDrawsBytesForEveryAsciiGlyph) {
    // Sizes of the direct route's both regimes and a size whose boxes need several bands (the
    // general route), at a subpixel pen, both box modes, LCD, and synthetic bold (accurate
    // overlap): draw_set's bytes are draw()'s in separate buffers and in an atlas.
    for (const std::string& file : {kDejaVu, kCantarell}) {
        auto font = Font::open(file);
        ASSERT_TRUE(font);
        GlyphRasterizer rasterizer(*font);
        const std::vector<GlyphId> gids = ascii_glyphs(*font);
        std::vector<GlyphRenderOptions> variants;
        for (double size : {12.0, 16.0, 24.0, 150.0, 900.0}) {
            GlyphRenderOptions o;
            o.size_px = size;
            o.offset_px = {0.375, 0.25};
            o.box = size == 16.0 ? GlyphBoxMode::FreeType : GlyphBoxMode::Tight;
            variants.push_back(o);
        }
        variants.push_back(variants[1]);
        variants.back().fill.format = CoverageFormat::Lcd;
        variants.push_back(variants[2]);
        variants.back().bold = 0.04;
        for (const GlyphRenderOptions& o : variants) {
            std::vector<PreparedGlyph> glyphs;
            ASSERT_TRUE(rasterizer.prepare_set(gids.data(), gids.size(), o, glyphs).ok());
            ASSERT_EQ(glyphs.size(), gids.size());
            expect_set_equals_draw(rasterizer, glyphs,
                                   file + " at " + std::to_string(o.size_px) + " px");
        }
    }
}

TEST(GlyphSet, ColourGlyphsBetweenOutlineGlyphsAreDrawnAsDrawDrawsThem) {
    // A COLR glyph splits the run of outline glyphs around it: its alpha is draw()'s, and the
    // outline glyphs before and after it are too (one fill_paths call each side).
    auto font = Font::open(BEZEL_FONTS_DIR "/colour/test_glyphs-glyf_colr_1.ttf");
    ASSERT_TRUE(font) << font.error().message;
    GlyphRasterizer rasterizer(*font);
    GlyphRenderOptions o;
    o.size_px = 24;
    const GlyphId circles = font->glyph_for_char(0xF0E01).value();   // colored_circles_v1
    GlyphId a = 0;   // the first glyph drawn from its outline, with ink
    for (GlyphId g = 0; g < font->glyph_count() && a == 0; ++g) {
        auto box = rasterizer.measure(g, o);
        if (box && !box->color && box->width > 0) a = g;
    }
    ASSERT_NE(a, 0u);
    const std::vector<GlyphId> gids{a, circles, a, circles, a};
    std::vector<PreparedGlyph> glyphs;
    ASSERT_TRUE(rasterizer.prepare_set(gids.data(), gids.size(), o, glyphs).ok());
    ASSERT_TRUE(glyphs[1].box.color);
    ASSERT_FALSE(glyphs[0].box.color);
    expect_set_equals_draw(rasterizer, glyphs, "colour between outlines");
}

TEST(GlyphSet, ClippedAndHugeGlyphJobsTakeTheGeneralRouteWithFillPathsBytes) {
    // Glyph outlines as raw fill_paths jobs that the direct route refuses: overhanging a small
    // target (clipped) and scaled 40x into it (huge), mixed with jobs it takes.
    auto font = Font::open(kDejaVu);
    ASSERT_TRUE(font);
    GlyphRasterizer rasterizer(*font);
    GlyphRenderOptions o;
    o.size_px = 20;
    std::vector<PreparedGlyph> glyphs;
    const std::vector<GlyphId> gids = ascii_glyphs(*font);
    ASSERT_TRUE(rasterizer.prepare_set(gids.data(), gids.size(), o, glyphs).ok());
    std::vector<Mask> targets;
    std::vector<FillJob> jobs;
    for (std::size_t k = 0; k < glyphs.size(); ++k) targets.emplace_back(16, 14, 0xAB);
    for (std::size_t k = 0; k < glyphs.size(); ++k) {
        const PreparedGlyph& g = glyphs[k];
        const Affine inside = Affine::translate({-double(g.box.left), double(g.box.top)});
        const Affine m = k % 3 == 0 ? inside
                         : k % 3 == 1 ? Affine::translate({-6, 3}) * inside
                                      : Affine::scale(40) * Affine::translate({-5, 0}) * inside;
        jobs.push_back({&g.path, m, targets[k].view(), {0.5, 0.125}});
    }
    Rasterizer r;
    ASSERT_TRUE(r.fill_paths(jobs).ok());
    FillOptions fill;
    fill.origin = {0.5, 0.125};
    for (std::size_t k = 0; k < jobs.size(); ++k) {
        Mask alone(16, 14, 0xAB);
        ASSERT_TRUE(r.fill_path(*jobs[k].path, jobs[k].transform, alone.view(), fill).ok());
        ASSERT_EQ(targets[k].pixels(), alone.pixels()) << "job " << k;
    }
}

TEST(GlyphSet, BadJobsAreNamedBeforeAnyGlyphIsDrawn) {
    auto font = Font::open(kDejaVu);
    ASSERT_TRUE(font);
    GlyphRasterizer rasterizer(*font);
    GlyphRenderOptions o;
    o.size_px = 14;
    const std::vector<GlyphId> gids = ascii_glyphs(*font);
    std::vector<PreparedGlyph> glyphs;
    ASSERT_TRUE(rasterizer.prepare_set(gids.data(), 4, o, glyphs).ok());
    std::vector<Mask> targets(4, Mask(40, 40, 0xAB));
    std::vector<GlyphDrawJob> jobs;
    for (std::size_t k = 0; k < 4; ++k) jobs.push_back({&glyphs[k], targets[k].view()});
    const auto untouched = [&] {
        for (const Mask& t : targets)
            if (t.pixels() != std::vector<std::uint8_t>(1600, 0xAB)) return false;
        return true;
    };
    jobs[3].target = targets[3].view().sub(0, 0, 2, 2);   // smaller than the glyph
    Status s = rasterizer.draw_set(jobs);
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message.find("glyph set job 3 (glyph " + std::to_string(glyphs[3].gid) +
                                     "): target 2x2 is smaller"),
              std::string::npos) << s.error().message;
    EXPECT_TRUE(untouched());
    jobs[3].target = targets[3].view();
    jobs[2].glyph = nullptr;
    s = rasterizer.draw_set(jobs);
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message.find("glyph set job 2: the glyph is null"), std::string::npos)
        << s.error().message;
    EXPECT_TRUE(untouched());
    // A glyph id past the font's: prepare_set names its index and the glyph.
    std::vector<GlyphId> bad{gids[0], gids[1], static_cast<GlyphId>(font->glyph_count() + 5)};
    s = rasterizer.prepare_set(bad.data(), bad.size(), o, glyphs);
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().message.rfind("prepare_set: job 2: ", 0), 0u) << s.error().message;
    EXPECT_NE(s.error().message.find("glyph id " + std::to_string(bad[2])), std::string::npos)
        << s.error().message;
    EXPECT_EQ(glyphs.size(), 2u);
    // An empty set is a success.
    EXPECT_TRUE(rasterizer.draw_set(nullptr, 0).ok());
    EXPECT_TRUE(rasterizer.prepare_set(nullptr, 0, o, glyphs).ok());
    EXPECT_TRUE(glyphs.empty());
}

TEST(GlyphSet, WarmSetsAllocateNothing) {
    // Once its scratch has grown, a set of the same glyphs (and a smaller one) allocates nothing:
    // neither draw_set's job list nor fill_paths' fill.
    auto font = Font::open(kCantarell);
    ASSERT_TRUE(font);
    GlyphRasterizer rasterizer(*font);
    GlyphRenderOptions o;
    o.size_px = 18;
    const std::vector<GlyphId> gids = ascii_glyphs(*font);
    std::vector<PreparedGlyph> glyphs;
    ASSERT_TRUE(rasterizer.prepare_set(gids.data(), gids.size(), o, glyphs).ok());
    std::vector<Mask> targets;
    for (const PreparedGlyph& g : glyphs) targets.emplace_back(g.box.width, g.box.height);
    std::vector<GlyphDrawJob> jobs;
    std::vector<FillJob> fill_jobs;
    for (std::size_t k = 0; k < glyphs.size(); ++k) {
        jobs.push_back({&glyphs[k], targets[k].view()});
        fill_jobs.push_back({&glyphs[k].path, Affine::translate({0, 0}), targets[k].view(), {}});
    }
    Rasterizer r;
    ASSERT_TRUE(rasterizer.draw_set(jobs).ok());
    ASSERT_TRUE(r.fill_paths(fill_jobs).ok());
    const long before = g_allocations.load();
    for (int rep = 0; rep < 3; ++rep) {
        ASSERT_TRUE(rasterizer.draw_set(jobs).ok());
        ASSERT_TRUE(rasterizer.draw_set(jobs.data(), jobs.size() / 2).ok());
        ASSERT_TRUE(r.fill_paths(fill_jobs).ok());
    }
    EXPECT_EQ(g_allocations.load() - before, 0);
}

}  // namespace
}  // namespace bezel
