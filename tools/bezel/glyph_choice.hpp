// tools/bezel/glyph_choice.hpp — which glyphs `outline` and `glyph` work on: exactly one of
// --char C, --gid N or --text STR, checked and resolved the same way by both.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "bezel/expected.hpp"
#include "bezel/font.hpp"
#include "bezel/layout.hpp"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace bezel::cli {

// One glyph to work on: a gid and, when it came from a character, that character.
struct GlyphRequest {
    GlyphId gid = 0;
    std::optional<char32_t> code_point;
    bool missing = false;   // the font maps code_point to nothing: gid is .notdef (0)
};

struct GlyphChoice {
    std::string chr;   // --char
    GlyphId gid = 0;   // --gid
    std::string text;  // --text
    CLI::Option* gid_option = nullptr;
    CLI::Option* text_option = nullptr;
};

// Registers the three options on `cmd` as a group of which exactly one is required, storing into
// `choice` (which must outlive parsing). What is wrong with the command line alone is a usage
// error (exit 2) that CLI11 reports naming the option: none or more than one given, a --char that
// is not one character or U+XXXX, a --text that is not UTF-8, empty, or longer than
// kMaxTextCodePoints. `text_help` describes --text for the command's --help.
void add_glyph_choice(CLI::App& cmd, GlyphChoice& choice, const std::string& text_help);

// Resolves a parsed choice against `font`. A --gid past the font's glyphs is an error naming the
// font (a well-formed value this font lacks: a runtime error); characters of --char or --text the
// font does not map become .notdef (gid 0) marked `missing`, for report_missing_glyphs
// (missing_glyphs.hpp), as hb-view draws them.
Expected<std::vector<GlyphRequest>> requested_glyphs(const GlyphChoice& choice, const Font& font);

// The requests marked `missing`, counted, and the first of them.
MissingGlyphs missing_of(const std::vector<GlyphRequest>& requests);

}  // namespace bezel::cli
