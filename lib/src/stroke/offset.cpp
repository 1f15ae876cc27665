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
//   3. The handle lengths a, b are the least-squares fit to samples O(tᵢ) (spread along the
//      offset, see sample_offset) at chord-length parameters uᵢ (Schneider's fitting in "Graphics Gems", 1990): B(u) is linear in (a, b),
//          B(uᵢ) = P₀·(B₀+B₁) + P₃·(B₂+B₃) + a·B₁(uᵢ)·g·T₀ − b·B₂(uᵢ)·g·T₁,
//      so the 2×2 normal equations give them.
//   4. The error is measured along the source's normals at the samples and halfway between
//      them: for each such parameter tⱼ, the line
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

// Samples of the true offset: 12 equal steps in t, then any step whose chord is longer than
// 1/12 of the sampled length is halved (up to kMaxSampleSplits times), so that the samples are
// spread ALONG THE OFFSET even where the parameter crowds (near cusps the normal swings through
// a half turn in a tiny t range, which equal t steps would skip).
constexpr int kBaseSteps = 12;
constexpr int kMaxSampleSplits = 10;
constexpr std::size_t kMaxSamples = 96;
// Deepest halving of one piece: 2⁻²⁴ of the parameter range. Reached only when the requested
// tolerance is near double rounding of the geometry (stroke() raises it above that).
constexpr int kMaxDepth = 24;
// The normals are a sample: between them the gap can exceed what they saw, so the fit aims at
// this share of the tolerance (the 2000-cubic sweep of stroke_offset_test then stays within it).
constexpr double kTolShare = 0.8;

Point offset_point(const CubicBez& c, double t, double d) { return c.eval(t) + c.normal(t) * d; }

// Power-basis coefficients of a cubic: B(u) = k[3]·u³ + k[2]·u² + k[1]·u + k[0].
void power_basis(const CubicBez& b, Vec2 k[4]) {
    k[0] = b.p0;
    k[1] = (b.p1 - b.p0) * 3.0;
    k[2] = (b.p0 - b.p1 * 2.0 + b.p2) * 3.0;
    k[3] = b.p3 - b.p0 + (b.p1 - b.p2) * 3.0;
}

// The gap at t between the true offset and `fit` along the source normal at t (see 4. above);
// infinity when the normal line misses the fitted cubic. f(u) = (B(u) − C(t)) × N(t) is a cubic
// in u; Newton from `u_guess` (the chord-length parameter of that point) usually lands on the
// crossing in a few steps, and the exact cubic solver (5× dearer) takes over when it does not.
double normal_gap(const CubicBez& c, const CubicBez& fit, const Vec2 k[4], double t, double d,
                  double u_guess) {
    Point base = c.eval(t);
    Vec2 n = c.normal(t);
    Point target = base + n * d;
    double a3 = k[3].cross(n), a2 = k[2].cross(n), a1 = k[1].cross(n), a0 = (k[0] - base).cross(n);
    double scale = std::fabs(a3) + std::fabs(a2) + std::fabs(a1) + std::fabs(a0);
    double u = u_guess;
    for (int it = 0; it < 8; ++it) {
        double f = ((a3 * u + a2) * u + a1) * u + a0;
        double df = (3 * a3 * u + 2 * a2) * u + a1;
        if (std::fabs(f) <= 1e-13 * scale) {
            if (u >= -1e-9 && u <= 1 + 1e-9) return distance(fit.eval(u), target);
            break;
        }
        if (df == 0.0) break;
        u -= f / df;
        if (!(u > -0.5 && u < 1.5)) break;
    }
    double roots[3];
    int count = solve_cubic_in(a3, a2, a1, a0, 0.0, 1.0, roots);
    double best = HUGE_VAL;
    for (int i = 0; i < count; ++i) best = std::min(best, distance(fit.eval(roots[i]), target));
    return best;
}

struct Sample {
    double t;
    Point o;
    double u = 0;  // chord-length parameter, 0 at the first sample, 1 at the last
};

void sample_offset(const CubicBez& c, double d, std::vector<Sample>& out) {
    out.clear();
    double length = 0;
    for (int i = 0; i <= kBaseSteps; ++i) {
        double t = static_cast<double>(i) / kBaseSteps;
        out.push_back({t, offset_point(c, t, d)});
        if (i > 0) length += distance(out[i - 1].o, out[i].o);
    }
    double step = length / kBaseSteps;
    for (int pass = 0; pass < kMaxSampleSplits && out.size() < kMaxSamples; ++pass) {
        bool split = false;
        for (std::size_t i = 0; i + 1 < out.size() && out.size() < kMaxSamples; ++i) {
            if (distance(out[i].o, out[i + 1].o) <= step) continue;
            double t = 0.5 * (out[i].t + out[i + 1].t);
            out.insert(out.begin() + static_cast<std::ptrdiff_t>(i) + 1, Sample{t, offset_point(c, t, d)});
            ++i;
            split = true;
        }
        if (!split) break;
    }
    double acc = 0;
    for (std::size_t i = 1; i < out.size(); ++i) out[i].u = acc += distance(out[i - 1].o, out[i].o);
    if (acc > 0)
        for (Sample& smp : out) smp.u /= acc;
}

CubicBez fit_piece(const CubicBez& c, double d, const std::vector<Sample>& samples) {
    Point p0 = samples.front().o, p3 = samples.back().o;
    double g = 1.0 - d * c.curvature(0.5) < 0.0 ? -1.0 : 1.0;
    Vec2 t0 = c.tangent(0.0) * g, t1 = c.tangent(1.0) * g;

    double total = 0;
    for (std::size_t i = 1; i < samples.size(); ++i) total += distance(samples[i - 1].o, samples[i].o);
    double chord = distance(p0, p3);
    if (!(total > 0.0)) return {p0, p0, p3, p3};
    double saa = 0, sab = 0, sbb = 0, sar = 0, sbr = 0;
    for (std::size_t i = 1; i + 1 < samples.size(); ++i) {
        double s = samples[i].u, m = 1.0 - s;
        double b0 = m * m * m, b1 = 3 * m * m * s, b2 = 3 * m * s * s, b3 = s * s * s;
        Vec2 r = samples[i].o - (p0 * (b0 + b1) + p3 * (b2 + b3));
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
    // Handles far longer than the piece only arise from a badly conditioned fit; the error
    // check then rejects them and the piece is split.
    double cap = 4.0 * std::max(total, chord);
    a = std::clamp(a, -cap, cap);
    b = std::clamp(b, -cap, cap);
    return {p0, p0 + t0 * a, p3 - t1 * b, p3};
}

// Whether the normal gap stays within `limit` at the interior samples and halfway between all
// samples (stopping at the first miss: a miss means the piece is split anyway).
bool fit_within(const CubicBez& c, const CubicBez& fit, double d, const std::vector<Sample>& samples,
                double limit) {
    Vec2 k[4];
    power_basis(fit, k);
    for (std::size_t i = 0; i + 1 < samples.size(); ++i) {
        const Sample &a = samples[i], &b = samples[i + 1];
        if (!(normal_gap(c, fit, k, 0.5 * (a.t + b.t), d, 0.5 * (a.u + b.u)) <= limit)) return false;
        if (i > 0 && !(normal_gap(c, fit, k, a.t, d, a.u) <= limit)) return false;
    }
    return true;
}

void offset_rec(const CubicBez& c, double d, double tol, int depth, Budget& budget,
                std::vector<CubicBez>& out) {
    if (budget.exceeded()) return;
    std::vector<Sample> samples;
    sample_offset(c, d, samples);
    CubicBez fit = fit_piece(c, d, samples);
    if (depth >= kMaxDepth || fit_within(c, fit, d, samples, kTolShare * tol)) {
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
