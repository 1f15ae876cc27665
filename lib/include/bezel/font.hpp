// bezel/font.hpp — fonts through FreeType: TrueType, CFF/OpenType, collections, variable fonts.
//
// Units: glyph outlines and glyph metrics are in PIXELS at the requested size, y DOWN, origin at
// the pen position on the baseline (so an ascender is at negative y). Face-wide metrics are in
// font units (`em_units`) as the font stores them, y UP (ascender > 0, descender < 0).
//
// Threading: a Font owns its own FreeType library instance and face. One Font must not be used
// from two threads at once (FreeType faces are not thread-safe); separate Font objects, even of
// the same file or FontFace, may be used on separate threads freely. The cheap way to give each
// thread its own: one FontFace (bezel/font_face.hpp, the bytes read once), Font::open(face) per
// thread.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bezel/expected.hpp"
#include "bezel/font_face.hpp"
#include "bezel/geometry.hpp"
#include "bezel/limits.hpp"
#include "bezel/path.hpp"

#pragma GCC visibility push(default)  // the public API of libbezel.so (docs/architecture.md)
namespace bezel {

using GlyphId = std::uint32_t;

namespace font_detail {
struct Access;
}  // namespace font_detail
class GlyphRasterizer;

// Face-wide metrics in FONT UNITS (units_per_em to the em), y UP, as the font stores them.
// Font::metrics_px gives them in pixels at a size.
struct FontMetrics {
    int units_per_em = 0;
    double ascender = 0;   // typographic ascender (hhea, or OS/2 if hhea is empty), > 0
    double descender = 0;  // < 0
    double line_gap = 0;   // extra leading; line height = ascender − descender + line_gap
};

// Face-wide metrics in PIXELS at a size, as DISTANCES from the baseline (no sign convention to
// get wrong): in bezel's y-down pixels the ascender line is at y = −ascent_px and the descender
// line at y = +descent_px. Unhinted: FontMetrics scaled by size_px / units_per_em.
struct FontMetricsPx {
    double size_px = 0;
    double ascent_px = 0;       // above the baseline (FontMetrics::ascender scaled), > 0 for a usual font
    double descent_px = 0;      // below the baseline (−FontMetrics::descender scaled), > 0 for a usual font
    double line_gap_px = 0;     // extra leading between lines
    double line_height_px = 0;  // baseline to baseline: ascent_px + descent_px + line_gap_px
};

// One variation axis of a variable font. Values in the axis's user units (e.g. wght 100..900).
struct VariationAxis {
    std::string tag;   // four characters, e.g. "wght"
    std::string name;  // from the name table, or the tag when it has none
    double min_value = 0, default_value = 0, max_value = 0;
};

struct VariationSetting {
    std::string tag;
    double value = 0;
};

// Where a font comes from: a file, a face of it (collections), and the design coordinates it is
// used at (empty: the font's defaults). What a font list (bezel/font_collection.hpp) holds and
// what a system font lookup (fontconfig) returns.
struct FontSource {
    std::string file;   // for a font from memory (FontCollection::add(FontFace)), the face's name
    int face_index = 0;
    std::vector<VariationSetting> variations;
};

// Per-glyph metrics at a pixel size, y down, pen at the origin.
struct GlyphMetrics {
    double advance_px = 0;        // horizontal advance
    double left_bearing_px = 0;   // from the pen to the left edge of the outline's control box
    Rect bounds_px;               // control box of the outline (empty() for a blank glyph)
};

// Which of FreeType's hinters fits an outline to the pixel grid.
enum class Hinting : std::uint8_t {
    None,    // unhinted: the design scaled exactly
    Light,   // FreeType's light hinting (FT_LOAD_TARGET_LIGHT): vertical snapping only, so shapes
             // and horizontal spacing keep the design's; FreeType picks the font's native light
             // hinter (CFF, TrueType in subpixel mode) or its auto-hinter
    Full,    // FreeType's default hinting (FT_LOAD_TARGET_NORMAL): the font's own instructions
             // (TrueType bytecode, CFF hints), the auto-hinter for fonts without them
    Auto,    // FreeType's auto-hinter for every font (FT_LOAD_FORCE_AUTOHINT)
};

// "none", "light", "full", "auto".
const char* hinting_name(Hinting hinting);
// Whether the mode fits stems to the grid horizontally too (Full, Auto): such a glyph is drawn at
// a whole-pixel pen, since its fitting assumed a whole-pixel origin.
constexpr bool hints_horizontally(Hinting hinting) {
    return hinting == Hinting::Full || hinting == Hinting::Auto;
}

struct OutlineOptions {
    // The em size in pixels, (0, kMaxFontSizePx]. 16 by default, as GlyphRenderOptions and
    // ShapeOptions: one default text size for every options struct, so that default-made options
    // of a glyph's outline, its bitmap and its shaping describe the same glyph.
    double size_px = 16;
    Hinting hinting = Hinting::None;
};
// Unhinted: FreeType loads the outline in font units (FT_LOAD_NO_SCALE) and bezel scales it by
// size_px / units_per_em in double, with no rounding to FreeType's 1/64 px grid. The font units
// are FreeType's: glyf points are integers, shifted so that the hmtx left side bearing holds;
// composite transforms and variation deltas are applied by FreeType and rounded to units.
// Hinted (any other mode): FreeType scales and hints at size_px rounded to 1/64 px (TrueType
// fonts that ask for integer ppem get it), and the result, in 26.6 pixels, is converted exactly.

// How a point of the font's own outline data sits on the curve.
enum class PointKind : std::uint8_t {
    OnCurve,    // an end point of segments
    OffConic,   // a TrueType quadratic control point (runs of two imply an on-curve midpoint)
    OffCubic,   // a CFF cubic control point (always in pairs)
};

struct OutlinePoint {
    Point pos;         // pixels, y down
    PointKind kind = PointKind::OnCurve;
};

// A glyph's outline at a size: the Path plus the font's raw points, for inspection.
struct GlyphOutline {
    GlyphId gid = 0;
    Path path;                               // closed contours, pixels, y down
    std::vector<OutlinePoint> points;        // the font's points after scaling, in font order
    std::vector<std::size_t> contour_ends;   // index in `points` of each contour's last point
    GlyphMetrics metrics;
    // The font marks the contours as overlapping (glyf OVERLAP_SIMPLE / OVERLAP_COMPOUND).
    // Signed-area accumulation rasterizers add the partial coverage of anti-aliased edges that
    // overlap, which overestimates it there; FreeType renders such glyphs supersampled.
    bool overlapping_contours = false;
};

class Font {
public:
    // Opens a font file (TTF, OTF, TTC/OTC with `face_index`). The error names the file and
    // the problem: no such file, a directory, face index out of range (0..face count − 1), or
    // FreeType's reason ("FreeType error 0x02 (unknown file format)"). FreeType reads tables
    // lazily, so a damaged file may open and fail later, per glyph, with an error from outline().
    // Built on FontFace::open(file, face_index) then open(face), with its messages.
    static Expected<Font> open(const std::string& file, int face_index = 0);
    // A new instance of a face read once (bezel/font_face.hpp): its own FreeType library and
    // face over the face's shared bytes (no copy, no second read), at the font's default
    // variation coordinates. What each thread of a program calls for its own Font of one face.
    // Errors name the face (FreeType cannot start, or fails on bytes it accepted before).
    static Expected<Font> open(const FontFace& face);

    // A moved-from Font may only be destroyed or assigned to. A GlyphRasterizer made from a Font
    // shares its face (glyph.hpp), so moving or destroying the Font leaves the rasterizer valid.
    Font(Font&&) noexcept;
    Font& operator=(Font&&) noexcept;
    Font(const Font&) = delete;
    Font& operator=(const Font&) = delete;
    ~Font();

    // The file the font was read from, or a memory font's FontMemoryOptions::name: what every
    // message about the font starts with.
    const std::string& file() const;
    // The shared face this Font is an instance of (a copy of the FontFace it was opened from).
    const FontFace& face() const;
    // Identifies the glyphs this Font draws: its face and its current variation coordinates.
    // It changes with set_variations (and returns to an earlier value when the coordinates
    // return to one of the last few set), is never given to another Font, and is what
    // GlyphCache keys glyphs on (glyph.hpp). Two Fonts of one face at equal coordinates have
    // different ids (their glyphs are equal, but the cache does not rely on it).
    std::uint64_t instance_id() const;
    std::string family_name() const;
    std::string style_name() const;
    int face_index() const;
    int face_count() const;      // faces in the file (collections have > 1)
    std::size_t glyph_count() const;
    bool is_scalable() const;
    bool has_cubic_outlines() const;  // CFF/CFF2 rather than TrueType glyf
    // The face has colour glyphs of any kind (FreeType's FT_HAS_COLOR: COLR with CPAL, CBDT,
    // sbix); bezel/color_glyph.hpp's color_tables() says which, and draws them.
    bool has_color_bitmaps() const;
    // ok when the face has outlines; for a bitmap-only face (colour emoji, EBDT, BDF) an Error
    // naming the file: "NotoColorEmoji.ttf: a bitmap-only font (no outlines): its glyphs are
    // colour bitmaps, drawn only as colour glyphs", or for a monochrome bitmap font "...;
    // monochrome bitmap fonts are not supported". Every outline call fails with it; the colour
    // glyphs of such a font are read with load_color_bitmap (bezel/color_glyph.hpp).
    Status require_outlines() const;

    // For a bitmap-only sfnt, units per em, ascender, descender and line gap come from its head
    // and hhea tables (FreeType reports them as 0 for faces without outlines).
    FontMetrics metrics() const;
    // metrics() in pixels at `size_px` (FontMetricsPx: distances from the baseline). Errors name
    // the font: a size outside (0, kMaxFontSizePx], a face without units per em.
    Expected<FontMetricsPx> metrics_px(double size_px) const;

    // Glyph for a Unicode code point; std::nullopt when the font maps it to nothing (.notdef).
    std::optional<GlyphId> glyph_for_char(char32_t code_point) const;
    // The glyph's PostScript name, or "gidN" when the font has none.
    std::string glyph_name(GlyphId gid) const;

    std::vector<VariationAxis> axes() const;   // empty for a non-variable font
    // Sets design coordinates; unnamed axes stay at their defaults. Errors name an unknown tag or
    // an out-of-range value. Changes instance_id() when the coordinates change.
    Status set_variations(const std::vector<VariationSetting>& settings);

    // Metrics of `gid` at a size; errors name the glyph id when it is out of range.
    Expected<GlyphMetrics> glyph_metrics(GlyphId gid, const OutlineOptions& options);

    // The outline of `gid` at a size, y down, pen at the origin. Handles TrueType runs of
    // off-curve points, contours with no on-curve point, single-point contours, CFF cubics,
    // composite glyphs and empty glyphs (an empty path). Not const: FreeType loads into the face.
    // The Path has the segments FreeType's FT_Outline_Decompose produces, in its order:
    //   - every contour is closed; the line back to the start is the Close (not a Line) when the
    //     contour ends on-curve, an explicit Quad/Cubic to the start when it ends off-curve;
    //   - two consecutive conic points imply an on-curve point at their exact midpoint;
    //   - a contour whose first point is off-curve starts at its last point if that is on-curve,
    //     else at the midpoint of its last and first points (a contour with no on-curve point);
    //   - a single on-curve point is a degenerate contour Move + Close (no segment), kept so that
    //     the Path and `points` agree; a single off-curve point is Move p, Quad(p, p), Close.
    // Errors name the file and the glyph id: size out of range, gid ≥ glyph_count(), a glyph
    // FreeType cannot load (its reason), a bitmap-only font.
    Expected<GlyphOutline> outline(GlyphId gid, const OutlineOptions& options);

private:
    struct Impl;
    // The font module's other files (render_with_freetype in bezel/freetype_reference.hpp) reach Impl
    // through font_detail::Access.
    friend struct font_detail::Access;
    // A GlyphRasterizer keeps a share of the Impl (so it cannot dangle when the Font moves).
    friend class GlyphRasterizer;
    explicit Font(std::shared_ptr<Impl> impl);
    // outline() and glyph_metrics() share it; `want_path` false skips building the Path.
    Expected<GlyphOutline> load_glyph(GlyphId gid, const OutlineOptions& options, bool want_path);
    // Shared only with the GlyphRasterizers made from this Font (one face, one thread at a time).
    std::shared_ptr<Impl> impl_;
};

}  // namespace bezel
#pragma GCC visibility pop
