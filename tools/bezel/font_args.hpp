// tools/bezel/font_args.hpp — the font options every glyph-drawing subcommand takes, named after
// HarfBuzz's hb-view where they overlap: FONT (positional, default: the bundled DejaVu Sans),
// --face-index, --font-size, --named-instance, --variations, --hinting.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "bezel/expected.hpp"
#include "bezel/font.hpp"

namespace CLI { class App; }

namespace bezel::cli {

// hb-view's default size: large enough that pixel coordinates keep the design's detail.
inline constexpr double kDefaultFontSizePx = 256.0;

struct FontArgs {
    std::string file;            // set to BEZEL_DEFAULT_FONT by add_font_args
    int face_index = 0;
    double size_px = kDefaultFontSizePx;
    std::string variations;      // "wght=700,wdth=80"
    std::string named_instance;  // --named-instance: an index or a name of the font's fvar
    std::string hinting = "none";   // --hinting: none, light, full or auto
};

// Registers --font-slant X (hb-view's option: GlyphRenderOptions::slant, -1 to 1) on `cmd`.
void add_slant_option(CLI::App& cmd, double& slant);
// Registers --font-bold X (hb-view's option: GlyphRenderOptions::bold and ShapeOptions::bold,
// a fraction of the em, 0 to kMaxSyntheticBold) on `cmd`.
void add_bold_option(CLI::App& cmd, double& bold);

// The --hinting mode of `args` (add_font_args has checked the name).
Hinting hinting_of(const FontArgs& args);

// Registers FONT, --face-index, --font-size, --variations and --hinting on `cmd`, storing into
// `args` (which must outlive parsing). Malformed values (a size that is not a number or not in
// (0, kMaxFontSizePx], a variations string that does not parse) are usage errors reported by
// CLI11 when the command line is parsed; a command's own default size is not checked.
void add_font_args(CLI::App& cmd, FontArgs& args);

// Parses "wght=700,wdth=80" (also "wght=700 wdth=80"); tags are 1–4 characters, padded with
// spaces as OpenType does. The error names the bad item, not the option (CLI11 adds
// "--variations: " when it checks the option).
Expected<std::vector<VariationSetting>> parse_variations(const std::string& spec);

// Whether a command-line word names a font file that is not there: it has a font file's extension
// (.ttf, .otf, .ttc, .otc, .woff, .woff2, .dfont, .pfb, .pfa, any case) or a '/'. Such a word given
// where FONT or TEXT could go is a missing font, not text to draw.
bool looks_like_font_path(const std::string& word);

// The lone-word rule of the font commands (render, glyph, outline, atlas, info), read as a person
// means it. When `cmd` got FONT (stored in `font_file`) and no text in any other way (`text_given`
// false): a FONT that exists stays the font (nullopt); one that looks like a font path
// (looks_like_font_path) is a missing font, an Error that names it and suggests `text_option`;
// any other word is the text, returned, with `font_file` reset to the default font. Otherwise
// nullopt and `font_file` untouched.
Expected<std::optional<std::string>> lone_word_as_text(std::string& font_file, const CLI::App& cmd,
                                                       bool text_given,
                                                       const std::string& text_option);

// The variation settings `args` asks for: the coordinates of --named-instance (by index from 0,
// or by name, as `bezel info` lists them), then --variations, whose axes win over the instance's.
// Errors name the file: a font with no such instance (the message lists the ones it has).
Expected<std::vector<VariationSetting>> requested_variations(const FontArgs& args);

// What a command does with a font: its outlines (outline, info's outline facts), or its glyphs
// drawn, colour glyphs in colour (render, glyph, atlas), which a colour bitmap font has too.
enum class FontUse { Outlines, Glyphs };

// Opens args.file at args.face_index and applies requested_variations(args), also stored into
// `applied` when given (empty when none were asked for). Errors name the file and, for
// variations, the axis; a missing file or a directory is reported as such before FreeType sees it,
// and a bitmap-only font (no outlines to draw: Font::require_outlines) is an error too, unless
// `use` is Glyphs and its bitmaps are colour.
Expected<Font> open_font(const FontArgs& args, std::vector<VariationSetting>* applied = nullptr,
                         FontUse use = FontUse::Outlines);

}  // namespace bezel::cli
