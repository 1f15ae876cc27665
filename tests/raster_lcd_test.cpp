// LCD subpixel fills (Rasterizer::fill_path with CoverageFormat::Lcd) and the GammaTable.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <vector>

#include "bezel/image.hpp"
#include "bezel/raster.hpp"
#include "support/shapes.hpp"

namespace bezel {
namespace {

using test::add_rect;

Path circle(Point c, double radius) {
    Path p;
    test::add_circle(p, c, radius);
    return p;
}

FillOptions lcd_options(LcdOrder order = LcdOrder::Rgb,
                        OverlapMode mode = OverlapMode::Accumulate) {
    FillOptions o;
    o.rule = FillRule::NonZero;
    o.overlap = mode;
    o.format = CoverageFormat::Lcd;
    o.lcd_order = order;
    return o;
}

Mask lcd(Rasterizer& r, const Path& p, int display_w, int h, LcdOrder order = LcdOrder::Rgb,
         OverlapMode mode = OverlapMode::Accumulate) {
    Mask m(display_w * 3, h);
    EXPECT_TRUE(r.fill_path(p, Affine::identity(), m.view(), lcd_options(order, mode)).ok());
    return m;
}

TEST(Lcd, DefaultFilterIsFreeTypesAndSumsTo256) {
    const LcdFilter f = kLcdFilterDefault;
    EXPECT_EQ(f.taps[0], 0x08);
    EXPECT_EQ(f.taps[2], 0x56);
    EXPECT_EQ(std::accumulate(f.taps.begin(), f.taps.end(), 0), 256);
}

TEST(Lcd, FullCoverageInteriorIs255InEveryChannel) {
    Path p;
    add_rect(p, 1.0, 1.0, 11.0, 7.0);
    Rasterizer r;
    const Mask m = lcd(r, p, 12, 8);
    // A subpixel is 255 when all five subpixels its filter reads are covered.
    for (int y = 1; y < 7; ++y)
        for (int k = 3 + 2; k < 33 - 2; ++k) ASSERT_EQ(m.at(k, y), 255) << k << "," << y;
    EXPECT_EQ(m.at(0, 0), 0);
    EXPECT_EQ(m.at(35, 7), 0);
}

TEST(Lcd, VerticalEdgeProfileMatchesHandComputation) {
    // Left edge at display x = 4.75/3: subpixel 4 is 1/4 covered, 5 and on fully.
    Path p;
    add_rect(p, 4.75 / 3.0, 0.0, 20.0, 2.0);
    Rasterizer r;
    const Mask m = lcd(r, p, 8, 2);
    // out[k] = round(255/256 · Σ taps[j]·s[k−2+j]), s = 0, 0, 0, 0, 0.25, 1, 1, …
    //   k=2: 8·0.25 = 2            → 1.99  → 2
    //   k=3: 77·0.25 + 8 = 27.25   → 27.14 → 27
    //   k=4: 86·0.25 + 77 + 8 = 106.5 → 106.08 → 106
    //   k=5: 77·0.25 + 86 + 77 + 8 = 190.25 → 189.5 (+0.008) → 190
    //   k=6: 8·0.25 + 77 + 86 + 77 + 8 = 250 → 249.02 → 249
    //   k=7: 256 → 255
    const int want[] = {0, 0, 2, 27, 106, 190, 249, 255, 255};
    for (int k = 0; k < 9; ++k) EXPECT_EQ(m.at(k, 1), want[k]) << "subpixel " << k;
}

TEST(Lcd, BytesAreSubpixelsLeftToRightForEitherPanel) {
    // Byte 3x + k is subpixel k of display pixel x: the Bgr mask is the Rgb mask (its bytes are
    // B, G, R because that panel's subpixels are), and it is not symmetric, so order would show.
    const Path p = circle({7.3, 6.1}, 4.6);
    Rasterizer r;
    const Mask rgb = lcd(r, p, 15, 13, LcdOrder::Rgb);
    const Mask bgr = lcd(r, p, 15, 13, LcdOrder::Bgr);
    EXPECT_EQ(bgr, rgb);
    int colourful = 0;
    for (int y = 0; y < 13; ++y)
        for (int x = 0; x < 15; ++x) colourful += rgb.at(3 * x, y) != rgb.at(3 * x + 2, y);
    EXPECT_GT(colourful, 10);
    // The left edge of the disc lights the leftmost subpixel of its pixel more than the right.
    const int y = 6, x = 2;   // the disc spans x ∈ [2.7, 11.9] on row 6
    EXPECT_LT(rgb.at(3 * x, y), rgb.at(3 * x + 2, y));
}

TEST(Lcd, FilterKeepsTotalCoverage) {
    // The filter sums to 256: with the outline a display pixel inside the target on each side,
    // Σ filtered bytes = 255 · Σ 3×-sampled coverage, up to ½ per byte of rounding.
    const Path p = circle({9.37, 8.21}, 6.4);
    Rasterizer r;
    const Mask m = lcd(r, p, 19, 18);
    std::vector<float> samples(57 * 18);
    ASSERT_TRUE(r.fill_path(p, Affine::scale(3.0, 1.0), FloatMaskView{samples.data(), 57, 18, 57},
                            {FillRule::NonZero})
                    .ok());
    double total_samples = 0, total_out = 0;
    int nonzero = 0;
    for (float s : samples) total_samples += s;
    for (std::uint8_t v : m.pixels()) {
        total_out += v;
        nonzero += v != 0;
    }
    EXPECT_NEAR(total_out, 255.0 * total_samples, 0.5 * nonzero);
    EXPECT_NEAR(total_out / (255.0 * total_samples), 1.0, 2e-3);
}

TEST(Lcd, AccurateOverlapRendersDoubledShapeLikeOne) {
    Path one, two;
    add_rect(one, 2.2, 1.6, 7.7, 5.3);
    add_rect(two, 2.2, 1.6, 7.7, 5.3);
    add_rect(two, 2.2, 1.6, 7.7, 5.3);
    Rasterizer r;
    const Mask single = lcd(r, one, 10, 7);
    EXPECT_EQ(lcd(r, two, 10, 7, LcdOrder::Rgb, OverlapMode::Accurate), single);
    EXPECT_NE(lcd(r, two, 10, 7, LcdOrder::Rgb, OverlapMode::Accumulate), single);
}

TEST(Lcd, TallTargetsUseBandsWithTheSameResult) {
    // 600 × 3 + 4 floats per row: a 200-row target takes several bands of kMaxBandCells.
    const Path p = circle({300.4, 100.3}, 95.0);
    Rasterizer r;
    const Mask m = lcd(r, p, 600, 200);
    // Rows are independent: the same circle moved down by 90 rows gives the same rows.
    Path q = p.transformed(Affine::translate({0, 90.0}));
    Mask moved(1800, 290);
    ASSERT_TRUE(r.fill_path(q, Affine::identity(), moved.view(), lcd_options()).ok());
    for (int y = 0; y < 200; y += 7)
        for (int k = 0; k < 1800; ++k) ASSERT_EQ(moved.at(k, y + 90), m.at(k, y)) << k << "," << y;
}

TEST(Lcd, Errors) {
    Path p;
    add_rect(p, 1, 1, 2, 2);
    Rasterizer r;
    Mask m(10, 4);  // not a multiple of 3
    EXPECT_FALSE(r.fill_path(p, Affine::identity(), m.view(), lcd_options()).ok());
    EXPECT_FALSE(
        r.fill_path(p, Affine::identity(), MaskView{nullptr, 9, 4, 9}, lcd_options()).ok());
    Mask ok(9, 4);
    ok.at(0, 0) = 9;
    const Affine bad{1, 0, 0, 1, HUGE_VAL, 0};
    EXPECT_FALSE(r.fill_path(p, bad, ok.view(), lcd_options()).ok());
    EXPECT_EQ(ok.at(0, 0), 9);
    EXPECT_FALSE(r.fill_path(p, Affine::identity(),
                             MaskView{ok.view().data, 3 * kMaxBitmapDim, 1, 9}, lcd_options())
                     .ok());
}

TEST(Gamma, IdentityAtGammaOneContrastZero) {
    const GammaTable g;
    for (int c = 0; c < 256; ++c) EXPECT_EQ(g(static_cast<std::uint8_t>(c)), c);
}

TEST(Gamma, MonotoneWithFixedEndsForManySettings) {
    for (double gamma : {0.3, 0.8, 1.0, 1.43, 2.2, 4.0})
        for (double contrast : {0.0, 0.25, 0.5, 1.0}) {
            const GammaTable g(gamma, contrast);
            EXPECT_EQ(g(0), 0);
            EXPECT_EQ(g(255), 255);
            for (int c = 1; c < 256; ++c)
                ASSERT_GE(g.table()[c], g.table()[c - 1]) << gamma << " " << contrast << " at " << c;
        }
}

TEST(Gamma, KnownValues) {
    // 255·(128/255)^(1/2.2) = 186.4; with contrast 1 at gamma 1: g + g(1 − g) for g = 128/255.
    EXPECT_EQ(GammaTable(2.2)(128), 186);
    EXPECT_EQ(GammaTable(1.0, 1.0)(128), 192);
    EXPECT_LT(GammaTable(0.5)(128), 128);  // gamma < 1 thins
    // Out-of-range settings fall back: gamma → 1, contrast clamped.
    EXPECT_EQ(GammaTable(-1.0)(100), 100);
    EXPECT_EQ(GammaTable(NAN, NAN)(100), 100);
    EXPECT_EQ(GammaTable(1.0, 7.0).table(), GammaTable(1.0, 1.0).table());
}

TEST(Gamma, ApplyMapsEveryPixelOfAStridedView) {
    std::vector<std::uint8_t> buf(5 * 3, 128);
    const MaskView view{buf.data(), 4, 3, 5};  // the fifth byte of each row is not in the view
    GammaTable(2.2).apply(view);
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 4; ++x) EXPECT_EQ(buf[y * 5 + x], 186);
        EXPECT_EQ(buf[y * 5 + 4], 128);
    }
}

}  // namespace
}  // namespace bezel
