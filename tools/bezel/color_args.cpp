// The colour-glyph options: --palette, --custom-palette.
#include "color_args.hpp"

#include <CLI/CLI.hpp>
#include <cctype>
#include <sstream>

#include "bezel/color_glyph.hpp"
#include "cli_common.hpp"

namespace bezel::cli {

void add_color_options(CLI::App& cmd, ColorArgs& args) {
    cmd.add_option("--palette", args.palette,
                   "Colour glyphs (COLR): the font's CPAL palette to paint with (default 0; "
                   "`bezel info` lists them)")
        ->type_name("N")
        ->check(CLI::NonNegativeNumber);
    cmd.add_option("--custom-palette", args.custom_palette,
                   "Colour glyphs: palette entries replaced, comma-separated COLOUR (entries 0, "
                   "1, ... in turn) or INDEX=COLOUR items, e.g. 'ff0000,00ff00' or '3=#0000ff'")
        ->type_name("LIST");
}

Expected<GlyphColorOptions> color_options(const ColorArgs& args) {
    GlyphColorOptions out;
    out.palette.palette = args.palette;
    std::istringstream in(args.custom_palette);
    std::string item;
    int next = 0;
    while (std::getline(in, item, ',')) {
        while (!item.empty() && std::isspace(static_cast<unsigned char>(item.back()))) item.pop_back();
        while (!item.empty() && std::isspace(static_cast<unsigned char>(item.front())))
            item.erase(item.begin());
        if (item.empty()) continue;
        int index = next;
        std::string colour = item;
        if (const std::size_t eq = item.find('='); eq != std::string::npos) {
            const std::string number = item.substr(0, eq);
            const std::optional<double> parsed = parse_number(number);
            if (!parsed || *parsed < 0 || *parsed > 0xFFFE || *parsed != static_cast<int>(*parsed))
                return Error{"--custom-palette: '" + item + "': the index before '=' must be a "
                             "whole number from 0 to 65534"};
            index = static_cast<int>(*parsed);
            colour = item.substr(eq + 1);
        }
        auto c = parse_color(colour);
        if (!c) return Error{"--custom-palette: '" + item + "': " + c.error().message};
        out.palette.custom.push_back({index, *c});
        next = index + 1;
    }
    return out;
}

Status check_palette(const GlyphColorOptions& options, FontCollection& fonts) {
    for (std::size_t i = 0; i < fonts.size(); ++i) {
        Font& font = fonts.font(i);
        if (!font.has_color_bitmaps()) continue;   // FT_HAS_COLOR: COLR/CPAL and bitmap colour
        const std::vector<Palette> p = palettes(font);
        if (p.empty()) continue;
        const int count = static_cast<int>(p.size());
        if (options.palette.palette >= count)
            return Error{"--palette " + std::to_string(options.palette.palette) + ": " +
                         font.file() + " has " + std::to_string(count) + " palette" +
                         (count == 1 ? "" : "s") + " (0 to " + std::to_string(count - 1) + ")"};
        const int entries = static_cast<int>(p[options.palette.palette].entries.size());
        for (const ColorGlyphOptions::Entry& e : options.palette.custom)
            if (e.index >= entries)
                return Error{"--custom-palette: entry " + std::to_string(e.index) + ": " +
                             font.file() + "'s palettes have " + std::to_string(entries) +
                             " entries (0 to " + std::to_string(entries - 1) + ")"};
    }
    return ok_status();
}

}  // namespace bezel::cli
