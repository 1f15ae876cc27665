// bezel/freetype_reference.hpp — FreeType's own rasterizer as a reference renderer, for benchmarks
// and comparisons with bezel's (`bezel bench`, tools/bench); not needed to render, and the
// library's own rendering never calls it.
#pragma once

#include "bezel/expected.hpp"
#include "bezel/font.hpp"
#include "bezel/geometry.hpp"
#include "bezel/image.hpp"

#pragma GCC visibility push(default)  // the public API of libbezel.so (docs/architecture.md)
namespace bezel {

// FreeType's own anti-aliased rasterizer (FT_Outline_Render with FT_RASTER_FLAG_AA, the "smooth"
// renderer) on the unhinted outline of `gid` at options.size_px, written into `target` with the
// pen at `origin` (pixels, y down; every target pixel is written). For comparisons and
// benchmarks against bezel's rasterizer (`bezel bench`); FreeType rounds the outline to its
// 1/64 px grid and flattens curves itself. Errors as Font::outline, plus a target larger than
// FreeType's gray raster addresses (32767 px a side), a null target, a stride that does not hold
// a row, a pen position that is not finite or beyond 10^6 px.
Status render_with_freetype(Font& font, GlyphId gid, const OutlineOptions& options,
                            const MaskView& target, Vec2 origin);

}  // namespace bezel
#pragma GCC visibility pop
