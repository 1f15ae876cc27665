// tests/support/shapes.hpp — simple closed shapes that raster tests fill.
#pragma once

#include "bezel/path.hpp"

namespace bezel::test {

// Appends the rectangle [x0, x1] × [y0, y1] as one closed contour.
inline void add_rect(Path& p, double x0, double y0, double x1, double y1) {
    p.move_to({x0, y0});
    p.line_to({x1, y0});
    p.line_to({x1, y1});
    p.line_to({x0, y1});
    p.close();
}

// Appends a circle as four cubic quarter arcs, k = 4/3·(√2 − 1)·r (radial error ≈ 2.7e-4·r).
inline void add_circle(Path& p, Point c, double r) {
    const double k = 0.5522847498 * r;
    p.move_to({c.x + r, c.y});
    p.cubic_to({c.x + r, c.y + k}, {c.x + k, c.y + r}, {c.x, c.y + r});
    p.cubic_to({c.x - k, c.y + r}, {c.x - r, c.y + k}, {c.x - r, c.y});
    p.cubic_to({c.x - r, c.y - k}, {c.x - k, c.y - r}, {c.x, c.y - r});
    p.cubic_to({c.x + k, c.y - r}, {c.x + r, c.y - k}, {c.x + r, c.y});
    p.close();
}

}  // namespace bezel::test
