// GlyphRasterizer: one glyph's outline from the Font, filled by bezel's Rasterizer into a caller
// buffer, placed by FreeType's bitmap_left / bitmap_top convention.
//
// The pen sits at the offset (dx, dy) (pixels, y down) from the glyph's whole-pixel origin. A box
// [x0, x1] × [y0, y1] (y down) of whole pixels around the ink at the pen gives left = x0 (columns
// from the origin to the first column) and top = −y0 (rows above the baseline, FreeType's
// bitmap_top); bitmap pixel (i, j) is at (left + i, −top + j) from the origin, so the outline
// moves by (dx − left, dy + top) into the bitmap. LCD modes add kLcdPaddingPx columns on each
// side for the filter's spread. Two ways to find the box (GlyphBoxMode):
//   Tight     columns floor(bx0 + dx) .. ceil(bx1 + dx) of the curves' tight bounds b, rows alike;
//   FreeType  the control box and the offset in 26.6 fixed point, floor/ceil, as FreeType's
//             ft_glyphslot_preset_bitmap (y up there: bitmap_top is the ceiling of the box's top).
// Synthetic bold and slant change the outline before either box is taken (bold first, then the
// shear: glyph.hpp says why), so both boxes are those of the outline as drawn.
#include <cmath>
#include <cstdio>
#include <string>

#include "bezel/glyph.hpp"
#include "text/glyph_draw.hpp"
#include "text/synthetic_bold.hpp"

namespace bezel {

namespace {

bool is_lcd(const GlyphRenderOptions& o) { return o.fill.format == CoverageFormat::Lcd; }

std::string glyph_label(GlyphId gid) { return "glyph " + std::to_string(gid); }

// A number in a message: "%g" (6 significant digits), not std::to_string's "%f".
std::string format_number(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

Status check_options(GlyphId gid, const GlyphRenderOptions& o) {
    auto in_range = [](double v) { return std::fabs(v) <= kMaxGlyphOffsetPx; };  // NaN fails
    if (!in_range(o.offset_px.x) || !in_range(o.offset_px.y))
        return Error{glyph_label(gid) + ": pen offset (" + format_number(o.offset_px.x) + ", " +
                     format_number(o.offset_px.y) + ") is not finite or beyond ±" +
                     std::to_string(static_cast<int>(kMaxGlyphOffsetPx)) + " px"};
    if (!(std::fabs(o.slant) <= kMaxSyntheticSlant))   // NaN fails too
        return Error{glyph_label(gid) + ": slant " + format_number(o.slant) + " is not in -" +
                     format_number(kMaxSyntheticSlant) + " to " +
                     format_number(kMaxSyntheticSlant)};
    if (!(o.bold >= 0 && o.bold <= kMaxSyntheticBold))   // NaN fails too
        return Error{glyph_label(gid) + ": bold " + format_number(o.bold) + " is not in 0 to " +
                     format_number(kMaxSyntheticBold)};
    if (o.bold > 0 && o.fill.rule != FillRule::NonZero)
        return Error{glyph_label(gid) + ": synthetic bold needs the nonzero fill rule (the "
                     "dilated outline overlaps itself)"};
    if (o.fill.origin.x != 0 || o.fill.origin.y != 0)
        return Error{glyph_label(gid) + ": fill.origin must be zero (offset_px places the pen)"};
    if (o.fill.combine != CoverageCombine::Replace)
        return Error{glyph_label(gid) + ": fill.combine must be Replace (a glyph bitmap is its "
                     "own coverage; a cache keeps it to blend many times)"};
    return ok_status();
}

// The tight box of `path` at the offset. The pixel extent is checked against kMaxBitmapDim in
// double before any conversion to int.
Status tight_box(GlyphId gid, const Path& path, const GlyphRenderOptions& o, GlyphBox& box) {
    const Rect b = path.bounds();
    if (b.is_empty()) return ok_status();
    const double x0 = std::floor(b.x0 + o.offset_px.x), x1 = std::ceil(b.x1 + o.offset_px.x);
    const double y0 = std::floor(b.y0 + o.offset_px.y), y1 = std::ceil(b.y1 + o.offset_px.y);
    if (!(x1 - x0 <= kMaxBitmapDim && y1 - y0 <= kMaxBitmapDim && std::fabs(x0) <= kMaxBitmapDim &&
          std::fabs(y0) <= kMaxBitmapDim))
        return Error{glyph_label(gid) + ": a bitmap of " + format_number(x1 - x0) + "x" +
                     format_number(y1 - y0) + " px at (" + format_number(x0) + ", " +
                     format_number(y0) + ") from the pen reaches past the " +
                     std::to_string(kMaxBitmapDim) + " px bitmaps may span"};
    const int pad = is_lcd(o) ? kLcdPaddingPx : 0;
    box.left = static_cast<int>(x0) - pad;
    box.top = -static_cast<int>(y0);
    box.width = static_cast<int>(x1 - x0) + 2 * pad;
    box.height = static_cast<int>(y1 - y0);
    return ok_status();
}

// A coordinate in FreeType's 26.6 fixed point (what its control box is made of).
long long to_26_6(double px) { return std::llround(px * 64.0); }
long long floor_px(long long v) { return v >= 0 ? v / 64 : -((-v + 63) / 64); }
long long ceil_px(long long v) { return -floor_px(-v); }

// FreeType's box of the control box `b` (y down) at the offset.
Status freetype_box(GlyphId gid, const Rect& b, const GlyphRenderOptions& o, GlyphBox& box) {
    if (b.is_empty()) return ok_status();
    // In FreeType's y-up frame: the box's bottom is −b.y1, its top −b.y0, the offset (dx, −dy).
    const long long ox = to_26_6(o.offset_px.x), oy = to_26_6(-o.offset_px.y);
    const long long x0 = floor_px(to_26_6(b.x0) + ox), x1 = ceil_px(to_26_6(b.x1) + ox);
    const long long y0 = floor_px(to_26_6(-b.y1) + oy), y1 = ceil_px(to_26_6(-b.y0) + oy);
    const long long pad = is_lcd(o) ? kLcdPaddingPx : 0;
    const long long w = x1 - x0 + 2 * pad, h = y1 - y0;
    if (w > kMaxBitmapDim || h > kMaxBitmapDim)
        return Error{glyph_label(gid) + ": a bitmap of " + std::to_string(w) + "x" +
                     std::to_string(h) + " px is larger than the " + std::to_string(kMaxBitmapDim) +
                     " px a side bitmaps may have"};
    box.left = static_cast<int>(x0 - pad);
    box.top = static_cast<int>(y1);
    box.width = static_cast<int>(w);
    box.height = static_cast<int>(h);
    return ok_status();
}

}  // namespace

GlyphRasterizer::GlyphRasterizer(Font& font) : font_(font.impl_), tables_(color_tables(font)) {}

Expected<PreparedGlyph> GlyphRasterizer::prepare(GlyphId gid, const GlyphRenderOptions& options) {
    if (auto ok = check_options(gid, options); !ok) return ok.error();
    // Fonts without colour tables (most) pay one flag test for colour.
    if (options.color.enabled && tables_.any()) {
        const ColorFormat format = color_format(gid);
        if (drawn_in_color(format)) return prepare_color(gid, format, options);
    }
    if (options.embedded_bitmaps && font_.has_bitmap_strikes()) {
        auto strike = font_.strike_bitmap(gid, options.size_px);
        if (!strike) return strike.error();
        if (*strike) return prepare_strike(gid, std::move(**strike), options);
    }
    auto outline = font_.outline(gid, {options.size_px, options.hinting});
    if (!outline) return outline.error();
    PreparedGlyph glyph;
    glyph.gid = gid;
    glyph.options = options;
    glyph.box.advance_px = outline->metrics.advance_px;
    // Glyphs the font marks as overlapping get the accurate overlap resolution regardless.
    glyph.box.overlap =
        outline->overlapping_contours ? OverlapMode::Accurate : options.fill.overlap;
    if (options.bold > 0) {
        // glyph.hpp's rule: dilate by d, then move right by d and up (−y) by d.
        const double d = options.bold * options.size_px / 2;
        auto dilated = text_detail::dilate_outline(outline->path, d, kSyntheticBoldTolerancePx);
        if (!dilated) return Error{glyph_label(gid) + ": synthetic bold: " +
                                   dilated.error().message};
        outline->path = std::move(*dilated);
        outline->path.transform(Affine::translate({d, -d}));
        outline->metrics.bounds_px = outline->path.control_box();
        if (glyph.box.advance_px != 0) glyph.box.advance_px += 2 * d;
        glyph.box.overlap = OverlapMode::Accurate;
    }
    if (options.slant != 0) {
        // x += slant · (−y): y points down, so the height above the baseline is −y.
        const Affine shear = Affine::skew(-options.slant, 0);
        outline->path.transform(shear);
        Rect control = Rect::empty();
        if (options.bold > 0) {
            control = outline->path.control_box();
        } else {
            for (const OutlinePoint& p : outline->points)
                control = control.union_with(shear * p.pos);
        }
        outline->metrics.bounds_px = control;
    }
    Status boxed = options.box == GlyphBoxMode::FreeType
                       ? freetype_box(gid, outline->metrics.bounds_px, options, glyph.box)
                       : tight_box(gid, outline->path, options, glyph.box);
    if (!boxed) return boxed.error();
    glyph.path = std::move(outline->path);
    return glyph;
}

// A strike's bitmap at the whole pixel nearest the pen: its box is the bitmap's own, moved by
// the rounded offset (no LCD padding: the strike has no subpixel detail to filter).
Expected<PreparedGlyph> GlyphRasterizer::prepare_strike(GlyphId gid, StrikeBitmap strike,
                                                        const GlyphRenderOptions& options) {
    PreparedGlyph glyph;
    glyph.gid = gid;
    glyph.options = options;
    glyph.box.bitmap_strike = true;
    glyph.box.advance_px = strike.advance_px;
    if (strike.width > 0 && strike.height > 0) {
        const double dx = std::floor(options.offset_px.x + 0.5);
        const double dy = std::floor(options.offset_px.y + 0.5);
        glyph.box.left = strike.left + static_cast<int>(dx);
        glyph.box.top = strike.top - static_cast<int>(dy);
        glyph.box.width = strike.width;
        glyph.box.height = strike.height;
    }
    glyph.strike = std::make_shared<const StrikeBitmap>(std::move(strike));
    return glyph;
}

Status GlyphRasterizer::draw_strike(const PreparedGlyph& glyph, const MaskView& target) {
    const StrikeBitmap& s = *glyph.strike;
    const int repeat = is_lcd(glyph.options) ? 3 : 1;
    for (int y = 0; y < glyph.box.height; ++y) {
        std::uint8_t* out = target.row(y);
        const std::uint8_t* in = s.coverage.data() + static_cast<std::size_t>(y) * s.width;
        for (int x = 0; x < glyph.box.width; ++x)
            for (int k = 0; k < repeat; ++k) *out++ = in[x];
    }
    return ok_status();
}

Status GlyphRasterizer::draw(const PreparedGlyph& glyph, const MaskView& target) {
    const GlyphBox& box = glyph.box;
    if (box.width == 0 || box.height == 0) return ok_status();
    if (Status s = text_detail::check_glyph_target(glyph, target); !s)
        return Error{glyph_label(glyph.gid) + ": " + s.error().message};
    if (box.color) return draw_color_alpha(glyph, target);
    if (glyph.strike) return draw_strike(glyph, target);
    const FillJob job = text_detail::outline_job(glyph, target);
    FillOptions fill = text_detail::outline_fill(glyph);
    fill.origin = job.origin;
    // The one place glyphs meet the Rasterizer (draw_set's fill_paths places them the same way).
    Status filled = raster_.fill_path(*job.path, job.transform, job.target, fill);
    if (!filled) return Error{glyph_label(glyph.gid) + ": " + filled.error().message};
    return ok_status();
}

// A colour glyph's alpha as coverage: painted into scratch RGBA, the A byte kept (three times in
// LCD modes, where the target has three bytes a pixel).
Status GlyphRasterizer::draw_color_alpha(const PreparedGlyph& glyph, const MaskView& target) {
    const GlyphBox& box = glyph.box;
    const std::size_t row_bytes = 4 * static_cast<std::size_t>(box.width);
    rgba_scratch_.resize(row_bytes * static_cast<std::size_t>(box.height));
    const RgbaView rgba{rgba_scratch_.data(), box.width, box.height,
                        static_cast<std::ptrdiff_t>(row_bytes)};
    if (Status drawn = draw_rgba(glyph, rgba); !drawn) return drawn;
    const int repeat = is_lcd(glyph.options) ? 3 : 1;
    for (int y = 0; y < box.height; ++y) {
        std::uint8_t* out = target.row(y);
        const std::uint8_t* in = rgba.row(y);
        for (int x = 0; x < box.width; ++x)
            for (int k = 0; k < repeat; ++k) *out++ = in[4 * x + 3];
    }
    return ok_status();
}

Expected<GlyphBox> GlyphRasterizer::measure(GlyphId gid, const GlyphRenderOptions& options) {
    auto glyph = prepare(gid, options);
    if (!glyph) return glyph.error();
    return glyph->box;
}

Expected<GlyphBox> GlyphRasterizer::render(GlyphId gid, const GlyphRenderOptions& options,
                                           const MaskView& target) {
    auto glyph = prepare(gid, options);
    if (!glyph) return glyph.error();
    if (Status drawn = draw(*glyph, target); !drawn) return drawn.error();
    return glyph->box;
}

}  // namespace bezel
