// tools/bezel/glyph_bitmap.hpp — `bezel glyph`'s model: glyph bitmaps from the library's
// GlyphRasterizer, placed as FreeType places them, and their output formats (glyph_output.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bezel/expected.hpp"
#include "bezel/font.hpp"
#include "bezel/glyph.hpp"
#include "bezel/image.hpp"
#include "glyph_choice.hpp"
#include "picture.hpp"

namespace CLI { class App; }

namespace bezel::cli {

// Shared by `bezel glyph` and `bezel fill` (glyph_options.cpp).
// -o, --fill and --tolerance, bound to the given variables.
void add_picture_options(CLI::App& cmd, std::string& output_file, std::string& fill,
                         double& tolerance_px);
// --tolerance must be a number of pixels in [kMinFlattenTolerancePx, 100].
Status check_tolerance(double tolerance_px);

// Most pixels one `bezel glyph` call renders over all its glyphs (LCD counts display pixels):
// 2^24, i.e. a 4096 × 4096 glyph or a thousand 128 × 128 ones. The JSON form spends two hex digits
// per pixel (six for LCD), so this also bounds the output to a few hundred megabytes at worst.
inline constexpr std::size_t kMaxGlyphOutputPixels = std::size_t{1} << 24;

// One glyph as `bezel glyph` prints it: GlyphRasterizer's box (GlyphBoxMode::FreeType:
// left = bitmap_left, top = bitmap_top, as FT_Render_Glyph) and pixels, with the glyph's name and
// the character it was asked for.
struct GlyphBitmap {
    GlyphId gid = 0;
    std::string name;
    std::optional<char32_t> code_point;
    std::string font;                   // the font file, when the glyphs come from a list
    GlyphBox box;                       // width in display pixels
    CoverageFormat format = CoverageFormat::Gray;
    LcdOrder lcd_order = LcdOrder::Rgb;
    // rows packed: width bytes, 3·width for LCD (subpixels left to right: the panel's order),
    // 4·width for a colour glyph
    // (box.color: premultiplied R, G, B, A, as GlyphRasterizer::draw_rgba writes it)
    std::vector<std::uint8_t> pixels;
    int bytes_per_pixel() const { return box.color ? 4 : format == CoverageFormat::Lcd ? 3 : 1; }
};

const char* mode_name(const GlyphBitmap& g);   // "gray", "lcd-rgb", "lcd-bgr", "rgba"

// Output formats (glyph_output.cpp).
// Coverage as text, one character per byte of `mask` from the ramp " .:-=+*#%@" (any nonzero
// coverage shows), each row prefixed by '|', trailing blanks dropped.
std::string ascii_art(ConstMaskView mask);
std::string glyphs_ascii(const std::vector<GlyphBitmap>& glyphs, const GlyphRenderOptions& options);
// The JSON contract: an array, one object per glyph (see the help footer in glyph.cpp).
std::string glyphs_json(const std::vector<GlyphBitmap>& glyphs, const GlyphRenderOptions& options);
// How the glyph picture (png, pgm) is drawn.
struct GlyphPictureOptions {
    // Ink on paper (picture.hpp), or nullopt for the coverage as is (0 = empty, 255 = covered).
    std::optional<PictureColours> colours;
    int margin_px = 0;   // empty pixels around the glyphs on every side, 0..kMaxGlyphMarginPx
    PngOptions png;
};

// The widest --margin of a glyph picture: as much as a glyph at the largest font size needs
// around it, and small enough that margins alone never make a picture too large to encode.
inline constexpr int kMaxGlyphMarginPx = 4096;

// All glyphs side by side, left to right, one empty column apart, top rows aligned on a common
// baseline, options.margin_px empty pixels around them, painted in options.colours. Gray
// coverage in gray colours gives a gray PNG; LCD modes or other colours an RGB one (RGBA for
// translucent colours). Colour glyphs are composited onto the paper "over" in sRGB bytes, as
// the picture convention mixes ink (out = glyph + paper·(1 − alpha), premultiplied), and make
// the picture RGB (RGBA on translucent paper); without colours (--coverage) a picture holding
// colour glyphs is RGBA on transparent, those glyphs as they are and coverage as black ink of
// that alpha. An error when every glyph is empty (no image of 0 × 0 exists).
Expected<std::string> glyphs_png(const std::vector<GlyphBitmap>& glyphs,
                                 const GlyphPictureOptions& options);
// The same picture as binary PGM (P5) when gray, else PPM (P6).
Expected<std::string> glyphs_pnm(const std::vector<GlyphBitmap>& glyphs,
                                 const GlyphPictureOptions& options);

}  // namespace bezel::cli
