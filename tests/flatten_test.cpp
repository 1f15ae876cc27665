// Tests of bezel/flatten.hpp: the distance bound of every method over thousands of random curves
// (fixed seed), the contour bookkeeping, the limits, and the drift of forward differencing.
//
// How the error is measured. A reference polyline samples the curve at N uniform parameters, N
// chosen by Wang's formula so that the reference is within e_ref ≤ tol/200 of the curve. Then
//  - curve → polyline: every reference sample's distance to the output polyline;
//  - polyline → curve: every output vertex and three interior points of every output segment,
//    distance to the reference polyline (minus nothing: e_ref is added to the allowance instead);
// both searched near a moving cursor, with a full scan whenever the local answer exceeds the
// allowance, so a reported excess is real. The allowance is tol + e_ref + rounding (1e-9 of the
// curve's extent).
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <string>
#include <vector>

#include "bezel/flatten.hpp"
#include "flatten/forward_difference.hpp"
#include "flatten/methods.hpp"

#include "support/allocation_counter.hpp"

using bezel::test::g_allocations;

namespace bezel {
namespace {

// --- Random curves ----------------------------------------------------------------------------

// SplitMix64: a fixed, library-independent sequence (std:: distributions differ between
// standard libraries).
struct Rng {
    std::uint64_t s;
    std::uint64_t next() {
        std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    int below(int n) { return static_cast<int>(next() % static_cast<std::uint64_t>(n)); }
    Point point(double s) { return {uniform(-s, s), uniform(-s, s)}; }
};

// Shapes that break flatteners: generic, cusp, loop, near-degenerate, collinear (including
// backtracking along the line), and all of them at scales from 10⁻³ to 10⁶.
enum class Shape { Generic, Cusp, Loop, NearDegenerate, Collinear, Count };

CubicBez random_cubic(Rng& rng, Shape shape, double scale) {
    CubicBez c;
    switch (shape) {
        case Shape::Generic:
            c = {rng.point(1), rng.point(1), rng.point(1), rng.point(1)};
            break;
        case Shape::Cusp: {  // the X-shaped control polygon (0,0) (1,1) (0,1) (1,0) has a cusp
            double j = 1e-3 * rng.uniform();
            c = {{0, 0}, {1 + j, 1}, {0, 1 - j}, {1, 0}};
            break;
        }
        case Shape::Loop:
            c = {{0, 0}, {rng.uniform(1.5, 3), 1}, {rng.uniform(-2, -0.5), 1}, {1, 0}};
            break;
        case Shape::NearDegenerate: {
            Point p = rng.point(1);
            double e = std::pow(10.0, rng.uniform(-12, -3));
            switch (rng.below(4)) {
                case 0: c = {p, p + rng.point(e), p + rng.point(e), p + rng.point(e)}; break;
                case 1: { Point q = rng.point(1); c = {p, p, q, q}; break; }           // straight
                case 2: { Point q = rng.point(1); c = {p, p, p, q}; break; }           // p1 = p2 = p0
                default: { Point q = rng.point(1); c = {p, rng.point(1), q, q}; break; }
            }
            break;
        }
        case Shape::Collinear: {
            Point p = rng.point(1), dir = Vec2{1, rng.uniform(-1, 1)}.normalized();
            c = {p + dir * rng.uniform(-1, 1), p + dir * rng.uniform(-3, 3), p + dir * rng.uniform(-3, 3),
                 p + dir * rng.uniform(-1, 1)};
            break;
        }
        case Shape::Count: break;
    }
    Affine m = Affine::translate(rng.point(100)) * Affine::rotate(rng.uniform(0, 6.3)) * Affine::scale(scale);
    return {m * c.p0, m * c.p1, m * c.p2, m * c.p3};
}

QuadBez random_quad(Rng& rng, Shape shape, double scale) {
    CubicBez c = random_cubic(rng, shape, scale);
    switch (shape) {
        case Shape::Cusp: return {c.p0, c.p3 + (c.p3 - c.p0) * rng.uniform(0, 3), c.p3};  // fold back
        case Shape::NearDegenerate: return {c.p0, rng.below(2) ? c.p0 : c.p1, c.p3};
        default: return {c.p0, c.p1, c.p3};
    }
}

// Curve sizes from 10⁻³ to 10⁴ px (the reference polyline of a larger curve at these tolerances
// would need millions of samples; FlattenLimits covers the huge ones).
double random_scale(Rng& rng) { return std::pow(10.0, rng.uniform(-3, 4)); }
double random_tolerance(Rng& rng) { return std::pow(10.0, rng.uniform(-2.5, 0)); }

// --- Error measurement ------------------------------------------------------------------------

double segment_distance(Point p, Point a, Point b) {
    Vec2 ab = b - a, ap = p - a;
    double len2 = ab.length_squared();
    double s = len2 > 0 ? std::clamp(ap.dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (ap - ab * s).length();
}

std::size_t g_full_scans = 0;
// Distance from p to the polyline, searched by walking downhill from `cursor` and a window around
// it; a full scan when that finds nothing within `allowance` (so any excess reported is exact).
double polyline_distance(const std::vector<Point>& poly, Point p, std::size_t& cursor, double allowance) {
    if (poly.size() < 2) return poly.empty() ? HUGE_VAL : distance(p, poly[0]);
    const std::size_t segs = poly.size() - 1;
    auto d = [&](std::size_t i) { return segment_distance(p, poly[i], poly[i + 1]); };
    cursor = std::min(cursor, segs - 1);
    double best = d(cursor);
    while (cursor + 1 < segs) {  // downhill forward
        double n = d(cursor + 1);
        if (n > best) break;
        best = n;
        ++cursor;
    }
    while (cursor > 0) {  // and back
        double n = d(cursor - 1);
        if (n >= best) break;
        best = n;
        --cursor;
    }
    std::size_t lo = cursor > 8 ? cursor - 8 : 0, hi = std::min(segs, cursor + 9);
    for (std::size_t i = lo; i < hi; ++i) {
        double v = d(i);
        if (v < best) { best = v; cursor = i; }
    }
    if (best > allowance) {
        ++g_full_scans;
        for (std::size_t i = 0; i < segs; ++i) {
            double v = d(i);
            if (v < best) { best = v; cursor = i; }
        }
    }
    return best;
}

struct Measured {
    double hausdorff = 0;       // max of both directions
    double vertex_off_curve = 0;
    double reference_error = 0;  // e_ref: how far the reference polyline may be from the curve
    std::size_t segments = 0;
};

template <typename Curve>
double second_difference_max(const Curve& c);
template <>
double second_difference_max(const QuadBez& q) { return 2.0 * (q.p0 - q.p1 * 2.0 + q.p2).length(); }
template <>
double second_difference_max(const CubicBez& c) {
    return 6.0 * std::max((c.p0 - c.p1 * 2.0 + c.p2).length(), (c.p1 - c.p2 * 2.0 + c.p3).length());
}

// `poly` starts at the curve's start point.
// `vertex_allowance` (+ the reference's own error): up to it the vertices' distances are exact,
// not upper bounds.
template <typename Curve>
Measured measure(const Curve& curve, const std::vector<Point>& poly, double allowance,
                 double vertex_allowance = -1) {
    if (vertex_allowance < 0) vertex_allowance = allowance;
    Measured m;
    m.segments = poly.size() - 1;
    // Reference: N uniform samples, Wang: ‖B − ℓ‖ ≤ d(d−1)M/(8N²) (second_difference_max = d(d−1)M).
    double dm = second_difference_max(curve);
    double target = std::max(allowance / 200.0, 1e-300);
    double n_real = std::sqrt(dm / (8.0 * target));
    std::size_t n = static_cast<std::size_t>(std::clamp(std::ceil(n_real), 64.0, 65536.0));
    m.reference_error = dm / (8.0 * static_cast<double>(n) * static_cast<double>(n));
    std::vector<Point> ref(n + 1);
    for (std::size_t i = 0; i <= n; ++i) ref[i] = curve.eval(static_cast<double>(i) / static_cast<double>(n));

    std::size_t cursor = 0;
    for (Point p : ref) m.hausdorff = std::max(m.hausdorff, polyline_distance(poly, p, cursor, allowance));
    cursor = 0;
    std::size_t ref_cursor = 0;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        m.vertex_off_curve = std::max(m.vertex_off_curve, polyline_distance(ref, poly[i], cursor, vertex_allowance + m.reference_error));
        if (i + 1 < poly.size()) {
            for (double s : {0.25, 0.5, 0.75}) {
                Point q = lerp(poly[i], poly[i + 1], s);
                ref_cursor = cursor;
                m.hausdorff = std::max(m.hausdorff, polyline_distance(ref, q, ref_cursor, allowance));
            }
        }
    }
    m.hausdorff = std::max(m.hausdorff, m.vertex_off_curve);
    return m;
}

template <typename Curve>
std::vector<Point> run(FlattenMethod method, const Curve& c, double tol, bool* met = nullptr) {
    std::vector<Point> out{c.p0};
    bool ok = false;
    switch (method) {
        case FlattenMethod::ClassicFlatness:
            ok = flatten_detail::classic_flatness(c, kDefaultClassicFlatnessEpsilon, out);
            break;
        case FlattenMethod::DistanceSubdivision: ok = flatten_detail::distance_subdivision(c, tol, out); break;
        case FlattenMethod::WangUniform: ok = flatten_detail::wang_uniform(c, tol, out); break;
        case FlattenMethod::ParabolaIntegral: ok = flatten_detail::parabola_integral(c, tol, out); break;
    }
    if (met) *met = ok;
    return out;
}

double extent(const QuadBez& q) {
    Rect r = Rect::from_points(q.p0, q.p1).union_with(q.p2);
    return std::max(r.width(), r.height()) + std::max(std::fabs(r.x0), std::fabs(r.y0));
}
double extent(const CubicBez& c) {
    Rect r = Rect::from_points(c.p0, c.p1).union_with(c.p2).union_with(c.p3);
    return std::max(r.width(), r.height()) + std::max(std::fabs(r.x0), std::fabs(r.y0));
}

Point end_of(const QuadBez& q) { return q.p2; }
Point end_of(const CubicBez& c) { return c.p3; }

const char* name(FlattenMethod m) {
    switch (m) {
        case FlattenMethod::ClassicFlatness: return "ClassicFlatness";
        case FlattenMethod::DistanceSubdivision: return "DistanceSubdivision";
        case FlattenMethod::WangUniform: return "WangUniform";
        case FlattenMethod::ParabolaIntegral: return "ParabolaIntegral";
    }
    return "?";
}

// The property every bounded method must have, over `count` random curves of every shape.
template <typename Curve, typename Make>
void expect_within_tolerance(FlattenMethod method, std::uint64_t seed, int count, Make make) {
    Rng rng{seed};
    double worst_ratio = 0;
    std::size_t total_segments = 0;
    for (int i = 0; i < count; ++i) {
        Shape shape = static_cast<Shape>(i % static_cast<int>(Shape::Count));
        Curve c = make(rng, shape, random_scale(rng));
        double tol = random_tolerance(rng);
        bool met = false;
        std::vector<Point> poly = run(method, c, tol, &met);
        ASSERT_TRUE(met) << name(method) << " curve " << i;
        ASSERT_GE(poly.size(), 2u);
        ASSERT_EQ(poly.back(), end_of(c)) << "end point copied exactly, curve " << i;
        double rounding = 1e-9 * extent(c);
        Measured m = measure(c, poly, tol + rounding);
        ASSERT_LE(m.hausdorff, tol + m.reference_error + rounding)
            << name(method) << " curve " << i << " shape " << static_cast<int>(shape) << " tol " << tol
            << " segments " << m.segments;
        worst_ratio = std::max(worst_ratio, m.hausdorff / tol);
        total_segments += m.segments;
    }
    std::printf("  %s: worst measured error / tolerance = %.3f over %d curves, %zu segments (%zu scans)\n",
                name(method), worst_ratio, count, total_segments, g_full_scans);
}

CubicBez make_cubic(Rng& r, Shape s, double scale) { return random_cubic(r, s, scale); }
QuadBez make_quad(Rng& r, Shape s, double scale) { return random_quad(r, s, scale); }

constexpr int kRandomCurves = 2000;

// --- Per-method bounds ------------------------------------------------------------------------

TEST(FlattenDistanceSubdivision, RandomQuadsWithinTolerance) {
    expect_within_tolerance<QuadBez>(FlattenMethod::DistanceSubdivision, 1, kRandomCurves, make_quad);
}
TEST(FlattenDistanceSubdivision, RandomCubicsWithinTolerance) {
    expect_within_tolerance<CubicBez>(FlattenMethod::DistanceSubdivision, 2, kRandomCurves, make_cubic);
}
TEST(FlattenWangUniform, RandomQuadsWithinTolerance) {
    expect_within_tolerance<QuadBez>(FlattenMethod::WangUniform, 3, kRandomCurves, make_quad);
}
TEST(FlattenWangUniform, RandomCubicsWithinTolerance) {
    expect_within_tolerance<CubicBez>(FlattenMethod::WangUniform, 4, kRandomCurves, make_cubic);
}
TEST(FlattenParabolaIntegral, RandomQuadsWithinTolerance) {
    expect_within_tolerance<QuadBez>(FlattenMethod::ParabolaIntegral, 5, kRandomCurves, make_quad);
}
TEST(FlattenParabolaIntegral, RandomCubicsWithinTolerance) {
    expect_within_tolerance<CubicBez>(FlattenMethod::ParabolaIntegral, 6, kRandomCurves, make_cubic);
}

// The vertices of the uniform and subdivision methods are points of the curve.
TEST(FlattenVertices, LieOnTheCurve) {
    Rng rng{7};
    for (FlattenMethod method : {FlattenMethod::DistanceSubdivision, FlattenMethod::WangUniform,
                                 FlattenMethod::ClassicFlatness, FlattenMethod::ParabolaIntegral}) {
        for (int i = 0; i < 300; ++i) {
            Shape shape = static_cast<Shape>(i % static_cast<int>(Shape::Count));
            double tol = random_tolerance(rng);
            CubicBez c = random_cubic(rng, shape, random_scale(rng));
            double rounding = 1e-9 * extent(c);
            // ParabolaIntegral's vertices lie on the approximating quadratics: within 0.1·tol.
            double off = method == FlattenMethod::ParabolaIntegral ? 0.1 * tol : 0.0;
            Measured m = measure(c, run(method, c, tol), tol, off + rounding);
            ASSERT_LE(m.vertex_off_curve, off + m.reference_error + rounding) << name(method) << " cubic " << i;
            QuadBez q = random_quad(rng, shape, random_scale(rng));
            double qrounding = 1e-9 * extent(q);
            Measured mq = measure(q, run(method, q, tol), tol, qrounding);
            ASSERT_LE(mq.vertex_off_curve, mq.reference_error + qrounding) << name(method) << " quad " << i;
        }
    }
}

// ClassicFlatness bounds no distance in pixels, but each piece of chord length L is within
// (L/2)·√(2ε + ε²) of the curve (classic_flatness.cpp); assert that, with L the longest segment.
TEST(FlattenClassicFlatness, ErrorWithinItsChordRelativeBound) {
    Rng rng{8};
    const double eps = kDefaultClassicFlatnessEpsilon;
    double worst_px_at_scale_1 = 0;
    for (int i = 0; i < kRandomCurves; ++i) {
        Shape shape = static_cast<Shape>(i % static_cast<int>(Shape::Count));
        CubicBez c = random_cubic(rng, shape, random_scale(rng));
        bool met = false;
        std::vector<Point> poly = run(FlattenMethod::ClassicFlatness, c, 0, &met);
        ASSERT_EQ(poly.back(), c.p3);
        double longest = 0;
        for (std::size_t k = 0; k + 1 < poly.size(); ++k) longest = std::max(longest, distance(poly[k], poly[k + 1]));
        double bound = 0.5 * longest * std::sqrt(2 * eps + eps * eps);
        double rounding = 1e-9 * extent(c);
        Measured m = measure(c, poly, bound + rounding);
        if (met) {
            ASSERT_LE(m.hausdorff, bound + m.reference_error + rounding) << "cubic " << i;
        }
        worst_px_at_scale_1 = std::max(worst_px_at_scale_1, m.hausdorff / extent(c));
    }
    std::printf("  ClassicFlatness: worst error / curve extent = %.2e\n", worst_px_at_scale_1);
}

// The classic test is scale-free: the same curve made 1000× larger keeps the same pieces, so its
// error grows 1000× — why it is only the baseline.
TEST(FlattenClassicFlatness, ErrorScalesWithTheCurve) {
    CubicBez c{{0, 0}, {10, 30}, {40, 30}, {50, 0}};
    CubicBez big{c.p0 * 1000, c.p1 * 1000, c.p2 * 1000, c.p3 * 1000};
    std::vector<Point> small_poly = run(FlattenMethod::ClassicFlatness, c, 0);
    std::vector<Point> big_poly = run(FlattenMethod::ClassicFlatness, big, 0);
    EXPECT_EQ(small_poly.size(), big_poly.size());
    double e_small = measure(c, small_poly, 1.0).hausdorff;
    double e_big = measure(big, big_poly, 1000.0).hausdorff;
    EXPECT_NEAR(e_big / e_small, 1000.0, 1.0);
    EXPECT_GT(e_big, 1.0);  // at this size it misses by more than a pixel
}

// --- Segment counts ---------------------------------------------------------------------------

TEST(FlattenCounts, StraightCubicIsOneSegmentForDistanceSubdivision) {
    // Inner control points on the chord, unevenly spaced: straight, but not uniformly parametrized.
    CubicBez c{{0, 0}, {10, 5}, {70, 35}, {100, 50}};
    EXPECT_EQ(run(FlattenMethod::DistanceSubdivision, c, 0.01).size(), 2u);
    EXPECT_EQ(run(FlattenMethod::ClassicFlatness, c, 0.01).size(), 2u);
    EXPECT_EQ(run(FlattenMethod::ParabolaIntegral, c, 0.01).size(), 2u);
    // Wang's count sees the second differences, not the shape: uniform spacing on a line is 1.
    CubicBez uniform{{0, 0}, {100.0 / 3, 50.0 / 3}, {200.0 / 3, 100.0 / 3}, {100, 50}};
    EXPECT_EQ(run(FlattenMethod::WangUniform, uniform, 0.01).size(), 2u);
}

TEST(FlattenCounts, WangUsesExactlyTheFormulaCount) {
    Rng rng{9};
    for (int i = 0; i < 1000; ++i) {
        CubicBez c = random_cubic(rng, Shape::Generic, random_scale(rng) * 1e-3);
        double tol = random_tolerance(rng);
        double m = std::max((c.p0 - c.p1 * 2.0 + c.p2).length(), (c.p1 - c.p2 * 2.0 + c.p3).length());
        double n = std::ceil(std::sqrt(3.0 * m / (4.0 * tol * 63.0 / 64.0)));
        std::size_t expected = static_cast<std::size_t>(std::max(1.0, n));
        ASSERT_EQ(run(FlattenMethod::WangUniform, c, tol).size() - 1, expected) << "cubic " << i;
    }
}

// A quarter circle of radius R needs about (π/2)/√(8·tol/R) chords (sagitta Rθ²/8 = tol); each
// bounded method must be within a small factor of that, the analytic one closest.
TEST(FlattenCounts, QuarterCircleNearTheOptimum) {
    const double r = 100, k = 0.5522847498307936;  // the usual cubic circle approximation
    CubicBez arc{{r, 0}, {r, r * k}, {r * k, r}, {0, r}};
    QuadBez qarc{{r, 0}, {r, r}, {0, r}};
    const double tol = 0.1;
    const double optimum = (M_PI / 2) / std::sqrt(8 * tol / r);  // 17.6
    std::size_t wang = run(FlattenMethod::WangUniform, arc, tol).size() - 1;
    std::size_t dist = run(FlattenMethod::DistanceSubdivision, arc, tol).size() - 1;
    std::size_t parab = run(FlattenMethod::ParabolaIntegral, arc, tol).size() - 1;
    std::printf("  quarter circle R=100 tol=0.1: optimum %.1f, Wang %zu, distance %zu, parabola %zu\n",
                optimum, wang, dist, parab);
    EXPECT_GE(static_cast<double>(wang), optimum);
    EXPECT_LE(static_cast<double>(wang), 1.5 * optimum);
    EXPECT_GE(static_cast<double>(dist), optimum);
    EXPECT_LE(static_cast<double>(dist), 2.0 * optimum);
    EXPECT_GE(static_cast<double>(parab), optimum);
    EXPECT_LE(static_cast<double>(parab), 1.25 * optimum);
    std::size_t qparab = run(FlattenMethod::ParabolaIntegral, qarc, tol).size() - 1;
    std::size_t qwang = run(FlattenMethod::WangUniform, qarc, tol).size() - 1;
    EXPECT_LE(qparab, qwang);
}

// --- Forward differencing ---------------------------------------------------------------------

// Max distance between forward-differenced points (in T, re-seeded every `run` steps) and the
// exact polynomial, over the n − 1 interior points.
// The exact values are the same power-form polynomial evaluated in long double (Horner), so only
// the differencing's drift is measured, not the rounding of the coefficients.
template <typename T>
double fd_drift(const CubicBez& c, std::size_t n, std::size_t run) {
    flatten_detail::PowerCubic pc{c.p3 - c.p0 + (c.p1 - c.p2) * 3.0, (c.p0 - c.p1 * 2.0 + c.p2) * 3.0,
                                  (c.p1 - c.p0) * 3.0};
    double worst = 0;
    std::size_t i = 0;
    flatten_detail::forward_difference<T>(pc, n, run, [&](T x, T y) {
        ++i;
        long double t = static_cast<long double>(i) / static_cast<long double>(n);
        long double ex = ((pc.a.x * t + pc.b.x) * t + pc.c.x) * t;
        long double ey = ((pc.a.y * t + pc.b.y) * t + pc.c.y) * t;
        worst = std::max(worst, static_cast<double>(std::hypot(ex - static_cast<long double>(x),
                                                               ey - static_cast<long double>(y))));
    });
    EXPECT_EQ(i, n - 1);
    return worst;
}

// For every n up to kMaxSegmentsPerCurve — at the tolerance that makes Wang choose that n — pure
// double forward differencing drifts by a small fraction of the tolerance, and with re-seeding it
// stays within the 1/64 of it that WangUniform reserves for drift.
TEST(FlattenForwardDifference, DoubleDriftWithinToleranceUpToMaxSegments) {
    Rng rng{10};
    for (std::size_t n : {std::size_t{16}, std::size_t{256}, std::size_t{4096}, kMaxSegmentsPerCurve}) {
        double worst_pure = 0, worst_seeded = 0;
        for (int i = 0; i < 20; ++i) {
            // Curved shapes: for near-degenerate ones M (and so the tolerance that makes Wang
            // pick n) is far below the coordinates' own rounding.
            CubicBez c = random_cubic(rng, static_cast<Shape>(i % 3), random_scale(rng));
            double tol = flatten_detail::wang_cubic_count(c, 1.0) / static_cast<double>(n);
            tol *= tol;  // count ∝ 1/√tol: the tolerance for which Wang picks n
            if (!(tol > 0)) continue;
            double pure = fd_drift<double>(c, n, 0) / tol;
            double seeded = fd_drift<double>(c, n, flatten_detail::kForwardDifferenceRun) / tol;
            worst_pure = std::max(worst_pure, pure);
            worst_seeded = std::max(worst_seeded, seeded);
        }
        std::printf("  double FD, n = %6zu: drift / tol = %.2e pure, %.2e re-seeded every %zu\n", n,
                    worst_pure, worst_seeded, flatten_detail::kForwardDifferenceRun);
        EXPECT_LE(worst_pure, 1.0 / 16) << "n = " << n;  // measured 1.3e-2 at n = 2^16
        EXPECT_LE(worst_seeded, 1.0 / 64) << "n = " << n;
    }
}

// Float: measured, and bounded by the drift model u·n·(extent) with u = 2⁻²⁴ (measured factor
// 0.3–0.5). Against Wang's tolerance for n it is safe only up to n ≈ 64 (forward_difference.hpp).
TEST(FlattenForwardDifference, FloatDriftFollowsTheModel) {
    Rng rng{11};
    for (std::size_t n : {std::size_t{8}, std::size_t{16}, std::size_t{32}, std::size_t{64}, std::size_t{128}, std::size_t{1024}, std::size_t{8192}}) {
        double worst = 0, worst_vs_tol = 0;
        for (int i = 0; i < 50; ++i) {
            CubicBez c = random_cubic(rng, Shape::Generic, 100.0);
            double size = extent(CubicBez{{0, 0}, c.p1 - c.p0, c.p2 - c.p0, c.p3 - c.p0});
            double drift = fd_drift<float>(c, n, 0);
            worst = std::max(worst, drift / (size * static_cast<double>(n) * 0x1.0p-24));
            double tol = flatten_detail::wang_cubic_count(c, 1.0) / static_cast<double>(n);
            worst_vs_tol = std::max(worst_vs_tol, drift / (tol * tol));
        }
        std::printf("  float FD, n = %5zu: drift / (n·u·extent) = %.3f, drift / Wang tolerance for n = %.2e\n",
                    n, worst, worst_vs_tol);
        EXPECT_LE(worst, 16.0) << "n = " << n;
    }
}

// --- Paths: contours, transform, limits -------------------------------------------------------

Path sample_path() {
    Path p;
    p.move_to({10, 10});
    p.line_to({60, 10});
    p.quad_to({80, 30}, {60, 50});
    p.cubic_to({40, 70}, {20, 40}, {10, 10});  // ends on the start: closed explicitly
    p.close();
    p.move_to({100, 100});  // open contour
    p.cubic_to({150, 50}, {200, 150}, {250, 100});
    return p;
}

const FlattenMethod kAllMethods[] = {FlattenMethod::ClassicFlatness, FlattenMethod::DistanceSubdivision,
                                     FlattenMethod::WangUniform, FlattenMethod::ParabolaIntegral};

TEST(FlattenPath, ContoursEndPointsAndClosing) {
    for (FlattenMethod method : kAllMethods) {
        Polylines out;
        flatten(sample_path(), Affine::identity(), FlattenOptions{0.05, method}, out);
        ASSERT_EQ(out.contour_ends.size(), 2u) << name(method);
        std::size_t first_end = out.contour_ends[0];
        EXPECT_EQ(out.contour_ends[1], out.points.size());
        // First contour: starts at the move, passes the on-curve points exactly, and does not
        // repeat its start at the end (the filler closes it).
        EXPECT_EQ(out.points[0], (Point{10, 10}));
        EXPECT_EQ(out.points[1], (Point{60, 10}));
        EXPECT_NE(std::find(out.points.begin(), out.points.begin() + first_end, Point{60, 50}),
                  out.points.begin() + first_end);
        EXPECT_NE(out.points[first_end - 1], (Point{10, 10}));
        // Second contour: open, closed implicitly; ends exactly at the curve's end.
        EXPECT_EQ(out.points[first_end], (Point{100, 100}));
        EXPECT_EQ(out.points.back(), (Point{250, 100}));
    }
}

TEST(FlattenPath, AppendsToExistingOutput) {
    Polylines out;
    flatten(sample_path(), Affine::identity(), FlattenOptions{}, out);
    std::size_t once = out.points.size();
    flatten(sample_path(), Affine::identity(), FlattenOptions{}, out);
    ASSERT_EQ(out.points.size(), 2 * once);
    ASSERT_EQ(out.contour_ends.size(), 4u);
    EXPECT_EQ(out.contour_ends[2], once + out.contour_ends[0]);
    EXPECT_TRUE(std::equal(out.points.begin(), out.points.begin() + once, out.points.begin() + once));
}

// The transform goes onto the control points before flattening: flattening a transformed copy of
// the path gives bit-identical output.
TEST(FlattenPath, TransformAppliedToControlPoints) {
    Affine m = Affine::translate({3.5, -7}) * Affine::rotate(0.3) * Affine::scale(4.0, 2.5);
    Path src = sample_path(), moved;
    std::size_t pi = 0;
    const auto& pts = src.points();
    for (Verb v : src.verbs()) {
        switch (v) {
            case Verb::Move: moved.move_to(m * pts[pi++]); break;
            case Verb::Line: moved.line_to(m * pts[pi++]); break;
            case Verb::Quad: moved.quad_to(m * pts[pi], m * pts[pi + 1]); pi += 2; break;
            case Verb::Cubic: moved.cubic_to(m * pts[pi], m * pts[pi + 1], m * pts[pi + 2]); pi += 3; break;
            case Verb::Close: moved.close(); break;
        }
    }
    for (FlattenMethod method : kAllMethods) {
        Polylines a, b;
        flatten(src, m, FlattenOptions{0.1, method}, a);
        flatten(moved, Affine::identity(), FlattenOptions{0.1, method}, b);
        EXPECT_EQ(a.points, b.points) << name(method);
        EXPECT_EQ(a.contour_ends, b.contour_ends) << name(method);
        // And the tolerance is in output units: 4× larger output needs more segments (except for
        // the scale-free classic test).
        if (method == FlattenMethod::ClassicFlatness) continue;
        Polylines unscaled;
        flatten(src, Affine::identity(), FlattenOptions{0.1, method}, unscaled);
        EXPECT_GT(a.points.size(), unscaled.points.size()) << name(method);
    }
}

TEST(FlattenPath, LoneMoveAndPointContoursAreDropped) {
    Path p;
    p.move_to({1, 1});
    p.move_to({5, 5});
    p.line_to({5, 5});
    p.close();
    p.move_to({0, 0});
    p.line_to({10, 0});
    p.line_to({10, 10});
    p.move_to({7, 7});
    Polylines out;
    flatten(p, Affine::identity(), FlattenOptions{}, out);
    ASSERT_EQ(out.contour_ends, (std::vector<std::size_t>{3}));
    EXPECT_EQ(out.points, (std::vector<Point>{{0, 0}, {10, 0}, {10, 10}}));
}

TEST(FlattenPath, SteadyStateAllocatesNothing) {
    Path p = sample_path();
    for (FlattenMethod method : kAllMethods) {
        Polylines out;
        flatten(p, Affine::scale(3), FlattenOptions{0.01, method}, out);  // grows once
        out.clear();
        const long before = g_allocations.load();
        for (int i = 0; i < 10; ++i) {
            out.clear();
            flatten(p, Affine::scale(3), FlattenOptions{0.01, method}, out);
        }
        EXPECT_EQ(g_allocations.load(), before) << name(method);
    }
}

TEST(FlattenLimits, NonFiniteContourIsDroppedAndReported) {
    Path p;
    p.move_to({0, 0});
    p.line_to({10, 0});
    p.line_to({0, 10});
    p.close();
    p.move_to({20, 20});
    p.cubic_to({std::nan(""), 30}, {40, 40}, {50, 20});  // point index 4
    p.close();
    p.move_to({0, 0});
    p.quad_to({5, 5}, {10, 0});
    for (FlattenMethod method : kAllMethods) {
        Polylines out;
        flatten(p, Affine::identity(), FlattenOptions{0.1, method}, out);
        EXPECT_EQ(out.contour_ends.size(), 2u) << name(method);
        for (Point q : out.points) EXPECT_TRUE(q.is_finite());

        Polylines checked;
        checked.points.push_back({1, 2});
        Status s = flatten_checked(p, Affine::identity(), FlattenOptions{0.1, method}, checked);
        ASSERT_FALSE(s.ok());
        EXPECT_EQ(s.error().message, "flatten: path point 4 is not finite after the transform");
        EXPECT_EQ(checked.points, (std::vector<Point>{{1, 2}}));  // left as it was
        EXPECT_TRUE(checked.contour_ends.empty());
    }
}

TEST(FlattenLimits, HugeCoordinatesAndTransformsAreRefused) {
    Path p;
    p.move_to({0, 0});
    p.cubic_to({1e16, 0}, {0, 1e16}, {1, 1});
    Polylines out;
    flatten(p, Affine::identity(), FlattenOptions{}, out);
    EXPECT_TRUE(out.points.empty());
    Status s = flatten_checked(p, Affine::identity(), FlattenOptions{}, out);
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().message, "flatten: path point 1 is beyond 2^50 px from the origin after the transform");

    Path ok = sample_path();
    Affine inf{HUGE_VAL, 0, 0, 1, 0, 0};
    flatten(ok, inf, FlattenOptions{}, out);
    EXPECT_TRUE(out.points.empty());
    Status t = flatten_checked(ok, inf, FlattenOptions{}, out);
    ASSERT_FALSE(t.ok());
    EXPECT_EQ(t.error().message, "flatten: the transform is not finite");
}

// A curve of extent 10¹² px at tolerance 10⁻⁹ px would need ~10¹⁰ segments: every method stops at
// kMaxSegmentsPerCurve, flatten() accepts it, flatten_checked() says so.
TEST(FlattenLimits, SegmentCountIsCappedPerCurve) {
    Path p;
    p.move_to({0, 0});
    p.cubic_to({1e12, 1e12}, {-1e12, 1e12}, {1, 0});
    p.quad_to({1e12, -1e12}, {0, 0});
    for (FlattenMethod method : kAllMethods) {
        FlattenOptions o{1e-9, method, 1e-15};
        Polylines out;
        flatten(p, Affine::identity(), o, out);
        EXPECT_LE(out.points.size(), 1 + 2 * kMaxSegmentsPerCurve) << name(method);
        EXPECT_GE(out.points.size(), 3u) << name(method);
        Status s = flatten_checked(p, Affine::identity(), o, out);
        ASSERT_FALSE(s.ok()) << name(method);
        EXPECT_NE(s.error().message.find("path verb 1: tolerance not met"), std::string::npos)
            << s.error().message;
    }
}

TEST(FlattenLimits, BadTolerancesAreClampedOrReported) {
    Path p = sample_path();
    for (double tol : {0.0, -1.0, std::nan(""), 1e-300}) {
        Polylines out;
        flatten(p, Affine::identity(), FlattenOptions{tol, FlattenMethod::WangUniform}, out);  // terminates
        EXPECT_EQ(out.contour_ends.size(), 2u);
        EXPECT_FALSE(flatten_checked(p, Affine::identity(), FlattenOptions{tol}, out).ok());
    }
    Polylines out;
    Status s = flatten_checked(p, Affine::identity(), FlattenOptions{0.1, FlattenMethod::ClassicFlatness, -1}, out);
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message.find("classic_flatness_epsilon"), std::string::npos);
    EXPECT_TRUE(flatten_checked(p, Affine::identity(), FlattenOptions{}, out).ok());
    // Infinite tolerance: every curve is one segment.
    Polylines coarse;
    flatten(p, Affine::identity(), FlattenOptions{HUGE_VAL, FlattenMethod::DistanceSubdivision}, coarse);
    EXPECT_EQ(coarse.points.size(), 3u + 2u);
}

}  // namespace
}  // namespace bezel
