// Private: the reference rasterizer — the oracle the fast path is tested against.
//
// Deliberately written differently from the fast path (accumulate.hpp, sweep.hpp) so that a bug
// is unlikely to be shared: double precision throughout, FreeType's two arrays per row (cover
// and area) instead of one delta array, and every edge cut at EVERY integer x and y it crosses,
// so each piece lies in exactly one cell:
//   piece in cell (i, j) with vertical extent dy (signed, + downwards) and mean x offset m in
//   [0, 1] inside the cell:   cover[j][i] += dy,   area[j][i] += dy·m.
//   coverage(i, j) = Σ_{k<i} cover[j][k] + cover[j][i] − area[j][i]
// i.e. the pixel gets the part of the piece's cover to the right of the piece, every pixel
// after it all of it. Clipping: pieces above, below or right of the target are dropped; pieces
// left of it are moved to x = 0 (m = 0), which is exact (see accumulate.hpp).
// Slow (every crossing of every edge is sorted), simple, for tests and tools only.
#pragma once

#include <vector>

#include "bezel/flatten.hpp"
#include "bezel/raster.hpp"

namespace bezel::raster_detail {

// Coverage in [0, 1] of each pixel of a width × height target, row-major, y down; polygon
// points land at p + origin. Precondition: finite coordinates with |p + origin| ≤ 1e9 (the
// number of pieces is proportional to the crossings inside the target, so far-away coordinates
// cost nothing, but the reference makes no claim about overflow).
std::vector<double> reference_coverage(const Polylines& lines, FillRule rule, int width,
                                       int height, Vec2 origin);

// round(255·coverage), as the 8-bit fill promises.
std::vector<unsigned char> reference_u8(const Polylines& lines, FillRule rule, int width,
                                        int height, Vec2 origin);

}  // namespace bezel::raster_detail
