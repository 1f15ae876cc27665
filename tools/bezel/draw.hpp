// tools/bezel/draw.hpp — the drawing pieces the CLI's pictures share (smooth, intersect,
// stroke): the SVG frame and numbers, strokes as fillable polygons, and layered gray PNGs
// through bezel's own rasterizer.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "bezel/expected.hpp"
#include "bezel/image.hpp"
#include "bezel/flatten.hpp"
#include "picture.hpp"

namespace bezel::cli {

// The pictures' scale: kDisplayPx display pixels on the longer side, whatever the input's units;
// stroke widths and dot sizes are counted in display pixels, so pictures look alike.
inline constexpr double kDisplayPx = 600.0;
inline constexpr double kPi = 3.14159265358979323846;

// A number for SVG attributes and path data: 6 significant digits ("%.6g").
std::string svg_number(double v);

// A picture of `box` (the input's units, y down; not empty): `open_tag` is the <svg> element's
// opening tag, with `box` as the viewBox and kDisplayPx display pixels on the longer side;
// `unit` is one display pixel in the input's units, for stroke widths and dot sizes.
struct SvgFrame {
    std::string open_tag;
    double unit;
};
SvgFrame svg_frame(const Rect& box);

// Each polyline edge becomes a rectangle of half-width hw, extended by hw past both ends (square
// caps, which also fill the joints). All rectangles wind the same way, so NonZero unions them.
void stroke_polyline(const std::vector<Point>& pts, double hw, Polylines& out);

// One layer of a picture: its shapes (filled NonZero) and how dark full coverage inks (0..1).
struct InkLayer {
    const Polylines* shapes;
    double ink;
};

// Fills every layer into a w×h mask, inks each pixel with the darkest layer (max of ink ×
// coverage) in `colours` (picture.hpp: black on white, a gray PNG, by default), and returns the
// PNG file's bytes. Errors come from the rasterizer or from encoding the PNG.
Expected<std::string> ink_png(const std::vector<InkLayer>& layers, int w, int h,
                              const PictureColours& colours,
                              const PngOptions& png);

}  // namespace bezel::cli
