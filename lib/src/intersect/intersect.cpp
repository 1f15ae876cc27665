// intersect() and self_intersect(): validation, the working frame, dispatch by type, and the
// handling of a detected overlap (the rest of the two curves is still searched).
#include <algorithm>
#include <cmath>

#include "intersect/curve_ops.hpp"

namespace bezel {

namespace isect {
namespace {

// Solves A against B (frame space), both not collapsed to a point and not collinear.
void curves_with_overlap(const Curve& a, const Curve& b, Raw& raw) {
    CurveOverlap ov;
    if (!curve_curve(a, b, raw, &ov)) return;
    raw.hits.clear();
    raw.overlaps.push_back(ov);
    // Outside the overlap the curves may still meet: the remainder of each (at most two pieces,
    // for the shared stretch ends where one of the curves ends) against the whole other. The
    // junctions with the overlap come back as hits at its ends, which finish() drops.
    const double tb0 = std::min(ov.t_b0, ov.t_b1), tb1 = std::max(ov.t_b0, ov.t_b1);
    const double eps = kTangentMergeParam;
    auto solve_piece = [&](bool piece_of_a, double lo, double hi) {
        Raw sub;
        if (piece_of_a)
            curve_curve(subsegment(a, lo, hi), b, sub, nullptr);
        else
            curve_curve(a, subsegment(b, lo, hi), sub, nullptr);
        raw.work += sub.work;
        raw.over_budget |= sub.over_budget;
        for (Hit h : sub.hits) {
            (piece_of_a ? h.s : h.t) = lo + (hi - lo) * (piece_of_a ? h.s : h.t);
            raw.hits.push_back(h);
        }
    };
    if (ov.t_a0 > eps) solve_piece(true, 0.0, ov.t_a0);
    if (ov.t_a1 < 1.0 - eps) solve_piece(true, ov.t_a1, 1.0);
    if (tb0 > eps) solve_piece(false, 0.0, tb0);
    if (tb1 < 1.0 - eps) solve_piece(false, tb1, 1.0);
}

void solve(const Curve& a, const Curve& b, Raw& raw) {
    const bool point_a = control_extent(a) <= kTouch, point_b = control_extent(b) <= kTouch;
    if (point_a && point_b) {
        if (distance(a.p[0], b.p[0]) <= kTouch) raw.hits.push_back({0.0, 0.0, Source::Endpoint});
        return;
    }
    if (point_a) return point_curve(a.p[0], b, raw, false);
    if (point_b) return point_curve(b.p[0], a, raw, true);
    if (collinear_pair(a, b, raw)) return;
    if (a.degree == 1) return line_curve(a, b, raw, false);
    if (b.degree == 1) return line_curve(b, a, raw, true);
    curves_with_overlap(a, b, raw);
}

// The double point of a cubic's loop. With C(t) = a·t³ + b·t² + c·t + d (power form),
//   C(s) − C(t) = (s − t)·[a(s² + st + t²) + b(s + t) + c],
// so a double point s ≠ t solves a(σ² − π) + b·σ + c = 0 with σ = s + t, π = s·t. Crossing
// with a eliminates π:  σ = −(a × c)/(a × b);  projecting on a gives π = σ² + a·(bσ + c)/|a|².
// s, t are then the roots of x² − σx + π (real and distinct only for a loop), polished by 2D
// Newton on C(s) = C(t).
void cubic_loop(const Curve& c, Raw& raw) {
    double vx[4], vy[4], px[4], py[4];
    for (int i = 0; i < 4; ++i) vx[i] = c.p[i].x, vy[i] = c.p[i].y;
    bernstein_to_power(vx, 3, px);
    bernstein_to_power(vy, 3, py);
    Vec2 a{px[3], py[3]}, b{px[2], py[2]}, cc{px[1], py[1]};
    double ab = a.cross(b);
    if (ab == 0.0 || a.length_squared() == 0.0) return;
    double sigma = -a.cross(cc) / ab;
    double pi = sigma * sigma + a.dot(b * sigma + cc) / a.length_squared();
    double disc = sigma * sigma - 4.0 * pi;
    if (!(disc > 0.0)) return;
    double root = std::sqrt(disc);
    double s = 0.5 * (sigma - root), t = 0.5 * (sigma + root);
    if (s > 1.0 + kParamSlack || t < -kParamSlack || s < -kParamSlack || t > 1.0 + kParamSlack)
        return;
    double ps = s, pt = t;
    if (newton_cross(c, c, ps, pt, 0.0, 1.0, 0.0, 1.0, kParamSlack) && pt - ps > kTangentMergeParam)
        s = ps, t = pt;
    s = std::clamp(s, 0.0, 1.0);
    t = std::clamp(t, 0.0, 1.0);
    // A loop closing exactly at an end (C(0) = C(t)): make that end exact.
    for (double* x : {&s, &t}) {
        double e = *x < 0.5 ? 0.0 : 1.0;
        if (std::fabs(*x - e) > kSnapParam) continue;
        double& other = x == &s ? t : s;
        Point p = c.eval(e);
        double o = project(c, p, other, 0.0, 1.0);
        if (distance(p, c.eval(o)) <= kTouch) *x = e, other = o;
    }
    if (t - s <= kTangentMergeParam) return;  // a cusp, not a loop
    if (distance(c.eval(s), c.eval(t)) > 2.0 * kTouch) return;
    raw.hits.push_back({s, t, Source::Newton});
}

Error non_finite(const char* which) {
    return Error{std::string("intersect: curve ") + which + " has a non-finite coordinate"};
}

}  // namespace
}  // namespace isect

Expected<CurveIntersections> intersect(const Curve& a, const Curve& b) {
    using namespace isect;
    if (!a.is_finite()) return non_finite("A");
    if (!b.is_finite()) return non_finite("B");
    Frame f = make_frame(a, b);
    Curve fa = f.to_frame(a), fb = f.to_frame(b);
    Raw raw;
    solve(fa, fb, raw);
    if (raw.over_budget)
        return Error{"intersect: more than " + std::to_string(kMaxIntersectWork) +
                     " sub-curve pairs (curves running within tolerance of each other?)"};
    CurveIntersections out;
    finish(fa, fb, a, raw, out);
    return out;
}

Expected<CurveIntersections> self_intersect(const Curve& c) {
    using namespace isect;
    if (!c.is_finite()) return non_finite("C");
    CurveIntersections out;
    Frame f = make_frame(c, c);
    Curve fc = f.to_frame(c);
    if (c.degree == 1 || control_extent(fc) <= kTouch) return out;
    Raw raw;
    if (!collinear_self(fc, raw)) {
        if (c.degree == 2) return out;
        cubic_loop(fc, raw);
    }
    for (const Hit& h : raw.hits) {
        CurveIntersection ci;
        ci.t_a = h.s;
        ci.t_b = h.t;
        ci.point = c.eval(h.s);
        bool end = h.s == 0.0 || h.s == 1.0 || h.t == 0.0 || h.t == 1.0;
        ci.kind = end ? IntersectionKind::Endpoint
                      : h.source == Source::Tangent ? IntersectionKind::Tangent
                                                    : IntersectionKind::Cross;
        out.points.push_back(ci);
    }
    // The contract's order (by t_a, then t_b) and no twins: the loop and the collinear fold each
    // give their hits in their own order, and on a fold at the precision limit (a 2^50 px cubic
    // doubling back within 70 px, a fuzzer's) both report.
    const auto by_t = [](const CurveIntersection& l, const CurveIntersection& r) {
        return l.t_a < r.t_a || (l.t_a == r.t_a && l.t_b < r.t_b);
    };
    std::sort(out.points.begin(), out.points.end(), by_t);
    out.points.erase(std::unique(out.points.begin(), out.points.end(),
                                 [](const CurveIntersection& l, const CurveIntersection& r) {
                                     return l.t_a == r.t_a && l.t_b == r.t_b;
                                 }),
                     out.points.end());
    out.overlaps = raw.overlaps;
    std::sort(out.overlaps.begin(), out.overlaps.end(),
              [](const CurveOverlap& l, const CurveOverlap& r) { return l.t_a0 < r.t_a0; });
    return out;
}

}  // namespace bezel
