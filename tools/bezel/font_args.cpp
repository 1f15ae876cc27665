#include "font_args.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "bezel/font_info.hpp"
#include "cli_common.hpp"
#include "parse_check.hpp"

namespace bezel::cli {

namespace {

// A --font-size as typed: a finite number in (0, kMaxFontSizePx]. Checked on the text, before
// CLI11 converts it, so that "big" gets this message rather than CLI11's "Could not convert".
// The message leaves the option's name to CLI11 ("--font-size: '0': ...").
Expected<double> parse_font_size(const std::string& text) {
    const std::optional<double> px = parse_number(text);
    if (!px) return Error{"'" + text + "': not a number"};
    // Written so that NaN fails too.
    if (!(*px > 0.0 && *px <= kMaxFontSizePx)) {
        std::ostringstream msg;
        msg << "'" << text << "': must be > 0 and <= " << kMaxFontSizePx;
        return Error{msg.str()};
    }
    return *px;
}

}  // namespace

bool looks_like_font_path(const std::string& word) {
    if (word.find('/') != std::string::npos) return true;
    const std::string ext = lowercase_extension(word);
    for (const char* known :
         {".ttf", ".otf", ".ttc", ".otc", ".woff", ".woff2", ".dfont", ".pfb", ".pfa"})
        if (ext == known) return true;
    return false;
}

Expected<std::optional<std::string>> lone_word_as_text(std::string& font_file, const CLI::App& cmd,
                                                       bool text_given,
                                                       const std::string& text_option) {
    if (cmd.count("FONT") == 0 || text_given) return std::optional<std::string>{};
    std::error_code ec;
    if (std::filesystem::exists(font_file, ec)) return std::optional<std::string>{};
    if (looks_like_font_path(font_file))
        return Error{font_file + ": no such font file (to use these words as text, give them with " +
                     text_option + ")"};
    std::optional<std::string> text = std::move(font_file);
    font_file = BEZEL_DEFAULT_FONT;
    return text;
}

void add_font_args(CLI::App& cmd, FontArgs& args) {
    args.file = BEZEL_DEFAULT_FONT;
    cmd.add_option("FONT", args.file,
                   "Font file (TTF, OTF, TTC/OTC); default: the bundled DejaVu Sans")
        ->capture_default_str()
        ->type_name("FILE");
    cmd.add_option("--face-index", args.face_index, "Face to use in a font collection")
        ->capture_default_str()
        ->check(non_negative_number());
    cmd.add_option("--font-size", args.size_px, "Em size in pixels")
        ->capture_default_str()
        ->type_name("PX")
        ->check(parse_check(parse_font_size, "font-size"));
    cmd.add_option("--named-instance", args.named_instance,
                   "A named instance of a variable font, by index (from 0) or name, as bezel info "
                   "lists them; --variations applies on top")
        ->type_name("N|NAME");
    cmd.add_option("--variations", args.variations,
                   "Variable-font axis values, comma-separated, e.g. \"wght=700,wdth=80\"")
        ->type_name("LIST")
        ->check(parse_check(parse_variations, "variations"));
    cmd.add_option("--hinting", args.hinting,
                   "none (exact outlines, the default), light (vertical only), full (the font's "
                   "own hints) or auto (FreeType's auto-hinter)")
        ->type_name("MODE")
        ->check(CLI::IsMember({"none", "light", "full", "auto"}));
}

void add_slant_option(CLI::App& cmd, double& slant) {
    cmd.add_option("--font-slant", slant,
                   "Synthetic slant: each point moves right by X times its height above the "
                   "baseline (0.2 leans about 11 degrees; default 0)")
        ->type_name("X")
        ->check(in_range(-kMaxSyntheticSlant, kMaxSyntheticSlant));
}

void add_bold_option(CLI::App& cmd, double& bold) {
    cmd.add_option("--font-bold", bold,
                   "Synthetic bold, a fraction of the em: the ink grows by X/2 em on every side "
                   "(the glyph dilated by the stroker's offsets) and each advance by X em, as "
                   "FreeType's FT_GlyphSlot_Embolden (0.02 to 0.05 is typical; default 0)")
        ->type_name("X")
        ->check(in_range(0.0, kMaxSyntheticBold));
}

Hinting hinting_of(const FontArgs& args) {
    if (args.hinting == "light") return Hinting::Light;
    if (args.hinting == "full") return Hinting::Full;
    if (args.hinting == "auto") return Hinting::Auto;
    return Hinting::None;
}

Expected<std::vector<VariationSetting>> parse_variations(const std::string& spec) {
    std::vector<VariationSetting> out;
    std::string item;
    std::string normalized = spec;
    for (char& c : normalized)
        if (c == ' ') c = ',';
    std::istringstream in(normalized);
    while (std::getline(in, item, ',')) {
        if (item.empty()) continue;
        auto eq = item.find('=');
        std::string tag = item.substr(0, eq);
        if (eq == std::string::npos || tag.empty() || tag.size() > 4)
            return Error{"'" + item + "': expected TAG=VALUE with a 1-4 letter tag"};
        std::string num = item.substr(eq + 1);
        const std::optional<double> value = parse_number(num);
        if (!value || !std::isfinite(*value))
            return Error{"'" + item + "': '" + num + "' is not a number"};
        tag.resize(4, ' ');
        out.push_back({tag, *value});
    }
    return out;
}

Expected<std::vector<VariationSetting>> requested_variations(const FontArgs& args) {
    std::vector<VariationSetting> settings;
    if (!args.named_instance.empty()) {
        auto info = font_info(args.file, args.face_index);
        if (!info) return info.error();
        const std::vector<NamedInstance>& instances = info->instances;
        const NamedInstance* found = nullptr;
        const std::optional<double> index = parse_number(args.named_instance);
        for (std::size_t i = 0; i < instances.size() && found == nullptr; ++i)
            if (instances[i].name == args.named_instance ||
                (index && *index == static_cast<double>(i)))
                found = &instances[i];
        if (found == nullptr) {
            std::string names;
            for (std::size_t i = 0; i < instances.size(); ++i)
                names += (i ? ", " : "") + std::to_string(i) + " " + instances[i].name;
            return Error{args.file + ": --named-instance " + args.named_instance + ": " +
                         (instances.empty() ? std::string("the font has no named instances")
                                            : "no such instance (it has " + names + ")")};
        }
        settings = found->coordinates;
    }
    auto explicit_settings = parse_variations(args.variations);
    if (!explicit_settings) return Error{"--variations: " + explicit_settings.error().message};
    for (const VariationSetting& v : *explicit_settings) {
        auto same = std::find_if(settings.begin(), settings.end(),
                                 [&](const VariationSetting& s) { return s.tag == v.tag; });
        if (same != settings.end()) {
            same->value = v.value;
        } else {
            settings.push_back(v);
        }
    }
    return settings;
}

Expected<Font> open_font(const FontArgs& args, std::vector<VariationSetting>* applied,
                         FontUse use) {
    std::error_code ec;
    auto status = std::filesystem::status(args.file, ec);
    if (!std::filesystem::exists(status)) return Error{args.file + ": no such file"};
    if (std::filesystem::is_directory(status))
        return Error{args.file + ": is a directory, not a font file"};

    auto font = Font::open(args.file, args.face_index);
    if (!font) return font.error();
    // Say what is wrong with a bitmap-only font once, before any per-character message; a
    // colour bitmap font is drawable where colour glyphs are.
    if (!(use == FontUse::Glyphs && font->has_color_bitmaps()))
        if (Status s = font->require_outlines(); !s) return s.error();
    if (!args.variations.empty() || !args.named_instance.empty()) {
        auto settings = requested_variations(args);
        if (!settings) return settings.error();
        auto set = font->set_variations(*settings);
        if (!set) {
            // The header promises the axis in the message, not the file; add the file if absent.
            const std::string& m = set.error().message;
            return m.find(args.file) == std::string::npos ? Error{args.file + ": " + m} : set.error();
        }
        if (applied != nullptr) *applied = std::move(*settings);
    }
    return font;
}

}  // namespace bezel::cli
