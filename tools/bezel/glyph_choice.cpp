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
    CLI::Option_group* which = cmd.add_option_group("glyph", "Which glyph(s), one of:");
    which->add_option("--char", choice.chr, "A character: itself in UTF-8, or U+XXXX")
        ->type_name("C")
        ->check(parse_check([](const std::string& v) { return parse_code_point(v); }, "char"));
    which->add_option("--gid", choice.gid, "A glyph id")->type_name("N");
    which->add_option("--text", choice.text, text_help)
        ->type_name("STR")
        ->check(parse_check(decode_glyph_text, "text"));
    cmd.add_option("TEXT", choice.text,
                   "The text, as --text; a lone word that is no font file is TEXT")
        ->check(parse_check(decode_glyph_text, "TEXT"));
}

int settle_glyph_choice(GlyphChoice& choice, FontArgs& font, const CLI::App& cmd,
                        const std::string& command) {
    const std::size_t given = cmd.count("--char") + cmd.count("--gid") + cmd.count("--text") +
                              cmd.count("TEXT");
    auto word = lone_word_as_text(font.file, cmd, given > 0, "--text");
    if (!word) return fail_runtime(word.error().message);
    if (word->has_value()) {
        if (auto ok = decode_glyph_text(**word); !ok)
            return fail_usage("TEXT: " + ok.error().message, command);
        choice.text = std::move(**word);
        choice.kind = GlyphChoice::Kind::Text;
        return kExitOk;
    }
    if (given != 1)
        return fail_usage(std::string(given == 0 ? "no glyph given" : "more than one way of "
                                                                      "choosing glyphs given") +
                              ": give exactly one of --char, --gid, --text or TEXT",
                          command);
    choice.kind = cmd.count("--char") > 0  ? GlyphChoice::Kind::Char
                  : cmd.count("--gid") > 0 ? GlyphChoice::Kind::Gid
                                           : GlyphChoice::Kind::Text;
    return kExitOk;
}

Expected<std::vector<GlyphRequest>> requested_glyphs(const GlyphChoice& choice, const Font& font) {
    if (choice.kind == GlyphChoice::Kind::Gid) {
        if (choice.gid >= font.glyph_count())
            return Error{"--gid " + std::to_string(choice.gid) + ": out of range, " + font.file() +
                         " has " + std::to_string(font.glyph_count()) + " glyphs"};
        return std::vector<GlyphRequest>{{choice.gid, std::nullopt}};
    }
    std::vector<GlyphRequest> out;
    if (choice.kind == GlyphChoice::Kind::Text) {
        auto cps = decode_glyph_text(choice.text);
        if (!cps) return Error{"--text: " + cps.error().message};  // checked when settled
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

Expected<std::vector<GlyphRequest>> requested_glyphs(const GlyphChoice& choice,
                                                     FontCollection& fonts) {
    auto requests = requested_glyphs(choice, fonts.font(0));
    if (!requests) return requests.error();
    for (GlyphRequest& r : *requests) {
        if (!r.missing) continue;
        const std::optional<std::size_t> font = fonts.font_for(std::u32string(1, *r.code_point));
        if (!font) continue;
        if (auto gid = fonts.font(*font).glyph_for_char(*r.code_point))
            r = GlyphRequest{*gid, r.code_point, false, *font};
    }
    return requests;
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
