// Font: opening faces, face-wide data, glyph lookup, outlines and glyph metrics at a size.
//
// Unhinted outlines are loaded with FT_LOAD_NO_SCALE — FreeType's outline in font units, exactly
// as the font stores it (glyf coordinates are integers; composite transforms and variation
// deltas are applied by FreeType and rounded to units) — and scaled here in double by
// size_px / units_per_em. Scaling in FreeType instead (FT_Set_Char_Size) rounds every point to
// 1/64 px, which is visible when an outline is magnified or compared across sizes.
// Hinted outlines need the size set on the face, so they come from FreeType in 26.6 pixels.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>

#include "bezel/font.hpp"
#include "font/font_impl.hpp"
#include "font/ft_error.hpp"
#include "font/outline_convert.hpp"

#include FT_FONT_FORMATS_H
#include FT_TRUETYPE_TABLES_H

namespace bezel {

using font_detail::format_number;
using font_detail::ft_error_text;

std::string font_detail::format_number(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

std::uint64_t font_detail::next_instance_id() {
    static std::atomic<std::uint64_t> counter{0};
    return ++counter;
}

Font::Font(std::shared_ptr<Impl> impl) : impl_(std::move(impl)) {}
Font::Font(Font&&) noexcept = default;
Font& Font::operator=(Font&&) noexcept = default;
Font::~Font() = default;

Expected<Font> Font::open(const std::string& file, int face_index) {
    auto face = FontFace::open(file, face_index);
    if (!face) return face.error();
    return open(*face);
}

Expected<Font> Font::open(const FontFace& source) {
    auto impl = std::make_shared<Impl>(source);
    impl->file = source.name();
    impl->face_index = source.face_index();
    impl->face_count = source.face_count();
    impl->instance_id = font_detail::next_instance_id();

    FT_Library library = nullptr;
    if (FT_Error e = FT_Init_FreeType(&library)) {
        return Error{impl->file + ": cannot start FreeType: " + ft_error_text(e)};
    }
    impl->library.reset(library);
    // The bytes were checked by FontFace; FreeType reads them in place (they outlive the face:
    // Impl holds the FontFace).
    FT_Face face = nullptr;
    if (FT_Error e = FT_New_Memory_Face(library, source.data(), static_cast<FT_Long>(source.size()),
                                        source.face_index(), &face)) {
        return Error{impl->file + ": face " + std::to_string(source.face_index()) + ": " +
                     ft_error_text(e)};
    }
    impl->face.reset(face);
    return Font(std::move(impl));
}

const FontFace& Font::face() const { return impl_->source; }
std::uint64_t Font::instance_id() const { return impl_->instance_id; }

const std::string& Font::file() const { return impl_->file; }

std::string Font::family_name() const {
    const char* s = impl_->face->family_name;
    return s != nullptr ? s : "";
}

std::string Font::style_name() const {
    const char* s = impl_->face->style_name;
    return s != nullptr ? s : "";
}

int Font::face_index() const { return impl_->face_index; }
int Font::face_count() const { return impl_->face_count; }

std::size_t Font::glyph_count() const {
    return static_cast<std::size_t>(std::max<FT_Long>(impl_->face->num_glyphs, 0));
}

bool Font::is_scalable() const { return FT_IS_SCALABLE(impl_->face.get()); }

bool Font::has_cubic_outlines() const {
    // FreeType names every PostScript-outline format: "CFF" covers OpenType CFF and CFF2 and
    // bare CFF; "Type 1" and "CID Type 1" the older ones. TrueType and Type 42 are quadratic.
    const char* name = FT_Get_Font_Format(impl_->face.get());
    const std::string format = name != nullptr ? name : "";
    return format == "CFF" || format == "Type 1" || format == "CID Type 1";
}

FontMetrics Font::metrics() const {
    const FT_Face face = impl_->face.get();
    FontMetrics m;
    m.units_per_em = face->units_per_EM;
    m.ascender = face->ascender;
    m.descender = face->descender;
    // FreeType's `height` is the baseline-to-baseline distance, ascender − descender + gap.
    m.line_gap = static_cast<double>(face->height) - (face->ascender - face->descender);
    // FreeType fills the scalable metrics only for faces with outlines: a bitmap-only sfnt
    // (colour emoji in CBDT or sbix, EBDT) reports 0 for all of them, though its head and hhea
    // tables hold the design's values. Read those, so the font's own numbers are reported.
    if (m.units_per_em == 0) {
        if (const auto* head = static_cast<const TT_Header*>(FT_Get_Sfnt_Table(face, FT_SFNT_HEAD)))
            m.units_per_em = head->Units_Per_EM;
        if (const auto* hhea = static_cast<const TT_HoriHeader*>(FT_Get_Sfnt_Table(face, FT_SFNT_HHEA))) {
            m.ascender = hhea->Ascender;
            m.descender = hhea->Descender;
            m.line_gap = hhea->Line_Gap;
        }
    }
    return m;
}

Expected<FontMetricsPx> Font::metrics_px(double size_px) const {
    if (!(size_px > 0.0 && size_px <= kMaxFontSizePx)) {  // also rejects NaN
        return Error{impl_->file + ": font size " + format_number(size_px) +
                     " px out of range (0, " + format_number(kMaxFontSizePx) + "]"};
    }
    const FontMetrics m = metrics();
    if (m.units_per_em <= 0) return Error{impl_->file + ": the font has no units per em"};
    const double k = size_px / m.units_per_em;
    FontMetricsPx px;
    px.size_px = size_px;
    px.ascent_px = m.ascender * k;
    px.descent_px = -m.descender * k;
    px.line_gap_px = m.line_gap * k;
    px.line_height_px = px.ascent_px + px.descent_px + px.line_gap_px;
    return px;
}

bool Font::has_color_bitmaps() const { return FT_HAS_COLOR(impl_->face.get()); }

Status Font::require_outlines() const {
    if (is_scalable() && impl_->face->units_per_EM != 0) return ok_status();
    if (has_color_bitmaps())
        return Error{impl_->file + ": a bitmap-only font (no outlines): its glyphs are colour "
                     "bitmaps, drawn only as colour glyphs"};
    return Error{impl_->file + ": a bitmap-only font (no outlines); monochrome bitmap fonts are "
                 "not supported"};
}

std::optional<GlyphId> Font::glyph_for_char(char32_t code_point) const {
    if (code_point > 0x10FFFF) return std::nullopt;
    const FT_UInt gid = FT_Get_Char_Index(impl_->face.get(), code_point);
    if (gid == 0) return std::nullopt;
    return GlyphId{gid};
}

std::string Font::glyph_name(GlyphId gid) const {
    const FT_Face face = impl_->face.get();
    if (gid < glyph_count() && FT_HAS_GLYPH_NAMES(face)) {
        char name[256] = {};
        if (FT_Get_Glyph_Name(face, gid, name, sizeof name) == 0 && name[0] != '\0') {
            return name;
        }
    }
    return "gid" + std::to_string(gid);
}

const char* hinting_name(Hinting hinting) {
    switch (hinting) {
        case Hinting::None: return "none";
        case Hinting::Light: return "light";
        case Hinting::Full: return "full";
        case Hinting::Auto: return "auto";
    }
    return "none";
}

namespace {

FT_Int32 hinted_load_flags(Hinting hinting) {
    switch (hinting) {
        case Hinting::Light: return FT_LOAD_TARGET_LIGHT;
        case Hinting::Auto: return FT_LOAD_FORCE_AUTOHINT;
        case Hinting::None:   // not reached: unhinted loads use FT_LOAD_NO_SCALE
        case Hinting::Full: break;
    }
    return FT_LOAD_DEFAULT;
}

}  // namespace

Expected<GlyphOutline> Font::load_glyph(GlyphId gid, const OutlineOptions& options,
                                        bool want_path) {
    const FT_Face face = impl_->face.get();
    const std::string& file = impl_->file;
    if (!(options.size_px > 0.0 && options.size_px <= kMaxFontSizePx)) {  // also rejects NaN
        return Error{file + ": font size " + format_number(options.size_px) +
                     " px out of range (0, " + format_number(kMaxFontSizePx) + "]"};
    }
    if (gid >= glyph_count()) {
        return Error{file + ": glyph id " + std::to_string(gid) + " out of range (the font has " +
                     std::to_string(glyph_count()) + " glyphs)"};
    }
    const std::string glyph_label = file + ": glyph " + std::to_string(gid);
    if (Status s = require_outlines(); !s) return s.error();

    double scale = 0.0;  // from FreeType's outline units to pixels
    if (options.hinting != Hinting::None) {
        // 72 dpi makes points and pixels the same, so the char size is the pixel size in 26.6.
        const FT_F26Dot6 size = std::max<FT_F26Dot6>(1, std::lround(options.size_px * 64.0));
        if (size != impl_->char_size_26_6) {
            if (FT_Error e = FT_Set_Char_Size(face, 0, size, 72, 72)) {
                impl_->char_size_26_6 = 0;
                return Error{glyph_label + ": cannot set size " + format_number(options.size_px) +
                             " px: " + ft_error_text(e)};
            }
            impl_->char_size_26_6 = size;
        }
        const FT_Int32 flags = hinted_load_flags(options.hinting) | FT_LOAD_NO_BITMAP;
        if (FT_Error e = FT_Load_Glyph(face, gid, flags)) {
            return Error{glyph_label + ": " + ft_error_text(e)};
        }
        scale = 1.0 / 64.0;
    } else {
        if (FT_Error e = FT_Load_Glyph(face, gid,
                                       FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP)) {
            return Error{glyph_label + ": " + ft_error_text(e)};
        }
        scale = options.size_px / face->units_per_EM;
    }
    const FT_GlyphSlot slot = face->glyph;
    if (slot->format != FT_GLYPH_FORMAT_OUTLINE) {
        return Error{glyph_label + ": not an outline glyph"};
    }

    GlyphOutline out;
    out.gid = gid;
    if (Status s = font_detail::read_ft_outline(slot->outline, scale, out.points, out.contour_ends);
        !s) {
        return Error{glyph_label + ": malformed outline: " + s.error().message};
    }
#ifdef FT_OUTLINE_OVERLAP  // FreeType ≥ 2.10.3
    out.overlapping_contours = (slot->outline.flags & FT_OUTLINE_OVERLAP) != 0;
#endif
    if (want_path) {
        if (Status s = font_detail::path_from_points(out.points, out.contour_ends, out.path); !s) {
            return Error{glyph_label + ": malformed outline: " + s.error().message};
        }
    }

    // In both load modes the slot's metrics are in the outline's units (font units or 26.6), so
    // the same scale applies.
    Rect bounds = Rect::empty();
    for (const OutlinePoint& p : out.points) bounds = bounds.union_with(p.pos);
    out.metrics.bounds_px = bounds;
    out.metrics.advance_px = static_cast<double>(slot->metrics.horiAdvance) * scale;
    out.metrics.left_bearing_px = bounds.is_empty()
                                      ? static_cast<double>(slot->metrics.horiBearingX) * scale
                                      : bounds.x0;
    return out;
}

Expected<GlyphMetrics> Font::glyph_metrics(GlyphId gid, const OutlineOptions& options) {
    Expected<GlyphOutline> loaded = load_glyph(gid, options, /*want_path=*/false);
    if (!loaded) return loaded.error();
    return loaded->metrics;
}

Expected<GlyphOutline> Font::outline(GlyphId gid, const OutlineOptions& options) {
    return load_glyph(gid, options, /*want_path=*/true);
}

}  // namespace bezel
