// The pictures of `bezel intersect`: an SVG (both paths stroked, overlaps as bands, points as
// coloured rings) and the same picture as a gray PNG drawn with bezel's own rasterizer.
//
// Geometry stays in the paths' own units (y down). Stroke widths and ring sizes are measured in
// `u`, one display pixel: the picture is kDisplayPx display pixels on its longer side, so it
// looks the same whatever the paths' scale.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "bezel/flatten.hpp"
#include "draw.hpp"
#include "bezel/raster.hpp"
#include "intersect_output.hpp"

namespace bezel::cli {
namespace {

constexpr const char* kColorA = "#1565c0";
constexpr const char* kColorB = "#c62828";
constexpr const char* kColorOverlap = "#fbc02d";

const char* kind_color(IntersectionKind k) {
    switch (k) {
        case IntersectionKind::Cross: return "#000000";
        case IntersectionKind::Tangent: return "#ef6c00";
        case IntersectionKind::Endpoint: return "#2e7d32";
    }
    return "#000000";
}

// The drawing area: both paths' bounds with a margin; a unit box when there is nothing.
Rect frame_of(const IntersectReport& r) {
    Rect box = r.a.bounds();
    if (!r.self) box = box.union_with(r.b.bounds());
    if (box.is_empty()) box = {0, 0, 1, 1};
    double size = std::max({box.width(), box.height(), 1e-9 * std::fabs(box.x0), 1e-300});
    return box.inflated(0.06 * size);
}

// A path holding only the piece [t0, t1] of one segment (for overlap bands).
Path piece_path(const Path& path, std::size_t seg, double t0, double t1) {
    Curve c(path.segment(seg));
    Path p;
    switch (c.degree) {
        case 1: {
            Line l = Line{c.p[0], c.p[1]}.subsegment(t0, t1);
            p.move_to(l.p0);
            p.line_to(l.p1);
            break;
        }
        case 2: {
            QuadBez q = QuadBez{c.p[0], c.p[1], c.p[2]}.subsegment(t0, t1);
            p.move_to(q.p0);
            p.quad_to(q.p1, q.p2);
            break;
        }
        default: {
            CubicBez k = CubicBez{c.p[0], c.p[1], c.p[2], c.p[3]}.subsegment(t0, t1);
            p.move_to(k.p0);
            p.cubic_to(k.p1, k.p2, k.p3);
            break;
        }
    }
    return p;
}

// ---- PNG: strokes as polygons for the fill rasterizer -------------------------------------------

// Every segment of `path` (mapped by m to pixels), stroked.
void stroke_path(const Path& path, const Affine& m, double hw, Polylines& out) {
    Polylines flat;
    for (const PathSeg& seg : path.segments()) {
        Path one;
        one.move_to(seg.p[0]);
        switch (seg.kind) {
            case SegKind::Line: one.line_to(seg.p[1]); break;
            case SegKind::Quad: one.quad_to(seg.p[1], seg.p[2]); break;
            case SegKind::Cubic: one.cubic_to(seg.p[1], seg.p[2], seg.p[3]); break;
        }
        flat.clear();
        flatten(one, m, FlattenOptions{0.05}, flat);
        stroke_polyline(flat.points, hw, out);
    }
}

// A ring: outer circle one way, inner circle the other, so NonZero leaves the hole empty.
void ring(Point c, double r_out, double r_in, Polylines& out) {
    constexpr int kSides = 32;
    for (int k = 0; k < kSides; ++k) {
        double a = 2.0 * kPi * k / kSides;
        out.points.push_back(c + Vec2{std::cos(a), std::sin(a)} * r_out);
    }
    out.contour_ends.push_back(out.points.size());
    for (int k = kSides; k > 0; --k) {
        double a = 2.0 * kPi * k / kSides;
        out.points.push_back(c + Vec2{std::cos(a), std::sin(a)} * r_in);
    }
    out.contour_ends.push_back(out.points.size());
}

}  // namespace

std::string format_intersect_svg(const IntersectReport& r) {
    Rect box = frame_of(r);
    const SvgFrame frame = svg_frame(box);
    const double u = frame.unit;
    std::ostringstream s;
    s << frame.open_tag;
    s << "<title>bezel intersect: " << r.result.intersections.size() << " intersections, "
      << r.result.overlaps.size() << " overlaps</title>\n";
    s << "<rect x=\"" << svg_number(box.x0) << "\" y=\"" << svg_number(box.y0) << "\" width=\"" << svg_number(box.width())
      << "\" height=\"" << svg_number(box.height()) << "\" fill=\"white\"/>\n";
    const Path& b = r.self ? r.a : r.b;
    for (const PathOverlap& o : r.result.overlaps) {
        double lo = std::min(o.t_a0, o.t_a1), hi = std::max(o.t_a0, o.t_a1);
        s << "<path d=\"" << to_svg_path(piece_path(r.a, o.seg_a, lo, hi)) << "\" fill=\"none\" stroke=\""
          << kColorOverlap << "\" stroke-opacity=\"0.6\" stroke-width=\"" << svg_number(8 * u)
          << "\" stroke-linecap=\"round\"/>\n";
    }
    s << "<path d=\"" << to_svg_path(r.a) << "\" fill=\"none\" stroke=\"" << kColorA
      << "\" stroke-width=\"" << svg_number(1.5 * u) << "\"/>\n";
    if (!r.self)
        s << "<path d=\"" << to_svg_path(b) << "\" fill=\"none\" stroke=\"" << kColorB
          << "\" stroke-width=\"" << svg_number(1.5 * u) << "\"/>\n";
    for (const PathIntersection& p : r.result.intersections)
        s << "<circle cx=\"" << svg_number(p.point.x) << "\" cy=\"" << svg_number(p.point.y) << "\" r=\"" << svg_number(5 * u)
          << "\" fill=\"none\" stroke=\"" << kind_color(p.kind) << "\" stroke-width=\"" << svg_number(1.5 * u)
          << "\"><title>" << intersection_kind_name(p.kind) << ": A seg " << p.seg_a << " t=" << p.t_a
          << ", " << (r.self ? "A" : "B") << " seg " << p.seg_b << " t=" << p.t_b
          << "</title></circle>\n";
    s << "</svg>\n";
    return s.str();
}

Expected<std::string> format_intersect_png(const IntersectReport& r,
                                           const PictureColours& colours,
                                           const PngOptions& png) {
    Rect box = frame_of(r);
    double size = std::max(box.width(), box.height());
    double scale = kIntersectPngSizePx / size;
    int w = std::max(1, static_cast<int>(std::ceil(box.width() * scale)));
    int h = std::max(1, static_cast<int>(std::ceil(box.height() * scale)));
    Affine m = Affine::scale(scale) * Affine::translate({-box.x0, -box.y0});

    Polylines la, lb, lo, lm;
    stroke_path(r.a, m, 0.75, la);
    if (!r.self) stroke_path(r.b, m, 0.75, lb);
    for (const PathOverlap& o : r.result.overlaps)
        stroke_path(piece_path(r.a, o.seg_a, std::min(o.t_a0, o.t_a1), std::max(o.t_a0, o.t_a1)), m,
                    4.0, lo);
    for (const PathIntersection& p : r.result.intersections) ring(m * p.point, 5.0, 3.5, lm);
    // Ink: A black, B mid-gray, overlap bands light gray, rings black; white paper.
    return ink_png({{&la, 1.0}, {&lb, 0.55}, {&lo, 0.3}, {&lm, 1.0}}, w, h, colours, png);
}

}  // namespace bezel::cli
