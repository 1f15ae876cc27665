// Balanced uniform flattening for rendering; see render_flatten.hpp for the maths.
#include "raster/render_flatten.hpp"

#include <cmath>

namespace bezel::raster_detail {

namespace {

// Collects the walk into Polylines with flatten()'s conventions.
struct PolylineSink {
    Polylines& out;
    std::size_t contour_start = 0;
    Point first{};

    void move(V2 v) {
        const Point p = v.point();
        contour_start = out.points.size();
        out.points.push_back(p);
        first = p;
    }
    void line(V2 v) { out.points.push_back(v.point()); }
    bool reserve(int) { return false; }  // push_back tests for room anyway
    void line_reserved(V2 v) { line(v); }
    void close() {
        if (out.points.size() - contour_start < 2) {
            out.points.resize(contour_start);  // a lone move encloses nothing
            return;
        }
        if (out.points.back() == first) out.points.pop_back();  // closing is implicit
        out.contour_ends.push_back(out.points.size());
    }
};

}  // namespace

bool flatten_balanced(const Path& path, const Affine& m, double tol, Polylines& out) {
    const std::vector<Point>& pts = path.points();
    PolylineSink sink{out, out.points.size(), {}};
    return walk_balanced(path.verbs(), tol,
                         [&](std::size_t i, V2& v) {
                             const Point p = m * pts[i];
                             v = V2::of(p);
                             // Also false for NaN.
                             return std::fabs(p.x) <= kMaxFlattenCoordinatePx &&
                                    std::fabs(p.y) <= kMaxFlattenCoordinatePx;
                         },
                         sink);
}

}  // namespace bezel::raster_detail
