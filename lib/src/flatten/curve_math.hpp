// Private to the flatten module: the few Bézier operations the hot loops need, inline, plus the
// chord-distance bounds that both DistanceSubdivision and ParabolaIntegral's check rely on.
//
// Kept here rather than taken from bezier.hpp so the loops inline fully and the bounds sit next
// to their proofs.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "bezel/bezier.hpp"
#include "bezel/geometry.hpp"

namespace bezel::flatten_detail {

// de Casteljau at t = 1/2: the two halves share the midpoint, which is computed once so that the
// left half's end and the right half's start are the same double.
inline void split_half(const QuadBez& q, QuadBez& left, QuadBez& right) {
    Point a = (q.p0 + q.p1) * 0.5, b = (q.p1 + q.p2) * 0.5, m = (a + b) * 0.5;
    left = {q.p0, a, m};
    right = {m, b, q.p2};
}
inline void split_half(const CubicBez& c, CubicBez& left, CubicBez& right) {
    Point a = (c.p0 + c.p1) * 0.5, b = (c.p1 + c.p2) * 0.5, d = (c.p2 + c.p3) * 0.5;
    Point ab = (a + b) * 0.5, bd = (b + d) * 0.5, m = (ab + bd) * 0.5;
    left = {c.p0, a, ab, m};
    right = {m, bd, d, c.p3};
}

inline Point end_point(const QuadBez& q) { return q.p2; }
inline Point end_point(const CubicBez& c) { return c.p3; }

// Squared distance from p to the segment [a, b] (to a when a == b).
inline double distance_to_segment_squared(Point p, Point a, Point b) {
    Vec2 ab = b - a, ap = p - a;
    double len2 = ab.length_squared();
    if (!(len2 > 0.0)) return ap.length_squared();
    double s = std::clamp(ap.dot(ab) / len2, 0.0, 1.0);
    return (ap - ab * s).length_squared();
}

// Upper bound on the squared Hausdorff distance between a quadratic and its chord [p0, p2].
//
// Proof. Let L = ‖p2 − p0‖ and let x, y be the coordinates of p1 − p0 along and across the chord.
// The curve's offset from the chord line is B₁(t)·y with B₁ = 2t(1−t) ≤ 1/2, and its coordinate
// along the chord is 2t(1−t)·x + t²·L. If 0 ≤ x ≤ L that coordinate stays in [0, L] (a convex
// combination of 0, x and L), so every curve point lies within |y|/2 of the chord *segment* and,
// conversely, every chord point has a curve point with the same coordinate (continuity), at
// distance ≤ |y|/2. Otherwise fall back to the convex hull: the curve lies in the triangle
// p0 p1 p2, which lies within dist(p1, segment) of the segment, and the same continuity
// argument covers the other direction. The bound is exact (attained at t = 1/2) in the first case.
inline double quad_chord_bound_squared(Point p0, Point p1, Point p2) {
    Vec2 chord = p2 - p0, v = p1 - p0;
    double len2 = chord.length_squared();
    double along = v.dot(chord);
    if (len2 > 0.0 && along >= 0.0 && along <= len2) {
        double cross = chord.cross(v);
        return 0.25 * cross * cross / len2;  // (|y|/2)², y = cross / L
    }
    return distance_to_segment_squared(p1, p0, p2);
}

// Upper bound on the squared Hausdorff distance between a cubic and its chord [p0, p3].
//
// Proof, as for the quadratic: the offset from the chord line is B₁(t)·y₁ + B₂(t)·y₂ with
// B₁ + B₂ = 3t(1−t) ≤ 3/4, so |offset| ≤ (3/4)·max(|y₁|, |y₂|); when both inner control points
// project inside the chord the curve does too and the bound holds for the segment in both
// directions. Otherwise the convex hull gives max(dist(p1, seg), dist(p2, seg)).
inline double cubic_chord_bound_squared(Point p0, Point p1, Point p2, Point p3) {
    Vec2 chord = p3 - p0, v1 = p1 - p0, v2 = p2 - p0;
    double len2 = chord.length_squared();
    double a1 = v1.dot(chord), a2 = v2.dot(chord);
    if (len2 > 0.0 && a1 >= 0.0 && a1 <= len2 && a2 >= 0.0 && a2 <= len2) {
        double c1 = chord.cross(v1), c2 = chord.cross(v2);
        double c = std::max(c1 * c1, c2 * c2);
        return 0.5625 * c / len2;  // ((3/4)·max|y|)²
    }
    return std::max(distance_to_segment_squared(p1, p0, p3), distance_to_segment_squared(p2, p0, p3));
}

// A segment count from a real estimate: ≥ 1, ≤ limit, and NaN or ∞ become `limit` (a count that
// cannot be computed is treated as too large, never cast: casting NaN to an integer is undefined).
inline std::size_t clamp_count(double estimate, std::size_t limit) {
    if (!(estimate < static_cast<double>(limit))) return limit;
    if (!(estimate > 1.0)) return 1;
    return static_cast<std::size_t>(std::ceil(estimate));
}

}  // namespace bezel::flatten_detail
