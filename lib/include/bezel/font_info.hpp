// bezel/font_info.hpp — what a font file says about itself (names, metrics, axes, named instances,
// tables, scripts covered), for `bezel info` and tools that list fonts.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "bezel/color_glyph.hpp"
#include "bezel/expected.hpp"
#include "bezel/font.hpp"

#pragma GCC visibility push(default)  // the public API of libbezel.so (docs/architecture.md)
namespace bezel {

struct FontTable {
    std::string tag;             // four characters, e.g. "glyf", "CFF "
    std::uint32_t length = 0;    // bytes
};

struct NamedInstance {
    std::string name;                            // its subfamily name, e.g. "Bold"
    std::vector<VariationSetting> coordinates;   // one per axis, design units
};

// What a font file says about itself, for the CLI and tools that list fonts.
struct FontInfo {
    std::string file;
    int face_index = 0, face_count = 1;
    std::string family, style;          // as Font::family_name / style_name
    std::string postscript_name;        // name ID 6; "" when absent
    std::string version;                // name ID 5; "" when absent
    std::size_t glyph_count = 0;
    FontMetrics metrics;                // as Font::metrics (font units, y up)
    std::string outline_format;         // "TrueType" (glyf), "CFF", "CFF2", "bitmap" or "none"
    std::vector<VariationAxis> axes;
    std::vector<NamedInstance> instances;
    std::vector<FontTable> tables;      // the table directory, in its order
    // ISO 15924 tags of the scripts the cmap covers: all of a few representative letters of the
    // script (e.g. Arab: ا ب ع ي ه) map to glyphs.
    std::vector<std::string> scripts;
    // Colour: the colour tables bezel reads (color_glyph.hpp's color_tables) and the CPAL palettes.
    ColorTables color;
    std::vector<Palette> palettes;
};

// Reads `file`'s face `face_index` (FreeType for names and metrics, HarfBuzz for the table
// directory and named instances). Errors as Font::open.
Expected<FontInfo> font_info(const std::string& file, int face_index = 0);

}  // namespace bezel
#pragma GCC visibility pop
