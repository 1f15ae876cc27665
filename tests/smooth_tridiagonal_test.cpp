// The O(n) tridiagonal solvers behind the natural spline, against a dense Gaussian elimination.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "smooth/tridiagonal.hpp"

using namespace bezel;
using smooth_detail::Tridiagonal;

namespace {

// Dense Gaussian elimination with partial pivoting, one column of right-hand sides per
// coordinate: the plain reference the O(n) solvers are compared with.
std::vector<Vec2> dense_solve(std::vector<std::vector<double>> a, std::vector<Vec2> b) {
    const std::size_t n = b.size();
    for (std::size_t col = 0; col < n; ++col) {
        std::size_t pivot = col;
        for (std::size_t r = col + 1; r < n; ++r)
            if (std::fabs(a[r][col]) > std::fabs(a[pivot][col])) pivot = r;
        std::swap(a[col], a[pivot]);
        std::swap(b[col], b[pivot]);
        for (std::size_t r = col + 1; r < n; ++r) {
            double f = a[r][col] / a[col][col];
            for (std::size_t k = col; k < n; ++k) a[r][k] -= f * a[col][k];
            b[r] -= b[col] * f;
        }
    }
    std::vector<Vec2> x(n);
    for (std::size_t i = n; i-- > 0;) {
        Vec2 s = b[i];
        for (std::size_t k = i + 1; k < n; ++k) s -= x[k] * a[i][k];
        x[i] = s / a[i][i];
    }
    return x;
}

// A random strictly diagonally dominant system: off-diagonals in [-1, 1], the diagonal's
// magnitude exceeding their sum by at least 0.1, either sign.
Tridiagonal random_system(std::mt19937_64& rng, std::size_t n, bool cyclic) {
    std::uniform_real_distribution<double> off(-1.0, 1.0), margin(0.1, 3.0);
    std::bernoulli_distribution negative(0.3);
    Tridiagonal m;
    m.sub.assign(n, 0.0);
    m.diag.assign(n, 0.0);
    m.super.assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        if (cyclic || i > 0) m.sub[i] = off(rng);
        if (cyclic || i + 1 < n) m.super[i] = off(rng);
        double d = std::fabs(m.sub[i]) + std::fabs(m.super[i]) + margin(rng);
        m.diag[i] = negative(rng) ? -d : d;
    }
    return m;
}

std::vector<std::vector<double>> dense(const Tridiagonal& m, bool cyclic) {
    const std::size_t n = m.diag.size();
    std::vector<std::vector<double>> a(n, std::vector<double>(n, 0.0));
    for (std::size_t i = 0; i < n; ++i) {
        a[i][i] += m.diag[i];
        if (i > 0) a[i][i - 1] += m.sub[i];
        else if (cyclic) a[0][n - 1] += m.sub[0];
        if (i + 1 < n) a[i][i + 1] += m.super[i];
        else if (cyclic) a[n - 1][0] += m.super[n - 1];
    }
    return a;
}

std::vector<Vec2> random_rhs(std::mt19937_64& rng, std::size_t n) {
    std::uniform_real_distribution<double> v(-100.0, 100.0);
    std::vector<Vec2> b(n);
    for (Vec2& x : b) x = {v(rng), v(rng)};
    return b;
}

double max_abs(const std::vector<Vec2>& x) {
    double m = 0.0;
    for (const Vec2& v : x) m = std::max({m, std::fabs(v.x), std::fabs(v.y)});
    return m;
}

}  // namespace

// 3000 random dominant systems of size 1..60: the Thomas solution agrees with the dense one to
// 1e-12 relative to the solution's largest entry (both are backward stable here; the dominance
// margin ≥ 0.1 keeps the condition number below ~60).
TEST(Tridiagonal, ThomasMatchesDenseEliminationOnRandomSystems) {
    std::mt19937_64 rng(0x5eed0006);
    std::uniform_int_distribution<std::size_t> size(1, 60);
    for (int trial = 0; trial < 3000; ++trial) {
        std::size_t n = size(rng);
        Tridiagonal m = random_system(rng, n, false);
        std::vector<Vec2> b = random_rhs(rng, n);
        std::vector<Vec2> expected = dense_solve(dense(m, false), b);
        std::vector<Vec2> x = b;
        ASSERT_TRUE(smooth_detail::solve_tridiagonal(m, x)) << "trial " << trial;
        double scale = max_abs(expected);
        for (std::size_t i = 0; i < n; ++i)
            ASSERT_LE((x[i] - expected[i]).length(), 1e-12 * scale) << "trial " << trial << " row " << i;
    }
}

TEST(Tridiagonal, CyclicMatchesDenseEliminationOnRandomSystems) {
    std::mt19937_64 rng(0x5eed0007);
    std::uniform_int_distribution<std::size_t> size(3, 60);
    for (int trial = 0; trial < 3000; ++trial) {
        std::size_t n = size(rng);
        Tridiagonal m = random_system(rng, n, true);
        std::vector<Vec2> b = random_rhs(rng, n);
        std::vector<Vec2> expected = dense_solve(dense(m, true), b);
        std::vector<Vec2> x = b;
        ASSERT_TRUE(smooth_detail::solve_cyclic_tridiagonal(m, x)) << "trial " << trial;
        double scale = max_abs(expected);
        for (std::size_t i = 0; i < n; ++i)
            ASSERT_LE((x[i] - expected[i]).length(), 1e-12 * scale) << "trial " << trial << " row " << i;
    }
}

// The natural spline's own uniform matrix [2 1; 1 4 1; …; 1 2] with a known solution: every
// derivative (1, −2) reproduces rhs = (3, −6), (6, −12), …, (3, −6).
TEST(Tridiagonal, SolvesTheUniformSplineSystemExactly) {
    const std::size_t n = 9;
    Tridiagonal m{std::vector<double>(n, 1.0), std::vector<double>(n, 4.0),
                  std::vector<double>(n, 1.0)};
    m.diag.front() = m.diag.back() = 2.0;
    std::vector<Vec2> x(n, Vec2{6.0, -12.0});
    x.front() = x.back() = Vec2{3.0, -6.0};
    ASSERT_TRUE(smooth_detail::solve_tridiagonal(m, x));
    for (const Vec2& v : x) {
        EXPECT_NEAR(v.x, 1.0, 1e-15);
        EXPECT_NEAR(v.y, -2.0, 1e-15);
    }
}

TEST(Tridiagonal, ZeroPivotIsReportedNotDividedBy) {
    // [0 1; 1 0] has no LU factorisation without pivoting: the first pivot is 0.
    Tridiagonal m{{0.0, 1.0}, {0.0, 0.0}, {1.0, 0.0}};
    std::vector<Vec2> x{{1, 1}, {2, 2}};
    EXPECT_FALSE(smooth_detail::solve_tridiagonal(m, x));
    // [1 1; 1 1] is singular: the second pivot is 1 − 1·1 = 0.
    Tridiagonal s{{0.0, 1.0}, {1.0, 1.0}, {1.0, 0.0}};
    std::vector<Vec2> y{{1, 1}, {2, 2}};
    EXPECT_FALSE(smooth_detail::solve_tridiagonal(s, y));
}
