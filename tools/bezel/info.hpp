// tools/bezel/info.hpp — `bezel info`'s two output forms of bezel::FontInfo, and of a text's
// coverage (--coverage).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "bezel/text.hpp"

namespace bezel::cli {

// Aligned "key  value" lines, then the table directory.
std::string format_info_text(const FontInfo& info);
// The JSON contract (see info_format.cpp), one object, keys in a fixed order.
std::string format_info_json(const FontInfo& info);

// Which characters of a text a font maps (`bezel info --coverage`): each distinct character
// once, in the order of first appearance, with its glyph or none.
struct CoverageReport {
    struct Entry {
        char32_t code_point = 0;
        std::optional<GlyphId> gid;   // nullopt: the font's cmap does not map it
        std::size_t font = 0;         // which font of `fonts` draws it
    };
    std::string file;
    int face_index = 0;
    std::vector<std::string> fonts;   // the list, when coverage_of got several fonts
    std::vector<Entry> entries;
};

// `text` must be valid UTF-8 of at most kMaxTextCodePoints characters (the caller checks).
CoverageReport coverage_of(const Font& font, const std::u32string& text);
// Over a font list: the font each character is drawn with is the one text layout picks for its
// grapheme cluster (font fallback, layout.hpp), at its first appearance; `gid` is that font's
// cmap glyph, nullopt when no font has it (drawn as the first font's .notdef). Errors as
// layout_text.
Expected<CoverageReport> coverage_of(FontCollection& fonts, const std::string& utf8);
// "file  F (face N)", "covered  K of N characters", then one line per character:
// "  U+0048  H  gid 43" or "  U+2603  ☃  missing". Over a list, "fonts" lists them
// ("  0  F") and each covered character ends with "font I".
std::string format_coverage_text(const CoverageReport& report);
// {"file", "face_index", "characters": N, "missing": M,
//  "coverage": [{"char", "code_point": "U+XXXX", "gid": int|null}]}; over a list, also
// "fonts": [file, ...] and each entry's "font": index|null.
std::string format_coverage_json(const CoverageReport& report);

}  // namespace bezel::cli
