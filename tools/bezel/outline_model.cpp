#include "outline_model.hpp"

namespace bezel::cli {

const char* direction_name(Direction d) {
    switch (d) {
        case Direction::Clockwise: return "clockwise";
        case Direction::CounterClockwise: return "counter-clockwise";
        case Direction::Degenerate: return "degenerate";
    }
    return "degenerate";
}

const char* point_kind_name(PointKind kind) {
    switch (kind) {
        case PointKind::OnCurve: return "on";
        case PointKind::OffConic: return "off-conic";
        case PointKind::OffCubic: return "off-cubic";
    }
    return "on";
}

const char* segment_kind_name(SegmentKind kind) {
    switch (kind) {
        case SegmentKind::Line: return "line";
        case SegmentKind::Quad: return "quad";
        case SegmentKind::Cubic: return "cubic";
    }
    return "line";
}

double OutlineReport::ascender_px() const {
    return metrics.units_per_em > 0 ? metrics.ascender * size_px / metrics.units_per_em : 0.0;
}

double OutlineReport::descender_px() const {
    return metrics.units_per_em > 0 ? metrics.descender * size_px / metrics.units_per_em : 0.0;
}

double OutlineReport::total_advance_px() const {
    if (glyphs.empty()) return 0.0;
    return glyphs.back().pen_x_px + glyphs.back().outline.metrics.advance_px;
}

std::vector<std::vector<Segment>> path_segments(const Path& path) {
    std::vector<std::vector<Segment>> contours;
    const auto& pts = path.points();
    std::size_t pi = 0;
    Point start, current;
    bool open = false;  // inside a contour (a Move or a drawing verb since the last Close)
    auto begin_contour = [&](Point at) {
        contours.emplace_back();
        start = current = at;
        open = true;
    };
    for (Verb verb : path.verbs()) {
        // Builder semantics: a drawing verb with no open contour starts one at the current point.
        if (verb != Verb::Move && verb != Verb::Close && !open) begin_contour(current);
        switch (verb) {
            case Verb::Move:
                begin_contour(pts[pi++]);
                break;
            case Verb::Line: {
                Segment s{SegmentKind::Line, {current, pts[pi], {}, {}}, false};
                current = pts[pi++];
                contours.back().push_back(s);
                break;
            }
            case Verb::Quad: {
                Segment s{SegmentKind::Quad, {current, pts[pi], pts[pi + 1], {}}, false};
                current = pts[pi + 1];
                pi += 2;
                contours.back().push_back(s);
                break;
            }
            case Verb::Cubic: {
                Segment s{SegmentKind::Cubic, {current, pts[pi], pts[pi + 1], pts[pi + 2]}, false};
                current = pts[pi + 2];
                pi += 3;
                contours.back().push_back(s);
                break;
            }
            case Verb::Close:
                if (open && current != start)
                    contours.back().push_back({SegmentKind::Line, {current, start, {}, {}}, true});
                current = start;
                open = false;
                break;
        }
    }
    return contours;
}

std::vector<Contour> describe_contours(const GlyphOutline& outline) {
    std::vector<Contour> contours;
    std::vector<std::vector<Segment>> segments = path_segments(outline.path);
    std::size_t first = 0;
    for (std::size_t c = 0; c < outline.contour_ends.size(); ++c) {
        std::size_t last = outline.contour_ends[c];
        if (last < first || last >= outline.points.size()) break;  // malformed: stop, don't read past
        Contour contour;
        contour.first = first;
        contour.last = last;
        double twice_area = 0;
        for (std::size_t i = first; i <= last; ++i) {
            Point a = outline.points[i].pos;
            Point b = outline.points[i == last ? first : i + 1].pos;
            twice_area += a.cross(b);
        }
        contour.signed_area_px2 = 0.5 * twice_area;
        contour.direction = twice_area > 0   ? Direction::Clockwise
                            : twice_area < 0 ? Direction::CounterClockwise
                                             : Direction::Degenerate;
        if (c < segments.size()) contour.segments = std::move(segments[c]);
        contours.push_back(std::move(contour));
        first = last + 1;
    }
    return contours;
}

std::string hinting_label(Hinting hinting) {
    return hinting == Hinting::None ? "unhinted" : std::string(hinting_name(hinting)) + " hinting";
}

}  // namespace bezel::cli
