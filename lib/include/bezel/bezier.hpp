// bezel/bezier.hpp — Bézier curves of degree 1, 2, 3 and general degree ≤ 16.
//
// SKELETON: the foundation issue's geometry work fills this in (evaluation three ways, derivatives,
// split/subsegment, bounds, elevation, basis conversion, roots, arc length). The member names
// below (p0..p3) are fixed: other modules use them.
#pragma once

#include "bezel/geometry.hpp"

namespace bezel {

struct Line {
    Point p0, p1;
    constexpr Point eval(double t) const { return lerp(p0, p1, t); }
};

struct QuadBez {
    Point p0, p1, p2;
    constexpr Point eval(double t) const {
        return lerp(lerp(p0, p1, t), lerp(p1, p2, t), t);
    }
};

struct CubicBez {
    Point p0, p1, p2, p3;
    constexpr Point eval(double t) const {
        Point a = lerp(p0, p1, t), b = lerp(p1, p2, t), c = lerp(p2, p3, t);
        return lerp(lerp(a, b, t), lerp(b, c, t), t);
    }
};

}  // namespace bezel
