#include "draw.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "bezel/image.hpp"
#include "bezel/raster.hpp"

namespace bezel::cli {

std::string svg_number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

SvgFrame svg_frame(const Rect& box) {
    const double size = std::max(box.width(), box.height());
    const double scale = kDisplayPx / size;
    std::string tag = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + svg_number(box.width() * scale) +
                      "\" height=\"" + svg_number(box.height() * scale) + "\" viewBox=\"" + svg_number(box.x0) +
                      ' ' + svg_number(box.y0) + ' ' + svg_number(box.width()) + ' ' +
                      svg_number(box.height()) + "\">\n";
    return {std::move(tag), size / kDisplayPx};
}

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

Expected<std::string> ink_png(const std::vector<InkLayer>& layers, int w, int h,
                              const PictureColours& colours,
                              const PngOptions& png) {
    Rasterizer raster;
    std::vector<Mask> masks;
    for (const InkLayer& layer : layers) {
        Mask m(w, h);
        auto st = raster.fill(*layer.shapes, m.view());  // NonZero
        if (!st) return st.error();
        masks.push_back(std::move(m));
    }
    Image out(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double ink = 0.0;
            for (std::size_t i = 0; i < layers.size(); ++i)
                ink = std::max(ink, layers[i].ink * masks[i].at(x, y) / 255.0);
            out.at(x, y) = paint(colours, ink);
        }
    return picture_png(out, colours.gray(), colours.translucent(), png);
}

}  // namespace bezel::cli
