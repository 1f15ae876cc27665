// OverlapMode::Accurate: coverage of the filled REGION, not of the winding-weighted area.
//
// References: the union of two axis-aligned rectangles has an exact coverage per pixel
// (inclusion–exclusion), which checks the edge-case font's overlapping 'O' with no supersampling
// in between; other shapes are checked against the 16×16 box-filtered render.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "bezel/font.hpp"
#include "bezel/image.hpp"
#include "bezel/raster.hpp"

namespace bezel {
namespace {

struct Box {
    double x0, y0, x1, y1;
};

void add_box(Path& p, Box b, bool clockwise = true) {
    p.move_to({b.x0, b.y0});
    if (clockwise) {
        p.line_to({b.x1, b.y0});
        p.line_to({b.x1, b.y1});
        p.line_to({b.x0, b.y1});
    } else {
        p.line_to({b.x0, b.y1});
        p.line_to({b.x1, b.y1});
        p.line_to({b.x1, b.y0});
    }
    p.close();
}

double overlap_1d(double a0, double a1, double b0, double b1) {
    return std::max(0.0, std::min(a1, b1) - std::max(a0, b0));
}
double area_in_pixel(Box b, int x, int y) {
    return overlap_1d(b.x0, b.x1, x, x + 1.0) * overlap_1d(b.y0, b.y1, y, y + 1.0);
}
// Exact coverage of pixel (x, y) by the union of a and b.
double union_coverage(Box a, Box b, int x, int y) {
    const Box both{std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1),
                   std::min(a.y1, b.y1)};
    double inter = both.x1 > both.x0 && both.y1 > both.y0 ? area_in_pixel(both, x, y) : 0.0;
    return area_in_pixel(a, x, y) + area_in_pixel(b, x, y) - inter;
}

Mask render(Rasterizer& r, const Path& p, OverlapMode mode, int w, int h,
            FillRule rule = FillRule::NonZero, const Affine& m = Affine::identity()) {
    Mask out(w, h);
    EXPECT_TRUE(r.fill_path(p, m, out.view(), {rule, mode}).ok());
    return out;
}

int max_diff(const Mask& a, const Mask& b) {
    int d = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) d = std::max(d, std::abs(a.at(x, y) - b.at(x, y)));
    return d;
}

TEST(OverlapAccurate, TwoIdenticalSquaresRenderLikeOne) {
    const Box b{2.25, 1.7, 9.6, 8.2};
    Path one, two;
    add_box(one, b);
    add_box(two, b);
    add_box(two, b);
    Rasterizer r;
    const Mask single = render(r, one, OverlapMode::Accumulate, 12, 10);
    const Mask plain = render(r, two, OverlapMode::Accumulate, 12, 10);
    const Mask accurate = render(r, two, OverlapMode::Accurate, 12, 10);
    // Plain accumulation counts the edge pixels twice: the left column (coverage 0.75) saturates.
    EXPECT_EQ(single.at(2, 4), 191);
    EXPECT_EQ(plain.at(2, 4), 255);
    EXPECT_LE(max_diff(accurate, single), 1);  // float sweep against double: rounding only
    // Also under even-odd, where the doubled square is an empty region (winding 2).
    const Mask eo = render(r, two, OverlapMode::Accurate, 12, 10, FillRule::EvenOdd);
    EXPECT_EQ(max_diff(eo, Mask(12, 10)), 0);
}

TEST(OverlapAccurate, OppositeWindingCancelsAsPlainDoes) {
    Path p;
    add_box(p, {1.5, 1.5, 6.5, 6.5}, true);
    add_box(p, {1.5, 1.5, 6.5, 6.5}, false);
    Rasterizer r;
    EXPECT_EQ(max_diff(render(r, p, OverlapMode::Accurate, 8, 8), Mask(8, 8)), 0);
}

TEST(OverlapAccurate, UnionOfRectanglesIsExact) {
    // Many random pairs of overlapping rectangles, same and opposite direction of drawing (the
    // union is the same under NonZero only when both wind the same way).
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.5, 14.5);
    Rasterizer r;
    int plain_worst = 0;
    for (int i = 0; i < 200; ++i) {
        Box a{u(rng), u(rng), 0, 0}, b{u(rng), u(rng), 0, 0};
        a.x1 = std::min(a.x0 + 1 + u(rng) / 2, 15.5);
        a.y1 = std::min(a.y0 + 1 + u(rng) / 2, 15.5);
        b.x1 = std::min(b.x0 + 1 + u(rng) / 2, 15.5);
        b.y1 = std::min(b.y0 + 1 + u(rng) / 2, 15.5);
        Path p;
        add_box(p, a);
        add_box(p, b);
        const Mask acc = render(r, p, OverlapMode::Accurate, 16, 16);
        const Mask plain = render(r, p, OverlapMode::Accumulate, 16, 16);
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) {
                const double want = 255.0 * union_coverage(a, b, x, y);
                ASSERT_NEAR(acc.at(x, y), want, 0.5 + 1e-6) << "pair " << i << " pixel " << x << "," << y;
                plain_worst = std::max(plain_worst, int(std::lround(std::abs(plain.at(x, y) - want))));
            }
    }
    EXPECT_GT(plain_worst, 30);  // the plain mode really does over-darken these
}

TEST(OverlapAccurate, OverlappingGlyphOIsExactAtEverySize) {
    // EdgeCases.ttf 'O': squares (100,100)–(500,500) and (300,300)–(700,700), font units y up.
    Expected<Font> font = Font::open(std::string(BEZEL_FONTS_DIR) + "/edge-cases/EdgeCases.ttf");
    ASSERT_TRUE(font);
    const GlyphId gid = *font->glyph_for_char('O');
    Rasterizer r;
    for (double size : {12.0, 24.0, 48.0, 96.0}) {
        Expected<GlyphOutline> o = font->outline(gid, {size, Hinting::None});
        ASSERT_TRUE(o);
        ASSERT_TRUE(o->overlapping_contours);
        const double k = size / 1000.0;
        const Vec2 pen{0.37, size * 0.75 + 0.41};  // fractional, so edges fall inside pixels
        const Box a{100 * k + pen.x, pen.y - 500 * k, 500 * k + pen.x, pen.y - 100 * k};
        const Box b{300 * k + pen.x, pen.y - 700 * k, 700 * k + pen.x, pen.y - 300 * k};
        const int n = static_cast<int>(size);
        const Affine m = Affine::translate(pen);
        const Mask acc = render(r, o->path, OverlapMode::Accurate, n, n, FillRule::NonZero, m);
        const Mask plain = render(r, o->path, OverlapMode::Accumulate, n, n, FillRule::NonZero, m);
        double acc_max = 0, plain_max = 0;
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const double want = 255.0 * union_coverage(a, b, x, y);
                acc_max = std::max(acc_max, std::abs(acc.at(x, y) - want));
                plain_max = std::max(plain_max, std::abs(plain.at(x, y) - want));
            }
        EXPECT_LE(acc_max, 0.5 + 1e-6) << size << " px";
        EXPECT_GT(plain_max, 2.0) << size << " px";
    }
}

// The 16×16 reference: the path at 16× rendered with float coverage, box-filtered back.
std::vector<double> reference(Rasterizer& r, const Path& p, int w, int h) {
    const int W = w * 16, H = h * 16;
    std::vector<float> big(static_cast<std::size_t>(W) * H);
    EXPECT_TRUE(r.fill_path(p, Affine::scale(16.0), FloatMaskView{big.data(), W, H, W},
                            {FillRule::NonZero})
                    .ok());
    std::vector<double> out(static_cast<std::size_t>(w) * h, 0.0);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
            out[static_cast<std::size_t>(y / 16) * w + x / 16] += big[static_cast<std::size_t>(y) * W + x];
    for (double& v : out) v *= 255.0 / 256.0;
    return out;
}

TEST(OverlapAccurate, RotatedOverlapsMatchSupersampledReference) {
    // Two overlapping rotated squares and a circle over a triangle: the 16× reference still
    // over-counts inside its own fine pixels along both edges near a crossing, at most 1/256 of
    // a pixel per such fine pixel — so allow 2/255.
    Path p;
    const Point c{10.3, 9.7};
    for (double ang : {0.3, 1.0}) {
        const Vec2 u{std::cos(ang) * 6, std::sin(ang) * 6}, v{-u.y, u.x};
        p.move_to(c + u + v);
        p.line_to(c - u + v + Vec2{2, 0});
        p.line_to(c - u - v);
        p.line_to(c + u - v);
        p.close();
    }
    p.move_to({2, 18});
    p.line_to({17, 17.2});
    p.line_to({9, 3.5});
    p.close();
    Rasterizer r;
    const std::vector<double> ref = reference(r, p, 20, 20);
    const Mask acc = render(r, p, OverlapMode::Accurate, 20, 20);
    const Mask plain = render(r, p, OverlapMode::Accumulate, 20, 20);
    double acc_max = 0, plain_max = 0;
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 20; ++x) {
            acc_max = std::max(acc_max, std::abs(acc.at(x, y) - ref[y * 20 + x]));
            plain_max = std::max(plain_max, std::abs(plain.at(x, y) - ref[y * 20 + x]));
        }
    EXPECT_LE(acc_max, 2.0);
    EXPECT_GT(plain_max, 10.0);
}

TEST(OverlapAccurate, EqualsPlainOnGlyphsWithoutOverlaps) {
    Expected<Font> font = Font::open(std::string(BEZEL_FONTS_DIR) + "/dejavu-sans/DejaVuSans.ttf");
    ASSERT_TRUE(font);
    Rasterizer r;
    for (double size : {12.0, 31.5}) {
        for (char32_t ch : std::u32string(U"aAgQ@&%8Bxé§")) {
            auto gid = font->glyph_for_char(ch);
            ASSERT_TRUE(gid);
            Expected<GlyphOutline> o = font->outline(*gid, {size, Hinting::None});
            ASSERT_TRUE(o);
            const int n = static_cast<int>(size * 1.4);
            const Affine m = Affine::translate({1.3, size + 0.6});
            const Mask acc = render(r, o->path, OverlapMode::Accurate, n, n, FillRule::NonZero, m);
            const Mask plain = render(r, o->path, OverlapMode::Accumulate, n, n, FillRule::NonZero, m);
            EXPECT_LE(max_diff(acc, plain), 1) << "U+" << std::hex << unsigned(ch) << " at " << size;
        }
    }
}

TEST(OverlapAccurate, ClipsLikePlainOutsideTheTarget) {
    // A shape hanging off every side: cover from the left still reaches the target.
    Path p;
    add_box(p, {-5.25, -3.5, 4.75, 12.5});
    add_box(p, {3.1, 2.2, 30, 6.6});
    Rasterizer r;
    const Box a{-5.25, -3.5, 4.75, 12.5}, b{3.1, 2.2, 30, 6.6};
    const Mask acc = render(r, p, OverlapMode::Accurate, 8, 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            EXPECT_NEAR(acc.at(x, y), 255.0 * union_coverage(a, b, x, y), 0.5 + 1e-6);
}

TEST(OverlapAccurate, HugeAndNearlyFlatEdgesGiveTheExactUnion) {
    // A half-plane x < 3.25 whose far corners are ±2^49 px away, overlapped by a box whose top
    // edge rises by a subnormal amount: that edge's slope is infinite, and 0·∞ at its top end
    // made NaN coverage (a fuzzer finding).
    const double far = 0x1p49;
    Path p;
    p.move_to({-far, -far});
    p.line_to({3.25, -far});
    p.line_to({3.25, far});
    p.line_to({-far, far});
    p.close();
    p.move_to({2.5, 1.5});
    p.line_to({6.75, 1.5 + 4.9e-324});
    p.line_to({6.75, 4.0});
    p.line_to({2.5, 4.0});
    p.close();
    Rasterizer r;
    const Box a{-10, -10, 3.25, 18}, b{2.5, 1.5, 6.75, 4.0};
    for (FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
        const Mask acc = render(r, p, OverlapMode::Accurate, 8, 8, rule);
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x) {
                // Even-odd: the overlap is a hole.
                const Box both{2.5, 1.5, 3.25, 4.0};
                const double want = rule == FillRule::NonZero
                                        ? union_coverage(a, b, x, y)
                                        : union_coverage(a, b, x, y) - area_in_pixel(both, x, y);
                EXPECT_NEAR(acc.at(x, y), 255.0 * want, 0.5 + 1e-6) << x << "," << y;
            }
    }
}

TEST(OverlapAccurate, HostileOverlapStaysBoundedAndDegradesToPlain) {
    // A triangle over rows 0–40 and 400 copies of a small one over rows 20–40: those rows have
    // 802 active edges, past kMaxOverlapRowWork, so they keep the plain accumulation while the
    // rows above are exact. The call succeeds and takes no longer than a plain one in kind.
    Path big, many;
    auto tri = [](Path& p, double y0) {
        p.move_to({0.5, y0});
        p.line_to({7.5, 40});
        p.line_to({0.2, 40});
        p.close();
    };
    tri(big, 0);
    many = big;
    for (int i = 0; i < 400; ++i) tri(many, 20);
    Rasterizer r;
    const Mask exact = render(r, big, OverlapMode::Accumulate, 8, 40);
    const Mask plain = render(r, many, OverlapMode::Accumulate, 8, 40);
    const Mask acc = render(r, many, OverlapMode::Accurate, 8, 40);
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 8; ++x) {
            if (y < 20) {
                EXPECT_NEAR(acc.at(x, y), exact.at(x, y), 1) << x << "," << y;
            } else {
                EXPECT_EQ(acc.at(x, y), plain.at(x, y)) << x << "," << y;
            }
        }
    // A star of 300 spokes through one point crosses itself ~45 000 times in one row: that row
    // runs out of its budget midway and keeps its plain coverage too.
    Path star;
    const int spokes = 301;
    for (int i = 0; i < spokes; ++i) {
        const double a = 2 * M_PI * i * 150 / spokes;
        star.line_to({20 + 19 * std::cos(a), 20 + 19 * std::sin(a)});
    }
    star.close();
    const Mask star_plain = render(r, star, OverlapMode::Accumulate, 40, 40);
    const Mask star_acc = render(r, star, OverlapMode::Accurate, 40, 40);
    for (int x = 0; x < 40; ++x) EXPECT_EQ(star_acc.at(x, 20), star_plain.at(x, 20)) << x;
    int differ = 0;  // rows with few crossings are exact, and differ from the plain render
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 40; ++x) differ += star_acc.at(x, y) != star_plain.at(x, y);
    EXPECT_GT(differ, 0);
}

TEST(OverlapAccurate, ErrorsAreFillPathsAndLeaveTheTarget) {
    Path p;
    add_box(p, {1, 1, 3, 3});
    Rasterizer r;
    Mask m(4, 4);
    m.at(0, 0) = 77;
    Affine bad{1, 0, 0, 1, std::nan(""), 0};
    EXPECT_FALSE(r.fill_path(p, bad, m.view(), {FillRule::NonZero, OverlapMode::Accurate}).ok());
    EXPECT_EQ(m.at(0, 0), 77);
    EXPECT_FALSE(r.fill_path(p, Affine::identity(), MaskView{nullptr, 4, 4, 4},
                             {FillRule::NonZero, OverlapMode::Accurate})
                     .ok());
}

}  // namespace
}  // namespace bezel
