// FT_Outline → bezel points → Path. See outline_convert.hpp for the rules; the walk below
// follows FT_Outline_Decompose (freetype/src/base/ftoutln.c) step by step so that bezel's Path
// and every FreeType-based renderer see the same segments.
#include "font/outline_convert.hpp"

#include <string>

namespace bezel::font_detail {

Status read_ft_outline(const FT_Outline& outline, double scale, std::vector<OutlinePoint>& points,
                       std::vector<std::size_t>& contour_ends) {
    points.clear();
    contour_ends.clear();
    // FreeType ≤ 2.13.2 declares the counts `short`, later versions `unsigned short`; long holds
    // both.
    const long n_points = outline.n_points;
    const long n_contours = outline.n_contours;
    if (n_points < 0 || n_contours < 0) {
        return Error{"negative point or contour count"};
    }
    if (n_contours == 0) {
        if (n_points != 0) return Error{"points but no contours"};
        return ok_status();
    }
    long previous_end = -1;
    for (long c = 0; c < n_contours; ++c) {
        const long end = outline.contours[c];
        if (end <= previous_end || end >= n_points) {
            return Error{"contour " + std::to_string(c) + " ends at point " + std::to_string(end) +
                         " (previous end " + std::to_string(previous_end) + ", " +
                         std::to_string(n_points) + " points)"};
        }
        previous_end = end;
        contour_ends.push_back(static_cast<std::size_t>(end));
    }
    if (previous_end != n_points - 1) {
        return Error{"points after the last contour"};
    }
    points.reserve(static_cast<std::size_t>(n_points));
    for (long i = 0; i < n_points; ++i) {
        const FT_Vector& v = outline.points[i];
        PointKind kind;
        switch (FT_CURVE_TAG(outline.tags[i])) {
            case FT_CURVE_TAG_ON: kind = PointKind::OnCurve; break;
            case FT_CURVE_TAG_CONIC: kind = PointKind::OffConic; break;
            case FT_CURVE_TAG_CUBIC: kind = PointKind::OffCubic; break;
            default: return Error{"point " + std::to_string(i) + " has an undefined tag"};
        }
        // 0.0 − y·s rather than −(y·s): a point on the baseline gets +0, not −0, so that printed
        // outlines do not show "-0".
        const double x = static_cast<double>(v.x) * scale;
        const double y = 0.0 - static_cast<double>(v.y) * scale;
        points.push_back(OutlinePoint{Point{x, y}, kind});
    }
    return ok_status();
}

namespace {
Point midpoint(Point a, Point b) { return (a + b) * 0.5; }
}  // namespace

Status path_from_points(const std::vector<OutlinePoint>& points,
                        const std::vector<std::size_t>& contour_ends, Path& out) {
    std::size_t first = 0;
    for (std::size_t c = 0; c < contour_ends.size(); ++c) {
        const std::size_t last = contour_ends[c];
        if (last < first || last >= points.size()) {
            return Error{"contour " + std::to_string(c) + " has an invalid end point"};
        }
        const auto bad = [&](const char* what) {
            return Error{"contour " + std::to_string(c) + ": " + what};
        };
        if (points[first].kind == PointKind::OffCubic) {
            return bad("starts with a cubic control point");
        }

        Point start = points[first].pos;
        std::size_t next = first + 1;  // the next point to consume
        std::size_t limit = last;      // the last point the walk consumes
        if (points[first].kind == PointKind::OffConic) {
            if (points[last].kind == PointKind::OnCurve) {
                // Start at the on-curve point before the first one (cyclically): it is the end
                // of the contour, so the walk stops one point early.
                start = points[last].pos;
                limit = last - 1;  // last > first here: a lone point cannot be both kinds
            } else {
                // First and last both off-curve: the implied on-curve point between them.
                start = midpoint(points[last].pos, points[first].pos);
            }
            next = first;  // the first point is consumed as a control point below
        }
        out.move_to(start);

        // Set when the contour ends with a curve back to `start` (the segment is explicit);
        // otherwise it ends on-curve and Close draws the line back.
        bool ended_on_curve_to_start = false;
        while (next <= limit && !ended_on_curve_to_start) {
            const OutlinePoint& p = points[next];
            if (p.kind == PointKind::OnCurve) {
                out.line_to(p.pos);
                ++next;
            } else if (p.kind == PointKind::OffConic) {
                Point control = p.pos;
                ++next;
                for (;;) {
                    if (next > limit) {
                        out.quad_to(control, start);
                        ended_on_curve_to_start = true;
                        break;
                    }
                    const OutlinePoint& q = points[next];
                    ++next;
                    if (q.kind == PointKind::OnCurve) {
                        out.quad_to(control, q.pos);
                        break;
                    }
                    if (q.kind != PointKind::OffConic) return bad("cubic point after a conic one");
                    // Two conic controls in a row: the implied on-curve point is their midpoint.
                    out.quad_to(control, midpoint(control, q.pos));
                    control = q.pos;
                }
            } else {
                if (next + 1 > limit || points[next + 1].kind != PointKind::OffCubic) {
                    return bad("cubic control points not in pairs");
                }
                const Point c1 = points[next].pos, c2 = points[next + 1].pos;
                next += 2;
                if (next <= limit) {
                    out.cubic_to(c1, c2, points[next].pos);
                    ++next;
                } else {
                    out.cubic_to(c1, c2, start);
                    ended_on_curve_to_start = true;
                }
            }
        }
        out.close();
        first = last + 1;
    }
    return ok_status();
}

}  // namespace bezel::font_detail
