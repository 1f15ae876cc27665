// bezel/geometry.hpp — points, vectors, rectangles and affine maps: the value types every other
// module is written in.
//
// Coordinates are doubles. bezel paths and bitmaps have y pointing DOWN (as SVG and images do);
// fonts have y pointing up, and the font module flips them at its boundary.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#pragma GCC visibility push(default)  // the public API of libbezel.so (docs/architecture.md)
namespace bezel {

// A 2D vector or point. One type serves both (Point is an alias): the affine algebra of Bézier
// curves (Σ Bᵢ(t)·Pᵢ) is written most plainly when points can be scaled and summed.
struct Vec2 {
    double x = 0.0;
    double y = 0.0;

    constexpr Vec2() = default;
    constexpr Vec2(double x_, double y_) : x(x_), y(y_) {}

    constexpr Vec2 operator+(Vec2 o) const { return {x + o.x, y + o.y}; }
    constexpr Vec2 operator-(Vec2 o) const { return {x - o.x, y - o.y}; }
    constexpr Vec2 operator-() const { return {-x, -y}; }
    constexpr Vec2 operator*(double s) const { return {x * s, y * s}; }
    constexpr Vec2 operator/(double s) const { return {x / s, y / s}; }
    constexpr Vec2& operator+=(Vec2 o) { x += o.x; y += o.y; return *this; }
    constexpr Vec2& operator-=(Vec2 o) { x -= o.x; y -= o.y; return *this; }
    constexpr Vec2& operator*=(double s) { x *= s; y *= s; return *this; }
    constexpr bool operator==(Vec2 o) const { return x == o.x && y == o.y; }
    constexpr bool operator!=(Vec2 o) const { return !(*this == o); }

    constexpr double dot(Vec2 o) const { return x * o.x + y * o.y; }
    // z component of the 3D cross product: > 0 when `o` is counter-clockwise from *this in a
    // y-up frame (clockwise on screen, where y points down).
    constexpr double cross(Vec2 o) const { return x * o.y - y * o.x; }
    constexpr double length_squared() const { return x * x + y * y; }
    double length() const { return std::hypot(x, y); }
    // Unit vector in the same direction; the zero vector stays zero (no NaN).
    Vec2 normalized() const {
        double l = length();
        return l > 0.0 ? Vec2{x / l, y / l} : Vec2{};
    }
    // Rotated +90° in a y-up frame: (x, y) → (−y, x).
    constexpr Vec2 perp() const { return {-y, x}; }
    bool is_finite() const { return std::isfinite(x) && std::isfinite(y); }
};
using Point = Vec2;

constexpr Vec2 operator*(double s, Vec2 v) { return v * s; }

// Linear interpolation a + (b − a)·t. Exact at t = 0 and t = 1, and exact when a == b.
// Why two branches: the one-sided form a + (b − a)·1 can miss b (a = 1e20, b = 1 gives 0), so
// each half measures from its nearer end; de Casteljau's split points then land exactly on the
// control points at t = 0 and t = 1.
constexpr Vec2 lerp(Vec2 a, Vec2 b, double t) {
    if (t < 0.5) return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t};
    double u = 1.0 - t;  // exact for t in [0.5, 2] (Sterbenz), so t = 1 gives u = 0
    return {b.x - (b.x - a.x) * u, b.y - (b.y - a.y) * u};
}
inline double distance(Point a, Point b) { return (b - a).length(); }

// An axis-aligned rectangle [x0, x1] × [y0, y1]. `empty()` is the identity for `union_with`.
struct Rect {
    double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;

    constexpr Rect() = default;
    constexpr Rect(double x0_, double y0_, double x1_, double y1_)
        : x0(x0_), y0(y0_), x1(x1_), y1(y1_) {}
    static constexpr Rect from_points(Point a, Point b) {
        return {std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
    }
    // An "inverted" rectangle that contains nothing; union with anything gives that thing.
    static constexpr Rect empty() { return {HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL}; }

    constexpr bool is_empty() const { return !(x0 <= x1 && y0 <= y1); }
    constexpr double width() const { return x1 - x0; }
    constexpr double height() const { return y1 - y0; }
    constexpr Point center() const { return {(x0 + x1) * 0.5, (y0 + y1) * 0.5}; }
    constexpr bool contains(Point p) const { return p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1; }
    constexpr Rect union_with(const Rect& o) const {
        return {std::min(x0, o.x0), std::min(y0, o.y0), std::max(x1, o.x1), std::max(y1, o.y1)};
    }
    constexpr Rect union_with(Point p) const {
        return {std::min(x0, p.x), std::min(y0, p.y), std::max(x1, p.x), std::max(y1, p.y)};
    }
    constexpr Rect inflated(double d) const { return {x0 - d, y0 - d, x1 + d, y1 + d}; }
    constexpr bool operator==(const Rect& o) const {
        return x0 == o.x0 && y0 == o.y0 && x1 == o.x1 && y1 == o.y1;
    }
};

// An affine map, stored as the top two rows of a 3×3 matrix (SVG's and kurbo's convention):
//   x' = a·x + c·y + e
//   y' = b·x + d·y + f
// Composition `A * B` applies B first, then A.
struct Affine {
    double a = 1.0, b = 0.0, c = 0.0, d = 1.0, e = 0.0, f = 0.0;

    static constexpr Affine identity() { return {}; }
    static constexpr Affine translate(Vec2 t) { return {1, 0, 0, 1, t.x, t.y}; }
    static constexpr Affine scale(double s) { return {s, 0, 0, s, 0, 0}; }
    static constexpr Affine scale(double sx, double sy) { return {sx, 0, 0, sy, 0, 0}; }
    // Rotation by `radians`, counter-clockwise in a y-up frame (clockwise on a y-down screen).
    static Affine rotate(double radians) {
        double s = std::sin(radians), co = std::cos(radians);
        return {co, s, -s, co, 0, 0};
    }
    static constexpr Affine skew(double kx, double ky) { return {1, ky, kx, 1, 0, 0}; }

    constexpr Point operator*(Point p) const { return {a * p.x + c * p.y + e, b * p.x + d * p.y + f}; }
    // The linear part only: maps a vector (a difference of points), ignoring translation.
    constexpr Vec2 apply_vector(Vec2 v) const { return {a * v.x + c * v.y, b * v.x + d * v.y}; }
    constexpr Affine operator*(const Affine& o) const {
        return {a * o.a + c * o.b, b * o.a + d * o.b, a * o.c + c * o.d,
                b * o.c + d * o.d, a * o.e + c * o.f + e, b * o.e + d * o.f + f};
    }
    constexpr double determinant() const { return a * d - b * c; }
    // Precondition: determinant() != 0. The result is not finite otherwise.
    constexpr Affine inverse() const {
        double inv = 1.0 / determinant();
        return {d * inv, -b * inv, -c * inv, a * inv, (c * f - d * e) * inv, (b * e - a * f) * inv};
    }
    constexpr bool operator==(const Affine& o) const {
        return a == o.a && b == o.b && c == o.c && d == o.d && e == o.e && f == o.f;
    }
    bool is_finite() const {
        return std::isfinite(a) && std::isfinite(b) && std::isfinite(c) && std::isfinite(d) &&
               std::isfinite(e) && std::isfinite(f);
    }
};

// ---- Real roots of quadratics and cubics ------------------------------------------------------
//
// Contract shared by the solvers below:
// - They return the number of DISTINCT real roots written to `roots`, in increasing order.
// - Roots of magnitude above kMaxRootMagnitude are not reported (they only arise when the leading
//   coefficient is below ~2⁻³⁴⁰ of the largest one: such a polynomial is, to double precision,
//   of lower degree, and its other roots are still found).
// - An identically zero polynomial (every x is a root) reports 0 roots; so does any non-finite
//   coefficient. Neither case is an error for the callers (bounding boxes, intersections).
// - Scale-invariant: coefficients are first scaled by a power of two (exactly), so 1e-200 and
//   1e+200 inputs behave like unit ones.
// - Accuracy: a simple root is returned to within a few ulps (relative) of the exact root of the
//   given double coefficients. Roots closer together than about √ε·|root| (ε = 2⁻⁵²) cannot be
//   told apart from a double root once the coefficients are rounded, and are returned as one
//   root; a double root comes back with relative error ~√ε, a triple root ~∛ε — this is the
//   conditioning of the problem, not of the method.
inline constexpr double kMaxRootMagnitude = 0x1p340;  // ≈ 2.2e102

// Real roots of a·x² + b·x + c. Works for any a, including 0 (linear) and a tiny relative to b
// (one root goes to infinity; the other stays accurate). Method: Kahan's fma discriminant and the
// cancellation-free pair x₁ = q/a, x₂ = c/q with q = −(b + sign(b)·√Δ)/2 (the "citardauq" form).
int solve_quadratic(double a, double b, double c, double roots[2]);

// Real roots of a·x³ + b·x² + c·x + d, any a (a = 0 gives the quadratic's roots). Method:
// critical points from solve_quadratic split the line into monotone pieces, each searched by
// bracketed Newton iteration with bisection fallback (Yuksel, "High-Performance Polynomial Root
// Finding for Graphics", HPG 2022), so every root is polished to full precision and the work is
// bounded (at most 300 evaluations per root; 6–13 on average in tests, 63 at most seen).
int solve_cubic(double a, double b, double c, double d, double roots[3]);

// As above, keeping only roots in [t_min, t_max] (closed interval), still sorted and distinct.
int solve_quadratic_in(double a, double b, double c, double t_min, double t_max, double roots[2]);
int solve_cubic_in(double a, double b, double c, double d, double t_min, double t_max,
                   double roots[3]);

}  // namespace bezel
#pragma GCC visibility pop
