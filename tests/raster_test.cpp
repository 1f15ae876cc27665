// Tests of bezel/raster.hpp: exact-area properties, the fast path against the reference oracle
// (lib/src/raster/reference.hpp), clipping, hostile input, limits, SIMD kernels against scalar.
//
// Tolerances: the fast path accumulates in float, the reference in double. Float coverage is
// compared within 1e-4 (float rounding of sums of a few hundred deltas of magnitude ≤ 1 stays
// far below it); 8-bit output within 1 level (a float difference of 1e-6 can flip the rounding
// of a value that lies on a .5 boundary; more than one level would be a real error).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <random>
#include <vector>

#include "bezel/diagnostics.hpp"
#include "bezel/raster.hpp"
#include "raster/accumulate.hpp"
#include "raster/dense_batch.hpp"
#include "raster/direct_fill.hpp"
#include "raster/draw_batch.hpp"
#include "raster/fill_common.hpp"
#include "raster/kernels.hpp"
#include "raster/reference.hpp"
#include "raster/render_flatten.hpp"
#include "raster/sweep.hpp"

namespace bezel {
namespace {

using raster_detail::reference_coverage;
using raster_detail::reference_u8;

// Options of a polyline fill with `rule`, moved by `origin` (target pixels).
FillOptions fill_at(FillRule rule, Vec2 origin) {
    FillOptions o;
    o.rule = rule;
    o.origin = origin;
    return o;
}

constexpr double kFloatTol = 1e-4;

Polylines polygon(std::initializer_list<std::initializer_list<Point>> contours) {
    Polylines p;
    for (const auto& c : contours) {
        for (Point q : c) p.points.push_back(q);
        p.contour_ends.push_back(p.points.size());
    }
    return p;
}

Polylines rect(double x0, double y0, double x1, double y1) {
    return polygon({{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}});
}

struct FloatImage {
    int w, h;
    std::vector<float> px;
    FloatImage(int w_, int h_) : w(w_), h(h_), px(static_cast<std::size_t>(w_) * h_, -1.0f) {}
    FloatMaskView view() { return {px.data(), w, h, w}; }
    float at(int x, int y) const { return px[static_cast<std::size_t>(y) * w + x]; }
};

// Random polygon: `n` points in [lo, hi]², any shape (self-intersecting, degenerate), split
// into 1..3 contours.
Polylines random_polygon(std::mt19937& rng, int n, double lo, double hi) {
    std::uniform_real_distribution<double> u(lo, hi);
    std::uniform_int_distribution<int> contours(1, 3);
    Polylines p;
    int k = contours(rng);
    for (int c = 0; c < k; ++c) {
        for (int i = 0; i < n; ++i) p.points.push_back({u(rng), u(rng)});
        p.contour_ends.push_back(p.points.size());
    }
    return p;
}

// A simple (non-self-intersecting) polygon, star-shaped around `c`: vertex k at an angle in
// [2πk/n, 2π(k+1)/n), so consecutive angles differ by less than 4π/n ≤ 4π/5 < π (n ≥ 5), which
// keeps `c` inside and the boundary from crossing itself.
Polylines random_star(std::mt19937& rng, Point c, double rmin, double rmax, int n) {
    std::uniform_real_distribution<double> jitter(0.0, 1.0), rad(rmin, rmax);
    Polylines p;
    for (int k = 0; k < n; ++k) {
        double t = 2.0 * M_PI * (k + jitter(rng)) / n;
        double r = rad(rng);
        p.points.push_back({c.x + r * std::cos(t), c.y + r * std::sin(t)});
    }
    p.contour_ends.push_back(p.points.size());
    return p;
}

double shoelace_area(const Polylines& p) {
    double area = 0.0;
    std::size_t start = 0;
    for (std::size_t end : p.contour_ends) {
        for (std::size_t k = start; k < end; ++k) {
            Point a = p.points[k], b = p.points[k + 1 < end ? k + 1 : start];
            area += a.cross(b);
        }
        start = end;
    }
    return 0.5 * area;
}

// --- Exact-area properties -----------------------------------------------------------------

TEST(RasterProperties, RectangleCoverageIsExactOverlapArea) {
    std::mt19937 rng(101);
    std::uniform_real_distribution<double> u(-3.0, 27.0);
    Rasterizer r;
    for (int trial = 0; trial < 2000; ++trial) {
        double x0 = u(rng), x1 = u(rng), y0 = u(rng), y1 = u(rng);
        FloatImage img(24, 24);
        ASSERT_TRUE(r.fill(rect(x0, y0, x1, y1), img.view(), {FillRule::NonZero}).ok());
        double lx = std::min(x0, x1), hx = std::max(x0, x1);
        double ly = std::min(y0, y1), hy = std::max(y0, y1);
        for (int y = 0; y < 24; ++y) {
            for (int x = 0; x < 24; ++x) {
                double ox = std::max(0.0, std::min(hx, x + 1.0) - std::max(lx, double(x)));
                double oy = std::max(0.0, std::min(hy, y + 1.0) - std::max(ly, double(y)));
                ASSERT_NEAR(img.at(x, y), ox * oy, kFloatTol)
                    << "trial " << trial << " pixel " << x << "," << y;
            }
        }
    }
}

TEST(RasterProperties, EvenOddCancelsInnerLoop) {
    // Outer and inner squares drawn in the SAME direction: winding 2 inside the inner one.
    Polylines p = polygon({{{2, 2}, {18, 2}, {18, 18}, {2, 18}}, {{6, 6}, {14, 6}, {14, 14}, {6, 14}}});
    Rasterizer r;
    Mask eo(20, 20), nz(20, 20);
    ASSERT_TRUE(r.fill(p, eo.view(), {FillRule::EvenOdd}).ok());
    ASSERT_TRUE(r.fill(p, nz.view(), {FillRule::NonZero}).ok());
    for (int y = 0; y < 20; ++y) {
        for (int x = 0; x < 20; ++x) {
            bool outer = x >= 2 && x < 18 && y >= 2 && y < 18;
            bool inner = x >= 6 && x < 14 && y >= 6 && y < 14;
            EXPECT_EQ(eo.at(x, y), outer && !inner ? 255 : 0) << x << "," << y;
            EXPECT_EQ(nz.at(x, y), outer ? 255 : 0) << x << "," << y;
        }
    }
}

TEST(RasterProperties, EvenOddTriangleWaveOnFractionalInnerLoop) {
    // Inner square with fractional edges: winding 2 in the partially covered pixels must give
    // 1 − (fraction), not min(1 + fraction, 1).
    Polylines p = polygon({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{3.25, 3}, {7, 3}, {7, 7}, {3.25, 7}}});
    Rasterizer r;
    FloatImage img(10, 10);
    ASSERT_TRUE(r.fill(p, img.view(), {FillRule::EvenOdd}).ok());
    EXPECT_NEAR(img.at(3, 4), 0.25, kFloatTol);  // 3/4 of the pixel wound twice
    EXPECT_NEAR(img.at(1, 4), 1.0, kFloatTol);
    EXPECT_NEAR(img.at(5, 5), 0.0, kFloatTol);
}

TEST(RasterProperties, CoverageIsInvariantUnderWholePixelTranslation) {
    std::mt19937 rng(202);
    Rasterizer r;
    for (int trial = 0; trial < 1000; ++trial) {
        Polylines p = random_polygon(rng, 3 + trial % 8, 0.0, 16.0);
        int dx = static_cast<int>(rng() % 9), dy = static_cast<int>(rng() % 9);
        Vec2 frac{(rng() % 64) / 64.0, (rng() % 64) / 64.0};
        FillRule rule = trial % 2 ? FillRule::EvenOdd : FillRule::NonZero;
        FloatImage a(26, 26), b(26, 26);
        ASSERT_TRUE(r.fill(p, a.view(), fill_at(rule, frac)).ok());
        ASSERT_TRUE(r.fill(p, b.view(), fill_at(rule, frac + Vec2{double(dx), double(dy)})).ok());
        for (int y = 0; y + dy < 26; ++y)
            for (int x = 0; x + dx < 26; ++x)
                ASSERT_NEAR(a.at(x, y), b.at(x + dx, y + dy), kFloatTol) << "trial " << trial;
    }
}

TEST(RasterProperties, TotalCoverageEqualsPolygonArea) {
    std::mt19937 rng(303);
    Rasterizer r;
    for (int trial = 0; trial < 2000; ++trial) {
        Polylines p = random_star(rng, {20.0, 20.0}, 1.0, 18.0, 5 + trial % 40);
        FloatImage img(40, 40);
        ASSERT_TRUE(r.fill(p, img.view(), {FillRule::NonZero}).ok());
        double sum = 0.0;
        for (float v : img.px) sum += v;
        // Float accumulation: ~1e-6 relative per pixel, 1600 pixels.
        ASSERT_NEAR(sum, std::fabs(shoelace_area(p)), 2e-3) << "trial " << trial;
    }
}

// --- The fast path against the reference -----------------------------------------------------

TEST(RasterReference, FastPathMatchesReferenceOnRandomPolygons) {
    std::mt19937 rng(404);
    Rasterizer r;
    int worst_u8 = 0;
    double worst_f = 0.0;
    for (int trial = 0; trial < 3000; ++trial) {
        int w = 1 + static_cast<int>(rng() % 48), h = 1 + static_cast<int>(rng() % 48);
        // Points reach outside the target on every side, so clipping is exercised.
        Polylines p = random_polygon(rng, 3 + trial % 12, -10.0, 58.0);
        FillRule rule = trial % 2 ? FillRule::EvenOdd : FillRule::NonZero;
        Vec2 origin{(rng() % 100) / 37.0 - 1.0, (rng() % 100) / 41.0 - 1.0};
        FloatImage f(w, h);
        Mask m(w, h);
        ASSERT_TRUE(r.fill(p, f.view(), fill_at(rule, origin)).ok());
        ASSERT_TRUE(r.fill(p, m.view(), fill_at(rule, origin)).ok());
        std::vector<double> ref = reference_coverage(p, rule, w, h, origin);
        std::vector<unsigned char> ref8 = reference_u8(p, rule, w, h, origin);
        for (std::size_t i = 0; i < ref.size(); ++i) {
            worst_f = std::max(worst_f, std::fabs(f.px[i] - ref[i]));
            worst_u8 = std::max(worst_u8, std::abs(int(m.pixels()[i]) - int(ref8[i])));
        }
        ASSERT_LE(worst_f, kFloatTol) << "trial " << trial;
        ASSERT_LE(worst_u8, 1) << "trial " << trial;
    }
    RecordProperty("worst_float_error", std::to_string(worst_f));
}

TEST(RasterReference, MultiBandTallTargetMatchesReference) {
    // 1000 px wide: a band holds kMaxBandCells / 1002 = 261 rows, so 700 rows take 3 bands.
    std::mt19937 rng(505);
    Rasterizer r;
    for (int trial = 0; trial < 6; ++trial) {
        Polylines p = random_polygon(rng, 12, -50.0, 1050.0);
        FillRule rule = trial % 2 ? FillRule::EvenOdd : FillRule::NonZero;
        Mask m(1000, 700);
        ASSERT_TRUE(r.fill(p, m.view(), fill_at(rule, {0.3, -0.7})).ok());
        std::vector<unsigned char> ref = reference_u8(p, rule, 1000, 700, {0.3, -0.7});
        for (std::size_t i = 0; i < ref.size(); ++i)
            ASSERT_LE(std::abs(int(m.pixels()[i]) - int(ref[i])), 1) << "trial " << trial << " i " << i;
    }
}

TEST(RasterReference, NearHorizontalAndNearVerticalEdgesMatchReference) {
    // Slivers: slopes of 1e-7 and 1e7, where a division by a tiny difference would lose
    // precision.
    Rasterizer r;
    const double e = 1e-7;
    std::vector<Polylines> cases = {
        polygon({{{0.5, 3.0}, {30.5, 3.0 + e}, {30.5, 9.0}, {0.5, 9.0}}}),
        polygon({{{3.0, 0.5}, {3.0 + e, 30.5}, {9.0, 30.5}, {9.0, 0.5}}}),
        polygon({{{2.9999999, 1.0}, {3.0000001, 20.0}, {12.0, 20.0}, {12.0, 1.0}}}),
        polygon({{{1.0, 1.0}, {31.0, 1.5}, {1.0, 2.0}}}),
    };
    for (std::size_t c = 0; c < cases.size(); ++c) {
        FloatImage f(32, 32);
        ASSERT_TRUE(r.fill(cases[c], f.view(), {FillRule::NonZero}).ok());
        std::vector<double> ref = reference_coverage(cases[c], FillRule::NonZero, 32, 32, {});
        for (std::size_t i = 0; i < ref.size(); ++i)
            ASSERT_NEAR(f.px[i], ref[i], kFloatTol) << "case " << c << " pixel " << i;
    }
}

// --- fill_path's direct route (direct_fill.hpp): curves flattened straight into the band --------

// A random closed path of lines, quads and cubics with every control point in the unit square
// (so its image under a map into a target lies inside the target), 1..3 contours.
Path random_curved_path(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    auto pt = [&] { return Point{u(rng), u(rng)}; };
    Path p;
    const int contours = 1 + static_cast<int>(rng() % 3);
    for (int c = 0; c < contours; ++c) {
        p.move_to(pt());
        const int verbs = 1 + static_cast<int>(rng() % 6);
        for (int k = 0; k < verbs; ++k) {
            switch (rng() % 3) {
                case 0: p.line_to(pt()); break;
                case 1: p.quad_to(pt(), pt()); break;
                default: p.cubic_to(pt(), pt(), pt()); break;
            }
        }
        p.close();
    }
    return p;
}

// The general route's input: the same balanced polyline fill_path flattens to.
Polylines balanced_polyline(const Path& p, const Affine& m, double tol) {
    Polylines lines;
    EXPECT_TRUE(raster_detail::flatten_balanced(p, m, tol, lines));
    return lines;
}

TEST(RasterDirect, FillPathMatchesReferenceAndGeneralRouteOnRandomCurvedPaths) {
    // Targets 1..220 px wide cover both regimes (dense up to kDenseBlocks blocks per row,
    // sparse beyond);
    // transforms: axis-aligned (flipped or not) and rotated. Points keep a margin of 0.5 px from
    // the target border, beyond any balanced vertex's excursion (< tol), so the route draws
    // exactly the balanced polyline: the reference on that polyline is the oracle.
    std::mt19937 rng(2024);
    Rasterizer r;
    const double tol = kDefaultRasterTolerancePx;
    double worst_f = 0.0;
    for (int trial = 0; trial < 400; ++trial) {
        const int w = 1 + static_cast<int>(rng() % 220), h = 1 + static_cast<int>(rng() % 60);
        const Path p = random_curved_path(rng);
        Affine m;
        switch (trial % 3) {
            case 0: m = {w - 1.0, 0, 0, h - 1.0, 0.5, 0.5}; break;
            case 1: m = {-(w - 1.0), 0, 0, h - 1.0, w - 0.5, 0.5}; break;  // mirrored
            default: {
                // The unit square, centred, rotated, scaled into the inscribed circle.
                const double t = 0.1 + trial * 0.37, s = (std::min(w, h) - 1.0) / std::sqrt(2.0);
                m = Affine::translate({w / 2.0, h / 2.0}) *
                    Affine{s * std::cos(t), s * std::sin(t), -s * std::sin(t), s * std::cos(t), 0, 0} *
                    Affine::translate({-0.5, -0.5});
            }
        }
        const FillRule rule = trial % 2 ? FillRule::EvenOdd : FillRule::NonZero;
        const Polylines lines = balanced_polyline(p, m, tol);
        FloatImage f(w, h);
        Mask direct(w, h), general(w, h);
        ASSERT_TRUE(r.fill_path(p, m, f.view(), {rule}).ok());
        ASSERT_TRUE(r.fill_path(p, m, direct.view(), {rule}).ok());
        ASSERT_TRUE(r.fill(lines, general.view(), {rule}).ok());
        const std::vector<double> ref = reference_coverage(lines, rule, w, h, {});
        const std::vector<unsigned char> ref8 = reference_u8(lines, rule, w, h, {});
        for (std::size_t i = 0; i < ref.size(); ++i) {
            worst_f = std::max(worst_f, std::fabs(f.px[i] - ref[i]));
            ASSERT_LE(std::abs(int(direct.pixels()[i]) - int(ref8[i])), 1) << "trial " << trial;
            ASSERT_LE(std::abs(int(direct.pixels()[i]) - int(general.pixels()[i])), 1)
                << "trial " << trial;
        }
        ASSERT_LE(worst_f, kFloatTol) << "trial " << trial;
    }
    RecordProperty("worst_float_error", std::to_string(worst_f));
}

// A circle of four cubics (the usual 0.5523 handle), counter-clockwise on screen (y down)
// when `ccw`, else clockwise.
void add_circle(Path& p, double cx, double cy, double r, bool ccw) {
    const double k = 0.5523 * r, s = ccw ? -1.0 : 1.0;
    p.move_to({cx + r, cy});
    p.cubic_to({cx + r, cy + s * k}, {cx + k, cy + s * r}, {cx, cy + s * r});
    p.cubic_to({cx - k, cy + s * r}, {cx - r, cy + s * k}, {cx - r, cy});
    p.cubic_to({cx - r, cy - s * k}, {cx - k, cy - s * r}, {cx, cy - s * r});
    p.cubic_to({cx + k, cy - s * r}, {cx + r, cy - s * k}, {cx + r, cy});
    p.close();
}

TEST(RasterDirect, SparseBandsWriteEveryPixelOfNestedRingsAndManyContours) {
    // Wide boxes take the marked regime, whose sweep writes each pixel exactly once (runs and
    // summed blocks, no clearing pass): targets start as garbage (0xAB, NaN) and every pixel
    // must end as the reference's. Nested rings of alternating orientation (non-zero: rings;
    // even-odd: every other annulus), among many small circles, give runs of coverage 0, 1
    // and 2 between blocks; the last case is a box 16384 px wide, edges at the target's far
    // end. Within the direct route's usual bounds: 1/255 (8-bit) and kFloatTol.
    std::mt19937 rng(3434);
    Rasterizer r;
    const double tol = kDefaultRasterTolerancePx;
    for (int trial = 0; trial < 8; ++trial) {
        const bool huge = trial == 7;
        const int w = huge ? kMaxBitmapDim : 120 + static_cast<int>(rng() % 480);
        const int h = huge ? 20 : 20 + static_cast<int>(rng() % 80);
        std::uniform_real_distribution<double> ux(1.0, w - 1.0), uy(1.0, h - 1.0);
        Path p;
        const double cx = w / 2.0, cy = h / 2.0, rmax = std::min(w, h) / 2.0 - 1.0;
        for (int ring = 0; ring < 5; ++ring)
            add_circle(p, cx, cy, rmax * (1.0 - 0.18 * ring), ring % 2 == 1 || trial % 3 == 0);
        for (int c = 0; c < 30; ++c) {
            const double x = ux(rng), y = uy(rng);
            const double rc = std::min({x, w - x, y, h - y, 6.0}) - 0.5;
            if (rc > 0.2) add_circle(p, x, y, rc, rng() % 2 == 0);
        }
        if (huge) {  // a sliver along the whole width: edges from x = 0.5 to 16383.5
            p.move_to({0.5, 2.0});
            p.quad_to({w / 2.0, 0.5}, {w - 0.5, 2.0});
            p.line_to({w - 0.5, 17.5});
            p.close();
        }
        for (const FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
            const Polylines lines = balanced_polyline(p, Affine{}, tol);
            Mask m(w, h, 0xAB);
            FloatImage f(w, h);
            std::fill(f.px.begin(), f.px.end(), std::numeric_limits<float>::quiet_NaN());
            ASSERT_TRUE(r.fill_path(p, Affine{}, m.view(), {rule}).ok());
            ASSERT_TRUE(r.fill_path(p, Affine{}, f.view(), {rule}).ok());
            const std::vector<double> ref = reference_coverage(lines, rule, w, h, {});
            const std::vector<unsigned char> ref8 = reference_u8(lines, rule, w, h, {});
            for (std::size_t i = 0; i < ref.size(); ++i) {
                ASSERT_LE(std::abs(int(m.pixels()[i]) - int(ref8[i])), 1)
                    << "trial " << trial << " pixel " << i % w << ", " << i / w;
                ASSERT_NEAR(f.px[i], ref[i], kFloatTol)
                    << "trial " << trial << " pixel " << i % w << ", " << i / w;
            }
        }
    }
}

TEST(RasterDirect, TranslationsDrawTheStoredTransformsCoverageBitForBit) {
    // A translation (the identity included) is not stored: the walk adds (e, f) to the path's
    // own points. b = 1e-300 is not a translation, so that transform is stored, yet it maps
    // every point here (coordinates ≥ 0.5) to the same doubles; the two fills must agree in
    // every float and byte, in both regimes (targets up to 220 px wide), under both rules, and
    // the translation must agree with the general route on the same polyline (±1 level).
    std::mt19937 rng(77);
    Rasterizer r;
    for (int trial = 0; trial < 200; ++trial) {
        const int w = 2 + static_cast<int>(rng() % 220), h = 2 + static_cast<int>(rng() % 60);
        std::uniform_real_distribution<double> frac(0.0, 1.0);
        const double e = frac(rng) * 0.25, f = frac(rng) * 0.25;
        // The path in pixels, 0.5 px in from the border before the translation.
        const Path p = random_curved_path(rng).transformed(
            {w - 1.5, 0, 0, h - 1.5, 0.5, 0.5});
        const Affine moved = Affine::translate({e, f});
        const Affine stored{1, 1e-300, 0, 1, e, f};
        const FillRule rule = trial % 2 ? FillRule::EvenOdd : FillRule::NonZero;
        FloatImage fa(w, h), fb(w, h);
        Mask ma(w, h), mb(w, h), general(w, h);
        ASSERT_TRUE(r.fill_path(p, moved, fa.view(), {rule}).ok());
        ASSERT_TRUE(r.fill_path(p, stored, fb.view(), {rule}).ok());
        ASSERT_TRUE(r.fill_path(p, moved, ma.view(), {rule}).ok());
        ASSERT_TRUE(r.fill_path(p, stored, mb.view(), {rule}).ok());
        ASSERT_TRUE(r.fill(balanced_polyline(p, moved, kDefaultRasterTolerancePx), general.view(),
                           {rule}).ok());
        for (std::size_t i = 0; i < fa.px.size(); ++i) {
            ASSERT_EQ(fa.px[i], fb.px[i]) << "trial " << trial << " pixel " << i;
            ASSERT_EQ(ma.pixels()[i], mb.pixels()[i]) << "trial " << trial << " pixel " << i;
            ASSERT_LE(std::abs(int(ma.pixels()[i]) - int(general.pixels()[i])), 1)
                << "trial " << trial << " pixel " << i;
        }
    }
}

TEST(RasterDirect, PathTouchingEveryTargetBorderStaysWithinTheTolerance) {
    // Control points ON the border (a glyph box starting at pixel 0, the common case): balanced
    // vertices may stray < tol outside, which the route folds back into the band. Coverage then
    // differs from the exact polyline's by at most the excursion's area in a pixel, < tol.
    const double tol = kDefaultRasterTolerancePx;
    Path p;  // an ellipse of four cubics touching all four sides of [0, 37] × [0, 23]
    const double k = 0.5523, cx = 18.5, cy = 11.5, rx = 18.5, ry = 11.5;
    p.move_to({cx + rx, cy});
    p.cubic_to({cx + rx, cy + k * ry}, {cx + k * rx, cy + ry}, {cx, cy + ry});
    p.cubic_to({cx - k * rx, cy + ry}, {cx - rx, cy + k * ry}, {cx - rx, cy});
    p.cubic_to({cx - rx, cy - k * ry}, {cx - k * rx, cy - ry}, {cx, cy - ry});
    p.cubic_to({cx + k * rx, cy - ry}, {cx + rx, cy - k * ry}, {cx + rx, cy});
    p.close();
    p.move_to({0, 23});  // a quad corner sitting in the target's bottom-left corner
    p.quad_to({0, 20}, {3, 23});
    p.close();
    Rasterizer r;
    for (FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
        FloatImage f(37, 23);
        ASSERT_TRUE(r.fill_path(p, Affine::identity(), f.view(), {rule}).ok());
        const std::vector<double> ref =
            reference_coverage(balanced_polyline(p, Affine::identity(), tol), rule, 37, 23, {});
        for (std::size_t i = 0; i < ref.size(); ++i) ASSERT_NEAR(f.px[i], ref[i], tol) << i;
    }
}

TEST(RasterDirect, ControlPointsStrayingLessThanTheToleranceOutsideAreClampedWithinIt) {
    // A glyph box from rounded coordinates (FreeType's 26.6 box) may miss the outline by up to
    // 1/128 px: the route takes such a path (control points up to tol outside the target) and
    // clamps its vertices into the band, x exactly and y by less than 2·tol, so coverage is
    // within 2·tol of the exact clipped polyline's. Ellipses overshooting all four sides by
    // 0.8·tol, in the dense (37 px) and marked (200 px) regimes, through the translated walk
    // and the stored one (b = 1e-300 maps these points to the same doubles).
    const double tol = kDefaultRasterTolerancePx, out = 0.8 * tol;
    std::vector<float> acc;
    std::vector<std::uint8_t> flags;
    std::vector<Point> points;
    for (const int w : {37, 200}) {
        const int h = 23;
        Path p;
        const double k = 0.5523, cx = w / 2.0, cy = h / 2.0, rx = cx + out, ry = cy + out;
        p.move_to({cx + rx, cy});
        p.cubic_to({cx + rx, cy + k * ry}, {cx + k * rx, cy + ry}, {cx, cy + ry});
        p.cubic_to({cx - k * rx, cy + ry}, {cx - rx, cy + k * ry}, {cx - rx, cy});
        p.quad_to({cx - rx, cy - ry}, {cx, cy - ry});
        p.line_to({cx + rx, cy - ry});
        p.close();
        for (const Affine& m : {Affine::identity(), Affine{1, 1e-300, 0, 1, 0, 0}}) {
            for (FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
                FloatImage f(w, h);
                ASSERT_TRUE(raster_detail::fill_path_direct(p, m, rule, f.view(), tol,
                                                            {acc, flags, points}));
                const std::vector<double> ref =
                    reference_coverage(balanced_polyline(p, m, tol), rule, w, h, {});
                for (std::size_t i = 0; i < ref.size(); ++i)
                    ASSERT_NEAR(f.px[i], ref[i], 2.0 * tol) << "w " << w << " pixel " << i;
                // Farther out than tol the path needs clipping: the general route's.
                Mask m8(w, h);
                const Affine wider = Affine::translate({cx, cy}) *
                                     Affine::scale((rx + 0.5 * tol) / rx) *
                                     Affine::translate({-cx, -cy});
                EXPECT_FALSE(raster_detail::fill_path_direct(p, wider * m, rule, m8.view(), tol,
                                                             {acc, flags, points}));
            }
        }
    }
}

TEST(RasterDirect, SteepEdgesInsideOneColumnMatchReference) {
    // Edges that stay in one pixel column over many rows take the per-row loop of draw_line:
    // fractional and integer ends, both directions, at the left border, inside, and on the last
    // column's right border. Through fill (sparse, marking) and fill_path (the direct route).
    std::vector<Polylines> cases = {
        polygon({{{3.2, 0.3}, {3.9, 40.7}, {20.0, 40.7}, {20.0, 0.3}}}),
        polygon({{{3.9, 40.0}, {3.1, 1.0}, {0.0, 1.0}, {0.0, 40.0}}}),
        polygon({{{0.0, 2.5}, {0.6, 37.25}, {9.0, 20.0}}}),
        polygon({{{199.0, 5.0}, {199.999, 39.5}, {200.0, 0.0}}}),  // 200 wide: the sparse regime
        polygon({{{10.0, 0.0}, {10.0, 41.0}, {11.0, 41.0}, {11.0, 0.0}}}),
    };
    Rasterizer r;
    for (std::size_t c = 0; c < cases.size(); ++c) {
        FloatImage f(200, 41), g(200, 41);
        ASSERT_TRUE(r.fill(cases[c], f.view(), {FillRule::NonZero}).ok());
        Path p;
        std::size_t start = 0;
        for (std::size_t end : cases[c].contour_ends) {
            p.move_to(cases[c].points[start]);
            for (std::size_t i = start + 1; i < end; ++i) p.line_to(cases[c].points[i]);
            p.close();
            start = end;
        }
        ASSERT_TRUE(r.fill_path(p, Affine::identity(), g.view(), {FillRule::NonZero}).ok());
        const std::vector<double> ref = reference_coverage(cases[c], FillRule::NonZero, 200, 41, {});
        for (std::size_t i = 0; i < ref.size(); ++i) {
            ASSERT_NEAR(f.px[i], ref[i], kFloatTol) << "case " << c << " pixel " << i;
            ASSERT_NEAR(g.px[i], ref[i], kFloatTol) << "case " << c << " pixel " << i;
        }
    }
}

// --- Clipping and hostile coordinates ------------------------------------------------------

TEST(RasterClipping, EdgesLeftOfTargetStillContributeCover) {
    // A square from x = −5 to 3.5: the target must show columns 0..2 full and column 3 half.
    Rasterizer r;
    FloatImage f(8, 8);
    ASSERT_TRUE(r.fill(rect(-5, 1, 3.5, 6), f.view(), {FillRule::NonZero}).ok());
    for (int y = 0; y < 8; ++y) {
        double row = (y >= 1 && y < 6) ? 1.0 : 0.0;
        for (int x = 0; x < 8; ++x) {
            double expect = x < 3 ? row : x == 3 ? 0.5 * row : 0.0;
            EXPECT_NEAR(f.at(x, y), expect, kFloatTol) << x << "," << y;
        }
    }
}

TEST(RasterClipping, WindowOfLargerRenderEqualsRenderOfWindow) {
    std::mt19937 rng(606);
    Rasterizer r;
    for (int trial = 0; trial < 500; ++trial) {
        Polylines p = random_polygon(rng, 3 + trial % 9, 0.0, 40.0);
        FillRule rule = trial % 2 ? FillRule::EvenOdd : FillRule::NonZero;
        FloatImage big(40, 40), win(15, 12);
        int wx = static_cast<int>(rng() % 25), wy = static_cast<int>(rng() % 28);
        ASSERT_TRUE(r.fill(p, big.view(), {rule}).ok());
        ASSERT_TRUE(r.fill(p, win.view(), fill_at(rule, {-double(wx), -double(wy)})).ok());
        for (int y = 0; y < 12; ++y)
            for (int x = 0; x < 15; ++x)
                ASSERT_NEAR(win.at(x, y), big.at(x + wx, y + wy), kFloatTol) << "trial " << trial;
    }
}

TEST(RasterClipping, HugeCoordinatesClipExactlyWithoutOverflow) {
    Rasterizer r;
    const double big = std::numeric_limits<double>::max();
    // A rectangle from x = −DBL_MAX to 5.5 equals one from 0 to 5.5 inside the target.
    FloatImage a(10, 10), b(10, 10);
    ASSERT_TRUE(r.fill(rect(-big, 2, 5.5, 7.25), a.view(), {FillRule::NonZero}).ok());
    ASSERT_TRUE(r.fill(rect(0, 2, 5.5, 7.25), b.view(), {FillRule::NonZero}).ok());
    for (std::size_t i = 0; i < a.px.size(); ++i) ASSERT_NEAR(a.px[i], b.px[i], kFloatTol);
    // Spanning ±DBL_MAX in both axes: the whole target is covered.
    ASSERT_TRUE(r.fill(rect(-big, -big, big, big), a.view(), {FillRule::NonZero}).ok());
    for (float v : a.px) ASSERT_NEAR(v, 1.0, kFloatTol);
    // Random far-away triangles: never a crash, always coverage in [0, 1].
    std::mt19937 rng(707);
    std::uniform_real_distribution<double> expo(-300.0, 300.0);
    for (int trial = 0; trial < 2000; ++trial) {
        Polylines p;
        for (int k = 0; k < 3; ++k) {
            double sx = rng() % 2 ? 1 : -1, sy = rng() % 2 ? 1 : -1;
            p.points.push_back({sx * std::pow(10.0, expo(rng)), sy * std::pow(10.0, expo(rng))});
        }
        p.contour_ends.push_back(3);
        ASSERT_TRUE(r.fill(p, a.view(), fill_at(FillRule::NonZero, {3.5, 4.5})).ok());
        for (float v : a.px) ASSERT_TRUE(v >= 0.0f && v <= 1.0f) << "trial " << trial;
    }
}

TEST(RasterClipping, FarCoordinatesMatchReference) {
    // Edges from ±1e8 crossing the target: clipped in double, compared with the oracle.
    std::mt19937 rng(808);
    std::uniform_real_distribution<double> far(-1e8, 1e8), near(0.0, 20.0);
    Rasterizer r;
    for (int trial = 0; trial < 300; ++trial) {
        Polylines p = polygon({{{far(rng), near(rng)}, {near(rng), far(rng)}, {near(rng), near(rng)}}});
        FloatImage f(20, 20);
        ASSERT_TRUE(r.fill(p, f.view(), {FillRule::NonZero}).ok());
        std::vector<double> ref = reference_coverage(p, FillRule::NonZero, 20, 20, {});
        for (std::size_t i = 0; i < ref.size(); ++i)
            ASSERT_NEAR(f.px[i], ref[i], 1e-3) << "trial " << trial;  // 1e8 in double: ~1e-8 px
    }
}

TEST(RasterClipping, SubnormalEdgeClippedAtTheTopMatchesReference) {
    // fuzz_raster finding: an edge from y = −2⁻¹⁰⁷⁴ to 2⁻¹⁰⁷⁴ clipped at y = 0 took its x from
    // t = 0/0 (both ends halved to 0), a NaN that reached an int conversion. Its cover is
    // nothing; the triangle's other edges give the rest.
    const double tiny = 4.9406564584124654e-324;
    Rasterizer r;
    for (int w : {1, 3}) {
        Polylines p = polygon({{{-2.9149873104633546e-322, -tiny}, {tiny, tiny}, {0.75, 0.9}}});
        FloatImage f(w, 1);
        ASSERT_TRUE(r.fill(p, f.view(), {FillRule::NonZero}).ok());
        std::vector<double> ref = reference_coverage(p, FillRule::NonZero, w, 1, {});
        for (std::size_t i = 0; i < ref.size(); ++i) {
            ASSERT_TRUE(std::isfinite(f.px[i]));
            EXPECT_NEAR(f.px[i], ref[i], 1e-6) << i;
        }
    }
}

// --- Errors and limits -----------------------------------------------------------------------

TEST(RasterErrors, NanOrInfinityIsAnErrorAndLeavesTargetUntouched) {
    Rasterizer r;
    for (double bad : {std::nan(""), HUGE_VAL, -HUGE_VAL}) {
        Mask m(5, 5);
        m.at(2, 2) = 77;
        Polylines p = polygon({{{1, 1}, {bad, 3}, {4, 4}}});
        Status s = r.fill(p, m.view(), {FillRule::NonZero});
        ASSERT_FALSE(s.ok());
        EXPECT_NE(s.error().message.find("NaN"), std::string::npos) << s.error().message;
        EXPECT_EQ(m.at(2, 2), 77);
        EXPECT_FALSE(r.fill(rect(1, 1, 2, 2), m.view(), fill_at(FillRule::NonZero, {bad, 0})).ok());
        EXPECT_EQ(m.at(2, 2), 77);
    }
}

TEST(RasterErrors, TargetLimitsAndBadContoursAreErrors) {
    Rasterizer r;
    std::uint8_t px[4] = {};
    EXPECT_FALSE(r.fill(rect(0, 0, 1, 1), MaskView{px, kMaxBitmapDim + 1, 1, kMaxBitmapDim + 1},
                        {FillRule::NonZero}).ok());
    EXPECT_FALSE(r.fill(rect(0, 0, 1, 1), MaskView{px, -1, 1, 1}, {FillRule::NonZero}).ok());
    EXPECT_FALSE(r.fill(rect(0, 0, 1, 1), MaskView{nullptr, 2, 2, 2}, {FillRule::NonZero}).ok());
    Polylines bad = rect(0, 0, 1, 1);
    bad.contour_ends = {5};
    EXPECT_FALSE(r.fill(bad, MaskView{px, 2, 2, 2}, {FillRule::NonZero}).ok());
    bad.contour_ends = {2};  // two points after the last end
    EXPECT_FALSE(r.fill(bad, MaskView{px, 2, 2, 2}, {FillRule::NonZero}).ok());
    // Empty target and empty polylines are fine.
    EXPECT_TRUE(r.fill(rect(0, 0, 1, 1), MaskView{nullptr, 0, 0, 0}, {FillRule::NonZero}).ok());
    Mask m(3, 3);
    m.at(1, 1) = 9;
    EXPECT_TRUE(r.fill(Polylines{}, m.view(), {FillRule::NonZero}).ok());
    EXPECT_EQ(m.at(1, 1), 0);  // clearing is part of the fill
}

TEST(RasterErrors, FillPathRefusesAnEdgeBudgetBeyondKMaxEdges) {
    // 100 quarter circles at a scale of 1e13 px: each would need ~10⁷ segments at the default
    // tolerance; even at flatten's per-curve cap (kMaxSegmentsPerCurve) that is 6.5M > kMaxEdges.
    Path arcs;
    arcs.move_to({1, 0});
    for (int i = 0; i < 100; ++i) {
        arcs.cubic_to({1, 0.55}, {0.55, 1}, {0, 1});
        arcs.cubic_to({0.55, 1}, {1, 0.55}, {1, 0});
    }
    arcs.close();
    Rasterizer r;
    Mask m(16, 16);
    Status s = r.fill_path(arcs, Affine::scale(1e13), m.view(), {FillRule::NonZero});
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message.find("more than the " + std::to_string(kMaxEdges) + " a fill takes"),
              std::string::npos)
        << s.error().message;
    // Refused before flattening: nothing was allocated for it.
    EXPECT_EQ(r.scratch_capacity_bytes(), 0u);
    // A non-finite transform is an error too.
    EXPECT_FALSE(
        r.fill_path(arcs, Affine::scale(std::nan("")), m.view(), {FillRule::NonZero}).ok());
}

// --- Targets with stride, float output, path filling, steady-state memory -------------------

TEST(RasterTarget, RendersIntoAtlasSubViewWithoutTouchingNeighbours) {
    Mask atlas(64, 32);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 64; ++x) atlas.at(x, y) = 123;
    Polylines p = polygon({{{1.3, 0.2}, {13.7, 4.1}, {6.2, 11.9}}});
    Rasterizer r;
    MaskView sub = atlas.view().sub(20, 10, 15, 13);
    ASSERT_TRUE(r.fill(p, sub, {FillRule::NonZero}).ok());
    Mask alone(15, 13);
    ASSERT_TRUE(r.fill(p, alone.view(), {FillRule::NonZero}).ok());
    for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 64; ++x) {
            bool inside = x >= 20 && x < 35 && y >= 10 && y < 23;
            EXPECT_EQ(atlas.at(x, y), inside ? alone.at(x - 20, y - 10) : 123) << x << "," << y;
        }
    }
}

TEST(RasterTarget, NegativeStrideRendersBottomUpMemory) {
    Mask m(10, 10);
    Polylines p = polygon({{{0, 0}, {10, 0}, {0, 10}}});
    Rasterizer r;
    // Row 0 of the view is the LAST row of the memory.
    MaskView flipped{&m.at(0, 9), 10, 10, -10};
    ASSERT_TRUE(r.fill(p, flipped, {FillRule::NonZero}).ok());
    Mask direct(10, 10);
    ASSERT_TRUE(r.fill(p, direct.view(), {FillRule::NonZero}).ok());
    for (int y = 0; y < 10; ++y)
        for (int x = 0; x < 10; ++x) EXPECT_EQ(m.at(x, 9 - y), direct.at(x, y));
}

TEST(RasterTarget, FillPathOfCircleCoversItsArea) {
    // A circle of radius 20 px from four cubic arcs (k = 0.5522847498): the arcs deviate from the
    // circle by 2.7e-4 relative, so the area is π·r²·(1 ± 6e-4), flattening adds < 0.1 px·perimeter.
    const double k = 0.5522847498;
    Path c;
    c.move_to({1, 0});
    c.cubic_to({1, k}, {k, 1}, {0, 1});
    c.cubic_to({-k, 1}, {-1, k}, {-1, 0});
    c.cubic_to({-1, -k}, {-k, -1}, {0, -1});
    c.cubic_to({k, -1}, {1, -k}, {1, 0});
    c.close();
    Rasterizer r;
    FloatImage img(50, 50);
    Affine m = Affine::translate({25.25, 24.5}) * Affine::scale(20.0);
    ASSERT_TRUE(r.fill_path(c, m, img.view(), {FillRule::NonZero}).ok());
    double sum = 0.0;
    for (float v : img.px) sum += v;
    EXPECT_NEAR(sum, M_PI * 400.0, M_PI * 400.0 * 6e-4 + 0.1 * 2 * M_PI * 20.0);
    EXPECT_NEAR(img.at(25, 24), 1.0, kFloatTol);
    EXPECT_NEAR(img.at(2, 2), 0.0, kFloatTol);
}

TEST(RasterTarget, BalancedFlatteningKeepsTheAreaOfAParabolicSegment) {
    // The region between the chord (0,0)–(20,0) and the quadratic with control (10,20) has area
    // 2/3 · base · height = 2/3 · 20 · 10. Plain chords (flatten(), n = 7 at 0.25 px) lose
    // 1/n² of it (each of the n parabolic slivers is 1/n³ of the whole): 2.7 px². fill_path's
    // balanced vertices cancel that up to the two half-corrected end chords.
    Path p;
    p.move_to({0, 0});
    p.quad_to({10, 20}, {20, 0});
    p.close();
    FlattenOptions o;
    o.tolerance_px = 0.25;
    const Affine m = Affine::translate({2.5, 2.25});
    auto area = [](const FloatImage& img) {
        double sum = 0.0;
        for (float v : img.px) sum += v;
        return sum;
    };
    Rasterizer r;
    FloatImage balanced(25, 15), plain(25, 15);
    ASSERT_TRUE(
        r.fill_path(p, m, balanced.view(), {FillRule::NonZero, OverlapMode::Accumulate, o}).ok());
    Polylines lines;
    flatten(p, m, o, lines);
    ASSERT_TRUE(r.fill(lines, plain.view(), {FillRule::NonZero}).ok());
    const double exact = 2.0 / 3.0 * 20.0 * 10.0;
    EXPECT_NEAR(area(plain), exact - exact / 49.0, 1e-3);  // the bias being removed
    EXPECT_LT(std::fabs(area(balanced) - exact), 0.25 * (exact - area(plain)));
}

TEST(RasterTarget, ReusedRasterizerStopsGrowingAfterTheLargestFill) {
    std::mt19937 rng(909);
    Rasterizer r;
    Mask big(200, 200);
    ASSERT_TRUE(r.fill(rect(-1, -1, 201, 201), big.view(), {FillRule::NonZero}).ok());
    const std::size_t after_first = r.scratch_capacity_bytes();
    for (int trial = 0; trial < 200; ++trial) {
        int w = 1 + static_cast<int>(rng() % 200), h = 1 + static_cast<int>(rng() % 200);
        Mask m(w, h);
        ASSERT_TRUE(
            r.fill(random_polygon(rng, 10, -20, 220), m.view(), {FillRule::EvenOdd}).ok());
        ASSERT_EQ(r.scratch_capacity_bytes(), after_first);
    }
}

// --- Sweep kernels: SIMD against scalar ---------------------------------------------------------

// A group of `rows` rows of n cells (column-major, as sweep.hpp lays it out) on a 32-byte
// aligned start, with deltas in a random subset of blocks; `flags` marks exactly those, plus
// some spurious marks, which must be harmless.
struct RandomGroup {
    std::vector<float> storage;
    std::vector<std::uint8_t> flags;
    float* acc = nullptr;
};
RandomGroup random_group(std::mt19937& rng, int n, int rows) {
    using namespace raster_detail;
    std::uniform_real_distribution<float> delta(-1.0f, 1.0f);
    RandomGroup g;
    g.storage.assign(static_cast<std::size_t>(group_cells(n)) + 8, 0.0f);
    g.acc = band_cells(g.storage, static_cast<std::size_t>(group_cells(n)));
    g.flags.assign(static_cast<std::size_t>(row_flag_bytes(n)), 0);
    for (int b = 0; b < row_blocks(n); ++b) {
        if (rng() % 3 == 0) {
            g.flags[b] = 1;
            for (int i = b * kBlock; i < (b + 1) * kBlock && i < n + 2; ++i)
                for (int r = 0; r < rows; ++r)
                    if (rng() % 2) g.acc[i * kGroupRows + r] = delta(rng) * 1.5f;
        } else if (rng() % 8 == 0) {
            g.flags[b] = 1;  // marked but empty
        }
    }
    return g;
}

// An aligned copy of `cells` floats from `src` (vector copies move the alignment).
struct AlignedCells {
    std::vector<float> storage;
    float* data;
    AlignedCells(const float* src, std::size_t cells) : storage(cells + 8, 0.0f) {
        data = raster_detail::band_cells(storage, cells);
        std::copy(src, src + cells, data);
    }
};

// The scalar reference for one row r of a group: its running sums, cell by cell.
template <typename Out>
std::vector<Out> reference_row(const float* acc, int n, int r, FillRule rule) {
    using namespace raster_detail;
    std::vector<Out> out(static_cast<std::size_t>(n));
    float sum = 0.0f;
    for (int i = 0; i < n; ++i) {
        sum += acc[i * kGroupRows + r];
        if constexpr (sizeof(Out) == 1)
            out[i] = coverage_u8(sum, rule);
        else
            out[i] = coverage_of(sum, rule);
    }
    return out;
}

TEST(RasterKernels, GroupSweepsMatchRowByRowSumsOnRandomGroups) {
    // Every kernel (scalar included) against the running sums of each row taken one by one:
    // runs of unmarked blocks are filled with each row's running coverage, marked ones summed,
    // partial groups and rows written only where they exist, acc and flags left all zero.
    using namespace raster_detail;
    std::vector<const SweepKernels*> kernels = {&scalar_kernels(), &sse2_kernels()};
    if (avx2_kernels()) kernels.push_back(avx2_kernels());
    std::mt19937 rng(1010);
    for (int trial = 0; trial < 1500; ++trial) {
        const int n = 1 + static_cast<int>(rng() % 200);
        const int rows = 1 + static_cast<int>(rng() % kGroupRows);
        const int out_stride = n + static_cast<int>(rng() % 5);
        RandomGroup g = random_group(rng, n, rows);
        for (int rule = 0; rule < 2; ++rule) {
            const FillRule fr = static_cast<FillRule>(rule);
            for (const SweepKernels* k : kernels) {
                const std::size_t cells = static_cast<std::size_t>(group_cells(n));
                AlignedCells b(g.acc, cells);
                std::vector<std::uint8_t> fl = g.flags;
                std::vector<float> kf(static_cast<std::size_t>(out_stride) * kGroupRows, -1.0f);
                k->f32[rule](b.data, fl.data(), n, rows, kf.data(), out_stride);
                for (float v : b.storage) ASSERT_EQ(v, 0.0f) << k->name << ": acc not re-zeroed";
                for (std::uint8_t f : fl) ASSERT_EQ(f, 0) << k->name << ": flags not cleared";
                AlignedCells c(g.acc, cells);
                fl = g.flags;
                std::vector<std::uint8_t> k8(static_cast<std::size_t>(out_stride) * kGroupRows, 7);
                k->u8[rule](c.data, fl.data(), n, rows, k8.data(), out_stride);
                for (float v : c.storage) ASSERT_EQ(v, 0.0f) << k->name << ": acc not re-zeroed";
                for (int r = 0; r < kGroupRows; ++r) {
                    if (r >= rows) {  // rows past the group's end are not written
                        for (int i = 0; i < out_stride; ++i)
                            ASSERT_EQ(k8[r * out_stride + i], 7) << k->name << " row " << r;
                        continue;
                    }
                    const std::vector<float> sf = reference_row<float>(g.acc, n, r, fr);
                    const std::vector<std::uint8_t> s8 = reference_row<std::uint8_t>(g.acc, n, r, fr);
                    for (int i = 0; i < n; ++i) {
                        ASSERT_NEAR(kf[r * out_stride + i], sf[i], 1e-5)
                            << k->name << " n " << n << " row " << r << " i " << i;
                        ASSERT_LE(std::abs(int(k8[r * out_stride + i]) - int(s8[i])), 1)
                            << k->name << " n " << n << " row " << r << " i " << i;
                    }
                    for (int i = n; i < out_stride; ++i)  // nothing written between rows
                        ASSERT_EQ(k8[r * out_stride + i], 7) << k->name;
                }
            }
        }
    }
}

// Two empty W × H bands (cells and flags) for drawing the same edges two ways, with the given
// steep-edge kernels (null: every row drawn one by one).
struct BandPair {
    std::vector<float> sa, sb;
    std::vector<std::uint8_t> fa, fb;
    std::size_t cells;
    raster_detail::Band first, second;
    BandPair(int W, int H, const raster_detail::SteepKernels* ka,
             const raster_detail::SteepKernels* kb)
        : fa(static_cast<std::size_t>(raster_detail::row_groups(H) * raster_detail::row_flag_bytes(W))),
          fb(fa.size()),
          cells(static_cast<std::size_t>(raster_detail::row_groups(H)) * raster_detail::group_cells(W)),
          first{raster_detail::band_cells(sa, cells), fa.data(), raster_detail::group_cells(W),
                raster_detail::row_flag_bytes(W), W, H, ka},
          second{raster_detail::band_cells(sb, cells), fb.data(), raster_detail::group_cells(W),
                 raster_detail::row_flag_bytes(W), W, H, kb} {}
    BandPair(const BandPair&) = delete;
    BandPair& operator=(const BandPair&) = delete;
};

TEST(RasterKernels, VectorSteepEdgesAddTheCellsOfTheRowByRowLoop) {
    // The full rows of long steep edges and stems, which draw_line hands to the AVX2 kernels
    // (draw_avx2.cpp) eight at a time, the rows of partial groups masked. Drawn into a band with
    // the kernels and into one without, every cell must match: steep edges bit for bit (the same
    // operations in the same order), stems within float rounding (the scalar stem loop steps x
    // by dxdy, the kernel takes it from the formula at each row border). Both directions, both
    // marking modes; the kernels may mark a block the loop does not (the column range of a
    // group), never the reverse.
    using namespace raster_detail;
    const SteepKernels* k = avx2_steep_kernels();
    if (k == nullptr) GTEST_SKIP() << "no AVX2 on this CPU";
    const int W = 90, H = 120;
    BandPair pair(W, H, k, nullptr);
    const Band& with = pair.first;
    const Band& without = pair.second;
    float* const a = with.acc;
    float* const b = without.acc;
    const std::size_t cells = pair.cells;
    const std::vector<std::uint8_t>& fa = pair.fa;
    const std::vector<std::uint8_t>& fb = pair.fb;
    std::mt19937 rng(4242);
    std::uniform_real_distribution<double> ux(0.0, W), uy(0.0, H), du(-1.0, 1.0);
    int steep = 0, stems = 0;
    for (int trial = 0; trial < 400; ++trial) {
        const bool stem = trial % 2 == 1;
        double x0 = ux(rng), y0 = uy(rng), y1 = uy(rng), x1;
        if (std::abs(y1 - y0) < 3.0) continue;  // some full rows between its end rows
        if (stem) {
            const double c = std::floor(x0);
            x0 = c + 0.5 + 0.49 * du(rng);
            x1 = c + 0.5 + 0.49 * du(rng);
            if (x0 >= W || x1 >= W) continue;
        } else {
            x1 = std::clamp(x0 + du(rng) * std::abs(y1 - y0), 0.0, static_cast<double>(W));
            if (std::floor(std::min(x0, x1)) + 1.0 >= std::max(x0, x1)) continue;  // a stem
        }
        (stem ? stems : steep)++;
        if (trial % 3 == 0) {
            draw_line<true>(with, x0, y0, x1, y1);
            draw_line<true>(without, x0, y0, x1, y1);
        } else {
            draw_line<false>(with, x0, y0, x1, y1);
            draw_line<false>(without, x0, y0, x1, y1);
        }
        for (std::size_t c = 0; c < cells; ++c) {
            if (stem) {
                ASSERT_NEAR(a[c], b[c], 1e-5) << "stem, trial " << trial << " cell " << c;
            } else {
                ASSERT_EQ(a[c], b[c]) << "steep edge, trial " << trial << " cell " << c;
            }
        }
        if (trial % 3 == 0) {  // every block the loop marks is marked (extra marks are harmless)
            for (std::size_t f = 0; f < fa.size(); ++f) ASSERT_GE(fa[f], fb[f]) << "flag " << f;
        }
        std::copy(a, a + cells, b);  // the next trial starts from equal bands
    }
    EXPECT_GT(steep, 50);
    EXPECT_GT(stems, 50);
}

// Random batches of every shape the batch kernels sort: one-row pieces in two columns or more,
// pieces across one row border, stems, long and wide edges, horizontal ones, odd and even
// counts, inside [0, W] × [0, H]. Returns the count; `fast_like` counts those inside one row
// and two columns (or horizontal).
int random_batch(std::mt19937& rng, int W, int H, raster_detail::SegmentBatch& out,
                 int& fast_like) {
    using raster_detail::SegmentBatch;
    std::uniform_real_distribution<double> ux(0.0, W), uy(0.0, H), u(0.0, 1.0), du(-1.0, 1.0);
    const auto clampx = [&](double x) { return std::clamp(x, 0.0, static_cast<double>(W)); };
    const auto clampy = [&](double y) { return std::clamp(y, 0.0, static_cast<double>(H)); };
    const int n = 1 + static_cast<int>(u(rng) * SegmentBatch::kSize);
    for (int q = 0; q < n; ++q) {
        const double x0 = ux(rng), y0 = uy(rng);
        double x1 = x0, y1 = y0;
        switch (static_cast<int>(u(rng) * 6)) {
            case 0: case 1:  // inside one row, up to 1 wide, or 2 (two columns or three)
                x1 = clampx(x0 + (q % 2 == 0 ? 1.0 : 2.0) * du(rng));
                y1 = std::min(std::floor(y0) + u(rng), static_cast<double>(H));
                break;
            case 2:  // across one row border, narrow (the cut ones)
                x1 = clampx(x0 + du(rng));
                y1 = clampy(y0 + (u(rng) < 0.5 ? -1.0 : 1.0) * (1.0 + u(rng)));
                break;
            case 3:  // a stem
                x1 = clampx(std::floor(x0) + u(rng));
                y1 = uy(rng);
                break;
            case 4:  // long or wide, any direction
                x1 = ux(rng);
                y1 = u(rng) < 0.3 ? clampy(y0 + 0.5 * du(rng)) : uy(rng);
                break;
            default:  // horizontal: draws nothing
                x1 = ux(rng);
                break;
        }
        if (y1 == y0 || (std::floor(std::min(y0, y1)) + 1.0 >= std::max(y0, y1) &&
                         std::floor(std::min(x0, x1)) + 2.0 >= std::max(x0, x1)))
            ++fast_like;
        out.seg[q] = {_mm_set_pd(y0, x0), _mm_set_pd(y1, x1)};
    }
    out.seg[n] = {_mm_setzero_pd(), _mm_setzero_pd()};  // the pair loop's padding
    return n;
}

// The float segments of a dense band's batch (dense_batch.hpp) from its double ones, rounded as
// the direct route's walk rounds them.
void to_float_segments(raster_detail::SegmentBatch& b, int n) {
    for (int q = 0; q < n; ++q)
        b.fseg[q] = _mm_movelh_ps(_mm_cvtpd_ps(b.seg[q].a), _mm_cvtpd_ps(b.seg[q].b));
}

TEST(RasterKernels, FourSegmentBatchesLeaveThePairLoopsBandBitForBit) {
    // The direct route hands its queued segments to the AVX2 batches (draw_batch_avx2.cpp) when
    // the CPU has them, else to the baseline loops: for marked (sparse) bands the SSE2 pair loop
    // (draw_batch.hpp), for dense bands the four-lane float loop (dense_batch.hpp, F4), whose
    // AVX2 copy runs eight lanes. Each pair does the same lane operations in the same order and
    // sets aside the same segments, so on random batches of every shape the cells must match
    // bit for bit, and so must the block flags, in all three modes (dense, which always cuts;
    // marked, cutting or not).
    using namespace raster_detail;
    const BatchKernels* k = avx2_batch_kernels();
    if (k == nullptr) GTEST_SKIP() << "no AVX2 on this CPU";
    const int W = 60, H = 50;
    std::mt19937 rng(9001);
    int fast_like = 0, drawn = 0;
    for (int mode = 0; mode < 3; ++mode) {
        const bool mark = mode != 0, split = mode == 2;
        BandPair pair(W, H, avx2_steep_kernels(), avx2_steep_kernels());
        for (int trial = 0; trial < 300; ++trial) {
            SegmentBatch sse, four;
            const int n = random_batch(rng, W, H, sse, fast_like);
            four = sse;
            drawn += n;
            if (mark) {
                if (split) draw_batch<true, true>(pair.first, sse, n);
                else draw_batch<true, false>(pair.first, sse, n);
                k->marked[split](pair.second, four, n);
            } else {
                to_float_segments(sse, n);
                to_float_segments(four, n);
                draw_dense_batch<F4>(pair.first, sse, n);
                k->dense(pair.second, four, n);
            }
            for (std::size_t c = 0; c < pair.cells; ++c)
                ASSERT_EQ(pair.first.acc[c], pair.second.acc[c])
                    << "mode " << mode << " trial " << trial << " cell " << c;
            ASSERT_EQ(pair.fa, pair.fb) << "mode " << mode << " trial " << trial;
        }
    }
    EXPECT_GT(fast_like, drawn / 3);  // the vector lanes are exercised, not only the set-aside
}

TEST(RasterKernels, DenseFloatBatchAddsTheDoublePairLoopsCellsWithinFloatRounding) {
    // The dense batch works in single precision on vertices rounded to float; the SSE2 pair loop
    // in double on the same segments is the reference. Each cell of the band must agree within
    // the float rounding of the values added to it (a cell's deltas are bounded by the rows'
    // cover, at most a few per cell here), and the prefix sums — the coverage — as well. Both
    // cut segments across one row border.
    using namespace raster_detail;
    const int W = 60, H = 50;
    std::mt19937 rng(4711);
    int fast_like = 0;
    double worst = 0.0;
    {
        BandPair pair(W, H, avx2_steep_kernels(), avx2_steep_kernels());
        for (int trial = 0; trial < 600; ++trial) {
            SegmentBatch dbl, flt;
            const int n = random_batch(rng, W, H, dbl, fast_like);
            flt = dbl;
            to_float_segments(flt, n);
            draw_batch<false, true>(pair.first, dbl, n);
            draw_dense_batch<F4>(pair.second, flt, n);
            for (int y = 0; y < H; ++y) {
                const float* ra = row_of(pair.first, y);
                const float* rb = row_of(pair.second, y);
                double sa = 0.0, sb = 0.0;
                for (int x = 0; x < W + 2; ++x) {
                    ASSERT_NEAR(ra[x * kCell], rb[x * kCell], 2e-5)
                        << "trial " << trial << " row " << y << " cell " << x;
                    sa += ra[x * kCell];
                    sb += rb[x * kCell];
                    worst = std::max(worst, std::fabs(sa - sb));
                }
            }
            std::copy(pair.first.acc, pair.first.acc + pair.cells, pair.second.acc);
        }
    }
    EXPECT_LT(worst, 1e-4);
    EXPECT_GT(worst, 0.0);  // the float route is really taken: it rounds differently
    RecordProperty("worst_coverage_difference", std::to_string(worst));
}

TEST(RasterKernels, DenseSteepSegmentsCutAtEveryRowAddTheCellsOfDrawLine) {
    // A dense batch cuts a steep segment (|dx| ≤ |dy| ≤ kSteepPieceMaxDy) that crosses two row
    // borders or more into one-row pieces for its narrow lanes (dense_steep), in float;
    // draw_line's steep case in double is the reference. Segments of 2 to kSteepPieceMaxDy
    // rows (a batch's pieces fill several kSteepChunk chunks) and some taller (set aside for
    // draw_line), both directions, ends on the band's left and right borders and just above
    // row 0 (the direct route's excursions): every cell within float rounding of the
    // reference, through the baseline batch (F4) and the AVX2 one when the CPU has it.
    using namespace raster_detail;
    const int W = 40, H = 120;
    std::mt19937 rng(31337);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    BatchFn kernels[2] = {draw_dense_batch<F4>, nullptr};
    if (const BatchKernels* k = avx2_batch_kernels()) kernels[1] = k->dense;
    for (BatchFn kernel : kernels) {
        if (kernel == nullptr) continue;
        BandPair pair(W, H, nullptr, nullptr);
        for (int trial = 0; trial < 300; ++trial) {
            SegmentBatch b;
            const int n = 1 + static_cast<int>(u(rng) * 24);
            for (int q = 0; q < n; ++q) {
                const double len = q % 4 == 3 ? 2.0 + u(rng) * (H - 3)
                                              : 2.0 + u(rng) * (kSteepPieceMaxDy - 2.0);
                double y0 = u(rng) * (H - len), y1 = y0 + len;
                if (q % 5 == 0) y0 = -0.3 * u(rng);  // an excursion above row 0
                double x0 = u(rng) * W;
                double x1 = std::clamp(x0 + (2.0 * u(rng) - 1.0) * (y1 - y0), 0.0, double(W));
                if (q % 7 == 0) x0 = q % 2 ? 0.0 : W;
                if (std::fabs(x1 - x0) > y1 - y0) x1 = x0;  // steep (and so a stem) at worst
                if (q % 2) std::swap(y0, y1), std::swap(x0, x1);
                const __m128 f = _mm_setr_ps(float(x0), float(y0), float(x1), float(y1));
                b.fseg[q] = f;
                alignas(16) float e[4];
                _mm_store_ps(e, f);  // the reference draws the float-rounded vertices
                draw_line<false>(pair.first, e[0], e[1], e[2], e[3]);
            }
            kernel(pair.second, b, n);
            for (int y = 0; y < H; ++y) {
                const float* ra = row_of(pair.first, y);
                const float* rb = row_of(pair.second, y);
                for (int x = 0; x < W + 3; ++x)
                    ASSERT_NEAR(ra[x * kCell], rb[x * kCell], 2e-5)
                        << "trial " << trial << " row " << y << " cell " << x;
            }
            std::fill(pair.first.acc, pair.first.acc + pair.cells, 0.0f);
            std::fill(pair.second.acc, pair.second.acc + pair.cells, 0.0f);
        }
    }
}

TEST(RasterKernels, ShallowPiecesAcrossOneBorderAddTheCellsOfTheColumnWalk) {
    // In sparse (marked) bands, draw_line gives a shallow edge's row pieces that cross at most
    // one column border to the three-cell narrow piece; dense bands still walk the columns
    // (draw_row_piece). On random shallow edges, one row and several, both directions, the two
    // must add the same cells within float rounding, and every block holding a delta must be
    // marked.
    using namespace raster_detail;
    const int W = 70, H = 30;
    BandPair pair(W, H, nullptr, nullptr);
    const Band& marked = pair.first;
    const Band& dense = pair.second;
    std::mt19937 rng(777);
    std::uniform_real_distribution<double> ux(0.0, W), uy(0.0, H - 1.0), u(0.0, 1.0);
    int narrow_wide = 0;  // pieces wider than 1 that take the narrow route
    for (int trial = 0; trial < 3000; ++trial) {
        const double y0 = uy(rng), dy = (trial % 3 == 0 ? 0.9 : 4.0) * u(rng) + 0.01;
        const double y1 = std::min(y0 + dy, static_cast<double>(H));
        const double dx = (std::abs(y1 - y0) + 0.01) * (1.0 + 2.0 * u(rng)) * (u(rng) < 0.5 ? -1 : 1);
        const double x0 = ux(rng), x1 = std::clamp(x0 + dx, 0.0, static_cast<double>(W));
        if (std::abs(x1 - x0) <= std::abs(y1 - y0)) continue;  // not shallow after the clamp
        if (std::abs(x1 - x0) > 1.0 && std::floor(std::max(x0, x1)) - std::floor(std::min(x0, x1)) <= 1.0)
            ++narrow_wide;
        const bool up = trial % 2 == 1;
        draw_line<true>(marked, up ? x1 : x0, up ? y1 : y0, up ? x0 : x1, up ? y0 : y1);
        draw_line<false>(dense, up ? x1 : x0, up ? y1 : y0, up ? x0 : x1, up ? y0 : y1);
        for (int y = 0; y < H; ++y) {
            const float* ra = row_of(marked, y);
            const float* rb = row_of(dense, y);
            const std::uint8_t* flags = flags_of(marked, y);
            for (int x = 0; x < row_cells(W); ++x) {
                ASSERT_NEAR(ra[x * kCell], rb[x * kCell], 2e-5)
                    << "trial " << trial << " row " << y << " cell " << x;
                if (ra[x * kCell] != 0.0f) {
                    ASSERT_EQ(flags[x >> kBlockShift], 1) << "unmarked";
                }
            }
        }
    }
    EXPECT_GT(narrow_wide, 300);
}

TEST(RasterKernels, EdgesStartingJustAboveRowZeroKeepEveryRowBalanced) {
    // The direct route hands its drawing vertices up to 1/3 px above row 0 (balanced vertices
    // outside the control box); row 0 takes that part of every edge. If one drawing path
    // clipped it instead, the deltas of row 0 would no longer add up to zero past the polygon
    // and a streak would run to the row's end. Closed polygons with such a vertex, each edge a
    // stem, a steep edge or a shallow one, long enough for the vector kernels: every row's
    // deltas must sum to zero, through draw_line with and without the kernels, and through the
    // dense float batch (dense_batch.hpp, which draws stems itself) in both lane counts.
    using namespace raster_detail;
    const int W = 40, H = 60;
    const std::size_t cells = static_cast<std::size_t>(row_groups(H)) * group_cells(W);
    const BatchKernels* four = avx2_batch_kernels();
    const double polys[][3][2] = {
        {{5.5, -0.25}, {5.9, 50.5}, {20.2, 44.0}},    // a stem from above row 0
        {{5.5, -0.3}, {12.8, 47.2}, {30.1, 10.5}},    // a steep edge from above row 0
        {{2.5, -0.05}, {38.0, 3.5}, {3.1, 40.0}},     // a shallow one
        {{7.25, 30.0}, {7.75, -0.2}, {30.0, 20.0}},   // a stem up to above row 0
    };
    // Routes: draw_line with the AVX2 kernels, without them, the float batch in four lanes,
    // in eight (AVX2 only).
    for (int route = 0; route < 4; ++route) {
        if ((route == 0 && avx2_steep_kernels() == nullptr) || (route == 3 && four == nullptr))
            continue;
        for (const auto& poly : polys) {
            std::vector<float> storage;
            float* acc = band_cells(storage, cells);
            std::vector<std::uint8_t> flags(static_cast<std::size_t>(row_groups(H) * row_flag_bytes(W)));
            const Band band{acc, flags.data(), group_cells(W), row_flag_bytes(W), W, H,
                            route == 1 ? nullptr : avx2_steep_kernels()};
            if (route < 2) {
                for (int e = 0; e < 3; ++e)
                    draw_line<false>(band, poly[e][0], poly[e][1], poly[(e + 1) % 3][0],
                                     poly[(e + 1) % 3][1]);
            } else {
                SegmentBatch b;
                for (int e = 0; e < 3; ++e)
                    b.seg[e] = {_mm_set_pd(poly[e][1], poly[e][0]),
                                _mm_set_pd(poly[(e + 1) % 3][1], poly[(e + 1) % 3][0])};
                to_float_segments(b, 3);
                if (route == 2) draw_dense_batch<F4>(band, b, 3);
                else four->dense(band, b, 3);
            }
            for (int y = 0; y < H; ++y) {
                double sum = 0.0;
                for (int x = 0; x < row_cells(W); ++x) sum += row_of(band, y)[x * kCell];
                ASSERT_NEAR(sum, 0.0, 1e-5) << "row " << y << ", route " << route
                                            << ", polygon from y " << poly[0][1];
            }
        }
    }
}

TEST(RasterKernels, OneTableIsChosenAndItIsAvx2ExactlyWhenEveryAvx2KernelExists) {
    // Fills take every run-time kernel from kernel_table(): the AVX2 table holds all three AVX2
    // kernels or does not exist, the baseline table holds the SSE2 sweep and no other kernel, and
    // the public diagnostics name the chosen one.
    using namespace raster_detail;
    const KernelTable& base = baseline_table();
    EXPECT_STREQ(base.name, "sse2");
    EXPECT_EQ(base.sweep, &sse2_kernels());
    EXPECT_EQ(base.steep, nullptr);
    EXPECT_EQ(base.batch, nullptr);
    const KernelTable* avx2 = avx2_table();
    const bool has_avx2 = avx2_kernels() != nullptr;
    EXPECT_EQ(avx2_steep_kernels() != nullptr, has_avx2);
    EXPECT_EQ(avx2_batch_kernels() != nullptr, has_avx2);
    ASSERT_EQ(avx2 != nullptr, has_avx2);
    if (avx2 != nullptr) {
        EXPECT_EQ(avx2->sweep, avx2_kernels());
        EXPECT_EQ(avx2->steep, avx2_steep_kernels());
        EXPECT_EQ(avx2->batch, avx2_batch_kernels());
    }
    EXPECT_EQ(&kernel_table(), has_avx2 ? avx2 : &base);
    EXPECT_STREQ(raster_kernel_name(), kernel_table().name);
}

TEST(RasterKernels, WangStepCountIsTheCeilingOfWangsFormula) {
    // wang_steps counts ⌈s⌉, s = √(√dd2 · k), by compares up to 16 (two ladders) and by square
    // roots past it; every branch must give the formula's ceiling: just below and just above
    // each integer up to 40, at random values across the ladders and the square-root path,
    // and 0 past kMaxSegmentsPerCurve or for NaN.
    using namespace raster_detail;
    const auto formula = [](double dd2, double k) {
        return static_cast<int>(std::ceil(std::sqrt(std::sqrt(dd2) * k)));
    };
    for (int i = 1; i <= 40; ++i) {
        for (double s : {i - 1e-6, i - 1e-9, i + 1e-9, i + 1e-6}) {
            const double k = 0.75, dd2 = std::pow(s / k, 4.0) * k * k;  // √(√dd2 · k) = s
            ASSERT_EQ(wang_steps(dd2, k), formula(dd2, k)) << "s " << s;
        }
    }
    std::mt19937 rng(16);
    std::uniform_real_distribution<double> us(0.0, 60.0), uk(0.05, 40.0);
    int ladder = 0, second = 0, roots = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const double s = us(rng), k = uk(rng);
        const double dd2 = std::pow(s * s / k, 2.0);
        const int n = wang_steps(dd2, k);
        ASSERT_EQ(n, formula(dd2, k)) << "dd2 " << dd2 << " k " << k;
        (n <= 8 ? ladder : n <= 16 ? second : roots)++;
    }
    EXPECT_GT(ladder, 1000);
    EXPECT_GT(second, 1000);
    EXPECT_GT(roots, 1000);
    const double cap = static_cast<double>(kMaxSegmentsPerCurve);
    EXPECT_EQ(wang_steps(std::pow(cap * cap, 2.0), 1.0), static_cast<int>(kMaxSegmentsPerCurve));
    EXPECT_EQ(wang_steps(std::pow((cap + 0.5) * (cap + 0.5), 2.0), 1.0), 0);
    EXPECT_EQ(wang_steps(std::nan(""), 1.0), 0);
}

TEST(RasterKernels, DenseBandSweepsMatchRowByRowSums) {
    // The dense kernels sum every block of every group of a band in one call (no flags) and
    // write rows out_stride apart; each row must equal its running sums, and acc must end all
    // zero, guard cells included. A quarter of the bands are at most eight pixels wide, which
    // the AVX2 kernel sums by its narrow path.
    using namespace raster_detail;
    std::vector<const SweepKernels*> kernels = {&scalar_kernels(), &sse2_kernels()};
    if (avx2_kernels()) kernels.push_back(avx2_kernels());
    std::mt19937 rng(1111);
    std::uniform_real_distribution<float> delta(-1.0f, 1.0f);
    for (int trial = 0; trial < 500; ++trial) {
        const int n = 1 + static_cast<int>(rng() % (trial % 4 == 0 ? 8 : 170));
        const int rows = 1 + static_cast<int>(rng() % 20);
        const std::ptrdiff_t stride = group_cells(n);
        const int out_stride = n + static_cast<int>(rng() % 5);
        const std::size_t cells = static_cast<std::size_t>(row_groups(rows) * stride);
        std::vector<float> storage(cells + 8, 0.0f);
        float* band = band_cells(storage, cells);
        for (int y = 0; y < rows; ++y)
            for (int i = 0; i < row_cells(n); ++i)
                if (rng() % 3 == 0)
                    band[(y / kGroupRows) * stride + i * kGroupRows + y % kGroupRows] =
                        delta(rng) * 1.5f;
        for (int rule = 0; rule < 2; ++rule) {
            const FillRule fr = static_cast<FillRule>(rule);
            for (const SweepKernels* k : kernels) {
                AlignedCells b(band, cells);
                std::vector<float> kf(static_cast<std::size_t>(out_stride) * rows, -1.0f);
                k->dense_f32[rule](b.data, stride, n, rows, kf.data(), out_stride);
                for (float v : b.storage) ASSERT_EQ(v, 0.0f) << k->name << ": acc not re-zeroed";
                AlignedCells c(band, cells);
                std::vector<std::uint8_t> k8(static_cast<std::size_t>(out_stride) * rows, 7);
                k->dense_u8[rule](c.data, stride, n, rows, k8.data(), out_stride);
                for (float v : c.storage) ASSERT_EQ(v, 0.0f) << k->name << ": acc not re-zeroed";
                for (int y = 0; y < rows; ++y) {
                    const float* group = band + (y / kGroupRows) * stride;
                    const std::vector<float> sf = reference_row<float>(group, n, y % kGroupRows, fr);
                    const std::vector<std::uint8_t> s8 =
                        reference_row<std::uint8_t>(group, n, y % kGroupRows, fr);
                    for (int i = 0; i < n; ++i) {
                        ASSERT_NEAR(kf[y * out_stride + i], sf[i], 1e-5) << k->name;
                        ASSERT_LE(std::abs(int(k8[y * out_stride + i]) - int(s8[i])), 1)
                            << k->name << " n " << n << " row " << y << " i " << i;
                    }
                    for (int i = n; i < out_stride; ++i)  // nothing written between rows
                        ASSERT_EQ(k8[y * out_stride + i], 7) << k->name;
                }
            }
        }
    }
}

TEST(RasterKernels, ByteSweepsSaturateAtFullCoverageForEveryWindingUpToTheEdgeLimit) {
    // The AVX2 byte kernels leave the clamp to 1 to the saturating packs, so a running sum of
    // any magnitude up to the winding bound (kMaxEdges) must still come out 255 under non-zero,
    // and under even-odd as the parity of the winding says. Each row holds one value from the
    // first column on, so every pixel of the row has it as its running sum.
    using namespace raster_detail;
    std::vector<const SweepKernels*> kernels = {&scalar_kernels(), &sse2_kernels()};
    if (avx2_kernels()) kernels.push_back(avx2_kernels());
    const float big = static_cast<float>(kMaxEdges);
    const float values[2][kGroupRows] = {{big, -big, 3.0f, -2.0f, 1.0f, -1.0f, 1.5f, 0.25f},
                                         {1000.0f, -1000.0f, 2.0f, 17.0f, -17.0f, 0.5f, -0.5f, 0.0f}};
    for (int n : {5, 8, 16, 40}) {
        const std::ptrdiff_t stride = group_cells(n);
        for (const auto& vs : values) {
            for (int rule = 0; rule < 2; ++rule) {
                const FillRule fr = static_cast<FillRule>(rule);
                for (const SweepKernels* k : kernels) {
                    for (int dense = 0; dense < 2; ++dense) {
                        std::vector<float> storage(static_cast<std::size_t>(stride) + 8, 0.0f);
                        float* acc = band_cells(storage, static_cast<std::size_t>(stride));
                        for (int r = 0; r < kGroupRows; ++r) acc[r] = vs[r];
                        std::vector<std::uint8_t> flags(static_cast<std::size_t>(row_flag_bytes(n)), 0);
                        flags[0] = 1;
                        std::vector<std::uint8_t> out(static_cast<std::size_t>(n) * kGroupRows, 7);
                        if (dense)
                            k->dense_u8[rule](acc, stride, n, kGroupRows, out.data(), n);
                        else
                            k->u8[rule](acc, flags.data(), n, kGroupRows, out.data(), n);
                        for (int r = 0; r < kGroupRows; ++r) {
                            const int want = coverage_u8(vs[r], fr);  // the scalar rule
                            if (fr == FillRule::NonZero && std::fabs(vs[r]) >= 1.0f) {
                                ASSERT_EQ(want, 255);
                            }
                            for (int i = 0; i < n; ++i)
                                ASSERT_EQ(int(out[r * n + i]), want)
                                    << k->name << (dense ? " dense" : " group") << " n " << n
                                    << " rule " << rule << " value " << vs[r];
                        }
                    }
                }
            }
        }
    }
}

// --- Rasterizer::fill_paths: sets of fills in one call -----------------------------------------

// A job of the set tests: its path, transform, origin and target (prefilled with a byte that no
// fill writes everywhere, so an untouched target is visible).
struct SetCase {
    Path path;
    Affine transform;
    Vec2 origin;
    Mask target;
};

// Random curved paths placed three ways: inside the target (the direct route), partly outside
// (clipped: the general route), and scaled far beyond it (huge: the general route, clipped in
// double), with fractional origins.
std::vector<SetCase> random_set(std::mt19937& rng, int n) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<SetCase> out;
    for (int k = 0; k < n; ++k) {
        SetCase c;
        const int w = 1 + static_cast<int>(rng() % 120), h = 1 + static_cast<int>(rng() % 50);
        c.path = random_curved_path(rng);
        switch (k % 4) {
            case 0: case 1: c.transform = {w - 1.0, 0, 0, h - 1.0, 0, 0}; break;
            case 2: c.transform = {1.6 * w, 0.3 * h, -0.2 * w, 1.4 * h, -0.3 * w, -0.2 * h}; break;
            default: c.transform = Affine::scale(4e4) * Affine::translate({-0.5, -0.5}); break;
        }
        c.origin = {u(rng), u(rng)};
        c.target = Mask(w, h, 0xAB);
        out.push_back(std::move(c));
    }
    return out;
}

std::vector<FillJob> jobs_of(std::vector<SetCase>& cases) {
    std::vector<FillJob> jobs;
    for (SetCase& c : cases) jobs.push_back({&c.path, c.transform, c.target.view(), c.origin});
    return jobs;
}

// Each job's bytes as fill_path makes them, with the job's origin in the options.
void expect_each_job_equals_fill_path(std::vector<SetCase>& cases, FillOptions options,
                                      const char* what) {
    Rasterizer single;
    for (std::size_t k = 0; k < cases.size(); ++k) {
        const SetCase& c = cases[k];
        Mask alone(c.target.width(), c.target.height(), 0xAB);
        options.origin = c.origin;
        ASSERT_TRUE(single.fill_path(c.path, c.transform, alone.view(), options).ok());
        ASSERT_EQ(c.target.pixels(), alone.pixels()) << what << ", job " << k;
    }
}

TEST(RasterSet, EachJobEqualsItsOwnFillPathByteForByte) {
    std::mt19937 rng(3434);
    for (FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
        std::vector<SetCase> cases = random_set(rng, 120);
        std::vector<FillJob> jobs = jobs_of(cases);
        Rasterizer r;
        FillOptions options;
        options.rule = rule;
        ASSERT_TRUE(r.fill_paths(jobs, options).ok());
        expect_each_job_equals_fill_path(cases, options, "plain fill");
    }
}

TEST(RasterSet, EveryFillOptionGivesFillPathsBytes) {
    // The options fill_paths does not take its own route for (LCD, accurate overlap, combining,
    // other flatteners, coarse tolerances) go through fill_path job by job: the same bytes. A
    // job fill_path itself refuses while flattening (ClassicFlatness gives up on some random
    // cubics after 16 halvings) stops the set there: the jobs before it written, it and the
    // rest untouched, its index reported.
    std::mt19937 rng(5656);
    std::vector<FillOptions> variants(6);
    variants[0].format = CoverageFormat::Lcd;
    variants[1].overlap = OverlapMode::Accurate;
    variants[2].combine = CoverageCombine::Over;
    variants[3].combine = CoverageCombine::Add;
    variants[4].flatten.method = FlattenMethod::ClassicFlatness;
    variants[5].flatten.tolerance_px = 0.7;   // past the direct route's largest tolerance
    int stopped = 0;
    for (std::size_t v = 0; v < variants.size(); ++v) {
        std::vector<SetCase> cases = random_set(rng, 24);
        if (variants[v].format == CoverageFormat::Lcd)
            for (SetCase& c : cases)   // 3 bytes a display pixel
                c.target = Mask(3 * c.target.width(), c.target.height(), 0xAB);
        // The first job fill_path refuses, if any.
        std::size_t first_refused = cases.size();
        Rasterizer single;
        for (std::size_t k = 0; k < cases.size() && first_refused == cases.size(); ++k) {
            Mask scratch(cases[k].target.width(), cases[k].target.height());
            FillOptions o = variants[v];
            o.origin = cases[k].origin;
            if (!single.fill_path(cases[k].path, cases[k].transform, scratch.view(), o).ok())
                first_refused = k;
        }
        std::vector<FillJob> jobs = jobs_of(cases);
        Rasterizer r;
        std::size_t failed = cases.size();
        const Status s = r.fill_paths(jobs, variants[v], &failed);
        if (first_refused == cases.size()) {
            ASSERT_TRUE(s.ok()) << "variant " << v << ": " << s.error().message;
        } else {
            ++stopped;
            ASSERT_FALSE(s.ok()) << "variant " << v;
            EXPECT_EQ(failed, first_refused) << "variant " << v;
            EXPECT_NE(s.error().message.find("job " + std::to_string(first_refused) + ": "),
                      std::string::npos) << s.error().message;
            for (std::size_t k = first_refused; k < cases.size(); ++k)
                EXPECT_EQ(cases[k].target.pixels(),
                          std::vector<std::uint8_t>(cases[k].target.pixels().size(), 0xAB))
                    << "variant " << v << ", job " << k << " was written";
            cases.resize(first_refused);
        }
        expect_each_job_equals_fill_path(cases, variants[v], "option variant");
    }
    RecordProperty("sets_stopped_by_a_refused_flattening", stopped);
}

TEST(RasterSet, AtlasJobsFillTheirRectanglesAndLeaveTheGapsAlone) {
    // Six jobs into one 80×40 atlas, each a rectangle with a 1-pixel gap around it: each
    // rectangle holds its own fill_path's bytes, every gap byte keeps its value.
    std::mt19937 rng(7878);
    Mask atlas(80, 40, 0x5A);
    std::vector<Path> paths;
    for (int k = 0; k < 6; ++k) paths.push_back(random_curved_path(rng));
    struct Rect { int x, y, w, h; };
    const std::vector<Rect> rects{{1, 1, 20, 17}, {23, 1, 30, 17}, {55, 1, 24, 17},
                                  {1, 20, 10, 19}, {13, 20, 40, 19}, {55, 20, 24, 19}};
    std::vector<FillJob> jobs;
    for (std::size_t k = 0; k < rects.size(); ++k) {
        const Rect& q = rects[k];
        // The first three inside their rectangle, the others overhanging it (clipped).
        const double grow = k < 3 ? 1.0 : 1.8;
        jobs.push_back({&paths[k], Affine::scale(grow * (q.w - 1), grow * (q.h - 1)),
                        atlas.view().sub(q.x, q.y, q.w, q.h), {0.25 * double(k), 0.5}});
    }
    Rasterizer r;
    ASSERT_TRUE(r.fill_paths(jobs).ok());
    std::vector<bool> inside(80 * 40, false);
    for (std::size_t k = 0; k < rects.size(); ++k) {
        const Rect& q = rects[k];
        Mask alone(q.w, q.h);
        FillOptions o;
        o.origin = jobs[k].origin;
        ASSERT_TRUE(r.fill_path(paths[k], jobs[k].transform, alone.view(), o).ok());
        for (int y = 0; y < q.h; ++y)
            for (int x = 0; x < q.w; ++x) {
                ASSERT_EQ(atlas.view().at(q.x + x, q.y + y), alone.view().at(x, y))
                    << "job " << k << " pixel " << x << "," << y;
                inside[std::size_t(q.y + y) * 80 + std::size_t(q.x + x)] = true;
            }
    }
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 80; ++x) {
            if (!inside[std::size_t(y) * 80 + std::size_t(x)]) {
                ASSERT_EQ(atlas.view().at(x, y), 0x5A) << "gap pixel " << x << "," << y;
            }
        }
}

TEST(RasterSet, InvalidJobIsNamedAndNoTargetIsTouched) {
    // Job 2 of four is bad in each way fill_path would refuse; the error names it, says what is
    // wrong and reports its index. A bad job (null path, target, transform, origin) is found by
    // the validation pass: all four targets stay as they were. A bad path is found when its job
    // is reached: jobs 0 and 1 are written (fill_path's bytes), 2 and 3 are not.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    Path good;
    good.move_to({1, 1});
    good.quad_to({8, 2}, {6, 7});
    good.close();
    Path bad_point = good;
    bad_point.line_to({nan, 3});
    bad_point.close();
    Path beyond_budget;   // curves that would flatten to far more than kMaxEdges segments
    beyond_budget.move_to({0, 0});
    for (int i = 0; i < 200; ++i) beyond_budget.cubic_to({1e9, 0}, {1e9, 1e9}, {0, 1e9});
    beyond_budget.close();
    struct Bad {
        const char* what;
        std::function<void(FillJob&)> spoil;
        const char* message;
        bool in_path;   // found when the job is reached, not by the validation pass
    };
    const std::vector<Bad> cases{
        {"null path", [](FillJob& j) { j.path = nullptr; }, "path is null", false},
        {"negative target", [](FillJob& j) { j.target.width = -3; }, "is outside 0..", false},
        {"null target memory", [](FillJob& j) { j.target.data = nullptr; }, "null data", false},
        {"NaN transform", [&](FillJob& j) { j.transform.c = nan; }, "transform is not finite",
         false},
        {"infinite origin",
         [](FillJob& j) { j.origin.x = std::numeric_limits<double>::infinity(); },
         "origin is not finite", false},
        {"NaN point", [&](FillJob& j) { j.path = &bad_point; }, "is not finite after", true},
        {"huge point", [](FillJob& j) { j.transform = Affine::scale(1e300); }, "beyond 2^50 px",
         true},
        {"edge budget", [&](FillJob& j) { j.path = &beyond_budget; }, "segments at tolerance",
         true},
    };
    Mask filled(10, 9);
    ASSERT_TRUE(Rasterizer().fill_path(good, Affine::identity(), filled.view()).ok());
    for (const Bad& b : cases) {
        std::vector<Mask> targets(4, Mask(10, 9, 0xAB));
        std::vector<FillJob> jobs;
        for (Mask& t : targets) jobs.push_back({&good, Affine::identity(), t.view(), {}});
        b.spoil(jobs[2]);
        Rasterizer r;
        std::size_t failed = 99;
        const Status s = r.fill_paths(jobs, {}, &failed);
        ASSERT_FALSE(s.ok()) << b.what;
        EXPECT_NE(s.error().message.find("fill_paths: job 2: "), std::string::npos)
            << b.what << ": " << s.error().message;
        EXPECT_NE(s.error().message.find(b.message), std::string::npos)
            << b.what << ": " << s.error().message;
        EXPECT_EQ(failed, 2u) << b.what;
        for (std::size_t k = 0; k < targets.size(); ++k) {
            const bool written = b.in_path && k < 2;
            EXPECT_EQ(targets[k].pixels(),
                      written ? filled.pixels() : std::vector<std::uint8_t>(90, 0xAB))
                << b.what << ": target " << k;
        }
    }
    // A fault of the set itself: its index is the job count.
    Mask t(4, 4, 0xAB);
    std::vector<FillJob> one{{&good, Affine::identity(), t.view(), {}}};
    FillOptions moved;
    moved.origin = {1, 0};
    std::size_t failed = 99;
    Rasterizer r;
    const Status s = r.fill_paths(one, moved, &failed);
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message.find("origin must be zero"), std::string::npos);
    EXPECT_EQ(failed, 1u);
    EXPECT_FALSE(r.fill_paths(nullptr, 3).ok());
}

TEST(RasterSet, EmptySetSucceedsAndWritesNothing) {
    Rasterizer r;
    EXPECT_TRUE(r.fill_paths(nullptr, 0).ok());
    EXPECT_TRUE(r.fill_paths(std::vector<FillJob>{}).ok());
    EXPECT_EQ(r.scratch_capacity_bytes(), 0u);
    // A job whose path is empty clears its target, as fill_path does.
    Path empty;
    Mask t(5, 3, 0xAB);
    ASSERT_TRUE(r.fill_paths({{&empty, Affine::identity(), t.view(), {}}}).ok());
    EXPECT_EQ(t.pixels(), std::vector<std::uint8_t>(15, 0));
}

TEST(RasterSet, ScratchStopsGrowingOnceTheLargestJobWasFilled) {
    // fill_paths shares fill_path's scratch: a repeated set, or a set of smaller jobs, does not
    // grow it (allocation counts of a warm set are in glyph_rasterizer_test).
    std::mt19937 rng(9191);
    std::vector<SetCase> cases = random_set(rng, 40);
    std::vector<FillJob> jobs = jobs_of(cases);
    Rasterizer r;
    ASSERT_TRUE(r.fill_paths(jobs).ok());
    const std::size_t warm = r.scratch_capacity_bytes();
    EXPECT_GT(warm, 0u);
    for (int rep = 0; rep < 3; ++rep) ASSERT_TRUE(r.fill_paths(jobs).ok());
    ASSERT_TRUE(r.fill_paths(jobs.data(), jobs.size() / 2).ok());
    EXPECT_EQ(r.scratch_capacity_bytes(), warm);
}

}  // namespace
}  // namespace bezel
