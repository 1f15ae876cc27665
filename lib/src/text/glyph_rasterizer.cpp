// GlyphRasterizer: one glyph's outline from the Font, filled by bezel's Rasterizer into a caller
// buffer, placed by FreeType's bitmap_left / bitmap_top convention.
//
// The box. With the pen at (sx, sy) (the subpixel offset, pixels, y down) and the outline's tight
// bounds [x0, x1] × [y0, y1] (y down), the bitmap covers
//   columns floor(x0 + sx) .. ceil(x1 + sx),   rows floor(y0 + sy) .. ceil(y1 + sy),
// so left = floor(x0 + sx) and top = −floor(y0 + sy) (rows above the baseline, FreeType's
// bitmap_top). FreeType rounds its control box the same way; ours is the tight box of the
// curves, so it is never larger. LCD modes add kLcdPaddingPx columns on each side for the
// filter's spread.
#include <cmath>
#include <string>

#include "bezel/glyph.hpp"

namespace bezel {

namespace {

bool is_lcd(RenderMode mode) { return mode != RenderMode::Gray; }

Status check_options(GlyphId gid, const GlyphRenderOptions& o) {
    auto in_unit = [](double v) { return v >= 0.0 && v < 1.0; };  // NaN fails
    if (!in_unit(o.subpixel_x) || !in_unit(o.subpixel_y))
        return Error{"glyph " + std::to_string(gid) + ": subpixel offset (" +
                     std::to_string(o.subpixel_x) + ", " + std::to_string(o.subpixel_y) +
                     ") is outside [0, 1)"};
    return ok_status();
}

// The box of an outline whose bounds are `b`, at the options' subpixel offset. The pixel extent
// is checked against kMaxBitmapDim in double before any conversion to int.
Expected<GlyphBox> box_of(GlyphId gid, const GlyphOutline& outline, const GlyphRenderOptions& o) {
    GlyphBox box;
    box.advance_px = outline.metrics.advance_px;
    Rect b = outline.path.bounds();
    if (b.is_empty()) return box;
    double x0 = std::floor(b.x0 + o.subpixel_x), x1 = std::ceil(b.x1 + o.subpixel_x);
    double y0 = std::floor(b.y0 + o.subpixel_y), y1 = std::ceil(b.y1 + o.subpixel_y);
    if (!(x1 - x0 <= kMaxBitmapDim && y1 - y0 <= kMaxBitmapDim && std::fabs(x0) <= kMaxBitmapDim &&
          std::fabs(y0) <= kMaxBitmapDim))
        return Error{"glyph " + std::to_string(gid) + ": bitmap of " + std::to_string(x1 - x0) +
                     "x" + std::to_string(y1 - y0) + " px exceeds kMaxBitmapDim (" +
                     std::to_string(kMaxBitmapDim) + ")"};
    int pad = is_lcd(o.mode) ? kLcdPaddingPx : 0;
    box.left = static_cast<int>(x0) - pad;
    box.top = -static_cast<int>(y0);
    box.width = static_cast<int>(x1 - x0) + 2 * pad;
    box.height = static_cast<int>(y1 - y0);
    return box;
}

}  // namespace

GlyphRasterizer::GlyphRasterizer(Font& font) : font_(&font) {}

Expected<GlyphBox> GlyphRasterizer::measure(GlyphId gid, const GlyphRenderOptions& options) {
    if (auto ok = check_options(gid, options); !ok) return ok.error();
    auto outline = font_->outline(gid, {options.size_px, false});
    if (!outline) return outline.error();
    outline_ = std::move(*outline);
    return box_of(gid, outline_, options);
}

Expected<GlyphBox> GlyphRasterizer::render(GlyphId gid, const GlyphRenderOptions& options,
                                           const MaskView& target) {
    auto box = measure(gid, options);
    if (!box) return box;
    const int bytes_per_px = is_lcd(options.mode) ? 3 : 1;
    if (box->width == 0 || box->height == 0) return box;
    if (target.width < box->width * bytes_per_px || target.height < box->height || !target.data)
        return Error{"glyph " + std::to_string(gid) + ": target " + std::to_string(target.width) +
                     "x" + std::to_string(target.height) + " is smaller than the glyph's " +
                     std::to_string(box->width * bytes_per_px) + "x" +
                     std::to_string(box->height) + " bytes"};
    // Pen at (left, −top) from the bitmap's corner: bitmap pixel (i, j) is page pixel
    // (pen + left + i, pen − top + j), so the outline moves by (sx − left, sy + top).
    const Affine to_bitmap = Affine::translate(
        {options.subpixel_x - box->left, options.subpixel_y + box->top});
    // Glyphs the font marks as overlapping get the accurate overlap resolution regardless.
    const OverlapMode overlap =
        outline_.overlapping_contours ? OverlapMode::Accurate : options.overlap;
    FlattenOptions flatten = raster_flatten_defaults();
    flatten.tolerance_px = options.tolerance_px;
    MaskView glyph = target.sub(0, 0, box->width * bytes_per_px, box->height);
    const FillOptions fill{options.rule, overlap, flatten, {},
                           is_lcd(options.mode) ? CoverageFormat::Lcd : CoverageFormat::Gray,
                           options.mode == RenderMode::LcdBgr ? LcdOrder::Bgr : LcdOrder::Rgb};
    Status filled = raster_.fill_path(outline_.path, to_bitmap, glyph, fill);
    if (!filled) return Error{"glyph " + std::to_string(gid) + ": " + filled.error().message};
    return box;
}

}  // namespace bezel
