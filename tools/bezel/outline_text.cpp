// The text form of `bezel outline`: a header, then per glyph its contours with their points and
// segments, sized for a terminal (one point or segment per line, three decimals).
#include <cmath>
#include <cstdio>
#include <sstream>

#include "cli_common.hpp"
#include "outline_model.hpp"

namespace bezel::cli {
namespace {

// Three decimals, and never "-0.000".
std::string three_decimals(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f", v);
    std::string s = buf;
    if (s == "-0.000") s = "0.000";
    return s;
}

std::string pt(Point p) { return "(" + three_decimals(p.x) + ", " + three_decimals(p.y) + ")"; }

// Direction as seen, and what it makes the contour under the font's convention (TrueType: outer
// contours clockwise; CFF: counter-clockwise). Without nesting analysis this is what the
// direction claims, which is exactly what a designer checks it against.
std::string describe_direction(Direction d, bool cubic) {
    if (d == Direction::Degenerate) return "degenerate (zero area)";
    bool outer = (d == Direction::Clockwise) != cubic;
    return std::string(direction_name(d)) + (outer ? " (outer" : " (hole") + " by " +
           (cubic ? "CFF" : "TrueType") + " convention)";
}

void write_header(std::ostringstream& out, const OutlineReport& r) {
    out << "font     " << r.family << ' ' << r.style << "  (" << r.font_file << ", face "
        << r.face_index << ", " << (r.cubic ? "CFF cubic" : "TrueType quadratic") << " outlines)\n";
    out << "size     " << three_decimals(r.size_px) << " px, " << hinting_label(r.hinting) << "; "
        << r.metrics.units_per_em << " units/em; ascender " << three_decimals(r.ascender_px())
        << " px, descender " << three_decimals(r.descender_px()) << " px (y up)\n";
    if (!r.variations.empty()) {
        out << "axes    ";
        for (const auto& v : r.variations) out << ' ' << v.tag << '=' << v.value;
        out << '\n';
    }
    out << "coords   pixels, y down, pen at (0, 0) on the baseline; outer contours run "
        << (r.cubic ? "counter-clockwise (CFF)" : "clockwise (TrueType)") << "\n";
}

void write_glyph(std::ostringstream& out, const GlyphReport& g, bool cubic, bool several) {
    const GlyphOutline& o = g.outline;
    out << "\nglyph";
    if (g.code_point) {
        char32_t cp = *g.code_point;
        if (cp >= 0x20 && cp != 0x7F && !(cp >= 0x80 && cp < 0xA0)) {
            std::string utf8;
            append_utf8(utf8, cp);
            out << " '" << utf8 << "'";
        }
        out << ' ' << format_code_point(cp);
    }
    out << "  gid " << g.gid << "  name " << g.name << '\n';
    out << "  advance " << three_decimals(o.metrics.advance_px);
    if (several) out << "  pen x " << three_decimals(g.pen_x_px);
    if (o.metrics.bounds_px.is_empty())
        out << "  bounds (empty)";
    else
        out << "  bounds x " << three_decimals(o.metrics.bounds_px.x0) << " .. " << three_decimals(o.metrics.bounds_px.x1)
            << "  y " << three_decimals(o.metrics.bounds_px.y0) << " .. " << three_decimals(o.metrics.bounds_px.y1);
    out << "  " << g.contours.size() << (g.contours.size() == 1 ? " contour, " : " contours, ")
        << o.points.size() << " points\n";

    for (std::size_t c = 0; c < g.contours.size(); ++c) {
        const Contour& k = g.contours[c];
        std::size_t n = k.last - k.first + 1;
        out << "  contour " << c << ": " << n << (n == 1 ? " point " : " points ") << "[" << k.first
            << ".." << k.last << "], " << describe_direction(k.direction, cubic) << '\n';
        for (std::size_t i = k.first; i <= k.last; ++i) {
            char line[128];
            std::snprintf(line, sizeof line, "    %4zu %10s %10s  %s\n", i,
                          three_decimals(o.points[i].pos.x).c_str(), three_decimals(o.points[i].pos.y).c_str(),
                          point_kind_name(o.points[i].kind));
            out << line;
        }
        out << (k.segments.empty() ? "    segments: none\n" : "    segments:\n");
        for (const Segment& s : k.segments) {
            char kind[16];
            std::snprintf(kind, sizeof kind, "%-6s", segment_kind_name(s.kind));
            out << "      " << kind;
            for (std::size_t i = 0; i < s.point_count(); ++i) out << (i ? " " : "") << pt(s.p[i]);
            if (s.closing) out << "  (closing)";
            out << '\n';
        }
    }
}

}  // namespace

std::string format_text(const OutlineReport& report) {
    std::ostringstream out;
    write_header(out, report);
    for (const GlyphReport& g : report.glyphs)
        write_glyph(out, g, report.cubic, report.glyphs.size() > 1);
    return out.str();
}

}  // namespace bezel::cli
