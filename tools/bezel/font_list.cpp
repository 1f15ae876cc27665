#include "font_list.hpp"

#include <CLI/CLI.hpp>
#include <filesystem>

#include "cli_common.hpp"
#include "parse_check.hpp"

namespace bezel::cli {

namespace {

// The names of a --fallback list; an empty one (",," or a trailing comma) is an error.
Expected<std::vector<std::string>> split_font_names(const std::string& list) {
    std::vector<std::string> out;
    std::size_t start = 0;
    for (;;) {
        const std::size_t comma = list.find(',', start);
        std::string name = list.substr(start, comma == std::string::npos ? std::string::npos
                                                                          : comma - start);
        if (name.empty()) return Error{"'" + list + "': an empty font name"};
        out.push_back(std::move(name));
        if (comma == std::string::npos) return out;
        start = comma + 1;
    }
}

// "file.ttc#2" → file.ttc, face 2, when file.ttc exists and "file.ttc#2" itself does not.
FontSource font_source_named(const std::string& name) {
    std::error_code ec;
    const std::size_t hash = name.rfind('#');
    if (hash != std::string::npos && hash + 1 < name.size() &&
        name.find_first_not_of("0123456789", hash + 1) == std::string::npos &&
        name.size() - hash - 1 <= 5 && !std::filesystem::exists(name, ec) &&
        std::filesystem::exists(name.substr(0, hash), ec)) {
        const int face = std::stoi(name.substr(hash + 1));
        if (face <= kMaxFaceIndex) return FontSource{name.substr(0, hash), face, {}};
    }
    return FontSource{name, 0, {}};
}

}  // namespace

void add_font_list_options(CLI::App& cmd, FontListArgs& list) {
    cmd.add_option("--font", list.fonts,
                   "A font of the list, in order (repeatable; after FONT when both are given); "
                   "FILE#N is face N of a collection. Each character comes from the first font "
                   "that has it")
        ->type_name("FILE");
    cmd.add_option("--fallback", list.fallback,
                   "Fonts after the others, comma-separated, for characters they lack")
        ->type_name("FILE,...")
        ->check(parse_check(split_font_names, "fallback"));
    cmd.add_option("--font-family", list.family,
                   "An installed font by family or fontconfig pattern (\"Noto Serif:bold\", "
                   "\"monospace\"), as fc-match picks it; first in the list unless FONT or --font "
                   "is given")
        ->type_name("PATTERN");
    cmd.add_flag("--no-system-fonts", list.no_system_fonts,
                 "Do not look in the system's fonts (fontconfig) for characters no listed font "
                 "has: draw them as the first font's .notdef");
}

bool font_file_given(const FontArgs& font, const CLI::App& cmd) {
    return cmd.count("FONT") > 0 && font.file != BEZEL_DEFAULT_FONT;
}

bool has_font_list(const FontListArgs& list) {
    return !list.fonts.empty() || !list.family.empty() || !list.fallback.empty();
}

Expected<std::vector<FontSource>> font_sources(const FontArgs& font, const FontListArgs& list,
                                               bool font_given,
                                               std::vector<VariationSetting> first_variations) {
    std::vector<FontSource> out;
    if (font_given || (list.fonts.empty() && list.family.empty()))
        out.push_back({font.file, font.face_index, {}});
    for (const std::string& f : list.fonts) out.push_back(font_source_named(f));
    if (!list.family.empty()) {
        auto system = SystemFonts::open();
        if (!system) return system.error();
        auto matched = system->match(list.family);
        if (!matched) return Error{"--font-family: " + matched.error().message};
        out.push_back(std::move(*matched));
    }
    if (!list.fallback.empty()) {
        auto names = split_font_names(list.fallback);
        if (!names) return Error{"--fallback " + names.error().message};
        for (const std::string& name : *names) out.push_back(font_source_named(name));
    }
    // A --font-family match may come with coordinates (a named instance): the command line's
    // go after them, and a later setting of an axis wins.
    std::vector<VariationSetting>& v = out.front().variations;
    v.insert(v.end(), first_variations.begin(), first_variations.end());
    return out;
}

Expected<FontCollection> open_font_list(const FontArgs& font, const FontListArgs& list,
                                        bool font_given,
                                        std::vector<VariationSetting> first_variations) {
    auto sources = font_sources(font, list, font_given, std::move(first_variations));
    if (!sources) return sources.error();
    auto fonts = FontCollection::open(*sources);
    if (!fonts) return fonts.error();
    // Colour bitmap fonts are drawn in colour (glyph.hpp); other bitmap-only fonts have nothing
    // bezel draws.
    for (std::size_t i = 0; i < fonts->size(); ++i)
        if (!fonts->font(i).has_color_bitmaps())
            if (Status s = fonts->font(i).require_outlines(); !s) return s.error();
    if (!list.no_system_fonts)
        fonts->set_fallback(system_fallback(
            !list.family.empty() ? list.family : fonts->font(0).family_name()));
    return fonts;
}

std::string font_list_names(const FontCollection& fonts) {
    std::string out;
    for (std::size_t i = 0; i < fonts.size(); ++i)
        out += (i > 0 ? ", " : "") + fonts.source(i).file;
    return out;
}

}  // namespace bezel::cli
