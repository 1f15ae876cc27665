// bezel_imgui.hpp — Dear ImGui 1.86's font atlas built by bezel: an ImFontBuilderIO (the hook
// imgui_freetype uses) that rasterizes every ImFontConfig's glyph ranges with bezel's glyph path,
// and SVG icons drawn by bezel into the atlas as font glyphs.
//
//   ImFontAtlas& atlas = *ImGui::GetIO().Fonts;
//   atlas.AddFontFromFileTTF("DejaVuSans.ttf", 16.0f);
//   atlas.FontBuilderIO = bezel_imgui::builder();
//   if (!atlas.Build()) std::fprintf(stderr, "%s\n", bezel_imgui::last_build_error().c_str());
//
// Units: ImGui's. ImFontConfig::SizePixels is the height from the font's hhea descender to its
// ascender in pixels (what stb_truetype's ScaleForPixelHeight and imgui_freetype's REAL_DIM size
// request mean), not the em; glyph boxes are pixels, y DOWN, relative to the top of the line.
// docs/imgui.md maps every ImFontConfig field and says what is not supported.
//
// Uses bezel's public API only (bezel::bezel); ImGui's atlas packing (stb_rect_pack, the atlas's
// custom rectangles) and ImFontAtlasBuildFinish are ImGui's own, called as its builders call them.
#pragma once

#include <string>
#include <string_view>

#include <imgui.h>

#include "bezel/expected.hpp"
#include "bezel/font.hpp"
#include "bezel/path.hpp"
#include "bezel/raster.hpp"

struct ImFontBuilderIO;

namespace bezel_imgui {

// ImFontConfig::FontBuilderFlags / ImFontAtlas::FontBuilderFlags (OR-ed together), bit for bit
// imgui_freetype's ImGuiFreeTypeBuilderFlags, so a program switching builders keeps its flags.
enum BuilderFlags : unsigned {
    NoHinting = 1u << 0,       // bezel::Hinting::None
    NoAutoHint = 1u << 1,      // Hinting::Full (see hinting_for_flags)
    ForceAutoHint = 1u << 2,   // Hinting::Auto
    LightHinting = 1u << 3,    // Hinting::Light
    MonoHinting = 1u << 4,     // Hinting::Full (bezel has no monochrome hinting target)
    Bold = 1u << 5,            // GlyphRenderOptions::bold = kBoldStrength
    Oblique = 1u << 6,         // GlyphRenderOptions::slant = kObliqueSlant
    Monochrome = 1u << 7,      // coverage ≥ 1/2 becomes 255, the rest 0 (no anti-aliasing)
    LoadColor = 1u << 8,       // not supported: 1.86's atlas is alpha; colour glyphs give their alpha
    Bitmap = 1u << 9,          // GlyphRenderOptions::embedded_bitmaps: a font's strike at the size
                               // (drawn once, without oversampling: it is whole pixels)
};

// The hinting a set of flags asks for, as imgui_freetype reads them: NoHinting wins, then
// LightHinting, then ForceAutoHint; otherwise (no flag, NoAutoHint, MonoHinting) the font's own
// hinter, Hinting::Full. NoAutoHint cannot forbid FreeType's auto-hinter through bezel: a font
// without hints is auto-hinted under Full, where imgui_freetype would leave it unhinted.
bezel::Hinting hinting_for_flags(unsigned flags);

// imgui_freetype's styles in bezel's terms. Bold: FreeType's FT_GlyphSlot_Embolden strength, an
// em/24 (stems and advance widen by size/24 px). Oblique: FT_GlyphSlot_Oblique's shear,
// 0x0366A / 65536 (about 12°).
inline constexpr double kBoldStrength = 1.0 / 24.0;
inline constexpr double kObliqueSlant = 0x0366A / 65536.0;

// Largest OversampleH / OversampleV accepted: stb_truetype's STBTT_MAX_OVERSAMPLE, beyond which
// ImGui's own builder refuses the font too. Each step renders the glyph once more.
inline constexpr int kMaxOversample = 8;
// Tallest atlas the packer may fill, pixels: ImGui's own builders' limit (1024 × 32).
inline constexpr int kMaxTexHeight = 1024 * 32;

// The builder: set ImFontAtlas::FontBuilderIO to it before Build() (or GetTexData*()). Its Build
// returns false on bad input, with the reason in last_build_error(), and leaves the atlas without
// texture (ImGui's failure path); it never asserts or crashes on a font it is given.
const ImFontBuilderIO* builder();

// What build_atlas does, returning bezel's error instead of false. On success the atlas is built
// as ImGui's own builders leave it: every font's glyphs added (ImFont::AddGlyph, with the
// config's GlyphOffset, Min/MaxAdvanceX, PixelSnapH and GlyphExtraSpacing), the custom
// rectangles packed and ImFontAtlasBuildFinish run, the texture in TexPixelsAlpha8
// (GetTexDataAsRGBA32 converts it). Errors name the font (ImFontConfig::Name and its index in
// ConfigData) and what is wrong: no font configured, data bezel cannot open (its message), FontNo
// out of range, SizePixels not in (0, kMaxFontSizePx], an oversample outside 1..kMaxOversample,
// a glyph range whose first code point is 0 or after its last, a font that gets no glyph at all
// (ImGui needs one), a glyph bezel fails to draw, glyphs that do not fit the texture (counted
// as they are drawn, against the largest texture the atlas may grow to: TexDesiredWidth or 4096
// wide, kMaxTexHeight tall).
bezel::Status build_atlas(ImFontAtlas& atlas);

// The message of the last failed Build() through builder() on this thread ("" after a success).
const std::string& last_build_error();

// --- SVG icons --------------------------------------------------------------------------------
struct SvgIconOptions {
    // The square of path coordinates drawn into the icon: [0, view_box]² (an SVG viewBox
    // "0 0 view_box view_box"), y down. > 0.
    double view_box = 24;
    int size_px = 16;          // the icon's width and height in the atlas, 1..kMaxBitmapDim
    float advance_x = 0;       // the glyph's advance; 0: size_px + 1
    ImVec2 offset{0, 0};       // from the line's top-left to the icon's, as AddCustomRectFontGlyph
    bezel::FillRule rule = bezel::FillRule::NonZero;
};

// An icon reserved in an atlas, waiting to be drawn once the atlas is built.
struct SvgIcon {
    int rect_id = -1;          // ImFontAtlas::GetCustomRectByIndex
    bezel::Path path;          // the parsed path data, view-box units
    bezel::Affine transform;   // view box → icon pixels
    bezel::FillRule rule = bezel::FillRule::NonZero;
};

// Before Build(): parses `svg_path_data` (bezel::parse_svg_path) and reserves a size_px² custom
// rectangle mapped to `codepoint` of `font` (ImFontAtlas::AddCustomRectFontGlyph). Errors name
// the icon's code point: bad path data (the parser's message), a null font, options out of range.
bezel::Expected<SvgIcon> add_svg_icon(ImFontAtlas& atlas, ImFont* font, ImWchar codepoint,
                                      std::string_view svg_path_data,
                                      const SvgIconOptions& options = {});

// After Build(), before the texture is uploaded: fills the icon's rectangle with the path's exact
// coverage (bezel::Rasterizer::fill_path) in TexPixelsAlpha8, and in TexPixelsRGBA32 as white
// with that alpha when the RGBA copy exists already. Errors: the atlas is not built, the
// rectangle was not packed, the rasterizer's.
bezel::Status draw_svg_icon(ImFontAtlas& atlas, const SvgIcon& icon);

}  // namespace bezel_imgui
