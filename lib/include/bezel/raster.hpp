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
//         the display width). The fill is sampled at 3× horizontal resolution (subpixel k covers
//         display x in [k/3, (k+1)/3]) and filtered by FillOptions::lcd_filter; byte 3p + k of a
//         row is subpixel k of display pixel p, left to right. So the bytes are in the PANEL's
//         order, FillOptions::lcd_order: R, G, B for Rgb, B, G, R for Bgr (image.hpp's LcdOrder).
//         The bytes themselves do not depend on the order (they are positions on the screen);
//         the order says which colour each is, and blend_lcd_mask must be given the same one.
enum class CoverageFormat : std::uint8_t { Gray, Lcd };

// --- Drawing into a target that already holds coverage ----------------------------------------
// How a fill's coverage b meets the coverage a the target holds (both in [0, 1]; in a MaskView
// the bytes a, b in 0..255, b being the byte a Replace fill would write):
//   Replace: out = b on EVERY pixel of the target (0 where the fill does not reach: the target
//            is cleared). The default, and what a fill of one shape into its own mask wants.
//   Over:    out = a + b − a·b; in bytes a + b − round(a·b/255). Alpha compositing's "over" of
//            coverage: the union of shapes drawn one after another (icons, the paths of a
//            drawing), exact where they are disjoint and where one covers a pixel fully, and the
//            expected coverage of the union where two edges cross a pixel independently (two
//            half-covered pixels make ¾). Symmetric and associative (in real numbers), so the
//            drawing order does not matter.
//   Add:     out = min(a + b, 1); in bytes min(a + b, 255). Exact for pieces that do not overlap
//            but share edges (a shape cut into tiles, a glyph assembled from parts): a pixel
//            covered ½ by each side of a shared edge becomes 1, where Over leaves a seam of ¾.
//            Over-counts where the pieces overlap.
// Over and Add leave pixels the fill does not reach untouched, and LCD coverage combines each
// subpixel byte alike.
enum class CoverageCombine : std::uint8_t { Replace, Over, Add };

// Every choice a fill makes. Each default is the plain fill: NonZero, Accumulate, flattening at
// kDefaultRasterTolerancePx with WangUniform, no origin shift, gray coverage, replacing the
// target.
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
    LcdOrder lcd_order = LcdOrder::Rgb;         // Lcd only: the panel's subpixel order, which
                                                // is the mask's byte order (see CoverageFormat)
    LcdFilter lcd_filter = kLcdFilterDefault;   // Lcd only
    // What becomes of the coverage the target holds (above). Every fill, every target type and
    // format takes it. Over and Add draw the fill into scratch the size of its control box
    // (clipped to the target) and combine that with the target, so they cost a little more than
    // Replace, and the fill's coverage b may differ from a Replace fill's by float rounding
    // (at most one 8-bit step), the points being moved by whole pixels into the scratch.
    CoverageCombine combine = CoverageCombine::Replace;
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

// One fill of a set (Rasterizer::fill_paths): `*path` mapped by `transform`, then moved by
// `origin` (target pixels, y down; a fractional origin places it at a subpixel offset), into
// `target`. An atlas is one target named by several jobs through its sub-rectangles
// (MaskView::sub), each job's origin placing the outline inside its own rectangle.
struct FillJob {
    const Path* path = nullptr;   // borrowed for the call; must not be null
    Affine transform;
    MaskView target;
    Vec2 origin;
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
    // `options.origin`, into `target` with `options.rule`: 8-bit alpha round(coverage·255)
    // into a MaskView, coverage in [0, 1] (not quantized) into a FloatMaskView. With
    // CoverageCombine::Replace (the default) it writes EVERY pixel of the target (0 where
    // nothing covers it: clearing is part of the call); Over and Add combine the coverage with
    // the target's and leave the pixels the fill does not reach as they were.
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
    // `options.format` with `options.overlap`, replacing or combining with the target's coverage
    // as `options.combine` says. For FlattenMethod::WangUniform the vertices are
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

    // Fills a set of paths in one call: job k gives exactly the bytes
    //   fill_path(*jobs[k].path, jobs[k].transform, jobs[k].target, o)
    // would, where o is `options` with o.origin = jobs[k].origin (tested byte for byte), the
    // jobs in order (a later job's target may overwrite an earlier one's where they overlap:
    // atlas rectangles are meant to be disjoint). What the set shares: the options are checked
    // and the route (direct or general, direct_fill.hpp) is chosen once for all jobs, and the
    // scratch memory is one.
    // Errors, each naming the first job at fault by its index ("fill_paths: job 7: ...").
    // Found by a validation pass over every job BEFORE any target is written, so they leave
    // every target untouched: `options.origin` not zero (each job carries its own), a null
    // `jobs` with count > 0, and per job a null path, a target fill_path would refuse (its size,
    // null data, in Lcd format a width that is not a multiple of 3), a transform or origin that
    // is not finite. Found when the job is reached, before its target is written (so the jobs
    // before it are written, it and the jobs after it are not): what fill_path finds in the path
    // itself, a point that is not finite or beyond kMaxFlattenCoordinatePx after the transform,
    // a path over the edge budget, a curve the flattener gives up on. (Proving every point good
    // up front would take one more pass over all points: docs/rasterizer.md says what it costs.)
    // When `failed_job` is not null, an error stores the index of the job it names there (count
    // when the set itself is at fault: the options or a null array); success leaves it alone.
    // An empty set (count 0) is a success that writes nothing. Allocates nothing once the
    // scratch has grown to the largest job (as fill_path).
    Status fill_paths(const FillJob* jobs, std::size_t count, const FillOptions& options = {},
                      std::size_t* failed_job = nullptr);
    Status fill_paths(const std::vector<FillJob>& jobs, const FillOptions& options = {},
                      std::size_t* failed_job = nullptr) {
        return fill_paths(jobs.data(), jobs.size(), options, failed_job);
    }

    // Bytes of scratch memory currently held (for tests of the no-allocation promise).
    std::size_t scratch_capacity_bytes() const;

private:
    struct FeatureScratch;  // LCD, accurate-overlap and combine scratch (src/raster/overlap.hpp)

    template <typename View>
    Status fill_impl(const Polylines& lines, FillRule rule, const View& target, Vec2 origin);
    template <typename View>
    Status fill_path_impl(const Path& path, const Affine& transform, FillRule rule,
                          const View& target, const FlattenOptions& flatten_options);
    // fill_path_impl after the direct route refused (or was not tried): the edge budget, the
    // balanced or checked flattening and the banded fill.
    template <typename View>
    Status fill_path_general(const Path& path, const Affine& transform, FillRule rule,
                             const View& target, const FlattenOptions& flatten_options);
    template <typename View>
    Status fill_path_gray(const Path& path, const Affine& transform, const View& target,
                          const FillOptions& options);
    Status fill_path_lcd(const Path& path, const Affine& transform, const MaskView& target,
                         const FillOptions& options);
    // CoverageCombine::Over and Add (src/raster/combine.cpp); `transform` has the origin in it.
    Status fill_combined(const Polylines& lines, const MaskView& target, const FillOptions& options);
    Status fill_combined(const Polylines& lines, const FloatMaskView& target,
                         const FillOptions& options);
    Status fill_path_combined(const Path& path, const Affine& transform, const MaskView& target,
                              const FillOptions& options);
    Status fill_path_combined(const Path& path, const Affine& transform,
                              const FloatMaskView& target, const FillOptions& options);
    FeatureScratch& features();

    std::vector<float> acc_;            // per-band cell deltas; all zero between calls
    std::vector<std::uint8_t> flags_;   // per-band "block has deltas" marks; all zero between calls
    Polylines flattened_;               // fill_path's reused polylines
    std::unique_ptr<FeatureScratch> features_;  // made on first use
};

}  // namespace bezel
#pragma GCC visibility pop
