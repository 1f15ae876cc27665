// ParabolaIntegral: Levien's analytic flattening of quadratics ("Flattening quadratic Béziers",
// R. Levien, 2019, raphlinus.github.io; also kurbo's flatten), cubics through quadratics first.
//
// Quadratics. Every quadratic is a piece of the parabola y = x² up to rotation, translation and
// uniform scale. For a short chord the error is ≈ κ·Δs²/8; on y = x², κ = 2/(1 + 4x²)^{3/2} and
// ds = √(1 + 4x²)·dx, so holding the error at tol the segment density in x is
//     d(segments)/dx = 1 / (2·√tol · (1 + 4x²)^{1/4}),
// and spacing the points evenly in I(x) = ∫ (1 + 4x²)^{−1/4} dx makes every segment's error equal.
// I and its inverse are replaced by Levien's closed-form approximations
//     I(x) ≈ x / (1 − D + (D⁴ + x²/4)^{1/4}),  D = 0.67;   I⁻¹(a) ≈ a·(1 − B + √(B² + a²/4)),  B = 0.39,
// and n = ⌈ (|I(x₂) − I(x₀)| / 2)·√(scale / tol) ⌉ with x₀, x₂, scale the quadratic's position on
// the unit parabola (map_to_basic in Levien's code).
//
// Proof of the bound. The approximations (and the small-segment limit) make the spacing an
// estimate, not a guarantee. So each piece [tᵢ, tᵢ₊₁] is checked exactly: it is itself a
// quadratic, with control point B(tᵢ) + B'(tᵢ)·(tᵢ₊₁ − tᵢ)/2, and quad_chord_bound_squared bounds
// its Hausdorff distance to its chord. A piece that fails (rare; near-degenerate quadratics, where
// the map to the parabola breaks down, fail wholesale) is halved as in DistanceSubdivision. Every
// piece that is emitted has passed a proven bound, so the result is within tol.
//
// Cubics. A cubic on [t₀, t₁] is replaced by the quadratic with the same end points and control
// point (3(P₁ + P₂) − P₀ − P₃)/4. Their difference is, exactly,
//     C(t) − Q(t) = (D/2)·t(1 − t)(1 − 2t),  D = P₃ − 3P₂ + 3P₁ − P₀,
// (elevate Q to degree 3: the control points of C − Q are 0, D/6, −D/6, 0), whose maximum norm
// is ‖D‖·√3/36 (at t = 1/2 ± √3/6). Splitting the cubic into m equal parameter pieces divides D by
// m³, so m = ⌈(√3·‖D‖ / (36·α·tol))^{1/3}⌉ quadratics are within α·tol of it, parametrically and
// hence in Hausdorff distance; each quadratic is flattened within (1 − α)·tol, and the triangle
// inequality for the Hausdorff distance gives tol. α = kCubicToQuadShare: fewer quadratics, but
// each flattened more finely, trade off; measured on Cantarell (cubic) at 512 px, α = 0.05, 0.1,
// 0.2 give 181.6 k, 180.6 k, 185.0 k segments. Polyline vertices of a cubic lie on the quadratics,
// so within α·tol of the cubic, not on it.
//
// Not done (yet): kurbo spreads one cubic's segments over all its quadratics by the summed
// integral instead of rounding up per quadratic, which saves up to one segment per quadratic;
// without it this method loses to WangUniform on cubic fonts (Cantarell 512 px: 180.6 k vs
// 172.6 k). Pieces straddling two quadratics would need the hull check of both parts.
#include <algorithm>
#include <cmath>

#include "bezel/flatten.hpp"
#include "flatten/curve_math.hpp"
#include "flatten/methods.hpp"
#include "flatten/subdivide.hpp"

namespace bezel::flatten_detail {

namespace {

// Share of the tolerance spent on approximating a cubic by quadratics.
constexpr double kCubicToQuadShare = 0.1;

double approx_parabola_integral(double x) {
    constexpr double d = 0.67;
    constexpr double d4 = d * d * d * d;
    return x / (1.0 - d + std::sqrt(std::sqrt(d4 + 0.25 * x * x)));
}

double approx_parabola_inv_integral(double a) {
    constexpr double b = 0.39;
    return a * (1.0 - b + std::sqrt(b * b + 0.25 * a * a));
}

// Flattens q within tolerance_px using at most `budget` (≥ 1) segments.
bool flatten_quad(const QuadBez& q, double tolerance_px, std::size_t budget, std::vector<Point>& out) {
    const double tol2 = tolerance_px * tolerance_px;
    // Position on the unit parabola (Levien's map_to_basic): dd is the second difference, x₀ and
    // x₂ the parabola abscissae of the end points, scale the size of the parabola.
    const Vec2 d01 = q.p1 - q.p0, d12 = q.p2 - q.p1, dd = d01 - d12;
    const double cross = (q.p2 - q.p0).cross(dd);
    const double x0 = d01.dot(dd) / cross, x2 = d12.dot(dd) / cross;
    const double scale = std::fabs(cross) / (dd.length() * std::fabs(x2 - x0));
    const double a0 = approx_parabola_integral(x0), a2 = approx_parabola_integral(x2);
    const double count = 0.5 * std::fabs(a2 - a0) * std::sqrt(scale / tolerance_px);
    // A straight or collinear quadratic has cross = 0 and no parabola: NaN or ∞ here. Start from
    // one piece and let the exact check split it.
    const std::size_t n = std::isfinite(count) ? clamp_count(count, budget) : 1;
    const double u0 = approx_parabola_inv_integral(a0);
    const double u_scale = 1.0 / (approx_parabola_inv_integral(a2) - u0);

    std::size_t spare = budget - n;  // further pieces the repair step may add
    bool met = true;
    Point prev = q.p0;
    double t_prev = 0.0;
    for (std::size_t i = 1; i <= n; ++i) {
        double t = 1.0;
        Point p = q.p2;
        if (i < n) {
            double u = approx_parabola_inv_integral(a0 + (a2 - a0) * (static_cast<double>(i) / n));
            double t_est = (u - u0) * u_scale;
            t = t_est > t_prev ? std::min(t_est, 1.0) : t_prev;  // monotone; NaN → t_prev
            p = q.eval(t);
        }
        // The exact control point of the piece: B(t_prev) + B'(t_prev)·Δt/2, B' = 2(d01 + t·(d12 − d01)).
        Point c = prev + (d01 + (d12 - d01) * t_prev) * (t - t_prev);
        if (quad_chord_bound_squared(prev, c, p) <= tol2) {
            out.push_back(p);
        } else {
            auto is_flat = [tol2](const QuadBez& s) { return quad_chord_bound_squared(s.p0, s.p1, s.p2) <= tol2; };
            met &= subdivide(QuadBez{prev, c, p}, is_flat, spare, out);  // ends exactly at p
        }
        prev = p;
        t_prev = t;
    }
    return met;
}

}  // namespace

bool parabola_integral(const QuadBez& q, double tolerance_px, std::vector<Point>& out) {
    return flatten_quad(q, tolerance_px, kMaxSegmentsPerCurve, out);
}

bool parabola_integral(const CubicBez& c, double tolerance_px, std::vector<Point>& out) {
    // A cubic already within tolerance of its chord (short or straight ones: many in fonts) is its
    // chord; the parametric cubic-to-quadratic bound below would split a straight but unevenly
    // parametrized cubic needlessly.
    if (cubic_chord_bound_squared(c.p0, c.p1, c.p2, c.p3) <= tolerance_px * tolerance_px) {
        out.push_back(c.p3);
        return true;
    }
    const Vec2 d = c.p3 - c.p0 + (c.p1 - c.p2) * 3.0;
    const double quad_tol = kCubicToQuadShare * tolerance_px;
    const double m_real = std::cbrt(std::sqrt(3.0) / 36.0 * d.length() / quad_tol);
    std::size_t m = clamp_count(m_real, kMaxSegmentsPerCurve);
    bool met = m_real <= static_cast<double>(kMaxSegmentsPerCurve);

    // Power form B(t) = P₀ + c₁t + c₂t² + c₃t³ and its derivative, for the quadratics' ends.
    const Vec2 k1 = (c.p1 - c.p0) * 3.0, k2 = (c.p0 - c.p1 * 2.0 + c.p2) * 3.0, k3 = d;
    auto deriv = [&](double t) { return k1 + (k2 * 2.0 + k3 * (3.0 * t)) * t; };
    const double dt = 1.0 / static_cast<double>(m);
    std::size_t budget = kMaxSegmentsPerCurve;
    Point start = c.p0;
    Vec2 start_deriv = deriv(0.0);
    for (std::size_t i = 0; i < m; ++i) {
        double t1 = static_cast<double>(i + 1) * dt;
        Point end = i + 1 == m ? c.p3 : c.eval(t1);
        Vec2 end_deriv = deriv(t1);
        // Quadratic control point (3(C₁ + C₂) − C₀ − C₃)/4 of the sub-cubic, with C₁ = C₀ + B'(t₀)·Δt/3
        // and C₂ = C₃ − B'(t₁)·Δt/3: (C₀ + C₃)/2 + (B'(t₀) − B'(t₁))·Δt/4.
        Point ctrl = (start + end) * 0.5 + (start_deriv - end_deriv) * (0.25 * dt);
        std::size_t own = budget - (m - i - 1);  // leave one segment for each later quadratic
        std::size_t before = out.size();
        met &= flatten_quad(QuadBez{start, ctrl, end}, (1.0 - kCubicToQuadShare) * tolerance_px, own, out);
        budget -= out.size() - before;
        start = end;
        start_deriv = end_deriv;
    }
    return met;
}

}  // namespace bezel::flatten_detail
