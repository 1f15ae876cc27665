// tools/bezel/stroke_output.hpp — what `bezel stroke` writes: the outline as SVG path data, an
// SVG picture (the outline filled, the source path on top) or a PNG through bezel's rasterizer.
#pragma once

#include <string>

#include "bezel/expected.hpp"
#include "bezel/image.hpp"
#include "bezel/geometry.hpp"
#include "bezel/path.hpp"
#include "bezel/stroke.hpp"
#include "picture.hpp"

namespace bezel::cli {

enum class StrokeFormat { Path, Svg, Png };

// Largest PNG side `bezel stroke` draws, in pixels; a bigger fitted picture is an error that
// suggests --size or --transform.
inline constexpr int kMaxStrokePngDim = 8192;

struct PngFrame {
    Affine transform;        // path units → pixels
    int width = 0, height = 0;  // 0: fit the canvas to the mapped outline plus a 2 px margin
};

// A standalone SVG: white paper, the outline filled (nonzero), the source path as a hairline.
std::string format_stroke_svg(const Path& source, const Path& outline, const StrokeStyle& style);

// The outline filled NonZero with overlaps resolved exactly (OverlapMode::Accurate: the
// outline's pieces overlap by design), painted in `colours` (picture.hpp: black on white by
// default, then an 8-bit gray PNG), as PNG bytes.
Expected<std::string> format_stroke_png(const Path& outline, const PngFrame& frame,
                                        const PictureColours& colours,
                                        const PngOptions& png);

}  // namespace bezel::cli
