// bezel/glyph.hpp — single glyphs rasterized into caller buffers, and a bounded cache of them:
// what a toolkit calls to fill its own atlas.
//
// Units: pixels, y DOWN. A bitmap's `left`/`top` follow FreeType's bitmap_left / bitmap_top (top =
// rows ABOVE the baseline, so the bitmap's first row is at pen.y − top).
//
// Threading: a GlyphRasterizer or GlyphCache holds scratch memory (and the rasterizer shares a
// Font's FreeType face); one object must not be used from two threads at once. Steady state
// allocates nothing per glyph: cache hits reuse their buffers and the cache is bounded (a miss,
// like every prepare(), allocates the outline it loads).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "bezel/color_glyph.hpp"
#include "bezel/expected.hpp"
#include "bezel/flatten.hpp"
#include "bezel/font.hpp"
#include "bezel/geometry.hpp"
#include "bezel/image.hpp"
#include "bezel/limits.hpp"
#include "bezel/raster.hpp"

#pragma GCC visibility push(default)  // the public API of libbezel.so (docs/architecture.md)
namespace bezel {

// Where a glyph's bitmap box is put around its outline.
enum class GlyphBoxMode : std::uint8_t {
    // The smallest integer box covering the outline's curves at the pen offset (their tight
    // bounds): columns floor(x0 + dx) .. ceil(x1 + dx), rows likewise. The default.
    Tight,
    // FreeType's FT_Render_Glyph box (ft_glyphslot_preset_bitmap): the outline's CONTROL box in
    // 26.6 fixed point, shifted by the pen offset rounded to 26.6, floor/ceil to whole pixels.
    // It holds the Tight box (control points may lie outside the ink) up to FreeType's 1/64 px
    // rounding: an ink edge a hair past a pixel boundary can round inside the box, and that hair
    // of coverage is cut, as FreeType cuts it. What `bezel glyph`'s JSON contract promises.
    FreeType,
};

// How far the emboldened boundary (GlyphRenderOptions::bold) may lie from the exact dilated
// one, pixels: the flattening error a fill already has (kDefaultRasterTolerancePx), so the
// dilation adds no error of a larger order than the rasterizer's own.
inline constexpr double kSyntheticBoldTolerancePx = kDefaultRasterTolerancePx;

// Colour glyphs (bezel/color_glyph.hpp): which form of a glyph is drawn, with which colours.
struct GlyphColorOptions {
    // A glyph the font colours (COLRv1, COLRv0, a CBDT or sbix bitmap) is drawn in colour
    // (GlyphBox::color). False: every glyph is its outline's coverage mask, as before colour
    // (a COLR base glyph's own outline, often empty; a bitmap-only font's glyphs are errors).
    bool enabled = true;
    ColorGlyphOptions palette;            // palette index and custom entries
    Rgba8 foreground{0, 0, 0, 255};       // COLR palette index 0xFFFF, and draw_rgba's ink
    BitmapFilter bitmap_filter = BitmapFilter::Box;   // how a bitmap strike is scaled to size
};

struct GlyphRenderOptions {
    double size_px = 16;   // the em size in pixels, (0, kMaxFontSizePx]
    // Fitting the outline to the pixel grid (font.hpp's Hinting, FreeType's hinters): None, Light
    // (vertical only: what 12-16 px UI text usually wants), Full (the font's instructions), Auto
    // (FreeType's auto-hinter). Honoured by prepare() and part of GlyphCache's key. A glyph hinted
    // horizontally (Full, Auto) was fitted at a whole-pixel origin: draw it at a whole-pixel pen
    // (offset_px.x = 0), as TextRenderer does. Ignored by colour glyphs and bitmap strikes.
    Hinting hinting = Hinting::None;
    // Embedded bitmap strikes (font.hpp's StrikeBitmap): when true and the font has a monochrome
    // or gray strike of exactly size_px pixels per em holding the glyph, the glyph is that
    // strike's pixels as coverage (a 1-bit strike 0 or 255), not its outline: box.bitmap_strike
    // says so. The bitmap is placed at the whole pixel nearest the pen (offset_px rounded, as a
    // strike cannot move by a fraction of a pixel); hinting, slant, bold, box mode and the fill's
    // rule and flattening do not apply; in LCD modes each coverage byte is written to all three
    // subpixels (no colour fringes: the strike was designed for whole pixels). box.advance_px is
    // the strike's own advance. A colour glyph stays colour. Off by default: toolkits draw
    // anti-aliased outlines at subpixel pens by default (Dear ImGui's FreeType builder loads
    // without bitmaps unless ImGuiFreeTypeBuilderFlags_Bitmap asks), and strikes, designed for
    // aliased display, look out of place beside them; a toolkit that wants a font's hand-tuned
    // small sizes turns it on.
    bool embedded_bitmaps = false;
    // Synthetic slant (hb-view's --font-slant): each point moves right by `slant` times its
    // height above the baseline (0.2 leans about 11°; negative leans left), after hinting.
    // |slant| ≤ kMaxSyntheticSlant. The box and the FreeType box are those of the slanted outline.
    double slant = 0;
    // Synthetic bold (hb-view's --font-bold; HarfBuzz's hb_font_set_synthetic_bold with equal x
    // and y strengths, not in place), a fraction of the em, 0 ≤ bold ≤ kMaxSyntheticBold.
    // With d = bold · size_px / 2 (pixels):
    //   ink      every point within d of the glyph's filled outline becomes ink: the ink dilated
    //            by a disk of radius d, so stems widen by 2d = bold · size_px, outer corners
    //            round with radius d and holes (counters) shrink by d on every side;
    //   place    the dilated ink moves right by d and up by d, so its left edge and its bottom
    //            stay where the plain glyph's were and it grows to the right and upwards, as
    //            FreeType's FT_GlyphSlot_Embolden and HarfBuzz place an emboldened glyph;
    //   advance  box.advance_px grows by bold · size_px (a glyph with no advance, a mark,
    //            keeps 0), as FT_GlyphSlot_Embolden widens the advance; ShapeOptions::bold
    //            widens the shaped advances by the same amount.
    // Order: after hinting (the font's hints fit its own outline to the grid; the dilation then
    // moves every hinted edge outward by the same d), before the slant (so a stem's horizontal
    // width grows by exactly bold · size_px whatever the slant, matching the advance: a shear
    // keeps horizontal distances, while dilating a slanted stem would widen it by 2d/cos θ).
    // The dilated boundary is within kSyntheticBoldTolerancePx of the exact one (construction
    // at lib/src/text/synthetic_bold.cpp). Needs FillRule::NonZero; the glyph is then filled
    // with OverlapMode::Accurate. The box and the FreeType box are those of the dilated outline.
    double bold = 0;
    // The pen position relative to the glyph's whole-pixel origin, pixels, x right, y DOWN. A
    // toolkit passes the fractional part of its pen position, in [0, 1), and adds the whole part
    // to the box's left / −top itself (GlyphCache quantizes it to kSubpixelBins bins); any finite
    // offset with |x|, |y| ≤ kMaxGlyphOffsetPx is accepted and moves the box with the ink.
    Vec2 offset_px;
    GlyphBoxMode box = GlyphBoxMode::Tight;
    // Colour glyphs. A glyph drawn in colour ignores `hinting`, `bold`, `box` (its box is the
    // tight box of what its paint can ink: paint_bounds, or the scaled bitmap) and the coverage
    // format (colour is gray anti-aliased); `slant` shears a COLR glyph's paint (a bitmap is not
    // sheared), and `fill.flatten` flattens the outlines it clips to.
    GlyphColorOptions color;
    // How the outline is filled: fill rule, overlap mode, flattening, gray or LCD coverage and
    // the LCD order and filter, as for any Rasterizer fill. Accurate overlap is chosen
    // automatically for glyphs that mark overlapping contours (Accumulate here never forces plain
    // accumulation on them). `fill.origin` must be zero: `offset_px` places the pen; and
    // `fill.combine` Replace: a glyph bitmap is the glyph's own coverage.
    FillOptions fill;
};

// Where a glyph bitmap sits relative to the pen, and its size. For LCD coverage `width` counts
// DISPLAY pixels and the bitmap has 3 bytes per pixel, its subpixels left to right (the panel's
// order: raster.hpp's CoverageFormat::Lcd).
struct GlyphBox {
    int left = 0, top = 0;        // bitmap_left / bitmap_top, as FreeType
    int width = 0, height = 0;
    double advance_px = 0;        // horizontal advance
    // The overlap mode the glyph is filled with: Accurate when the font marks its contours as
    // overlapping or the options ask for it.
    OverlapMode overlap = OverlapMode::Accumulate;
    // Drawn in colour (a COLR paint or a bitmap): draw_rgba() gives its pixels, width × height
    // premultiplied RGBA with no LCD padding; draw() gives its alpha as coverage.
    bool color = false;
    // Drawn from an embedded monochrome or gray bitmap strike (GlyphRenderOptions::
    // embedded_bitmaps), not from the outline. In LCD modes its box has no LCD padding.
    bool bitmap_strike = false;
};

// A glyph loaded and measured for one set of options: prepare() reads the outline from the Font
// once, draw() fills it (as often as wanted, into any target) without touching the Font.
struct PreparedGlyph {
    GlyphId gid = 0;
    GlyphRenderOptions options;
    GlyphBox box;
    Path path;   // the outline, pixels, y down, pen at the origin (before the offset)
    // A colour glyph (box.color): its paint graph, mapped into the box by `paint_transform`, or
    // its bitmap strike, scaled onto the whole box (the strike's box scaled to size_px, its edges
    // rounded to whole pixels). Shared, immutable.
    std::shared_ptr<const ColorGlyph> paint;
    Affine paint_transform;
    std::shared_ptr<const ColorBitmap> bitmap;
    // A glyph drawn from a bitmap strike (box.bitmap_strike): its pixels, copied into the box.
    std::shared_ptr<const StrikeBitmap> strike;
};

// One glyph of a set (GlyphRasterizer::draw_set): `*glyph` drawn into the top-left
// box.width × box.height corner of `target` (× 3 bytes in LCD modes), as draw() would. For an
// atlas, `target` is the glyph's rectangle of it (MaskView::sub).
struct GlyphDrawJob {
    const PreparedGlyph* glyph = nullptr;   // borrowed for the call; must not be null
    MaskView target;
};

// Rasterizes single glyphs of one Font into caller buffers with a stride. What a toolkit calls
// to fill its own atlas; the one glyph path of bezel (GlyphCache, TextRenderer and the bezel CLI
// render glyphs through it).
class GlyphRasterizer {
public:
    // Shares `font`'s FreeType face (shared ownership, not a borrow): the Font may be moved or
    // destroyed afterwards and the rasterizer keeps drawing its glyphs. Sharing means: variations
    // set on the Font (or on whatever Font it was moved into) are the rasterizer's too, and the
    // Font and its rasterizers are one object for threading (one thread at a time). A thread
    // of its own takes its own Font::open(face) and a rasterizer of that. `font` must not be a
    // moved-from Font.
    explicit GlyphRasterizer(Font& font);
    // The Font's instance_id() (font.hpp): its face and current variation coordinates, what
    // GlyphCache keys this rasterizer's glyphs on.
    std::uint64_t instance_id() const { return font_.instance_id(); }

    // Loads the outline of `gid` (one Font::outline call) and computes its box by
    // `options.box`, plus kLcdPaddingPx display pixels on each side in LCD modes. Errors name the
    // glyph: an offset that is not finite or beyond kMaxGlyphOffsetPx, a nonzero fill.origin, a
    // box larger than kMaxBitmapDim, and Font::outline's (size out of range, gid ≥ glyph_count(), …).
    Expected<PreparedGlyph> prepare(GlyphId gid, const GlyphRenderOptions& options);
    // Fills `glyph` into the top-left box.width × box.height corner of `target` (width × 3 bytes
    // in LCD modes), writing every byte of that corner and nothing else. A glyph with an empty
    // box writes nothing and needs no target. A colour glyph writes its alpha (each of the three
    // bytes alike in LCD modes): a toolkit with only a coverage atlas still gets its silhouette.
    // Errors: a target smaller than the box (or without memory), the Rasterizer's or the
    // Painter's, each naming the glyph.
    Status draw(const PreparedGlyph& glyph, const MaskView& target);
    // Draws `glyph` into the top-left box.width × box.height corner of a premultiplied RGBA
    // target (paint.hpp's RgbaView: bytes R, G, B, A, stride in bytes), writing every pixel of
    // that corner: a colour glyph in its colours, any other glyph as its gray coverage times
    // options.color.foreground. Errors as draw(); an LCD glyph that is not colour is one (three
    // coverages do not fit one alpha).
    Status draw_rgba(const PreparedGlyph& glyph, const RgbaView& target);
    // Whether `gid` would be drawn in colour with `options` (GlyphBox::color), without loading it.
    bool is_color(GlyphId gid, const GlyphColorOptions& options);
    // The font's colour form of `gid` (color_glyph.hpp), ColorFormat::None at the cost of one flag
    // test for a font without colour tables. Svg: bezel draws the glyph from its outline.
    ColorFormat color_format(GlyphId gid);

    // A set of glyphs, what a toolkit filling an atlas calls: prepare_set() loads them all
    // (their boxes tell the toolkit where each goes), draw_set() draws them all in one
    // Rasterizer::fill_paths call (one per run of outline glyphs with the same fill options;
    // colour and bitmap-strike glyphs are drawn as draw() draws them, in order).
    //
    // prepare_set: out[k] = prepare(gids[k], options) for k < count (`out` resized to count).
    // The first error stops it, naming the set index and the glyph; `out` then holds the
    // glyphs before it.
    Status prepare_set(const GlyphId* gids, std::size_t count, const GlyphRenderOptions& options,
                       std::vector<PreparedGlyph>& out);
    // draw_set: each job's bytes are exactly those of draw(*job.glyph, job.target) (tested);
    // jobs whose targets overlap are drawn in order. Errors name the set index and the glyph:
    // a null glyph or a target smaller than the box (draw()'s), found for every job before any
    // target is written; then the Rasterizer's (fill_paths') and the Painter's, found when the
    // job is reached, the jobs before it drawn (a glyph from prepare() has finite points within
    // the limits, so the Rasterizer has nothing to refuse in it).
    // Allocates nothing for outline glyphs once its scratch has grown to the largest set.
    Status draw_set(const GlyphDrawJob* jobs, std::size_t count);
    Status draw_set(const std::vector<GlyphDrawJob>& jobs) {
        return draw_set(jobs.data(), jobs.size());
    }

    // prepare()'s box alone.
    Expected<GlyphBox> measure(GlyphId gid, const GlyphRenderOptions& options);
    // prepare() then draw(): one outline load. Errors as the two.
    Expected<GlyphBox> render(GlyphId gid, const GlyphRenderOptions& options,
                              const MaskView& target);

private:
    Expected<PreparedGlyph> prepare_color(GlyphId gid, ColorFormat format,
                                          const GlyphRenderOptions& options);
    Expected<PreparedGlyph> prepare_strike(GlyphId gid, StrikeBitmap strike,
                                           const GlyphRenderOptions& options);
    Status draw_color_alpha(const PreparedGlyph& glyph, const MaskView& target);
    Status draw_strike(const PreparedGlyph& glyph, const MaskView& target);
    Font font_;   // shares the Impl of the Font it was made from
    Rasterizer raster_;
    std::unique_ptr<Painter> painter_;            // made on the first colour glyph
    std::vector<std::uint8_t> rgba_scratch_;      // draw() of a colour glyph
    ColorTables tables_;                          // the font's, read once
    std::vector<FillJob> set_jobs_;               // draw_set's run of outline glyphs
    std::vector<std::size_t> set_index_;          // and each one's index in the set
};

// A rendered glyph owned by a cache: its box and pixels (rows packed: stride = width, or
// 3·width in LCD modes). A colour glyph (box.color) has its premultiplied RGBA in `rgba` (stride
// 4·width) and an empty `mask`.
struct CachedGlyph {
    GlyphBox box;
    ConstMaskView mask;
    ConstRgbaView rgba;
};

struct GlyphCacheStats {
    std::size_t hits = 0, misses = 0, evictions = 0;
    std::size_t bytes = 0, entries = 0;
};

// Subpixel pen positions the cache renders per axis: a pen offset v in [0, 1) falls in bin
// b = floor(v · kSubpixelBins) and is drawn at b / kSubpixelBins (so at most 1/4 px early). A
// toolkit that rounds its pen to the nearest quarter first (as TextRenderer does) has an exact
// bin and a placement error of at most 1/8 px.
inline constexpr int kSubpixelBins = 4;

// Glyph bitmaps, rendered once and blended many times, keyed by what the pixels depend on:
//   the face the rasterizer really draws: its Font's instance_id() (font.hpp), which names the
//     face and its variation coordinates, so two rasterizers of different fonts or of different
//     instances of one variable font never share an entry, and a rasterizer whose Font changes
//     its variations finds its glyphs of the new instance (and, when it returns to one of the
//     last few, those of the old);
//   the glyph id and the pen's subpixel bin on each axis (kSubpixelBins);
//   every option that changes the pixels: size, hinting, embedded bitmaps, slant, bold, box
//     mode, every FillOptions field but the origin, the colour options (enabled, palette, custom
//     entries, bitmap filter; the foreground only for a colour glyph whose paint uses it, so
//     text colours share mask glyphs).
// Memory is bounded by max_bytes (least recently used entries are evicted), except while a
// batch pins the glyphs it returned (begin_batch).
//
// Handle lifetime: a CachedGlyph* from get() and the pixels it points to stay valid until that
// entry is evicted or the cache is cleared or destroyed. Only a get() that misses evicts,
// and it evicts the least recently used entries first (never the entry it returns). A glyph
// larger than max_bytes on its own is rendered but not kept: outside a batch it is valid until
// the next get(). Inside a batch (begin_batch .. end_batch) NOTHING the batch returned is
// evicted or overwritten: a frame looks up all its glyphs, then blits them all.
class GlyphCache {
public:
    explicit GlyphCache(std::size_t max_bytes = kDefaultGlyphCacheBytes);
    GlyphCache(GlyphCache&&) noexcept;
    GlyphCache& operator=(GlyphCache&&) noexcept;
    GlyphCache(const GlyphCache&) = delete;
    GlyphCache& operator=(const GlyphCache&) = delete;
    ~GlyphCache();

    // The glyph `gid` of `rasterizer`'s font drawn with `options`. Each component of
    // `options.offset_px` must be in [0, 1) (the fractional part of the pen; the caller adds the
    // whole part to the box): it is quantized to its bin (kSubpixelBins) before lookup and
    // rendering. An offset outside [0, 1), or not a number, is an Error naming the glyph and the
    // value (GlyphRasterizer accepts any offset; the cache's bins cover only a pixel). A miss loads
    // the outline once. A warm hit allocates nothing. Errors as GlyphRasterizer::prepare and draw.
    Expected<const CachedGlyph*> get(GlyphRasterizer& rasterizer, GlyphId gid,
                                     const GlyphRenderOptions& options);

    // A frame's batch: from begin_batch() to end_batch() every glyph get() returns is pinned, so
    // all of them stay valid together until end_batch() (see "Handle lifetime" above). Pinned
    // entries are never evicted; when they alone fill max_bytes the cache grows past it for the
    // batch (a frame's glyphs must all exist at once) and the next miss after end_batch() evicts
    // it back under the bound. Batches do not nest: begin_batch() inside a batch is an Error.
    // clear() ends a batch.
    Status begin_batch();
    void end_batch();
    bool in_batch() const;

    void clear();
    GlyphCacheStats stats() const;
    std::size_t max_bytes() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace bezel
#pragma GCC visibility pop
