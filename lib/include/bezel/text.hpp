// bezel/text.hpp — text to pixels: HarfBuzz shaping, line layout, glyph rasterization into caller
// buffers, a bounded glyph cache, and whole-paragraph rendering.
//
// Units: pixels, y DOWN. A glyph's pen position is on its baseline; a bitmap's `left`/`top`
// follow FreeType's bitmap_left / bitmap_top (top = rows ABOVE the baseline, so the bitmap's
// first row is at pen.y − top).
//
// Threading: Shaper, GlyphRasterizer, GlyphCache and TextRenderer hold a font (FreeType face or
// HarfBuzz font) and scratch memory; one object must not be used from two threads at once.
// Separate objects — even of the same font file — may be used on separate threads freely.
// Steady state allocates nothing per glyph: buffers are reused and the cache is bounded.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "bezel/expected.hpp"
#include "bezel/font.hpp"
#include "bezel/image.hpp"
#include "bezel/raster.hpp"

namespace bezel {

// --- Limits -------------------------------------------------------------------------------------
// Longest text one shape/layout/render call accepts, in bytes of UTF-8 (16 MiB). Past it, Error.
inline constexpr std::size_t kMaxTextBytes = std::size_t{1} << 24;
// Default bound of a GlyphCache's pixel memory (bytes of bitmaps it keeps): 16 MiB.
inline constexpr std::size_t kDefaultGlyphCacheBytes = std::size_t{1} << 24;

// --- UTF-8 --------------------------------------------------------------------------------------
// Decodes UTF-8 strictly (no overlong forms, no surrogates, nothing above U+10FFFF). The error
// names the byte offset of the first bad sequence: "text byte 7: invalid UTF-8".
Expected<std::u32string> decode_utf8(std::string_view text);
void append_utf8(std::string& out, char32_t code_point);

// --- Shaping ------------------------------------------------------------------------------------
enum class Direction : std::uint8_t { Auto, LeftToRight, RightToLeft, TopToBottom, BottomToTop };

// An OpenType feature setting in hb-view's syntax: "kern", "-liga", "+smcp", "aalt=2",
// "liga[3:5]=0" (a range of CLUSTER indices, end exclusive).
struct FeatureSetting {
    std::string tag;            // four characters
    std::uint32_t value = 1;
    std::size_t start = 0;      // cluster range [start, end)
    std::size_t end = SIZE_MAX;
};
// Parses a comma- (or space-) separated list of features in hb-view's syntax. The error names
// the item that does not parse.
Expected<std::vector<FeatureSetting>> parse_features(std::string_view spec);

struct ShapeOptions {
    double size_px = 16;                       // em size, (0, kMaxFontSizePx]
    std::vector<FeatureSetting> features;
    std::vector<VariationSetting> variations;  // design coordinates, as Font::set_variations
    Direction direction = Direction::Auto;     // Auto: from the text (first strong character)
    std::string script;                        // ISO 15924 ("Arab", "Deva"); "" = from the text
    std::string language;                      // BCP 47 ("ar", "hi"); "" = HarfBuzz's default
};

// One shaped glyph. Advances and offsets in pixels, y DOWN (HarfBuzz's y-up offsets negated).
struct ShapedGlyph {
    GlyphId gid = 0;
    std::uint32_t cluster = 0;   // byte offset in the UTF-8 input of the cluster's first character
    double x_advance = 0, y_advance = 0;
    double x_offset = 0, y_offset = 0;
};

// A shaped run, glyphs in VISUAL order (left to right for horizontal text, as HarfBuzz returns
// them for RTL too).
struct ShapedRun {
    std::vector<ShapedGlyph> glyphs;
    Direction direction = Direction::LeftToRight;  // resolved
    std::string script;                            // resolved ISO 15924 tag
    double advance = 0;                            // sum of advances along the direction
};

// HarfBuzz shaping of one font file (its own hb_face from the file; glyph ids are the same as
// Font's for the same file and face index).
class Shaper {
public:
    // Errors name the file: missing, not a font, face index out of range.
    static Expected<Shaper> open(const std::string& file, int face_index = 0);
    Shaper(Shaper&&) noexcept;
    Shaper& operator=(Shaper&&) noexcept;
    Shaper(const Shaper&) = delete;
    Shaper& operator=(const Shaper&) = delete;
    ~Shaper();

    // Shapes `utf8` as one run (no line breaking, no bidi reordering across runs). Errors:
    // invalid UTF-8 (offset named), text longer than kMaxTextBytes, size out of range, an
    // unknown variation axis, a script or language tag that does not parse.
    Expected<ShapedRun> shape(std::string_view utf8, const ShapeOptions& options);

private:
    struct Impl;
    explicit Shaper(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

// --- Line layout --------------------------------------------------------------------------------
enum class Align : std::uint8_t { Start, Center, End };

struct LayoutOptions {
    double width_px = 0;       // wrap lines at break opportunities to fit this width; 0 = no wrap
    double line_height = 0;    // baseline-to-baseline distance as a multiple of the font's own
                               // (ascender − descender + line gap); 0 means 1.0
    double margin_px = 0;      // around the text block on all four sides
    Align align = Align::Start;  // Start is left for LTR paragraphs and right for RTL ones
};

// A glyph placed on the page: pen position (baseline) in page pixels, y down.
struct PlacedGlyph {
    GlyphId gid = 0;
    double x = 0, y = 0;
    std::uint32_t cluster = 0;   // byte offset in the whole input text
};

struct LaidOutLine {
    std::size_t first_glyph = 0, glyph_count = 0;   // into TextLayout::glyphs
    std::uint32_t text_begin = 0, text_end = 0;     // byte range of the text on this line
    double baseline_y = 0;
    double width = 0;                               // advance width of the line's glyphs
};

struct TextLayout {
    std::vector<PlacedGlyph> glyphs;
    std::vector<LaidOutLine> lines;
    double width = 0, height = 0;   // page size including margins (width_px + margins if wrapping)
};

// Shapes and lays out a paragraph: explicit newlines (\n, \r\n, U+2028) start lines; with
// width_px > 0 lines wrap at break opportunities (after spaces, after hyphens, between ideographs;
// a word wider than the line is broken between clusters); each line is shaped per run of one
// script and direction, runs ordered right to left within an RTL paragraph. `metrics` gives line
// height. Errors as Shaper::shape, plus a negative or non-finite width/margin/line height,
// metrics with units_per_em ≤ 0, and a vertical direction (layout is horizontal only).
//
// Lines: N line separators make N + 1 lines (an empty text is one empty line); the first
// baseline is at margin + ascender; spaces at the end of a wrapped line hang (not placed, not
// counted in its width, but inside its text range). Where a line cuts a word between clusters,
// both pieces are reshaped (Arabic letters at the cut take their final/initial forms).
//
// Bidi is a simplified Unicode Bidirectional Algorithm (UAX #9), without fribidi. Implemented:
// the paragraph direction from its first strong character (P2/P3) unless shape.direction gives
// it; strong classes from the Unicode script (letters of Hebrew, Arabic, Syriac, Thaana, N'Ko, …
// are R, other letters L); marks take the class before them (W1); digits are left-to-right
// numbers, one level up unless they follow L text (W2, W7, I1, I2); neutrals between equal
// directions take it, others the paragraph's (N1, N2); runs reordered by level per line (L2).
// Left out: explicit embeddings, overrides and isolates (LRE…PDI are neutrals), the number
// separator/terminator rules W3–W6 ("1,000" or "5%" beside Arabic may split), paired brackets
// (N0), and L1 (trailing whitespace keeps its level; wrapped lines drop it instead). Line
// breaking is a subset of UAX #14: no dictionary breaking (Thai, Lao, Khmer), no quotation or
// numeric prefix/postfix classes.
Expected<TextLayout> layout_text(Shaper& shaper, const FontMetrics& metrics,
                                 std::string_view utf8, const ShapeOptions& shape,
                                 const LayoutOptions& layout);

// --- Glyph rasterization ------------------------------------------------------------------------
enum class RenderMode : std::uint8_t { Gray, LcdRgb, LcdBgr };

struct GlyphRenderOptions {
    double size_px = 16;
    double subpixel_x = 0;     // pen's fractional x offset in [0, 1)
    double subpixel_y = 0;     // in [0, 1)
    RenderMode mode = RenderMode::Gray;
    FillRule rule = FillRule::NonZero;
    // Accurate is chosen automatically for glyphs that mark overlapping contours; Accumulate
    // here never forces plain accumulation on them.
    OverlapMode overlap = OverlapMode::Accumulate;
    double tolerance_px = kDefaultRasterTolerancePx;
};

// Where a glyph bitmap sits relative to the pen, and its size. For LCD modes `width` counts
// DISPLAY pixels and the bitmap has 3 bytes per pixel.
struct GlyphBox {
    int left = 0, top = 0;        // bitmap_left / bitmap_top, as FreeType
    int width = 0, height = 0;
    double advance = 0;           // horizontal advance, pixels
};

// Rasterizes single glyphs of one Font (borrowed: it must outlive this object) into caller
// buffers. What a toolkit calls to fill its own atlas.
class GlyphRasterizer {
public:
    explicit GlyphRasterizer(Font& font);

    // The box a glyph will need (smallest integer box covering the outline at the subpixel
    // offset, plus kLcdPaddingPx on each side in LCD modes). Errors as Font::outline.
    Expected<GlyphBox> measure(GlyphId gid, const GlyphRenderOptions& options);
    // Renders into `target`, whose size must be at least the measured box (width × 3 bytes in LCD
    // modes); the glyph goes to its top-left corner, the rest of `target` is left untouched.
    Expected<GlyphBox> render(GlyphId gid, const GlyphRenderOptions& options,
                              const MaskView& target);

private:
    Font* font_;
    Rasterizer raster_;
    GlyphOutline outline_;   // reused
};

// A rendered glyph owned by a cache: its box and pixels (rows packed: stride = width, or
// 3·width in LCD modes).
struct CachedGlyph {
    GlyphBox box;
    ConstMaskView mask;
};

struct GlyphCacheStats {
    std::size_t hits = 0, misses = 0, evictions = 0;
    std::size_t bytes = 0, entries = 0;
};

// Glyph bitmaps keyed by (font id, size, variation coordinates, glyph id, subpixel bin, render
// mode), rendered once and blended many times. The subpixel x offset is quantized to
// kSubpixelBins bins. Memory is bounded by max_bytes (least recently used entries are evicted).
// A pointer from get() stays valid until the next get() or clear().
inline constexpr int kSubpixelBins = 4;
class GlyphCache {
public:
    explicit GlyphCache(std::size_t max_bytes = kDefaultGlyphCacheBytes);
    GlyphCache(GlyphCache&&) noexcept;
    GlyphCache& operator=(GlyphCache&&) noexcept;
    GlyphCache(const GlyphCache&) = delete;
    GlyphCache& operator=(const GlyphCache&) = delete;
    ~GlyphCache();

    // `font_id` distinguishes fonts (and variation instances) the caller renders with; the
    // subpixel_x of `options` is quantized to a bin before lookup and rendering.
    Expected<const CachedGlyph*> get(GlyphRasterizer& rasterizer, std::uint64_t font_id,
                                     GlyphId gid, const GlyphRenderOptions& options);
    void clear();
    GlyphCacheStats stats() const;
    std::size_t max_bytes() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// --- Whole-paragraph rendering --------------------------------------------------------------------
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

// --- Font inspection (`bezel info`) --------------------------------------------------------------
struct FontTable {
    std::string tag;             // four characters, e.g. "glyf", "CFF "
    std::uint32_t length = 0;    // bytes
};

struct NamedInstance {
    std::string name;                            // its subfamily name, e.g. "Bold"
    std::vector<VariationSetting> coordinates;   // one per axis, design units
};

// What a font file says about itself, for the CLI and tools that list fonts.
struct FontInfo {
    std::string file;
    int face_index = 0, face_count = 1;
    std::string family, style;          // as Font::family_name / style_name
    std::string postscript_name;        // name ID 6; "" when absent
    std::string version;                // name ID 5; "" when absent
    std::size_t glyph_count = 0;
    FontMetrics metrics;                // as Font::metrics (font units, y up)
    std::string outline_format;         // "TrueType" (glyf), "CFF", "CFF2", "bitmap" or "none"
    std::vector<VariationAxis> axes;
    std::vector<NamedInstance> instances;
    std::vector<FontTable> tables;      // the table directory, in its order
    // ISO 15924 tags of the scripts the cmap covers: all of a few representative letters of the
    // script (e.g. Arab: ا ب ع ي ه) map to glyphs.
    std::vector<std::string> scripts;
};

// Reads `file`'s face `face_index` (FreeType for names and metrics, HarfBuzz for the table
// directory and named instances). Errors as Font::open.
Expected<FontInfo> font_info(const std::string& file, int face_index = 0);

}  // namespace bezel
