// Private to the flatten module (and its tests): points of a polynomial curve at t = i/n by
// forward differencing, in a chosen float type so the tests can measure the drift of each.
//
// The curve is taken relative to its start, B(t) − P₀ = a·t³ + b·t² + c·t (power form; for a
// cubic a = P₃ − 3P₂ + 3P₁ − P₀, b = 3(P₂ − 2P₁ + P₀), c = 3(P₁ − P₀)). With h = 1/n the
// differences of f(t) = a·t³ + b·t² + c·t at step h are
//     Δf  = a·(3t²h + 3th² + h³) + b·(2th + h²) + c·h
//     Δ²f = a·(6th² + 6h³) + 2b·h²
//     Δ³f = 6a·h³                         (constant)
// and each next point costs three additions: f += Δf; Δf += Δ²f; Δ²f += Δ³f (one more, + P₀,
// puts it back in place; working relative to P₀ keeps the magnitudes, and so the rounding, at the
// curve's size rather than its position).
//
// Drift. Rounding errors made in Δ²f reach f summed twice, so in the worst case they grow as n³:
// |error| ≲ u·(|f| + n·|Δf| + n²·|Δ²f|)·n with u the unit roundoff. Re-seeding the differences
// from the exact polynomial every `run` steps caps n at `run`.
//
// Measured (flatten_test, FlattenForwardDifference.*), drift as a fraction of the tolerance for
// which Wang's formula picks n (random curved cubics, 10⁻³–10⁴ px):
//   double, pure:        n = 256: 8·10⁻¹⁰, 4096: 3·10⁻⁶, 65536: 1.3·10⁻²  (the n³ growth)
//   double, re-seeded:   n = 65536: 1.3·10⁻⁵
//   float,  pure:        n = 16: 10⁻⁴, 32: 1.3·10⁻³, 64: 8.6·10⁻³, 128: 5·10⁻², 1024: 34
// and in absolute terms float drift ≈ 0.3–0.5 · n·2⁻²⁴·(curve extent). So double is safe for every
// n up to kMaxSegmentsPerCurve (pure FD just inside the 1/64 reserve; re-seeded far inside), and
// float is safe only while n ≤ 64 — enough for glyph curves at text sizes, not for large ones.
#pragma once

#include <cstddef>

#include "bezel/geometry.hpp"

namespace bezel::flatten_detail {

// Steps between re-seeds in WangUniform. Glyph curves need far fewer steps, so there they are pure
// three-addition forward differencing; the re-seed only matters for huge curves, where it keeps the
// double drift near 10⁻⁵ of the tolerance (pure FD at n = 2^16 reaches 1.3·10⁻², measured).
inline constexpr std::size_t kForwardDifferenceRun = 1024;

// Power-form coefficients of B(t) − P₀ for a cubic (a quadratic has a = 0).
struct PowerCubic {
    Vec2 a, b, c;
};

// Calls emit(x, y) with B(i/n) − P₀ for i = 1 … n−1, computed by forward differencing in T,
// re-seeded from the exact polynomial (in double) every `run` steps (run = 0: never).
template <typename T, typename Emit>
void forward_difference(const PowerCubic& pc, std::size_t n, std::size_t run, Emit&& emit) {
    const double h = 1.0 / static_cast<double>(n);
    T fx = 0, fy = 0, dx = 0, dy = 0, ddx = 0, ddy = 0;
    const T dddx = static_cast<T>(6.0 * pc.a.x * h * h * h);
    const T dddy = static_cast<T>(6.0 * pc.a.y * h * h * h);
    auto seed = [&](double step) {
        double t = step * h, p = t * h, q = h * h;
        double k3 = 3.0 * t * p + 3.0 * t * q + q * h;  // 3t²h + 3th² + h³
        double k2 = 2.0 * p + q;                        // 2th + h²
        fx = static_cast<T>(((pc.a.x * t + pc.b.x) * t + pc.c.x) * t);
        fy = static_cast<T>(((pc.a.y * t + pc.b.y) * t + pc.c.y) * t);
        dx = static_cast<T>(pc.a.x * k3 + pc.b.x * k2 + pc.c.x * h);
        dy = static_cast<T>(pc.a.y * k3 + pc.b.y * k2 + pc.c.y * h);
        ddx = static_cast<T>(pc.a.x * (6.0 * t * q + 6.0 * q * h) + 2.0 * pc.b.x * q);
        ddy = static_cast<T>(pc.a.y * (6.0 * t * q + 6.0 * q * h) + 2.0 * pc.b.y * q);
    };
    seed(0.0);
    std::size_t until_seed = run == 0 ? n : run;  // a countdown, not i % run: no division per point
    for (std::size_t i = 1; i < n; ++i) {
        if (--until_seed == 0) {
            seed(static_cast<double>(i - 1));  // differences at t_{i−1}, then step as usual
            until_seed = run;
        }
        fx += dx; fy += dy;
        dx += ddx; dy += ddy;
        ddx += dddx; ddy += dddy;
        emit(fx, fy);
    }
}

}  // namespace bezel::flatten_detail
