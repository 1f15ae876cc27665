// bezel/shape.hpp — HarfBuzz shaping of one run of text in one font, and the UTF-8 it reads.
//
// Units: pixels at ShapeOptions::size_px, y DOWN (HarfBuzz's y-up offsets negated). Clusters are
// byte offsets into the UTF-8 input.
//
// Threading: a Shaper holds a HarfBuzz font and a reused buffer; one Shaper must not be used from
// two threads at once. Separate Shapers, even of the same file or FontFace, may run on separate
// threads (Shapers of one FontFace share its immutable HarfBuzz face).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "bezel/expected.hpp"
#include "bezel/font.hpp"
#include "bezel/font_face.hpp"
#include "bezel/limits.hpp"

#pragma GCC visibility push(default)  // the public API of libbezel.so (docs/architecture.md)
namespace bezel {

// Decodes UTF-8 strictly (no overlong forms, no surrogates, nothing above U+10FFFF). The error
// names the byte offset of the first bad sequence: "text byte 7: invalid UTF-8".
Expected<std::u32string> decode_utf8(std::string_view text);
void append_utf8(std::string& out, char32_t code_point);

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

// ShapeOptions::script and ::language checked as Shaper::shape reads them, so that a front end
// can refuse a bad value before any work. A script is an ISO 15924 tag of a script HarfBuzz
// knows ("Arab", "latn"; "Ar" is malformed, "Xyzw" unknown); a language is a BCP 47 tag, loosely
// (subtags of 1-8 letters or digits joined by '-': "ar", "sr-Latn"). Errors name the tag.
Status check_script_tag(const std::string& tag);
Status check_language_tag(const std::string& tag);

struct ShapeOptions {
    double size_px = 16;                       // em size, (0, kMaxFontSizePx]
    std::vector<FeatureSetting> features;
    std::vector<VariationSetting> variations;  // design coordinates, as Font::set_variations
    Direction direction = Direction::Auto;     // Auto: from the text (first strong character)
    std::string script;                        // ISO 15924 ("Arab", "Deva"); "" = from the text
    std::string language;                      // BCP 47 ("ar", "hi"); "" = HarfBuzz's default
    // Synthetic bold, a fraction of the em, 0 ≤ bold ≤ kMaxSyntheticBold (HarfBuzz's
    // hb_font_set_synthetic_bold, not in place): every glyph with a nonzero advance has it
    // widened by bold · size_px along the direction (x for horizontal text, y for vertical), as
    // FreeType's FT_GlyphSlot_Embolden does; glyphs with no advance (marks) keep 0. Offsets are
    // HarfBuzz's. The glyphs themselves are emboldened by GlyphRenderOptions::bold (glyph.hpp),
    // which TextRenderer sets from this field, so a page's advances and ink always agree.
    double bold = 0;
};

// One shaped glyph. Advances and offsets in pixels, y DOWN (HarfBuzz's y-up offsets negated).
struct ShapedGlyph {
    GlyphId gid = 0;
    std::uint32_t cluster = 0;   // byte offset in the UTF-8 input of the cluster's first character
    double x_advance_px = 0, y_advance_px = 0;
    double x_offset_px = 0, y_offset_px = 0;
};

// A shaped run, glyphs in VISUAL order (left to right for horizontal text, as HarfBuzz returns
// them for RTL too).
struct ShapedRun {
    std::vector<ShapedGlyph> glyphs;
    Direction direction = Direction::LeftToRight;  // resolved
    std::string script;                            // resolved ISO 15924 tag
    double advance_px = 0;                            // sum of advances along the direction
};

// A font's line metrics in pixels (Shaper::extents says which side is which).
struct FontExtents {
    double ascender_px = 0, descender_px = 0, line_gap_px = 0;
};

// HarfBuzz shaping of one face (glyph ids are the same as Font's for the same face).
class Shaper {
public:
    // Built on FontFace::open(file, face_index) then open(face). Errors name the file: missing,
    // not a font, face index out of range.
    static Expected<Shaper> open(const std::string& file, int face_index = 0);
    // A Shaper of a face read once (bezel/font_face.hpp): the HarfBuzz face is parsed once per
    // FontFace and shared, read-only, by every Shaper of it on any thread; each Shaper has its
    // own HarfBuzz font (size, variations) and buffer. Errors name the face: bytes HarfBuzz does
    // not read as OpenType ("not an OpenType or TrueType font"), a face with no glyphs.
    static Expected<Shaper> open(const FontFace& face);
    Shaper(Shaper&&) noexcept;
    Shaper& operator=(Shaper&&) noexcept;
    Shaper(const Shaper&) = delete;
    Shaper& operator=(const Shaper&) = delete;
    ~Shaper();

    // Shapes `utf8` as one run (no line breaking, no bidi reordering across runs). Errors:
    // invalid UTF-8 (offset named), text longer than kMaxTextBytes, size out of range, an
    // unknown variation axis, a script or language tag that does not parse, a bold out of range.
    Expected<ShapedRun> shape(std::string_view utf8, const ShapeOptions& options);

    // The font's extents for options.direction at options.size_px and options.variations, as
    // hb_font_get_extents_for_direction gives them (hb-view's line spacing). Horizontal (and
    // Auto): hhea/OS/2 ascender above the baseline, descender below it (< 0), line gap. Vertical
    // (TopToBottom, BottomToTop): vhea's, measured across the column from its centre line,
    // ascender to the right (> 0) and descender to the left (< 0); a font without vhea gets
    // HarfBuzz's fallback of half an em each side and no gap. Errors as shape() for the size and
    // the variations.
    Expected<FontExtents> extents(const ShapeOptions& options);

private:
    struct Impl;
    explicit Shaper(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace bezel
#pragma GCC visibility pop
