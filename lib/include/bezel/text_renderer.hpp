// bezel/text_renderer.hpp — the one-call text renderer: a font, its shaper, a glyph rasterizer and
// a glyph cache, drawing a laid-out paragraph onto a page.
//
// Units: pixels, y DOWN. Threading: one TextRenderer must not be used from two threads at once;
// separate TextRenderers, even of the same file, may run on separate threads.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

#include "bezel/expected.hpp"
#include "bezel/font.hpp"
#include "bezel/font_collection.hpp"
#include "bezel/geometry.hpp"
#include "bezel/glyph.hpp"
#include "bezel/image.hpp"
#include "bezel/layout.hpp"
#include "bezel/shape.hpp"

#pragma GCC visibility push(default)  // the public API of libbezel.so (docs/architecture.md)
namespace bezel {

struct TextRenderOptions {
    ShapeOptions shape;
    LayoutOptions layout;
    CoverageFormat format = CoverageFormat::Gray;   // Lcd: subpixel text (RGB(A) pages only)
    LcdOrder lcd_order = LcdOrder::Rgb;   // Lcd: the panel's subpixel order (image.hpp)
    // Glyph outlines hinted by FreeType (font.hpp). Advances and positions stay HarfBuzz's
    // unhinted ones; a glyph hinted horizontally (Full, Auto) is drawn at the whole pixel nearest
    // its pen, since its stems were fitted to the grid at a whole-pixel origin; None and Light
    // keep subpixel pen x (a quarter pixel). The pen y is a whole pixel (one baseline row per
    // line), except for unhinted vertical text (a TopToBottom or BottomToTop direction), whose
    // glyphs advance along y and keep a quarter pixel there too.
    Hinting hinting = Hinting::None;
    // Synthetic slant of every glyph, as GlyphRenderOptions::slant. (Synthetic bold is
    // shape.bold: it widens the advances too, so it lives with the shaping it changes.)
    double slant = 0;
    Rgba8 foreground{0, 0, 0, 255};
    Rgba8 background{255, 255, 255, 255};
    // How coverage becomes ink (image.hpp): by default Perceptual, text as heavy as renderers
    // that mix encoded values draw it, in both polarities; TextRendering::Linear for the exact
    // linear-light mix (compositing, measuring). One curve per render, from the two colours.
    CoverageCurveOptions coverage;
    // Colour glyphs (glyph.hpp): drawn in colour by default, with palette 0; `color.foreground`
    // is ignored (`foreground` above is the text colour a COLR glyph's 0xFFFF entries take). A
    // colour glyph is composited onto the page "over" in linear light (paint.hpp's blend_rgba),
    // not through the coverage curve, and is gray anti-aliased in LCD text. With
    // `color.enabled` false every glyph is a mask in the foreground colour, and fallback takes
    // only fonts with outlines.
    GlyphColorOptions color;
};

// Receives the rows of a page that are finished while the rest is still drawn
// (TextRenderer::render_gray_streaming), so a consumer can encode or send the top of the page
// meanwhile (`bezel render` deflates PNG bands on other cores: PngGrayStream).
class PageRowsSink {
public:
    virtual ~PageRowsSink() = default;
    // Rows [0, rows) of the page will not be written again. `rows` never decreases from one call
    // to the next, and the last call has rows = the page height. The page exists (sized) by the
    // first call; rows_final must not write the page or resize it.
    virtual void rows_final(int rows) = 0;
};

// A FontCollection + a GlyphRasterizer per font + one GlyphCache: the one-call text renderer.
class TextRenderer {
public:
    // One font file. Errors name the file. A bitmap-only colour font (CBDT, sbix) opens: its
    // glyphs are drawn in colour (with TextRenderOptions::color.enabled false, drawing one is an
    // Error: the font has no outlines).
    static Expected<TextRenderer> open(const std::string& file, int face_index = 0,
                                       std::size_t cache_bytes = kDefaultGlyphCacheBytes);
    // A face already read (font_face.hpp: from memory, or shared with other renderers and
    // threads): the renderer's Font and Shaper are instances of it, nothing is read again.
    // Errors as FontCollection::add.
    static Expected<TextRenderer> open(const FontFace& face,
                                       std::size_t cache_bytes = kDefaultGlyphCacheBytes);
    // A list of fonts, text drawn with fallback (layout.hpp's layout_text over a collection).
    // A bitmap-only colour font (CBDT, sbix) may be in the list: its glyphs are drawn in colour.
    static Expected<TextRenderer> open(FontCollection fonts,
                                       std::size_t cache_bytes = kDefaultGlyphCacheBytes);
    TextRenderer(TextRenderer&&) noexcept;
    TextRenderer& operator=(TextRenderer&&) noexcept;
    TextRenderer(const TextRenderer&) = delete;
    TextRenderer& operator=(const TextRenderer&) = delete;
    ~TextRenderer();

    Font& font();        // the first font of the list
    Shaper& shaper();    // the first font's
    FontCollection& fonts();
    GlyphCache& cache();
    // The .notdef glyphs (characters the font does not map) of the last render, render_gray,
    // render_gray_streaming, layout or draw (of a string) call that got as far as laying out
    // the text; all zero before.
    const MissingGlyphs& missing_glyphs() const;
    // Whether the text of the last call holds a glyph drawn in colour. render_gray and
    // render_gray_streaming refuse such text with an Error, after laying it out and before
    // drawing or sizing anything (one gray byte a pixel cannot show colour), and this is then
    // true: the caller draws the page with render() instead (`bezel render` writes such a page as
    // RGB or RGBA where its text would have been gray).
    bool last_text_has_color() const;
    // How many glyphs of the last call's text the font has only as SVG colour glyphs, which bezel
    // does not paint: they were drawn from their outlines (or as .notdef). 0 before any call.
    std::size_t last_text_svg_glyphs() const;

    // ShapeOptions::variations apply to the first font (layout.hpp).
    // Shapes, lays out and draws `utf8` onto a new image sized to the layout (RGBA: background
    // filled, glyphs blended in linear light as image.hpp's blend functions, through the
    // coverage curve of options.coverage): draw() onto an Image of the background. Errors as layout_text and coverage_curve, plus an
    // image larger than kMaxImageDim, and CoverageFormat::Lcd with a background that is not
    // opaque (one alpha channel cannot hold three subpixel coverages).
    Expected<Image> render(std::string_view utf8, const TextRenderOptions& options);
    // The same page as one sRGB gray byte per pixel, for gray-on-gray text (what PNG and PGM
    // output of such text stores): equal to render()'s red (= green = blue) channel, pixel for
    // pixel, with a quarter of the memory to fill and blend. Errors as render(), plus a
    // foreground or background that is not opaque gray, or a format other than CoverageFormat::Gray.
    Expected<Mask> render_gray(std::string_view utf8, const TextRenderOptions& options);
    // render_gray's page drawn into `page` (replaced by the new page before any glyph is drawn),
    // streamed: `rows_sink` hears of each run of rows as soon as no glyph still to come reaches
    // it (glyphs are blended in layout order). Knowing the tops of the glyphs to come costs one
    // more glyph-cache lookup per glyph. Errors as render_gray; after an error `page` holds what
    // was drawn and the sink may not have heard of the last rows.
    Status render_gray_streaming(std::string_view utf8, const TextRenderOptions& options,
                                 Mask& page, PageRowsSink& rows_sink);

    // --- Drawing into the caller's pixels (a toolkit's surface or atlas) ---------------------
    // Shapes and lays out `utf8` as render() would, without drawing: the glyphs' pen positions,
    // the lines (baselines, ascent, descent, widths) and the page size render() would make
    // (width_px × height_px, margins included), all in pixels, y down, relative to the page's
    // top-left corner. Sets missing_glyphs(), last_text_has_color() and
    // last_text_svg_glyphs(). Errors as layout_text.
    Expected<TextLayout> layout(std::string_view utf8, const TextRenderOptions& options);
    // Lays out `utf8` and blends it onto `target` with the page's top-left corner (what is (0, 0)
    // in layout()) at `origin_px` in target pixels, which may be fractional (pens are then
    // placed as render() places them, from the moved positions) or put the text partly or
    // wholly outside the target (it is clipped to the target, not to the page: a glyph that
    // overhangs the margins, which render() cuts off, is drawn whole). Nothing else is
    // written: no background is filled, and only pixels under glyphs change, each blended in
    // linear light by image.hpp's functions (blend_mask through the coverage curve of
    // options.foreground over options.background, blend_lcd_mask in options.lcd_order, colour
    // glyphs by blend_image "over"). options.background is not drawn: it is the colour the
    // text weight is made for (the coverage curve) and should be the colour under the text. A
    // Gray8 target shows colour glyphs and a coloured foreground as their luma (image.hpp).
    // Drawing onto an Image of
    // options.background at origin (0, 0) gives render()'s page, pixel for pixel.
    // Errors, each before any pixel is written: layout_text's and coverage_curve's; a target of
    // negative size, larger than kMaxImageDim, or null with nonzero size; a non-finite origin;
    // CoverageFormat::Lcd onto a Gray8 target or with a background that is not opaque (LCD text
    // is for opaque surfaces; its blend on a pixel that is not opaque is image.hpp's).
    Status draw(std::string_view utf8, const TextRenderOptions& options, const PixelView& target,
                Point origin_px);
    // Draws a layout made by layout() of this renderer (so a toolkit can measure, place and draw
    // with one shaping), as above. `options` should be those it was laid out with: the glyphs
    // are drawn at options' size and variations. Errors as above, plus a layout naming a font
    // this renderer does not have.
    Status draw(const TextLayout& layout, const TextRenderOptions& options,
                const PixelView& target, Point origin_px);

private:
    struct Impl;
    Expected<TextLayout> lay_out(std::string_view utf8, const TextRenderOptions& options,
                                 bool gray_page);
    Status draw_glyphs(const TextLayout& layout, const TextRenderOptions& options,
                       const PixelView& target, Point origin, const CoverageCurve& curve,
                       PageRowsSink* rows_sink);
    Status draw_gray(std::string_view utf8, const TextRenderOptions& options, Mask& page,
                     PageRowsSink* rows_sink);
    explicit TextRenderer(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace bezel
#pragma GCC visibility pop
