// One glyph rendered for ImGui's atlas at ImGui's oversampling: the texels of its atlas rectangle
// and the quad ImGui draws them on.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "bezel/expected.hpp"
#include "bezel/glyph.hpp"

namespace bezel_imgui::detail {

struct Oversample {
    int h = 1, v = 1;   // 1..kMaxOversample texels per pixel, across and down
};

// A glyph's texels (width × height bytes, rows packed, at `offset` in the store they were
// appended to) and the quad they map to: pixels, y DOWN, relative to the pen on the baseline
// (ImGui adds the line's ascent). An empty glyph (a space) has no texel and a zero quad.
struct GlyphTexels {
    int width = 0, height = 0;
    std::size_t offset = 0;
    float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    float advance_px = 0;
};

// Renders `gid` with `options` (whose offset_px is overwritten) at `oversample`, appending its
// texels to `store`.
//
// Texel m of a row (m counted in 1/h px steps, like the oversampled column it comes from) is the
// exact coverage of the one-pixel-wide window [m/h, m/h + 1] of the glyph: bezel renders the
// glyph h times with the pen at k/h px (k = 0..h−1) and pixel j of render k is window
// m = h·j − k, so the renders interleave into the texel row (rows likewise with v). This is what
// stb_truetype's oversampling approximates (a box prefilter of h columns rendered at h× width),
// computed from exact areas with one rounding to 8 bits. The outline is loaded once (prepare)
// and filled h·v times (draw), each time with the pen and the tight box moved. ImGui samples a texel at its centre, so
// the quad starts half a window minus half a texel left of window m_min:
//   x0 = m_min/h + (h − 1)/(2h),   x1 = x0 + width/h      (stb's xoff: x0/h − (h − 1)/(2h)
//                                                          for its box left x0 = m_min + h − 1)
// With h = v = 1 the texels are the bitmap GlyphRasterizer draws at pen offset 0.
// `monochrome`: coverage ≥ 128 becomes 255, the rest 0. `max_store_bytes` bounds `store`
// (the texture the glyphs must fit): a glyph that would grow it past the bound is an error,
// found from its box before anything is drawn or allocated for it. Errors: that, and
// GlyphRasterizer's.
bezel::Status render_glyph_texels(bezel::GlyphRasterizer& rasterizer, bezel::GlyphId gid,
                                  bezel::GlyphRenderOptions options, Oversample oversample,
                                  bool monochrome, std::size_t max_store_bytes,
                                  std::vector<std::uint8_t>& store,
                                  std::vector<std::uint8_t>& scratch, GlyphTexels& out);

}  // namespace bezel_imgui::detail
