#include "missing_glyphs.hpp"

#include <CLI/CLI.hpp>
#include <iostream>

#include "cli_common.hpp"

namespace bezel::cli {

void add_strict_option(CLI::App& cmd, bool& strict) {
    cmd.add_flag("--strict", strict,
                 "A character the font has no glyph for is an error (exit 1, nothing written) "
                 "instead of a warning and the font's .notdef box");
}

namespace {

// "U+00E9 'é'"; control and space characters as their code point alone.
std::string describe_character(char32_t cp) {
    std::string text = format_code_point(cp);
    if (cp <= 0x20 || cp == 0x7F || (cp >= 0x80 && cp < 0xA0)) return text;
    std::string utf8;
    append_utf8(utf8, cp);
    return text + " '" + utf8 + "'";
}

}  // namespace

Status report_missing_glyphs(const std::string& font_file, const MissingGlyphs& missing,
                             bool strict) {
    if (missing.count == 0) return ok_status();
    std::string what = font_file + ": no glyph for " + describe_character(missing.first_code_point);
    if (missing.count > 1)
        what += " (and " + std::to_string(missing.count - 1) + " more " +
                (missing.count == 2 ? "character" : "characters") + ")";
    if (strict) return Error{what + " (--strict)"};
    std::cerr << "bezel: warning: " << what << "; drawn as .notdef\n";
    return ok_status();
}

}  // namespace bezel::cli
