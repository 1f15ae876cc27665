// FillOptions, the one options struct of every fill: its defaults are the plain fill; an origin
// on fill_path is the transform's translation moved (the same bits, in every format); Accurate
// overlap into a float target is the byte fill's coverage unquantized; every combination a fill
// does not implement is an Error that names it and leaves the target alone.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "bezel/diagnostics.hpp"
#include "bezel/raster.hpp"
#include "support/shapes.hpp"

namespace bezel {
namespace {

using test::add_circle;
using test::add_rect;

// Two overlapping discs and a square: curves, and overlaps for OverlapMode::Accurate to resolve.
Path shapes() {
    Path p;
    add_circle(p, {8.3, 9.1}, 5.2);
    add_circle(p, {12.6, 10.4}, 4.7);
    add_rect(p, 3.25, 14.5, 9.75, 19.125);
    return p;
}

Polylines square() {
    Polylines lines;
    lines.points = {{1.5, 1.5}, {4.5, 1.5}, {4.5, 4.5}, {1.5, 4.5}};
    lines.contour_ends = {4};
    return lines;
}

FillOptions with(OverlapMode overlap, CoverageFormat format = CoverageFormat::Gray,
                 LcdOrder order = LcdOrder::Rgb) {
    FillOptions o;
    o.overlap = overlap;
    o.format = format;
    o.lcd_order = order;
    return o;
}

TEST(FillOptions, DefaultsAreThePlainFill) {
    const FillOptions o;
    EXPECT_EQ(o.rule, FillRule::NonZero);
    EXPECT_EQ(o.overlap, OverlapMode::Accumulate);
    EXPECT_EQ(o.flatten.tolerance_px, kDefaultRasterTolerancePx);
    EXPECT_EQ(o.flatten.method, FlattenMethod::WangUniform);
    EXPECT_EQ(o.flatten.classic_flatness_epsilon, kDefaultClassicFlatnessEpsilon);
    EXPECT_EQ(o.origin.x, 0.0);
    EXPECT_EQ(o.origin.y, 0.0);
    EXPECT_EQ(o.format, CoverageFormat::Gray);
    EXPECT_EQ(o.lcd_order, LcdOrder::Rgb);
    EXPECT_EQ(o.lcd_filter.taps, kLcdFilterDefault.taps);
}

// The origin of fill_path is added to the transform's translation: the same bits as a caller
// folding it in, for bytes, floats, accurate overlap and LCD, at subpixel and whole offsets.
TEST(FillOptions, FillPathOriginIsTheTransformMovedBitForBit) {
    const Path p = shapes();
    const Affine base = Affine::translate({1.0, -0.5}) * Affine::rotate(0.3) *
                        Affine::scale(0.9, 1.1);
    const Vec2 origins[] = {{0.25, 0.5}, {-3.75, 2.125}, {1e-3, 7.0}, {0.1, -0.3}};
    Rasterizer r;
    for (Vec2 origin : origins) {
        Affine moved = base;
        moved.e += origin.x;
        moved.f += origin.y;
        for (OverlapMode overlap : {OverlapMode::Accumulate, OverlapMode::Accurate}) {
            FillOptions o = with(overlap);
            Mask a(24, 26), b(24, 26);
            o.origin = origin;
            ASSERT_TRUE(r.fill_path(p, base, a.view(), o).ok());
            o.origin = {};
            ASSERT_TRUE(r.fill_path(p, moved, b.view(), o).ok());
            EXPECT_EQ(a, b) << origin.x << "," << origin.y;

            std::vector<float> fa(24 * 26, -1.0f), fb(24 * 26, -2.0f);
            o.origin = origin;
            ASSERT_TRUE(r.fill_path(p, base, FloatMaskView{fa.data(), 24, 26, 24}, o).ok());
            o.origin = {};
            ASSERT_TRUE(r.fill_path(p, moved, FloatMaskView{fb.data(), 24, 26, 24}, o).ok());
            EXPECT_EQ(std::memcmp(fa.data(), fb.data(), fa.size() * sizeof(float)), 0);

            for (LcdOrder order : {LcdOrder::Rgb, LcdOrder::Bgr}) {
                FillOptions lcd = with(overlap, CoverageFormat::Lcd, order);
                Mask la(3 * 26, 26), lb(3 * 26, 26);
                lcd.origin = origin;
                ASSERT_TRUE(r.fill_path(p, base, la.view(), lcd).ok());
                lcd.origin = {};
                ASSERT_TRUE(r.fill_path(p, moved, lb.view(), lcd).ok());
                EXPECT_EQ(la, lb);
            }
        }
    }
}

TEST(FillOptions, NonFiniteOriginOnFillPathIsAnErrorAndLeavesTheTarget) {
    const Path p = shapes();
    Rasterizer r;
    for (double bad : {std::nan(""), HUGE_VAL, -HUGE_VAL}) {
        FillOptions o;
        o.origin = {0.5, bad};
        Mask m(24, 24);
        m.at(3, 3) = 77;
        Status s = r.fill_path(p, Affine::identity(), m.view(), o);
        ASSERT_FALSE(s.ok());
        EXPECT_NE(s.error().message.find("origin"), std::string::npos) << s.error().message;
        EXPECT_EQ(m.at(3, 3), 77);

        std::vector<float> f(24 * 24, -1.0f);
        EXPECT_FALSE(r.fill_path(p, Affine::identity(), FloatMaskView{f.data(), 24, 24, 24}, o));
        EXPECT_EQ(f[0], -1.0f);

        o.format = CoverageFormat::Lcd;
        Mask lcd(72, 24);
        lcd.at(3, 3) = 77;
        EXPECT_FALSE(r.fill_path(p, Affine::identity(), lcd.view(), o));
        EXPECT_EQ(lcd.at(3, 3), 77);
    }
}

// Float coverage with accurate overlap: the bytes' coverage before rounding, and the overlap
// resolved (two copies of a square with edges at x = 1.5: Accumulate counts the edge pixel twice).
TEST(FillOptions, AccurateIntoAFloatTargetIsTheByteFillUnquantized) {
    Path twice;
    add_rect(twice, 1.5, 1.0, 5.5, 5.0);
    add_rect(twice, 1.5, 1.0, 5.5, 5.0);
    Rasterizer r;
    std::vector<float> acc(8 * 6), exact(8 * 6);
    ASSERT_TRUE(r.fill_path(twice, Affine::identity(), FloatMaskView{acc.data(), 8, 6, 8}).ok());
    ASSERT_TRUE(r.fill_path(twice, Affine::identity(), FloatMaskView{exact.data(), 8, 6, 8},
                            with(OverlapMode::Accurate))
                    .ok());
    EXPECT_FLOAT_EQ(acc[2 * 8 + 1], 1.0f);
    EXPECT_FLOAT_EQ(exact[2 * 8 + 1], 0.5f);
    EXPECT_FLOAT_EQ(exact[2 * 8 + 3], 1.0f);

    const Path p = shapes();
    Mask bytes(24, 24);
    std::vector<float> f(24 * 24);
    ASSERT_TRUE(r.fill_path(p, Affine::identity(), bytes.view(), with(OverlapMode::Accurate)).ok());
    ASSERT_TRUE(r.fill_path(p, Affine::identity(), FloatMaskView{f.data(), 24, 24, 24},
                            with(OverlapMode::Accurate))
                    .ok());
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 24; ++x) {
            const float c = f[static_cast<std::size_t>(y) * 24 + x];
            ASSERT_GE(c, 0.0f);
            ASSERT_LE(c, 1.0f);
            ASSERT_NEAR(c * 255.0, bytes.at(x, y), 0.5 + 1e-4) << x << "," << y;
        }
}

// What no fill implements is an Error naming the option; the target is left as it was.
TEST(FillOptions, AccurateOverlapOfPolylinesIsAnErrorNamingIt) {
    Rasterizer r;
    Mask m(6, 6);
    m.at(2, 2) = 9;
    Status s = r.fill(square(), m.view(), with(OverlapMode::Accurate));
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message.find("OverlapMode::Accurate"), std::string::npos)
        << s.error().message;
    EXPECT_EQ(m.at(2, 2), 9);

    std::vector<float> f(36, -1.0f);
    s = r.fill(square(), FloatMaskView{f.data(), 6, 6, 6}, with(OverlapMode::Accurate));
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message.find("OverlapMode::Accurate"), std::string::npos);
    EXPECT_EQ(f[14], -1.0f);
}

TEST(FillOptions, LcdCoverageOfPolylinesIsAnErrorNamingIt) {
    Rasterizer r;
    Mask m(18, 6);
    m.at(2, 2) = 9;
    Status s = r.fill(square(), m.view(), with(OverlapMode::Accumulate, CoverageFormat::Lcd));
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message.find("CoverageFormat::Lcd"), std::string::npos)
        << s.error().message;
    EXPECT_EQ(m.at(2, 2), 9);

    std::vector<float> f(36, -1.0f);
    s = r.fill(square(), FloatMaskView{f.data(), 6, 6, 6},
               with(OverlapMode::Accumulate, CoverageFormat::Lcd));
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message.find("CoverageFormat::Lcd"), std::string::npos);
    EXPECT_EQ(f[14], -1.0f);
}

TEST(FillOptions, LcdCoverageIntoAFloatTargetIsAnErrorNamingIt) {
    Rasterizer r;
    std::vector<float> f(18 * 6, -1.0f);
    for (OverlapMode overlap : {OverlapMode::Accumulate, OverlapMode::Accurate}) {
        Status s = r.fill_path(shapes(), Affine::identity(), FloatMaskView{f.data(), 18, 6, 18},
                               with(overlap, CoverageFormat::Lcd));
        ASSERT_FALSE(s.ok());
        EXPECT_NE(s.error().message.find("CoverageFormat::Lcd"), std::string::npos)
            << s.error().message;
        for (float v : f) ASSERT_EQ(v, -1.0f);
    }
}

// The scratch of the LCD and accurate fills moves with the Rasterizer.
TEST(FillOptions, RasterizerMovesWithItsScratch) {
    const Path p = shapes();
    const FillOptions lcd = with(OverlapMode::Accurate, CoverageFormat::Lcd, LcdOrder::Bgr);
    Rasterizer first;
    Mask want(72, 24), gray_want(24, 24);
    ASSERT_TRUE(first.fill_path(p, Affine::identity(), want.view(), lcd).ok());
    ASSERT_TRUE(first.fill_path(p, Affine::identity(), gray_want.view(),
                                with(OverlapMode::Accurate))
                    .ok());
    const std::size_t held = first.scratch_capacity_bytes();

    Rasterizer second(std::move(first));
    EXPECT_EQ(second.scratch_capacity_bytes(), held);
    Mask got(72, 24);
    ASSERT_TRUE(second.fill_path(p, Affine::identity(), got.view(), lcd).ok());
    EXPECT_EQ(got, want);

    Rasterizer third;
    third = std::move(second);
    Mask gray(24, 24);
    ASSERT_TRUE(third.fill_path(p, Affine::identity(), gray.view(), with(OverlapMode::Accurate))
                    .ok());
    EXPECT_EQ(gray, gray_want);
}

TEST(Diagnostics, RasterKernelNameIsAKnownLevel) {
    const std::string name = raster_kernel_name();
    EXPECT_TRUE(name == "avx2" || name == "sse2") << name;
}

}  // namespace
}  // namespace bezel
