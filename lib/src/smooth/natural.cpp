// Natural (and periodic) C² interpolating cubic splines: the derivative system of smooth.hpp,
// solved in O(n), then one Hermite piece per interval.
//
// The interior equation comes from matching second derivatives at Cᵢ. A Hermite piece on an
// interval of length h with end values y₀, y₁ and end derivatives d₀, d₁ (in u) has
//     y″(start) = 6(y₁ − y₀)/h² − (4d₀ + 2d₁)/h,    y″(end) = −6(y₁ − y₀)/h² + (2d₀ + 4d₁)/h.
// Setting y″(end) of piece i−1 equal to y″(start) of piece i and multiplying by hᵢ₋₁hᵢ/2 gives
//     hᵢ·Dᵢ₋₁ + 2(hᵢ₋₁ + hᵢ)·Dᵢ + hᵢ₋₁·Dᵢ₊₁ = 3(hᵢ·Δᵢ₋₁/hᵢ₋₁ + hᵢ₋₁·Δᵢ/hᵢ),   Δᵢ = Cᵢ₊₁ − Cᵢ,
// and y″ = 0 at the open ends gives 2D₀ + D₁ = 3Δ₀/h₀, Dₘ₋₁ + 2Dₘ = 3Δₘ₋₁/hₘ₋₁.
#include <cstddef>

#include "bezel/bezier.hpp"
#include "bezel/smooth.hpp"
#include "smooth/input.hpp"
#include "smooth/tridiagonal.hpp"

namespace bezel {

using smooth_detail::format_point;
using smooth_detail::method_error;

namespace {
constexpr const char* kNatural = "natural spline";
}

Expected<Path> natural_spline(const std::vector<Point>& points,
                              const NaturalSplineOptions& options) {
    auto prepared = smooth_detail::prepare_points(kNatural, points, options.closed, 2, 3);
    if (!prepared) return prepared.error();
    const std::vector<Point>& c = *prepared;
    const std::size_t n = c.size();
    const bool closed = options.closed;
    // Intervals: i → i+1 for i < n−1, and n−1 → 0 when closed.
    const std::size_t intervals = closed ? n : n - 1;
    auto next = [&](std::size_t i) { return (i + 1) % n; };

    std::vector<double> h(intervals, 1.0);
    for (std::size_t i = 0; i < intervals; ++i) {
        Vec2 d = c[next(i)] - c[i];
        if (d == Vec2{})
            return method_error(kNatural, "points[" + std::to_string(i) + "] and points[" +
                                              std::to_string(next(i)) + "] are both " +
                                              format_point(c[i]) +
                                              "; remove the repeated point");
        if (options.param == SplineParam::ChordLength) h[i] = d.length();
    }
    auto delta = [&](std::size_t i) { return c[next(i)] - c[i]; };

    smooth_detail::Tridiagonal m;
    m.sub.assign(n, 0.0);
    m.diag.assign(n, 0.0);
    m.super.assign(n, 0.0);
    std::vector<Vec2> rhs(n);
    // Row i couples the interval before Cᵢ (length hp, "previous") and the one after (hn).
    for (std::size_t i = 0; i < n; ++i) {
        const bool has_prev = closed || i > 0;
        const bool has_next = closed || i + 1 < n;
        if (has_prev && has_next) {
            const std::size_t ip = (i + n - 1) % n;  // interval ending at Cᵢ
            const double hp = h[ip], hn = h[i];
            m.sub[i] = hn;
            m.diag[i] = 2.0 * (hp + hn);
            m.super[i] = hp;
            rhs[i] = (delta(ip) * (hn / hp) + delta(i) * (hp / hn)) * 3.0;
        } else if (has_next) {  // natural start: 2D₀ + D₁ = 3Δ₀/h₀
            m.diag[i] = 2.0;
            m.super[i] = 1.0;
            rhs[i] = delta(0) * (3.0 / h[0]);
        } else {  // natural end: Dₘ₋₁ + 2Dₘ = 3Δₘ₋₁/hₘ₋₁
            m.sub[i] = 1.0;
            m.diag[i] = 2.0;
            rhs[i] = delta(i - 1) * (3.0 / h[i - 1]);
        }
    }
    const bool solved = closed ? smooth_detail::solve_cyclic_tridiagonal(m, rhs)
                               : smooth_detail::solve_tridiagonal(m, rhs);
    // The matrix is strictly diagonally dominant, so this only fails on overflow: chord-length
    // ratios hᵢ/hᵢ₋₁ of ~1e300 (points 1e-300 apart next to points 1e0 apart).
    if (!solved)
        return method_error(kNatural, "the derivative system overflowed (the point spacing is "
                                      "too uneven)");
    const std::vector<Vec2>& d = rhs;

    Path path;
    path.move_to(c[0]);
    for (std::size_t i = 0; i < intervals; ++i) {
        const std::size_t j = next(i);
        // dQ/dt = h·dQ/du on a piece whose own t runs over an interval of u-length h.
        CubicBez piece = hermite_to_bezier(c[i], c[j], d[i] * h[i], d[j] * h[i]);
        path.cubic_to(piece.p1, piece.p2, c[j]);
    }
    if (closed) path.close();
    if (!path.is_finite())
        return method_error(kNatural, "a piece overflowed (the point spacing is too uneven)");
    return path;
}

}  // namespace bezel
