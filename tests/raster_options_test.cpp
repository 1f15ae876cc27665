// FillOptions, the one options struct of every fill: its defaults are the plain fill; an origin
// on fill_path is the transform's translation moved (the same bits, in every format); Accurate
// overlap into a float target is the byte fill's coverage unquantized; every combination a fill
// does not implement is an Error that names it and leaves the target alone; Over and Add combine
// a fill with the coverage the target holds by their formulas.
#include <gtest/gtest.h>

#include <algorithm>
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
    EXPECT_EQ(o.combine, CoverageCombine::Replace);
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

// --- CoverageCombine: drawing into a target that already holds coverage -----------------------

Path disc(Point c, double r) {
    Path p;
    add_circle(p, c, r);
    return p;
}

FillOptions combining(CoverageCombine rule, CoverageFormat format = CoverageFormat::Gray) {
    FillOptions o;
    o.combine = rule;
    o.format = format;
    return o;
}

// One shape filled on its own (Replace) into a w × h mask.
Mask alone(Rasterizer& r, const Path& p, int w, int h, const FillOptions& o = {}) {
    Mask m(w, h);
    FillOptions replace = o;
    replace.combine = CoverageCombine::Replace;
    EXPECT_TRUE(r.fill_path(p, Affine(), m.view(), replace).ok());
    return m;
}

TEST(CoverageCombine, ReplaceIsTheDefaultAndClearsTheTarget) {
    Rasterizer r;
    Mask m(20, 20, 77);
    ASSERT_TRUE(r.fill_path(disc({5.3, 6.1}, 3.2), Affine(), m.view()).ok());
    EXPECT_EQ(m, alone(r, disc({5.3, 6.1}, 3.2), 20, 20));
    EXPECT_EQ(m.at(19, 19), 0);
}

TEST(CoverageCombine, TwoDisjointShapesEqualEachAlone) {
    // Two icons into one mask: every pixel is the one shape's coverage that reaches it, as that
    // shape filled alone gives it.
    Rasterizer r;
    const Path a = disc({6.2, 7.4}, 4.1), b = disc({19.7, 12.3}, 5.6);
    const Mask ma = alone(r, a, 28, 20), mb = alone(r, b, 28, 20);
    for (CoverageCombine rule : {CoverageCombine::Over, CoverageCombine::Add}) {
        Mask m(28, 20);
        ASSERT_TRUE(r.fill_path(a, Affine(), m.view(), combining(rule)).ok());
        ASSERT_TRUE(r.fill_path(b, Affine(), m.view(), combining(rule)).ok());
        int inked = 0;
        for (int y = 0; y < 20; ++y)
            for (int x = 0; x < 28; ++x) {
                ASSERT_TRUE(ma.at(x, y) == 0 || mb.at(x, y) == 0);
                ASSERT_EQ(m.at(x, y), ma.at(x, y) + mb.at(x, y)) << x << "," << y;
                inked += m.at(x, y) != 0;
            }
        EXPECT_GT(inked, 100);
    }
}

TEST(CoverageCombine, OverlappingShapesFollowTheFormula) {
    Rasterizer r;
    const Path a = disc({8.3, 9.1}, 5.2), b = disc({12.6, 10.4}, 4.7);
    const Mask ma = alone(r, a, 24, 20), mb = alone(r, b, 24, 20);
    Mask over = ma, add = ma;
    ASSERT_TRUE(r.fill_path(b, Affine(), over.view(), combining(CoverageCombine::Over)).ok());
    ASSERT_TRUE(r.fill_path(b, Affine(), add.view(), combining(CoverageCombine::Add)).ok());
    int both = 0;
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 24; ++x) {
            const int av = ma.at(x, y), bv = mb.at(x, y);
            ASSERT_EQ(over.at(x, y), av + bv - (av * bv + 127) / 255) << x << "," << y;
            ASSERT_EQ(add.at(x, y), std::min(av + bv, 255)) << x << "," << y;
            both += av > 0 && av < 255 && bv > 0 && bv < 255;
        }
    EXPECT_GE(both, 3);   // edge pixels of both shapes, where the rules differ
    // Float targets: the same rules on unquantized coverage.
    std::vector<float> fa(24 * 20), fb(24 * 20), f(24 * 20);
    const FloatMaskView va{fa.data(), 24, 20, 24}, vb{fb.data(), 24, 20, 24}, v{f.data(), 24, 20, 24};
    ASSERT_TRUE(r.fill_path(a, Affine(), va).ok());
    ASSERT_TRUE(r.fill_path(b, Affine(), vb).ok());
    ASSERT_TRUE(r.fill_path(a, Affine(), v).ok());
    ASSERT_TRUE(r.fill_path(b, Affine(), v, combining(CoverageCombine::Over)).ok());
    for (std::size_t i = 0; i < f.size(); ++i)
        ASSERT_NEAR(f[i], fa[i] + fb[i] - fa[i] * fb[i], 1e-6) << i;
}

TEST(CoverageCombine, AddJoinsTilesSharingAnEdgeWithoutASeam) {
    // Two rectangles meeting at x = 5.5: the pixel column they share is half covered by each.
    Rasterizer r;
    Path left, right;
    add_rect(left, 1, 1, 5.5, 6);
    add_rect(right, 5.5, 1, 9, 6);
    Mask add(10, 7), over(10, 7);
    for (const Path* p : {&left, &right}) {
        ASSERT_TRUE(r.fill_path(*p, Affine(), add.view(), combining(CoverageCombine::Add)).ok());
        ASSERT_TRUE(r.fill_path(*p, Affine(), over.view(), combining(CoverageCombine::Over)).ok());
    }
    EXPECT_EQ(add.at(5, 3), 255);
    EXPECT_EQ(over.at(5, 3), 128 + 128 - (128 * 128 + 127) / 255);   // the seam Over leaves
}

TEST(CoverageCombine, LcdAndPolylineFillsCombineToo) {
    Rasterizer r;
    const Path a = disc({5.2, 5.1}, 3.4), b = disc({8.1, 6.3}, 3.0);
    const FillOptions lcd = combining(CoverageCombine::Over, CoverageFormat::Lcd);
    const Mask la = alone(r, a, 3 * 14, 12, lcd), lb = alone(r, b, 3 * 14, 12, lcd);
    Mask m = la;
    ASSERT_TRUE(r.fill_path(b, Affine(), m.view(), lcd).ok());
    for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 3 * 14; ++x) {
            const int av = la.at(x, y), bv = lb.at(x, y);
            ASSERT_EQ(m.at(x, y), av + bv - (av * bv + 127) / 255) << x << "," << y;
        }
    // Polylines: a square over a mask of 100 everywhere.
    Mask s(8, 8), t(8, 8, 100);
    ASSERT_TRUE(r.fill(square(), s.view()).ok());
    ASSERT_TRUE(r.fill(square(), t.view(), combining(CoverageCombine::Add)).ok());
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) ASSERT_EQ(t.at(x, y), std::min(100 + s.at(x, y), 255));
}

TEST(CoverageCombine, ErrorsAndShapesOffTheTargetLeaveItAlone) {
    Rasterizer r;
    Mask m(12, 12, 40);
    const Mask before = m;
    Path bad;
    add_circle(bad, {50, 50}, 3);   // off the target
    ASSERT_TRUE(r.fill_path(bad, Affine(), m.view(), combining(CoverageCombine::Over)).ok());
    EXPECT_EQ(m, before);
    bad.line_to({std::nan(""), 2});
    EXPECT_FALSE(r.fill_path(bad, Affine(), m.view(), combining(CoverageCombine::Over)).ok());
    EXPECT_FALSE(r.fill_path(disc({5, 5}, 3), Affine(), MaskView{nullptr, 4, 4, 4},
                             combining(CoverageCombine::Over)).ok());
    FillOptions lcd = combining(CoverageCombine::Add, CoverageFormat::Lcd);
    Mask odd(13, 4);
    auto st = r.fill_path(disc({2, 2}, 1), Affine(), odd.view(), lcd);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().message.find("multiple of 3"), std::string::npos);
    EXPECT_EQ(m, before);
}

TEST(Diagnostics, RasterKernelNameIsAKnownLevel) {
    const std::string name = raster_kernel_name();
    EXPECT_TRUE(name == "avx2" || name == "sse2") << name;
}

}  // namespace
}  // namespace bezel
