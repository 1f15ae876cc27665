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
    };
    std::string file;
    int face_index = 0;
    std::vector<Entry> entries;
};

// `text` must be valid UTF-8 of at most kMaxTextCodePoints characters (the caller checks).
CoverageReport coverage_of(const Font& font, const std::u32string& text);
// "file  F (face N)", "covered  K of N characters", then one line per character:
// "  U+0048  H  gid 43" or "  U+2603  ☃  missing".
std::string format_coverage_text(const CoverageReport& report);
// {"file", "face_index", "characters": N, "missing": M,
//  "coverage": [{"char", "code_point": "U+XXXX", "gid": int|null}]}
std::string format_coverage_json(const CoverageReport& report);

}  // namespace bezel::cli
