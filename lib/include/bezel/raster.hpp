// bezel/raster.hpp — anti-aliased coverage rasterization of filled polygons and paths.
//
// Coverage is EXACT AREA: a pixel's value is the area of the pixel square covered by the fill,
// computed analytically from the polygon's edges (signed area and cover per cell, the
// libart / FreeType "smooth" / font-rs formulation), not by supersampling. For a path, the only
// approximation is flattening, whose distance bound the caller chooses (`tolerance_px`).
//
// Coordinates: pixels, y DOWN. Pixel (x, y) of a target is the square [x, x+1] × [y, y+1]; a
// point p (of the polylines, or of the path after its transform) lands at p + origin in target
// pixels (FillOptions::origin; a fractional origin positions a glyph at a subpixel offset).
//
// Every fill takes one FillOptions (rule, overlap mode, flattening, origin, coverage format, LCD
// order and filter); a combination a fill does not implement is an Error naming it, never a
// silent substitute.
//
// Clipping is exact: parts of the fill outside the target are dropped, and edges LEFT of the
// target still contribute their cover, so a shape that starts left of the target renders inside
// it as it would in a larger target. Coordinates far outside the target, up to the largest
// finite double, are clipped in double precision without overflow; a NaN or infinite coordinate
// is an Error and leaves the target untouched.
//
// Threading: a Rasterizer holds reusable scratch memory and must not be used by two threads at
// once; separate Rasterizers are independent and may run on separate threads.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "bezel/expected.hpp"
#include "bezel/flatten.hpp"
#include "bezel/geometry.hpp"
#include "bezel/image.hpp"
#include "bezel/limits.hpp"
#include "bezel/path.hpp"

#pragma GCC visibility push(default)  // the public API of libbezel.so (docs/architecture.md)
namespace bezel {

// How winding numbers become coverage.
//   NonZero: coverage = min(|accumulated signed area|, 1)
//   EvenOdd: coverage = triangle wave of the accumulated area with period 2, so a region wound
//            twice (an inner loop drawn in the same direction) is empty.
// Both use plain area accumulation: where two contours OVERLAP inside one pixel with the same
// orientation, the partial pixel is over-counted (clamped at 1) — FreeType's default behaviour.
enum class FillRule : std::uint8_t { NonZero, EvenOdd };

// Flattening tolerance of every fill unless told otherwise: 0.01 px. Exact-area coverage leaves
// flattening as the only geometric error: at 0.01 px the mean coverage error is at the 8-bit
// rounding floor, and the worst pixel errs by about tol·255 (≈ 2.5/255), which is what keeps the
// tolerance from growing. The measurements are in docs/perf-log.md.
inline constexpr double kDefaultRasterTolerancePx = 0.01;
inline FlattenOptions raster_flatten_defaults() {
    FlattenOptions o;
    o.tolerance_px = kDefaultRasterTolerancePx;
    return o;
}

// --- Overlapping contours ----------------------------------------------------------------------
// How coverage is formed where contours overlap (variable fonts and glyphs the font marks with
// OVERLAP_SIMPLE / OVERLAP_COMPOUND, FreeType's FT_OUTLINE_OVERLAP).
//   Accumulate: plain signed-area accumulation, exact for non-overlapping contours; where two
//               contours' anti-aliased edges overlap inside one pixel their partial coverages
//               add, which over-darkens that pixel (FreeType's default behaviour).
//   Accurate:   the overlap is resolved before coverage is formed, so an overlapped edge pixel is
//               as dark as the union of the shapes covers it (within the error stated at the
//               implementation). Slower; the default for glyphs with overlapping_contours.
enum class OverlapMode : std::uint8_t { Accumulate, Accurate };

// --- LCD subpixel rendering ---------------------------------------------------------------------
// (LcdOrder, the panel's subpixel order, is declared in image.hpp: blending uses it too.)
// A 5-tap FIR filter applied horizontally to coverage sampled at 3× horizontal resolution, in
// 1/256 units (sum 256 for a filter that keeps total coverage).
struct LcdFilter {
    std::array<std::uint8_t, 5> taps;
};
// FreeType's default (FT_LCD_FILTER_DEFAULT): 0x08 0x4D 0x56 0x4D 0x08, sum 256.
inline constexpr LcdFilter kLcdFilterDefault{{0x08, 0x4D, 0x56, 0x4D, 0x08}};
// Extra display pixels an LCD rendering needs on each side of the outline's box: the filter
// spreads coverage two subpixels out.
inline constexpr int kLcdPaddingPx = 1;

// What a fill writes into a MaskView.
//   Gray: one byte per pixel, round(coverage·255).
//   Lcd:  3 bytes per DISPLAY pixel (FreeType's FT_PIXEL_MODE_LCD layout: `target.width` is 3 ×
//         the display width, and the bytes of a display pixel are always R, G, B in memory,
//         whatever the panel's order). The fill is sampled at 3× horizontal resolution (subpixel
//         k covers display x in [k/3, (k+1)/3]), filtered by FillOptions::lcd_filter, and each
//         colour takes the subpixel its panel lights: on an Rgb panel R is the left third, on a
//         Bgr panel the right third (the Bgr bytes are the Rgb bytes reversed within each pixel).
enum class CoverageFormat : std::uint8_t { Gray, Lcd };

// Every choice a fill makes. Each default is the plain fill: NonZero, Accumulate, flattening at
// kDefaultRasterTolerancePx with WangUniform, no origin shift, gray coverage.
struct FillOptions {
    FillRule rule = FillRule::NonZero;
    // Accurate is implemented for fill_path (either target type); fill of polylines is Accumulate
    // only.
    OverlapMode overlap = OverlapMode::Accumulate;
    // How fill_path flattens curves, in target pixels after the transform. fill ignores it (its
    // polylines are already flat).
    FlattenOptions flatten = raster_flatten_defaults();
    // Added to every point after the transform, in target pixels (y down): a polyline point p
    // lands at p + origin, a fractional origin places the fill at a subpixel offset. For
    // fill_path it is exactly the transform with origin added to its translation (the same
    // bits); in Lcd format it is in display pixels. Must be finite.
    Vec2 origin{};
    // Lcd is implemented for fill_path into a MaskView only.
    CoverageFormat format = CoverageFormat::Gray;
    LcdOrder lcd_order = LcdOrder::Rgb;         // Lcd only: the panel's subpixel order
    LcdFilter lcd_filter = kLcdFilterDefault;   // Lcd only
};

// --- Gamma / contrast ---------------------------------------------------------------------------
// Coverage from the rasterizer is LINEAR (area fraction). A compositor that blends in a non-linear
// space (sRGB bytes, as most toolkits do) can map coverage through this table first to get
// stroke weights close to blending in linear light. `gamma` > 0 (1 = identity); `contrast` in
// [0, 1] raises mid coverage further (0 = none). Formula at the implementation.
class GammaTable {
public:
    explicit GammaTable(double gamma = 1.0, double contrast = 0.0);
    std::uint8_t operator()(std::uint8_t coverage) const { return table_[coverage]; }
    void apply(const MaskView& mask) const;   // in place, every pixel
    const std::array<std::uint8_t, 256>& table() const { return table_; }

private:
    std::array<std::uint8_t, 256> table_{};
};

class Rasterizer {
public:
    Rasterizer();
    ~Rasterizer();
    Rasterizer(const Rasterizer&) = delete;             // scratch memory is not shared by accident
    Rasterizer& operator=(const Rasterizer&) = delete;
    Rasterizer(Rasterizer&&) noexcept;
    Rasterizer& operator=(Rasterizer&&) noexcept;

    // Fills the closed polygons `lines` (each contour closed implicitly), moved by
    // `options.origin`, into `target` with `options.rule`, writing EVERY pixel of the target (0
    // where nothing covers it: clearing is part of the call): 8-bit alpha round(coverage·255)
    // into a MaskView, coverage in [0, 1] (not quantized) into a FloatMaskView.
    // Errors, each leaving the target unchanged: an option this fill does not implement
    // (OverlapMode::Accurate or CoverageFormat::Lcd, named in the message), a target dimension
    // negative or > kMaxBitmapDim, a null target with nonzero size, more than kMaxEdges
    // segments, contour_ends inconsistent with points, a NaN or infinite point or origin.
    // Allocates nothing once its scratch has grown to the largest target used.
    Status fill(const Polylines& lines, const MaskView& target, const FillOptions& options = {});
    Status fill(const Polylines& lines, const FloatMaskView& target,
                const FillOptions& options = {});

    // Flattens `path` mapped by `transform` (to target pixels; then moved by `options.origin`)
    // with `options.flatten` into a reused internal Polylines, then fills it as above, in
    // `options.format` with `options.overlap`. For FlattenMethod::WangUniform the vertices are
    // error-balanced (same step count and distance bound, zero mean area error per chord), so the
    // polyline differs from flatten()'s. When the path's pixel box is narrow (at most 93 px
    // wide: glyphs at text sizes), those vertices are rounded to float relative to the box before
    // they are drawn, which moves each by at most 2⁻²⁴ of the box's larger side (under 4e-6 px in
    // a box under 64 px) and a pixel's coverage by no more.
    // CoverageFormat::Lcd: `transform` maps to DISPLAY pixels and the caller leaves
    // kLcdPaddingPx display pixels of room on each side of the outline.
    // Errors, each leaving the target unchanged: CoverageFormat::Lcd into a FloatMaskView (not
    // implemented, named in the message), a target or origin fill would refuse, a transform that
    // is not finite, a path point that is not finite or beyond kMaxFlattenCoordinatePx after it,
    // a path that would flatten to more than kMaxEdges segments (estimated by Wang's bound before
    // flattening, so nothing is allocated for it), and in Lcd format a target width that is not
    // a multiple of 3.
    // Allocates nothing once its scratch has grown to the largest target and path used.
    Status fill_path(const Path& path, const Affine& transform, const MaskView& target,
                     const FillOptions& options = {});
    Status fill_path(const Path& path, const Affine& transform, const FloatMaskView& target,
                     const FillOptions& options = {});

    // Bytes of scratch memory currently held (for tests of the no-allocation promise).
    std::size_t scratch_capacity_bytes() const;

private:
    struct FeatureScratch;  // LCD and accurate-overlap scratch (src/raster/overlap.hpp)

    template <typename View>
    Status fill_impl(const Polylines& lines, FillRule rule, const View& target, Vec2 origin);
    template <typename View>
    Status fill_path_impl(const Path& path, const Affine& transform, FillRule rule,
                          const View& target, const FlattenOptions& flatten_options);
    template <typename View>
    Status fill_path_gray(const Path& path, const Affine& transform, const View& target,
                          const FillOptions& options);
    Status fill_path_lcd(const Path& path, const Affine& transform, const MaskView& target,
                         const FillOptions& options);
    FeatureScratch& features();

    std::vector<float> acc_;            // per-band cell deltas; all zero between calls
    std::vector<std::uint8_t> flags_;   // per-band "block has deltas" marks; all zero between calls
    Polylines flattened_;               // fill_path's reused polylines
    std::unique_ptr<FeatureScratch> features_;  // made on first use
};

}  // namespace bezel
#pragma GCC visibility pop
