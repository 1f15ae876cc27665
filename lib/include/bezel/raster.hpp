// bezel/raster.hpp — anti-aliased coverage rasterization of filled polygons and paths.
//
// Coverage is EXACT AREA: a pixel's value is the area of the pixel square covered by the fill,
// computed analytically from the polygon's edges (signed area and cover per cell, the
// libart / FreeType "smooth" / font-rs formulation), not by supersampling. For a path, the only
// approximation is flattening, whose distance bound the caller chooses (`tolerance_px`).
//
// Coordinates: pixels, y DOWN. Pixel (x, y) of a target is the square [x, x+1] × [y, y+1]; a
// polygon point p lands at p + origin in target pixels (a fractional origin positions a glyph
// at a subpixel offset). Any affine transform goes into the path convenience or into the
// polylines themselves.
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

namespace bezel {

// How winding numbers become coverage.
//   NonZero: coverage = min(|accumulated signed area|, 1)
//   EvenOdd: coverage = triangle wave of the accumulated area with period 2, so a region wound
//            twice (an inner loop drawn in the same direction) is empty.
// Both use plain area accumulation: where two contours OVERLAP inside one pixel with the same
// orientation, the partial pixel is over-counted (clamped at 1) — FreeType's default behaviour.
enum class FillRule : std::uint8_t { NonZero, EvenOdd };

// Flattening tolerance fill_path uses unless told otherwise: 0.01 px. Why: exact-area coverage
// leaves flattening as the only geometric error (chords cut inside convex curves, always the same
// way), and on the test fonts the mean coverage error against the 16×-supersampled reference at
// 12 px (tools/bench/raster_bench --accuracy) is 1.29/255 at flatten's general default of 1/16 px,
// 0.70/255 at 0.03, 0.46/255 at 1/64 and 0.25/255 at 0.01 px — the last is 8-bit rounding alone
// (max 1.7/255). The cost is ~1.75× the segments of 1/16 px (segments grow as 1/√tol).
// Those figures are for plain chords; fill_path's WangUniform flattening now places vertices so
// each chord's mean area error is zero (src/raster/render_flatten.hpp), giving 0.19/255 mean at
// 0.01 px (DejaVu, 12 px, all ASCII). The max (≈ tol·255 in the worst pixel) still pins the
// tolerance: 0.015 px already reaches 3.1/255 at 96 px.
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
// Order of the subpixels in a display pixel, left to right.
enum class LcdOrder : std::uint8_t { Rgb, Bgr };
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

namespace raster_detail {
struct FeatureScratch;  // src/raster/overlap.hpp: scratch of the LCD and accurate-overlap fills
void release(FeatureScratch* scratch);
}  // namespace raster_detail

// The SIMD level of the coverage sweep chosen for this CPU at run time: "avx2" or "sse2".
const char* raster_kernel_name();

class Rasterizer {
public:
    Rasterizer() = default;
    Rasterizer(const Rasterizer&) = delete;             // scratch memory is not shared by accident
    Rasterizer& operator=(const Rasterizer&) = delete;
    Rasterizer(Rasterizer&&) noexcept = default;
    Rasterizer& operator=(Rasterizer&&) noexcept = default;

    // Fills the closed polygons `lines` (each contour closed implicitly) into `target`, writing
    // EVERY pixel of the target (0 where nothing covers it: clearing is part of the call), as
    // 8-bit alpha round(coverage·255). Errors, each leaving the target unchanged: a target
    // dimension negative or > kMaxBitmapDim, a null target with nonzero size, more than
    // kMaxEdges segments, contour_ends inconsistent with points, a NaN or infinite point or
    // origin. Allocates nothing once its scratch has grown to the largest target used.
    Status fill(const Polylines& lines, FillRule rule, const MaskView& target, Vec2 origin = {});
    // The same, writing float coverage in [0, 1] (not quantized).
    Status fill(const Polylines& lines, FillRule rule, const FloatMaskView& target,
                Vec2 origin = {});

    // Flattens `path` mapped by `transform` (to target pixels) with `flatten_options` into a
    // reused internal Polylines, then fills it as above. For FlattenMethod::WangUniform the
    // vertices are error-balanced (same step count and distance bound, zero mean area error per
    // chord), so the polyline differs from flatten()'s. When the path's pixel box is narrow (at
    // most 93 px wide: glyphs at text sizes), those vertices are rounded to float relative to
    // the box before they are drawn, which moves each by at most 2⁻²⁴ of the box's larger side
    // (under 4e-6 px in a box under 64 px) and a pixel's coverage by no more. Errors as above,
    // plus a transform that is not finite, and a path that would flatten to more than kMaxEdges
    // segments (estimated by Wang's bound before flattening, so nothing is allocated for it).
    Status fill_path(const Path& path, const Affine& transform, FillRule rule,
                     const MaskView& target,
                     const FlattenOptions& flatten_options = raster_flatten_defaults());
    Status fill_path(const Path& path, const Affine& transform, FillRule rule,
                     const FloatMaskView& target,
                     const FlattenOptions& flatten_options = raster_flatten_defaults());

    // fill_path with a choice of overlap handling (OverlapMode::Accumulate is fill_path).
    Status fill_path(const Path& path, const Affine& transform, FillRule rule,
                     OverlapMode overlap, const MaskView& target,
                     const FlattenOptions& flatten_options = raster_flatten_defaults());

    // LCD subpixel coverage: the path (mapped by `transform` to DISPLAY pixels) is sampled at 3×
    // horizontal resolution, filtered by `filter`, and written as 3 bytes per display pixel in
    // `order`: `target.width` is 3 × the display width (FreeType's FT_PIXEL_MODE_LCD layout).
    // The caller leaves kLcdPaddingPx display pixels of room on each side of the outline. Errors
    // as fill_path, plus a target width that is not a multiple of 3.
    Status fill_path_lcd(const Path& path, const Affine& transform, FillRule rule, LcdOrder order,
                         const MaskView& target, OverlapMode overlap = OverlapMode::Accumulate,
                         const LcdFilter& filter = kLcdFilterDefault,
                         const FlattenOptions& flatten_options = raster_flatten_defaults());

    // Bytes of scratch memory currently held (for tests of the no-allocation promise).
    std::size_t scratch_capacity_bytes() const;

private:
    template <typename View>
    Status fill_impl(const Polylines& lines, FillRule rule, const View& target, Vec2 origin);
    template <typename View>
    Status fill_path_impl(const Path& path, const Affine& transform, FillRule rule,
                          const View& target, const FlattenOptions& flatten_options);

    std::vector<float> acc_;            // per-band cell deltas; all zero between calls
    std::vector<std::uint8_t> flags_;   // per-band "block has deltas" marks; all zero between calls
    Polylines flattened_;      // fill_path's reused polylines
    // LCD and accurate-overlap scratch (lcd.cpp, overlap.cpp), made on their first use.
    std::unique_ptr<raster_detail::FeatureScratch, void (*)(raster_detail::FeatureScratch*)>
        features_{nullptr, &raster_detail::release};
};

}  // namespace bezel
