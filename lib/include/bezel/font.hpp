// bezel/font.hpp — fonts through FreeType: TrueType, CFF/OpenType, collections, variable fonts.
//
// Units: glyph outlines and glyph metrics are in PIXELS at the requested size, y DOWN, origin at
// the pen position on the baseline (so an ascender is at negative y). Face-wide metrics are in
// font units (`em_units`) as the font stores them, y UP (ascender > 0, descender < 0).
//
// Threading: a Font owns its own FreeType library instance. One Font must not be used from two
// threads at once (FreeType faces are not thread-safe); separate Font objects, even of the same
// file, may be used on separate threads freely.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bezel/expected.hpp"
#include "bezel/geometry.hpp"
#include "bezel/path.hpp"

namespace bezel {

using GlyphId = std::uint32_t;

// Face-wide metrics in font units, y up.
struct FontMetrics {
    int units_per_em = 0;
    double ascender = 0;   // typographic ascender (hhea, or OS/2 if hhea is empty), > 0
    double descender = 0;  // < 0
    double line_gap = 0;   // extra leading; line height = ascender − descender + line_gap
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

// Per-glyph metrics at a pixel size, y down, pen at the origin.
struct GlyphMetrics {
    double advance_px = 0;        // horizontal advance
    double left_bearing_px = 0;   // from the pen to the left edge of the outline's control box
    Rect bounds_px;               // control box of the outline (empty() for a blank glyph)
};

struct OutlineOptions {
    double size_px = 0;       // the em size in pixels (> 0 and ≤ kMaxFontSizePx)
    bool hinting = false;     // false: unhinted, exact scaling; true: FreeType's hinter (native
                              // TrueType bytecode or CFF hinter, auto-hinter otherwise)
};

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
};

// Largest em size accepted, in pixels: beyond it FreeType's 26.6 fixed point overflows.
inline constexpr double kMaxFontSizePx = 16384.0;

class Font {
public:
    // Opens a font file (TTF, OTF, TTC/OTC with `face_index`). The error names the file and
    // FreeType's reason.
    static Expected<Font> open(const std::string& file, int face_index = 0);

    Font(Font&&) noexcept;
    Font& operator=(Font&&) noexcept;
    Font(const Font&) = delete;
    Font& operator=(const Font&) = delete;
    ~Font();

    const std::string& file() const;
    std::string family_name() const;
    std::string style_name() const;
    int face_index() const;
    int face_count() const;      // faces in the file (collections have > 1)
    std::size_t glyph_count() const;
    bool is_scalable() const;
    bool has_cubic_outlines() const;  // CFF/CFF2 rather than TrueType glyf

    FontMetrics metrics() const;

    // Glyph for a Unicode code point; std::nullopt when the font maps it to nothing (.notdef).
    std::optional<GlyphId> glyph_for_char(char32_t code_point) const;
    // The glyph's PostScript name, or "gidN" when the font has none.
    std::string glyph_name(GlyphId gid) const;

    std::vector<VariationAxis> axes() const;   // empty for a non-variable font
    // Sets design coordinates; unnamed axes stay at their defaults. Errors name an unknown tag or
    // an out-of-range value.
    Status set_variations(const std::vector<VariationSetting>& settings);

    // Metrics of `gid` at a size; errors name the glyph id when it is out of range.
    Expected<GlyphMetrics> glyph_metrics(GlyphId gid, const OutlineOptions& options);

    // The outline of `gid` at a size, y down, pen at the origin. Handles TrueType runs of
    // off-curve points, contours with no on-curve point, single-point contours, CFF cubics,
    // composite glyphs and empty glyphs (an empty path). Not const: FreeType loads into the face.
    Expected<GlyphOutline> outline(GlyphId gid, const OutlineOptions& options);

private:
    struct Impl;
    explicit Font(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace bezel
