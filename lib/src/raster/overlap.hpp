// Private: exact coverage of the filled REGION, for overlapping contours (OverlapMode::Accurate),
// and the scratch the LCD, accurate-overlap and combining fills keep in a Rasterizer.
//
// Why plain accumulation over-darkens. Area accumulation gives each pixel ∫ w(x, y) dA, the
// integral of the winding number, clamped to 1. Where two contours with the same orientation
// overlap, w = 2, so a pixel crossed by an anti-aliased edge of one contour lying over a partly
// covered pixel of the other counts that part twice: two identical squares drawn on top of each
// other give an edge pixel of true coverage 0.5 the value min(2·0.5, 1) = 1.
//
// The exact method. Coverage should be the AREA of {p : rule(w(p)) is inside}. Inside one pixel
// row, cut the row into horizontal SLABS at every edge end point and every crossing of two
// edges. Within a slab no two edges cross, so their left-to-right order is fixed, and the
// winding number is constant between consecutive edges. Sweeping the edges in that order, only
// the edges where "inside" flips are boundary edges of the region: an edge entering the region
// (outside → inside) adds +1 × its slab piece's signed area to the right, an edge leaving it −1,
// and every other edge (one that moves w between 1 and 2, say) adds nothing. The accumulated
// area is then exactly the area of the region inside each cell, whatever the overlap.
//
// Error bound: exact up to floating point — the crossings are found in double, so a slab may
// hold a residual crossing displaced by ~1e-12 px, an error of that order times the row width.
// Measured against the 16×16 supersampled reference, it matches the plain rasterizer's error on
// non-overlapping outlines (tests/raster_overlap_test.cpp, docs/rasterizer.md).
//
// Cost: per row, O(k²) crossing tests for k edges active in it, then O(k log k) per slab. Two
// walls bound it (below); a row past the first, and every row once the second is reached, keeps
// the plain accumulation the caller has already written — hostile input degrades to
// OverlapMode::Accumulate in those rows instead of running away.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "bezel/flatten.hpp"
#include "bezel/image.hpp"
#include "bezel/raster.hpp"

namespace bezel::raster_detail {

// Edge visits (pairs tested for a crossing, plus edges swept per slab) one ROW may take: 2^16,
// e.g. ~360 edges active in one row. Real glyphs stay far below: a pixel row of a complex CJK
// glyph at 12 px meets ~80 flattened edges, and at 512 px ~60 (longer edges, as many crossings).
inline constexpr std::size_t kMaxOverlapRowWork = std::size_t{1} << 16;
// Edge visits one accurate fill may take in all: 2^28, about a second. A glyph at 512 px takes
// under 1/100 of it.
inline constexpr std::size_t kMaxOverlapWork = std::size_t{1} << 28;

// One non-horizontal polygon edge, top end first (y down).
struct UnionEdge {
    double x_top, y_top, x_bot, y_bot;
    double dxdy;    // x change per unit of y
    int winding;    // +1 for an edge drawn downwards, −1 upwards
    // Clamped to the edge's x range: a nearly horizontal edge (dy subnormal) has an infinite
    // dxdy, and 0·∞ at its top would be NaN (a fuzzer finding).
    double x_at(double y) const {
        if (!(y > y_top)) return x_top;
        const double x = x_top + (y - y_top) * dxdy;
        return x_bot > x_top ? std::min(x, x_bot) : std::max(x, x_bot);
    }
};

struct SlabEdge {
    double x_mid;
    std::uint32_t edge;
};

struct OverlapScratch {
    Polylines lines;                    // the flattened path
    std::vector<UnionEdge> edges;       // sorted by y_top
    std::vector<std::uint32_t> active;  // edges meeting the current row
    std::vector<double> events;         // slab boundaries of the current row
    std::vector<SlabEdge> slab;         // edges of the current slab, sorted by x_mid
    std::vector<double> cells;          // the current row's area deltas (width + 2)
};

// Flattens `path` exactly as Rasterizer::fill_path does and writes the region's exact coverage
// into `target` (every row that the work bound allows; the others are left as they are).
// Precondition: the same fill_path call (same path, transform, options, target size) has just
// succeeded, so every input check and the edge budget have passed.
template <typename View>
void fill_region_exact(const Path& path, const Affine& transform, FillRule rule,
                       const FlattenOptions& options, const View& target, OverlapScratch& s);

}  // namespace bezel::raster_detail

namespace bezel {

// The Rasterizer's scratch for the LCD and accurate-overlap fills, made on their first use.
struct Rasterizer::FeatureScratch {
    raster_detail::OverlapScratch overlap;
    std::vector<float> lcd_samples;  // 3× horizontal float coverage, lcd.cpp
    // A combining fill's coverage before it meets the target (combine.cpp).
    std::vector<std::uint8_t> combine_bytes;
    std::vector<float> combine_floats;
};

}  // namespace bezel
