// Tests for bezel/geometry.hpp: the value types' algebra and the quadratic/cubic root solvers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "bezel/geometry.hpp"

using namespace bezel;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

struct Rng {
    std::mt19937_64 gen;
    explicit Rng(std::uint64_t seed) : gen(seed) {}
    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(gen); }
    // ± 10^e with e uniform in [lo_exp, hi_exp]: magnitudes spread over many decades.
    double log_uniform(double lo_exp, double hi_exp) {
        double v = std::pow(10.0, uniform(lo_exp, hi_exp));
        return uniform(0, 1) < 0.5 ? -v : v;
    }
};

// Σ|coefᵢ|·|x|ⁱ and p′(x) for a·x³ + b·x² + c·x + d.
double magnitude(double a, double b, double c, double d, double x) {
    double ax = std::fabs(x);
    return ((std::fabs(a) * ax + std::fabs(b)) * ax + std::fabs(c)) * ax + std::fabs(d);
}
double dcubic(double a, double b, double c, double x) { return (3 * a * x + 2 * b) * x + c; }

bool sorted_distinct(const double* r, int n) {
    for (int i = 1; i < n; ++i)
        if (!(r[i - 1] < r[i])) return false;
    return true;
}

}  // namespace

// ---- Value types ---------------------------------------------------------------------------------

TEST(Lerp, ExactAtBothEndsEvenAcrossScales) {
    // The one-sided form a + (b − a)·1 returns 0 here instead of 1.
    Point a{1e20, -3.0}, b{1.0, 1e-30};
    EXPECT_EQ(lerp(a, b, 0.0), a);
    EXPECT_EQ(lerp(a, b, 1.0), b);
    Rng rng(1);
    for (int i = 0; i < 10000; ++i) {
        Point p{rng.log_uniform(-30, 30), rng.log_uniform(-30, 30)};
        Point q{rng.log_uniform(-30, 30), rng.log_uniform(-30, 30)};
        ASSERT_EQ(lerp(p, q, 0.0), p);
        ASSERT_EQ(lerp(p, q, 1.0), q);
        ASSERT_EQ(lerp(p, p, rng.uniform(-2, 3)), p);  // equal ends: exact for any t
    }
}

TEST(Affine, InverseUndoesMapAndCompositionAppliesRightFirst) {
    Rng rng(2);
    for (int i = 0; i < 2000; ++i) {
        Affine m{rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-3, 3),
                 rng.uniform(-3, 3), rng.uniform(-9, 9), rng.uniform(-9, 9)};
        if (std::fabs(m.determinant()) < 0.1) continue;
        Point p{rng.uniform(-10, 10), rng.uniform(-10, 10)};
        Point back = m.inverse() * (m * p);
        // Condition number ≤ ~|m|²/|det| ≤ 36/0.1; 1e-10 covers it.
        EXPECT_NEAR(back.x, p.x, 1e-10);
        EXPECT_NEAR(back.y, p.y, 1e-10);
        // (T·M)·p = T·(M·p): only the order of two additions differs, so 1 ulp-ish of 30.
        Affine t = Affine::translate({1, 2});
        Point lhs = (t * m) * p, rhs = t * (m * p);
        EXPECT_NEAR(lhs.x, rhs.x, 1e-14);
        EXPECT_NEAR(lhs.y, rhs.y, 1e-14);
    }
}

TEST(Rect, EmptyIsIdentityForUnion) {
    Rect r{1, 2, 3, 4};
    EXPECT_TRUE(Rect::empty().is_empty());
    EXPECT_EQ(Rect::empty().union_with(r), r);
    EXPECT_EQ(Rect::empty().union_with(Point{5, 6}), (Rect{5, 6, 5, 6}));
}

// ---- solve_quadratic -------------------------------------------------------------------------------

TEST(SolveQuadratic, RecoversRandomRootsToTheirConditioning) {
    // a(x − r1)(x − r2) with roots over 40 decades. The coefficients are rounded, which moves a
    // root r1 by up to ~2ε·|r1|·(|r1| + |r2|)/|r1 − r2| (first-order perturbation); the solver
    // must stay within 8× that.
    Rng rng(10);
    int checked = 0;
    for (int i = 0; i < 20000; ++i) {
        double r1 = rng.log_uniform(-20, 20), r2 = rng.log_uniform(-20, 20);
        if (i % 4 == 0) r2 = r1 * (1 + rng.uniform(-1e-3, 1e-3));  // close pairs too
        double a = rng.log_uniform(-5, 5);
        double b = -a * (r1 + r2), c = a * r1 * r2;
        double lo = std::min(r1, r2), hi = std::max(r1, r2);
        double cond = (std::fabs(r1) + std::fabs(r2)) / (hi - lo);
        double roots[2];
        int n = solve_quadratic(a, b, c, roots);
        if (cond > 1e6) continue;  // nearly double: covered by DoubleRoot tests
        ASSERT_EQ(n, 2) << r1 << " " << r2;
        EXPECT_NEAR(roots[0], lo, 8 * 2 * kEps * std::fabs(lo) * cond) << r1 << " " << r2;
        EXPECT_NEAR(roots[1], hi, 8 * 2 * kEps * std::fabs(hi) * cond) << r1 << " " << r2;
        ++checked;
    }
    EXPECT_GT(checked, 15000);
}

TEST(SolveQuadratic, DoubleRootIsReportedOnce) {
    double roots[2];
    ASSERT_EQ(solve_quadratic(1, -6, 9, roots), 1);
    EXPECT_EQ(roots[0], 3.0);
    // Random dyadic double roots (coefficients exact): one root, to √ε relative.
    Rng rng(11);
    for (int i = 0; i < 5000; ++i) {
        double r = std::round(rng.uniform(-1e6, 1e6)) / 1024.0;
        double a = std::ldexp(1.0, static_cast<int>(rng.uniform(-40, 40)));
        ASSERT_EQ(solve_quadratic(a, -2 * a * r, a * r * r, roots), 1) << r;
        EXPECT_NEAR(roots[0], r, 1e-8 * std::fabs(r) + 1e-300);
    }
    // Rounded (non-dyadic) double roots: Δ lands within rounding of 0 and still merges.
    for (int i = 0; i < 5000; ++i) {
        double r = rng.log_uniform(-10, 10);
        int n = solve_quadratic(1, -2 * r, r * r, roots);
        ASSERT_GE(n, 1);
        for (int k = 0; k < n; ++k) EXPECT_NEAR(roots[k], r, 4e-8 * std::fabs(r));
    }
}

TEST(SolveQuadratic, TinyLeadingCoefficientKeepsTheFiniteRootAccurate) {
    double roots[2];
    // 1e-30·x² + 2x − 4: roots ≈ 2 and ≈ −2e30. The textbook formula loses the root 2 entirely.
    ASSERT_EQ(solve_quadratic(1e-30, 2, -4, roots), 2);
    EXPECT_NEAR(roots[0], -2e30, 1e-14 * 2e30);
    EXPECT_NEAR(roots[1], 2.0, 4 * kEps * 2.0);
    // Leading coefficient so small the other root is beyond kMaxRootMagnitude: only 2 remains.
    ASSERT_EQ(solve_quadratic(1e-200, 2, -4, roots), 1);
    EXPECT_NEAR(roots[0], 2.0, 4 * kEps * 2.0);
    ASSERT_EQ(solve_quadratic(0, 2, -4, roots), 1);  // exactly linear
    EXPECT_EQ(roots[0], 2.0);
}

TEST(SolveQuadratic, DegenerateAndNonFiniteInputs) {
    double roots[2] = {7, 7};
    EXPECT_EQ(solve_quadratic(0, 0, 0, roots), 0);
    EXPECT_EQ(solve_quadratic(0, 0, 3, roots), 0);
    EXPECT_EQ(solve_quadratic(1, 0, 1, roots), 0);  // x² + 1
    EXPECT_EQ(solve_quadratic(NAN, 1, 1, roots), 0);
    EXPECT_EQ(solve_quadratic(1, INFINITY, 1, roots), 0);
    ASSERT_EQ(solve_quadratic(1, 0, 0, roots), 1);
    EXPECT_EQ(roots[0], 0.0);
    ASSERT_EQ(solve_quadratic(2, 0, -8, roots), 2);
    EXPECT_EQ(roots[0], -2.0);
    EXPECT_EQ(roots[1], 2.0);
}

TEST(SolveQuadratic, ScalingAllCoefficientsChangesNothing) {
    Rng rng(12);
    for (int i = 0; i < 5000; ++i) {
        double a = rng.uniform(-1, 1), b = rng.uniform(-1, 1), c = rng.uniform(-1, 1);
        double r[2], s[2], u[2];
        int n = solve_quadratic(a, b, c, r);
        // Power-of-two scales are exact, so the answer must be identical.
        ASSERT_EQ(solve_quadratic(a * 0x1p-1000, b * 0x1p-1000, c * 0x1p-1000, s), n);
        ASSERT_EQ(solve_quadratic(a * 0x1p+1000, b * 0x1p+1000, c * 0x1p+1000, u), n);
        for (int k = 0; k < n; ++k) {
            EXPECT_EQ(r[k], s[k]);
            EXPECT_EQ(r[k], u[k]);
        }
    }
}

// ---- solve_cubic -------------------------------------------------------------------------------------

TEST(SolveCubic, RecoversRandomRootsToTheirConditioning) {
    // a(x − r1)(x − r2)(x − r3), expanded in doubles. Each coefficient carries a few roundings,
    // so a simple root r moves by up to ~4ε·Σ|coefᵢ||r|ⁱ/|p′(r)| (first order); allow 8× that.
    Rng rng(20);
    int full = 0;
    for (int i = 0; i < 20000; ++i) {
        double span = (i % 3 == 0) ? 12 : 3;
        double r[3] = {rng.log_uniform(-span, span), rng.log_uniform(-span, span),
                       rng.log_uniform(-span, span)};
        std::sort(r, r + 3);
        double a = rng.log_uniform(-3, 3);
        double b = -a * (r[0] + r[1] + r[2]);
        double c = a * (r[0] * r[1] + r[0] * r[2] + r[1] * r[2]);
        double d = -a * r[0] * r[1] * r[2];
        double tol[3];
        for (int k = 0; k < 3; ++k)
            tol[k] = 32 * kEps * magnitude(a, b, c, d, r[k]) / std::fabs(dcubic(a, b, c, r[k]));
        double roots[3];
        int n = solve_cubic(a, b, c, d, roots);
        ASSERT_TRUE(sorted_distinct(roots, n));
        // Every reported root is near a true one.
        for (int k = 0; k < n; ++k) {
            bool near = false;
            for (int j = 0; j < 3; ++j) near |= std::fabs(roots[k] - r[j]) <= tol[j];
            EXPECT_TRUE(near) << roots[k] << " vs " << r[0] << " " << r[1] << " " << r[2];
        }
        // When the roots' uncertainty windows are apart, all three are found.
        bool separated = r[0] + tol[0] < r[1] - tol[1] && r[1] + tol[1] < r[2] - tol[2] &&
                         tol[0] < 1e-6 * std::fabs(r[0]) + 1e-300 &&
                         tol[1] < 1e-6 * std::fabs(r[1]) + 1e-300 &&
                         tol[2] < 1e-6 * std::fabs(r[2]) + 1e-300;
        if (separated) {
            ASSERT_EQ(n, 3) << r[0] << " " << r[1] << " " << r[2];
            for (int k = 0; k < 3; ++k) EXPECT_NEAR(roots[k], r[k], tol[k]);
            ++full;
        }
    }
    EXPECT_GT(full, 15000);
}

TEST(SolveCubic, RandomCoefficientsGiveSmallResidualsAndTheRightCount) {
    // Random coefficients: the count must match the discriminant's sign (3 real roots when
    // Δ > 0, 1 when Δ < 0; computed in long double, cases near Δ = 0 skipped) and every root
    // must have a residual within rounding: |p(x)| ≤ 8ε·Σ|coefᵢ||x|ⁱ + |p′(x)|·4ε|x|.
    Rng rng(21);
    int counted = 0;
    for (int i = 0; i < 50000; ++i) {
        double a = rng.uniform(-1, 1), b = rng.uniform(-1, 1), c = rng.uniform(-1, 1),
               d = rng.uniform(-1, 1);
        if (i % 5 == 0) a *= 1e-6;  // nearly quadratic
        double roots[3];
        int n = solve_cubic(a, b, c, d, roots);
        ASSERT_TRUE(sorted_distinct(roots, n));
        for (int k = 0; k < n; ++k) {
            double x = roots[k];
            double p = ((a * x + b) * x + c) * x + d;
            EXPECT_LE(std::fabs(p), 8 * kEps * magnitude(a, b, c, d, x) +
                                        std::fabs(dcubic(a, b, c, x)) * 4 * kEps * std::fabs(x))
                << a << " " << b << " " << c << " " << d << " root " << x;
        }
        long double A = a, B = b, C = c, D = d;
        long double disc = 18 * A * B * C * D - 4 * B * B * B * D + B * B * C * C -
                           4 * A * C * C * C - 27 * A * A * D * D;
        long double scale = std::fabs(18 * A * B * C * D) + std::fabs(4 * B * B * B * D) +
                            B * B * C * C + std::fabs(4 * A * C * C * C) + 27 * A * A * D * D;
        if (std::fabs(disc) < 1e-6L * scale) continue;
        ++counted;
        ASSERT_EQ(n, disc > 0 ? 3 : 1) << a << " " << b << " " << c << " " << d;
    }
    EXPECT_GT(counted, 40000);
}

TEST(SolveCubic, DoubleAndTripleRoots) {
    double roots[3];
    // (x − 1)²(x − 2) = x³ − 4x² + 5x − 2.
    ASSERT_EQ(solve_cubic(1, -4, 5, -2, roots), 2);
    EXPECT_NEAR(roots[0], 1.0, 1e-7);
    EXPECT_NEAR(roots[1], 2.0, 4 * kEps);
    // (x − 2)³ = x³ − 6x² + 12x − 8: a triple root is conditioned like ∛ε ≈ 6e-6.
    int n = solve_cubic(1, -6, 12, -8, roots);
    ASSERT_GE(n, 1);
    for (int k = 0; k < n; ++k) EXPECT_NEAR(roots[k], 2.0, 2e-5);
    // x³ = 0 and x²(x − 3) = 0.
    ASSERT_EQ(solve_cubic(5, 0, 0, 0, roots), 1);
    EXPECT_EQ(roots[0], 0.0);
    ASSERT_EQ(solve_cubic(1, -3, 0, 0, roots), 2);
    EXPECT_EQ(roots[0], 0.0);
    EXPECT_EQ(roots[1], 3.0);
    // Random dyadic double roots (exact coefficients): both roots found, the double one to √ε.
    Rng rng(22);
    for (int i = 0; i < 5000; ++i) {
        double r = std::round(rng.uniform(-4096, 4096)) / 64.0;
        double s = std::round(rng.uniform(-4096, 4096)) / 64.0;
        if (std::fabs(r - s) < 1.0) continue;
        // (x − r)²(x − s) = x³ − (2r + s)x² + (r² + 2rs)x − r²s, exact in doubles here.
        n = solve_cubic(1, -(2 * r + s), r * r + 2 * r * s, -r * r * s, roots);
        ASSERT_EQ(n, 2) << r << " " << s;
        double lo = std::min(r, s), hi = std::max(r, s);
        double scale = std::max(std::fabs(r), std::fabs(s)) + 1;
        EXPECT_NEAR(roots[0], lo, 1e-6 * scale);
        EXPECT_NEAR(roots[1], hi, 1e-6 * scale);
    }
}

TEST(SolveCubic, TinyLeadingCoefficientDegradesToTheQuadratic) {
    double roots[3];
    // 1e-20·x³ + x² − 3x + 2: roots ≈ 1, 2 (perturbed by ~1e-20) and ≈ −1e20.
    ASSERT_EQ(solve_cubic(1e-20, 1, -3, 2, roots), 3);
    EXPECT_NEAR(roots[0], -1e20, 1e-12 * 1e20);
    EXPECT_NEAR(roots[1], 1.0, 4 * kEps);
    EXPECT_NEAR(roots[2], 2.0, 8 * kEps);
    // So tiny the third root is beyond kMaxRootMagnitude: the quadratic's roots remain.
    ASSERT_EQ(solve_cubic(1e-300, 1, -3, 2, roots), 2);
    EXPECT_NEAR(roots[0], 1.0, 4 * kEps);
    EXPECT_NEAR(roots[1], 2.0, 8 * kEps);
    ASSERT_EQ(solve_cubic(0, 1, -3, 2, roots), 2);  // exactly quadratic
    EXPECT_EQ(roots[0], 1.0);
    EXPECT_EQ(roots[1], 2.0);
    // And the continuum between: the two moderate roots stay put as a shrinks.
    for (double a = 1e-2; a > 1e-250; a *= 1e-3) {
        int n = solve_cubic(a, 1, -3, 2, roots);
        ASSERT_GE(n, 2) << a;
        EXPECT_NEAR(roots[n - 2], 1.0, 4 * a + 8 * kEps) << a;
        EXPECT_NEAR(roots[n - 1], 2.0, 16 * a + 8 * kEps) << a;
    }
}

TEST(SolveCubic, HugeAndTinyScales) {
    double roots[3];
    // Roots −3s, s/2, s over ±100 decades: relative accuracy is what counts. (Much smaller s
    // would underflow the caller's own product r0·r1·r2 ~ s³, not the solver.)
    for (double s : {1e90, 1e-90, 1e-100, 1e100}) {
        double r[3] = {-3 * s, 0.5 * s, 1 * s};
        double b = -(r[0] + r[1] + r[2]), c = r[0] * r[1] + r[0] * r[2] + r[1] * r[2],
               d = -r[0] * r[1] * r[2];
        ASSERT_EQ(solve_cubic(1, b, c, d, roots), 3) << s;
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(roots[k], r[k], 1e-14 * std::fabs(r[k])) << s;
    }
    // Coefficients near the ends of the double range, same roots 1, 2, 3.
    for (double k : {0x1p-1000, 0x1p+1000, 1e-300, 1e300}) {
        ASSERT_EQ(solve_cubic(k, -6 * k, 11 * k, -6 * k, roots), 3) << k;
        EXPECT_NEAR(roots[0], 1.0, 1e-14);
        EXPECT_NEAR(roots[1], 2.0, 1e-14);
        EXPECT_NEAR(roots[2], 3.0, 1e-14);
    }
}

TEST(SolveCubic, DegenerateAndNonFiniteInputs) {
    double roots[3];
    EXPECT_EQ(solve_cubic(0, 0, 0, 0, roots), 0);
    EXPECT_EQ(solve_cubic(0, 0, 0, 1, roots), 0);
    EXPECT_EQ(solve_cubic(NAN, 0, 0, 1, roots), 0);
    EXPECT_EQ(solve_cubic(1, 0, -INFINITY, 1, roots), 0);
    ASSERT_EQ(solve_cubic(0, 0, 2, -1, roots), 1);
    EXPECT_EQ(roots[0], 0.5);
    ASSERT_EQ(solve_cubic(1, 0, 0, -8, roots), 1);  // x³ = 8
    EXPECT_NEAR(roots[0], 2.0, 2 * kEps);
    ASSERT_EQ(solve_cubic(1, 0, 1, 0, roots), 1);  // x(x² + 1)
    EXPECT_EQ(roots[0], 0.0);
}

TEST(SolveInInterval, KeepsOnlyRootsInTheClosedInterval) {
    double roots[3];
    // (x − 0)(x − 0.5)(x − 1) = x³ − 1.5x² + 0.5x
    ASSERT_EQ(solve_cubic_in(1, -1.5, 0.5, 0, 0.0, 1.0, roots), 3);
    ASSERT_EQ(solve_cubic_in(1, -1.5, 0.5, 0, 0.25, 2.0, roots), 2);
    EXPECT_NEAR(roots[0], 0.5, 2 * kEps);
    EXPECT_NEAR(roots[1], 1.0, 2 * kEps);
    ASSERT_EQ(solve_quadratic_in(1, -3, 2, 1.5, 5, roots), 1);
    EXPECT_EQ(roots[0], 2.0);
    EXPECT_EQ(solve_quadratic_in(1, -3, 2, 3, 5, roots), 0);
}
