#include "font_args.hpp"

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "parse_check.hpp"

namespace bezel::cli {

void add_font_args(CLI::App& cmd, FontArgs& args) {
    args.file = BEZEL_DEFAULT_FONT;
    cmd.add_option("FONT", args.file,
                   "Font file (TTF, OTF, TTC/OTC); default: the bundled DejaVu Sans")
        ->capture_default_str()
        ->type_name("FILE");
    cmd.add_option("--face-index", args.face_index, "Face to use in a font collection")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
    cmd.add_option("--font-size", args.size_px, "Em size in pixels")
        ->capture_default_str()
        ->type_name("PX");
    cmd.add_option("--variations", args.variations,
                   "Variable-font axis values, comma-separated, e.g. \"wght=700,wdth=80\"")
        ->type_name("LIST")
        ->check(parse_check(parse_variations, "variations"));
    cmd.add_flag("--hinting", args.hinting,
                 "Hint the outlines (TrueType bytecode or FreeType's hinter) instead of exact "
                 "scaling");
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
            return Error{"--variations '" + item + "': expected TAG=VALUE with a 1-4 letter tag"};
        std::string num = item.substr(eq + 1);
        char* end = nullptr;
        double value = std::strtod(num.c_str(), &end);
        if (num.empty() || end != num.c_str() + num.size() || !std::isfinite(value))
            return Error{"--variations '" + item + "': '" + num + "' is not a number"};
        tag.resize(4, ' ');
        out.push_back({tag, value});
    }
    return out;
}

Status check_font_size(const FontArgs& args) {
    // Written so that NaN fails too.
    if (!(args.size_px > 0.0 && args.size_px <= kMaxFontSizePx)) {
        std::ostringstream msg;
        msg << "--font-size " << args.size_px << ": must be > 0 and <= " << kMaxFontSizePx;
        return Error{msg.str()};
    }
    return ok_status();
}

Expected<Font> open_font(const FontArgs& args) {
    std::error_code ec;
    auto status = std::filesystem::status(args.file, ec);
    if (!std::filesystem::exists(status)) return Error{args.file + ": no such file"};
    if (std::filesystem::is_directory(status))
        return Error{args.file + ": is a directory, not a font file"};

    auto font = Font::open(args.file, args.face_index);
    if (!font) return font.error();
    if (!args.variations.empty()) {
        auto settings = parse_variations(args.variations);
        if (!settings) return settings.error();
        auto set = font->set_variations(*settings);
        if (!set) {
            // The header promises the axis in the message, not the file; add the file if absent.
            const std::string& m = set.error().message;
            return m.find(args.file) == std::string::npos ? Error{args.file + ": " + m} : set.error();
        }
    }
    return font;
}

}  // namespace bezel::cli
