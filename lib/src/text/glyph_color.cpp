// GlyphRasterizer's colour glyphs: a COLR paint graph or a bitmap strike, boxed like an outline
// glyph (FreeType's bitmap_left / bitmap_top convention, glyph_rasterizer.cpp) and drawn into
// premultiplied RGBA.
//
// Placement. Glyph space is font units, y up (paint.hpp); the pen-relative pixel frame is y down,
// so a COLR glyph at size s in a font of `upem` units maps by M = [s/upem, 0; 0, −s/upem], then the
// synthetic slant's shear x += slant·(−y), then the pen offset. Its box is the whole-pixel box of
// paint_bounds mapped by that (the four corners of the glyph-space box, so a sheared box is still
// covered). A bitmap strike at strike_px is scaled by k = size_px / strike_px: its box, pen-relative,
// [left·k, (left + width)·k] × [−top·k, (−top + height)·k], moved by the offset, has its edges rounded
// to whole pixels and the strike is scaled onto exactly that box (so a 136-px strike drawn at 16 px
// lands within half a pixel of where FreeType's metrics put it).
#include <algorithm>
#include <cmath>
#include <string>

#include "bezel/glyph.hpp"

namespace bezel {

namespace {

std::string label(Font& font, GlyphId gid) {
    return "glyph " + std::to_string(gid) + " (" + font.glyph_name(gid) + ")";
}

// The whole-pixel box around [x0, x1] × [y0, y1] (pen-relative pixels, y down), or an error when it
// reaches past kMaxBitmapDim.
Status box_of(Font& font, GlyphId gid, double x0, double y0, double x1, double y1, bool round,
              GlyphBox& box) {
    const double bx0 = round ? std::round(x0) : std::floor(x0);
    const double by0 = round ? std::round(y0) : std::floor(y0);
    double bx1 = round ? std::round(x1) : std::ceil(x1);
    double by1 = round ? std::round(y1) : std::ceil(y1);
    // A bitmap smaller than a pixel at this size still shows as one pixel.
    if (round) {
        bx1 = std::max(bx1, bx0 + 1);
        by1 = std::max(by1, by0 + 1);
    }
    if (!(bx1 - bx0 <= kMaxBitmapDim && by1 - by0 <= kMaxBitmapDim &&
          std::fabs(bx0) <= kMaxBitmapDim && std::fabs(by0) <= kMaxBitmapDim))
        return Error{label(font, gid) + ": its colour bitmap would reach past the " +
                     std::to_string(kMaxBitmapDim) + " px a bitmap may span"};
    box.left = static_cast<int>(bx0);
    box.top = -static_cast<int>(by0);
    box.width = static_cast<int>(bx1 - bx0);
    box.height = static_cast<int>(by1 - by0);
    return ok_status();
}

}  // namespace

ColorFormat GlyphRasterizer::color_format(GlyphId gid) {
    return tables_.any() ? bezel::color_format(font_, gid) : ColorFormat::None;
}

bool GlyphRasterizer::is_color(GlyphId gid, const GlyphColorOptions& options) {
    return options.enabled && drawn_in_color(color_format(gid));
}

Expected<PreparedGlyph> GlyphRasterizer::prepare_color(GlyphId gid, ColorFormat format,
                                                       const GlyphRenderOptions& options) {
    PreparedGlyph glyph;
    glyph.gid = gid;
    glyph.options = options;
    glyph.box.color = true;
    const Vec2 pen = options.offset_px;
    if (format == ColorFormat::Bitmap) {
        auto bitmap = load_color_bitmap(font_, gid, options.size_px);
        if (!bitmap) return bitmap.error();
        const double k = options.size_px / bitmap->strike_px;
        glyph.box.advance_px = bitmap->advance_px * k;
        if (bitmap->width > 0 && bitmap->height > 0) {
            Status boxed = box_of(font_, gid, bitmap->left * k + pen.x, -bitmap->top * k + pen.y,
                                  (bitmap->left + bitmap->width) * k + pen.x,
                                  (bitmap->height - bitmap->top) * k + pen.y, true, glyph.box);
            if (!boxed) return boxed.error();
        }
        glyph.bitmap = std::make_shared<const ColorBitmap>(std::move(*bitmap));
        return glyph;
    }
    auto paint = load_color_glyph(font_, gid, options.color.palette);
    if (!paint) return paint.error();
    // The builder keeps the graph's invariants; checked here too, since a refused graph has an
    // empty box and would otherwise draw as silently blank.
    if (Status valid = validate(*paint); !valid)
        return Error{label(font_, gid) + ": " + valid.error().message};
    auto metrics = font_.glyph_metrics(gid, {options.size_px, Hinting::None});
    if (!metrics) return metrics.error();
    glyph.box.advance_px = metrics->advance_px;
    const double s = options.size_px / font_.metrics().units_per_em;
    const Affine to_pen = Affine::skew(-options.slant, 0) * Affine{s, 0, 0, -s, pen.x, pen.y};
    const Rect bounds = paint_bounds(*paint);
    if (!bounds.is_empty()) {
        Rect px = Rect::empty();
        for (Point corner : {Point{bounds.x0, bounds.y0}, Point{bounds.x1, bounds.y0},
                             Point{bounds.x0, bounds.y1}, Point{bounds.x1, bounds.y1}})
            px = px.union_with(to_pen * corner);
        Status boxed = box_of(font_, gid, px.x0, px.y0, px.x1, px.y1, false, glyph.box);
        if (!boxed) return boxed.error();
    }
    // The box's top-left pixel is (left, −top) from the pen's whole-pixel origin.
    glyph.paint_transform =
        Affine::translate({-static_cast<double>(glyph.box.left), static_cast<double>(glyph.box.top)}) *
        to_pen;
    glyph.paint = std::make_shared<const ColorGlyph>(std::move(*paint));
    return glyph;
}

Status GlyphRasterizer::draw_rgba(const PreparedGlyph& glyph, const RgbaView& target) {
    const GlyphBox& box = glyph.box;
    if (box.width == 0 || box.height == 0) return ok_status();
    if (target.width < box.width || target.height < box.height || !target.data)
        return Error{label(font_, glyph.gid) + ": target " + std::to_string(target.width) + "x" +
                     std::to_string(target.height) + " is smaller than the glyph's " +
                     std::to_string(box.width) + "x" + std::to_string(box.height) + " pixels"};
    const RgbaView corner = target.sub(0, 0, box.width, box.height);
    if (glyph.bitmap) {
        scale_rgba(glyph.bitmap->view(), corner, glyph.options.color.bitmap_filter);
        return ok_status();
    }
    if (glyph.paint) {
        if (!painter_) painter_ = std::make_unique<Painter>();
        PaintOptions paint;
        paint.transform = glyph.paint_transform;
        paint.foreground = glyph.options.color.foreground;
        paint.flatten = glyph.options.fill.flatten;
        Status painted = painter_->paint(*glyph.paint, paint, corner);
        if (!painted) return Error{label(font_, glyph.gid) + ": " + painted.error().message};
        return ok_status();
    }
    if (glyph.options.fill.format == CoverageFormat::Lcd)
        return Error{label(font_, glyph.gid) +
                     ": LCD coverage cannot be drawn into RGBA (one alpha per pixel)"};
    // The coverage is drawn into the first box.width bytes of each row, then widened in place to
    // premultiplied foreground · coverage, right to left so no byte is read after it is written.
    const MaskView coverage{corner.data, box.width, box.height, corner.stride};
    if (Status drawn = draw(glyph, coverage); !drawn) return drawn;
    const Rgba8 fg = glyph.options.color.foreground;
    for (int y = 0; y < box.height; ++y) {
        std::uint8_t* row = corner.row(y);
        for (int x = box.width; x-- > 0;) {
            const unsigned a = (row[x] * unsigned{fg.a} + 127) / 255;   // coverage · fg alpha
            std::uint8_t* px = row + 4 * x;
            px[3] = static_cast<std::uint8_t>(a);
            px[2] = static_cast<std::uint8_t>((fg.b * a + 127) / 255);
            px[1] = static_cast<std::uint8_t>((fg.g * a + 127) / 255);
            px[0] = static_cast<std::uint8_t>((fg.r * a + 127) / 255);
        }
    }
    return ok_status();
}

}  // namespace bezel
