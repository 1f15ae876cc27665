// Private: fill_path's direct route — each curve is flattened straight into the accumulation
// band (no Polylines round trip, no per-point bounds pass, no clipping per segment).
//
// It applies to the common case of a glyph drawn into a target that holds it: every transformed
// control point inside the target or less than the flattening tolerance outside it (so no
// clipping: the curves lie in their control points' convex hull, and the vertices of a path
// that strays are clamped into the target, which moves the outline by less than 2·tol), one
// band, and the edge budget met by the cheap bound of path_fill.cpp. Anything else returns
// false with the target untouched, and fill_path takes the general route (flatten_balanced +
// fill), which also reports every error.
//
// The polyline is the one flatten_balanced makes (the same walk, render_flatten.hpp), so the
// coverage equals the general route's up to float rounding of the band-relative coordinates.
// Balanced vertices sit up to |Δ²|/12 ≤ tol off the curve, outward, so one may stray out of the
// control box by less than tol; such a vertex is drawn as if moved into the band (x clamping is
// exact, see accumulate.hpp; in y it moves by less than tol), within the flattening error.
//
// Two regimes by box width: a box of at most kDenseBlocks blocks per row (small sizes) is DENSE —
// edges mark no blocks and the whole band is summed in one sweep call, since nearly every block
// holds an edge anyway; wider boxes mark blocks so the sweep fills empty and solid runs without
// summing them. 6 blocks (96 px) was chosen against 2, 4, 8 and 10: none is faster at every
// size, and 10 is slower at 384-512 px (docs/perf-log.md).
#pragma once

#include "raster/sse2.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

#include "bezel/raster.hpp"

namespace bezel::raster_detail {

inline constexpr int kDenseBlocks = 6;
// Largest flattening tolerance the direct route takes (vertex excursions stay under 1/3 px, see
// direct_fill.cpp); coarser tolerances go the general route.
inline constexpr double kDirectMaxTolerancePx = 0.5;

struct DirectScratch {
    std::vector<float>& acc;            // band deltas, all zero between calls
    std::vector<std::uint8_t>& flags;   // block flags, all zero between calls
    std::vector<Point>& points;         // the transformed control points
};

// Fills `path` mapped by `m` into `target` when the direct route applies (see above) and
// returns true; returns false, touching nothing but scratch capacity, otherwise. `tol` is the
// flattening tolerance (> 0, finite); `m` is finite.
template <typename View>
bool fill_path_direct(const Path& path, const Affine& m, FillRule rule, const View& target,
                      double tol, const DirectScratch& scratch);

}  // namespace bezel::raster_detail
