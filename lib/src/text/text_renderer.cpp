// TextRenderer: layout_text, then every placed glyph from the cache blended onto the page.
//
// Placement. A pen x is rounded to the nearest 1/kSubpixelBins of a pixel and split into an
// integer column and a bin (so the cache's floor-quantization sees an exact bin and the error is
// at most 1/8 px), or to the nearest whole pixel for glyphs hinted horizontally; a pen y is
// rounded to a whole pixel, so every glyph of a line shares one baseline row and horizontal
// stems stay crisp. Vertical text (a TopToBottom or BottomToTop direction) advances along y
// instead: unhinted, its pen y is binned as x is (a column's glyphs keep their exact spacing to
// 1/8 px, as a line's do); hinted (every mode snaps y), it is rounded to a whole pixel, as for
// horizontal text. Its pen x is binned or rounded as for horizontal text.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "bezel/text_renderer.hpp"

namespace bezel {

namespace {

// Most pixels of one rendered page: 64 Mpx (256 MiB of RGBA), well past a poster of text, short
// of what kMaxImageDim alone would allow (4 GiB).
constexpr double kMaxPagePixels = double{1 << 26};

bool same_variations(const std::vector<VariationSetting>& a, const std::vector<VariationSetting>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].tag != b[i].tag || a[i].value != b[i].value) return false;
    return true;
}

// A whole number of pixels as digits ("3934407"), however large: "%.0f" never switches to an
// exponent and needs no conversion to an integer type that might not hold it.
std::string whole_number(double v) {
    char buf[320];
    std::snprintf(buf, sizeof buf, "%.0f", v);
    return buf;
}

}  // namespace

// What the renderer keeps per font of the collection.
struct FontSlot {
    // Shares the collection's Font: the cache keys its glyphs on the Font's instance_id(), which
    // follows the variations set below.
    std::unique_ptr<GlyphRasterizer> rasterizer;
    std::vector<VariationSetting> applied;        // the coordinates the Font is set to
};

struct TextRenderer::Impl {
    FontCollection fonts;
    std::vector<FontSlot> slots;   // one per font of `fonts`, grown as fallback adds fonts
    GlyphCache cache;
    MissingGlyphs missing;   // of the last draw
    bool has_color = false;  // of the last draw
    std::size_t svg_glyphs = 0;   // of the last draw
    std::vector<VariationSetting> wanted;   // scratch

    Impl(FontCollection f, std::size_t cache_bytes) : fonts(std::move(f)), cache(cache_bytes) {}

    // Slots for every font, each Font at the coordinates it is shaped at (layout.hpp: the
    // first font's own plus ShapeOptions::variations, the others their own).
    Status prepare_fonts(const ShapeOptions& shape) {
        while (slots.size() < fonts.size()) {
            FontSlot slot;
            slot.rasterizer = std::make_unique<GlyphRasterizer>(fonts.font(slots.size()));
            slot.applied = fonts.source(slots.size()).variations;
            slots.push_back(std::move(slot));
        }
        for (std::size_t i = 0; i < slots.size(); ++i) {
            fonts.variations_for(i, shape.variations, wanted);
            if (same_variations(wanted, slots[i].applied)) continue;
            Font& font = fonts.font(i);
            if (auto set = font.set_variations(wanted); !set) {
                const std::string& m = set.error().message;
                return m.find(font.file()) == std::string::npos ? Error{font.file() + ": " + m}
                                                                : set.error();
            }
            slots[i].applied = wanted;
        }
        return ok_status();
    }
};

TextRenderer::TextRenderer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
TextRenderer::TextRenderer(TextRenderer&&) noexcept = default;
TextRenderer& TextRenderer::operator=(TextRenderer&&) noexcept = default;
TextRenderer::~TextRenderer() = default;

Expected<TextRenderer> TextRenderer::open(const std::string& file, int face_index,
                                          std::size_t cache_bytes) {
    auto fonts = FontCollection::open({FontSource{file, face_index, {}}});
    if (!fonts) return fonts.error();
    return open(std::move(*fonts), cache_bytes);
}

Expected<TextRenderer> TextRenderer::open(const FontFace& face, std::size_t cache_bytes) {
    auto fonts = FontCollection::from_face(face);
    if (!fonts) return fonts.error();
    return open(std::move(*fonts), cache_bytes);
}

Expected<TextRenderer> TextRenderer::open(FontCollection fonts, std::size_t cache_bytes) {
    return TextRenderer(std::make_unique<Impl>(std::move(fonts), cache_bytes));
}

Font& TextRenderer::font() { return impl_->fonts.font(0); }
Shaper& TextRenderer::shaper() { return impl_->fonts.shaper(0); }
FontCollection& TextRenderer::fonts() { return impl_->fonts; }
GlyphCache& TextRenderer::cache() { return impl_->cache; }
const MissingGlyphs& TextRenderer::missing_glyphs() const { return impl_->missing; }
bool TextRenderer::last_text_has_color() const { return impl_->has_color; }
std::size_t TextRenderer::last_text_svg_glyphs() const { return impl_->svg_glyphs; }

// Shapes and lays out `utf8` with every font prepared, and notes the text's missing, colour and
// SVG glyphs; a gray page refuses text with colour glyphs here, before it is made.
Expected<TextLayout> TextRenderer::lay_out(std::string_view utf8, const TextRenderOptions& options,
                                           bool gray_page) {
    Impl& r = *impl_;
    // A bitmap-only colour font drawn without colour would have no glyphs at all.
    r.fonts.set_outlines_only(!options.color.enabled);
    if (auto ok = r.prepare_fonts(options.shape); !ok) return ok.error();
    r.missing = MissingGlyphs{};
    r.has_color = false;
    r.svg_glyphs = 0;
    auto layout = layout_text(r.fonts, utf8, options.shape, options.layout);
    if (!layout) return layout.error();
    r.missing = find_missing_glyphs(*layout, utf8);
    // Fonts the fallback added while laying out.
    if (auto ok = r.prepare_fonts(options.shape); !ok) return ok.error();
    for (const PlacedGlyph& g : layout->glyphs) {
        const ColorFormat format = r.slots[g.font].rasterizer->color_format(g.gid);
        if (format == ColorFormat::Svg) ++r.svg_glyphs;
        if (drawn_in_color(format)) r.has_color = r.has_color || options.color.enabled;
    }
    if (gray_page && r.has_color)
        return Error{"render_gray: the text holds colour glyphs, which a gray page cannot show "
                     "(render() draws it in RGBA)"};
    return layout;
}

namespace {

// The page render() and render_gray() make for `layout`: at least one pixel (empty text still
// gives a background image), at most kMaxImageDim a side and kMaxPagePixels in all.
Status page_size(const TextLayout& layout, int& width, int& height) {
    const double w = std::ceil(layout.width_px), h = std::ceil(layout.height_px);
    if (!(w <= kMaxImageDim && h <= kMaxImageDim && w * h <= kMaxPagePixels))
        return Error{"text page of " + whole_number(w) + "x" + whole_number(h) +
                     " px is too large (at most " + std::to_string(kMaxImageDim) + " px a side, " +
                     std::to_string(static_cast<long>(kMaxPagePixels)) + " px in all)"};
    width = std::max(1, static_cast<int>(w));
    height = std::max(1, static_cast<int>(h));
    return ok_status();
}

}  // namespace

// Blends each placed glyph of `layout`, moved by `origin`, from the cache onto `target`: colour
// glyphs "over", masks in the foreground through `curve`. With a sink, rows of the target are
// reported final as no glyph still to come reaches them.
Status TextRenderer::draw_glyphs(const TextLayout& layout, const TextRenderOptions& options,
                                 const PixelView& target, Point origin,
                                 const CoverageCurve& curve, PageRowsSink* rows_sink) {
    Impl& r = *impl_;
    const int page_h = target.height;
    GlyphRenderOptions glyph;
    glyph.size_px = options.shape.size_px;
    glyph.fill.format = options.format;
    glyph.fill.lcd_order = options.lcd_order;
    glyph.hinting = options.hinting;
    glyph.slant = options.slant;
    glyph.bold = options.shape.bold;   // the layout's advances were widened by the same value
    glyph.color = options.color;
    glyph.color.foreground = options.foreground;
    const bool whole_pixel_pen = hints_horizontally(options.hinting);
    const bool subpixel_y = options.hinting == Hinting::None &&
                            (options.shape.direction == Direction::TopToBottom ||
                             options.shape.direction == Direction::BottomToTop);
    // The cached glyph at g's pen, with its top-left pixel; null for an empty glyph or a pen
    // more than 2·kMaxImageDim off the target's origin, which no glyph (at most kMaxBitmapDim
    // wide) can carry onto a target of at most kMaxImageDim (this guards the int conversions).
    auto look_up = [&](const PlacedGlyph& g, int& x, int& y) -> Expected<const CachedGlyph*> {
        const double pen_x = g.x_px + origin.x, pen_y = g.y_px + origin.y;
        const double quarters = whole_pixel_pen
                                    ? std::floor(pen_x + 0.5) * kSubpixelBins
                                    : std::floor(pen_x * kSubpixelBins + 0.5);
        const double column = std::floor(quarters / kSubpixelBins);
        glyph.offset_px.x = (quarters - column * kSubpixelBins) / kSubpixelBins;
        double row = std::floor(pen_y + 0.5);
        glyph.offset_px.y = 0;
        if (subpixel_y) {
            const double bins = std::floor(pen_y * kSubpixelBins + 0.5);
            row = std::floor(bins / kSubpixelBins);
            glyph.offset_px.y = (bins - row * kSubpixelBins) / kSubpixelBins;
        }
        if (std::fabs(column) > kMaxImageDim * 2.0 || std::fabs(row) > kMaxImageDim * 2.0)
            return nullptr;
        FontSlot& slot = r.slots[g.font];
        auto cached = r.cache.get(*slot.rasterizer, g.gid, glyph);
        if (!cached) return cached.error();
        const CachedGlyph& c = **cached;
        if (c.box.width == 0) return nullptr;
        x = static_cast<int>(column) + c.box.left;
        y = static_cast<int>(row) - c.box.top;
        return &c;
    };
    const std::vector<PlacedGlyph>& glyphs = layout.glyphs;
    // first_row[i]: the top row of glyphs i.. (page_h when none reaches the page).
    std::vector<int> first_row;
    if (rows_sink != nullptr) {
        first_row.assign(glyphs.size() + 1, page_h);
        for (std::size_t i = glyphs.size(); i-- > 0;) {
            int x = 0, y = page_h;
            auto c = look_up(glyphs[i], x, y);
            if (!c) return c.error();
            first_row[i] = std::min(first_row[i + 1], *c != nullptr ? y : page_h);
        }
    }
    int reported = 0;
    for (std::size_t i = 0; i < glyphs.size(); ++i) {
        int x = 0, y = 0;
        auto c = look_up(glyphs[i], x, y);
        if (!c) return c.error();
        if (*c != nullptr) {
            const CachedGlyph& cached = **c;
            if (cached.box.color)
                blend_image(target,
                            ConstPixelView(cached.rgba.data, cached.rgba.width, cached.rgba.height,
                                           cached.rgba.stride, PixelFormat::Rgba8Premultiplied),
                            x, y);
            else if (options.format == CoverageFormat::Gray)
                blend_mask(target, cached.mask, x, y, options.foreground, curve);
            else
                // The mask's bytes are in the panel's order (raster.hpp's CoverageFormat::Lcd).
                blend_lcd_mask(target, cached.mask, x, y, options.foreground, options.lcd_order,
                               curve);
        }
        if (rows_sink != nullptr && first_row[i + 1] > reported) {
            reported = first_row[i + 1];
            rows_sink->rows_final(reported);
        }
    }
    if (rows_sink != nullptr) rows_sink->rows_final(page_h);
    return ok_status();
}

namespace {

// LCD text needs a colour target over opaque paper: subpixel coverage is three coverages a
// pixel, which one alpha channel cannot keep and one gray byte cannot show.
Status check_lcd(const TextRenderOptions& options, const char* call) {
    if (options.format == CoverageFormat::Lcd && options.background.a != 255)
        return Error{std::string(call) + ": LCD coverage needs an opaque background (alpha 255)"};
    return ok_status();
}

}  // namespace

Expected<TextLayout> TextRenderer::layout(std::string_view utf8, const TextRenderOptions& options) {
    return lay_out(utf8, options, false);
}

Status TextRenderer::draw(std::string_view utf8, const TextRenderOptions& options,
                          const PixelView& target, Point origin_px) {
    auto laid_out = lay_out(utf8, options, false);
    if (!laid_out) return laid_out.error();
    return draw(*laid_out, options, target, origin_px);
}

Status TextRenderer::draw(const TextLayout& layout, const TextRenderOptions& options,
                          const PixelView& target, Point origin_px) {
    if (Status ok = check_lcd(options, "draw"); !ok) return ok;
    if (options.format == CoverageFormat::Lcd && target.format == PixelFormat::Gray8)
        return Error{"draw: LCD coverage needs an RGBA or BGRA target (a gray pixel has no "
                     "subpixels)"};
    if (target.width < 0 || target.height < 0 || target.width > kMaxImageDim ||
        target.height > kMaxImageDim)
        return Error{"draw: target " + std::to_string(target.width) + "x" +
                     std::to_string(target.height) + " is outside 0.." +
                     std::to_string(kMaxImageDim) + " px a side"};
    if (target.data == nullptr && target.width > 0 && target.height > 0)
        return Error{"draw: target " + std::to_string(target.width) + "x" +
                     std::to_string(target.height) + " has no pixel memory (null data)"};
    if (!std::isfinite(origin_px.x) || !std::isfinite(origin_px.y))
        return Error{"draw: origin is not finite (NaN or infinity)"};
    // The fonts at the coordinates these options shape at (a layout made with other variations
    // would be drawn with these glyphs).
    if (Status ok = impl_->prepare_fonts(options.shape); !ok) return ok;
    for (const PlacedGlyph& g : layout.glyphs)
        if (g.font >= impl_->slots.size())
            return Error{"draw: the layout names font " + std::to_string(g.font) +
                         ", which this renderer does not have (lay it out with this renderer)"};
    auto curve = coverage_curve(options.foreground, options.background, options.coverage);
    if (!curve) return curve.error();
    return draw_glyphs(layout, options, target, origin_px, *curve, nullptr);
}

Expected<Image> TextRenderer::render(std::string_view utf8, const TextRenderOptions& options) {
    if (Status ok = check_lcd(options, "render"); !ok) return ok.error();
    auto curve = coverage_curve(options.foreground, options.background, options.coverage);
    if (!curve) return curve.error();
    auto laid_out = lay_out(utf8, options, false);
    if (!laid_out) return laid_out.error();
    int w = 0, h = 0;
    if (Status ok = page_size(*laid_out, w, h); !ok) return ok.error();
    Image out(w, h, options.background);
    if (Status ok = draw_glyphs(*laid_out, options, out.view(), {}, *curve, nullptr); !ok)
        return ok.error();
    return out;
}

Expected<Mask> TextRenderer::render_gray(std::string_view utf8, const TextRenderOptions& options) {
    Mask out;
    auto drawn = draw_gray(utf8, options, out, nullptr);
    if (!drawn) return drawn.error();
    return out;
}

Status TextRenderer::render_gray_streaming(std::string_view utf8, const TextRenderOptions& options,
                                           Mask& page, PageRowsSink& rows_sink) {
    return draw_gray(utf8, options, page, &rows_sink);
}

Status TextRenderer::draw_gray(std::string_view utf8, const TextRenderOptions& options, Mask& page,
                               PageRowsSink* rows_sink) {
    const Rgba8 fg = options.foreground, bg = options.background;
    if (options.format != CoverageFormat::Gray)
        return Error{"render_gray: needs CoverageFormat::Gray (LCD coverage is per channel)"};
    if (!(fg.r == fg.g && fg.g == fg.b && bg.r == bg.g && bg.g == bg.b && fg.a == 255 &&
          bg.a == 255))
        return Error{"render_gray: needs opaque gray foreground and background colours"};
    auto curve = coverage_curve(fg, bg, options.coverage);
    if (!curve) return curve.error();
    auto laid_out = lay_out(utf8, options, true);
    if (!laid_out) return laid_out.error();
    int w = 0, h = 0;
    if (Status ok = page_size(*laid_out, w, h); !ok) return ok;
    // The paper's byte written once (a zeroed page then filled would write it twice).
    page = Mask(w, h, bg.r);
    const MaskView v = page.view();
    // A gray page is a Gray8 view: blend_mask there is blend_mask_gray, bit for bit.
    return draw_glyphs(*laid_out, options, PixelView{v.data, v.width, v.height, v.stride,
                                                     PixelFormat::Gray8},
                       {}, *curve, rows_sink);
}

}  // namespace bezel
