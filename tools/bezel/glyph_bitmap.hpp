// tools/bezel/glyph_bitmap.hpp — `bezel glyph`'s model: glyph bitmaps placed as FreeType places
// them, rendered by bezel's Rasterizer, and their output formats (glyph_output.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bezel/expected.hpp"
#include "bezel/font.hpp"
#include "bezel/image.hpp"
#include "bezel/raster.hpp"
#include "glyph_choice.hpp"

namespace CLI { class App; }

namespace bezel::cli {

// Shared by `bezel glyph` and `bezel fill` (glyph_options.cpp).
// The output format: `format_option` when given, else the one `extensions` maps the -o file's
// extension to (".png" → "png", …, case-insensitive), else `fallback` (stdout). An unknown
// extension is an error naming the file and the extensions known.
Expected<std::string> pick_picture_format(
    const std::string& format_option, const std::string& output_file,
    const std::vector<std::pair<std::string, std::string>>& extensions, const std::string& fallback);
// -o, --fill and --tolerance, bound to the given variables.
void add_picture_options(CLI::App& cmd, std::string& output_file, std::string& fill,
                         double& tolerance_px);
// --tolerance must be a number of pixels in [kMinFlattenTolerancePx, 100].
Status check_tolerance(double tolerance_px);

// Most pixels one `bezel glyph` call renders over all its glyphs (LCD counts display pixels):
// 2^24, i.e. a 4096 × 4096 glyph or a thousand 128 × 128 ones. The JSON form spends two hex digits
// per pixel (six for LCD), so this also bounds the output to a few hundred megabytes at worst.
inline constexpr std::size_t kMaxGlyphOutputPixels = std::size_t{1} << 24;
// Largest |--offset| component, in pixels: keeps every box coordinate far inside int.
inline constexpr double kMaxGlyphOffsetPx = 16384.0;

enum class GlyphMode : std::uint8_t { Gray, LcdRgb, LcdBgr };

struct GlyphRenderSettings {
    double size_px = 0;
    bool hinting = false;
    Vec2 offset;                     // pen position, pixels, x right, y DOWN
    FillRule rule = FillRule::NonZero;
    GlyphMode mode = GlyphMode::Gray;
    FlattenOptions flatten = raster_flatten_defaults();
    // Accumulate: Accurate only for glyphs the font marks as overlapping; Accurate: for all
    // (unmarked fonts have overlapping components too, e.g. 59 accented glyphs of DejaVu Sans).
    OverlapMode overlap = OverlapMode::Accumulate;
};

// One rendered glyph. The box follows FreeType's FT_Render_Glyph: `left` = bitmap_left (columns
// from the pen to the first column), `top` = bitmap_top (rows above the baseline), computed from
// the outline's CONTROL box in 26.6 fixed point, floor/ceil to whole pixels (FreeType's
// ft_glyphslot_preset_bitmap), the LCD box one pixel wider on each side (ft_lcd_padding).
struct GlyphBitmap {
    GlyphId gid = 0;
    std::string name;
    std::optional<char32_t> code_point;
    double advance_px = 0;
    int left = 0, top = 0, width = 0, height = 0;   // width in display pixels
    bool accurate_overlap = false;   // rendered with OverlapMode::Accurate
    Path outline;                       // pixels, y down, pen at the origin (before the offset)
    GlyphMode mode = GlyphMode::Gray;
    std::vector<std::uint8_t> pixels;   // rows packed: width bytes, or 3·width for LCD (R, G, B)
    int bytes_per_pixel() const { return mode == GlyphMode::Gray ? 1 : 3; }
};

// Loads the outline and computes the box (no pixels yet). Errors name the glyph.
Expected<GlyphBitmap> measure_glyph(Font& font, const GlyphRequest& request,
                                    const GlyphRenderSettings& settings);
// Renders into `glyph` (measured by measure_glyph with the same settings).
Status render_glyph(Rasterizer& raster, const GlyphRenderSettings& settings, GlyphBitmap& glyph);

const char* mode_name(GlyphMode mode);   // "gray", "lcd-rgb", "lcd-bgr"

// Output formats (glyph_output.cpp).
// Coverage as text, one character per byte of `mask` from the ramp " .:-=+*#%@" (any nonzero
// coverage shows), each row prefixed by '|', trailing blanks dropped.
std::string ascii_art(ConstMaskView mask);
std::string glyphs_ascii(const std::vector<GlyphBitmap>& glyphs, const GlyphRenderSettings& s);
// The JSON contract: an array, one object per glyph (see the help footer in glyph.cpp).
std::string glyphs_json(const std::vector<GlyphBitmap>& glyphs, const GlyphRenderSettings& s);
// All glyphs side by side, left to right, one empty column apart, top rows aligned on a common
// baseline; coverage as is (0 black = empty, 255 white = covered). LCD modes give an RGB image.
// An error when every glyph is empty (no image of 0 × 0 exists).
Expected<std::string> glyphs_png(const std::vector<GlyphBitmap>& glyphs);
// The same picture as binary PGM (P5), or PPM (P6) for LCD modes.
Expected<std::string> glyphs_pnm(const std::vector<GlyphBitmap>& glyphs);

}  // namespace bezel::cli
