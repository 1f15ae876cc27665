// stroke(): validation, the dashing step, and one ContourStroker per contour (outline.cpp).
#include "bezel/stroke.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "stroke/stroke_internal.hpp"

namespace bezel {
namespace stroke_detail {

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

std::vector<ContourInput> contours_of(const Path& path) {
    std::vector<ContourInput> out;
    const auto& pts = path.points();
    std::size_t pi = 0;
    Point last{};
    auto add = [&](SegKind kind, int n) {
        PathSeg seg;
        seg.kind = kind;
        seg.p[0] = last;
        for (int k = 0; k < n; ++k) seg.p[k + 1] = pts[pi + k];
        pi += static_cast<std::size_t>(n);
        last = seg.p[n];
        out.back().segs.push_back(seg);
    };
    for (Verb v : path.verbs()) {
        switch (v) {
            case Verb::Move:
                out.emplace_back();
                out.back().start = last = pts[pi++];
                break;
            case Verb::Line: add(SegKind::Line, 1); break;
            case Verb::Quad: add(SegKind::Quad, 2); break;
            case Verb::Cubic: add(SegKind::Cubic, 3); break;
            case Verb::Close: {
                ContourInput& c = out.back();
                c.closed = true;
                if (last != c.start) {
                    PathSeg seg;
                    seg.p[0] = last;
                    seg.p[1] = c.start;
                    seg.closing = true;
                    c.segs.push_back(seg);
                }
                last = c.start;
                break;
            }
        }
    }
    return out;
}

Status check_dashes(const std::vector<double>& dashes, double dash_offset) {
    double sum = 0;
    for (std::size_t i = 0; i < dashes.size(); ++i) {
        if (!(std::isfinite(dashes[i]) && dashes[i] >= 0))
            return Error{"dash pattern entry " + std::to_string(i) + " (" + num(dashes[i]) +
                         "): must be finite and >= 0"};
        sum += dashes[i];
    }
    if (!dashes.empty() && !(sum > 0 && std::isfinite(sum)))
        return Error{"dash pattern: the lengths must not all be 0"};
    if (!std::isfinite(dash_offset))
        return Error{"dash offset " + num(dash_offset) + ": must be finite"};
    return ok_status();
}

}  // namespace stroke_detail

using namespace stroke_detail;

Expected<Path> stroke(const Path& path, const StrokeStyle& style) {
    if (!(std::isfinite(style.width) && style.width > 0))
        return Error{"stroke width " + num(style.width) + ": must be finite and > 0"};
    if (!(style.miter_limit >= 1))
        return Error{"miter limit " + num(style.miter_limit) + ": must be >= 1"};
    if (!(std::isfinite(style.tolerance) && style.tolerance > 0))
        return Error{"stroke tolerance " + num(style.tolerance) + ": must be finite and > 0"};
    if (!path.is_finite()) return Error{"stroke: the path has a non-finite coordinate"};
    if (auto ok = check_dashes(style.dashes, style.dash_offset); !ok) return ok.error();

    Path dashed;
    const Path* src = &path;
    if (!style.dashes.empty()) {
        // Every stroked dash is at least a Move, its two sides, two caps (a butt cap is one
        // line, a round one two arcs, a square one three lines) and a Close; a zero-length dash
        // with butt caps makes nothing.
        DashLimit limit;
        limit.segments_per_dash = style.cap == LineCap::Butt    ? 6
                                  : style.cap == LineCap::Round ? 8
                                                                : 10;
        limit.max_segments = kMaxStrokeSegments;
        limit.count_empty = style.cap != LineCap::Butt;
        auto d = dash_limited(path, style.dashes, style.dash_offset, limit);
        if (!d) return d.error();
        dashed = std::move(*d);
        src = &dashed;
    }
    // Relative thresholds (zero length, cusps) use the geometry's size; a tolerance below
    // double rounding of that size (1e-12 of it) could never be met and is raised to it.
    Rect box = src->control_box();
    double h = style.width / 2;
    double size = box.is_empty() ? h : std::max({box.width(), box.height(), h});
    double extent = box.is_empty() ? 0.0
                                   : std::max({std::fabs(box.x0), std::fabs(box.x1),
                                               std::fabs(box.y0), std::fabs(box.y1)});
    double tol = std::max(style.tolerance, 1e-12 * std::max(size, extent));

    Path out;
    Budget budget;
    for (const ContourInput& contour : contours_of(*src)) {
        stroke_contour(contour, style, tol, size, budget, out);
        if (budget.exceeded() || out.verbs().size() > kMaxStrokeSegments)
            return Error{"stroke: the outline would exceed " + std::to_string(kMaxStrokeSegments) +
                         " segments (the stroker's limit); raise the tolerance or simplify the path"};
    }
    if (!out.is_finite()) return Error{"stroke: the outline overflowed (coordinates too large)"};
    return out;
}

}  // namespace bezel
