// bezel/color_glyph.hpp — a font's colour glyphs, read through FreeType: COLR version 1 paint
// graphs and version 0 layers with their CPAL palettes (as bezel/paint.hpp's ColorGlyph, painted by
// bezel), and CBDT/CBLC and sbix bitmap strikes.
//
// COLR (versions 0 and 1) is read by bezel from the table's bytes, every offset bounds-checked:
// Debian 12's FreeType 2.12.1 is built with its COLRv1 functions (FT_Get_Color_Glyph_Paint,
// FT_Get_Paint, FT_Get_Colorline_Stops, FT_Get_Color_Glyph_ClipBox) compiled out — they return 0
// for every glyph — and its COLRv0 iterator stops silently at a bad index. CPAL palettes come from
// FreeType's FT_Palette_* (the palette type flags from the table: FreeType 2.12.1 reads them as
// 0), CBDT/CBLC and sbix images from FreeType's FT_LOAD_COLOR. Variable COLRv1 paints (the Var*
// formats, variable clip boxes and colour stops) are read at their default values: the variation
// deltas are not applied, so a variable colour font draws its default instance at every setting.
// SVG-in-OpenType glyphs are not drawn in colour: color_format() reports them as Svg, and they are
// drawn from their outline (or as .notdef) like any other glyph, with a warning from the callers.
//
// Threading: as Font (these calls load into the face).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "bezel/expected.hpp"
#include "bezel/font.hpp"
#include "bezel/paint.hpp"

#pragma GCC visibility push(default)  // the public API of libbezel.so (docs/architecture.md)
namespace bezel {

// How a glyph is coloured, the first of these the font has for it, in the order bezel prefers
// them: COLRv1, COLRv0, a bitmap (CBDT, sbix), SVG (not drawn), or none.
enum class ColorFormat : std::uint8_t { None, ColrV1, ColrV0, Bitmap, Svg };
const char* color_format_name(ColorFormat format);   // "none", "COLRv1", "COLRv0", "bitmap", "SVG"
// Whether bezel draws a glyph of this format in colour: COLRv1, COLRv0 and bitmaps (not SVG).
constexpr bool drawn_in_color(ColorFormat format) {
    return format == ColorFormat::ColrV1 || format == ColorFormat::ColrV0 ||
           format == ColorFormat::Bitmap;
}

// Which colour tables the face has (for `bezel info`).
struct ColorTables {
    bool colr_v0 = false, colr_v1 = false, cpal = false, cbdt = false, sbix = false, svg = false;
    bool any() const { return colr_v0 || colr_v1 || cbdt || sbix || svg; }
};
ColorTables color_tables(Font& font);

ColorFormat color_format(Font& font, GlyphId gid);

// A CPAL palette: its entries (straight sRGB) and the CPAL v1 flags.
struct Palette {
    std::vector<Rgba8> entries;
    bool for_light_background = false, for_dark_background = false;
};
// The font's palettes (empty without CPAL).
std::vector<Palette> palettes(Font& font);

// Which colours a colour glyph is built with.
struct ColorGlyphOptions {
    int palette = 0;   // index into palettes(); 0 is the default palette
    // Entries that replace the chosen palette's (hb-view's --custom-palette "index=colour"):
    // entry `index` becomes `color`. An index past the palette is an error.
    struct Entry {
        int index = 0;
        Rgba8 color;
    };
    std::vector<Entry> custom;
};

// The COLR paint graph of `gid` (version 1, or version 0's layers as PaintLayers of
// PaintGlyph(PaintSolid)), with palette colours resolved and every outline it clips to loaded in
// font units (y up), exactly as the font stores them (FT_LOAD_NO_SCALE; no rounding). Clip boxes
// are the ClipList's integers, in font units. Geometry is the table's fixed-point values converted
// exactly: F2Dot14 angles in units of 180°, counter-clockwise; each Translate, Scale, Rotate and
// Skew (with or without a centre c, as T(c)·M·T(−c)) becomes one PaintTransform; sweep angles are
// un-biased into degrees. A PaintColrGlyph of one glyph is built once and shared by every parent;
// one of a glyph without a paint graph paints nothing (the spec's rule). The graph is walked with
// kMaxPaintDepth and kMaxPaintNodes: a graph that loops or is deeper is an error naming the glyph
// ("f.ttf: glyph 12 (name): COLR paint graph nests deeper than 64", "… loops: PaintColrGlyph of
// glyph 12 (name) inside itself"), as are a palette or custom entry index out of range (naming the
// index and the count), a palette number out of range, a glyph without COLR data, and a damaged
// table (what and at which offset).
Expected<ColorGlyph> load_color_glyph(Font& font, GlyphId gid, const ColorGlyphOptions& options);

// A bitmap colour glyph from the strike nearest the size (the smallest strike at least as large,
// else the largest), as FreeType decodes it (FT_LOAD_COLOR: BGRA, premultiplied) converted to
// premultiplied RGBA, with its placement at the strike's size. sbix images are placed by their
// originOffsetX/Y (left = originOffsetX, top = originOffsetY + height); the advance is CBDT's
// strike metric, or for sbix hmtx's advance scaled to the strike exactly. A glyph the strike has no
// image for (a space) is an empty 0×0 bitmap with its advance. Loading leaves the face's size as
// the outline calls set it (the strike is selected on a size object of its own).
struct ColorBitmap {
    std::vector<std::uint8_t> rgba;   // premultiplied R, G, B, A; rows packed
    int width = 0, height = 0;
    double strike_px = 0;             // the strike's pixels per em
    int left = 0, top = 0;            // bitmap_left / bitmap_top at strike_px (top: rows above the baseline)
    double advance_px = 0;            // at strike_px
    ConstRgbaView view() const { return {rgba.data(), width, height, 4 * std::ptrdiff_t{width}}; }
};
// Errors name the glyph: size out of range, the font has no CBDT or sbix strikes, a damaged image,
// one that is not BGRA, or one larger than kMaxColorBitmapBytes (refused from the image's header,
// before FreeType decodes its pixels).
Expected<ColorBitmap> load_color_bitmap(Font& font, GlyphId gid, double size_px);

}  // namespace bezel
#pragma GCC visibility pop
