// bezel_text_renderer: a TextRenderer over a FontCollection of the caller's fonts; pages into
// caller pixels.
#include <cmath>
#include <string_view>

#include "bezel/font_collection.hpp"
#include "bezel/limits.hpp"
#include "capi/handles.hpp"

using namespace bezel;
using namespace bezel::capi_detail;

namespace {

bezel_status to_text_options(ErrorSlot* err, const char* fn, const bezel_text_options* options,
                             TextRenderOptions& out) {
    bezel_text_options o;
    bezel_text_options_init(&o);
    if (options) o = *options;
    if (!(o.size_px > 0 && o.size_px <= kMaxFontSizePx))
        return fail(err, BEZEL_STATUS_OUT_OF_RANGE,
                    std::string(fn) + ": size_px " + std::to_string(o.size_px) +
                        " is outside (0, " + std::to_string(static_cast<int>(kMaxFontSizePx)) +
                        "]");
    const int align = raw_enum(o.align);
    if (align != BEZEL_ALIGN_START && align != BEZEL_ALIGN_CENTER && align != BEZEL_ALIGN_END)
        return fail(err, BEZEL_STATUS_INVALID_ARGUMENT,
                    std::string(fn) + ": align " + std::to_string(align) +
                        " is not a bezel_align (0..2)");
    TextRenderOptions t;
    t.shape.size_px = o.size_px;
    if (o.language) t.shape.language = o.language;
    if (o.script) t.shape.script = o.script;
    // layout_text refuses negative and non-finite widths, margins and line heights by name.
    t.layout.width_px = o.width_px;
    t.layout.line_height = o.line_height;
    t.layout.margin_px = o.margin_px;
    t.layout.align = align == BEZEL_ALIGN_CENTER ? Align::Center
                     : align == BEZEL_ALIGN_END  ? Align::End
                                                   : Align::Start;
    if (bezel_status s = to_hinting(err, fn, raw_enum(o.hinting), t.hinting)) return s;
    if (bezel_status s = to_coverage(err, fn, raw_enum(o.coverage), t.format, t.lcd_order))
        return s;
    t.foreground = {o.foreground.r, o.foreground.g, o.foreground.b, o.foreground.a};
    t.background = {o.background.r, o.background.g, o.background.b, o.background.a};
    out = std::move(t);
    return BEZEL_STATUS_OK;
}

bezel_status to_format(ErrorSlot* err, const char* fn, int in, PixelFormat& out) {
    switch (in) {
    case BEZEL_PIXEL_GRAY8: out = PixelFormat::Gray8; return BEZEL_STATUS_OK;
    case BEZEL_PIXEL_RGBA8: out = PixelFormat::Rgba8; return BEZEL_STATUS_OK;
    case BEZEL_PIXEL_BGRA8: out = PixelFormat::Bgra8; return BEZEL_STATUS_OK;
    case BEZEL_PIXEL_RGBA8_PREMULTIPLIED:
        out = PixelFormat::Rgba8Premultiplied;
        return BEZEL_STATUS_OK;
    case BEZEL_PIXEL_BGRA8_PREMULTIPLIED:
        out = PixelFormat::Bgra8Premultiplied;
        return BEZEL_STATUS_OK;
    }
    return fail(err, BEZEL_STATUS_INVALID_ARGUMENT,
                std::string(fn) + ": format " + std::to_string(in) +
                    " is not a bezel_pixel_format (0..4)");
}

// The text, or an error for NULL data with a nonzero length.
bezel_status to_text(ErrorSlot* err, const char* fn, const char* utf8, std::size_t length,
                     std::string_view& out) {
    if (!utf8 && length > 0) return null_argument(err, fn, "utf8 (with a nonzero length)");
    if (length > kMaxTextBytes)
        return fail(err, BEZEL_STATUS_OUT_OF_RANGE,
                    std::string(fn) + ": " + std::to_string(length) +
                        " bytes of text is more than kMaxTextBytes (" +
                        std::to_string(kMaxTextBytes) + ")");
    out = std::string_view(utf8 ? utf8 : "", length);
    return BEZEL_STATUS_OK;
}

// The page render() makes for `layout` (text_renderer.cpp's page_size: at least one pixel).
bezel_status page_extent(ErrorSlot* err, const char* fn, const TextLayout& layout,
                         std::size_t missing, bezel_text_extent& out) {
    const double w = std::ceil(layout.width_px), h = std::ceil(layout.height_px);
    if (!(w <= kMaxImageDim && h <= kMaxImageDim))
        return fail(err, BEZEL_STATUS_OUT_OF_RANGE,
                    std::string(fn) + ": the text page of " + std::to_string(w) + "x" +
                        std::to_string(h) + " px is larger than " + std::to_string(kMaxImageDim) +
                        " px a side (kMaxImageDim)");
    out = bezel_text_extent{};
    out.width = std::max(1, static_cast<int>(w));
    out.height = std::max(1, static_cast<int>(h));
    out.first_baseline_px = layout.lines.empty() ? 0 : layout.lines.front().baseline_y_px;
    out.line_count = layout.lines.size();
    out.missing_glyphs = missing;
    return BEZEL_STATUS_OK;
}

// LCD text needs three coverages per pixel and an opaque surface: refused before anything is
// written (TextRenderer::draw refuses it too, but render() has filled the background by then).
bezel_status check_lcd(ErrorSlot* err, const char* fn, const TextRenderOptions& t,
                       PixelFormat format) {
    if (t.format != CoverageFormat::Lcd) return BEZEL_STATUS_OK;
    if (format == PixelFormat::Gray8)
        return fail(err, BEZEL_STATUS_INVALID_ARGUMENT,
                    std::string(fn) + ": LCD coverage needs a colour format, not GRAY8");
    if (t.background.a != 255)
        return fail(err, BEZEL_STATUS_INVALID_ARGUMENT,
                    std::string(fn) + ": LCD coverage needs an opaque background");
    return BEZEL_STATUS_OK;
}

// The arguments bezel_text_render and bezel_text_draw share, checked and converted: the text,
// its options and the pixel format (its raw int: raw_enum), which must agree about LCD coverage.
bezel_status to_text_call(ErrorSlot* err, const char* fn, const char* utf8, std::size_t length,
                          const bezel_text_options* options, int format,
                          std::string_view& text, TextRenderOptions& t, PixelFormat& pixel_format) {
    if (bezel_status s = to_text(err, fn, utf8, length, text)) return s;
    if (bezel_status s = to_text_options(err, fn, options, t)) return s;
    if (bezel_status s = to_format(err, fn, format, pixel_format)) return s;
    return check_lcd(err, fn, t, pixel_format);
}

}  // namespace

extern "C" {

void bezel_text_options_init(bezel_text_options* options) {
    if (!options) return;
    *options = bezel_text_options{};
    options->size_px = 16;
    options->align = BEZEL_ALIGN_START;
    options->hinting = BEZEL_HINTING_NONE;
    options->coverage = BEZEL_COVERAGE_GRAY;
    options->foreground = bezel_rgba{0, 0, 0, 255};
    options->background = bezel_rgba{255, 255, 255, 255};
}

bezel_status bezel_text_renderer_create(bezel_font* const* fonts, std::size_t font_count,
                                        bezel_text_renderer** out) {
    static const char* const fn = "bezel_text_renderer_create";
    return guarded(nullptr, fn, [&]() -> bezel_status {
        if (!fonts) return null_argument(nullptr, fn, "fonts");
        if (!out) return null_argument(nullptr, fn, "out");
        if (font_count == 0 || font_count > kMaxCollectionFonts)
            return fail(nullptr, BEZEL_STATUS_OUT_OF_RANGE,
                        std::string(fn) + ": font_count " + std::to_string(font_count) +
                            " is outside 1.." + std::to_string(kMaxCollectionFonts) +
                            " (kMaxCollectionFonts)");
        for (std::size_t i = 0; i < font_count; ++i)
            if (!fonts[i])
                return null_argument(nullptr, fn, ("fonts[" + std::to_string(i) + "]").c_str());
        Expected<FontCollection> list =
            FontCollection::from_face(fonts[0]->face, fonts[0]->variations);
        if (!list) return fail(nullptr, BEZEL_STATUS_FONT_ERROR, list.error().message);
        for (std::size_t i = 1; i < font_count; ++i) {
            Expected<std::size_t> added = list->add(fonts[i]->face, fonts[i]->variations);
            if (!added) return fail(nullptr, BEZEL_STATUS_FONT_ERROR, added.error().message);
        }
        Expected<TextRenderer> renderer = TextRenderer::open(std::move(*list));
        if (!renderer) return fail(nullptr, BEZEL_STATUS_FONT_ERROR, renderer.error().message);
        *out = new bezel_text_renderer{std::move(*renderer), {}};
        return BEZEL_STATUS_OK;
    });
}

void bezel_text_renderer_destroy(bezel_text_renderer* renderer) { delete renderer; }

const char* bezel_text_renderer_last_error(const bezel_text_renderer* renderer) {
    return renderer ? renderer->error.c_str() : bezel_last_error();
}

bezel_status bezel_text_measure(bezel_text_renderer* renderer, const char* utf8, std::size_t length,
                                const bezel_text_options* options, bezel_text_extent* extent) {
    static const char* const fn = "bezel_text_measure";
    if (!renderer) return null_argument(nullptr, fn, "renderer");
    ErrorSlot* err = &renderer->error;
    return guarded(err, fn, [&]() -> bezel_status {
        if (!extent) return null_argument(err, fn, "extent");
        std::string_view text;
        if (bezel_status s = to_text(err, fn, utf8, length, text)) return s;
        TextRenderOptions t;
        if (bezel_status s = to_text_options(err, fn, options, t)) return s;
        Expected<TextLayout> layout = renderer->renderer.layout(text, t);
        if (!layout) return fail(err, BEZEL_STATUS_INVALID_ARGUMENT, layout.error().message);
        return page_extent(err, fn, *layout, renderer->renderer.missing_glyphs().count, *extent);
    });
}

bezel_status bezel_text_render(bezel_text_renderer* renderer, const char* utf8, std::size_t length,
                               const bezel_text_options* options, bezel_pixel_format format,
                               std::uint8_t* buffer, std::size_t buffer_size, std::ptrdiff_t stride,
                               bezel_text_extent* extent) {
    static const char* const fn = "bezel_text_render";
    if (!renderer) return null_argument(nullptr, fn, "renderer");
    ErrorSlot* err = &renderer->error;
    return guarded(err, fn, [&]() -> bezel_status {
        std::string_view text;
        TextRenderOptions t;
        PixelFormat pixel_format{};
        if (bezel_status s =
                to_text_call(err, fn, utf8, length, options, raw_enum(format), text, t,
                             pixel_format))
            return s;
        Expected<TextLayout> layout = renderer->renderer.layout(text, t);
        if (!layout) return fail(err, BEZEL_STATUS_INVALID_ARGUMENT, layout.error().message);
        bezel_text_extent page;
        if (bezel_status s = page_extent(err, fn, *layout,
                                         renderer->renderer.missing_glyphs().count, page))
            return s;
        if (extent) *extent = page;
        const std::size_t bpp = static_cast<std::size_t>(bytes_per_pixel(pixel_format));
        if (bezel_status s = check_buffer(err, std::string(fn) + ": text page", buffer,
                                          buffer_size, stride,
                                          static_cast<std::size_t>(page.width) * bpp,
                                          static_cast<std::size_t>(page.height)))
            return s;
        const PixelView view{buffer, page.width, page.height, stride, pixel_format};
        // The page's background, then the text over it: TextRenderer::render()'s page, pixel for
        // pixel (text_renderer.hpp: drawing onto the background at (0, 0) gives it).
        std::uint8_t background[4];
        store_pixel(pixel_format, background, t.background);
        for (int y = 0; y < page.height; ++y)
            for (int x = 0; x < page.width; ++x)
                for (std::size_t k = 0; k < bpp; ++k) view.pixel(x, y)[k] = background[k];
        Status drawn = renderer->renderer.draw(*layout, t, view, Point{0, 0});
        if (!drawn) return fail(err, BEZEL_STATUS_INVALID_ARGUMENT, drawn.error().message);
        return BEZEL_STATUS_OK;
    });
}

bezel_status bezel_text_draw(bezel_text_renderer* renderer, const char* utf8, std::size_t length,
                             const bezel_text_options* options, bezel_pixel_format format,
                             std::uint8_t* buffer, std::size_t buffer_size, int width, int height,
                             std::ptrdiff_t stride, double x_px, double y_px) {
    static const char* const fn = "bezel_text_draw";
    if (!renderer) return null_argument(nullptr, fn, "renderer");
    ErrorSlot* err = &renderer->error;
    return guarded(err, fn, [&]() -> bezel_status {
        std::string_view text;
        TextRenderOptions t;
        PixelFormat pixel_format{};
        if (bezel_status s =
                to_text_call(err, fn, utf8, length, options, raw_enum(format), text, t,
                             pixel_format))
            return s;
        if (width < 0 || height < 0 || width > kMaxImageDim || height > kMaxImageDim)
            return fail(err, BEZEL_STATUS_OUT_OF_RANGE,
                        std::string(fn) + ": surface " + std::to_string(width) + "x" +
                            std::to_string(height) + " is outside 0.." +
                            std::to_string(kMaxImageDim) + " px a side (kMaxImageDim)");
        if (!(std::isfinite(x_px) && std::isfinite(y_px)))
            return fail(err, BEZEL_STATUS_INVALID_ARGUMENT,
                        std::string(fn) + ": origin (" + std::to_string(x_px) + ", " +
                            std::to_string(y_px) + ") is not finite");
        const std::size_t bpp = static_cast<std::size_t>(bytes_per_pixel(pixel_format));
        if (bezel_status s = check_buffer(err, std::string(fn) + ": surface", buffer, buffer_size,
                                          stride, static_cast<std::size_t>(width) * bpp,
                                          static_cast<std::size_t>(height)))
            return s;
        const bool empty = width == 0 || height == 0;
        const PixelView view{empty ? nullptr : buffer, empty ? 0 : width, empty ? 0 : height,
                             stride, pixel_format};
        Status drawn = renderer->renderer.draw(text, t, view, Point{x_px, y_px});
        if (!drawn) return fail(err, BEZEL_STATUS_INVALID_ARGUMENT, drawn.error().message);
        return BEZEL_STATUS_OK;
    });
}

}  // extern "C"
