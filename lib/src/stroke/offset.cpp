// Offset curves of cubics, approximated by cubics.
//
// The exact offset O(t) = C(t) + d·N(t) of a cubic is not a polynomial curve (N involves
// 1/|C′|), so it is approximated piecewise, the idea of Tiller & Hanson ("Offsets of
// two-dimensional profiles", IEEE CG&A 1984: an offset piece keeps the tangent directions of the
// source) refined as in kurbo's stroker (Levien, "Cleaner parallel curves with Euler spirals"
// and kurbo/src/stroke.rs: fit, measure, subdivide until within the accuracy).
//
// For a piece of C over t ∈ [0, 1]:
//   1. The ends are exact: P₀ = O(0), P₃ = O(1).
//   2. The offset's tangent is parallel to the source's: O′ = |C′|·(1 − d·κ)·T, so the inner
//      handles lie on P₀ + a·g·T(0) and P₃ − b·g·T(1), g = sign(1 − d·κ) (the offset runs
//      backwards where it folds, d·κ > 1; split_cubic makes g constant on a piece).
//   3. The handle lengths a, b are the least-squares fit to samples O(tᵢ) at chord-length
//      parameters uᵢ (Schneider's fitting in "Graphics Gems", 1990): B(u) is linear in (a, b),
//          B(uᵢ) = P₀·(B₀+B₁) + P₃·(B₂+B₃) + a·B₁(uᵢ)·g·T₀ − b·B₂(uᵢ)·g·T₁,
//      so the 2×2 normal equations give them.
//   4. The error is measured along the source's normals: for each check parameter tⱼ, the line
//      C(tⱼ) + s·N(tⱼ) meets the fitted cubic where (B(u) − C(tⱼ)) × N(tⱼ) = 0, a cubic in u; the
//      distance from O(tⱼ) to the nearest such point is the error there. (The true offset
//      crosses each normal line at exactly O(tⱼ), so this is the gap between the two curves in
//      the direction that matters for the stroke's boundary.) Above `tol` anywhere, the piece
//      is halved in t and each half fitted again.
#include <algorithm>
#include <cmath>

#include "stroke/stroke_internal.hpp"

namespace bezel::stroke_detail {
namespace {

constexpr int kFitSamples = 10;    // interior samples for the least-squares fit
constexpr int kCheckSamples = 16;  // interior normals at which the error is measured
// Deepest halving of one piece: 2⁻²⁴ of the parameter range. Reached only when the requested
// tolerance is near double rounding of the geometry (stroke() raises it above that).
constexpr int kMaxDepth = 24;

Point offset_point(const CubicBez& c, double t, double d) { return c.eval(t) + c.normal(t) * d; }

// Power-basis coefficients of a cubic: B(u) = k[3]·u³ + k[2]·u² + k[1]·u + k[0].
void power_basis(const CubicBez& b, Vec2 k[4]) {
    k[0] = b.p0;
    k[1] = (b.p1 - b.p0) * 3.0;
    k[2] = (b.p0 - b.p1 * 2.0 + b.p2) * 3.0;
    k[3] = b.p3 - b.p0 + (b.p1 - b.p2) * 3.0;
}

// The gap at t between the true offset and `fit` along the source normal at t (see 4. above);
// infinity when the normal line misses the fitted cubic.
double normal_gap(const CubicBez& c, const CubicBez& fit, const Vec2 k[4], double t, double d) {
    Point base = c.eval(t);
    Vec2 n = c.normal(t);
    Point target = base + n * d;
    double roots[3];
    int count = solve_cubic_in(k[3].cross(n), k[2].cross(n), k[1].cross(n),
                               (k[0] - base).cross(n), 0.0, 1.0, roots);
    double best = HUGE_VAL;
    for (int i = 0; i < count; ++i) best = std::min(best, distance(fit.eval(roots[i]), target));
    // A fit whose tangent at this crossing runs along the normal would also give a root; the
    // end points are exact, so their own gaps are 0 and need no check.
    return best;
}

CubicBez fit_piece(const CubicBez& c, double d) {
    Point p0 = offset_point(c, 0.0, d), p3 = offset_point(c, 1.0, d);
    double g = 1.0 - d * c.curvature(0.5) < 0.0 ? -1.0 : 1.0;
    Vec2 t0 = c.tangent(0.0) * g, t1 = c.tangent(1.0) * g;

    Point samples[kFitSamples + 2];
    double u[kFitSamples + 2];
    samples[0] = p0;
    u[0] = 0.0;
    for (int i = 1; i <= kFitSamples; ++i)
        samples[i] = offset_point(c, static_cast<double>(i) / (kFitSamples + 1), d);
    samples[kFitSamples + 1] = p3;
    for (int i = 1; i <= kFitSamples + 1; ++i) u[i] = u[i - 1] + distance(samples[i - 1], samples[i]);
    double total = u[kFitSamples + 1];
    double chord = distance(p0, p3);
    if (!(total > 0.0)) return {p0, p0, p3, p3};
    double saa = 0, sab = 0, sbb = 0, sar = 0, sbr = 0;
    for (int i = 1; i <= kFitSamples; ++i) {
        double s = u[i] / total, m = 1.0 - s;
        double b0 = m * m * m, b1 = 3 * m * m * s, b2 = 3 * m * s * s, b3 = s * s * s;
        Vec2 r = samples[i] - (p0 * (b0 + b1) + p3 * (b2 + b3));
        Vec2 va = t0 * b1, vb = t1 * -b2;
        saa += va.dot(va);
        sab += va.dot(vb);
        sbb += vb.dot(vb);
        sar += va.dot(r);
        sbr += vb.dot(r);
    }
    double det = saa * sbb - sab * sab;
    double a = total / 3.0, b = total / 3.0;
    if (std::fabs(det) > 1e-12 * saa * sbb && det != 0.0) {
        a = (sar * sbb - sbr * sab) / det;
        b = (saa * sbr - sab * sar) / det;
    }
    // Handles far longer than the piece only arise from a bad-conditioned fit; the error check
    // then rejects them and the piece is split.
    double cap = 4.0 * std::max(total, chord);
    a = std::clamp(a, -cap, cap);
    b = std::clamp(b, -cap, cap);
    return {p0, p0 + t0 * a, p3 - t1 * b, p3};
}

double fit_error(const CubicBez& c, const CubicBez& fit, double d) {
    Vec2 k[4];
    power_basis(fit, k);
    double worst = 0.0;
    for (int j = 1; j <= kCheckSamples; ++j) {
        double t = static_cast<double>(j) / (kCheckSamples + 1);
        worst = std::max(worst, normal_gap(c, fit, k, t, d));
        if (!(worst < HUGE_VAL)) break;
    }
    return worst;
}

void offset_rec(const CubicBez& c, double d, double tol, int depth, Budget& budget,
                std::vector<CubicBez>& out) {
    if (budget.exceeded()) return;
    CubicBez fit = fit_piece(c, d);
    if (depth >= kMaxDepth || fit_error(c, fit, d) <= tol) {
        out.push_back(fit);
        budget.take(1);
        return;
    }
    auto halves = c.split(0.5);
    offset_rec(halves.first, d, tol, depth + 1, budget, out);
    offset_rec(halves.second, d, tol, depth + 1, budget, out);
}

}  // namespace

void offset_cubic(const CubicBez& c, double d, double tol, Budget& budget,
                  std::vector<CubicBez>& out) {
    std::size_t first = out.size();
    offset_rec(c, d, tol, 0, budget, out);
    // Adjacent fits meet at O(t) computed from each half's own control points, equal to within
    // rounding; snap them so the outline is exactly connected.
    for (std::size_t i = first + 1; i < out.size(); ++i) out[i].p0 = out[i - 1].p3;
}

}  // namespace bezel::stroke_detail
