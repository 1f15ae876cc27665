// Curve (the public any-degree segment), the working frame, and the small numerical tools every
// intersection solver shares: projection of a point, point-on-curve, and two Newton iterations.
#include <algorithm>
#include <cassert>
#include <cmath>

#include "intersect/curve_ops.hpp"

namespace bezel {

Curve::Curve(const PathSeg& s) {
    switch (s.kind) {
        case SegKind::Line: degree = 1; break;
        case SegKind::Quad: degree = 2; break;
        case SegKind::Cubic: degree = 3; break;
    }
    for (int i = 0; i <= degree; ++i) p[i] = s.p[i];
}

Point Curve::eval(double t) const {
    switch (degree) {
        case 1: return Line{p[0], p[1]}.eval(t);
        case 2: return QuadBez{p[0], p[1], p[2]}.eval(t);
        default: return CubicBez{p[0], p[1], p[2], p[3]}.eval(t);
    }
}

Vec2 Curve::deriv_at(double t) const {
    switch (degree) {
        case 1: return p[1] - p[0];
        case 2: return QuadBez{p[0], p[1], p[2]}.deriv_at(t);
        default: return CubicBez{p[0], p[1], p[2], p[3]}.deriv_at(t);
    }
}

bool Curve::is_finite() const {
    for (int i = 0; i <= degree; ++i)
        if (!p[i].is_finite()) return false;
    return degree >= 1 && degree <= 3;
}

const char* intersection_kind_name(IntersectionKind kind) {
    switch (kind) {
        case IntersectionKind::Cross: return "cross";
        case IntersectionKind::Tangent: return "tangent";
        case IntersectionKind::Endpoint: return "endpoint";
    }
    return "cross";
}

namespace isect {

namespace {

// The exact origin for one axis (see Frame): the low end when all values share a sign and lie
// within a factor of two of each other, else 0.
double axis_origin(double lo, double hi) {
    if (lo > 0.0 && hi <= 2.0 * lo) return lo;
    if (hi < 0.0 && lo >= 2.0 * hi) return hi;
    return 0.0;
}

}  // namespace

Curve Frame::to_frame(const Curve& c) const {
    Curve r = c;
    for (int i = 0; i <= c.degree; ++i) r.p[i] = (c.p[i] - origin) * scale;
    return r;
}

Frame make_frame(const Curve& a, const Curve& b) {
    Rect box = control_box(a).union_with(control_box(b));
    Frame f;
    f.origin = {axis_origin(box.x0, box.x1), axis_origin(box.y0, box.y1)};
    double m = std::max({std::fabs(box.x0 - f.origin.x), std::fabs(box.x1 - f.origin.x),
                         std::fabs(box.y0 - f.origin.y), std::fabs(box.y1 - f.origin.y)});
    if (m > 0.0 && std::isfinite(m)) {
        int e = 0;
        std::frexp(m, &e);  // m = f·2ᵉ, f ∈ [0.5, 1)
        f.scale = std::ldexp(1.0, -e);
    }
    return f;
}

Vec2 deriv2_at(const Curve& c, double t) {
    switch (c.degree) {
        case 1: return {};
        case 2: return QuadBez{c.p[0], c.p[1], c.p[2]}.deriv2();
        default: return CubicBez{c.p[0], c.p[1], c.p[2], c.p[3]}.deriv2_at(t);
    }
}

std::pair<Curve, Curve> split(const Curve& c, double t) {
    switch (c.degree) {
        case 1: {
            auto [l, r] = Line{c.p[0], c.p[1]}.split(t);
            return {Curve(l), Curve(r)};
        }
        case 2: {
            auto [l, r] = QuadBez{c.p[0], c.p[1], c.p[2]}.split(t);
            return {Curve(l), Curve(r)};
        }
        default: {
            auto [l, r] = CubicBez{c.p[0], c.p[1], c.p[2], c.p[3]}.split(t);
            return {Curve(l), Curve(r)};
        }
    }
}

Curve subsegment(const Curve& c, double t0, double t1) {
    switch (c.degree) {
        case 1: return Line{c.p[0], c.p[1]}.subsegment(t0, t1);
        case 2: return QuadBez{c.p[0], c.p[1], c.p[2]}.subsegment(t0, t1);
        default: return CubicBez{c.p[0], c.p[1], c.p[2], c.p[3]}.subsegment(t0, t1);
    }
}

double control_extent(const Curve& c) {
    double m = 0.0;
    for (int i = 1; i <= c.degree; ++i) m = std::max(m, (c.p[i] - c.p[0]).length_squared());
    return std::sqrt(m);
}

void bernstein_to_power(const double* v, int n, double out[4]) {
    out[0] = out[1] = out[2] = out[3] = 0.0;
    switch (n) {
        case 1:  // v0 + (v1 − v0)t
            out[0] = v[0];
            out[1] = v[1] - v[0];
            break;
        case 2:  // v0 + 2(v1 − v0)t + (v0 − 2v1 + v2)t²
            out[0] = v[0];
            out[1] = 2.0 * (v[1] - v[0]);
            out[2] = v[0] - 2.0 * v[1] + v[2];
            break;
        default:  // the rows of basis::kBezier, lowest power first
            out[0] = v[0];
            out[1] = 3.0 * (v[1] - v[0]);
            out[2] = 3.0 * (v[0] - 2.0 * v[1] + v[2]);
            out[3] = v[3] - v[0] + 3.0 * (v[1] - v[2]);
            break;
    }
}

int poly_roots_in(const double c[4], double lo, double hi, double roots[3]) {
    if (c[3] != 0.0) return solve_cubic_in(c[3], c[2], c[1], c[0], lo, hi, roots);
    return solve_quadratic_in(c[2], c[1], c[0], lo, hi, roots);
}

double project(const Curve& c, Point p, double t, double lo, double hi) {
    // Newton on f(t) = ½|C(t) − p|²: f′ = (C − p)·C′, f″ = |C′|² + (C − p)·C″. Where f″ ≤ 0 (far
    // from the curve, on the concave side) the Gauss–Newton step with |C′|² alone still descends.
    for (int it = 0; it < 16; ++it) {
        Vec2 d = c.eval(t) - p;
        Vec2 d1 = c.deriv_at(t);
        double g = d.dot(d1);
        double h = d1.length_squared() + d.dot(deriv2_at(c, t));
        if (!(h > 0.0)) h = d1.length_squared();
        if (!(h > 0.0)) break;
        double nt = std::clamp(t - g / h, lo, hi);
        double step = std::fabs(nt - t);
        t = nt;
        if (step <= 1e-16) break;
    }
    return t;
}

int point_on_curve(Point p, const Curve& c, double tol, double ts[3]) {
    // Candidates: where each coordinate of C(t) equals p's (one of the two is a simple root
    // wherever C′ ≠ 0), then polished by projection and kept when within tol.
    double cand[6];
    int nc = 0;
    for (int axis = 0; axis < 2; ++axis) {
        double v[4], coef[4], r[3];
        for (int i = 0; i <= c.degree; ++i) v[i] = axis == 0 ? c.p[i].x - p.x : c.p[i].y - p.y;
        bernstein_to_power(v, c.degree, coef);
        int n = poly_roots_in(coef, -kParamSlack, 1.0 + kParamSlack, r);
        for (int i = 0; i < n; ++i) cand[nc++] = std::clamp(r[i], 0.0, 1.0);
    }
    // Endpoints too: a root of a double-root coordinate can be lost to rounding.
    double found[8];
    int nf = 0;
    auto consider = [&](double t) {
        t = project(c, p, t, 0.0, 1.0);
        if (distance(c.eval(t), p) > tol) return;
        for (int i = 0; i < nf; ++i)
            if (std::fabs(found[i] - t) <= kTangentMergeParam) return;
        found[nf++] = t;
    };
    if (c.p[0] == p) found[nf++] = 0.0;
    if (c.p[c.degree] == p) {
        bool dup = false;
        for (int i = 0; i < nf; ++i) dup |= found[i] == 1.0;
        if (!dup) found[nf++] = 1.0;
    }
    for (int i = 0; i < nc && nf < 8; ++i) consider(cand[i]);
    // Insertion sort (at most 8 entries; std::sort trips g++ 12's -Warray-bounds here).
    for (int i = 1; i < nf; ++i)
        for (int j = i; j > 0 && found[j] < found[j - 1]; --j) std::swap(found[j], found[j - 1]);
    int m = std::min(nf, 3);
    for (int i = 0; i < m; ++i) ts[i] = found[i];
    return m;
}

bool newton_cross(const Curve& a, const Curve& b, double& s, double& t, double s_lo, double s_hi,
                  double t_lo, double t_hi, double margin) {
    // Solve [A′ −B′]·[Δs Δt]ᵀ = B(t) − A(s) =: f by Cramer's rule, D = A′ × B′:
    //   Δs = (f × −B′)/(A′ × −B′) = (f × B′)/D,   Δt = (A′ × f)/(A′ × −B′) = −(A′ × f)/D.
    const double s_min = s_lo - margin, s_max = s_hi + margin;
    const double t_min = t_lo - margin, t_max = t_hi + margin;
    bool converging = false;
    for (int it = 0; it < 24; ++it) {
        PointDeriv ea = eval_with_deriv(a, s), eb = eval_with_deriv(b, t);
        Vec2 f = eb.p - ea.p, da = ea.d, db = eb.d;
        double det = da.cross(db);
        if (det == 0.0 || !std::isfinite(det)) return false;
        double ds = f.cross(db) / det;
        double dt = -da.cross(f) / det;
        s += ds;
        t += dt;
        // Far outside the box: the root (if any) is someone else's, or Newton is lost.
        double ws = s_hi - s_lo, wt = t_hi - t_lo;
        if (!(s >= s_lo - ws - margin && s <= s_hi + ws + margin && t >= t_lo - wt - margin &&
              t <= t_hi + wt + margin))
            return false;
        // Quadratic convergence: once a step is below 1e-9, the next one is at rounding level.
        if (std::fabs(ds) <= 1e-15 && std::fabs(dt) <= 1e-15) break;
        if (std::fabs(ds) <= 1e-9 && std::fabs(dt) <= 1e-9) converging = true;
        else if (converging) return false;  // it was not converging after all
        if (it == 23) return false;
    }
    return s >= s_min && s <= s_max && t >= t_min && t <= t_max;
}

bool newton_tangent(const Curve& a, const Curve& b, double& s, double& t, double s_lo,
                    double s_hi, double t_lo, double t_hi, double margin) {
    // F = [(A − B)·B′, A′ × B′]; Jacobian
    //   ∂F₁/∂s = A′·B′,   ∂F₁/∂t = −|B′|² + (A − B)·B″,
    //   ∂F₂/∂s = A″ × B′, ∂F₂/∂t = A′ × B″.
    // At a contact det J = λ²|B′|⁵(κ_B − κ_A) with A′ = λB′: a simple root unless the curvatures
    // are equal, where Newton degrades to linear convergence (hence the iteration budget).
    for (int it = 0; it < 60; ++it) {
        Vec2 d = a.eval(s) - b.eval(t);
        Vec2 da = a.deriv_at(s), db = b.deriv_at(t);
        Vec2 dda = deriv2_at(a, s), ddb = deriv2_at(b, t);
        double f1 = d.dot(db), f2 = da.cross(db);
        double j11 = da.dot(db), j12 = -db.length_squared() + d.dot(ddb);
        double j21 = dda.cross(db), j22 = da.cross(ddb);
        double det = j11 * j22 - j12 * j21;
        if (det == 0.0 || !std::isfinite(det)) return false;
        double ds = -(f1 * j22 - j12 * f2) / det;
        double dt = -(j11 * f2 - f1 * j21) / det;
        s += ds;
        t += dt;
        if (!(s >= s_lo - margin && s <= s_hi + margin && t >= t_lo - margin &&
              t <= t_hi + margin))
            return false;
        if (std::fabs(ds) <= 1e-15 && std::fabs(dt) <= 1e-15) return true;
    }
    return true;  // linear convergence at an equal-curvature contact: the caller checks distance
}

bool on_line(const Curve& c, Point p0, Vec2 r, double tol) {
    double len = r.length();
    if (len == 0.0) return false;
    for (int i = 0; i <= c.degree; ++i)
        if (std::fabs(r.cross(c.p[i] - p0)) > tol * len) return false;
    return true;
}

}  // namespace isect
}  // namespace bezel
