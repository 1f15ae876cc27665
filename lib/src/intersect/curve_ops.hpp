// Private to the intersect module: the working frame, tolerances in it, small curve operations
// on `Curve` (dispatching to Line/QuadBez/CubicBez), and the raw hit list the solvers fill.
#pragma once

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "bezel/intersect.hpp"

namespace bezel::isect {

// ---- Working frame ----------------------------------------------------------------------------
// Every solver works on curves moved to an exact local origin and scaled by an exact power of two
// so that the largest coordinate magnitude is in [0.5, 1). Exactness matters: a rounded
// translation of coordinates near 1e6 would move control points by ~1e-10, far more than the
// 1e-12 parameter accuracy promised. Per axis, the origin is the box's low end when every
// coordinate x satisfies o ≤ x ≤ 2o (same sign), so x − o is exact by Sterbenz's lemma; else 0.
// Tolerances below are absolute in this frame, i.e. relative to the scale of the input.
struct Frame {
    Vec2 origin;
    double scale = 1.0;  // a power of two; frame coordinates = (p − origin)·scale
    Curve to_frame(const Curve& c) const;
};
// The frame for curves a and b together (b may be the same curve). Precondition: finite.
Frame make_frame(const Curve& a, const Curve& b);

// Frame-space tolerances (coordinates have magnitude < 1).
inline constexpr double kTouch = kIntersectTouchTolerance;
inline constexpr double kOverlap = kIntersectOverlapTolerance;
// Parameter slack: roots computed this far outside [0, 1] are clamped and then validated by the
// endpoint snap (kept only if the endpoint really lies on the other curve).
inline constexpr double kParamSlack = 1e-9;
// A parameter this close to 0 or 1 is tried as the exact endpoint.
inline constexpr double kSnapParam = 1e-8;

// ---- Curve operations ---------------------------------------------------------------------------
Vec2 deriv2_at(const Curve& c, double t);
std::pair<Curve, Curve> split(const Curve& c, double t);
Curve subsegment(const Curve& c, double t0, double t1);
inline Rect control_box(const Curve& c) {
    Rect r = Rect::from_points(c.p[0], c.p[1]);
    for (int i = 2; i <= c.degree; ++i) r = r.union_with(c.p[i]);
    return r;
}
// Point and first derivative together, in Bernstein form with u = 1 − t:
//   C = u³P₀ + 3u²t·P₁ + 3ut²·P₂ + t³P₃,   C′ = 3[u²(P₁ − P₀) + 2ut(P₂ − P₁) + t²(P₃ − P₂)]
// (and the quadratic/linear analogues). For t in [0, 1] the weights are non-negative, so the
// error is a few ulps of the control points' magnitude — as de Casteljau — at a third of the
// cost; Newton's iterations, which evaluate the most, use it.
struct PointDeriv {
    Point p;
    Vec2 d;
};
inline PointDeriv eval_with_deriv(const Curve& c, double t) {
    const double u = 1.0 - t;
    const Point* q = c.p;
    switch (c.degree) {
        case 1: return {q[0] * u + q[1] * t, q[1] - q[0]};
        case 2:
            return {q[0] * (u * u) + q[1] * (2.0 * u * t) + q[2] * (t * t),
                    ((q[1] - q[0]) * u + (q[2] - q[1]) * t) * 2.0};
        default: {
            const double u2 = u * u, t2 = t * t, ut = u * t;
            return {q[0] * (u2 * u) + q[1] * (3.0 * u2 * t) + q[2] * (3.0 * u * t2) + q[3] * (t2 * t),
                    ((q[1] - q[0]) * u2 + (q[2] - q[1]) * (2.0 * ut) + (q[3] - q[2]) * t2) * 3.0};
        }
    }
}
// Largest distance of a control point from p[0]: 0 for a curve collapsed to a point.
double control_extent(const Curve& c);
// Power-basis coefficients of the scalar Bézier with control values v[0..n]:
// out[k] multiplies tᵏ (k = 0..3; unused ones 0).
void bernstein_to_power(const double* v, int n, double out[4]);
// Real roots in [lo, hi] of Σ out[k]·tᵏ (degree ≤ 3): via solve_cubic_in / solve_quadratic_in.
int poly_roots_in(const double c[4], double lo, double hi, double roots[3]);
// Parameter of the point on c nearest to p, by Newton from t, kept in [lo, hi].
double project(const Curve& c, Point p, double t, double lo, double hi);
// Every t in [0, 1] where c passes within `tol` of p (at most 3 for a cubic; closer ones merged).
int point_on_curve(Point p, const Curve& c, double tol, double ts[3]);

// ---- Raw results ----------------------------------------------------------------------------------
enum class Source : unsigned char { Newton, Tangent, Endpoint };
struct Hit {
    double s = 0.0, t = 0.0;
    Source source = Source::Newton;
};
struct Raw {
    std::vector<Hit> hits;
    std::vector<CurveOverlap> overlaps;
    std::size_t work = 0;  // sub-curve pairs examined (kMaxIntersectWork)
    bool over_budget = false;
};

// 2D Newton on A(s) = B(t) from (s, t). Succeeds when it converges to a point with s within
// [s_lo, s_hi] and t within [t_lo, t_hi] (each widened by `margin`).
bool newton_cross(const Curve& a, const Curve& b, double& s, double& t, double s_lo, double s_hi,
                  double t_lo, double t_hi, double margin);
// Newton on the tangency equations (A(s) − B(t))·B′(t) = 0, A′(s) × B′(t) = 0 from (s, t),
// staying within the box widened by `margin`. The root is a simple one when the curvatures at
// the contact differ, so convergence is quadratic there.
bool newton_tangent(const Curve& a, const Curve& b, double& s, double& t, double s_lo,
                    double s_hi, double t_lo, double t_hi, double margin);

// ---- Solvers (frame space; each appends to raw) -------------------------------------------------
// Both curves lie (within kTouch) on one line: overlaps of monotone pieces and touching points.
// Returns false when they are not collinear (nothing appended).
bool collinear_pair(const Curve& a, const Curve& b, Raw& raw);
// The same for one collinear curve folding over itself (pairs of its monotone pieces).
bool collinear_self(const Curve& c, Raw& raw);
// True when every control point of c is within tol of the line through p0 with direction r.
bool on_line(const Curve& c, Point p0, Vec2 r, double tol);
// A is a Line (degree 1), B any curve (not collinear with A).
void line_curve(const Curve& line, const Curve& b, Raw& raw, bool swapped);
// Point p (a collapsed curve) against b.
void point_curve(Point p, const Curve& b, Raw& raw, bool swapped);
// Looks for one coincident piece of two curves of degree ≥ 2; appends it and returns true.
bool find_overlap(const Curve& a, const Curve& b, CurveOverlap& out);
// Curve–curve by subdivision with the isolation test, Newton, and the tangent resolver. With
// `probe`, the first pair still not isolated at width kOverlapProbeWidth triggers find_overlap;
// if that finds one, it is stored in *probe, true is returned and raw's hits are meaningless.
bool curve_curve(const Curve& a, const Curve& b, Raw& raw, CurveOverlap* probe);
inline constexpr double kOverlapProbeWidth = 1.0 / 64;
// Clusters of unresolved leaf boxes (near tangencies): resolves them into hits.
struct Leaf {
    double s0, s1, t0, t1;
};
void resolve_leaves(const Curve& a, const Curve& b, std::vector<Leaf>& leaves, Raw& raw);

// Snaps near-endpoint parameters, adds exact endpoint coincidences, drops hits inside overlaps,
// merges duplicates and classifies; fills `out` with points evaluated on the ORIGINAL curve a.
void finish(const Curve& a, const Curve& b, const Curve& orig_a, Raw& raw,
            CurveIntersections& out);

}  // namespace bezel::isect
