#include "glyph_bitmap.hpp"

#include <cmath>
#include <string>

namespace bezel::cli {

namespace {

// A coordinate in FreeType's 26.6 fixed point (what its control box is made of).
long long to_26_6(double px) { return std::llround(px * 64.0); }
long long floor_px(long long v) { return v >= 0 ? v / 64 : -((-v + 63) / 64); }
long long ceil_px(long long v) { return -floor_px(-v); }

bool is_lcd(GlyphMode mode) { return mode != GlyphMode::Gray; }

}  // namespace

const char* mode_name(GlyphMode mode) {
    switch (mode) {
        case GlyphMode::Gray: return "gray";
        case GlyphMode::LcdRgb: return "lcd-rgb";
        case GlyphMode::LcdBgr: return "lcd-bgr";
    }
    return "gray";
}

Expected<GlyphBitmap> measure_glyph(Font& font, const GlyphRequest& request,
                                    const GlyphRenderSettings& settings) {
    auto outline = font.outline(request.gid, {settings.size_px, settings.hinting});
    if (!outline) return outline.error();
    GlyphBitmap g;
    g.gid = request.gid;
    g.name = font.glyph_name(request.gid);
    g.code_point = request.code_point;
    g.advance_px = outline->metrics.advance_px;
    g.accurate_overlap =
        outline->overlapping_contours || settings.overlap == OverlapMode::Accurate;
    g.mode = settings.mode;
    const Rect& b = outline->metrics.bounds_px;   // control box, y down
    if (b.is_empty()) return g;
    // FreeType's box: the 26.6 control box (y up) shifted by the 26.6 pen offset, floor/ceil.
    const long long ox = to_26_6(settings.offset.x), oy = to_26_6(-settings.offset.y);
    const long long x0 = floor_px(to_26_6(b.x0) + ox), x1 = ceil_px(to_26_6(b.x1) + ox);
    const long long y0 = floor_px(to_26_6(-b.y1) + oy), y1 = ceil_px(to_26_6(-b.y0) + oy);
    const long long pad = is_lcd(settings.mode) ? kLcdPaddingPx : 0;
    const long long w = x1 - x0 + 2 * pad, h = y1 - y0;
    if (w > kMaxBitmapDim || h > kMaxBitmapDim)
        return Error{"glyph " + std::to_string(request.gid) + ": a bitmap of " +
                     std::to_string(w) + "x" + std::to_string(h) + " px is larger than " +
                     std::to_string(kMaxBitmapDim) + " (kMaxBitmapDim)"};
    g.left = static_cast<int>(x0 - pad);
    g.top = static_cast<int>(y1);
    g.width = static_cast<int>(w);
    g.height = static_cast<int>(h);
    g.outline = std::move(outline->path);
    return g;
}

Status render_glyph(Rasterizer& raster, const GlyphRenderSettings& settings, GlyphBitmap& glyph) {
    const int bpp = glyph.bytes_per_pixel();
    glyph.pixels.assign(static_cast<std::size_t>(glyph.width) * bpp * glyph.height, 0);
    if (glyph.width == 0 || glyph.height == 0) return ok_status();
    // Bitmap pixel (i, j) is at (left + i, −top + j) from the pen; the pen is at the offset.
    const Affine to_bitmap =
        Affine::translate({settings.offset.x - glyph.left, settings.offset.y + glyph.top});
    const MaskView view{glyph.pixels.data(), glyph.width * bpp, glyph.height,
                        static_cast<std::ptrdiff_t>(glyph.width) * bpp};
    const OverlapMode overlap =
        glyph.accurate_overlap ? OverlapMode::Accurate : OverlapMode::Accumulate;
    const FillOptions fill{settings.rule, overlap, settings.flatten, {},
                           is_lcd(settings.mode) ? CoverageFormat::Lcd : CoverageFormat::Gray,
                           settings.mode == GlyphMode::LcdBgr ? LcdOrder::Bgr : LcdOrder::Rgb};
    Status st = raster.fill_path(glyph.outline, to_bitmap, view, fill);
    if (!st) return Error{"glyph " + std::to_string(glyph.gid) + ": " + st.error().message};
    return ok_status();
}

}  // namespace bezel::cli
