// Hermite curves from points and tangents, and the cardinal spline as its special case.
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>

#include "bezel/bezier.hpp"
#include "bezel/smooth.hpp"
#include "smooth/input.hpp"

namespace bezel {

using smooth_detail::method_error;

namespace {

// The tension in a message: "%g" (6 significant digits), not std::to_string's "%f".
std::string tension_text(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}
constexpr const char* kHermite = "hermite";
constexpr const char* kCardinal = "cardinal spline";
}  // namespace

Expected<Path> hermite(const std::vector<Point>& points, const std::vector<Vec2>& tangents,
                       bool closed) {
    if (tangents.size() != points.size())
        return method_error(kHermite, std::to_string(points.size()) + " points but " +
                                          std::to_string(tangents.size()) +
                                          " tangents; give one tangent per point");
    auto prepared = smooth_detail::prepare_points(kHermite, points, closed, 2, 3);
    if (!prepared) return prepared.error();
    const std::vector<Point>& p = *prepared;
    const std::size_t n = p.size();  // tangents beyond n belong to a dropped closing point
    for (std::size_t i = 0; i < n; ++i)
        if (auto ok = smooth_detail::check_vector(kHermite, "tangents", i, tangents[i]); !ok)
            return ok.error();

    Path path;
    path.move_to(p[0]);
    const std::size_t pieces = closed ? n : n - 1;
    for (std::size_t i = 0; i < pieces; ++i) {
        const std::size_t j = (i + 1) % n;
        const CubicBez c = hermite_to_bezier(p[i], p[j], tangents[i], tangents[j]);
        if (!c.is_finite())
            return method_error(kHermite, "piece " + std::to_string(i) +
                                              " overflowed (coordinates too large)");
        path.cubic_to(c.p1, c.p2, p[j]);
    }
    if (closed) path.close();
    return path;
}

Expected<std::vector<Vec2>> cardinal_tangents(const std::vector<Point>& points, double tension,
                                              bool closed) {
    if (!(std::isfinite(tension) && tension >= 0.0))
        return method_error(kCardinal,
                            "tension " + tension_text(tension) + " is not a finite number ≥ 0");
    auto prepared = smooth_detail::prepare_points(kCardinal, points, closed, 2, 3);
    if (!prepared) return prepared.error();
    const std::vector<Point>& p = *prepared;
    const std::size_t n = p.size();
    std::vector<Vec2> t(n);
    for (std::size_t i = 0; i < n; ++i) {
        // Neighbours, with reflected phantoms P₋₁ = 2P₀ − P₁ and Pₙ = 2Pₙ₋₁ − Pₙ₋₂ when open.
        const Point prev = closed ? p[(i + n - 1) % n] : (i == 0 ? p[0] * 2.0 - p[1] : p[i - 1]);
        const Point next = closed ? p[(i + 1) % n] : (i + 1 == n ? p[n - 1] * 2.0 - p[n - 2] : p[i + 1]);
        t[i] = (next - prev) * tension;
        // A finite τ can still overflow (τ = 1e308 times a span of 2): an error, like every
        // other overflow here, never an infinite tangent.
        if (!std::isfinite(t[i].x) || !std::isfinite(t[i].y))
            return method_error(kCardinal, "tension " + tension_text(tension) +
                                               " overflows the tangent at points[" +
                                               std::to_string(i) + "]");
    }
    return t;
}

Expected<Path> cardinal_spline(const std::vector<Point>& points, double tension, bool closed) {
    auto tangents = cardinal_tangents(points, tension, closed);
    if (!tangents) return tangents.error();
    std::vector<Point> p = points;
    if (closed && p.size() >= 2 && p.back() == p.front()) p.pop_back();
    return hermite(p, *tangents, closed);
}

}  // namespace bezel
