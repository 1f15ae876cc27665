// tools/bezel/outline_model.hpp — what `bezel outline` reports about glyphs, independent of the
// output format: per glyph its outline, and per contour its points, direction and segments.
// The three writers (outline_text.cpp, outline_json.cpp, outline_svg.cpp) print this model.
//
// Units: pixels at the requested size, y DOWN, each glyph's pen at (0, 0) on the baseline (as
// bezel::Font delivers them). Directions are as seen on screen (y down).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "bezel/font.hpp"

namespace bezel::cli {

// Orientation of a contour as seen with the glyph upright: on screen (y down), and equally in
// font units plotted y up — the y flip between the two is the display convention itself, so it
// changes the sign of the shoelace area, not what the eye sees. TrueType outer contours run
// clockwise, CFF (PostScript) outer contours counter-clockwise.
enum class Direction { Clockwise, CounterClockwise, Degenerate };

// "clockwise", "counter-clockwise", "degenerate".
const char* direction_name(Direction d);
// "on", "off-conic", "off-cubic".
const char* point_kind_name(PointKind kind);

enum class SegmentKind { Line, Quad, Cubic };
// "line", "quad", "cubic".
const char* segment_kind_name(SegmentKind kind);
// "unhinted", "light hinting", "full hinting", "auto hinting": the size line of text and SVG.
std::string hinting_label(Hinting hinting);

struct Segment {
    SegmentKind kind = SegmentKind::Line;
    std::array<Point, 4> p{};  // start, controls, end: the first point_count() entries are used
    bool closing = false;      // the line a Close verb adds back to the contour's start
    std::size_t point_count() const { return kind == SegmentKind::Line ? 2 : kind == SegmentKind::Quad ? 3 : 4; }
};

struct Contour {
    std::size_t first = 0, last = 0;  // inclusive range of indices into GlyphOutline::points
    // Shoelace area of the polygon through the font's points (on- and off-curve), px², y down:
    // ½ Σ (xᵢ·yᵢ₊₁ − xᵢ₊₁·yᵢ). With y down, positive means clockwise. The control polygon's
    // orientation equals the curve's whenever the contour does not self-intersect, which holds
    // for well-formed font outlines; it is a direction report, not an exact area.
    double signed_area_px2 = 0;
    Direction direction = Direction::Degenerate;
    // The Path's segments for this contour (the Path's contours are in the font's contour order).
    std::vector<Segment> segments;
};

struct GlyphReport {
    GlyphId gid = 0;
    std::string name;
    std::optional<char32_t> code_point;  // the character asked for, when one was
    double pen_x_px = 0;                 // where this glyph's origin sits along the line
    GlyphOutline outline;
    std::vector<Contour> contours;
};

struct OutlineReport {
    std::string font_file;
    std::string family, style;
    int face_index = 0;
    bool cubic = false;                  // CFF outlines rather than TrueType quadratics
    FontMetrics metrics;                 // font units, y up
    std::vector<VariationSetting> variations;
    double size_px = 0;
    Hinting hinting = Hinting::None;
    std::vector<GlyphReport> glyphs;

    // Face metrics scaled to the size, still y up (ascender > 0).
    double ascender_px() const;
    double descender_px() const;
    double total_advance_px() const;     // pen position after the last glyph
};

// Splits a Path into its contours' segments, one vector per contour (a contour starts at each
// Move, and at a drawing verb that follows a Close). Zero-length closing lines are left out.
std::vector<std::vector<Segment>> path_segments(const Path& path);

// Contours of `outline`: point ranges from contour_ends, directions from the shoelace formula,
// segments from the path. Extra path contours (none for a well-formed outline) are dropped.
std::vector<Contour> describe_contours(const GlyphOutline& outline);

// The three output formats. Each returns the complete document.
std::string format_text(const OutlineReport& report);
std::string format_json(const OutlineReport& report);
std::string format_svg(const OutlineReport& report);

}  // namespace bezel::cli
