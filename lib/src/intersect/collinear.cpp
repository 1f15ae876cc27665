// Curves lying on one common line (within kTouch): a one-dimensional problem.
//
// Along the line's unit direction r̂ each curve is the scalar Bézier x(t) = (C(t) − O)·r̂ with
// control values (Pᵢ − O)·r̂. A cubic "that is really a line" need not be monotone: it can run
// ahead, stop and come back. So each curve is cut at the roots of x′(t) into monotone pieces;
// two monotone pieces share the x-interval [max of lows, min of highs]. When that is longer than
// kTouch the pieces overlap there, and each end is mapped back to a parameter by inverting the
// monotone x(t) (bisection: certain, and exact at the piece ends). When it is a single point
// (within kTouch) they touch there: an endpoint meeting, or a fold of one touching the other.
#include <algorithm>
#include <cmath>

#include "intersect/curve_ops.hpp"

namespace bezel::isect {

namespace {

struct Scalar {
    int n = 1;
    double x[4] = {};
    double eval(double t) const {  // 1D de Casteljau: exact at t = 0 and 1
        double v[4] = {x[0], x[1], x[2], x[3]};
        for (int k = n; k > 0; --k)
            for (int i = 0; i < k; ++i) v[i] = t < 0.5 ? v[i] + (v[i + 1] - v[i]) * t
                                                       : v[i + 1] - (v[i + 1] - v[i]) * (1.0 - t);
        return v[0];
    }
};

struct Mono {
    double t0, t1;  // parameter range
    double x0, x1;  // x at t0 and t1 (x0 ≤ x1 or x0 ≥ x1: monotone either way)
    double lo() const { return std::min(x0, x1); }
    double hi() const { return std::max(x0, x1); }
};

Scalar along(const Curve& c, Point o, Vec2 r) {
    Scalar s;
    s.n = c.degree;
    for (int i = 0; i <= c.degree; ++i) s.x[i] = (c.p[i] - o).dot(r);
    return s;
}

int monotone_pieces(const Scalar& f, Mono out[3]) {
    // x′ has control values n(xᵢ₊₁ − xᵢ); its roots in (0, 1) are the turning points.
    double d[3], coef[4], roots[3];
    for (int i = 0; i < f.n; ++i) d[i] = f.n * (f.x[i + 1] - f.x[i]);
    int nr = 0;
    if (f.n >= 2) {
        bernstein_to_power(d, f.n - 1, coef);
        nr = poly_roots_in(coef, 0.0, 1.0, roots);
    }
    double cuts[5];
    int nc = 0;
    cuts[nc++] = 0.0;
    for (int i = 0; i < nr; ++i)
        if (roots[i] > cuts[nc - 1] && roots[i] < 1.0) cuts[nc++] = roots[i];
    cuts[nc++] = 1.0;
    int m = 0;
    for (int i = 0; i + 1 < nc; ++i) out[m++] = {cuts[i], cuts[i + 1], f.eval(cuts[i]), f.eval(cuts[i + 1])};
    return m;
}

// The t in the monotone piece with f(t) = x (clamped to the piece's x-range).
double invert(const Scalar& f, const Mono& m, double x) {
    if (x == m.x0) return m.t0;
    if (x == m.x1) return m.t1;
    bool up = m.x1 > m.x0;
    if (up ? x <= m.x0 : x >= m.x0) return m.t0;
    if (up ? x >= m.x1 : x <= m.x1) return m.t1;
    if (f.n == 1) return (x - f.x[0]) / (f.x[1] - f.x[0]);  // a line: x(t) is linear
    double a = m.t0, b = m.t1;
    for (int i = 0; i < 80; ++i) {
        double c = 0.5 * (a + b);
        if (c <= a || c >= b) break;
        ((f.eval(c) < x) == up ? a : b) = c;
    }
    // The bracket is down to adjacent doubles: keep the one whose value is closer.
    return std::fabs(f.eval(a) - x) < std::fabs(f.eval(b) - x) ? a : b;
}

// Finds the line through the two farthest control points of a and b (whichever pair).
bool common_line(const Curve& a, const Curve& b, Point& o, Vec2& r) {
    Point pts[8];
    int n = 0;
    for (int i = 0; i <= a.degree; ++i) pts[n++] = a.p[i];
    for (int i = 0; i <= b.degree; ++i) pts[n++] = b.p[i];
    double best = 0.0;
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j) {
            double d = (pts[j] - pts[i]).length_squared();
            if (d > best) best = d, o = pts[i], r = pts[j] - pts[i];
        }
    if (best == 0.0) return false;
    r = r.normalized();
    return on_line(a, o, r, kTouch) && on_line(b, o, r, kTouch);
}

void pair_pieces(const Scalar& fa, const Mono& pa, const Scalar& fb, const Mono& pb, Raw& raw) {
    double lo = std::max(pa.lo(), pb.lo()), hi = std::min(pa.hi(), pb.hi());
    if (hi - lo > kTouch) {
        double sa = invert(fa, pa, lo), sb = invert(fa, pa, hi);
        double ta = invert(fb, pb, lo), tb = invert(fb, pb, hi);
        if (sa <= sb)
            raw.overlaps.push_back({sa, sb, ta, tb});
        else
            raw.overlaps.push_back({sb, sa, tb, ta});
    } else if (hi - lo >= -kTouch) {
        double x = 0.5 * (lo + hi);
        raw.hits.push_back({invert(fa, pa, x), invert(fb, pb, x), Source::Tangent});
    }
}

}  // namespace

bool collinear_pair(const Curve& a, const Curve& b, Raw& raw) {
    // Quick reject, the usual case: a curve bulging away from its own chord by more than the
    // tolerance is not straight. (|chord × (P − P₀)| > kTouch·|chord| with |chord| ≤ 4 here.)
    for (const Curve* c : {&a, &b}) {
        Vec2 chord = c->end() - c->start();
        for (int i = 1; i < c->degree; ++i)
            if (std::fabs(chord.cross(c->p[i] - c->p[0])) > 4.0 * kTouch) return false;
    }
    Point o;
    Vec2 r;
    if (!common_line(a, b, o, r)) return false;
    Scalar fa = along(a, o, r), fb = along(b, o, r);
    Mono ma[3], mb[3];
    int na = monotone_pieces(fa, ma), nb = monotone_pieces(fb, mb);
    for (int i = 0; i < na; ++i)
        for (int j = 0; j < nb; ++j) pair_pieces(fa, ma[i], fb, mb[j], raw);
    return true;
}

bool collinear_self(const Curve& c, Raw& raw) {
    Point o;
    Vec2 r;
    if (!common_line(c, c, o, r)) return false;
    Scalar f = along(c, o, r);
    Mono m[3];
    int n = monotone_pieces(f, m);
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j) {
            std::size_t before = raw.hits.size();
            pair_pieces(f, m[i], f, m[j], raw);
            // Neighbouring pieces meet at their shared turning point: not an intersection.
            if (raw.hits.size() > before && raw.hits.back().s == raw.hits.back().t) raw.hits.pop_back();
        }
    return true;
}

}  // namespace bezel::isect
