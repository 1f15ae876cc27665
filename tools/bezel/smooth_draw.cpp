// The pictures of `bezel smooth`: an SVG (input points and polygon, Bézier handles, the result)
// and the same picture as a gray PNG drawn with bezel's own rasterizer.
//
// Geometry stays in the input's units (y down). Stroke widths and dot sizes are measured in `u`,
// one display pixel: the picture is kDisplayPx display pixels on its longer side, so it looks
// the same whatever the points' scale.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "bezel/flatten.hpp"
#include "bezel/image.hpp"
#include "bezel/raster.hpp"
#include "smooth_output.hpp"

namespace bezel::cli {
namespace {

constexpr double kDisplayPx = 600.0;
constexpr double kPi = 3.14159265358979323846;
constexpr const char* kColorCurve = "#1565c0";
constexpr const char* kColorPolygon = "#9e9e9e";
constexpr const char* kColorHandle = "#ab47bc";
constexpr const char* kColorPoint = "#c62828";

std::string f(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

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
        d << (i == 0 ? 'M' : 'L') << f(pts[i].x) << ' ' << f(pts[i].y);
    if (closed && pts.size() > 2) d << 'Z';
    return d.str();
}

// ---- PNG: strokes as polygons for the fill rasterizer -------------------------------------------

// Each polyline edge becomes a rectangle of half-width hw, extended by hw past both ends (square
// caps, which also fill the joints). All rectangles wind the same way, so NonZero unions them.
void stroke_polyline(const std::vector<Point>& pts, double hw, Polylines& out) {
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
        Vec2 d = pts[i + 1] - pts[i];
        double len = d.length();
        if (!(len > 0.0)) continue;
        Vec2 u = d / len * hw, n = u.perp();
        Point p = pts[i] - u, q = pts[i + 1] + u;
        for (Point v : {p + n, q + n, q - n, p - n}) out.points.push_back(v);
        out.contour_ends.push_back(out.points.size());
    }
}

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

Expected<Mask> fill(Rasterizer& raster, const Polylines& lines, int w, int h) {
    Mask m(w, h);
    auto st = raster.fill(lines, FillRule::NonZero, m.view());
    if (!st) return st.error();
    return m;
}

}  // namespace

std::string format_smooth_svg(const SmoothReport& r) {
    Rect box = frame_of(r);
    double size = std::max(box.width(), box.height());
    double u = size / kDisplayPx;
    double wpx = kDisplayPx * box.width() / size, hpx = kDisplayPx * box.height() / size;
    std::ostringstream s;
    s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << f(wpx) << "\" height=\"" << f(hpx)
      << "\" viewBox=\"" << f(box.x0) << ' ' << f(box.y0) << ' ' << f(box.width()) << ' '
      << f(box.height()) << "\">\n";
    s << "<title>bezel smooth --method " << r.method << ": " << r.input.size() << " points, "
      << (r.polyline ? r.points.size() : r.curve.segment_count())
      << (r.polyline ? " polygon points" : " pieces") << (r.closed ? ", closed" : "") << "</title>\n";
    s << "<rect x=\"" << f(box.x0) << "\" y=\"" << f(box.y0) << "\" width=\"" << f(box.width())
      << "\" height=\"" << f(box.height()) << "\" fill=\"white\"/>\n";
    // Input polygon: the control polygon of Chaikin and B-splines, the point order otherwise.
    s << "<path d=\"" << polygon_data(r.input, r.closed) << "\" fill=\"none\" stroke=\""
      << kColorPolygon << "\" stroke-width=\"" << f(u) << "\" stroke-dasharray=\"" << f(4 * u)
      << ' ' << f(3 * u) << "\"/>\n";
    auto hs = handles(r);
    if (!hs.empty()) {
        s << "<path d=\"";
        for (const auto& [a, b] : hs)
            s << 'M' << f(a.x) << ' ' << f(a.y) << 'L' << f(b.x) << ' ' << f(b.y);
        s << "\" fill=\"none\" stroke=\"" << kColorHandle << "\" stroke-width=\"" << f(0.75 * u)
          << "\"/>\n";
        for (const auto& h : hs)
            s << "<rect x=\"" << f(h.second.x - 2 * u) << "\" y=\"" << f(h.second.y - 2 * u)
              << "\" width=\"" << f(4 * u) << "\" height=\"" << f(4 * u) << "\" fill=\"white\" stroke=\""
              << kColorHandle << "\" stroke-width=\"" << f(0.75 * u) << "\"/>\n";
    }
    const std::string result = r.polyline ? polygon_data(r.points, r.closed) : to_svg_path(r.curve);
    s << "<path d=\"" << result << "\" fill=\"none\" stroke=\"" << kColorCurve
      << "\" stroke-width=\"" << f(2 * u) << "\" stroke-linejoin=\"round\"/>\n";
    for (std::size_t i = 0; i < r.input.size(); ++i) {
        const Point& p = r.input[i];
        s << "<circle cx=\"" << f(p.x) << "\" cy=\"" << f(p.y) << "\" r=\"" << f(3.5 * u)
          << "\" fill=\"" << kColorPoint << "\"><title>points[" << i << "] " << f(p.x) << ','
          << f(p.y) << "</title></circle>\n";
        s << "<text x=\"" << f(p.x + 5 * u) << "\" y=\"" << f(p.y - 5 * u) << "\" font-size=\""
          << f(11 * u) << "\" font-family=\"sans-serif\" fill=\"" << kColorPoint << "\">" << i
          << "</text>\n";
    }
    s << "</svg>\n";
    return s.str();
}

Expected<std::string> format_smooth_png(const SmoothReport& r) {
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

    Rasterizer raster;
    auto mc = fill(raster, curve, w, h), mp = fill(raster, polygon, w, h),
         mh = fill(raster, handle_lines, w, h), md = fill(raster, dots, w, h);
    for (auto* x : {&mc, &mp, &mh, &md})
        if (!*x) return x->error();

    // Ink: curve black, input polygon mid-gray, handles light gray, points dark; white paper.
    Mask out(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double ink = std::max({mc->at(x, y) / 255.0, 0.45 * mp->at(x, y) / 255.0,
                                   0.3 * mh->at(x, y) / 255.0, 0.8 * md->at(x, y) / 255.0});
            out.at(x, y) = static_cast<std::uint8_t>(std::lround(255.0 * (1.0 - ink)));
        }

    // write_png_gray writes files: go through a private temporary one, return its bytes.
    std::string tmpl = (std::filesystem::temp_directory_path() / "bezel-smooth-XXXXXX.png").string();
    int fd = ::mkstemps(tmpl.data(), 4);
    if (fd < 0) return Error{"cannot create a temporary file for the PNG"};
    ::close(fd);
    auto st = write_png_gray(tmpl, out.view());
    std::string bytes;
    if (st) {
        std::ifstream in(tmpl, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    std::filesystem::remove(tmpl);
    if (!st) return st.error();
    return bytes;
}

}  // namespace bezel::cli
