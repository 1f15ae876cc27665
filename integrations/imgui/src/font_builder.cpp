// The atlas build: ImGui's own builders' sequence (init the custom rectangles, gather each
// config's glyphs, pack custom rectangles then glyphs with stb_rect_pack, fill the alpha texture,
// set up the fonts, add the glyphs, finish), with bezel drawing the glyphs. Every check that can
// fail runs before the atlas's fonts are touched, so a failed build leaves them as they were and
// the atlas without texture.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <unordered_map>
#include <vector>

#include <imgui.h>
#include <imgui_internal.h>
#include <stb_rect_pack.h>

#include "bezel_imgui.hpp"
#include "bezel/glyph.hpp"
#include "bezel/limits.hpp"
#include "font_source.hpp"
#include "glyph_texels.hpp"

namespace bezel_imgui {

namespace {

using detail::GlyphTexels;

struct SourceGlyph {
    ImWchar codepoint = 0;
    GlyphTexels texels;
    int rect = -1;   // index into the packer's rectangles, -1 for an empty glyph
};

struct Source {
    ImFontConfig* cfg = nullptr;
    float ascent = 0, descent = 0;   // ImGui's line metrics, pixels (descent < 0)
    std::vector<SourceGlyph> glyphs;
};

std::string font_name(const ImFontAtlas& atlas, int index) {
    const ImFontConfig& cfg = atlas.ConfigData[index];
    std::string name = cfg.Name[0] != '\0' ? std::string(cfg.Name) : std::string("font");
    return name + " (ImGui font config " + std::to_string(index) + ")";
}

std::string hex(unsigned cp) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "U+%04X", cp);
    return buf;
}

// The code points `cfg` asks for, in range order: its GlyphRanges (ImGui's default ranges when
// null) and its EllipsisChar when set. Errors name the first bad range.
bezel::Expected<std::vector<ImWchar>> requested(ImFontAtlas& atlas, const ImFontConfig& cfg,
                                                const std::string& name) {
    const ImWchar* ranges = cfg.GlyphRanges ? cfg.GlyphRanges : atlas.GetGlyphRangesDefault();
    std::vector<ImWchar> out;
    for (int i = 0; ranges[2 * i] != 0; ++i) {
        const unsigned first = ranges[2 * i], last = ranges[2 * i + 1];
        if (last == 0 || first > last)
            return bezel::Error{name + ": glyph range " + std::to_string(i) + " (" + hex(first) +
                                ".." + hex(last) + ") is empty: its first code point is after "
                                "its last (ranges are pairs ending with 0)"};
        for (unsigned cp = first; cp <= last; ++cp) out.push_back(static_cast<ImWchar>(cp));
    }
    if (cfg.EllipsisChar != static_cast<ImWchar>(-1)) out.push_back(cfg.EllipsisChar);
    return out;
}

// The most texels the atlas can hold: its widest texture (TexDesiredWidth, or the widest ImGui
// picks, 4096) times kMaxTexHeight. Glyphs are counted against it as they are drawn, so a huge
// SizePixels meets an error, not an allocation of its bitmaps.
std::size_t max_texels(const ImFontAtlas& atlas) {
    const int width = atlas.TexDesiredWidth > 0 ? std::min(atlas.TexDesiredWidth, bezel::kMaxBitmapDim)
                                                : 4096;
    return static_cast<std::size_t>(width) * kMaxTexHeight;
}

// Opens one config's font and renders every requested glyph it has that no earlier config of
// the same destination font supplied (`taken`: first config wins, as in ImGui's builders).
bezel::Status gather(ImFontAtlas& atlas, int index, std::vector<bool>& taken, Source& src,
                     std::vector<std::uint8_t>& store) {
    ImFontConfig& cfg = atlas.ConfigData[index];
    const std::string name = font_name(atlas, index);
    if (!(cfg.SizePixels > 0) || cfg.SizePixels > bezel::kMaxFontSizePx)
        return bezel::Error{name + ": SizePixels " + std::to_string(cfg.SizePixels) +
                            " is not in (0, " + std::to_string(bezel::kMaxFontSizePx) + "]"};
    if (cfg.OversampleH < 1 || cfg.OversampleH > kMaxOversample || cfg.OversampleV < 1 ||
        cfg.OversampleV > kMaxOversample)
        return bezel::Error{name + ": OversampleH " + std::to_string(cfg.OversampleH) +
                            " / OversampleV " + std::to_string(cfg.OversampleV) +
                            ": each must be 1.." + std::to_string(kMaxOversample)};
    if (cfg.FontDataSize < 0) return bezel::Error{name + ": FontDataSize is negative"};
    auto font = detail::open_font_bytes(cfg.FontData, static_cast<std::size_t>(cfg.FontDataSize),
                                        cfg.FontNo, name);
    if (!font) return font.error();
    if (auto outlines = font->require_outlines(); !outlines) return outlines.error();
    auto codepoints = requested(atlas, cfg, name);
    if (!codepoints) return codepoints.error();

    // SizePixels spans the hhea descender to ascender (stb_truetype's ScaleForPixelHeight).
    const bezel::FontMetrics m = font->metrics();
    const double height_units = m.ascender - m.descender;
    if (!(height_units > 0) || m.units_per_em <= 0)
        return bezel::Error{name + ": the font has no vertical metrics (ascender − descender is " +
                            std::to_string(height_units) + " units)"};
    const double px_per_unit = cfg.SizePixels / height_units;
    // ImGui's line metrics, as its stb_truetype builder makes them: each moved a pixel away
    // from the baseline, then truncated toward zero (IM_FLOOR).
    src.cfg = &cfg;
    src.ascent = IM_FLOOR(static_cast<float>(m.ascender * px_per_unit) +
                          (m.ascender > 0 ? 1.0f : -1.0f));
    src.descent = IM_FLOOR(static_cast<float>(m.descender * px_per_unit) +
                           (m.descender > 0 ? 1.0f : -1.0f));

    const unsigned flags = cfg.FontBuilderFlags | atlas.FontBuilderFlags;
    bezel::GlyphRenderOptions options;
    options.size_px = m.units_per_em * px_per_unit;
    options.hinting = hinting_for_flags(flags);
    if (flags & Bold) options.bold = kBoldStrength;
    if (flags & Oblique) options.slant = kObliqueSlant;
    if (flags & Bitmap) options.embedded_bitmaps = true;
    // PixelSnapH puts every pen on a whole pixel, where the extra horizontal renders would only
    // blur the glyph (ImGui's own advice is OversampleH = 1 with it).
    const detail::Oversample oversample{cfg.PixelSnapH ? 1 : cfg.OversampleH, cfg.OversampleV};

    bezel::GlyphRasterizer rasterizer(*font);
    std::vector<std::uint8_t> scratch;
    for (const ImWchar cp : *codepoints) {
        if (taken[cp]) continue;
        const auto gid = font->glyph_for_char(cp);
        if (!gid) continue;
        taken[cp] = true;
        SourceGlyph g;
        g.codepoint = cp;
        auto drawn = detail::render_glyph_texels(rasterizer, *gid, options, oversample,
                                                 (flags & Monochrome) != 0, max_texels(atlas),
                                                 store, scratch, g.texels);
        if (!drawn) return bezel::Error{name + ": " + hex(cp) + ": " + drawn.error().message};
        src.glyphs.push_back(g);
    }
    return bezel::ok_status();
}

// ImGui's choice of texture width when the user leaves it open: the smallest of 512, 1024, 2048,
// 4096 whose square holds the glyphs' area at about half density (√area < 0.7 · width).
int texture_width(const ImFontAtlas& atlas, double total_area) {
    if (atlas.TexDesiredWidth > 0) return atlas.TexDesiredWidth;
    const double side = std::sqrt(total_area) + 1;
    for (int w : {4096, 2048, 1024})
        if (side >= 0.7 * w) return w;
    return 512;
}

int upper_power_of_two(int v) {
    int p = 1;
    while (p < v) p <<= 1;
    return p;
}

bezel::Status build(ImFontAtlas& atlas) {
    if (atlas.ConfigData.Size == 0) return bezel::Error{"ImGui font atlas: no font configured"};
    ImFontAtlasBuildInit(&atlas);
    atlas.TexID = ImTextureID{};
    atlas.TexWidth = atlas.TexHeight = 0;
    atlas.TexUvScale = ImVec2(0, 0);
    atlas.TexUvWhitePixel = ImVec2(0, 0);
    atlas.ClearTexData();

    std::vector<Source> sources(static_cast<std::size_t>(atlas.ConfigData.Size));
    std::vector<std::uint8_t> store;
    std::unordered_map<const ImFont*, std::vector<bool>> taken;
    for (int i = 0; i < atlas.ConfigData.Size; ++i) {
        const ImFontConfig& cfg = atlas.ConfigData[i];
        if (std::find(atlas.Fonts.begin(), atlas.Fonts.end(), cfg.DstFont) == atlas.Fonts.end())
            return bezel::Error{font_name(atlas, i) + ": its font is not in the atlas (MergeMode "
                                "without an earlier font?)"};
        auto& set = taken[cfg.DstFont];
        set.resize(IM_UNICODE_CODEPOINT_MAX + 1);
        if (auto ok = gather(atlas, i, set, sources[i], store); !ok) return ok.error();
    }
    // ImGui's lookup tables need at least one glyph in every font.
    for (const ImFont* font : atlas.Fonts) {
        std::size_t n = 0;
        for (const Source& s : sources)
            if (s.cfg->DstFont == font) n += s.glyphs.size();
        for (const ImFontAtlasCustomRect& r : atlas.CustomRects)
            if (r.Font == font) ++n;
        if (n == 0) {
            const auto first = std::find_if(sources.begin(), sources.end(), [&](const Source& s) {
                return s.cfg->DstFont == font;
            });
            const std::string name = first == sources.end()
                ? std::string("ImGui font ") + font->GetDebugName()
                : font_name(atlas, static_cast<int>(first - sources.begin()));
            return bezel::Error{name + ": none of the code points its glyph ranges ask for is "
                                "in the font (ImGui needs a glyph)"};
        }
    }

    // Packing: the custom rectangles first (ImGui's white pixel, cursors, baked lines, user
    // glyphs), then every glyph with TexGlyphPadding on its right and bottom.
    const int pad = std::max(0, atlas.TexGlyphPadding);
    std::vector<stbrp_rect> rects;
    double area = 0;
    int widest = 0;
    for (Source& s : sources) {
        for (SourceGlyph& g : s.glyphs) {
            if (g.texels.width == 0) continue;
            g.rect = static_cast<int>(rects.size());
            stbrp_rect r{};
            r.id = g.rect;
            r.w = g.texels.width + pad;
            r.h = g.texels.height + pad;
            rects.push_back(r);
            area += static_cast<double>(r.w) * r.h;
            widest = std::max(widest, static_cast<int>(r.w));
        }
    }
    for (const ImFontAtlasCustomRect& r : atlas.CustomRects) widest = std::max(widest, r.Width + pad);
    atlas.TexWidth = texture_width(atlas, area);
    if (atlas.TexWidth > bezel::kMaxBitmapDim || atlas.TexWidth < widest)
        return bezel::Error{"ImGui font atlas: texture width " + std::to_string(atlas.TexWidth) +
                            " cannot hold the widest glyph or rectangle (" +
                            std::to_string(widest) + " px with padding; at most " +
                            std::to_string(bezel::kMaxBitmapDim) + ")"};
    std::vector<stbrp_node> nodes(static_cast<std::size_t>(atlas.TexWidth - pad));
    stbrp_context packer;
    stbrp_init_target(&packer, atlas.TexWidth - pad, kMaxTexHeight - pad, nodes.data(),
                      static_cast<int>(nodes.size()));
    atlas.TexHeight = 0;
    ImFontAtlasBuildPackCustomRects(&atlas, &packer);
    for (int i = 0; i < atlas.CustomRects.Size; ++i)
        if (!atlas.CustomRects[i].IsPacked())
            return bezel::Error{"ImGui font atlas: custom rectangle " + std::to_string(i) +
                                " does not fit a " + std::to_string(atlas.TexWidth) + " × " +
                                std::to_string(kMaxTexHeight) + " texture"};
    if (!rects.empty()) stbrp_pack_rects(&packer, rects.data(), static_cast<int>(rects.size()));
    for (const stbrp_rect& r : rects) {
        if (!r.was_packed)
            return bezel::Error{"ImGui font atlas: the glyphs do not fit a " +
                                std::to_string(atlas.TexWidth) + " × " +
                                std::to_string(kMaxTexHeight) + " texture (fewer glyphs, a "
                                "smaller size or less oversampling)"};
        atlas.TexHeight = std::max(atlas.TexHeight, static_cast<int>(r.y + r.h));
    }
    atlas.TexHeight = (atlas.Flags & ImFontAtlasFlags_NoPowerOfTwoHeight)
                          ? atlas.TexHeight + 1
                          : upper_power_of_two(atlas.TexHeight);
    atlas.TexUvScale = ImVec2(1.0f / atlas.TexWidth, 1.0f / atlas.TexHeight);

    const std::size_t tex_bytes = static_cast<std::size_t>(atlas.TexWidth) * atlas.TexHeight;
    atlas.TexPixelsAlpha8 = static_cast<unsigned char*>(IM_ALLOC(tex_bytes));
    std::memset(atlas.TexPixelsAlpha8, 0, tex_bytes);
    for (const Source& s : sources) {
        unsigned char multiply[256];
        const bool multiplied = s.cfg->RasterizerMultiply != 1.0f;
        if (multiplied) ImFontAtlasBuildMultiplyCalcLookupTable(multiply, s.cfg->RasterizerMultiply);
        for (const SourceGlyph& g : s.glyphs) {
            if (g.rect < 0) continue;
            const stbrp_rect& r = rects[static_cast<std::size_t>(g.rect)];
            for (int y = 0; y < g.texels.height; ++y)
                std::memcpy(atlas.TexPixelsAlpha8 + (r.y + y) * atlas.TexWidth + r.x,
                            store.data() + g.texels.offset +
                                static_cast<std::size_t>(y) * g.texels.width,
                            static_cast<std::size_t>(g.texels.width));
            if (multiplied)
                ImFontAtlasBuildMultiplyRectAlpha8(multiply, atlas.TexPixelsAlpha8, r.x, r.y,
                                                   g.texels.width, g.texels.height,
                                                   atlas.TexWidth);
        }
    }

    // Fonts: a config's glyphs sit GlyphOffset from the pen, with the baseline at the rounded
    // ascent of the destination font (its first config's: merged fonts share its baseline).
    for (Source& s : sources) {
        ImFontConfig& cfg = *s.cfg;
        ImFont* dst = cfg.DstFont;
        ImFontAtlasBuildSetupFont(&atlas, dst, &cfg, s.ascent, s.descent);
        const float off_x = cfg.GlyphOffset.x;
        const float off_y = cfg.GlyphOffset.y + IM_ROUND(dst->Ascent);
        for (const SourceGlyph& g : s.glyphs) {
            float u0 = 0, v0 = 0, u1 = 0, v1 = 0;
            if (g.rect >= 0) {
                const stbrp_rect& r = rects[static_cast<std::size_t>(g.rect)];
                u0 = r.x * atlas.TexUvScale.x;
                v0 = r.y * atlas.TexUvScale.y;
                u1 = (r.x + g.texels.width) * atlas.TexUvScale.x;
                v1 = (r.y + g.texels.height) * atlas.TexUvScale.y;
            }
            dst->AddGlyph(&cfg, g.codepoint, g.texels.x0 + off_x, g.texels.y0 + off_y,
                          g.texels.x1 + off_x, g.texels.y1 + off_y, u0, v0, u1, v1,
                          g.texels.advance_px);
        }
    }
    ImFontAtlasBuildFinish(&atlas);
    return bezel::ok_status();
}

thread_local std::string t_last_error;

bool build_through_io(ImFontAtlas* atlas) {
    auto built = build_atlas(*atlas);
    t_last_error = built ? std::string() : built.error().message;
    return built.ok();
}

const ImFontBuilderIO kBuilder{&build_through_io};

}  // namespace

bezel::Hinting hinting_for_flags(unsigned flags) {
    if (flags & NoHinting) return bezel::Hinting::None;
    if (flags & LightHinting) return bezel::Hinting::Light;
    if (flags & ForceAutoHint) return bezel::Hinting::Auto;
    return bezel::Hinting::Full;
}

bezel::Status build_atlas(ImFontAtlas& atlas) {
    auto built = build(atlas);
    if (!built) {
        // ImGui's failure path: no texture (ClearTexData ran first); nothing was added to fonts.
        atlas.ClearTexData();
        atlas.TexWidth = atlas.TexHeight = 0;
    }
    return built;
}

const std::string& last_build_error() { return t_last_error; }

const ImFontBuilderIO* builder() { return &kBuilder; }

}  // namespace bezel_imgui
