// Circular arcs as cubics (round joins, round caps, dots), and copying paths.
#include <algorithm>
#include <cmath>

#include "stroke/stroke_internal.hpp"

namespace bezel::stroke_detail {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kMaxArcPieces = 1024;

// Radial error of the standard cubic for an arc of angle φ on the unit circle, handles of
// length k = 4/3·tan(φ/4) (Goldapp, "Approximation of circular arcs by cubic polynomials",
// CAGD 1991): e(φ) = (2/27)·sin⁶(φ/4) / cos²(φ/4) — 2.7e-4 for a quarter circle, shrinking as φ⁶.
double arc_error(double phi) {
    double s = std::sin(phi / 4), c = std::cos(phi / 4);
    return (2.0 / 27.0) * s * s * s * s * s * s / (c * c);
}

}  // namespace

void arc_to(Path& path, Point center, Vec2 from, Vec2 to, double r, double tol, Budget& budget) {
    double theta = std::atan2(from.cross(to), from.dot(to));
    Point end = center + to * r;
    if (!(std::fabs(theta) * r > 1e-3 * tol)) {  // shorter than anything the tolerance can see
        path.line_to(end);
        budget.take(1);
        return;
    }
    int n = std::max(1, static_cast<int>(std::ceil(std::fabs(theta) / (kPi / 2))));
    while (n < kMaxArcPieces && arc_error(std::fabs(theta) / n) * r > tol) n *= 2;
    n = std::min(n, kMaxArcPieces);
    if (!budget.take(static_cast<std::size_t>(n))) return;
    double phi = theta / n;
    double k = 4.0 / 3.0 * std::tan(phi / 4) * r;
    Vec2 side = from.perp();
    Vec2 u = from;
    for (int i = 1; i <= n; ++i) {
        double a = phi * i;
        Vec2 v = i == n ? to : from * std::cos(a) + side * std::sin(a);
        Point p0 = center + u * r, p3 = i == n ? end : center + v * r;
        path.cubic_to(p0 + u.perp() * k, p3 - v.perp() * k, p3);
        u = v;
    }
}

void append_path(Path& dst, const Path& src) {
    const auto& verbs = src.verbs();
    const auto& pts = src.points();
    std::size_t pi = 0;
    for (Verb v : verbs) {
        switch (v) {
            case Verb::Move: dst.move_to(pts[pi++]); break;
            case Verb::Line: dst.line_to(pts[pi++]); break;
            case Verb::Quad: dst.quad_to(pts[pi], pts[pi + 1]); pi += 2; break;
            case Verb::Cubic: dst.cubic_to(pts[pi], pts[pi + 1], pts[pi + 2]); pi += 3; break;
            case Verb::Close: dst.close(); break;
        }
    }
}

}  // namespace bezel::stroke_detail
