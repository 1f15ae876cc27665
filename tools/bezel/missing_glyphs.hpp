// tools/bezel/missing_glyphs.hpp — one policy for characters the font has no glyph for, shared by
// render, glyph, outline and atlas: the glyph is the font's .notdef (its "missing glyph" box, as
// hb-view draws it), one warning line on stderr names the first such character and how many there
// are, and the command succeeds; with --strict it is an error (exit 1) and nothing is written.
#pragma once

#include <string>

#include "bezel/expected.hpp"
#include "bezel/layout.hpp"

namespace CLI { class App; }

namespace bezel::cli {

// Registers --strict on `cmd`, storing into `strict` (which must outlive parsing).
void add_strict_option(CLI::App& cmd, bool& strict);

// Nothing when missing.count is 0. Otherwise without `strict`, prints
//   bezel: warning: FILE: no glyph for U+00E9 'é' (and 2 more characters); drawn as .notdef
// and returns ok; with `strict`, returns that as an Error (without "drawn as ...") for
// fail_runtime.
Status report_missing_glyphs(const std::string& font_file, const MissingGlyphs& missing,
                             bool strict);

}  // namespace bezel::cli
