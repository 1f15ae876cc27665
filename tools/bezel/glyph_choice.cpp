// The --char / --gid / --text group of glyph_choice.hpp.
#include "glyph_choice.hpp"

#include <CLI/CLI.hpp>

#include "cli_common.hpp"
#include "parse_check.hpp"

namespace bezel::cli {

namespace {

// --text decoded and within its limits; the message leaves the option's name to the caller
// (CLI11 prefixes "--text: ").
Expected<std::u32string> decode_glyph_text(const std::string& text) {
    auto decoded = decode_utf8(text);
    if (!decoded) return decoded.error();
    if (decoded->empty()) return Error{"empty string"};
    if (decoded->size() > kMaxTextCodePoints)
        return Error{std::to_string(decoded->size()) + " characters, more than the " +
                     std::to_string(kMaxTextCodePoints) + " allowed"};
    return decoded;
}

}  // namespace

void add_glyph_choice(CLI::App& cmd, GlyphChoice& choice, const std::string& text_help) {
    // Exactly one: the group turns "none" and "more than one" into CLI11 parse errors.
    CLI::Option_group* which = cmd.add_option_group("glyph", "Which glyph(s), exactly one of:");
    which->add_option("--char", choice.chr, "A character: itself in UTF-8, or U+XXXX")
        ->type_name("C")
        ->check(parse_check([](const std::string& v) { return parse_code_point(v); }, "char"));
    choice.gid_option = which->add_option("--gid", choice.gid, "A glyph id")->type_name("N");
    choice.text_option = which->add_option("--text", choice.text, text_help)
                             ->type_name("STR")
                             ->check(parse_check(decode_glyph_text, "text"));
    which->require_option(1);
}

Expected<std::vector<GlyphRequest>> requested_glyphs(const GlyphChoice& choice, const Font& font) {
    if (choice.gid_option->count() > 0) {
        if (choice.gid >= font.glyph_count())
            return Error{"--gid " + std::to_string(choice.gid) + ": out of range, " + font.file() +
                         " has " + std::to_string(font.glyph_count()) + " glyphs"};
        return std::vector<GlyphRequest>{{choice.gid, std::nullopt}};
    }
    std::vector<GlyphRequest> out;
    if (choice.text_option->count() > 0) {
        auto cps = decode_glyph_text(choice.text);
        if (!cps) return Error{"--text: " + cps.error().message};  // checked at parsing already
        for (char32_t cp : *cps) {
            auto gid = font.glyph_for_char(cp);
            out.push_back({gid.value_or(0), cp, !gid});
        }
        return out;
    }
    auto cp = parse_code_point(choice.chr);
    if (!cp) return Error{"--char: " + cp.error().message};  // checked at parsing already
    auto gid = font.glyph_for_char(*cp);
    out.push_back({gid.value_or(0), *cp, !gid});
    return out;
}

MissingGlyphs missing_of(const std::vector<GlyphRequest>& requests) {
    MissingGlyphs missing;
    for (const GlyphRequest& r : requests) {
        if (!r.missing) continue;
        if (missing.count == 0) missing.first_code_point = r.code_point.value_or(0);
        ++missing.count;
    }
    return missing;
}

}  // namespace bezel::cli
