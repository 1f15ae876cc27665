// Line, QuadBez, CubicBez: the members that need more than a line of arithmetic (tangents at
// degenerate points, curvature, tight bounds) and the B-spline conversion. Arc length is in
// arclen.cpp; the inline members are in bezel/bezier.hpp.
#include "bezel/bezier.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bezel {

namespace {

// A derivative counts as zero when it is below this fraction of the curve's size (times the
// derivative's own scale factor n!/(n−k)!): coincident control points that differ by rounding
// noise then still count as coincident, and the tangent comes from the next derivative.
constexpr double kZeroDerivativeRel = 1e-12;

double size_of(const Rect& box) { return std::max(box.width(), box.height()); }

bool is_zero(Vec2 v, double tiny) { return !(v.length() > tiny); }

}  // namespace

// ---- Line ----------------------------------------------------------------------------------------

Vec2 Line::tangent(double /*t*/) const { return (p1 - p0).normalized(); }
Vec2 Line::normal(double t) const { return tangent(t).perp(); }

// ---- QuadBez ---------------------------------------------------------------------------------------

Vec2 QuadBez::tangent(double t) const {
    double size = size_of(control_box());
    if (!(size > 0.0)) return {};  // a point (or not finite)
    double tiny = kZeroDerivativeRel * size;
    Vec2 d1 = deriv_at(t);
    if (!is_zero(d1, 2.0 * tiny)) return d1.normalized();
    // Q′(t + h) = Q′(t) + h·Q″: with Q′(t) = 0 the direction just after t is +Q″, just before is −Q″.
    Vec2 d2 = deriv2();
    if (!is_zero(d2, 2.0 * tiny)) return (t < 1.0 ? d2 : -d2).normalized();
    return (p2 - p0).normalized();
}

Vec2 QuadBez::normal(double t) const { return tangent(t).perp(); }

double QuadBez::curvature(double t) const {
    Vec2 d1 = deriv_at(t);
    double l = d1.length();
    if (!(l > 0.0)) return 0.0;  // Q(t+h) = Q(t) + h²/2·Q″: locally straight
    // κ = (Q′ × Q″)/|Q′|³, written as ((Q′/|Q′|) × Q″)/|Q′|² to delay underflow.
    double k = (d1 / l).cross(deriv2()) / (l * l);
    return std::isfinite(k) ? k : 0.0;
}

Rect QuadBez::bounding_box() const {
    // Q′(t)/2 = (p1 − p0) + t·(p0 − 2p1 + p2): one linear equation per axis.
    Rect box = Rect::from_points(p0, p2);
    Vec2 a = p1 - p0, b = p0 - p1 * 2.0 + p2;
    double roots[2];
    int n = solve_quadratic_in(0.0, b.x, a.x, 0.0, 1.0, roots);
    for (int i = 0; i < n; ++i) box = box.union_with(eval(roots[i]));
    n = solve_quadratic_in(0.0, b.y, a.y, 0.0, 1.0, roots);
    for (int i = 0; i < n; ++i) box = box.union_with(eval(roots[i]));
    return box;
}

// ---- CubicBez --------------------------------------------------------------------------------------

Vec2 CubicBez::tangent(double t) const {
    double size = size_of(control_box());
    if (!(size > 0.0)) return {};
    double tiny = kZeroDerivativeRel * size;
    Vec2 d1 = deriv_at(t);
    if (!is_zero(d1, 3.0 * tiny)) return d1.normalized();
    // Taylor: C′(t + h) = C′(t) + h·C″(t) + h²/2·C‴. With C′(t) = 0 the direction just after t is
    // +C″(t) and just before it −C″(t); if C″(t) = 0 too, it is +C‴ on both sides.
    Vec2 d2 = deriv2_at(t);
    if (!is_zero(d2, 6.0 * tiny)) return (t < 1.0 ? d2 : -d2).normalized();
    Vec2 d3 = deriv3();
    if (!is_zero(d3, 6.0 * tiny)) return d3.normalized();
    return (p3 - p0).normalized();
}

Vec2 CubicBez::normal(double t) const { return tangent(t).perp(); }

double CubicBez::curvature(double t) const {
    Vec2 d1 = deriv_at(t), d2 = deriv2_at(t);
    double l = d1.length();
    if (l > 0.0) {
        double k = (d1 / l).cross(d2) / (l * l);
        if (std::isfinite(k)) return k;
    }
    // C′(t) = 0 (or |C′|² underflows). With h → 0 on either side, C′ ≈ ±h·C″ + h²/2·C‴ gives
    // C′ × C″ ≈ h²/2·(C″ × C‴) while |C′|³ ≈ |h|³·|C″|³, so κ → ±∞ with the sign of C″ × C‴;
    // when that cross product is 0 the curve is locally straight and κ → 0.
    double s = d2.cross(deriv3());
    if (s == 0.0 || !std::isfinite(s)) return 0.0;
    return std::copysign(std::numeric_limits<double>::infinity(), s);
}

Rect CubicBez::bounding_box() const {
    // C′(t)/3 = (1−t)²·A + 2t(1−t)·B + t²·C with A = p1 − p0, B = p2 − p1, C = p3 − p2;
    // in powers of t: (A − 2B + C)·t² + 2(B − A)·t + A. Its roots in [0, 1], per axis, are the
    // only interior places a coordinate can be extreme.
    Rect box = Rect::from_points(p0, p3);
    Vec2 A = p1 - p0, B = p2 - p1, C = p3 - p2;
    Vec2 qa = A - B * 2.0 + C, qb = (B - A) * 2.0;
    double roots[2];
    int n = solve_quadratic_in(qa.x, qb.x, A.x, 0.0, 1.0, roots);
    for (int i = 0; i < n; ++i) box = box.union_with(eval(roots[i]));
    n = solve_quadratic_in(qa.y, qb.y, A.y, 0.0, 1.0, roots);
    for (int i = 0; i < n; ++i) box = box.union_with(eval(roots[i]));
    return box;
}

// ---- Conversions -----------------------------------------------------------------------------------

CubicBez bspline_to_bezier(Point b0, Point b1, Point b2, Point b3) {
    const Point g[4] = {b0, b1, b2, b3};
    Point out[4];
    for (int row = 0; row < 4; ++row) {
        Point q{};
        for (int col = 0; col < 4; ++col) q += g[col] * basis::kBSplineToBezier.m[row][col];
        out[row] = q;
    }
    return {out[0], out[1], out[2], out[3]};
}

}  // namespace bezel
