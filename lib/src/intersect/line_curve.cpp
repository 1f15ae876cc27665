// A line against a line, quadratic or cubic, and a point against any curve.
//
// Line–curve: with the line L(s) = P + s·r, the signed distance of the curve from the line's
// support, scaled by |r|, is the polynomial
//     g(t) = r × (B(t) − P) = Σ Bᵢ,ₙ(t)·(r × (Bᵢ − P)),
// a Bézier in t with control values r × (Bᵢ − P); its roots in [0, 1] (solve_cubic_in, which
// returns a double root once) are where B meets the line, s = (B(t) − P)·r / |r|². Simple roots
// are then polished by 2D Newton on both parameters. Where B touches the line, g has a double
// root that no solver can place better than √ε; but g′(t) = r × B′(t) has a SIMPLE root there
// (when B's curvature is not 0), so the contact is taken from g′ = 0 and kept when |g| ≤ kTouch·|r|.
#include <algorithm>
#include <cmath>

#include "intersect/curve_ops.hpp"

namespace bezel::isect {

namespace {

void push(Raw& raw, double s, double t, Source src, bool swapped) {
    if (swapped)
        raw.hits.push_back({t, s, src});
    else
        raw.hits.push_back({s, t, src});
}

bool in_range(double x) { return x >= -kParamSlack && x <= 1.0 + kParamSlack; }

void line_line(const Curve& l, const Curve& m, Raw& raw, bool swapped) {
    // P + s·r = Q + t·u; with w = Q − P and D = r × u:  s = (w × u)/D,  t = (w × r)/D.
    Vec2 r = l.p[1] - l.p[0], u = m.p[1] - m.p[0], w = m.p[0] - l.p[0];
    double d = r.cross(u);
    if (d == 0.0) return;  // parallel and not collinear (collinear pairs never get here)
    double s = w.cross(u) / d, t = w.cross(r) / d;
    if (in_range(s) && in_range(t)) push(raw, s, t, Source::Newton, swapped);
}

}  // namespace

void line_curve(const Curve& line, const Curve& b, Raw& raw, bool swapped) {
    if (b.degree == 1) return line_line(line, b, raw, swapped);
    const Point p = line.p[0];
    const Vec2 r = line.p[1] - line.p[0];
    const double r2 = r.length_squared();
    double v[4], g[4], roots[3];
    for (int i = 0; i <= b.degree; ++i) v[i] = r.cross(b.p[i] - p);
    bernstein_to_power(v, b.degree, g);
    const double tol = kTouch * std::sqrt(r2);

    auto param_on_line = [&](double t) { return (b.eval(t) - p).dot(r) / r2; };
    auto g_at = [&](double t) { return r.cross(b.eval(t) - p); };
    // g′(t) power coefficients.
    double dg[4] = {g[1], 2.0 * g[2], 3.0 * g[3], 0.0};
    double crit[3];
    int n_crit = poly_roots_in(dg, 0.0, 1.0, crit);

    int n = poly_roots_in(g, -kParamSlack, 1.0 + kParamSlack, roots);
    for (int i = 0; i < n; ++i) {
        double t = roots[i];
        Vec2 db = b.deriv_at(t);
        double sin_angle = std::fabs(r.cross(db)) / std::sqrt(r2 * db.length_squared());
        if (!(sin_angle >= kTangentSine)) {
            // A contact: prefer the critical point of g next to it (a simple root of g′).
            double best = t;
            for (int k = 0; k < n_crit; ++k)
                if (std::fabs(crit[k] - t) <= 1e-6 && std::fabs(g_at(crit[k])) <= tol) best = crit[k];
            double s = param_on_line(best);
            if (in_range(s)) push(raw, s, best, Source::Tangent, swapped);
            continue;
        }
        double s = param_on_line(t);
        if (!in_range(s)) continue;
        double ps = s, pt = t;
        if (newton_cross(line, b, ps, pt, 0.0, 1.0, 0.0, 1.0, kParamSlack)) s = ps, t = pt;
        push(raw, s, t, Source::Newton, swapped);
    }
    // Near misses within the touch tolerance: a minimum of |g| that no root reported.
    for (int k = 0; k < n_crit; ++k) {
        double t = crit[k];
        if (std::fabs(g_at(t)) > tol) continue;
        double s = param_on_line(t);
        if (in_range(s)) push(raw, s, t, Source::Tangent, swapped);
    }
}

void point_curve(Point p, const Curve& b, Raw& raw, bool swapped) {
    double ts[3];
    int n = point_on_curve(p, b, kTouch, ts);
    for (int i = 0; i < n; ++i) push(raw, 0.0, ts[i], Source::Endpoint, swapped);
}

}  // namespace bezel::isect
