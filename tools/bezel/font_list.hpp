// tools/bezel/font_list.hpp — several fonts for the text commands (render, glyph, atlas, info):
// --font FILE[#FACE] (repeatable) and --fallback FILE[,FILE...] after FONT. Text is drawn with
// font fallback: each character (glyph, atlas, info) or grapheme cluster (render) from the first
// font of the list that has it (bezel/font_collection.hpp).
#pragma once

#include <string>
#include <vector>

#include "bezel/expected.hpp"
#include "bezel/font_collection.hpp"
#include "font_args.hpp"

namespace CLI { class App; }

namespace bezel::cli {

struct FontListArgs {
    std::vector<std::string> fonts;   // --font, in order
    std::string fallback;             // --fallback, comma-separated
};

// Registers --font and --fallback on `cmd`, storing into `list` (which must outlive parsing).
void add_font_list_options(CLI::App& cmd, FontListArgs& list);

// Whether FONT names a font of the command line: given, and not a lone word taken as text
// (which lone_word_as_text replaces by the bundled font).
bool font_file_given(const FontArgs& font, const CLI::App& cmd);

// Whether the list names more than FONT.
bool has_font_list(const FontListArgs& list);

// The fonts in order: FONT (font.file at font.face_index, with `first_variations`) unless
// --font was given and FONT was not (`font_given` false: the bundled default or a lone word
// taken as text); then each --font; then each --fallback. A name FILE#N whose FILE exists and
// N is a number is face N of a collection. Errors: an empty name in --fallback.
Expected<std::vector<FontSource>> font_sources(const FontArgs& font, const FontListArgs& list,
                                               bool font_given,
                                               std::vector<VariationSetting> first_variations);

// Opens font_sources(...). Errors name the file and the reason (no such file, a directory, not
// a font, a bitmap-only font: the commands draw outlines).
Expected<FontCollection> open_font_list(const FontArgs& font, const FontListArgs& list,
                                        bool font_given,
                                        std::vector<VariationSetting> first_variations);

// "a.ttf" for one font, "a.ttf, b.ttf" for several: where a missing glyph was looked for.
std::string font_list_names(const FontCollection& fonts);

}  // namespace bezel::cli
