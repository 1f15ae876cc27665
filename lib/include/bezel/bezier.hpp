// bezel/bezier.hpp — Bézier curves of degree 1, 2, 3 and of general degree ≤ 16, the basis
// matrices of the common cubic splines, and conversions between them.
//
// A Bézier curve of degree n with control points P₀…Pₙ is
//     Q(t) = Σᵢ Bᵢ,ₙ(t)·Pᵢ,   Bᵢ,ₙ(t) = C(n,i)·tⁱ·(1−t)ⁿ⁻ⁱ,   t ∈ [0, 1]     (Bernstein form)
// It is evaluated three ways here, equal to rounding (tests hold them to 1e-12 for cubics):
// - de Casteljau: repeated linear interpolation of the control polygon (the `eval` members);
// - Bernstein: the sum above (`Bezier::eval_bernstein`);
// - matrix: Q(t) = T·M·G, T = [t³ t² t 1] (`basis::eval_matrix`, `Bezier::eval_matrix`).
//
// Parameters t outside [0, 1] extrapolate the polynomial; nothing here clamps t unless it says so.
// Coordinates are whatever the caller's are (bezel paths: y down). Where a sign depends on the
// orientation (normal, curvature) it is stated for a y-up frame; on a y-down screen it flips.
#pragma once

#include <cstddef>
#include <utility>

#include "bezel/expected.hpp"
#include "bezel/geometry.hpp"

#pragma GCC visibility push(default)  // the public API of libbezel.so (docs/architecture.md)
namespace bezel {

struct CubicBez;

// A straight segment, the Bézier curve of degree 1.
struct Line {
    Point p0, p1;

    constexpr Point eval(double t) const { return lerp(p0, p1, t); }
    // The hodograph of a line is the constant p1 − p0.
    constexpr Vec2 deriv() const { return p1 - p0; }
    constexpr Vec2 deriv_at(double /*t*/) const { return p1 - p0; }
    // Unit direction p0 → p1; the zero vector when p0 == p1 (a point has no direction).
    Vec2 tangent(double t) const;
    // tangent(t).perp(): +90° from the direction of travel in a y-up frame.
    Vec2 normal(double t) const;
    constexpr double curvature(double /*t*/) const { return 0.0; }
    constexpr std::pair<Line, Line> split(double t) const {
        Point m = eval(t);
        return {Line{p0, m}, Line{m, p1}};
    }
    constexpr Line subsegment(double t0, double t1) const { return {eval(t0), eval(t1)}; }
    constexpr Line reversed() const { return {p1, p0}; }
    constexpr Rect control_box() const { return Rect::from_points(p0, p1); }
    constexpr Rect bounding_box() const { return control_box(); }
    double length() const { return distance(p0, p1); }
    // Exact for a line; `accuracy` is accepted for a uniform curve interface.
    double arclen(double /*accuracy*/) const { return length(); }
    // t with |(p0→eval(t))| = s, clamped to [0, 1]; 0 for a zero-length line.
    double inv_arclen(double s, double accuracy) const;
    constexpr Line transformed(const Affine& m) const { return {m * p0, m * p1}; }
    bool is_finite() const { return p0.is_finite() && p1.is_finite(); }
    constexpr bool operator==(const Line& o) const { return p0 == o.p0 && p1 == o.p1; }
};

// The quadratic Bézier curve (TrueType outlines).
struct QuadBez {
    Point p0, p1, p2;

    // de Casteljau.
    constexpr Point eval(double t) const { return lerp(lerp(p0, p1, t), lerp(p1, p2, t), t); }
    // The hodograph: Q'(t) = 2(1−t)(p1−p0) + 2t(p2−p1), a line through these two vectors.
    constexpr Line deriv() const { return {(p1 - p0) * 2.0, (p2 - p1) * 2.0}; }
    constexpr Vec2 deriv_at(double t) const { return deriv().eval(t); }
    // Q''(t) = 2(p0 − 2p1 + p2), constant.
    constexpr Vec2 deriv2() const { return (p0 - p1 * 2.0 + p2) * 2.0; }
    // Unit tangent in the direction of increasing t. Where Q'(t) vanishes (p1 == p0 at t = 0,
    // p1 == p2 at t = 1, or the fold of a collinear quad) it uses the limit direction from the
    // next non-zero derivative (from the right for t < 1, from the left at t ≥ 1), then the
    // chord; a curve collapsed to a point gives the zero vector.
    Vec2 tangent(double t) const;
    Vec2 normal(double t) const;  // tangent(t).perp()
    // Signed curvature κ = (Q′ × Q″)/|Q′|³, > 0 turning counter-clockwise in a y-up frame, in
    // 1/length units. Where Q′ = 0 a quadratic is locally straight: returns 0.
    double curvature(double t) const;
    // de Casteljau at t: the two halves, meeting exactly at eval(t).
    constexpr std::pair<QuadBez, QuadBez> split(double t) const {
        Point a = lerp(p0, p1, t), b = lerp(p1, p2, t), m = lerp(a, b, t);
        return {QuadBez{p0, a, m}, QuadBez{m, b, p2}};
    }
    // The piece for t ∈ [t0, t1], reparametrised to [0, 1] (t0 > t1 gives it reversed). Its
    // control points are the blossom values f(t0,t0), f(t0,t1), f(t1,t1), each a de Casteljau
    // run with one parameter per level, so subsegment(0, 1) returns *this exactly.
    constexpr QuadBez subsegment(double t0, double t1) const {
        return {blossom(t0, t0), blossom(t0, t1), blossom(t1, t1)};
    }
    constexpr Point blossom(double u, double v) const {
        return lerp(lerp(p0, p1, u), lerp(p1, p2, u), v);
    }
    constexpr QuadBez reversed() const { return {p2, p1, p0}; }
    constexpr Rect control_box() const { return Rect::from_points(p0, p1).union_with(p2); }
    // The tight box: end points plus the interior extrema, where a component of Q′ vanishes.
    Rect bounding_box() const;
    // Arc length within `accuracy` (absolute, same units as the points; must be > 0 — values
    // below 1e-13 of the curve's size are raised to that). Adaptive Gauss–Legendre.
    double arclen(double accuracy) const;
    // t ∈ [0, 1] with |arclen of [0, t] − s| ≤ accuracy; s is clamped to [0, arclen].
    double inv_arclen(double s, double accuracy) const;
    // The same curve as a cubic, exactly (up to rounding of 2/3): degree elevation
    //   c1 = p0 + ⅔(p1 − p0),  c2 = p2 + ⅔(p1 − p2).
    constexpr CubicBez elevate() const;
    constexpr QuadBez transformed(const Affine& m) const { return {m * p0, m * p1, m * p2}; }
    bool is_finite() const { return p0.is_finite() && p1.is_finite() && p2.is_finite(); }
    constexpr bool operator==(const QuadBez& o) const {
        return p0 == o.p0 && p1 == o.p1 && p2 == o.p2;
    }
};

// The cubic Bézier curve (CFF outlines, SVG, the seed notes' Q(t) = T·M·G).
struct CubicBez {
    Point p0, p1, p2, p3;

    // de Casteljau.
    constexpr Point eval(double t) const {
        Point a = lerp(p0, p1, t), b = lerp(p1, p2, t), c = lerp(p2, p3, t);
        return lerp(lerp(a, b, t), lerp(b, c, t), t);
    }
    // The hodograph: C′(t) = 3·Σ Bᵢ,₂(t)·(pᵢ₊₁ − pᵢ). So C′(0) = 3(p1 − p0), C′(1) = 3(p3 − p2).
    constexpr QuadBez deriv() const { return {(p1 - p0) * 3.0, (p2 - p1) * 3.0, (p3 - p2) * 3.0}; }
    constexpr Vec2 deriv_at(double t) const { return deriv().eval(t); }
    // C″(t) = 6·[(1−t)(p0 − 2p1 + p2) + t(p1 − 2p2 + p3)]; C″(0) = 6(p0 − 2p1 + p2).
    constexpr Vec2 deriv2_at(double t) const { return deriv().deriv_at(t); }
    // C‴ = 6(p3 − 3p2 + 3p1 − p0), constant.
    constexpr Vec2 deriv3() const { return deriv().deriv2(); }
    // Unit tangent in the direction of increasing t; robust where C′(t) vanishes (p1 == p0 at
    // t = 0, p2 == p3 at t = 1, cusps): uses the limit direction from the next non-zero
    // derivative (from the right for t < 1, from the left at t ≥ 1), then the chord p3 − p0;
    // a curve collapsed to a point gives the zero vector. "Vanishes" means |C′| ≤ 1e-12 of the
    // control polygon's size, so rounding noise in coincident control points is ignored.
    Vec2 tangent(double t) const;
    Vec2 normal(double t) const;  // tangent(t).perp()
    // Signed curvature κ = (C′ × C″)/|C′|³, > 0 turning counter-clockwise in a y-up frame, in
    // 1/length units. Where C′ is exactly 0 (or |C′|³ underflows) it returns the limit: ±∞ with
    // the sign of C″ × C‴ at a cusp, 0 where the curve is locally straight.
    double curvature(double t) const;
    // de Casteljau at t: the two halves, meeting exactly at eval(t).
    constexpr std::pair<CubicBez, CubicBez> split(double t) const {
        Point a = lerp(p0, p1, t), b = lerp(p1, p2, t), c = lerp(p2, p3, t);
        Point ab = lerp(a, b, t), bc = lerp(b, c, t), m = lerp(ab, bc, t);
        return {CubicBez{p0, a, ab, m}, CubicBez{m, bc, c, p3}};
    }
    // The piece for t ∈ [t0, t1], reparametrised to [0, 1] (t0 > t1 gives it reversed). Control
    // points are the blossom values f(t0,t0,t0), f(t0,t0,t1), f(t0,t1,t1), f(t1,t1,t1): de
    // Casteljau with one parameter per level. subsegment(0, 1) returns *this exactly.
    constexpr CubicBez subsegment(double t0, double t1) const {
        return {blossom(t0, t0, t0), blossom(t0, t0, t1), blossom(t0, t1, t1),
                blossom(t1, t1, t1)};
    }
    // The polar form f(u, v, w): symmetric, multi-affine, f(t, t, t) = eval(t).
    constexpr Point blossom(double u, double v, double w) const {
        Point a = lerp(p0, p1, u), b = lerp(p1, p2, u), c = lerp(p2, p3, u);
        return lerp(lerp(a, b, v), lerp(b, c, v), w);
    }
    constexpr CubicBez reversed() const { return {p3, p2, p1, p0}; }
    constexpr Rect control_box() const {
        return Rect::from_points(p0, p1).union_with(p2).union_with(p3);
    }
    // The tight box: end points plus the interior extrema, where a component of C′ (a quadratic)
    // vanishes (solve_quadratic_in on (0, 1)).
    Rect bounding_box() const;
    // Arc length within `accuracy` (absolute, same units as the points; must be > 0 — values
    // below 1e-13 of the curve's size are raised to that). Adaptive Gauss–Legendre: 8- and
    // 16-point rules per piece, halving pieces whose two rules differ by more than their share.
    double arclen(double accuracy) const;
    // t ∈ [0, 1] with |arclen of [0, t] − s| ≤ accuracy; s is clamped to [0, arclen].
    double inv_arclen(double s, double accuracy) const;
    constexpr CubicBez transformed(const Affine& m) const {
        return {m * p0, m * p1, m * p2, m * p3};
    }
    bool is_finite() const {
        return p0.is_finite() && p1.is_finite() && p2.is_finite() && p3.is_finite();
    }
    constexpr bool operator==(const CubicBez& o) const {
        return p0 == o.p0 && p1 == o.p1 && p2 == o.p2 && p3 == o.p3;
    }
};

constexpr CubicBez QuadBez::elevate() const {
    return {p0, p0 + (p1 - p0) * (2.0 / 3.0), p2 + (p1 - p2) * (2.0 / 3.0), p2};
}

// ---- Basis matrices: Q(t) = T·M·G ----------------------------------------------------------------
//
// Row convention (the seed notes'): T is the ROW vector of powers, highest first,
//     T = [t³ t² t 1]  (cubic),  T = [t² t 1]  (quadratic),
// M is the basis matrix, m[row][col], rows matching T's powers, and G is the COLUMN of geometry
// (control points, or points and tangents for Hermite). Q(t) = Σ_col (Σ_row T[row]·m[row][col])·G[col]:
// T·M is the row of blending functions, one per geometry entry.
namespace basis {

struct Mat4 {
    double m[4][4];
};
struct Mat3 {
    double m[3][3];
};

constexpr Mat4 mul(const Mat4& a, const Mat4& b) {
    Mat4 r{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) r.m[i][j] += a.m[i][k] * b.m[k][j];
    return r;
}

// Cubic Bézier, G = [P0 P1 P2 P3]ᵀ: the Bernstein polynomials' power coefficients.
inline constexpr Mat4 kBezier = {{{-1, 3, -3, 1},  //
                                  {3, -6, 3, 0},
                                  {-3, 3, 0, 0},
                                  {1, 0, 0, 0}}};

// Quadratic Bézier, T = [t² t 1], G = [P0 P1 P2]ᵀ.
inline constexpr Mat3 kBezierQuad = {{{1, -2, 1},  //
                                      {-2, 2, 0},
                                      {1, 0, 0}}};

// Cubic Hermite, G = [P0 P1 T0 T1]ᵀ: end points and the derivatives dQ/dt at t = 0 and t = 1.
inline constexpr Mat4 kHermite = {{{2, -2, 1, 1},  //
                                   {-3, 3, -2, -1},
                                   {0, 0, 1, 0},
                                   {1, 0, 0, 0}}};

// Uniform cubic B-spline segment, G = [B0 B1 B2 B3]ᵀ (four consecutive de Boor points). C²
// between segments; it does not pass through its control points.
inline constexpr Mat4 kBSpline = {{{-1.0 / 6, 3.0 / 6, -3.0 / 6, 1.0 / 6},
                                   {3.0 / 6, -6.0 / 6, 3.0 / 6, 0},
                                   {-3.0 / 6, 0, 3.0 / 6, 0},
                                   {1.0 / 6, 4.0 / 6, 1.0 / 6, 0}}};

// The Bézier control points of a uniform B-spline segment: [P0..P3]ᵀ = S·[B0..B3]ᵀ with
//   P0 = (B0 + 4B1 + B2)/6,  P1 = (2B1 + B2)/3,  P2 = (B1 + 2B2)/3,  P3 = (B1 + 4B2 + B3)/6,
// so kBezier·kBSplineToBezier = kBSpline (tested).
inline constexpr Mat4 kBSplineToBezier = {{{1.0 / 6, 4.0 / 6, 1.0 / 6, 0},
                                           {0, 4.0 / 6, 2.0 / 6, 0},
                                           {0, 2.0 / 6, 4.0 / 6, 0},
                                           {0, 1.0 / 6, 4.0 / 6, 1.0 / 6}}};

// Cardinal (Catmull-Rom) spline segment from P1 to P2, G = [P0 P1 P2 P3]ᵀ, with tension τ as in
// the course notes: the tangent at P1 is τ·(P2 − P0) and at P2 is τ·(P3 − P1).
// τ = 0.5 is the standard Catmull-Rom spline; τ = 0 gives zero end tangents (a straight
// segment with flat ends); larger τ makes rounder, looser curves.
//   M = [ −τ   2−τ   τ−2    τ ]
//       [ 2τ   τ−3  3−2τ   −τ ]
//       [ −τ    0     τ     0 ]
//       [  0    1     0     0 ]
constexpr Mat4 catmull_rom(double tension) {
    double s = tension;
    return {{{-s, 2 - s, s - 2, s},  //
             {2 * s, s - 3, 3 - 2 * s, -s},
             {-s, 0, s, 0},
             {0, 1, 0, 0}}};
}

// Q(t) = T·M·G with T = [t³ t² t 1] (see the convention above).
constexpr Point eval_matrix(const Mat4& M, const Point (&G)[4], double t) {
    double T[4] = {t * t * t, t * t, t, 1.0};
    Point q{};
    for (int col = 0; col < 4; ++col) {
        double w = 0.0;
        for (int row = 0; row < 4; ++row) w += T[row] * M.m[row][col];
        q += G[col] * w;
    }
    return q;
}
// Q(t) = T·M·G with T = [t² t 1].
constexpr Point eval_matrix(const Mat3& M, const Point (&G)[3], double t) {
    double T[3] = {t * t, t, 1.0};
    Point q{};
    for (int col = 0; col < 3; ++col) {
        double w = 0.0;
        for (int row = 0; row < 3; ++row) w += T[row] * M.m[row][col];
        q += G[col] * w;
    }
    return q;
}

}  // namespace basis

// ---- Conversions to Bézier form --------------------------------------------------------------
// Each returns the cubic Bézier that traces exactly the same curve, with the same
// parametrisation, as the source segment's matrix form (to rounding).

// Hermite: end points p0, p1 and end derivatives t0 = Q′(0), t1 = Q′(1). Since C′(0) = 3(P1 − P0)
// and C′(1) = 3(P3 − P2): P1 = p0 + t0/3, P2 = p1 − t1/3.
constexpr CubicBez hermite_to_bezier(Point p0, Point p1, Vec2 t0, Vec2 t1) {
    return {p0, p0 + t0 / 3.0, p1 - t1 / 3.0, p1};
}
// Uniform cubic B-spline segment with de Boor points b0..b3 (kBSplineToBezier).
CubicBez bspline_to_bezier(Point b0, Point b1, Point b2, Point b3);
// Cardinal spline segment from p1 to p2 with neighbours p0, p3 and tension τ (see
// basis::catmull_rom): the Hermite segment with tangents τ(p2 − p0), τ(p3 − p1).
constexpr CubicBez catmull_rom_to_bezier(Point p0, Point p1, Point p2, Point p3, double tension) {
    return hermite_to_bezier(p1, p2, (p2 - p0) * tension, (p3 - p1) * tension);
}

// ---- General degree ----------------------------------------------------------------------------

// The Bernstein polynomial Bᵢ,ₙ(t) = C(n,i)·tⁱ·(1−t)ⁿ⁻ⁱ; 0 when i < 0, i > n or n < 0.
// Any n works; for n ≤ kMaxExactBinomial the coefficient C(n,i) is exact.
double bernstein(int n, int i, double t);

// Largest n for which every C(n, k) is an integer below 2⁵³, hence exact in a double.
inline constexpr int kMaxExactBinomial = 56;
// The binomial coefficient C(n, k) as a double (Pascal's rule, so exact for n ≤
// kMaxExactBinomial; the multiplicative formula beyond); 0 outside 0 ≤ k ≤ n.
double binomial(int n, int k);

// A Bézier curve of degree 0 ≤ n ≤ kMaxDegree with control points p[0..n]; fixed storage, no heap.
// Entries of p beyond `degree` are unused and kept zero.
struct Bezier {
    static constexpr int kMaxDegree = 16;

    int degree = 0;
    Point p[kMaxDegree + 1] = {};

    constexpr Bezier() = default;  // the degree-0 curve at the origin
    explicit constexpr Bezier(const Line& c) : degree(1) { p[0] = c.p0, p[1] = c.p1; }
    explicit constexpr Bezier(const QuadBez& c) : degree(2) { p[0] = c.p0, p[1] = c.p1, p[2] = c.p2; }
    explicit constexpr Bezier(const CubicBez& c) : degree(3) {
        p[0] = c.p0, p[1] = c.p1, p[2] = c.p2, p[3] = c.p3;
    }
    // From `count` control points (degree count − 1). Errors: count is 0 or above kMaxDegree + 1.
    static Expected<Bezier> from_points(const Point* points, std::size_t count);

    constexpr int point_count() const { return degree + 1; }

    // de Casteljau: n(n+1)/2 lerps, the most stable of the three.
    Point eval_de_casteljau(double t) const;
    Point eval(double t) const { return eval_de_casteljau(t); }
    // Σ Bᵢ,ₙ(t)·Pᵢ with the powers tⁱ, (1−t)ⁿ⁻ⁱ tabulated once per call.
    Point eval_bernstein(double t) const;
    // T·M·G with T = [tⁿ … t 1] and M the degree-n Bernstein-to-power matrix
    //   m[n−k][i] = (−1)^(k−i)·C(n,k)·C(k,i)   (k ≥ i, else 0),
    // built from binomials once for every degree (a constant table), then Horner in t. The power
    // basis is ill-conditioned at high degree (Σ|m| grows like 3ⁿ): for |P| ≤ 1 it agrees with
    // de Casteljau to ~2e-15 at n = 3, ~5e-13 at n = 8 and ~2e-9 at n = 16 (measured; tests
    // hold it to 4ε·3ⁿ). Use it to check the others, not to render.
    Point eval_matrix(double t) const;

    // The `order`-th derivative as a Bézier curve of degree n − order (order ≥ 0):
    //   Q′(t) = n·Σ Bᵢ,ₙ₋₁(t)·(Pᵢ₊₁ − Pᵢ).
    // Differentiating past degree 0 gives the zero curve of degree 0.
    Bezier deriv(int order = 1) const;
    Vec2 deriv_at(double t, int order = 1) const { return deriv(order).eval(t); }
    std::pair<Bezier, Bezier> split(double t) const;
    Bezier reversed() const;
    // Degree n + 1, same curve: Qᵢ = (i/(n+1))·Pᵢ₋₁ + (1 − i/(n+1))·Pᵢ.
    // Error when degree is already kMaxDegree.
    Expected<Bezier> elevate() const;
    Rect control_box() const;
    bool is_finite() const;
};

}  // namespace bezel
#pragma GCC visibility pop
