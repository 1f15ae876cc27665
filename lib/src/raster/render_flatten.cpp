// Balanced uniform flattening for rendering; see render_flatten.hpp for the maths.
#include "raster/render_flatten.hpp"

#include <cmath>

namespace bezel::raster_detail {

namespace {

inline bool in_range(Point p) {
    // Also false for NaN.
    return std::fabs(p.x) <= kMaxFlattenCoordinatePx && std::fabs(p.y) <= kMaxFlattenCoordinatePx;
}

// Steps for a curve whose largest second difference has squared length dd2: Wang's
// n = ⌈√(d(d−1)·M / (8·tol))⌉, with k = d(d−1)/(8·tol) precomputed. Returns 0 past the cap.
inline int wang_steps(double dd2, double k) {
    const double n = std::ceil(std::sqrt(std::sqrt(dd2) * k));
    if (!(n <= static_cast<double>(kMaxSegmentsPerCurve))) return 0;
    return n < 1.0 ? 1 : static_cast<int>(n);
}

inline double len2(Vec2 v) { return v.x * v.x + v.y * v.y; }

// Quadratic p0 p1 p2 in n uniform steps, points 1..n appended (p0 is already out).
// B(t) = p0 + 2(p1−p0)t + (p0−2p1+p2)t²: forward differences with step h give the first
// difference d1 = 2(p1−p0)h + a h² at t = 0 and the constant second difference dd = 2a h².
// Each interior point Bᵢ is emitted as Bᵢ − dd/12 (dd is the same for every point).
void quad(Point p0, Point p1, Point p2, int n, std::vector<Point>& out) {
    if (n == 1) {
        out.push_back(p2);
        return;
    }
    const double h = 1.0 / n;
    const Vec2 a = p0 - 2.0 * p1 + p2;
    const Vec2 b = 2.0 * (p1 - p0);
    Vec2 d1 = b * h + a * (h * h);
    const Vec2 dd = a * (2.0 * h * h);
    const Vec2 shift = dd * (-1.0 / 12.0);
    Point p = p0;
    for (int i = 1; i < n; ++i) {
        p = p + d1;
        d1 = d1 + dd;
        out.push_back(p + shift);
    }
    out.push_back(p2);
}

// Cubic in n uniform steps. B(t) = p0 + c1 t + c2 t² + c3 t³ with c1 = 3(p1−p0),
// c2 = 3(p0 − 2p1 + p2), c3 = p3 − p0 + 3(p1 − p2). Forward differences at t = 0, step h:
//   d1 = c1 h + c2 h² + c3 h³,  d2 = 2c2 h² + 6c3 h³,  d3 = 6c3 h³.
// The second difference CENTRED at point i (Bᵢ₋₁ − 2Bᵢ + Bᵢ₊₁) is the forward one of point i−1,
// which is d2 before it is advanced past point i.
void cubic(Point p0, Point p1, Point p2, Point p3, int n, std::vector<Point>& out) {
    if (n == 1) {
        out.push_back(p3);
        return;
    }
    const double h = 1.0 / n, h2 = h * h, h3 = h2 * h;
    const Vec2 c1 = 3.0 * (p1 - p0);
    const Vec2 c2 = 3.0 * (p0 - 2.0 * p1 + p2);
    const Vec2 c3 = (p3 - p0) + 3.0 * (p1 - p2);
    Vec2 d1 = c1 * h + c2 * h2 + c3 * h3;
    Vec2 d2 = c2 * (2.0 * h2) + c3 * (6.0 * h3);
    const Vec2 d3 = c3 * (6.0 * h3);
    Point p = p0;
    for (int i = 1; i < n; ++i) {
        p = p + d1;       // Bᵢ
        d1 = d1 + d2;     // Bᵢ₊₁ − Bᵢ; d2 is still Bᵢ₊₁ − 2Bᵢ + Bᵢ₋₁
        out.push_back(p + d2 * (-1.0 / 12.0));
        d2 = d2 + d3;
    }
    out.push_back(p3);
}

}  // namespace

bool flatten_balanced(const Path& path, const Affine& m, double tol, Polylines& out) {
    const std::vector<Point>& pts = path.points();
    const double k2 = 2.0 / (8.0 * tol), k3 = 6.0 / (8.0 * tol);
    std::size_t pi = 0;
    std::size_t contour_start = out.points.size();
    bool open = false;  // a Move has been emitted for the current contour
    Point first{}, last{};
    auto end_contour = [&] {
        if (!open) return;
        const std::size_t end = out.points.size();
        if (end - contour_start < 2) {
            out.points.resize(contour_start);  // a lone move encloses nothing
        } else {
            if (out.points.back() == first) out.points.pop_back();  // closing is implicit
            out.contour_ends.push_back(out.points.size());
        }
        open = false;
    };
    for (Verb v : path.verbs()) {
        switch (v) {
            case Verb::Move: {
                end_contour();
                const Point p = m * pts[pi++];
                if (!in_range(p)) return false;
                contour_start = out.points.size();
                out.points.push_back(p);
                first = last = p;
                open = true;
                break;
            }
            case Verb::Line: {
                const Point p = m * pts[pi++];
                if (!in_range(p)) return false;
                out.points.push_back(p);
                last = p;
                break;
            }
            case Verb::Quad: {
                const Point p1 = m * pts[pi], p2 = m * pts[pi + 1];
                pi += 2;
                if (!in_range(p1) || !in_range(p2)) return false;
                const int n = wang_steps(len2(last - 2.0 * p1 + p2), k2);
                if (n == 0) return false;
                quad(last, p1, p2, n, out.points);
                last = p2;
                break;
            }
            case Verb::Cubic: {
                const Point p1 = m * pts[pi], p2 = m * pts[pi + 1], p3 = m * pts[pi + 2];
                pi += 3;
                if (!in_range(p1) || !in_range(p2) || !in_range(p3)) return false;
                const double dd = std::max(len2(last - 2.0 * p1 + p2), len2(p1 - 2.0 * p2 + p3));
                const int n = wang_steps(dd, k3);
                if (n == 0) return false;
                cubic(last, p1, p2, p3, n, out.points);
                last = p3;
                break;
            }
            case Verb::Close:
                end_contour();
                break;
        }
    }
    end_contour();
    return true;
}

}  // namespace bezel::raster_detail
