// The SVG form of `bezel outline`: what a type designer looks at when checking an outline.
//
// Drawn, back to front: metric lines (baseline, ascender, descender, each glyph's origin and
// advance), the filled outline (light gray, nonzero) with its stroke, the control polygon
// (dashed), each contour's start ring and direction arrow, the points (on-curve: filled circles;
// off-curve: hollow squares, one colour for quadratic and one for cubic controls) with their
// indices, then a title and a legend.
//
// Geometry stays in the outline's own units (pixels at the font size, y down), so the SVG's
// coordinates are the ones the text and JSON forms print. Everything else — stroke widths,
// marker sizes, text — is measured in `u`, one display pixel: the SVG's width/height attributes
// show the em at kDisplayEmPx display pixels, so u = size_px / kDisplayEmPx and the picture looks
// the same at --font-size 64 and 512.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "cli_common.hpp"
#include "outline_model.hpp"

namespace bezel::cli {
namespace {

// Display size of one em for a single glyph; long --text strings shrink towards the minimum so
// the picture stays a manageable width.
constexpr double kDisplayEmPx = 600.0;
constexpr double kMinDisplayEmPx = 200.0;
constexpr double kMaxDisplayWidthPx = 2400.0;

constexpr const char* kOnColor = "#1565c0";
constexpr const char* kConicColor = "#e65100";
constexpr const char* kCubicColor = "#8e24aa";
constexpr const char* kStartColor = "#2e7d32";
constexpr const char* kMetricColor = "#4a90d9";
constexpr const char* kAdvanceColor = "#9e9e9e";

// Shortest fixed form with up to 3 decimals ("12.5", "-3", not "12.500").
std::string f(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f", v);
    std::string s = buf;
    s.erase(s.find_last_not_of('0') + 1);
    if (s.back() == '.') s.pop_back();
    if (s == "-0") s = "0";
    return s;
}

std::string escape_xml(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
    }
    return out;
}

std::string svg_path_data(const Path& path) {
    std::ostringstream d;
    const auto& pts = path.points();
    std::size_t i = 0;
    for (Verb v : path.verbs()) {
        switch (v) {
            case Verb::Move: d << 'M' << f(pts[i].x) << ' ' << f(pts[i].y); i += 1; break;
            case Verb::Line: d << 'L' << f(pts[i].x) << ' ' << f(pts[i].y); i += 1; break;
            case Verb::Quad:
                d << 'Q' << f(pts[i].x) << ' ' << f(pts[i].y) << ' ' << f(pts[i + 1].x) << ' '
                  << f(pts[i + 1].y);
                i += 2;
                break;
            case Verb::Cubic:
                d << 'C' << f(pts[i].x) << ' ' << f(pts[i].y) << ' ' << f(pts[i + 1].x) << ' '
                  << f(pts[i + 1].y) << ' ' << f(pts[i + 2].x) << ' ' << f(pts[i + 2].y);
                i += 3;
                break;
            case Verb::Close: d << 'Z'; break;
        }
    }
    return d.str();
}

std::string char_label(const GlyphReport& g) {
    std::string s;
    if (g.code_point) {
        char32_t cp = *g.code_point;
        if (cp > 0x20 && cp != 0x7F && !(cp >= 0x80 && cp <= 0xA0)) {
            s += "\u2018";
            append_utf8(s, cp);
            s += "\u2019 ";
        }
        s += format_code_point(cp) + " \u00b7 ";
    }
    return s + "gid " + std::to_string(g.gid) + " \u00b7 " + g.name;
}

class SvgWriter {
public:
    SvgWriter(const OutlineReport& r) : r_(r) {
        // The legend shows the kinds of off-curve point present (the font's kind if none).
        for (const GlyphReport& g : r.glyphs)
            for (const OutlinePoint& p : g.outline.points) {
                conic_ |= p.kind == PointKind::OffConic;
                cubic_ |= p.kind == PointKind::OffCubic;
            }
        if (!conic_ && !cubic_) (r.cubic ? cubic_ : conic_) = true;
        legend_items_ = 6 + int{conic_} + int{cubic_};

        const double em_px = r.size_px;
        const double line_px = std::max(r.total_advance_px(), em_px * 0.5);
        double display_em = std::clamp(kMaxDisplayWidthPx * em_px / line_px, kMinDisplayEmPx,
                                       kDisplayEmPx);
        u_ = em_px / display_em;

        // Glyph area: the metric lines and every glyph's control box, plus a margin.
        Rect area{0, -r.ascender_px(), r.total_advance_px(), -r.descender_px()};
        for (const GlyphReport& g : r.glyphs)
            if (!g.outline.metrics.bounds_px.is_empty()) {
                Rect b = g.outline.metrics.bounds_px;
                area = area.union_with(Rect{b.x0 + g.pen_x_px, b.y0, b.x1 + g.pen_x_px, b.y1});
            }
        area = area.inflated(40 * u_);
        legend_columns_ = std::max(1, static_cast<int>(area.width() / (kLegendColumn * u_)));
        legend_columns_ = std::min(legend_columns_, 3);
        double min_width = legend_columns_ * kLegendColumn * u_ + 20 * u_;
        if (area.width() < min_width) area = area.inflated((min_width - area.width()) / 2);
        glyph_area_ = area;
        view_ = Rect{area.x0, area.y0 - kTitleHeight * u_, area.x1,
                     area.y1 + legend_height() * u_};
    }

    std::string write() {
        out_ << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << f(view_.width() / u_)
             << "\" height=\"" << f(view_.height() / u_) << "\" viewBox=\"" << f(view_.x0) << ' '
             << f(view_.y0) << ' ' << f(view_.width()) << ' ' << f(view_.height()) << "\""
             << " font-family=\"DejaVu Sans, Verdana, sans-serif\">\n";
        out_ << "<title>" << escape_xml(title()) << "</title>\n";
        rect(view_, "white");
        metric_lines();
        for (const GlyphReport& g : r_.glyphs) glyph(g);
        title_text();
        legend();
        out_ << "</svg>\n";
        return out_.str();
    }

private:
    static constexpr double kTitleHeight = 44;    // display px above the glyph area
    static constexpr double kLegendRow = 17;      // display px per legend row
    static constexpr double kLegendColumn = 250;  // display px per legend column

    double legend_height() const {
        int rows = (legend_items_ + legend_columns_ - 1) / legend_columns_;
        return 16 + rows * kLegendRow;
    }

    std::string title() const {
        std::string t = r_.family + " " + r_.style;
        if (r_.glyphs.size() == 1) t += " \u00b7 " + char_label(r_.glyphs[0]);
        else t += " \u00b7 " + std::to_string(r_.glyphs.size()) + " glyphs";
        return t;
    }

    void rect(const Rect& b, const char* fill) {
        out_ << "<rect x=\"" << f(b.x0) << "\" y=\"" << f(b.y0) << "\" width=\"" << f(b.width())
             << "\" height=\"" << f(b.height()) << "\" fill=\"" << fill << "\"/>\n";
    }

    void line(Point a, Point b, const char* color, double width_u, const char* dash_u = nullptr) {
        out_ << "<line x1=\"" << f(a.x) << "\" y1=\"" << f(a.y) << "\" x2=\"" << f(b.x)
             << "\" y2=\"" << f(b.y) << "\" stroke=\"" << color << "\" stroke-width=\""
             << f(width_u * u_) << "\"";
        if (dash_u) out_ << " stroke-dasharray=\"" << dash(dash_u) << "\"";
        out_ << "/>\n";
    }

    // "4 3" in display px → the same pattern in user units.
    std::string dash(const char* pattern_u) const {
        std::istringstream in(pattern_u);
        std::string out;
        double v;
        while (in >> v) out += (out.empty() ? "" : " ") + f(v * u_);
        return out;
    }

    // Text with a white halo so it stays legible over lines and fills.
    void text(Point at, const std::string& s, const char* color, double size_u,
              const char* anchor = "start", const char* weight = "normal") {
        out_ << "<text x=\"" << f(at.x) << "\" y=\"" << f(at.y) << "\" font-size=\""
             << f(size_u * u_) << "\" fill=\"" << color << "\" text-anchor=\"" << anchor
             << "\" font-weight=\"" << weight << "\" stroke=\"white\" stroke-width=\""
             << f(2.5 * u_) << "\" paint-order=\"stroke\">" << escape_xml(s) << "</text>\n";
    }

    void metric_lines() {
        const double x0 = glyph_area_.x0, x1 = glyph_area_.x1;
        struct M { const char* name; double y; const char* dash; };
        const M lines[] = {{"ascender", -r_.ascender_px(), "6 4"},
                           {"baseline", 0.0, nullptr},
                           {"descender", -r_.descender_px(), "6 4"}};
        for (const M& m : lines) {
            line({x0, m.y}, {x1, m.y}, kMetricColor, m.dash ? 1.0 : 1.5, m.dash);
            text({x0 + 4 * u_, m.y - 4 * u_}, std::string(m.name) + " " + f(-m.y), kMetricColor,
                 11);
        }
        for (const GlyphReport& g : r_.glyphs) {
            for (double x : {g.pen_x_px, g.pen_x_px + g.outline.metrics.advance_px})
                line({x, glyph_area_.y0}, {x, glyph_area_.y1}, kAdvanceColor, 1.0, "3 3");
            text({g.pen_x_px + g.outline.metrics.advance_px - 3 * u_, glyph_area_.y1 - 6 * u_},
                 "advance " + f(g.outline.metrics.advance_px), kAdvanceColor, 10, "end");
            if (r_.glyphs.size() > 1)
                text({g.pen_x_px + 3 * u_, glyph_area_.y1 - 20 * u_}, char_label(g), "#555", 10);
        }
    }

    void glyph(const GlyphReport& g) {
        const GlyphOutline& o = g.outline;
        out_ << "<g transform=\"translate(" << f(g.pen_x_px) << " 0)\">\n";
        out_ << "<path d=\"" << svg_path_data(o.path)
             << "\" fill=\"#d9d9d9\" fill-rule=\"nonzero\" stroke=\"#212121\" stroke-width=\""
             << f(1.5 * u_) << "\" stroke-linejoin=\"round\"/>\n";
        for (std::size_t c = 0; c < g.contours.size(); ++c) control_polygon(o, g.contours[c]);
        for (std::size_t c = 0; c < g.contours.size(); ++c) contour_start(o, g.contours[c], c);
        for (std::size_t i = 0; i < o.points.size(); ++i) point(o.points[i], static_cast<long>(i));
        out_ << "</g>\n";
    }

    void control_polygon(const GlyphOutline& o, const Contour& c) {
        out_ << "<polygon points=\"";
        for (std::size_t i = c.first; i <= c.last; ++i)
            out_ << (i == c.first ? "" : " ") << f(o.points[i].pos.x) << ',' << f(o.points[i].pos.y);
        out_ << "\" fill=\"none\" stroke=\"#757575\" stroke-width=\"" << f(0.75 * u_)
             << "\" stroke-dasharray=\"" << dash("4 3") << "\"/>\n";
    }

    // A ring on the first point and an arrow along the first control-polygon leg: the tangent
    // of the contour at its start, so it shows the direction the points run.
    void contour_start(const GlyphOutline& o, const Contour& c, std::size_t index) {
        Point s = o.points[c.first].pos;
        Vec2 dir;
        for (std::size_t i = c.first + 1; i <= c.last && dir == Vec2{}; ++i)
            dir = (o.points[i].pos - s).normalized();
        out_ << "<circle cx=\"" << f(s.x) << "\" cy=\"" << f(s.y) << "\" r=\"" << f(8 * u_)
             << "\" fill=\"none\" stroke=\"" << kStartColor << "\" stroke-width=\"" << f(1.5 * u_)
             << "\"/>\n";
        if (dir != Vec2{}) {
            Point tail = s + dir * (10 * u_), tip = s + dir * (26 * u_);
            line(tail, tip - dir * (4 * u_), kStartColor, 2.0);
            Vec2 side = dir.perp() * (4.5 * u_);
            Point base = tip - dir * (9 * u_);
            out_ << "<polygon points=\"" << f(tip.x) << ',' << f(tip.y) << ' '
                 << f(base.x + side.x) << ',' << f(base.y + side.y) << ' ' << f(base.x - side.x)
                 << ',' << f(base.y - side.y) << "\" fill=\"" << kStartColor << "\"/>\n";
        }
        // Label beside the ring, clear of the arrow and of the point's own index (drawn to its
        // upper right): left of a vertical arrow, below a horizontal one.
        const char* turn = c.direction == Direction::Clockwise          ? " \u21bb"
                           : c.direction == Direction::CounterClockwise ? " \u21ba"
                                                                        : "";
        const bool vertical = std::abs(dir.y) >= std::abs(dir.x);
        Point at = vertical ? s + Vec2{-12 * u_, 4 * u_} : s + Vec2{0, 22 * u_};
        text(at, "c" + std::to_string(index) + turn, kStartColor, 11, vertical ? "end" : "middle",
             "bold");
    }

    // `index` < 0: no index label (the legend's samples).
    void point(const OutlinePoint& p, long index) {
        const double x = p.pos.x, y = p.pos.y;
        if (p.kind == PointKind::OnCurve) {
            out_ << "<circle cx=\"" << f(x) << "\" cy=\"" << f(y) << "\" r=\"" << f(3.5 * u_)
                 << "\" fill=\"" << kOnColor << "\" stroke=\"white\" stroke-width=\"" << f(0.8 * u_)
                 << "\"/>\n";
        } else {
            const double h = 3.2 * u_;
            out_ << "<rect x=\"" << f(x - h) << "\" y=\"" << f(y - h) << "\" width=\"" << f(2 * h)
                 << "\" height=\"" << f(2 * h) << "\" fill=\"white\" stroke=\""
                 << (p.kind == PointKind::OffConic ? kConicColor : kCubicColor)
                 << "\" stroke-width=\"" << f(1.4 * u_) << "\"/>\n";
        }
        if (index >= 0) text({x + 5 * u_, y - 5 * u_}, std::to_string(index), "#424242", 9);
    }

    void title_text() {
        const double x = glyph_area_.x0 + 8 * u_, y = glyph_area_.y0 - kTitleHeight * u_;
        text({x, y + 18 * u_}, title(), "#212121", 14, "start", "bold");
        std::string sub = f(r_.size_px) + " px, " + hinting_label(r_.hinting) + ", " +
                          (r_.cubic ? "CFF cubic" : "TrueType quadratic") +
                          " outlines \u00b7 pixels, y down, pen at (0, 0)";
        for (const auto& v : r_.variations) sub += " \u00b7 " + v.tag + "=" + f(v.value);
        text({x, y + 36 * u_}, sub, "#616161", 10);
    }

    void legend() {
        const bool conic = conic_, cubic = cubic_;
        const std::string outer = r_.cubic ? "counter-clockwise" : "clockwise";

        const double top = glyph_area_.y1 + 8 * u_;
        int item = 0;
        auto next = [&]() {
            int rows = (legend_items_ + legend_columns_ - 1) / legend_columns_;
            Point at{glyph_area_.x0 + (12 + (item / rows) * kLegendColumn) * u_,
                     top + (item % rows + 0.5) * kLegendRow * u_};
            ++item;
            return at;
        };
        auto label = [&](Point at, const std::string& s) {
            text({at.x + 22 * u_, at.y + 3.5 * u_}, s, "#424242", 10);
        };
        Point at = next();
        point({{at.x + 8 * u_, at.y}, PointKind::OnCurve}, -1);
        text({at.x + 13 * u_, at.y - 3 * u_}, "7", "#424242", 9);
        label(at, "   on-curve point, with its index");
        if (conic) {
            at = next();
            point({{at.x + 8 * u_, at.y}, PointKind::OffConic}, -1);
            label(at, "off-curve, quadratic (TrueType)");
        }
        if (cubic) {
            at = next();
            point({{at.x + 8 * u_, at.y}, PointKind::OffCubic}, -1);
            label(at, "off-curve, cubic (CFF)");
        }
        at = next();
        line({at.x, at.y}, {at.x + 18 * u_, at.y}, "#757575", 0.75, "4 3");
        label(at, "control polygon");
        at = next();
        out_ << "<rect x=\"" << f(at.x) << "\" y=\"" << f(at.y - 5 * u_) << "\" width=\""
             << f(18 * u_) << "\" height=\"" << f(10 * u_)
             << "\" fill=\"#d9d9d9\" stroke=\"#212121\" stroke-width=\"" << f(1.5 * u_) << "\"/>\n";
        label(at, "outline, filled nonzero");
        at = next();
        line({at.x, at.y}, {at.x + 14 * u_, at.y}, kStartColor, 2.0);
        out_ << "<circle cx=\"" << f(at.x) << "\" cy=\"" << f(at.y) << "\" r=\"" << f(4 * u_)
             << "\" fill=\"white\" stroke=\"" << kStartColor << "\" stroke-width=\"" << f(1.5 * u_)
             << "\"/>\n";
        label(at, "contour start and direction");
        at = next();
        text({at.x + 9 * u_, at.y + 4 * u_}, "\u21bb \u21ba", kStartColor, 11, "middle", "bold");
        label(at, "direction; outer contours run " + outer);
        at = next();
        line({at.x, at.y}, {at.x + 18 * u_, at.y}, kMetricColor, 1.0, "6 4");
        label(at, "ascender/descender; gray: advance");
    }

    const OutlineReport& r_;
    double u_ = 1;
    int legend_columns_ = 1;
    int legend_items_ = 0;
    bool conic_ = false, cubic_ = false;
    Rect glyph_area_, view_;
    std::ostringstream out_;
};

}  // namespace

std::string format_svg(const OutlineReport& report) { return SvgWriter(report).write(); }

}  // namespace bezel::cli
