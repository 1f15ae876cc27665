// WangUniform: n equal parameter steps, n from Wang's formula, points by forward differencing.
//
// Wang's formula (Wang Guozhao 1984; in this form e.g. in Filip, Magedson & Markot, "Surface
// algorithms using bounds on derivatives", CAGD 3, 1986). For a Bézier B of degree d with control
// points Pᵢ, let M = maxᵢ ‖Pᵢ − 2Pᵢ₊₁ + Pᵢ₊₂‖. Derivation:
//  1. B''(t) = d(d−1)·Σ Bᵢ^{d−2}(t)·(Pᵢ − 2Pᵢ₊₁ + Pᵢ₊₂), a convex combination scaled by d(d−1),
//     so ‖B''‖ ≤ d(d−1)·M.
//  2. On a parameter interval of length h, let ℓ be the chord interpolating B at both ends and
//     e = B − ℓ. Then e = −∫ G(t, s)·B''(s) ds with Green's kernel G ≥ 0 of the two-point problem,
//     ∫ G(t, s) ds = (t − t₀)(t₁ − t)/2 ≤ h²/8, so ‖e(t)‖ ≤ h²/8 · d(d−1)·M (a vector bound:
//     the kernel is non-negative, so the norm passes inside the integral).
//  3. With h = 1/n, ‖e‖ ≤ tol as soon as n ≥ √(d(d−1)·M / (8·tol)):
//        quadratic  n = ⌈√(M / (4·tol))⌉,      cubic  n = ⌈√(3·M / (4·tol))⌉.
// Since ‖B(t) − ℓ(t)‖ ≤ tol at the *same* parameter, every curve point is within tol of the
// polyline and every polyline point within tol of the curve: a Hausdorff bound.
//
// Rounding. The points come from forward differencing (forward_difference.hpp), whose drift is
// measured in flatten_test; 1/64 of the tolerance is set aside for it (n is computed for
// tol·63/64), far more than the measured double drift with re-seeding every kForwardDifferenceRun
// steps. The last point is the curve's end point, copied, not computed.
#include <algorithm>
#include <cmath>

#include "bezel/flatten.hpp"
#include "flatten/curve_math.hpp"
#include "flatten/forward_difference.hpp"
#include "flatten/methods.hpp"

namespace bezel::flatten_detail {

namespace {
// Share of the tolerance left for the curve after the reserve for forward-differencing drift.
constexpr double kWangToleranceShare = 63.0 / 64.0;

template <typename Curve>
bool emit_uniform(const Curve& curve, const PowerCubic& pc, double count, std::vector<Point>& out) {
    std::size_t n = clamp_count(count, kMaxSegmentsPerCurve);
    const Point p0 = curve.p0;
    forward_difference<double>(pc, n, kForwardDifferenceRun,
                               [&](double x, double y) { out.push_back({p0.x + x, p0.y + y}); });
    out.push_back(end_point(curve));
    // Met unless the count was clamped (NaN compares false, so it counts as clamped).
    return count <= static_cast<double>(kMaxSegmentsPerCurve);
}
}  // namespace

double wang_quad_count(const QuadBez& q, double tolerance_px) {
    double m = (q.p0 - q.p1 * 2.0 + q.p2).length();
    return std::sqrt(m / (4.0 * tolerance_px * kWangToleranceShare));
}

double wang_cubic_count(const CubicBez& c, double tolerance_px) {
    double m = std::max((c.p0 - c.p1 * 2.0 + c.p2).length(), (c.p1 - c.p2 * 2.0 + c.p3).length());
    return std::sqrt(3.0 * m / (4.0 * tolerance_px * kWangToleranceShare));
}

bool wang_uniform(const QuadBez& q, double tolerance_px, std::vector<Point>& out) {
    // B(t) − P₀ = (P₀ − 2P₁ + P₂)·t² + 2(P₁ − P₀)·t.
    PowerCubic pc{{0.0, 0.0}, q.p0 - q.p1 * 2.0 + q.p2, (q.p1 - q.p0) * 2.0};
    return emit_uniform(q, pc, wang_quad_count(q, tolerance_px), out);
}

bool wang_uniform(const CubicBez& c, double tolerance_px, std::vector<Point>& out) {
    PowerCubic pc{c.p3 - c.p0 + (c.p1 - c.p2) * 3.0, (c.p0 - c.p1 * 2.0 + c.p2) * 3.0,
                  (c.p1 - c.p0) * 3.0};
    return emit_uniform(c, pc, wang_cubic_count(c, tolerance_px), out);
}

}  // namespace bezel::flatten_detail
