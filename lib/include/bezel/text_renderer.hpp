// bezel/text_renderer.hpp — the one-call text renderer: a font, its shaper, a glyph rasterizer and
// a glyph cache, drawing a laid-out paragraph onto a page.
//
// Units: pixels, y DOWN. Threading: one TextRenderer must not be used from two threads at once;
// separate TextRenderers, even of the same file, may run on separate threads.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "bezel/expected.hpp"
#include "bezel/font.hpp"
#include "bezel/glyph.hpp"
#include "bezel/image.hpp"
#include "bezel/layout.hpp"
#include "bezel/shape.hpp"

namespace bezel {

struct TextRenderOptions {
    ShapeOptions shape;
    LayoutOptions layout;
    RenderMode mode = RenderMode::Gray;
    Rgba8 foreground{0, 0, 0, 255};
    Rgba8 background{255, 255, 255, 255};
};

// Font + Shaper + GlyphRasterizer + GlyphCache for one font file: the one-call text renderer.
class TextRenderer {
public:
    // Errors name the file.
    static Expected<TextRenderer> open(const std::string& file, int face_index = 0,
                                       std::size_t cache_bytes = kDefaultGlyphCacheBytes);
    TextRenderer(TextRenderer&&) noexcept;
    TextRenderer& operator=(TextRenderer&&) noexcept;
    TextRenderer(const TextRenderer&) = delete;
    TextRenderer& operator=(const TextRenderer&) = delete;
    ~TextRenderer();

    Font& font();
    Shaper& shaper();
    GlyphCache& cache();

    // Shapes, lays out and draws `utf8` onto a new image sized to the layout (RGBA: background
    // filled, glyphs blended in linear light as image.hpp's blend functions). Errors as
    // layout_text, plus an image larger than kMaxImageDim.
    Expected<Image> render(std::string_view utf8, const TextRenderOptions& options);
    // The same page as one sRGB gray byte per pixel, for gray-on-gray text (what PNG and PGM
    // output of such text stores): equal to render()'s red (= green = blue) channel, pixel for
    // pixel, with a quarter of the memory to fill and blend. Errors as render(), plus a
    // foreground or background that is not opaque gray, or a mode other than RenderMode::Gray.
    Expected<Mask> render_gray(std::string_view utf8, const TextRenderOptions& options);
    // The same page drawn into `page` (replaced by the new page before any glyph is drawn),
    // telling rows_final(n) whenever rows [0, n) will not be written again, so a consumer can
    // work on the finished top of the page while the rest is drawn (bezel render deflates PNG
    // bands meanwhile: PngGrayStream). Glyphs are blended in layout order and a row is final
    // once no glyph still to come reaches it; n never decreases, and the last call has n = the
    // page height. rows_final must not write the page or resize it. The tops of the glyphs
    // still to come are known before drawing, at the cost of one more glyph-cache lookup per
    // glyph. Errors as render_gray; after an error `page` holds what was drawn.
    Status render_gray(std::string_view utf8, const TextRenderOptions& options, Mask& page,
                       const std::function<void(int rows)>& rows_final);

private:
    struct Impl;
    template <typename Page, typename MakePage, typename Blend>
    Status draw(std::string_view utf8, const TextRenderOptions& options, Page& page,
                MakePage&& make_page, Blend&& blend,
                const std::function<void(int rows)>* rows_final = nullptr);
    explicit TextRenderer(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace bezel
