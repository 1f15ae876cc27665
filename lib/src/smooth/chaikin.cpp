// Chaikin corner cutting and its limit curve, the uniform quadratic B-spline.
//
// Why the limit is the quadratic B-spline: one round of Chaikin is exactly the knot-doubling
// refinement of a uniform quadratic B-spline's control polygon (Lane–Riesenfeld, degree 2), so
// every round's polygon is a control polygon of the same curve, and control polygons converge to
// their curve. The distance shrinks 4× per round: a polygon vertex Pᵢ is |Pᵢ₋₁ − 2Pᵢ + Pᵢ₊₁|/8
// from the curve point of its piece's middle, and a round divides second differences by 4.
#include <cstddef>

#include "bezel/smooth.hpp"
#include "smooth/input.hpp"

namespace bezel {

using smooth_detail::method_error;
using smooth_detail::prepare_points;

namespace {

constexpr const char* kChaikin = "chaikin";
constexpr const char* kChaikinLimit = "chaikin limit";

// Output size after `iterations` rounds, or 0 when it would exceed kMaxChaikinOutputPoints.
// Closed: n·2^k. Open: (n−1) edges double each round, 2(n−1)·2^(k−1) cut points, plus the two
// ends when kept.
std::size_t chaikin_output_size(std::size_t n, int iterations, const ChaikinOptions& options) {
    std::size_t count = n;
    for (int k = 0; k < iterations; ++k) {
        std::size_t edges = options.closed ? count : count - 1;
        std::size_t ends = (!options.closed && options.keep_ends) ? 2 : 0;
        if (edges > (kMaxChaikinOutputPoints - ends) / 2) return 0;
        count = 2 * edges + ends;
    }
    return count;
}

void chaikin_round(const std::vector<Point>& in, const ChaikinOptions& options,
                   std::vector<Point>& out) {
    out.clear();
    const std::size_t n = in.size();
    const std::size_t edges = options.closed ? n : n - 1;
    const bool keep = !options.closed && options.keep_ends;
    if (keep) out.push_back(in.front());
    for (std::size_t i = 0; i < edges; ++i) {
        Point a = in[i], b = in[(i + 1) % n];
        out.push_back(lerp(a, b, 0.25));  // ¾a + ¼b
        out.push_back(lerp(a, b, 0.75));  // ¼a + ¾b
    }
    if (keep) out.push_back(in.back());
}

}  // namespace

Expected<std::vector<Point>> chaikin(const std::vector<Point>& points, int iterations,
                                     const ChaikinOptions& options) {
    if (iterations < 0 || iterations > kMaxChaikinIterations)
        return method_error(kChaikin, "iterations " + std::to_string(iterations) +
                                          " out of range 0.." +
                                          std::to_string(kMaxChaikinIterations));
    auto prepared = prepare_points(kChaikin, points, options.closed, 2, 3);
    if (!prepared) return prepared.error();
    std::vector<Point> cur = std::move(*prepared);
    std::size_t final_size = chaikin_output_size(cur.size(), iterations, options);
    if (final_size == 0)
        return method_error(kChaikin, std::to_string(cur.size()) + " points cut " +
                                          std::to_string(iterations) +
                                          " times would give more than " +
                                          std::to_string(kMaxChaikinOutputPoints) + " points");
    std::vector<Point> next;
    next.reserve(final_size);
    cur.reserve(final_size);
    for (int k = 0; k < iterations; ++k) {
        chaikin_round(cur, options, next);
        cur.swap(next);
    }
    return cur;
}

Expected<Path> chaikin_limit(const std::vector<Point>& points, const ChaikinOptions& options) {
    const bool doubled_ends = !options.closed && options.keep_ends;
    auto prepared = prepare_points(kChaikinLimit, points, options.closed, doubled_ends ? 2 : 3, 3);
    if (!prepared) return prepared.error();
    std::vector<Point> p = std::move(*prepared);
    if (doubled_ends) {
        // Cutting with kept ends = cutting the polygon with each end doubled (see smooth.hpp).
        p.insert(p.begin(), p.front());
        p.push_back(p.back());
    }
    const std::size_t n = p.size();
    auto mid = [&](std::size_t i) { return lerp(p[i % n], p[(i + 1) % n], 0.5); };

    // Piece i: the quadratic with control point Pᵢ between the midpoints of its two edges.
    Path path;
    if (options.closed) {
        const Point start = mid(n - 1);
        path.move_to(start);
        for (std::size_t i = 0; i + 1 < n; ++i) path.quad_to(p[i], mid(i));
        path.quad_to(p[n - 1], start);  // ends exactly where it began
        path.close();
    } else {
        path.move_to(mid(0));
        for (std::size_t i = 1; i + 1 < n; ++i) path.quad_to(p[i], mid(i));
    }
    return path;
}

}  // namespace bezel
