// General-degree Bézier curves (degree ≤ Bezier::kMaxDegree), binomials and Bernstein polynomials.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "bezel/bezier.hpp"

namespace bezel {

namespace {

constexpr int kN = kMaxExactBinomial + 1;
using BinomialTable = std::array<std::array<double, kN>, kN>;

// Pascal's triangle C(n,k) = C(n−1,k−1) + C(n−1,k): integer additions, exact while below 2⁵³.
constexpr BinomialTable make_binomials() {
    BinomialTable c{};
    for (int n = 0; n < kN; ++n) {
        c[n][0] = 1.0;
        for (int k = 1; k <= n; ++k) c[n][k] = c[n - 1][k - 1] + (k < n ? c[n - 1][k] : 0.0);
    }
    return c;
}
constexpr BinomialTable kBinomials = make_binomials();

constexpr int kD = Bezier::kMaxDegree + 1;
// kPowerBasis[n][row][col]: the degree-n matrix M of Q(t) = T·M·G with T = [tⁿ … t 1], so row
// `row` holds the coefficients of t^(n−row). Expanding (1−t)ⁿ⁻ⁱ binomially,
//   Bᵢ,ₙ(t) = Σ_{k=i..n} (−1)^(k−i)·C(n,k)·C(k,i)·tᵏ,
// so m[n−k][i] = (−1)^(k−i)·C(n,k)·C(k,i) for k ≥ i and 0 otherwise. For n = 3 this is
// basis::kBezier. Built once, at compile time (17³ doubles, 39 KB of read-only data).
using PowerBasis = std::array<std::array<std::array<double, kD>, kD>, kD>;
constexpr PowerBasis make_power_basis() {
    PowerBasis m{};
    for (int n = 0; n < kD; ++n)
        for (int k = 0; k <= n; ++k)
            for (int i = 0; i <= k; ++i) {
                double v = kBinomials[n][k] * kBinomials[k][i];
                m[n][n - k][i] = ((k - i) % 2 == 0) ? v : -v;
            }
    return m;
}
constexpr PowerBasis kPowerBasis = make_power_basis();

// xᵏ for small integer k by repeated multiplication (std::pow's exactness for integer exponents
// is not promised; this is, to k roundings).
double ipow(double x, int k) {
    double r = 1.0;
    for (int i = 0; i < k; ++i) r *= x;
    return r;
}

}  // namespace

double binomial(int n, int k) {
    if (n < 0 || k < 0 || k > n) return 0.0;
    if (n < kN) return kBinomials[n][k];
    // Multiplicative formula C(n,k) = Π_{j=1..k} (n−k+j)/j, with the smaller of k and n−k.
    k = std::min(k, n - k);
    double c = 1.0;
    for (int j = 1; j <= k; ++j) c = c * (n - k + j) / j;
    return std::isfinite(c) ? std::round(c) : c;  // an integer, up to the rounding above
}

double bernstein(int n, int i, double t) {
    if (n < 0 || i < 0 || i > n) return 0.0;
    return binomial(n, i) * ipow(t, i) * ipow(1.0 - t, n - i);
}

Expected<Bezier> Bezier::from_points(const Point* points, std::size_t count) {
    if (count == 0 || count > static_cast<std::size_t>(kMaxDegree + 1)) {
        return Error{"Bezier::from_points: " + std::to_string(count) +
                     " control points (need 1 to " + std::to_string(kMaxDegree + 1) + ")"};
    }
    Bezier b;
    b.degree = static_cast<int>(count) - 1;
    for (std::size_t i = 0; i < count; ++i) b.p[i] = points[i];
    return b;
}

Point Bezier::eval_de_casteljau(double t) const {
    // Level r replaces q[i] by lerp(q[i], q[i+1], t); after n levels q[0] = Q(t).
    Point q[kMaxDegree + 1];
    for (int i = 0; i <= degree; ++i) q[i] = p[i];
    for (int r = degree; r > 0; --r)
        for (int i = 0; i < r; ++i) q[i] = lerp(q[i], q[i + 1], t);
    return q[0];
}

Point Bezier::eval_bernstein(double t) const {
    // Q(t) = Σ C(n,i)·tⁱ·(1−t)ⁿ⁻ⁱ·Pᵢ with the powers of t and of s = 1 − t tabulated once.
    double s = 1.0 - t;
    double tp[kMaxDegree + 1], sp[kMaxDegree + 1];
    tp[0] = sp[0] = 1.0;
    for (int i = 1; i <= degree; ++i) tp[i] = tp[i - 1] * t, sp[i] = sp[i - 1] * s;
    Point q{};
    for (int i = 0; i <= degree; ++i) q += p[i] * (kBinomials[degree][i] * tp[i] * sp[degree - i]);
    return q;
}

Point Bezier::eval_matrix(double t) const {
    // M·G first (the power-basis coefficients, one point per row), then T·(M·G) by Horner.
    const auto& M = kPowerBasis[degree];
    Point q{};
    for (int row = 0; row <= degree; ++row) {
        Point coef{};
        for (int col = 0; col <= degree; ++col) coef += p[col] * M[row][col];
        q = q * t + coef;
    }
    return q;
}

Bezier Bezier::deriv(int order) const {
    Bezier d = *this;
    for (int k = 0; k < order; ++k) {
        if (d.degree == 0) return Bezier{};  // the derivative of a constant is the zero curve
        // Q′(t) = n·Σ Bᵢ,ₙ₋₁(t)·(Pᵢ₊₁ − Pᵢ).
        int n = d.degree;
        for (int i = 0; i < n; ++i) d.p[i] = (d.p[i + 1] - d.p[i]) * static_cast<double>(n);
        d.p[n] = Point{};
        d.degree = n - 1;
    }
    return d;
}

std::pair<Bezier, Bezier> Bezier::split(double t) const {
    // The de Casteljau triangle: the left half's control points are the first point of each
    // level, the right half's the last point of each level (read from the bottom up).
    Bezier left, right;
    left.degree = right.degree = degree;
    Point q[kMaxDegree + 1];
    for (int i = 0; i <= degree; ++i) q[i] = p[i];
    left.p[0] = q[0];
    right.p[degree] = q[degree];
    for (int r = degree; r > 0; --r) {
        for (int i = 0; i < r; ++i) q[i] = lerp(q[i], q[i + 1], t);
        left.p[degree - r + 1] = q[0];
        right.p[r - 1] = q[r - 1];
    }
    return {left, right};
}

Bezier Bezier::reversed() const {
    Bezier r;
    r.degree = degree;
    for (int i = 0; i <= degree; ++i) r.p[i] = p[degree - i];
    return r;
}

Expected<Bezier> Bezier::elevate() const {
    if (degree >= kMaxDegree) {
        return Error{"Bezier::elevate: degree " + std::to_string(degree) +
                     " is already the maximum (" + std::to_string(kMaxDegree) + ")"};
    }
    // Qᵢ = (i/(n+1))·Pᵢ₋₁ + (1 − i/(n+1))·Pᵢ, i = 0 … n+1 (Farin, "Curves and Surfaces for CAGD",
    // §6.1): multiplying Q by (1−t) + t = 1 and regrouping the Bernstein terms.
    int n = degree;
    Bezier e;
    e.degree = n + 1;
    e.p[0] = p[0];
    e.p[n + 1] = p[n];
    for (int i = 1; i <= n; ++i) {
        double a = static_cast<double>(i) / (n + 1);
        e.p[i] = p[i - 1] * a + p[i] * (1.0 - a);
    }
    return e;
}

Rect Bezier::control_box() const {
    Rect r = Rect::empty();
    for (int i = 0; i <= degree; ++i) r = r.union_with(p[i]);
    return r;
}

bool Bezier::is_finite() const {
    for (int i = 0; i <= degree; ++i)
        if (!p[i].is_finite()) return false;
    return true;
}

}  // namespace bezel
