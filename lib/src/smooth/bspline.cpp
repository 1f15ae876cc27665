// Uniform cubic B-splines as Bézier pieces.
//
// Piece j uses the de Boor points Bⱼ..Bⱼ₊₃ and becomes a Bézier cubic through
// bspline_to_bezier (basis::kBSplineToBezier). The Bézier points of a piece are convex
// combinations of its de Boor points (the matrix rows are non-negative and sum to 1), which is
// the convex-hull property; consecutive pieces share their joint point (B₁ + 4B₂ + B₃)/6.
#include <cstddef>

#include "bezel/bezier.hpp"
#include "bezel/smooth.hpp"
#include "smooth/input.hpp"

namespace bezel {

namespace {
constexpr const char* kBSpline = "b-spline";
}

Expected<Path> bspline(const std::vector<Point>& de_boor_points, const BSplineOptions& options) {
    const bool pinned = !options.closed && options.pin_ends;
    auto prepared =
        smooth_detail::prepare_points(kBSpline, de_boor_points, options.closed, pinned ? 2 : 4, 3);
    if (!prepared) return prepared.error();
    std::vector<Point> b = std::move(*prepared);
    if (pinned) {
        // Triple end points: B₀ = B₁ = B₂ = P makes the first joint (P + 4P + P)/6 = P.
        b.insert(b.begin(), 2, b.front());
        b.insert(b.end(), 2, b.back());
    }
    const std::size_t n = b.size();
    // Closed: n pieces, indices wrapping. Open: n − 3 pieces.
    const std::size_t pieces = options.closed ? n : n - 3;
    auto at = [&](std::size_t i) { return b[i % n]; };

    Path path;
    Point start{};
    for (std::size_t j = 0; j < pieces; ++j) {
        CubicBez c = bspline_to_bezier(at(j), at(j + 1), at(j + 2), at(j + 3));
        if (j == 0) {
            // A pinned curve starts exactly on the end point, not on its rounded 1/6 + 4/6 + 1/6.
            start = pinned ? b.front() : c.p0;
            path.move_to(start);
        }
        Point end = c.p3;
        if (options.closed && j + 1 == pieces) end = start;  // close exactly
        if (pinned && j + 1 == pieces) end = b.back();
        path.cubic_to(c.p1, c.p2, end);
    }
    if (options.closed) path.close();
    return path;
}

}  // namespace bezel
