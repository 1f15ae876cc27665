// Tests for bezel/bezier.hpp: the seed notes' properties of Bézier curves over thousands of
// random curves (fixed seeds), the three evaluation methods, basis matrices and conversions,
// bounds, tangents, curvature and arc length.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "bezel/bezier.hpp"

using namespace bezel;

namespace {

struct Rng {
    std::mt19937_64 gen;
    explicit Rng(std::uint64_t seed) : gen(seed) {}
    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(gen); }
    Point point(double r) { return {uniform(-r, r), uniform(-r, r)}; }
    CubicBez cubic(double r = 100) { return {point(r), point(r), point(r), point(r)}; }
    QuadBez quad(double r = 100) { return {point(r), point(r), point(r)}; }
};

constexpr int kCurves = 5000;

double dist(Point a, Point b) { return (a - b).length(); }

// Is p inside the convex hull of pts (within tol)? Andrew's monotone chain, then p must be on the
// inner side of every edge.
bool in_convex_hull(std::vector<Point> pts, Point p, double tol) {
    std::sort(pts.begin(), pts.end(), [](Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    std::vector<Point> h(2 * pts.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        while (k >= 2 && (h[k - 1] - h[k - 2]).cross(pts[i] - h[k - 2]) <= 0) --k;
        h[k++] = pts[i];
    }
    for (std::size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
        while (k >= t && (h[k - 1] - h[k - 2]).cross(pts[i] - h[k - 2]) <= 0) --k;
        h[k++] = pts[i];
    }
    h.resize(k - 1);  // counter-clockwise (y up), last == first dropped
    if (h.size() < 3) return true;  // degenerate hull: not what this checks
    for (std::size_t i = 0; i < h.size(); ++i) {
        Vec2 e = h[(i + 1) % h.size()] - h[i];
        if (e.cross(p - h[i]) < -tol * e.length()) return false;
    }
    return true;
}

// Arc length reference: chord sums over n and 2n pieces, Richardson-extrapolated. The chord sum
// error is c·h² + O(h⁴), so (4·L₂ₙ − Lₙ)/3 is accurate to O(h⁴) on smooth curves.
template <class C>
double polyline_length(const C& c, int n) {
    double sum = 0;
    Point prev = c.eval(0);
    for (int i = 1; i <= n; ++i) {
        Point q = c.eval(static_cast<double>(i) / n);
        sum += dist(prev, q);
        prev = q;
    }
    return sum;
}
template <class C>
double reference_length(const C& c) {
    double l1 = polyline_length(c, 1 << 13), l2 = polyline_length(c, 1 << 14);
    return (4 * l2 - l1) / 3;
}

// Maximises f on [lo, hi] (unimodal there) by golden-section search.
template <class F>
double golden_max(F f, double lo, double hi) {
    const double g = (std::sqrt(5.0) - 1) / 2;
    double a = lo, b = hi;
    for (int i = 0; i < 200 && b - a > 1e-15; ++i) {
        double c = b - g * (b - a), d = a + g * (b - a);
        if (f(c) > f(d)) b = d; else a = c;
    }
    return f(0.5 * (a + b));
}

}  // namespace

// ---- Bernstein basis ---------------------------------------------------------------------------

TEST(Bernstein, NonNegativeAndSumToOneOnUnitInterval) {
    Rng rng(1);
    for (int n = 0; n <= Bezier::kMaxDegree; ++n) {
        for (int k = 0; k < 1000; ++k) {
            double t = k < 2 ? k : rng.uniform(0, 1);
            double sum = 0;
            for (int i = 0; i <= n; ++i) {
                double b = bernstein(n, i, t);
                ASSERT_GE(b, 0.0) << n << " " << i << " " << t;
                sum += b;
            }
            EXPECT_NEAR(sum, 1.0, 1e-14) << n << " " << t;
        }
    }
    EXPECT_EQ(bernstein(3, -1, 0.5), 0.0);
    EXPECT_EQ(bernstein(3, 4, 0.5), 0.0);
    EXPECT_EQ(bernstein(3, 1, 0.5), 3 * 0.125);
}

TEST(Binomial, ExactThroughPascalsTriangle) {
    EXPECT_EQ(binomial(16, 8), 12870.0);
    EXPECT_EQ(binomial(56, 28), 7648690600760440.0);  // < 2⁵³: exact
    EXPECT_EQ(binomial(5, 6), 0.0);
    for (int n = 1; n <= kMaxExactBinomial; ++n)
        for (int k = 1; k < n; ++k)
            ASSERT_EQ(binomial(n, k), binomial(n - 1, k - 1) + binomial(n - 1, k));
    EXPECT_NEAR(binomial(60, 3), 34220.0, 0.0);
}

// ---- The seed notes' properties, on thousands of random cubics ----------------------------------

TEST(CubicProperties, EndPointsInterpolatedExactly) {
    Rng rng(2);
    for (int i = 0; i < kCurves; ++i) {
        CubicBez c = rng.cubic();
        ASSERT_EQ(c.eval(0.0), c.p0);
        ASSERT_EQ(c.eval(1.0), c.p3);
    }
}

TEST(CubicProperties, EndDerivativesMatchControlPolygon) {
    // C′(0) = 3(P1 − P0), C′(1) = 3(P3 − P2), C″(0) = 6(P0 − 2P1 + P2), C″(1) = 6(P1 − 2P2 + P3).
    Rng rng(3);
    for (int i = 0; i < kCurves; ++i) {
        CubicBez c = rng.cubic();
        EXPECT_EQ(c.deriv_at(0), (c.p1 - c.p0) * 3.0);
        EXPECT_EQ(c.deriv_at(1), (c.p3 - c.p2) * 3.0);
        Vec2 d2 = c.deriv2_at(0), e2 = (c.p0 - c.p1 * 2.0 + c.p2) * 6.0;
        EXPECT_NEAR(d2.x, e2.x, 1e-12);
        EXPECT_NEAR(d2.y, e2.y, 1e-12);
        d2 = c.deriv2_at(1), e2 = (c.p1 - c.p2 * 2.0 + c.p3) * 6.0;
        EXPECT_NEAR(d2.x, e2.x, 1e-12);
        EXPECT_NEAR(d2.y, e2.y, 1e-12);
    }
}

TEST(CubicProperties, DerivativeMatchesCentralDifferences) {
    // (C(t+h) − C(t−h))/2h = C′(t) + h²/6·C‴: with |C‴| ≤ 6·8·100, h = 1e-4 gives ≤ 1e-5 of
    // truncation; rounding adds ~ε·100/h ≈ 2e-10.
    Rng rng(4);
    const double h = 1e-4;
    for (int i = 0; i < kCurves; ++i) {
        CubicBez c = rng.cubic();
        double t = rng.uniform(0, 1);
        Vec2 fd = (c.eval(t + h) - c.eval(t - h)) / (2 * h);
        Vec2 d = c.deriv_at(t);
        EXPECT_NEAR(fd.x, d.x, 1e-5);
        EXPECT_NEAR(fd.y, d.y, 1e-5);
        Vec2 fd2 = (c.deriv_at(t + h) - c.deriv_at(t - h)) / (2 * h);
        Vec2 d2 = c.deriv2_at(t);
        EXPECT_NEAR(fd2.x, d2.x, 1e-6);  // C″ is linear: only rounding remains
        EXPECT_NEAR(fd2.y, d2.y, 1e-6);
    }
}

TEST(CubicProperties, CurveStaysInConvexHullOfControlPoints) {
    Rng rng(5);
    for (int i = 0; i < kCurves; ++i) {
        CubicBez c = rng.cubic();
        std::vector<Point> pts = {c.p0, c.p1, c.p2, c.p3};
        // The check itself can fail: a point beyond the control box is outside the hull.
        ASSERT_FALSE(in_convex_hull(pts, {c.control_box().x1 + 1, 0}, 1e-9));
        for (int k = 0; k <= 32; ++k) {
            Point p = c.eval(k / 32.0);
            ASSERT_TRUE(in_convex_hull(pts, p, 1e-9)) << i << " t=" << k / 32.0;
            ASSERT_TRUE(c.control_box().inflated(1e-12).contains(p));
        }
    }
}

TEST(CubicProperties, SubdivisionHalvesReproduceCurve) {
    // Left half at u is C(s·u), right half at u is C(s + (1 − s)·u). Coordinates ≤ 100 and a few
    // roundings per level: 1e-12 absolute.
    Rng rng(6);
    for (int i = 0; i < kCurves; ++i) {
        CubicBez c = rng.cubic();
        double s = rng.uniform(0, 1);
        auto [l, r] = c.split(s);
        EXPECT_EQ(l.p3, r.p0);
        EXPECT_EQ(l.p0, c.p0);
        EXPECT_EQ(r.p3, c.p3);
        for (int k = 0; k <= 16; ++k) {
            double u = k / 16.0;
            ASSERT_LE(dist(l.eval(u), c.eval(s * u)), 1e-12);
            ASSERT_LE(dist(r.eval(u), c.eval(s + (1 - s) * u)), 1e-12);
        }
    }
}

TEST(CubicProperties, SubsegmentReproducesCurve) {
    Rng rng(7);
    for (int i = 0; i < kCurves; ++i) {
        CubicBez c = rng.cubic();
        ASSERT_EQ(c.subsegment(0, 1), c);
        double t0 = rng.uniform(0, 1), t1 = rng.uniform(0, 1);  // t0 > t1 half the time
        CubicBez s = c.subsegment(t0, t1);
        for (int k = 0; k <= 16; ++k) {
            double u = k / 16.0;
            ASSERT_LE(dist(s.eval(u), c.eval(t0 + (t1 - t0) * u)), 1e-12);
        }
        // Splitting agrees with subsegment on each half.
        auto [l, r] = c.split(t0);
        CubicBez sl = c.subsegment(0, t0), sr = c.subsegment(t0, 1);
        for (Point d : {l.p0 - sl.p0, l.p1 - sl.p1, l.p2 - sl.p2, l.p3 - sl.p3, r.p0 - sr.p0,
                        r.p1 - sr.p1, r.p2 - sr.p2, r.p3 - sr.p3})
            ASSERT_LE(d.length(), 1e-12);
    }
}

TEST(CubicProperties, ReversingControlPointsReversesCurve) {
    Rng rng(8);
    for (int i = 0; i < kCurves; ++i) {
        CubicBez c = rng.cubic();
        CubicBez r = c.reversed();
        for (int k = 0; k <= 16; ++k) {
            double t = k / 16.0;
            ASSERT_LE(dist(r.eval(t), c.eval(1 - t)), 1e-12);
        }
        ASSERT_EQ(r.reversed(), c);
    }
}

TEST(QuadProperties, SeedPropertiesHoldForQuadratics) {
    Rng rng(9);
    for (int i = 0; i < kCurves; ++i) {
        QuadBez q = rng.quad();
        ASSERT_EQ(q.eval(0), q.p0);
        ASSERT_EQ(q.eval(1), q.p2);
        EXPECT_EQ(q.deriv_at(0), (q.p1 - q.p0) * 2.0);
        EXPECT_EQ(q.deriv_at(1), (q.p2 - q.p1) * 2.0);
        ASSERT_EQ(q.subsegment(0, 1), q);
        double s = rng.uniform(0, 1);
        auto [l, r] = q.split(s);
        std::vector<Point> pts = {q.p0, q.p1, q.p2};
        for (int k = 0; k <= 16; ++k) {
            double u = k / 16.0;
            ASSERT_LE(dist(l.eval(u), q.eval(s * u)), 1e-12);
            ASSERT_LE(dist(r.eval(u), q.eval(s + (1 - s) * u)), 1e-12);
            ASSERT_LE(dist(q.reversed().eval(u), q.eval(1 - u)), 1e-12);
            ASSERT_TRUE(in_convex_hull(pts, q.eval(u), 1e-9));
        }
    }
}

TEST(LineProperties, SplitSubsegmentAndLength) {
    Line l{{1, 2}, {4, 6}};
    EXPECT_EQ(l.length(), 5.0);
    EXPECT_EQ(l.arclen(0.1), 5.0);
    EXPECT_EQ(l.inv_arclen(2.5, 1e-9), 0.5);
    EXPECT_EQ(l.inv_arclen(-1, 1e-9), 0.0);
    EXPECT_EQ(l.inv_arclen(99, 1e-9), 1.0);
    EXPECT_EQ(l.split(0.5).first.p1, (Point{2.5, 4}));
    EXPECT_EQ(l.subsegment(0, 1), l);
    EXPECT_EQ(l.tangent(0.3), (Vec2{0.6, 0.8}));
    EXPECT_EQ(l.normal(0.3), (Vec2{-0.8, 0.6}));
    EXPECT_EQ((Line{{1, 1}, {1, 1}}).tangent(0), (Vec2{0, 0}));
    EXPECT_EQ((Line{{1, 1}, {1, 1}}).inv_arclen(1, 1e-9), 0.0);
}

// ---- Three evaluations agree ---------------------------------------------------------------------

TEST(Evaluation, DeCasteljauBernsteinAndMatrixAgreeForCubics) {
    Rng rng(10);
    double worst = 0;
    for (int i = 0; i < kCurves; ++i) {
        CubicBez c = rng.cubic();
        Bezier b(c);
        const Point G[4] = {c.p0, c.p1, c.p2, c.p3};
        for (int k = 0; k < 8; ++k) {
            double t = rng.uniform(0, 1);
            Point dc = c.eval(t);
            Point bern = b.eval_bernstein(t), mat = basis::eval_matrix(basis::kBezier, G, t);
            Point gm = b.eval_matrix(t), gdc = b.eval_de_casteljau(t);
            worst = std::max({worst, dist(dc, bern), dist(dc, mat), dist(dc, gm), dist(dc, gdc)});
        }
    }
    EXPECT_LE(worst, 1e-12);  // coordinates up to 100
}

TEST(Evaluation, DeCasteljauAndMatrixAgreeForQuadratics) {
    Rng rng(11);
    for (int i = 0; i < kCurves; ++i) {
        QuadBez q = rng.quad();
        const Point G[3] = {q.p0, q.p1, q.p2};
        Bezier b(q);
        for (int k = 0; k < 8; ++k) {
            double t = rng.uniform(0, 1);
            ASSERT_LE(dist(q.eval(t), basis::eval_matrix(basis::kBezierQuad, G, t)), 1e-12);
            ASSERT_LE(dist(q.eval(t), b.eval_bernstein(t)), 1e-12);
        }
    }
}

TEST(Evaluation, GeneralDegreeMethodsAgreeUpToDegree16) {
    // Points in [−1, 1]². de Casteljau and Bernstein agree to ~n·ε. The power (matrix) basis is
    // ill-conditioned: its coefficients reach Σ|m| ~ 3ⁿ (≈ 4.3e7 for n = 16), so it is held to
    // 4ε·3ⁿ — and to 1e-12 through degree 5.
    Rng rng(12);
    for (int n = 0; n <= Bezier::kMaxDegree; ++n) {
        double tol_matrix = std::max(4 * std::numeric_limits<double>::epsilon() * std::pow(3.0, n), 1e-15);
        if (n <= 5) tol_matrix = std::min(tol_matrix, 1e-12);
        for (int i = 0; i < 500; ++i) {
            Point pts[Bezier::kMaxDegree + 1];
            for (int k = 0; k <= n; ++k) pts[k] = rng.point(1);
            auto b = Bezier::from_points(pts, n + 1);
            ASSERT_TRUE(b.ok());
            double t = rng.uniform(0, 1);
            Point dc = b->eval_de_casteljau(t);
            ASSERT_LE(dist(dc, b->eval_bernstein(t)), 1e-14) << n;
            ASSERT_LE(dist(dc, b->eval_matrix(t)), tol_matrix) << n;
        }
    }
}

TEST(Evaluation, GeneralMatrixIsTheCubicBezierMatrixAtDegree3) {
    // Bezier::eval_matrix's table row for n = 3 must be basis::kBezier: check by evaluating the
    // unit control vectors.
    for (int col = 0; col < 4; ++col) {
        Bezier b;
        b.degree = 3;
        b.p[col] = Point{1, 0};
        for (double t : {0.0, 0.25, 0.5, 1.0, 2.0}) {
            double T[4] = {t * t * t, t * t, t, 1};
            double w = 0;
            for (int row = 0; row < 4; ++row) w += T[row] * basis::kBezier.m[row][col];
            EXPECT_DOUBLE_EQ(b.eval_matrix(t).x, w);
        }
    }
}

// ---- General degree operations -------------------------------------------------------------------

TEST(GeneralBezier, SplitReversedDerivAndElevateReproduceCurve) {
    Rng rng(13);
    for (int i = 0; i < 2000; ++i) {
        int n = 1 + i % Bezier::kMaxDegree;
        Point pts[Bezier::kMaxDegree + 1];
        for (int k = 0; k <= n; ++k) pts[k] = rng.point(10);
        Bezier b = *Bezier::from_points(pts, n + 1);
        double s = rng.uniform(0, 1), u = rng.uniform(0, 1);
        auto [l, r] = b.split(s);
        ASSERT_LE(dist(l.eval(u), b.eval(s * u)), 1e-11) << n;
        ASSERT_LE(dist(r.eval(u), b.eval(s + (1 - s) * u)), 1e-11) << n;
        ASSERT_LE(dist(b.reversed().eval(u), b.eval(1 - u)), 1e-11) << n;
        // Derivative against central differences (h = 1e-5; |Q‴| ≤ n³·2ⁿ·10 bounds truncation).
        const double h = 1e-5;
        Vec2 fd = (b.eval(u + h) - b.eval(u - h)) / (2 * h);
        Vec2 d = b.deriv_at(u);
        double scale = std::pow(2.0, n) * n * n * n * 10;
        ASSERT_LE((fd - d).length(), h * h * scale + 1e-9 * scale) << n;
        if (n < Bezier::kMaxDegree) {
            auto e = b.elevate();
            ASSERT_TRUE(e.ok());
            ASSERT_EQ(e->degree, n + 1);
            ASSERT_LE(dist(e->eval(u), b.eval(u)), 1e-11) << n;
        }
    }
}

TEST(GeneralBezier, DerivativesOfACubicMatchTheTypedOnes) {
    Rng rng(14);
    for (int i = 0; i < 1000; ++i) {
        CubicBez c = rng.cubic();
        Bezier b(c);
        Bezier d1 = b.deriv(), d2 = b.deriv(2), d3 = b.deriv(3), d4 = b.deriv(4);
        ASSERT_EQ(d1.degree, 2);
        QuadBez q = c.deriv();
        EXPECT_EQ(d1.p[0], q.p0);
        EXPECT_EQ(d1.p[1], q.p1);
        EXPECT_EQ(d1.p[2], q.p2);
        ASSERT_EQ(d2.degree, 1);
        Line l = q.deriv();
        EXPECT_EQ(d2.p[0], l.p0);
        EXPECT_EQ(d2.p[1], l.p1);
        ASSERT_EQ(d3.degree, 0);
        // Same maths, different order of operations: equal to an ulp or two of ~5000.
        EXPECT_LE((d3.p[0] - c.deriv3()).length(), 1e-11);
        EXPECT_EQ(d4.degree, 0);
        EXPECT_EQ(d4.p[0], (Point{0, 0}));
        EXPECT_EQ(b.deriv(0).p[3], c.p3);
    }
}

TEST(GeneralBezier, LimitsAreErrorsNotCrashes) {
    Point pts[20] = {};
    auto none = Bezier::from_points(pts, 0);
    ASSERT_FALSE(none.ok());
    EXPECT_NE(none.error().message.find("0 control points"), std::string::npos);
    ASSERT_FALSE(Bezier::from_points(pts, 18).ok());
    auto top = Bezier::from_points(pts, 17);
    ASSERT_TRUE(top.ok());
    auto too_high = top->elevate();
    ASSERT_FALSE(too_high.ok());
    EXPECT_NE(too_high.error().message.find("degree 16"), std::string::npos);
}

// ---- Elevation -------------------------------------------------------------------------------------

TEST(Elevation, QuadToCubicReproducesTheQuad) {
    Rng rng(15);
    for (int i = 0; i < kCurves; ++i) {
        QuadBez q = rng.quad();
        CubicBez c = q.elevate();
        ASSERT_EQ(c.p0, q.p0);
        ASSERT_EQ(c.p3, q.p2);
        for (int k = 0; k <= 16; ++k) {
            double t = k / 16.0;
            ASSERT_LE(dist(c.eval(t), q.eval(t)), 1e-12);
            ASSERT_LE((c.deriv_at(t) - q.deriv_at(t)).length(), 1e-11);
        }
    }
}

// ---- Basis matrices and conversions --------------------------------------------------------------

TEST(Basis, BSplineToBezierMatrixMapsBezierBasisToBSplineBasis) {
    basis::Mat4 p = basis::mul(basis::kBezier, basis::kBSplineToBezier);
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(p.m[r][c], basis::kBSpline.m[r][c], 1e-15);
}

TEST(Basis, CatmullRomHalfTensionIsTheStandardMatrix) {
    constexpr basis::Mat4 m = basis::catmull_rom(0.5);
    const double standard[4][4] = {{-1, 3, -3, 1}, {2, -5, 4, -1}, {-1, 0, 1, 0}, {0, 2, 0, 0}};
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) EXPECT_EQ(m.m[r][c], 0.5 * standard[r][c]);
}

TEST(Basis, BlendingFunctionsArePartitionsOfUnity) {
    // Bézier, B-spline and Catmull-Rom weights sum to 1 for every t (translation invariance).
    Rng rng(16);
    for (const basis::Mat4& m : {basis::kBezier, basis::kBSpline, basis::catmull_rom(0.5),
                                 basis::catmull_rom(0.3)}) {
        for (int i = 0; i < 1000; ++i) {
            double t = rng.uniform(0, 1);
            const Point ones[4] = {{1, 0}, {1, 0}, {1, 0}, {1, 0}};
            EXPECT_NEAR(basis::eval_matrix(m, ones, t).x, 1.0, 1e-14);
        }
    }
}

TEST(Conversions, HermiteMatchesMatrixForm) {
    Rng rng(17);
    for (int i = 0; i < kCurves; ++i) {
        Point p0 = rng.point(100), p1 = rng.point(100);
        Vec2 t0 = rng.point(300), t1 = rng.point(300);
        CubicBez c = hermite_to_bezier(p0, p1, t0, t1);
        const Point G[4] = {p0, p1, t0, t1};
        for (int k = 0; k <= 8; ++k) {
            double t = k / 8.0;
            ASSERT_LE(dist(c.eval(t), basis::eval_matrix(basis::kHermite, G, t)), 1e-11);
        }
        EXPECT_LE((c.deriv_at(0) - t0).length(), 1e-12);
        EXPECT_LE((c.deriv_at(1) - t1).length(), 1e-12);
    }
}

TEST(Conversions, BSplineMatchesMatrixForm) {
    Rng rng(18);
    for (int i = 0; i < kCurves; ++i) {
        Point b[4] = {rng.point(100), rng.point(100), rng.point(100), rng.point(100)};
        CubicBez c = bspline_to_bezier(b[0], b[1], b[2], b[3]);
        for (int k = 0; k <= 8; ++k) {
            double t = k / 8.0;
            ASSERT_LE(dist(c.eval(t), basis::eval_matrix(basis::kBSpline, b, t)), 1e-12);
        }
    }
}

TEST(Conversions, CatmullRomMatchesMatrixFormAndInterpolates) {
    Rng rng(19);
    for (int i = 0; i < kCurves; ++i) {
        Point p[4] = {rng.point(100), rng.point(100), rng.point(100), rng.point(100)};
        double tau = i % 2 ? 0.5 : rng.uniform(0, 1);
        CubicBez c = catmull_rom_to_bezier(p[0], p[1], p[2], p[3], tau);
        basis::Mat4 m = basis::catmull_rom(tau);
        for (int k = 0; k <= 8; ++k) {
            double t = k / 8.0;
            ASSERT_LE(dist(c.eval(t), basis::eval_matrix(m, p, t)), 1e-12);
        }
        EXPECT_EQ(c.p0, p[1]);
        EXPECT_EQ(c.p3, p[2]);
    }
}

TEST(Conversions, AdjacentCatmullRomSegmentsShareTangents) {
    // Segments [p0 p1 p2 p3] and [p1 p2 p3 p4] meet at p2 with the same derivative τ(p3 − p1).
    Rng rng(20);
    for (int i = 0; i < 1000; ++i) {
        Point p[5] = {rng.point(9), rng.point(9), rng.point(9), rng.point(9), rng.point(9)};
        CubicBez a = catmull_rom_to_bezier(p[0], p[1], p[2], p[3], 0.5);
        CubicBez b = catmull_rom_to_bezier(p[1], p[2], p[3], p[4], 0.5);
        EXPECT_LE((a.deriv_at(1) - b.deriv_at(0)).length(), 1e-12);
    }
}

// ---- Bounding boxes --------------------------------------------------------------------------------

TEST(BoundingBox, TightBoxContainsCurveAndTouchesItOnEverySide) {
    // Contains 512 samples (to 1e-12: eval rounding), and each side is reached: every local
    // maximum of the samples' coordinate is refined by golden section, and the best of them must
    // equal the box's side within 1e-9.
    Rng rng(21);
    const int n = 512;
    for (int i = 0; i < 1500; ++i) {
        CubicBez c = rng.cubic();
        Rect box = c.bounding_box();
        Rect cbox = c.control_box();
        ASSERT_TRUE(cbox.contains({box.x0, box.y0}) && cbox.contains({box.x1, box.y1}));
        for (int side = 0; side < 4; ++side) {
            auto coord = [&](double t) {
                Point p = c.eval(std::clamp(t, 0.0, 1.0));
                switch (side) {
                    case 0: return -p.x;
                    case 1: return -p.y;
                    case 2: return p.x;
                    default: return p.y;
                }
            };
            double v[n + 1];
            for (int k = 0; k <= n; ++k) v[k] = coord(k / double(n));
            double best = -HUGE_VAL;
            for (int k = 0; k <= n; ++k) {
                if (side == 0) {
                    ASSERT_TRUE(box.inflated(1e-12).contains(c.eval(k / double(n))));
                }
                if ((k == 0 || v[k] >= v[k - 1]) && (k == n || v[k] >= v[k + 1])) {
                    double lo = std::max(k - 1, 0) / double(n), hi = std::min(k + 1, n) / double(n);
                    best = std::max(best, golden_max(coord, lo, hi));
                }
            }
            double edge = side == 0 ? -box.x0 : side == 1 ? -box.y0 : side == 2 ? box.x1 : box.y1;
            ASSERT_NEAR(best, edge, 1e-9) << i << " side " << side;
        }
    }
}

TEST(BoundingBox, QuadAndLineBoxes) {
    QuadBez q{{0, 0}, {1, 2}, {2, 0}};  // apex (1, 1) at t = ½
    EXPECT_EQ(q.bounding_box(), (Rect{0, 0, 2, 1}));
    EXPECT_EQ(q.control_box(), (Rect{0, 0, 2, 2}));
    EXPECT_EQ((Line{{3, 1}, {0, 2}}).bounding_box(), (Rect{0, 1, 3, 2}));
    Rng rng(22);
    for (int i = 0; i < kCurves; ++i) {
        QuadBez r = rng.quad();
        Rect box = r.bounding_box();
        CubicBez c = r.elevate();
        Rect cb = c.bounding_box();
        EXPECT_NEAR(box.x0, cb.x0, 1e-9);
        EXPECT_NEAR(box.y0, cb.y0, 1e-9);
        EXPECT_NEAR(box.x1, cb.x1, 1e-9);
        EXPECT_NEAR(box.y1, cb.y1, 1e-9);
    }
}

// ---- Tangents, normals, curvature ------------------------------------------------------------------

TEST(Tangent, UnitAndAlongTheDerivative) {
    Rng rng(23);
    for (int i = 0; i < kCurves; ++i) {
        CubicBez c = rng.cubic();
        double t = rng.uniform(0, 1);
        Vec2 tan = c.tangent(t), d = c.deriv_at(t);
        ASSERT_NEAR(tan.length(), 1.0, 1e-14);
        ASSERT_NEAR(tan.cross(d), 0.0, 1e-9 * d.length());
        ASSERT_GT(tan.dot(d), 0.0);
        ASSERT_EQ(c.normal(t), tan.perp());
    }
}

TEST(Tangent, DegenerateEndsFallBackToNextDerivativeThenChord) {
    // p1 == p0: the curve leaves p0 towards p2.
    CubicBez a{{0, 0}, {0, 0}, {3, 4}, {10, 0}};
    EXPECT_EQ(a.tangent(0), (Vec2{0.6, 0.8}));
    // p2 == p3: it arrives at p3 from p1's direction.
    CubicBez b{{0, 0}, {10, 0}, {13, 4}, {13, 4}};
    EXPECT_EQ(b.tangent(1), (Vec2{0.6, 0.8}));
    // p0 == p1 == p2: only C‴ ∝ p3 − p0 is left.
    CubicBez c{{1, 1}, {1, 1}, {1, 1}, {4, 5}};
    EXPECT_EQ(c.tangent(0), (Vec2{0.6, 0.8}));
    EXPECT_EQ(c.tangent(1), (Vec2{0.6, 0.8}));
    // Rounding noise in "coincident" points is ignored.
    CubicBez d{{0, 0}, {1e-15, -1e-15}, {3, 4}, {10, 0}};
    EXPECT_NEAR(d.tangent(0).x, 0.6, 1e-12);
    // A point has no direction.
    CubicBez e{{2, 2}, {2, 2}, {2, 2}, {2, 2}};
    EXPECT_EQ(e.tangent(0.5), (Vec2{0, 0}));
    QuadBez q{{0, 0}, {0, 0}, {3, 4}};
    EXPECT_EQ(q.tangent(0), (Vec2{0.6, 0.8}));
    QuadBez q1{{0, 0}, {3, 4}, {3, 4}};
    EXPECT_EQ(q1.tangent(1), (Vec2{0.6, 0.8}));
    // Matches the direction of travel just inside the curve: C′(h) = h·C″(0) + h²/2·C‴, whose
    // direction is off the limit by ≤ h/2·|C‴|/|C″(0)| radians.
    Rng rng(24);
    const double h = 1e-8;
    for (int i = 0; i < 1000; ++i) {
        Point p0 = rng.point(100), p2 = rng.point(100), p3 = rng.point(100);
        CubicBez s{p0, p0, p2, p3};
        double tol = h * s.deriv3().length() / s.deriv2_at(0).length() + 1e-9;
        EXPECT_LE((s.tangent(0) - s.deriv_at(h).normalized()).length(), tol);
        CubicBez r = s.reversed();
        EXPECT_LE((r.tangent(1) - r.deriv_at(1 - h).normalized()).length(), tol);
    }
}

TEST(Curvature, ParabolaHasTheTextbookCurvature) {
    // (−1,1), (0,−1), (1,1) is y = x² with x = 2t − 1: κ(x) = 2/(1 + 4x²)^{3/2}, counter-
    // clockwise (positive) in a y-up frame.
    QuadBez q{{-1, 1}, {0, -1}, {1, 1}};
    CubicBez c = q.elevate();
    for (int k = 0; k <= 20; ++k) {
        double t = k / 20.0, x = 2 * t - 1;
        double expected = 2 / std::pow(1 + 4 * x * x, 1.5);
        EXPECT_NEAR(q.curvature(t), expected, 1e-14);
        EXPECT_NEAR(c.curvature(t), expected, 1e-13);
    }
    // Reflection flips the sign; uniform scaling by s divides it by s.
    CubicBez m = c.transformed(Affine::scale(-1, 1));
    CubicBez big = c.transformed(Affine::scale(4));
    for (double t : {0.1, 0.5, 0.8}) {
        EXPECT_NEAR(m.curvature(t), -c.curvature(t), 1e-13);
        EXPECT_NEAR(big.curvature(t), c.curvature(t) / 4, 1e-13);
    }
}

TEST(Curvature, CuspIsInfiniteAndStraightDegenerateEndIsZero) {
    CubicBez cusp{{0, 0}, {1, 1}, {0, 1}, {1, 0}};  // C′(½) = 0
    EXPECT_EQ(cusp.deriv_at(0.5), (Vec2{0, 0}));
    EXPECT_TRUE(std::isinf(cusp.curvature(0.5)));
    // Near the cusp |κ| grows without bound, with the sign of the limit.
    EXPECT_GT(std::fabs(cusp.curvature(0.5 + 1e-6)), 1e4);
    EXPECT_EQ(std::signbit(cusp.curvature(0.5 + 1e-6)), std::signbit(cusp.curvature(0.5)));
    CubicBez straight{{0, 0}, {0, 0}, {1, 0}, {2, 0}};
    EXPECT_EQ(straight.curvature(0), 0.0);
    EXPECT_EQ(straight.curvature(0.5), 0.0);
    QuadBez qs{{0, 0}, {0, 0}, {1, 1}};
    EXPECT_EQ(qs.curvature(0), 0.0);
}

// ---- Arc length ----------------------------------------------------------------------------------

TEST(ArcLength, StraightCubicEqualsChord) {
    // Collinear control points in order along the line: |C′| never vanishes, so the length is the
    // chord whatever the (non-uniform) speed.
    Rng rng(25);
    for (int i = 0; i < 1000; ++i) {
        Point a = rng.point(100), b = rng.point(100);
        double u[2] = {rng.uniform(0, 1), rng.uniform(0, 1)};
        std::sort(u, u + 2);
        CubicBez c{a, lerp(a, b, u[0]), lerp(a, b, u[1]), b};
        EXPECT_NEAR(c.arclen(1e-9), distance(a, b), 1e-9);
        QuadBez q{a, lerp(a, b, u[0]), b};
        EXPECT_NEAR(q.arclen(1e-9), distance(a, b), 1e-9);
    }
}

TEST(ArcLength, MatchesRichardsonPolylineReference) {
    Rng rng(26);
    for (int i = 0; i < 200; ++i) {
        CubicBez c = rng.cubic();
        double ref = reference_length(c);
        // The reference is good to ~1e-7 on these curves (h = 2⁻¹⁴, O(h⁴) after extrapolation,
        // worse near a sharp turn); the requested accuracy is far below that.
        EXPECT_NEAR(c.arclen(1e-10), ref, 1e-6 * std::max(1.0, ref)) << i;
        QuadBez q = rng.quad();
        EXPECT_NEAR(q.arclen(1e-10), reference_length(q), 1e-6 * std::max(1.0, ref)) << i;
    }
}

TEST(ArcLength, AdditiveOverSplitsAndMeetsRequestedAccuracy) {
    Rng rng(27);
    for (int i = 0; i < 1000; ++i) {
        CubicBez c = rng.cubic();
        double fine = c.arclen(1e-12);
        for (double acc : {1e-2, 1e-5, 1e-9}) EXPECT_NEAR(c.arclen(acc), fine, acc + 1e-11);
        auto [l, r] = c.split(rng.uniform(0, 1));
        EXPECT_NEAR(l.arclen(1e-10) + r.arclen(1e-10), fine, 3e-10);
    }
}

TEST(ArcLength, NearCuspCurvesMeetRequestedAccuracy) {
    // The cusp curve (0,0) (1,1) (0,1) (1,0), scaled by 100, with its end nudged by up to 1e-3:
    // tiny loops and needle-sharp turns, where |C′| almost vanishes and two Gauss rules can agree
    // on a wrong value. Each accuracy must hold against a 1e-11 result (whose own error is
    // bounded by the rigorous chord/polygon bracket at the cusp).
    Rng rng(29);
    for (int i = 0; i < 500; ++i) {
        Vec2 nudge = rng.point(1e-3);
        CubicBez c{{0, 0}, {100, 100}, {0, 100}, Point{100, 0} + nudge};
        double fine = c.arclen(1e-11);
        for (double acc : {1e-1, 1e-3, 1e-6, 1e-9}) EXPECT_NEAR(c.arclen(acc), fine, acc) << i;
    }
}

TEST(ArcLength, CuspAndDegenerateCurvesTerminate) {
    CubicBez cusp{{0, 0}, {1, 1}, {0, 1}, {1, 0}};
    EXPECT_NEAR(cusp.arclen(1e-10), reference_length(cusp), 1e-7);
    CubicBez point{{3, 3}, {3, 3}, {3, 3}, {3, 3}};
    EXPECT_EQ(point.arclen(1e-9), 0.0);
    EXPECT_EQ(point.inv_arclen(1, 1e-9), 0.0);
    // Accuracy 0, negative or NaN is raised to the floor; the answer is still right.
    CubicBez c{{0, 0}, {0, 50}, {100, 50}, {100, 0}};
    double l = c.arclen(1e-9);
    for (double acc : {0.0, -1.0, std::nan("")}) EXPECT_NEAR(c.arclen(acc), l, 1e-9);
    // Non-finite curves do not hang.
    CubicBez bad{{0, 0}, {INFINITY, 0}, {1, 1}, {2, 2}};
    EXPECT_TRUE(std::isnan(bad.arclen(1e-3)));
    EXPECT_EQ(bad.inv_arclen(1, 1e-3), 0.0);
}

TEST(ArcLength, InverseRoundTrips) {
    Rng rng(28);
    const double acc = 1e-9;
    for (int i = 0; i < 1000; ++i) {
        CubicBez c = rng.cubic();
        double t = rng.uniform(0, 1);
        double s = c.subsegment(0, t).arclen(1e-11);
        double t2 = c.inv_arclen(s, acc);
        ASSERT_GE(t2, 0.0);
        ASSERT_LE(t2, 1.0);
        // Stated contract: arclen over [0, t2] is within `acc` of s (+ the reference's 1e-11s).
        EXPECT_NEAR(c.subsegment(0, t2).arclen(1e-11), s, acc + 3e-11) << i;
        QuadBez q = rng.quad();
        s = q.subsegment(0, t).arclen(1e-11);
        EXPECT_NEAR(q.subsegment(0, q.inv_arclen(s, acc)).arclen(1e-11), s, acc + 3e-11) << i;
    }
    CubicBez c = rng.cubic();
    EXPECT_EQ(c.inv_arclen(-5, acc), 0.0);
    EXPECT_EQ(c.inv_arclen(1e9, acc), 1.0);
}

TEST(Finite, DetectsNonFinitePoints) {
    EXPECT_TRUE((CubicBez{{0, 0}, {1, 1}, {2, 2}, {3, 3}}).is_finite());
    EXPECT_FALSE((CubicBez{{0, 0}, {NAN, 1}, {2, 2}, {3, 3}}).is_finite());
    EXPECT_FALSE((QuadBez{{0, 0}, {1, 1}, {2, INFINITY}}).is_finite());
    EXPECT_FALSE((Line{{0, 0}, {-INFINITY, 1}}).is_finite());
    Bezier b(CubicBez{{0, 0}, {1, 1}, {2, 2}, {3, NAN}});
    EXPECT_FALSE(b.is_finite());
}
