// tools/bezel/glyph_choice.hpp — which glyphs `outline` and `glyph` work on: exactly one of
// --char C, --gid N, --text STR or the TEXT positional (a lone positional word that is no font
// file counts as TEXT), checked and resolved the same way by both.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "bezel/expected.hpp"
#include "bezel/font.hpp"
#include "bezel/font_collection.hpp"
#include "font_args.hpp"
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
    std::size_t font = 0;   // index in the FontCollection (requested_glyphs over a list)
};

struct GlyphChoice {
    enum class Kind { Char, Gid, Text };
    std::string chr;    // --char
    GlyphId gid = 0;    // --gid
    std::string text;   // --text or TEXT
    Kind kind = Kind::Char;   // set by settle_glyph_choice
};

// Registers --char, --gid, --text and the TEXT positional on `cmd` (after add_font_args, so that
// FONT comes first), storing into `choice` (which must outlive parsing). Malformed values are
// usage errors (exit 2) that CLI11 reports naming the option: a --char that is not one character
// or U+XXXX, a --text or TEXT that is not UTF-8, empty, or longer than kMaxTextCodePoints.
// `text_help` describes --text for the command's --help.
void add_glyph_choice(CLI::App& cmd, GlyphChoice& choice, const std::string& text_help);

// After parsing: applies the lone-word rule (lone_word_as_text) and checks that exactly one way
// of choosing glyphs was given. Returns kExitOk, or the exit code after printing the error (a
// missing font path: 1; none or several ways, a lone word that is not valid text: 2).
int settle_glyph_choice(GlyphChoice& choice, FontArgs& font, const CLI::App& cmd,
                        const std::string& command);

// Resolves a settled choice against `font`. A --gid past the font's glyphs is an error naming the
// font (a well-formed value this font lacks: a runtime error); characters of --char, --text or
// TEXT the font does not map become .notdef (gid 0) marked `missing`, for report_missing_glyphs
// (missing_glyphs.hpp), as hb-view draws them.
Expected<std::vector<GlyphRequest>> requested_glyphs(const GlyphChoice& choice, const Font& font);
// The same over a list: each character from the first font that maps it, or the list's
// fallback source's (FontCollection::font_for: one character at a time, as it is asked for, no
// cluster or emoji rule), .notdef of the first font when none does; a --gid is the first font's.
Expected<std::vector<GlyphRequest>> requested_glyphs(const GlyphChoice& choice,
                                                     FontCollection& fonts);

// The requests marked `missing`, counted, and the first of them.
MissingGlyphs missing_of(const std::vector<GlyphRequest>& requests);

}  // namespace bezel::cli
