// The pictures of `bezel smooth`: an SVG (input points and polygon, Bézier handles, the result)
// and the same picture as a gray PNG drawn with bezel's own rasterizer.
//
// Geometry stays in the input's units (y down). Stroke widths and dot sizes are measured in `u`,
// one display pixel: the picture is kDisplayPx display pixels on its longer side, so it looks
// the same whatever the points' scale.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "bezel/flatten.hpp"
#include "draw.hpp"
#include "bezel/raster.hpp"
#include "smooth_output.hpp"

namespace bezel::cli {
namespace {

constexpr const char* kColorCurve = "#1565c0";
constexpr const char* kColorPolygon = "#9e9e9e";
constexpr const char* kColorHandle = "#ab47bc";
constexpr const char* kColorPoint = "#c62828";

// Everything drawn: input points, the result's control points or polygon; with a margin.
Rect frame_of(const SmoothReport& r) {
    Rect box = Rect::empty();
    for (const Point& p : r.input) box = box.union_with(p);
    for (const Point& p : r.points) box = box.union_with(p);
    if (!r.polyline) box = box.union_with(r.curve.control_box());
    if (box.is_empty()) box = {0, 0, 1, 1};
    double size = std::max({box.width(), box.height(), 1e-9 * std::fabs(box.x0), 1e-300});
    return box.inflated(0.08 * size);
}

// Each cubic piece's handles P₀P₁ and P₂P₃ (lines and quadratics as their exact cubics).
std::vector<std::pair<Point, Point>> handles(const SmoothReport& r) {
    std::vector<std::pair<Point, Point>> out;
    if (r.polyline) return out;
    for (const PathSeg& s : r.curve.segments()) {
        CubicBez c = s.to_cubic();
        out.push_back({c.p0, c.p1});
        out.push_back({c.p3, c.p2});
    }
    return out;
}

std::string polygon_data(const std::vector<Point>& pts, bool closed) {
    std::ostringstream d;
    for (std::size_t i = 0; i < pts.size(); ++i)
        d << (i == 0 ? 'M' : 'L') << svg_number(pts[i].x) << ' ' << svg_number(pts[i].y);
    if (closed && pts.size() > 2) d << 'Z';
    return d.str();
}

// ---- PNG: strokes as polygons for the fill rasterizer -------------------------------------------

// A cubic (already in pixels) as a polyline within tol_px: Wang's bound n = ⌈√(3·M / (4·tol))⌉
// uniform steps, M the larger second difference of the control points, capped at 4096.
std::vector<Point> polyline_of(const CubicBez& c, double tol_px) {
    double m = std::max((c.p0 - c.p1 * 2.0 + c.p2).length(), (c.p1 - c.p2 * 2.0 + c.p3).length());
    double n_real = std::ceil(std::sqrt(0.75 * m / tol_px));
    int n = std::clamp(static_cast<int>(std::min(n_real, 4096.0)), 1, 4096);
    std::vector<Point> pts;
    for (int k = 0; k <= n; ++k) pts.push_back(c.eval(static_cast<double>(k) / n));
    return pts;
}

// Filled disc of radius r: a 24-gon turning the same way as the stroke rectangles.
void disc(Point c, double r, Polylines& out) {
    constexpr int kSides = 24;
    for (int k = kSides; k > 0; --k) {
        double a = 2.0 * kPi * k / kSides;
        out.points.push_back(c + Vec2{std::cos(a), std::sin(a)} * r);
    }
    out.contour_ends.push_back(out.points.size());
}

}  // namespace

std::string format_smooth_svg(const SmoothReport& r) {
    Rect box = frame_of(r);
    const SvgFrame frame = svg_frame(box);
    const double u = frame.unit;
    std::ostringstream s;
    s << frame.open_tag;
    s << "<title>bezel smooth --method " << r.method << ": " << r.input.size() << " points, "
      << (r.polyline ? r.points.size() : r.curve.segment_count())
      << (r.polyline ? " polygon points" : " pieces") << (r.closed ? ", closed" : "") << "</title>\n";
    s << "<rect x=\"" << svg_number(box.x0) << "\" y=\"" << svg_number(box.y0) << "\" width=\"" << svg_number(box.width())
      << "\" height=\"" << svg_number(box.height()) << "\" fill=\"white\"/>\n";
    // Input polygon: the control polygon of Chaikin and B-splines, the point order otherwise.
    s << "<path d=\"" << polygon_data(r.input, r.closed) << "\" fill=\"none\" stroke=\""
      << kColorPolygon << "\" stroke-width=\"" << svg_number(u) << "\" stroke-dasharray=\"" << svg_number(4 * u)
      << ' ' << svg_number(3 * u) << "\"/>\n";
    auto hs = handles(r);
    if (!hs.empty()) {
        s << "<path d=\"";
        for (const auto& [a, b] : hs)
            s << 'M' << svg_number(a.x) << ' ' << svg_number(a.y) << 'L' << svg_number(b.x) << ' ' << svg_number(b.y);
        s << "\" fill=\"none\" stroke=\"" << kColorHandle << "\" stroke-width=\"" << svg_number(0.75 * u)
          << "\"/>\n";
        for (const auto& h : hs)
            s << "<rect x=\"" << svg_number(h.second.x - 2 * u) << "\" y=\"" << svg_number(h.second.y - 2 * u)
              << "\" width=\"" << svg_number(4 * u) << "\" height=\"" << svg_number(4 * u) << "\" fill=\"white\" stroke=\""
              << kColorHandle << "\" stroke-width=\"" << svg_number(0.75 * u) << "\"/>\n";
    }
    const std::string result = r.polyline ? polygon_data(r.points, r.closed) : to_svg_path(r.curve);
    s << "<path d=\"" << result << "\" fill=\"none\" stroke=\"" << kColorCurve
      << "\" stroke-width=\"" << svg_number(2 * u) << "\" stroke-linejoin=\"round\"/>\n";
    for (std::size_t i = 0; i < r.input.size(); ++i) {
        const Point& p = r.input[i];
        s << "<circle cx=\"" << svg_number(p.x) << "\" cy=\"" << svg_number(p.y) << "\" r=\"" << svg_number(3.5 * u)
          << "\" fill=\"" << kColorPoint << "\"><title>points[" << i << "] " << svg_number(p.x) << ','
          << svg_number(p.y) << "</title></circle>\n";
        s << "<text x=\"" << svg_number(p.x + 5 * u) << "\" y=\"" << svg_number(p.y - 5 * u) << "\" font-size=\""
          << svg_number(11 * u) << "\" font-family=\"sans-serif\" fill=\"" << kColorPoint << "\">" << i
          << "</text>\n";
    }
    s << "</svg>\n";
    return s.str();
}

Expected<std::string> format_smooth_png(const SmoothReport& r,
                                        const PictureColours& colours,
                                        const PngOptions& png) {
    Rect box = frame_of(r);
    double size = std::max(box.width(), box.height());
    double scale = kSmoothPngSizePx / size;
    int w = std::max(1, static_cast<int>(std::ceil(box.width() * scale)));
    int h = std::max(1, static_cast<int>(std::ceil(box.height() * scale)));
    Affine m = Affine::scale(scale) * Affine::translate({-box.x0, -box.y0});

    Polylines curve, polygon, handle_lines, dots;
    std::vector<Point> in_px;
    for (const Point& p : r.input) in_px.push_back(m * p);
    if (r.closed && in_px.size() > 2) in_px.push_back(in_px.front());
    stroke_polyline(in_px, 0.5, polygon);
    if (r.polyline) {
        std::vector<Point> px;
        for (const Point& p : r.points) px.push_back(m * p);
        if (r.closed && px.size() > 2) px.push_back(px.front());
        stroke_polyline(px, 1.0, curve);
    } else {
        for (const PathSeg& s : r.curve.segments()) {
            stroke_polyline(polyline_of(s.to_cubic().transformed(m), 0.05), 1.0, curve);
            // The rasterizer would refuse it anyway; stop before memory grows without bound.
            if (curve.contour_ends.size() > kMaxEdges / 4)
                return Error{"the curve needs more than " + std::to_string(kMaxEdges) +
                             " edges to draw; use -O svg"};
        }
    }
    for (const auto& [a, b] : handles(r)) stroke_polyline({m * a, m * b}, 0.4, handle_lines);
    for (const Point& p : r.input) disc(m * p, 3.0, dots);

    // Ink: curve black, input polygon mid-gray, handles light gray, points dark; white paper.
    return ink_png({{&curve, 1.0}, {&polygon, 0.45}, {&handle_lines, 0.3}, {&dots, 0.8}}, w, h,
                   colours, png);
}

}  // namespace bezel::cli
