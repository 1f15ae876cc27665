// tools/bezel/atlas_pack.hpp — shelf packing of glyph boxes into one texture for `bezel atlas`.
#pragma once

#include <vector>

#include "bezel/expected.hpp"

namespace bezel::cli {

// Empty pixels around every rectangle: one, so bilinear sampling at a glyph's edge reads zero
// coverage, not its neighbour.
inline constexpr int kAtlasPaddingPx = 1;

struct AtlasRect {
    int x = 0, y = 0, width = 0, height = 0;
};

struct AtlasPacking {
    int width = 0, height = 0;      // texture size
    std::vector<AtlasRect> rects;   // in the order of the input sizes
};

// Shelf packing: rectangles sorted by height (tallest first) fill rows left to right; a row is as
// tall as its first rectangle. The texture width is the smallest power of two that is at least
// sqrt(total padded area) and fits the widest rectangle (power-of-two widths suit older GPUs and
// keep rows long enough that shelves waste little); the height is tight (the shelves' total).
// Every rectangle keeps kAtlasPaddingPx empty pixels to every other one and to the texture's
// edges. Empty (0-size) rectangles get (0, 0, 0, 0). The error names the size when the texture
// would exceed `max_dim` on a side.
Expected<AtlasPacking> pack_shelves(const std::vector<AtlasRect>& sizes, int max_dim);

}  // namespace bezel::cli
