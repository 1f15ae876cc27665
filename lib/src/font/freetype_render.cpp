// render_with_freetype (bezel/freetype_reference.hpp): FreeType's smooth rasterizer on the unhinted
// outline, for comparisons and benchmarks (`bezel bench`).
//
// It does what tools/bench/raster_bench.cpp times for FreeType: the glyph loaded at the size
// with FT_LOAD_NO_HINTING (FreeType scales to 26.6, rounding every point to 1/64 px), translated
// to the pen position, the target cleared, then FT_Outline_Render with FT_RASTER_FLAG_AA into a
// gray FT_Bitmap that shares the caller's rows (pitch = stride). FT_Outline_Render is the plain
// smooth rasterizer: it does not supersample FT_OUTLINE_OVERLAP glyphs (FT_Render_Glyph would).
//
// The last loaded outline is cached (font_impl.hpp): rendering the same glyph at the same size
// and variation coordinates again skips the loader, so a timing loop times the rasterizer.
#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_MULTIPLE_MASTERS_H
#include FT_OUTLINE_H

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "bezel/freetype_reference.hpp"
#include "font/font_impl.hpp"
#include "font/ft_error.hpp"

namespace bezel {

namespace {

// FreeType's gray raster addresses rows and columns in 16-bit signed cells.
constexpr int kMaxFreeTypeTargetPx = 32767;
// A pen position beyond this is rejected: in 26.6 it must stay far inside FT_Pos (and FreeType's
// 32-bit cell arithmetic), and no target is that large anyway.
constexpr double kMaxFreeTypeOriginPx = 1e6;

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

// Variation blend coordinates of the face now (empty for a face without variations).
void current_coords(FT_Face face, font_detail::FreeTypeRenderCache& c, std::vector<FT_Fixed>& out) {
    out.clear();
    if (!FT_HAS_MULTIPLE_MASTERS(face)) return;
    if (c.axis_count < 0) {
        c.axis_count = 0;
        FT_MM_Var* mm = nullptr;
        if (FT_Get_MM_Var(face, &mm) == 0 && mm) {
            c.axis_count = static_cast<int>(mm->num_axis);
            FT_Done_MM_Var(face->glyph->library, mm);
        }
    }
    out.resize(static_cast<std::size_t>(c.axis_count));
    if (!out.empty() &&
        FT_Get_Var_Blend_Coordinates(face, static_cast<FT_UInt>(out.size()), out.data()) != 0)
        out.clear();
}

}  // namespace

Status render_with_freetype(Font& font, GlyphId gid, const OutlineOptions& options,
                            const MaskView& target, Vec2 origin) {
    auto& impl = font_detail::Access::impl(font);
    const FT_Face face = impl.face.get();
    const std::string& file = impl.file;
    if (!(options.size_px > 0.0 && options.size_px <= kMaxFontSizePx))
        return Error{file + ": font size " + number(options.size_px) + " px out of range (0, " +
                     number(kMaxFontSizePx) + "]"};
    if (gid >= font.glyph_count())
        return Error{file + ": glyph id " + std::to_string(gid) + " out of range (the font has " +
                     std::to_string(font.glyph_count()) + " glyphs)"};
    const std::string label = file + ": glyph " + std::to_string(gid);
    const int W = target.width, H = target.height;
    if (W < 0 || H < 0 || W > kMaxFreeTypeTargetPx || H > kMaxFreeTypeTargetPx)
        return Error{label + ": FreeType target " + std::to_string(W) + "x" + std::to_string(H) +
                     " is outside 0.." + std::to_string(kMaxFreeTypeTargetPx)};
    if (W > 0 && H > 0 && target.data == nullptr)
        return Error{label + ": FreeType target has no pixel memory (null data)"};
    if (H > 1 && (target.stride > INT_MAX || target.stride < -INT_MAX ||
                  std::abs(target.stride) < W))
        return Error{label + ": FreeType target stride " + std::to_string(target.stride) +
                     " does not hold rows of " + std::to_string(W) + " pixels"};
    if (!(std::abs(origin.x) <= kMaxFreeTypeOriginPx && std::abs(origin.y) <= kMaxFreeTypeOriginPx))
        return Error{label + ": pen position (" + number(origin.x) + ", " + number(origin.y) +
                     ") is not finite or beyond " + number(kMaxFreeTypeOriginPx) + " px"};
    if (!FT_IS_SCALABLE(face)) return Error{label + ": the font has no outlines (bitmap only)"};

    font_detail::FreeTypeRenderCache& c = impl.render_cache;
    const FT_F26Dot6 size = std::max<FT_F26Dot6>(1, std::lround(options.size_px * 64.0));
    std::vector<FT_Fixed> coords;
    current_coords(face, c, coords);
    if (!c.valid || c.gid != gid || c.size_26_6 != size || c.coords != coords) {
        c.valid = false;
        if (size != impl.char_size_26_6) {
            if (FT_Error e = FT_Set_Char_Size(face, 0, size, 72, 72)) {
                impl.char_size_26_6 = 0;
                return Error{label + ": cannot set size " + number(options.size_px) +
                             " px: " + font_detail::ft_error_text(e)};
            }
            impl.char_size_26_6 = size;
        }
        if (FT_Error e = FT_Load_Glyph(face, gid, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP))
            return Error{label + ": " + font_detail::ft_error_text(e)};
        const FT_Outline& o = face->glyph->outline;
        if (face->glyph->format != FT_GLYPH_FORMAT_OUTLINE)
            return Error{label + ": not an outline glyph"};
        const auto np = static_cast<std::size_t>(std::max(0, int(o.n_points)));
        const auto nc = static_cast<std::size_t>(std::max(0, int(o.n_contours)));
        c.loaded.assign(o.points, o.points + np);
        c.points = c.loaded;
        c.tags.assign(o.tags, o.tags + np);
        c.contours.assign(o.contours, o.contours + nc);
        c.outline_flags = o.flags;
        c.dx = c.dy = 0;
        c.gid = gid;
        c.size_26_6 = size;
        c.coords = coords;
        c.valid = true;
    }

    // Pen (x, y) in target pixels, y down; FreeType's bitmap has y up from its bottom edge, so an
    // outline point (u, v) (y up) lands at bitmap (x + u, H − y + v).
    const FT_Pos dx = std::lround(origin.x * 64.0), dy = std::lround((H - origin.y) * 64.0);
    if (dx != c.dx || dy != c.dy) {
        for (std::size_t i = 0; i < c.points.size(); ++i)
            c.points[i] = FT_Vector{c.loaded[i].x + dx, c.loaded[i].y + dy};
        c.dx = dx;
        c.dy = dy;
    }

    for (int y = 0; y < H; ++y) std::memset(target.row(y), 0, static_cast<std::size_t>(W));
    if (W == 0 || H == 0 || c.points.empty()) return ok_status();

    FT_Outline outline{};
    outline.n_points = static_cast<decltype(outline.n_points)>(c.points.size());
    outline.n_contours = static_cast<decltype(outline.n_contours)>(c.contours.size());
    outline.points = c.points.data();
    outline.tags = c.tags.data();
    outline.contours = c.contours.data();
    outline.flags = c.outline_flags;

    FT_Bitmap bm{};
    bm.rows = static_cast<unsigned>(H);
    bm.width = static_cast<unsigned>(W);
    bm.pitch = static_cast<int>(H > 1 ? target.stride : W);
    // A negative pitch is FreeType's "up flow": the buffer starts at the BOTTOM row.
    bm.buffer = bm.pitch < 0 ? target.row(H - 1) : target.data;
    bm.num_grays = 256;
    bm.pixel_mode = FT_PIXEL_MODE_GRAY;
    FT_Raster_Params params{};
    params.target = &bm;
    params.flags = FT_RASTER_FLAG_AA;
    if (FT_Error e = FT_Outline_Render(impl.library.get(), &outline, &params))
        return Error{label + ": FreeType's rasterizer failed: " + font_detail::ft_error_text(e)};
    return ok_status();
}

}  // namespace bezel
