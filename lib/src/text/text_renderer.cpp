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

// Shapes and lays out `utf8`, makes the page with make_page(width, height), then hands each
// placed glyph's cached glyph and its top-left pixel to blend(page, glyph, x, y). One loop for the
// RGBA and the gray page; a gray page refuses text with colour glyphs before it is made.
template <typename Page, typename MakePage, typename Blend>
Status TextRenderer::draw(std::string_view utf8, const TextRenderOptions& options, Page& page,
                          MakePage&& make_page, Blend&& blend, bool gray_page,
                          PageRowsSink* rows_sink) {
    Impl& r = *impl_;
    // A bitmap-only colour font drawn without colour would have no glyphs at all.
    r.fonts.set_outlines_only(!options.color.enabled);
    if (auto ok = r.prepare_fonts(options.shape); !ok) return ok;
    r.missing = MissingGlyphs{};
    r.has_color = false;
    r.svg_glyphs = 0;
    auto layout = layout_text(r.fonts, utf8, options.shape, options.layout);
    if (!layout) return layout.error();
    r.missing = find_missing_glyphs(*layout, utf8);
    // Fonts the fallback added while laying out.
    if (auto ok = r.prepare_fonts(options.shape); !ok) return ok;
    for (const PlacedGlyph& g : layout->glyphs) {
        const ColorFormat format = r.slots[g.font].rasterizer->color_format(g.gid);
        if (format == ColorFormat::Svg) ++r.svg_glyphs;
        if (drawn_in_color(format)) r.has_color = r.has_color || options.color.enabled;
    }
    if (gray_page && r.has_color)
        return Error{"render_gray: the text holds colour glyphs, which a gray page cannot show "
                     "(render() draws it in RGBA)"};

    const double w = std::ceil(layout->width_px), h = std::ceil(layout->height_px);
    if (!(w <= kMaxImageDim && h <= kMaxImageDim && w * h <= kMaxPagePixels))
        return Error{"text page of " + whole_number(w) + "x" + whole_number(h) +
                     " px is too large (at most " + std::to_string(kMaxImageDim) + " px a side, " +
                     std::to_string(static_cast<long>(kMaxPagePixels)) + " px in all)"};
    // A page is at least one pixel: empty text still gives a (background) image.
    const int page_h = std::max(1, static_cast<int>(h));
    page = make_page(std::max(1, static_cast<int>(w)), page_h);

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
    // The cached glyph at g's pen, with its top-left pixel; null for a pen far off the page (a
    // huge margin is refused by the size check above; this guards the int conversions) or an
    // empty glyph.
    auto look_up = [&](const PlacedGlyph& g, int& x, int& y) -> Expected<const CachedGlyph*> {
        const double quarters = whole_pixel_pen
                                    ? std::floor(g.x_px + 0.5) * kSubpixelBins
                                    : std::floor(g.x_px * kSubpixelBins + 0.5);
        const double column = std::floor(quarters / kSubpixelBins);
        glyph.offset_px.x = (quarters - column * kSubpixelBins) / kSubpixelBins;
        double row = std::floor(g.y_px + 0.5);
        glyph.offset_px.y = 0;
        if (subpixel_y) {
            const double bins = std::floor(g.y_px * kSubpixelBins + 0.5);
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
    const std::vector<PlacedGlyph>& glyphs = layout->glyphs;
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
        if (*c != nullptr) blend(page, **c, x, y);
        if (rows_sink != nullptr && first_row[i + 1] > reported) {
            reported = first_row[i + 1];
            rows_sink->rows_final(reported);
        }
    }
    if (rows_sink != nullptr) rows_sink->rows_final(page_h);
    return ok_status();
}

Expected<Image> TextRenderer::render(std::string_view utf8, const TextRenderOptions& options) {
    // Subpixel coverage is three coverages a pixel; one alpha channel cannot keep them, so LCD
    // text is blended only onto an opaque page.
    if (options.format == CoverageFormat::Lcd && options.background.a != 255)
        return Error{"render: LCD coverage needs an opaque background (alpha 255)"};
    auto curve = coverage_curve(options.foreground, options.background, options.coverage);
    if (!curve) return curve.error();
    Image out;
    auto drawn = draw<Image>(
        utf8, options, out, [&](int w, int h) { return Image(w, h, options.background); },
        [&](Image& onto, const CachedGlyph& glyph, int x, int y) {
            if (glyph.box.color)
                blend_rgba(onto, glyph.rgba, x, y);
            else if (options.format == CoverageFormat::Gray)
                blend_mask(onto, glyph.mask, x, y, options.foreground, *curve);
            else
                // LCD coverage is stored R, G, B per pixel whatever the panel's order (a BGR
                // panel's samples are reversed by the fill), so the bytes are RGB here.
                blend_lcd_mask(onto, glyph.mask, x, y, options.foreground, LcdOrder::Rgb, *curve);
        },
        false);
    if (!drawn) return drawn.error();
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
    return draw<Mask>(
        utf8, options, page,
        // The paper's byte written once (a zeroed page then filled would write it twice).
        [&](int w, int h) { return Mask(w, h, bg.r); },
        [&](Mask& onto, const CachedGlyph& glyph, int x, int y) {
            blend_mask_gray(onto.view(), glyph.mask, x, y, fg.r, *curve);
        },
        true, rows_sink);
}

}  // namespace bezel
