// SVG path data drawn by bezel into an ImGui atlas rectangle that ImGui maps to a font glyph.
#include <cmath>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "bezel_imgui.hpp"
#include "bezel/limits.hpp"

namespace bezel_imgui {

namespace {
std::string icon_name(ImWchar codepoint) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "SVG icon U+%04X", static_cast<unsigned>(codepoint));
    return buf;
}
}  // namespace

bezel::Expected<SvgIcon> add_svg_icon(ImFontAtlas& atlas, ImFont* font, ImWchar codepoint,
                                      std::string_view svg_path_data,
                                      const SvgIconOptions& options) {
    const std::string name = icon_name(codepoint);
    if (font == nullptr) return bezel::Error{name + ": no font to add it to"};
    if (!(options.view_box > 0) || !std::isfinite(options.view_box))
        return bezel::Error{name + ": view_box " + std::to_string(options.view_box) +
                            " is not a positive number"};
    if (options.size_px < 1 || options.size_px > bezel::kMaxBitmapDim)
        return bezel::Error{name + ": size_px " + std::to_string(options.size_px) + " is not in 1.." +
                            std::to_string(bezel::kMaxBitmapDim)};
    if (!std::isfinite(options.advance_x) || options.advance_x < 0)
        return bezel::Error{name + ": advance_x must be a finite number ≥ 0"};
    auto path = bezel::parse_svg_path(svg_path_data);
    if (!path) return bezel::Error{name + ": " + path.error().message};
    SvgIcon icon;
    icon.path = std::move(*path);
    icon.transform = bezel::Affine::scale(options.size_px / options.view_box);
    icon.rule = options.rule;
    const float advance = options.advance_x > 0 ? options.advance_x
                                                : static_cast<float>(options.size_px + 1);
    icon.rect_id = atlas.AddCustomRectFontGlyph(font, codepoint, options.size_px, options.size_px,
                                                advance, options.offset);
    return icon;
}

bezel::Status draw_svg_icon(ImFontAtlas& atlas, const SvgIcon& icon) {
    if (atlas.TexPixelsAlpha8 == nullptr || icon.rect_id < 0 || icon.rect_id >= atlas.CustomRects.Size)
        return bezel::Error{"SVG icon: the atlas is not built, or the icon is not one of its "
                            "rectangles (draw it after ImFontAtlas::Build)"};
    const ImFontAtlasCustomRect& r = atlas.CustomRects[icon.rect_id];
    const std::string name = icon_name(static_cast<ImWchar>(r.GlyphID));
    if (!r.IsPacked()) return bezel::Error{name + ": its rectangle was not packed"};
    const bezel::MaskView target{atlas.TexPixelsAlpha8 + r.Y * atlas.TexWidth + r.X, r.Width,
                                 r.Height, atlas.TexWidth};
    bezel::FillOptions fill;
    fill.rule = icon.rule;
    bezel::Rasterizer raster;
    if (auto drawn = raster.fill_path(icon.path, icon.transform, target, fill); !drawn)
        return bezel::Error{name + ": " + drawn.error().message};
    if (atlas.TexPixelsRGBA32 != nullptr) {
        // ImGui's RGBA copy of the alpha texture: white, with the coverage as alpha.
        for (int y = 0; y < r.Height; ++y)
            for (int x = 0; x < r.Width; ++x)
                atlas.TexPixelsRGBA32[(r.Y + y) * atlas.TexWidth + r.X + x] =
                    IM_COL32(255, 255, 255, target.at(x, y));
    }
    return bezel::ok_status();
}

}  // namespace bezel_imgui
