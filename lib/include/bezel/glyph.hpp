// bezel/glyph.hpp — single glyphs rasterized into caller buffers, and a bounded cache of them:
// what a toolkit calls to fill its own atlas.
//
// Units: pixels, y DOWN. A bitmap's `left`/`top` follow FreeType's bitmap_left / bitmap_top (top =
// rows ABOVE the baseline, so the bitmap's first row is at pen.y − top).
//
// Threading: a GlyphRasterizer or GlyphCache holds scratch memory (and the rasterizer borrows a
// Font); one object must not be used from two threads at once. Steady state allocates nothing per
// glyph: buffers are reused and the cache is bounded.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>

#include "bezel/expected.hpp"
#include "bezel/font.hpp"
#include "bezel/image.hpp"
#include "bezel/limits.hpp"
#include "bezel/raster.hpp"

namespace bezel {

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
    double advance_px = 0;           // horizontal advance
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

}  // namespace bezel
