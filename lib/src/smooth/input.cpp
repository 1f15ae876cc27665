#include "smooth/input.hpp"

#include <cmath>
#include <cstdio>

#include "bezel/smooth.hpp"

namespace bezel::smooth_detail {

std::string format_point(Point p) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "(%.17g, %.17g)", p.x, p.y);
    return buf;
}

Error method_error(const char* method, const std::string& what) {
    return Error{std::string(method) + ": " + what};
}

Status check_vector(const char* method, const char* what, std::size_t index, Vec2 v) {
    if (!v.is_finite())
        return method_error(method, std::string(what) + "[" + std::to_string(index) +
                                        "] is not finite " + format_point(v));
    if (std::fabs(v.x) > kMaxSmoothCoordinate || std::fabs(v.y) > kMaxSmoothCoordinate)
        return method_error(method, std::string(what) + "[" + std::to_string(index) + "] " +
                                        format_point(v) + " exceeds the largest coordinate " +
                                        "magnitude 2^100");
    return ok_status();
}

Status check_count(const char* method, std::size_t count, bool closed, std::size_t min_open,
                   std::size_t min_closed) {
    std::size_t need = closed ? min_closed : min_open;
    if (count >= need) return ok_status();
    return method_error(method, std::to_string(count) + (count == 1 ? " point" : " points") +
                                    (closed ? " in a closed curve" : "") + ", at least " +
                                    std::to_string(need) + " needed");
}

Expected<std::vector<Point>> prepare_points(const char* method, const std::vector<Point>& points,
                                            bool closed, std::size_t min_open,
                                            std::size_t min_closed) {
    if (points.size() > kMaxSmoothPoints)
        return method_error(method, std::to_string(points.size()) + " points, more than the " +
                                        std::to_string(kMaxSmoothPoints) + " allowed");
    for (std::size_t i = 0; i < points.size(); ++i)
        if (auto ok = check_vector(method, "points", i, points[i]); !ok) return ok.error();
    std::vector<Point> out = points;
    if (closed && out.size() >= 2 && out.back() == out.front()) out.pop_back();
    if (auto count = check_count(method, out.size(), closed, min_open, min_closed); !count)
        return count.error();
    bool all_equal = true;
    for (const Point& p : out) all_equal = all_equal && p == out.front();
    if (all_equal)
        return method_error(method, "all " + std::to_string(out.size()) + " points are " +
                                        format_point(out.front()) + ", there is no curve");
    return out;
}

std::vector<Point> merge_repeats(const std::vector<Point>& points, bool closed) {
    std::vector<Point> out;
    out.reserve(points.size());
    for (const Point& p : points)
        if (out.empty() || p != out.back()) out.push_back(p);
    if (closed)
        while (out.size() >= 2 && out.back() == out.front()) out.pop_back();
    return out;
}

}  // namespace bezel::smooth_detail
