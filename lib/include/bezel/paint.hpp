// bezel/paint.hpp — colour glyphs as paint graphs (OpenType COLR versions 0 and 1), and the painter
// that draws them through bezel's rasterizer into premultiplied RGBA.
//
// A ColorGlyph is a value: the paint graph of one glyph, built by the font module
// (bezel/color_glyph.hpp) from the font's COLR and CPAL tables, with every palette colour already
// resolved and every outline it clips to already loaded. The painter needs no font.
//
// Glyph space: FONT UNITS, y UP, the glyph's origin at (0, 0), as the COLR table states every
// coordinate. PaintOptions::transform maps glyph space to target pixels (y down); for a glyph at
// size s px in a font of `upem` units per em, with its pen at p: Affine{s/upem, 0, 0, −s/upem, p.x, p.y}.
//
// Colour space: painting follows the COLR specification, which takes its compositing from W3C
// Compositing and Blending Level 1 on sRGB-ENCODED values, as Skia (Chromium's COLRv1 renderer)
// does: every layer is premultiplied RGBA in sRGB-encoded values, and the anti-aliased coverage
// of a PaintGlyph clip multiplies a layer's premultiplied colour. (bezel's page blending is
// linear light, image.hpp; a finished colour glyph is one more piece of ink on the page.)
// Gradients interpolate the STRAIGHT (unpremultiplied) sRGB-encoded colour and alpha between two
// stops and premultiply the result, as Skia does for COLRv1 (its FreeType port makes each colour
// line an SkGradientShader without kInterpolateColorsInPremul_Flag): bezel is checked against
// Chromium's rendering. The CPAL section of the specification asks for interpolation of
// premultiplied linear-light values instead, which differs between stops of different alpha
// (premultiplied) and between distinct colours (linear light): docs/colour.md compares them.
//
// Threading: a Painter holds scratch memory; one Painter must not be used from two threads at once.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <variant>
#include <vector>

#include "bezel/expected.hpp"
#include "bezel/geometry.hpp"
#include "bezel/image.hpp"
#include "bezel/path.hpp"
#include "bezel/raster.hpp"

#pragma GCC visibility push(default)  // the public API of libbezel.so (docs/architecture.md)
namespace bezel {

// --- Premultiplied RGBA targets ------------------------------------------------------------------
// Four bytes per pixel in memory order R, G, B, A, PREMULTIPLIED (each colour byte ≤ alpha),
// sRGB-encoded colour. `stride` is in BYTES from one row to the next (≥ 4·width, or negative for
// bottom-up memory). What a colour glyph is drawn into (a toolkit's RGBA atlas).
struct RgbaView {
    std::uint8_t* data = nullptr;
    int width = 0, height = 0;
    std::ptrdiff_t stride = 0;

    std::uint8_t* row(int y) const { return data + static_cast<std::ptrdiff_t>(y) * stride; }
    std::uint8_t* pixel(int x, int y) const { return row(y) + 4 * static_cast<std::ptrdiff_t>(x); }
    RgbaView sub(int x, int y, int w, int h) const { return {pixel(x, y), w, h, stride}; }
};
struct ConstRgbaView {
    const std::uint8_t* data = nullptr;
    int width = 0, height = 0;
    std::ptrdiff_t stride = 0;

    ConstRgbaView() = default;
    ConstRgbaView(const std::uint8_t* d, int w, int h, std::ptrdiff_t s)
        : data(d), width(w), height(h), stride(s) {}
    ConstRgbaView(const RgbaView& v)  // NOLINT: a writable view is readable
        : data(v.data), width(v.width), height(v.height), stride(v.stride) {}
    const std::uint8_t* row(int y) const { return data + static_cast<std::ptrdiff_t>(y) * stride; }
    const std::uint8_t* pixel(int x, int y) const {
        return row(y) + 4 * static_cast<std::ptrdiff_t>(x);
    }
};

// Straight (not premultiplied) sRGB-encoded colour, each channel in [0, 1].
struct ColorF {
    float r = 0, g = 0, b = 0, a = 1;
    bool operator==(const ColorF& o) const { return r == o.r && g == o.g && b == o.b && a == o.a; }
    bool operator!=(const ColorF& o) const { return !(*this == o); }
};

// A colour as a paint names it: a palette entry (resolved into `color` when the graph is built),
// or the text's foreground colour (COLR palette index 0xFFFF), times `alpha` in [0, 1].
struct PaintColor {
    ColorF color;            // the palette entry; unused when `foreground`
    bool foreground = false;
    float alpha = 1;
};

// --- The paint graph (COLR version 1; version 0 is a PaintLayers of PaintGlyph(PaintSolid)) --------
enum class Extend : std::uint8_t { Pad, Repeat, Reflect };

struct ColorStop {
    float offset = 0;   // along the colour line; any finite value (the spec does not clamp stops)
    PaintColor color;
};
// Stops sorted by offset (stable: equal offsets keep their order, a hard edge). At least one stop.
// When every stop has the same offset, Pad is a hard edge there and Repeat or Reflect paints
// nothing (there is no span to repeat; Chromium draws nothing too).
struct ColorLine {
    Extend extend = Extend::Pad;
    std::vector<ColorStop> stops;
};

// Every compositing mode of COLR version 1 (PaintComposite), in the table's order (the enumerator
// value is the spec's CompositeMode number). Porter-Duff: Clear … Plus; separable blend modes:
// Screen … Multiply; non-separable: Hue … Luminosity (W3C Compositing and Blending Level 1).
enum class CompositeMode : std::uint8_t {
    Clear, Src, Dest, SrcOver, DestOver, SrcIn, DestIn, SrcOut, DestOut, SrcAtop, DestAtop, Xor,
    Plus, Screen, Overlay, Darken, Lighten, ColorDodge, ColorBurn, HardLight, SoftLight,
    Difference, Exclusion, Multiply, Hue, Saturation, Color, Luminosity,
};
inline constexpr int kCompositeModeCount = 28;
// The spec's name ("src_over", "color_dodge", …).
const char* composite_mode_name(CompositeMode mode);

// Nodes refer to each other by index into ColorGlyph::nodes.
using PaintIndex = std::uint32_t;

// The layers painted bottom to top, each composited SrcOver onto those below (PaintColrLayers).
struct PaintLayers {
    std::vector<PaintIndex> layers;
};
struct PaintSolid {
    PaintColor color;
};
// The colour at point p is the colour line at t, where t is the projection of p − p0 onto the
// line through p0 perpendicular to p2 − p0, measured so that t = 0 at p0 and 1 at p1's foot
// (the spec's p0, p1, p2 construction). p0 = p1, or p2 on the line p0 p1, paints nothing.
struct PaintLinearGradient {
    ColorLine line;
    Point p0, p1, p2;
};
// Two circles, as the spec (and HTML canvas's createRadialGradient): the colour at p is that of
// the largest t with r(t) = r0 + t·(r1 − r0) ≥ 0 and |p − c(t)| = r(t), c(t) = c0 + t·(c1 − c0),
// t extended by the colour line's extend mode; no such t paints nothing.
struct PaintRadialGradient {
    ColorLine line;
    Point c0, c1;
    double r0 = 0, r1 = 0;   // ≥ 0
};
// Angles in DEGREES, counter-clockwise in glyph space (y up) from the positive x axis: the colour
// at p is the colour line at t = (angle(p − center) − start) / (end − start), the angle taken in
// [0, 360); start = end paints nothing unless the line pads.
struct PaintSweepGradient {
    ColorLine line;
    Point center;
    double start_deg = 0, end_deg = 360;
};
// `paint` clipped to the glyph's outline (nonzero fill, anti-aliased).
struct PaintGlyph {
    std::uint32_t outline = 0;   // index into ColorGlyph::outlines
    PaintIndex paint = 0;
};
// `paint` with glyph space mapped by `transform` first (PaintTransform, and the Translate,
// Scale, Rotate and Skew forms with or without a centre, each converted to the one matrix).
struct PaintTransform {
    Affine transform;
    PaintIndex paint = 0;
};
// Another colour glyph's graph reused (PaintColrGlyph), clipped to that glyph's clip box when it
// has one.
struct PaintColrGlyph {
    PaintIndex paint = 0;
    std::optional<Rect> clip;   // glyph space
};
// `source` composited onto `backdrop` (each painted into a layer of its own) by `mode`; the
// result composited SrcOver onto what is below.
struct PaintComposite {
    PaintIndex source = 0, backdrop = 0;
    CompositeMode mode = CompositeMode::SrcOver;
};
using PaintNode = std::variant<PaintLayers, PaintSolid, PaintLinearGradient, PaintRadialGradient,
                               PaintSweepGradient, PaintGlyph, PaintTransform, PaintColrGlyph,
                               PaintComposite>;

// One colour glyph's paint graph. Nodes may be shared (a PaintColrGlyph reused, a layer list
// referenced twice), so the graph is a DAG; it is painted from `root`. Invariants (the builder's
// and validate()'s): every index is in range, and the graph has no cycle.
struct ColorGlyph {
    std::vector<PaintNode> nodes;
    PaintIndex root = 0;
    std::vector<Path> outlines;   // glyph space (font units, y up), closed contours
    std::optional<Rect> clip;     // the glyph's ClipBox, glyph space; none: unbounded
    // A PaintColor with `foreground` occurs: the pixels depend on the text colour (a cache keys on
    // it only then).
    bool uses_foreground = false;
};

// Checks the invariants above, and that painting `glyph` visits at most kMaxPaintNodes nodes at
// most kMaxPaintDepth deep (counting shared nodes each time they are reached). Errors say which:
// "paint graph loops at node N", "nests deeper than 64", "visits more than … nodes".
Status validate(const ColorGlyph& glyph);

// The glyph-space box the graph can ink: its clip box when it has one, else the union of the
// boxes of the outlines its PaintGlyph nodes reach, each mapped by the transforms above it (and
// narrowed to the clip boxes of the PaintColrGlyph nodes above it); empty
// when nothing can be inked. A graph that validate() refuses has an empty box.
Rect paint_bounds(const ColorGlyph& glyph);

struct PaintOptions {
    Affine transform;                  // glyph space → target pixels (see the top of this file)
    Rgba8 foreground{0, 0, 0, 255};    // palette index 0xFFFF
    // Flattening of the PaintGlyph outlines, in target pixels, as every fill (raster.hpp).
    FlattenOptions flatten = raster_flatten_defaults();
};

// Paints colour glyphs. Allocates nothing once its scratch (a few float RGBA layers of the target's
// size, two per level of nested PaintComposite, and a float coverage mask per level of nested clip,
// all bounded by the graph's depth) has grown to the largest target and graph used.
// A fill outside every PaintGlyph and clip box (the specification forbids it: "bounded layers
// only") covers the whole target. A subtree whose transform collapses the plane (determinant 0)
// paints nothing.
class Painter {
public:
    Painter();
    ~Painter();
    Painter(Painter&&) noexcept;
    Painter& operator=(Painter&&) noexcept;
    Painter(const Painter&) = delete;
    Painter& operator=(const Painter&) = delete;

    // Paints `glyph` into `target`, writing EVERY pixel of it (transparent where nothing is
    // painted): premultiplied RGBA8, rounded from float. Errors leave the target unchanged:
    // validate()'s, a transform that is not finite or not invertible, a target dimension negative or
    // > kMaxBitmapDim, a null target with nonzero size, and the rasterizer's for an outline.
    Status paint(const ColorGlyph& glyph, const PaintOptions& options, const RgbaView& target);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// --- Colour bitmaps (CBDT/CBLC, sbix) --------------------------------------------------------------
// How a colour bitmap strike is scaled to the requested size. Both filter in LINEAR light on
// premultiplied values (each sample's colour decoded from sRGB, weighted by its alpha), so a
// shrunk emoji keeps its brightness and its edges no dark fringe.
//   Box:      each target pixel is the area-weighted mean of the source pixels under it (exact
//             for shrinking, the default; when enlarging it is a nearest-pixel view with
//             anti-aliased pixel edges).
//   Bilinear: the source sampled at each target pixel's centre, bilinearly (for enlarging).
enum class BitmapFilter : std::uint8_t { Box, Bilinear };

// Scales the premultiplied RGBA `source` to fill `target` (each dimension scaled on its own),
// writing every pixel of the target. Empty views write nothing.
void scale_rgba(ConstRgbaView source, const RgbaView& target, BitmapFilter filter);

// Converts premultiplied RGBA to straight-alpha Rgba8 (an Image, for PNG output), and back.
// Precondition of premultiply: the target is the image's size.
Image to_image(ConstRgbaView premultiplied);
void premultiply(const Image& image, const RgbaView& target);

// Composites a finished colour glyph (premultiplied RGBA) "over" `page` with its top-left pixel at
// (x, y), parts outside the page clipped, in linear light as blend_mask does (image.hpp): each
// channel out = enc(dec(src_straight)·α + dec(dst)·(1 − α)), α the glyph's alpha, page alpha
// composited over. `opacity` in [0, 1] scales α (a faded text colour's alpha).
void blend_rgba(Image& page, ConstRgbaView glyph, int x, int y, float opacity = 1);

}  // namespace bezel
#pragma GCC visibility pop
