// Private: the flattener fill_path uses for WangUniform — uniform steps, Wang's count, and
// ERROR-BALANCED vertices, written straight into a reused Polylines (no callbacks, no allocation
// once it has grown).
//
// Why balanced. A chord always cuts inside a convex arc, so plain flattening loses area on one
// side only and the coverage error is biased (the mean error at 12 px grows linearly with the
// tolerance). Take uniform steps h = 1/n with curve points Bᵢ and second differences
// Δ²ᵢ = Bᵢ₋₁ − 2Bᵢ + Bᵢ₊₁. For a quadratic Δ² is constant, and the arc over one chord bulges
// out from the chord midpoint by −Δ²/8 (a parabola: B(t) + B(t+h) − 2B(t+h/2) = Δ²/4 for the
// half step); the area between chord and parabola is 2/3 of base × height, i.e. the arc lies on
// average −Δ²/12 off the chord. So emitting Bᵢ − Δ²ᵢ/12 instead of Bᵢ puts each chord where the
// arc is ON AVERAGE: the signed area error per chord is zero (exact for a quadratic, O(h³) for a
// cubic), the two ends (kept on the curve, being shared with the neighbouring segments) are
// half-corrected. The distance bound improves too: vertices lie |Δ²|/12 off the curve and chord
// midpoints |Δ²|/8 − |Δ²|/12 = |Δ²|/24, against |Δ²|/8 for the plain polyline.
#pragma once

#include "raster/sse2.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "bezel/flatten.hpp"
#include "bezel/geometry.hpp"
#include "bezel/path.hpp"

namespace bezel::raster_detail {

// Appends the transformed, balanced flattening of `path` to `out` (same contour conventions as
// flatten(): implicit close, a lone move dropped). Uses n = ⌈√(d(d−1)·M / (8·tol))⌉ steps per
// curve (Wang's count, M the largest transformed second difference of the control points), so
// the polyline is within tol of the curve (within 2/3·tol for a quadratic). Returns false, with
// `out` in an unspecified state, when the input is outside its fast path: a control point not
// finite or beyond kMaxFlattenCoordinatePx after the transform, or a curve needing more than
// kMaxSegmentsPerCurve steps — the caller then uses flatten_checked, which reports those.
bool flatten_balanced(const Path& path, const Affine& m, double tol, Polylines& out);

// --- The walk itself, shared by flatten_balanced and the direct fill (direct_fill.cpp) ---------
//
// Points travel as packed (x, y) pairs (SSE2, every x86-64 CPU): each operation below is the
// IEEE operation the scalar formula names, done for both coordinates by one instruction, so the
// polyline is what the scalar code computes and the two routes share it bit for bit.

static_assert(sizeof(Point) == 2 * sizeof(double), "Point is loaded as a packed (x, y) pair");
struct V2 {
    __m128d v;  // (x, y)
    static V2 of(Point p) { return {_mm_loadu_pd(&p.x)}; }
    static V2 splat(double s) { return {_mm_set1_pd(s)}; }
    Point point() const {
        Point p;
        _mm_storeu_pd(&p.x, v);
        return p;
    }
};
inline V2 operator+(V2 a, V2 b) { return {_mm_add_pd(a.v, b.v)}; }
inline V2 operator-(V2 a, V2 b) { return {_mm_sub_pd(a.v, b.v)}; }
inline V2 operator*(V2 a, double s) { return {_mm_mul_pd(a.v, _mm_set1_pd(s))}; }
inline V2 operator*(double s, V2 a) { return a * s; }
inline V2 operator*(V2 a, V2 b) { return {_mm_mul_pd(a.v, b.v)}; }
// x² + y², as Vec2::length_squared.
inline double len2(V2 a) {
    const __m128d sq = _mm_mul_pd(a.v, a.v);
    return _mm_cvtsd_f64(_mm_add_sd(sq, _mm_unpackhi_pd(sq, sq)));
}

// Steps for a curve whose largest second difference has squared length dd2: Wang's
// n = ⌈√(d(d−1)·M / (8·tol))⌉ = ⌈s⌉, s = √(√dd2 · k), with k = d(d−1)/(8·tol) precomputed.
// Returns 0 past the cap (and for NaN).
// Glyph curves mostly need n ≤ 16, and there ⌈s⌉ is counted without a square root: s > i
// exactly when s⁴ = dd2·k² > i⁴, so n = 1 + #{i = 1..15 : dd2·k² > i⁴}, in two steps (n ≤ 8,
// then 9..16) of four compares each. That is a few independent compares instead of two
// dependent square roots at the head of every curve.
// The compares are packed, two per instruction, and their all-ones results summed as integers:
// a compare and a flag-to-integer move each, scalar, were the bulk of a curve's setup.
// Why two steps and not one up to 8: at 0.01 px a quarter circle of radius 3 px already takes
// 11 steps, and 40 % of Cantarell's cubics at 12 px (62 % at 24 px) need more than 8. Past 16,
// ⌈s⌉ is found by truncation.
// i⁴ for i = 1..16: s > i exactly when t = s⁴ > i⁴.
inline constexpr double kStepFourth[16] = {1.0,    16.0,    81.0,    256.0,   625.0,   1296.0,
                                           2401.0, 4096.0,  6561.0,  10000.0, 14641.0, 20736.0,
                                           28561.0, 38416.0, 50625.0, 65536.0};
// How many of the eight thresholds q[0..7] t exceeds.
inline int count_over(__m128d tt, const double* q) {
    const __m128i c01 = _mm_castpd_si128(_mm_cmpgt_pd(tt, _mm_loadu_pd(q)));
    const __m128i c23 = _mm_castpd_si128(_mm_cmpgt_pd(tt, _mm_loadu_pd(q + 2)));
    const __m128i c45 = _mm_castpd_si128(_mm_cmpgt_pd(tt, _mm_loadu_pd(q + 4)));
    const __m128i c67 = _mm_castpd_si128(_mm_cmpgt_pd(tt, _mm_loadu_pd(q + 6)));
    __m128i neg = _mm_add_epi64(_mm_add_epi64(c01, c23), _mm_add_epi64(c45, c67));
    neg = _mm_add_epi64(neg, _mm_unpackhi_epi64(neg, neg));  // −count in the low lane
    return -static_cast<int>(_mm_cvtsi128_si64(neg));
}
inline int wang_steps(double dd2, double k) {
    const double t = dd2 * (k * k);
    // In each range t exceeds every threshold below it and not its top one (8⁴, 16⁴).
    if (t <= kStepFourth[7]) return 1 + count_over(_mm_set1_pd(t), kStepFourth);
    if (t <= kStepFourth[15]) return 9 + count_over(_mm_set1_pd(t), kStepFourth + 8);
    const double s = std::sqrt(std::sqrt(dd2) * k);
    if (!(s <= static_cast<double>(kMaxSegmentsPerCurve))) return 0;
    const int i = static_cast<int>(s);  // ⌈s⌉: 0 ≤ s ≤ the cap here
    return i + (static_cast<double>(i) < s);
}

// h = 1/n and its powers for the forward differences, each as an (x, y) pair of equal values
// (the operands of the packed products, loaded whole). Small n (nearly every curve of a glyph)
// come from a table: the division would otherwise sit at the head of each curve's chain of
// dependent operations (measured: the hottest instruction of the walk at 12 px). The entry is
// read in place: returned by value, GCC copied the struct through the stack and splatted each
// power with a shuffle, ten instructions at the head of every curve.
struct StepPowers {
    // h, h·h, (h·h)·h and the second and third differences' factors 2·(h·h), 6·((h·h)·h),
    // each twice.
    alignas(16) double h[2], h2[2], h3[2], h2x2[2], h3x6[2];
    constexpr void set(int n) {
        const double s = 1.0 / n, s2 = s * s, s3 = s2 * s;
        h[0] = h[1] = s;
        h2[0] = h2[1] = s2;
        h3[0] = h3[1] = s3;
        h2x2[0] = h2x2[1] = 2.0 * s2;
        h3x6[0] = h3x6[1] = 6.0 * s3;
    }
    V2 vh() const { return {_mm_load_pd(h)}; }
    V2 vh2() const { return {_mm_load_pd(h2)}; }
    V2 vh3() const { return {_mm_load_pd(h3)}; }
    V2 vh2x2() const { return {_mm_load_pd(h2x2)}; }
    V2 vh3x6() const { return {_mm_load_pd(h3x6)}; }
};
inline constexpr int kStepTable = 64;
struct StepTable {
    StepPowers p[kStepTable + 1];
    constexpr StepTable() : p{} {
        for (int n = 1; n <= kStepTable; ++n) p[n].set(n);
    }
};
inline constexpr StepTable kStepPowers{};
// The powers for n ≥ 1: the table's entry, or `spare` filled in.
inline const StepPowers& step_powers(int n, StepPowers& spare) {
    if (n <= kStepTable) return kStepPowers.p[n];
    spare.set(n);
    return spare;
}
// A curve's n points go to the sink through emit(sink, n, body): when sink.reserve(n) says the
// sink has room for all n, through sink.line_reserved, which skips the per-point room test (and
// so the direct route's flush call inside the point loop, around which the compiler spilled
// the loop's values at every curve); otherwise through sink.line. `body(push)` calls push(p)
// for each point in order.
template <typename Sink, typename Body>
inline void emit(Sink& sink, int n, Body&& body) {
    if (sink.reserve(n))
        body([&sink](V2 p) { sink.line_reserved(p); });
    else
        body([&sink](V2 p) { sink.line(p); });
}

// Quadratic p0 p1 p2 in n uniform steps; sink.line(Bᵢ) for points 1..n (p0 is already out).
// B(t) = p0 + 2(p1−p0)t + (p0−2p1+p2)t²: forward differences with step h give the first
// difference d1 = 2(p1−p0)h + a h² at t = 0 and the constant second difference dd = 2a h².
// Each interior point Bᵢ is emitted as Bᵢ − dd/12 (dd is the same for every point).
template <typename Sink>
inline void balanced_quad(V2 p0, V2 p1, V2 p2, int n, Sink& sink) {
    emit(sink, n, [&](auto&& push) {
        if (n > 1) {
            StepPowers spare;
            const StepPowers& s = step_powers(n, spare);
            const V2 a = p0 - 2.0 * p1 + p2;
            const V2 b = 2.0 * (p1 - p0);
            V2 d1 = b * s.vh() + a * s.vh2();
            const V2 dd = a * s.vh2x2();
            const V2 shift = dd * (-1.0 / 12.0);
            V2 p = p0;
            for (int i = 1; i < n; ++i) {
                p = p + d1;
                d1 = d1 + dd;
                push(p + shift);
            }
        }
        push(p2);
    });
}

// Cubic in n uniform steps. B(t) = p0 + c1 t + c2 t² + c3 t³ with c1 = 3(p1−p0),
// c2 = 3(p0 − 2p1 + p2), c3 = p3 − p0 + 3(p1 − p2). Forward differences at t = 0, step h:
//   d1 = c1 h + c2 h² + c3 h³,  d2 = 2c2 h² + 6c3 h³,  d3 = 6c3 h³.
// The second difference CENTRED at point i (Bᵢ₋₁ − 2Bᵢ + Bᵢ₊₁) is the forward one of point i−1,
// which is d2 before it is advanced past point i.
template <typename Sink>
inline void balanced_cubic(V2 p0, V2 p1, V2 p2, V2 p3, int n, Sink& sink) {
    emit(sink, n, [&](auto&& push) {
        if (n > 1) {
            StepPowers spare;
            const StepPowers& s = step_powers(n, spare);
            const V2 c1 = 3.0 * (p1 - p0);
            const V2 c2 = 3.0 * (p0 - 2.0 * p1 + p2);
            const V2 c3 = (p3 - p0) + 3.0 * (p1 - p2);
            V2 d1 = c1 * s.vh() + c2 * s.vh2() + c3 * s.vh3();
            V2 d2 = c2 * s.vh2x2() + c3 * s.vh3x6();
            const V2 d3 = c3 * s.vh3x6();
            V2 p = p0;
            for (int i = 1; i < n; ++i) {
                p = p + d1;    // Bᵢ
                d1 = d1 + d2;  // Bᵢ₊₁ − Bᵢ; d2 is still Bᵢ₊₁ − 2Bᵢ + Bᵢ₋₁
                push(p + d2 * (-1.0 / 12.0));
                d2 = d2 + d3;
            }
        }
        push(p3);
    });
}

// Walks `verbs` over control points given by `point(i, p)` (a V2; false: refuse the point),
// calling
//   sink.move(p)   at each contour start,
//   sink.line(p)   for each flattened vertex after it (or, for a curve's n points after
//                  sink.reserve(n) returned true, sink.line_reserved(p)),
//   sink.close()   at each contour end (Close verb, the next Move, or the end of the path),
// with p a V2. Returns false, midway, when `point` refuses a point or a curve needs more than
// kMaxSegmentsPerCurve steps.
template <typename PointAt, typename Sink>
bool walk_balanced(const std::vector<Verb>& verbs, double tol, PointAt&& point, Sink& sink) {
    const double k2 = 2.0 / (8.0 * tol), k3 = 6.0 / (8.0 * tol);
    std::size_t pi = 0;
    bool open = false;
    V2 last = V2::splat(0.0);
    for (Verb v : verbs) {
        switch (v) {
            case Verb::Move: {
                if (open) sink.close();
                if (!point(pi++, last)) return false;
                sink.move(last);
                open = true;
                break;
            }
            case Verb::Line: {
                if (!point(pi++, last)) return false;
                sink.line(last);
                break;
            }
            case Verb::Quad: {
                V2 p1, p2;
                if (!point(pi, p1) || !point(pi + 1, p2)) return false;
                pi += 2;
                const int n = wang_steps(len2(last - 2.0 * p1 + p2), k2);
                if (n == 0) return false;
                balanced_quad(last, p1, p2, n, sink);
                last = p2;
                break;
            }
            case Verb::Cubic: {
                V2 p1, p2, p3;
                if (!point(pi, p1) || !point(pi + 1, p2) || !point(pi + 2, p3)) return false;
                pi += 3;
                const double dd = std::max(len2(last - 2.0 * p1 + p2), len2(p1 - 2.0 * p2 + p3));
                const int n = wang_steps(dd, k3);
                if (n == 0) return false;
                balanced_cubic(last, p1, p2, p3, n, sink);
                last = p3;
                break;
            }
            case Verb::Close:
                if (open) sink.close();
                open = false;
                break;
        }
    }
    if (open) sink.close();
    return true;
}

}  // namespace bezel::raster_detail
