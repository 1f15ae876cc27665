// tools/bezel/color_args.hpp — the colour-glyph options of the commands that draw glyphs (render,
// glyph, atlas), named after hb-view's: --palette N and --custom-palette.
#pragma once

#include <string>

#include "bezel/expected.hpp"
#include "bezel/font_collection.hpp"
#include "bezel/glyph.hpp"

namespace CLI { class App; }

namespace bezel::cli {

struct ColorArgs {
    int palette = 0;              // --palette: a CPAL palette index
    std::string custom_palette;   // --custom-palette: "ff0000,00ff00" or "2=#ff0000,5=blue"
};

// Registers --palette and --custom-palette on `cmd`, storing into `args` (which must outlive
// parsing). A negative --palette is a usage error at parsing.
void add_color_options(CLI::App& cmd, ColorArgs& args);

// The glyph colour options `args` asks for. --custom-palette is a comma-separated list whose items
// are "COLOUR" (entry k for the k-th item, from 0) or "INDEX=COLOUR", colours as --foreground
// takes them. Errors name the option and the item.
Expected<GlyphColorOptions> color_options(const ColorArgs& args);

// Checks --palette and the custom entries against every font of `fonts` with CPAL palettes: an
// index past a font's palettes or entries is an Error naming the font and what it has. Fonts
// without palettes (bitmap colour fonts, fonts without colour) take any palette.
Status check_palette(const GlyphColorOptions& options, FontCollection& fonts);

}  // namespace bezel::cli
