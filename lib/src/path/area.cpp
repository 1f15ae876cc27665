// Signed area by Green's theorem, A = ½∮(x dy − y dx) = ½∮ B(t) × B′(t) dt, one closed form per
// piece. With × the 2D cross product (a × b = a.x·b.y − a.y·b.x), integrating the Bernstein
// products over [0, 1] gives:
//
//   line  P₀P₁:      ½ P₀×P₁
//   quad  P₀P₁P₂:    ⅓ (P₀×P₁ + P₁×P₂) + ⅙ P₀×P₂
//   cubic P₀…P₃:     (1/20)(6 P₀×P₁ + 3 P₀×P₂ + P₀×P₃ + 3 P₁×P₂ + 3 P₁×P₃ + 6 P₂×P₃)
//
// (each reduces to the line formula when the control points are evenly spaced on the chord).
// In y-down coordinates ½∮(x dy − y dx) is positive for a contour turning clockwise on screen.
//
// Each contour is implicitly closed by a line back to its start. We evaluate it in coordinates
// relative to that start: the area of a closed curve does not depend on the origin, the closing
// line then contributes ½ Pₙ×0 = 0, and the cross products are taken of small differences
// rather than of large absolute coordinates, which loses less to cancellation.
#include "bezel/path.hpp"

namespace bezel {

namespace {

double segment_area(const PathSeg& s, Point o) {
    Point p0 = s.p[0] - o, p1 = s.p[1] - o, p2 = s.p[2] - o, p3 = s.p[3] - o;
    switch (s.kind) {
        case SegKind::Line: return 0.5 * p0.cross(p1);
        case SegKind::Quad:
            return (p0.cross(p1) + p1.cross(p2)) * (1.0 / 3.0) + p0.cross(p2) * (1.0 / 6.0);
        case SegKind::Cubic:
            return (6.0 * p0.cross(p1) + 3.0 * p0.cross(p2) + p0.cross(p3) + 3.0 * p1.cross(p2) +
                    3.0 * p1.cross(p3) + 6.0 * p2.cross(p3)) *
                   (1.0 / 20.0);
    }
    return 0.0;
}

// Calls f(contour, area of one segment) for every segment. The first segment of a contour starts
// at the contour's Move point, which becomes the origin for the rest of that contour.
template <typename F>
void for_each_segment_area(const Path& path, F f) {
    Point origin;
    std::size_t contour = 0;
    bool first = true;
    for (const PathSeg& s : path.segments()) {
        if (first || s.contour != contour) {
            origin = s.p[0];
            contour = s.contour;
            first = false;
        }
        f(s.contour, segment_area(s, origin));
    }
}

}  // namespace

Winding winding_of_area(double signed_area) {
    if (signed_area > 0.0) return Winding::Clockwise;
    if (signed_area < 0.0) return Winding::CounterClockwise;
    return Winding::None;
}

double Path::signed_area() const {
    double total = 0.0;
    for_each_segment_area(*this, [&](std::size_t, double a) { total += a; });
    return total;
}

std::vector<double> Path::contour_areas() const {
    std::vector<double> out(contour_count(), 0.0);
    for_each_segment_area(*this, [&](std::size_t c, double a) { out[c] += a; });
    return out;
}

std::vector<Winding> Path::contour_windings() const {
    std::vector<double> areas = contour_areas();
    std::vector<Winding> out;
    out.reserve(areas.size());
    for (double a : areas) out.push_back(winding_of_area(a));
    return out;
}

}  // namespace bezel
