// bezel/path.hpp — paths made of contours of line, quadratic and cubic pieces.
//
// Coordinates are y DOWN (SVG's and bitmaps' convention). A path is stored as a verb list and a
// point list (one point per Line/Move, two per Quad, three per Cubic, none per Close), so it is a
// cheap value type: copying copies two vectors, and nothing else is hidden inside.
//
// SKELETON: the foundation issue's path work fills in the rest (segments, transform, bounds,
// reverse, area, SVG in/out). The builder calls below are fixed: other modules use them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "bezel/bezier.hpp"
#include "bezel/geometry.hpp"

namespace bezel {

enum class Verb : std::uint8_t { Move, Line, Quad, Cubic, Close };

class Path {
public:
    // Builder. A drawing call with no current contour starts one at the last point (or at (0,0)),
    // as SVG does. close() ends the contour; the next drawing call starts a new one at the same
    // start point.
    void move_to(Point p);
    void line_to(Point p);
    void quad_to(Point c, Point p);
    void cubic_to(Point c1, Point c2, Point p);
    void close();

    const std::vector<Verb>& verbs() const { return verbs_; }
    const std::vector<Point>& points() const { return points_; }
    bool empty() const { return verbs_.empty(); }
    void clear() { verbs_.clear(); points_.clear(); }

private:
    std::vector<Verb> verbs_;
    std::vector<Point> points_;
};

}  // namespace bezel
