// Catmull-Rom splines with uniform, centripetal and chordal knot spacing.
//
// Uniform (α = 0) pieces come straight from catmull_rom_to_bezier (the basis data of
// basis::catmull_rom). For α > 0 the knots are tⱼ₊₁ − tⱼ = |Pⱼ₊₁ − Pⱼ|^α and the tangent at P₁
// of the quadruple P₀..P₃ is the derivative of the Barry–Goldman pyramid at t₁:
//     m₁ = (P₁ − P₀)/(t₁ − t₀) − (P₂ − P₀)/(t₂ − t₀) + (P₂ − P₁)/(t₂ − t₁),
// (likewise m₂), and the piece is the Hermite segment with tangents 2τ·(t₂ − t₁)·m. For α = 0
// all spans are 1 and this is τ(P₂ − P₀), the uniform formula, which is how τ is defined for
// every α. Centripetal spacing (α = ½) is the one for which Yuksel et al. (2011) prove there is
// no cusp and no self-intersection within a piece.
#include <cmath>
#include <cstddef>

#include "bezel/bezier.hpp"
#include "bezel/smooth.hpp"
#include "smooth/input.hpp"

namespace bezel {

using smooth_detail::method_error;

namespace {

constexpr const char* kCatmullRom = "catmull-rom";

// Knot span between a and b: |b − a|^α. Callers have merged repeats, so a ≠ b and the span is
// positive (hypot does not underflow to 0 for distinct finite points, and pow of a positive
// number with α ≤ 1 stays positive).
double span(Point a, Point b, double alpha) { return std::pow(distance(a, b), alpha); }

// The non-uniform Catmull-Rom piece from p1 to p2.
CubicBez nonuniform_piece(Point p0, Point p1, Point p2, Point p3, double alpha, double tension) {
    const double d0 = span(p0, p1, alpha), d1 = span(p1, p2, alpha), d2 = span(p2, p3, alpha);
    const Vec2 m1 = (p1 - p0) / d0 - (p2 - p0) / (d0 + d1) + (p2 - p1) / d1;
    const Vec2 m2 = (p2 - p1) / d1 - (p3 - p1) / (d1 + d2) + (p3 - p2) / d2;
    const double scale = 2.0 * tension * d1;
    return hermite_to_bezier(p1, p2, m1 * scale, m2 * scale);
}

}  // namespace

Expected<Path> catmull_rom(const std::vector<Point>& points, const CatmullRomOptions& options) {
    if (!(options.alpha >= 0.0 && options.alpha <= 1.0))
        return method_error(kCatmullRom, "alpha " + std::to_string(options.alpha) +
                                             " out of range [0, 1] (0 uniform, 0.5 centripetal, "
                                             "1 chordal)");
    if (!(std::isfinite(options.tension) && options.tension >= 0.0))
        return method_error(kCatmullRom, "tension " + std::to_string(options.tension) +
                                             " is not a finite number ≥ 0");
    auto prepared = smooth_detail::prepare_points(kCatmullRom, points, options.closed, 2, 3);
    if (!prepared) return prepared.error();
    std::vector<Point> p = smooth_detail::merge_repeats(*prepared, options.closed);
    const std::size_t need = options.closed ? 3 : 2;
    if (p.size() < need)
        return method_error(kCatmullRom, std::to_string(p.size()) +
                                             " distinct points after merging repeats, at least " +
                                             std::to_string(need) + " needed");
    const std::size_t n = p.size();
    const bool closed = options.closed;
    // Neighbour i, with reflected phantom points past the ends of an open curve.
    auto at = [&](std::ptrdiff_t i) -> Point {
        const auto sn = static_cast<std::ptrdiff_t>(n);
        if (closed) return p[static_cast<std::size_t>(((i % sn) + sn) % sn)];
        if (i < 0) return p[0] * 2.0 - p[1];
        if (i >= sn) return p[n - 1] * 2.0 - p[n - 2];
        return p[static_cast<std::size_t>(i)];
    };

    const std::size_t pieces = closed ? n : n - 1;
    Path path;
    path.move_to(p[0]);
    for (std::size_t k = 0; k < pieces; ++k) {
        const auto i = static_cast<std::ptrdiff_t>(k);
        const Point p0 = at(i - 1), p1 = at(i), p2 = at(i + 1), p3 = at(i + 2);
        const CubicBez c = options.alpha == 0.0
                               ? catmull_rom_to_bezier(p0, p1, p2, p3, options.tension)
                               : nonuniform_piece(p0, p1, p2, p3, options.alpha, options.tension);
        if (!c.is_finite())
            return method_error(kCatmullRom, "piece " + std::to_string(k) +
                                                 " overflowed (coordinates too large)");
        path.cubic_to(c.p1, c.p2, p2);  // p2 itself, so the curve passes exactly through it
    }
    if (closed) path.close();
    return path;
}

}  // namespace bezel
