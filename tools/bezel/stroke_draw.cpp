// The pictures of `bezel stroke` (see stroke_output.hpp).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "bezel/image.hpp"
#include "bezel/raster.hpp"
#include "draw.hpp"
#include "stroke_output.hpp"

namespace bezel::cli {
namespace {

constexpr int kMarginPx = 2;

const char* join_name(LineJoin j) {
    return j == LineJoin::Round ? "round" : j == LineJoin::Bevel ? "bevel" : "miter";
}
const char* cap_name(LineCap c) {
    return c == LineCap::Round ? "round" : c == LineCap::Square ? "square" : "butt";
}

}  // namespace

std::string format_stroke_svg(const Path& source, const Path& outline, const StrokeStyle& style) {
    Rect box = outline.bounds().union_with(source.bounds());
    if (box.is_empty()) box = {0, 0, 1, 1};
    double size = std::max({box.width(), box.height(), 1e-9});
    box = box.inflated(0.05 * size);
    const SvgFrame frame = svg_frame(box);
    const double u = frame.unit;
    std::ostringstream s;
    s << frame.open_tag;
    s << "<title>bezel stroke --width " << svg_number(style.width) << " --join "
      << join_name(style.join) << " --cap " << cap_name(style.cap);
    if (!style.dashes.empty()) {
        s << " --dash ";
        for (std::size_t i = 0; i < style.dashes.size(); ++i)
            s << (i ? "," : "") << svg_number(style.dashes[i]);
    }
    s << ": " << outline.contour_count() << " contours, " << outline.segment_count()
      << " segments</title>\n";
    s << "<rect x=\"" << svg_number(box.x0) << "\" y=\"" << svg_number(box.y0) << "\" width=\""
      << svg_number(box.width()) << "\" height=\"" << svg_number(box.height())
      << "\" fill=\"white\"/>\n";
    s << "<path d=\"" << to_svg_path(outline, 9) << "\" fill=\"#1565c0\" fill-opacity=\"0.85\""
      << " fill-rule=\"nonzero\"/>\n";
    s << "<path d=\"" << to_svg_path(source, 9) << "\" fill=\"none\" stroke=\"#c62828\""
      << " stroke-width=\"" << svg_number(u) << "\"/>\n";
    s << "</svg>\n";
    return s.str();
}

Expected<std::string> format_stroke_png(const Path& outline, const PngFrame& frame,
                                        const PictureColours& colours,
                                        const PngOptions& png) {
    Path mapped = outline.transformed(frame.transform);
    if (!mapped.is_finite()) return Error{"--transform: the mapped outline is not finite"};
    Affine to_canvas;
    int w = frame.width, h = frame.height;
    if (w == 0) {
        Rect b = mapped.bounds();
        if (b.is_empty()) b = {0, 0, 0, 0};
        double x0 = std::floor(b.x0) - kMarginPx, y0 = std::floor(b.y0) - kMarginPx;
        double fw = std::ceil(b.x1) + kMarginPx - x0, fh = std::ceil(b.y1) + kMarginPx - y0;
        if (fw > kMaxStrokePngDim || fh > kMaxStrokePngDim)
            return Error{"the outline is " + svg_number(fw) + "x" + svg_number(fh) +
                         " px, more than " + std::to_string(kMaxStrokePngDim) +
                         " px a side: scale it with --transform or crop it with --size"};
        w = static_cast<int>(fw);
        h = static_cast<int>(fh);
        to_canvas = Affine::translate({-x0, -y0});
    }
    Mask mask(w, h);
    Rasterizer raster;
    auto st = raster.fill_path(mapped, to_canvas, mask.view(),
                               {FillRule::NonZero, OverlapMode::Accurate});
    if (!st) return st.error();
    return picture_png(paint_coverage(mask.view(), colours), colours.gray(), colours.translucent(),
                       png);
}

}  // namespace bezel::cli
