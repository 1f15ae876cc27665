// bezel/color_glyph.hpp: which colour tables a face has, its CPAL palettes (FreeType's palette
// API), COLR paint graphs (read by colr_table.cpp / colr_paint.cpp, outlines loaded here), and
// CBDT/sbix bitmaps (FreeType's FT_LOAD_COLOR).
#include "bezel/color_glyph.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>

#include "font/colr_table.hpp"
#include "font/font_impl.hpp"
#include "font/ft_error.hpp"
#include "font/outline_convert.hpp"

#include FT_ADVANCES_H
#include FT_COLOR_H
#include FT_SIZES_H
#include FT_TRUETYPE_TABLES_H
#include FT_TRUETYPE_TAGS_H

namespace bezel {

using font_detail::ft_error_text;

namespace {

// Font::Impl, reached through font_detail::Access (its name is private to Font).
using FontImpl = std::remove_reference_t<decltype(font_detail::Access::impl(std::declval<Font&>()))>;

constexpr FT_ULong kTagSvg = FT_MAKE_TAG('S', 'V', 'G', ' ');

bool has_table(FT_Face face, FT_ULong tag) {
    FT_ULong length = 0;
    return FT_Load_Sfnt_Table(face, tag, 0, nullptr, &length) == 0 && length > 0;
}

// `length` bytes of table `tag` from `offset`; empty when the table or the range is missing.
std::vector<std::uint8_t> read_table(FT_Face face, FT_ULong tag, FT_Long offset, FT_ULong length) {
    std::vector<std::uint8_t> bytes(length);
    if (length == 0 || FT_Load_Sfnt_Table(face, tag, offset, bytes.data(), &length) != 0) return {};
    return bytes;
}

// "glyph 12 (name)"
std::string glyph_name_label(const Font& font, GlyphId gid) {
    return "glyph " + std::to_string(gid) + " (" + font.glyph_name(gid) + ")";
}
std::string glyph_label(const Font& font, GlyphId gid) {
    return font.file() + ": " + glyph_name_label(font, gid);
}

// The face's COLR table, read once; null when it has none or it is damaged (then `error` says so).
const font_detail::ColrTable* colr_table(FontImpl& impl, std::string* error = nullptr) {
    if (!impl.colr_read) {
        impl.colr_read = true;
        const FT_Face face = impl.face.get();
        FT_ULong length = 0;
        if (FT_Load_Sfnt_Table(face, TTAG_COLR, 0, nullptr, &length) == 0 && length > 0) {
            Expected<font_detail::ColrTable> t =
                font_detail::ColrTable::parse(read_table(face, TTAG_COLR, 0, length));
            if (t)
                impl.colr = std::make_unique<font_detail::ColrTable>(std::move(*t));
            else
                impl.colr_error = t.error().message;
        }
    }
    if (error != nullptr) *error = impl.colr_error;
    return impl.colr.get();
}

// Whether the 'SVG ' table's document index lists `gid` (OpenType 'SVG ': version, Offset32 to
// the SVGDocumentList; the list: numEntries, then records of startGlyphID, endGlyphID,
// Offset32, uint32 length, sorted by glyph).
bool svg_has_glyph(FT_Face face, GlyphId gid) {
    const std::vector<std::uint8_t> header = read_table(face, kTagSvg, 0, 6);
    if (header.size() != 6) return false;
    const std::uint32_t list = font_detail::read_u32(header, 2);
    const std::vector<std::uint8_t> count = read_table(face, kTagSvg, static_cast<FT_Long>(list), 2);
    if (count.size() != 2) return false;
    const std::uint32_t n = font_detail::read_u16(count, 0);
    const std::vector<std::uint8_t> records =
        read_table(face, kTagSvg, static_cast<FT_Long>(list) + 2, 12 * n);
    if (records.size() != 12u * n) return false;
    for (std::uint32_t i = 0; i < n; ++i) {
        if (font_detail::read_u16(records, 12 * i) <= gid &&
            gid <= font_detail::read_u16(records, 12 * i + 2))
            return true;
    }
    return false;
}

bool has_bitmap_tables(FT_Face face) {
    return face->num_fixed_sizes > 0 && (has_table(face, TTAG_CBDT) || has_table(face, TTAG_sbix));
}

// Strike images are loaded with these flags: colour (BGRA), and never an outline instead.
constexpr FT_Int32 kStrikeLoad = FT_LOAD_COLOR | FT_LOAD_SBITS_ONLY;

// Whether the selected strike holds a colour image for `gid`: FreeType reads the image's header
// only (FT_LOAD_BITMAP_METRICS_ONLY; a PNG's IHDR, no pixels decoded). A glyph the strike has no
// image for loads as an empty 0×0 bitmap. Precondition: a StrikeSizeScope, a strike selected.
bool strike_has_image(FT_Face face, GlyphId gid) {
    if (FT_Load_Glyph(face, gid, kStrikeLoad | FT_LOAD_BITMAP_METRICS_ONLY) != 0) return false;
    const FT_GlyphSlot slot = face->glyph;
    return slot->format == FT_GLYPH_FORMAT_BITMAP && slot->bitmap.pixel_mode == FT_PIXEL_MODE_BGRA &&
           slot->bitmap.width > 0 && slot->bitmap.rows > 0;
}

// CPAL version 1's palette type flags, one per palette (none for version 0 or without the
// array), read from the table: FreeType 2.12.1's FT_Palette_Data.palette_flags reads them as 0.
// Layout: version, numPaletteEntries, numPalettes, numColorRecords (uint16 each), Offset32
// colorRecordsArray, uint16 colorRecordIndices[numPalettes], then Offset32 paletteTypesArray.
std::vector<std::uint32_t> cpal_palette_types(FT_Face face) {
    const std::vector<std::uint8_t> header = read_table(face, TTAG_CPAL, 0, 12);
    if (header.size() != 12 || font_detail::read_u16(header, 0) < 1) return {};
    const std::uint32_t n = font_detail::read_u16(header, 4);
    const std::vector<std::uint8_t> offset =
        read_table(face, TTAG_CPAL, 12 + 2 * static_cast<FT_Long>(n), 4);
    if (offset.size() != 4 || font_detail::read_u32(offset, 0) == 0) return {};
    const std::vector<std::uint8_t> types =
        read_table(face, TTAG_CPAL, static_cast<FT_Long>(font_detail::read_u32(offset, 0)), 4 * n);
    if (types.size() != 4u * n) return {};
    std::vector<std::uint32_t> out(n);
    for (std::uint32_t i = 0; i < n; ++i) out[i] = font_detail::read_u32(types, 4 * i);
    return out;
}

ColorF straight(Rgba8 c) { return {c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, c.a / 255.0f}; }

}  // namespace

const char* color_format_name(ColorFormat format) {
    switch (format) {
        case ColorFormat::None: return "none";
        case ColorFormat::ColrV1: return "COLRv1";
        case ColorFormat::ColrV0: return "COLRv0";
        case ColorFormat::Bitmap: return "bitmap";
        case ColorFormat::Svg: return "SVG";
    }
    return "none";
}

ColorTables color_tables(Font& font) {
    auto& impl = font_detail::Access::impl(font);
    const FT_Face face = impl.face.get();
    ColorTables t;
    if (const font_detail::ColrTable* colr = colr_table(impl)) {
        t.colr_v0 = colr->has_v0_glyphs();
        t.colr_v1 = colr->has_v1_glyphs();
    }
    t.cpal = has_table(face, TTAG_CPAL);
    t.cbdt = has_table(face, TTAG_CBDT) && face->num_fixed_sizes > 0;
    t.sbix = has_table(face, TTAG_sbix) && face->num_fixed_sizes > 0;
    t.svg = has_table(face, kTagSvg);
    return t;
}

ColorFormat color_format(Font& font, GlyphId gid) {
    auto& impl = font_detail::Access::impl(font);
    const FT_Face face = impl.face.get();
    if (gid >= font.glyph_count()) return ColorFormat::None;
    if (const font_detail::ColrTable* colr = colr_table(impl)) {
        if (colr->v1_root(gid)) return ColorFormat::ColrV1;
        if (colr->v0_layers(gid)) return ColorFormat::ColrV0;
    }
    if (has_bitmap_tables(face)) {
        font_detail::StrikeSizeScope scope(impl);
        if (scope.ok()) {
            for (int i = 0; i < face->num_fixed_sizes; ++i)
                if (FT_Select_Size(face, i) == 0 && strike_has_image(face, gid))
                    return ColorFormat::Bitmap;
        }
    }
    if (has_table(face, kTagSvg) && svg_has_glyph(face, gid)) return ColorFormat::Svg;
    return ColorFormat::None;
}

std::vector<Palette> palettes(Font& font) {
    const FT_Face face = font_detail::Access::impl(font).face.get();
    std::vector<Palette> out;
    FT_Palette_Data data{};
    if (FT_Palette_Data_Get(face, &data) != 0) return out;
    const std::vector<std::uint32_t> types = cpal_palette_types(face);
    for (FT_UShort i = 0; i < data.num_palettes; ++i) {
        FT_Color* colors = nullptr;
        if (FT_Palette_Select(face, i, &colors) != 0 || colors == nullptr) break;
        Palette p;
        p.entries.reserve(data.num_palette_entries);
        for (FT_UShort e = 0; e < data.num_palette_entries; ++e)
            p.entries.push_back({colors[e].red, colors[e].green, colors[e].blue, colors[e].alpha});
        if (i < types.size()) {
            p.for_light_background = (types[i] & FT_PALETTE_FOR_LIGHT_BACKGROUND) != 0;
            p.for_dark_background = (types[i] & FT_PALETTE_FOR_DARK_BACKGROUND) != 0;
        }
        out.push_back(std::move(p));
    }
    return out;
}

Expected<ColorGlyph> load_color_glyph(Font& font, GlyphId gid, const ColorGlyphOptions& options) {
    auto& impl = font_detail::Access::impl(font);
    const FT_Face face = impl.face.get();
    if (gid >= font.glyph_count())
        return Error{font.file() + ": glyph id " + std::to_string(gid) + " out of range (the font has " +
                     std::to_string(font.glyph_count()) + " glyphs)"};
    std::string damaged;
    const font_detail::ColrTable* colr = colr_table(impl, &damaged);
    if (colr == nullptr) {
        if (!damaged.empty()) return Error{glyph_label(font, gid) + ": " + damaged};
        return Error{glyph_label(font, gid) + ": no COLR data (the font has no COLR table)"};
    }
    const bool v1 = colr->v1_root(gid).has_value();
    if (!v1 && !colr->v0_layers(gid))
        return Error{glyph_label(font, gid) + ": no COLR data for this glyph"};

    // The palette: CPAL's entries, custom ones applied. A font without CPAL has one empty palette
    // (only the foreground colour, index 0xFFFF, can be used).
    const std::vector<Palette> all = palettes(font);
    const int count = std::max<int>(1, static_cast<int>(all.size()));
    if (options.palette < 0 || options.palette >= count)
        return Error{glyph_label(font, gid) + ": palette " + std::to_string(options.palette) +
                     " out of range (the font has " + std::to_string(all.size()) + " palettes)"};
    font_detail::ColrContext context;
    if (!all.empty())
        for (Rgba8 c : all[static_cast<std::size_t>(options.palette)].entries)
            context.palette.push_back(straight(c));
    for (const ColorGlyphOptions::Entry& e : options.custom) {
        if (e.index < 0 || static_cast<std::size_t>(e.index) >= context.palette.size())
            return Error{glyph_label(font, gid) + ": custom palette entry " + std::to_string(e.index) +
                         " out of range (the palette has " + std::to_string(context.palette.size()) +
                         " entries)"};
        context.palette[static_cast<std::size_t>(e.index)] = straight(e.color);
    }
    context.glyph_count = font.glyph_count();
    context.file = font.file();
    context.glyph_label = [&font](GlyphId g) { return glyph_name_label(font, g); };
    // Outlines in font units exactly as the font stores them (FT_LOAD_NO_SCALE), y up.
    context.load_outline = [face](GlyphId g) -> Expected<Path> {
        if (FT_Error e =
                FT_Load_Glyph(face, g, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP))
            return Error{ft_error_text(e)};
        if (face->glyph->format != FT_GLYPH_FORMAT_OUTLINE) return Error{"not an outline glyph"};
        std::vector<OutlinePoint> points;
        std::vector<std::size_t> ends;
        // read_ft_outline flips to y down; flip back, so the path is in the COLR's y-up space.
        if (Status s = font_detail::read_ft_outline(face->glyph->outline, 1.0, points, ends); !s)
            return Error{"malformed outline: " + s.error().message};
        for (OutlinePoint& p : points) p.pos.y = -p.pos.y;
        Path path;
        if (Status s = font_detail::path_from_points(points, ends, path); !s)
            return Error{"malformed outline: " + s.error().message};
        return path;
    };
    return v1 ? font_detail::build_colr_v1(*colr, gid, context)
              : font_detail::build_colr_v0(*colr, gid, context);
}

Expected<ColorBitmap> load_color_bitmap(Font& font, GlyphId gid, double size_px) {
    auto& impl = font_detail::Access::impl(font);
    const FT_Face face = impl.face.get();
    if (!(size_px > 0.0 && size_px <= kMaxFontSizePx))
        return Error{font.file() + ": font size " + font_detail::format_number(size_px) +
                     " px out of range (0, " + font_detail::format_number(kMaxFontSizePx) + "]"};
    if (gid >= font.glyph_count())
        return Error{font.file() + ": glyph id " + std::to_string(gid) + " out of range (the font has " +
                     std::to_string(font.glyph_count()) + " glyphs)"};
    const std::string label = glyph_label(font, gid);
    if (!has_bitmap_tables(face))
        return Error{label + ": no colour bitmap (the font has no CBDT or sbix strikes)"};

    // The smallest strike at least as large as the size, else the largest.
    int strike = -1, largest = 0;
    for (int i = 0; i < face->num_fixed_sizes; ++i) {
        const double px = face->available_sizes[i].y_ppem / 64.0;
        if (px > face->available_sizes[largest].y_ppem / 64.0) largest = i;
        if (px >= size_px && (strike < 0 || px < face->available_sizes[strike].y_ppem / 64.0))
            strike = i;
    }
    if (strike < 0) strike = largest;
    if (!(face->available_sizes[strike].y_ppem > 0))
        return Error{label + ": the font's bitmap strike " + std::to_string(strike) +
                     " has no pixel size"};

    font_detail::StrikeSizeScope scope(impl);
    if (!scope.ok()) return Error{label + ": cannot make a size object for the bitmap strikes"};
    if (FT_Error e = FT_Select_Size(face, strike))
        return Error{label + ": cannot select the bitmap strike: " + ft_error_text(e)};
    // The image's size from its header before FreeType decodes it, so an image past
    // kMaxColorBitmapBytes is refused undecoded.
    if (FT_Error e = FT_Load_Glyph(face, gid, kStrikeLoad | FT_LOAD_BITMAP_METRICS_ONLY))
        return Error{label + ": colour bitmap: " + ft_error_text(e)};
    auto too_large = [&](std::uint64_t w, std::uint64_t h) -> std::optional<Error> {
        if (w * h * 4 <= kMaxColorBitmapBytes) return std::nullopt;
        return Error{label + ": colour bitmap " + std::to_string(w) + "x" + std::to_string(h) +
                     " is larger than " + std::to_string(kMaxColorBitmapBytes >> 20) + " MiB of RGBA"};
    };
    if (auto e = too_large(face->glyph->bitmap.width, face->glyph->bitmap.rows)) return *e;
    if (FT_Error e = FT_Load_Glyph(face, gid, kStrikeLoad))
        return Error{label + ": colour bitmap: " + ft_error_text(e)};
    const FT_GlyphSlot slot = face->glyph;
    const FT_Bitmap& bm = slot->bitmap;
    if (auto e = too_large(bm.width, bm.rows)) return *e;
    const bool empty = bm.width == 0 || bm.rows == 0;
    if (slot->format != FT_GLYPH_FORMAT_BITMAP || (!empty && bm.pixel_mode != FT_PIXEL_MODE_BGRA))
        return Error{label + ": the strike's image is not a colour (BGRA) bitmap"};

    ColorBitmap out;
    out.width = static_cast<int>(bm.width);
    out.height = static_cast<int>(bm.rows);
    out.strike_px = face->available_sizes[strike].y_ppem / 64.0;
    out.left = slot->bitmap_left;
    out.top = slot->bitmap_top;
    // CBDT states the advance at the strike in whole pixels (its glyph metrics); sbix has none of
    // its own, and FreeType truncates hmtx's to whole pixels, so it is scaled here exactly.
    out.advance_px = slot->advance.x / 64.0;
    FT_Fixed design_advance = 0;
    const int upem = font.metrics().units_per_em;
    if (has_table(face, TTAG_sbix) && upem > 0 &&
        FT_Get_Advance(face, gid, FT_LOAD_NO_SCALE, &design_advance) == 0)
        out.advance_px = static_cast<double>(design_advance) * out.strike_px / upem;
    if (empty) {
        out.width = out.height = 0;
        return out;
    }
    out.rgba.resize(std::size_t{bm.width} * bm.rows * 4);
    // FreeType's BGRA is premultiplied, as bezel's RGBA: only the byte order changes. A negative
    // pitch means the buffer starts at the bottom row.
    for (unsigned y = 0; y < bm.rows; ++y) {
        const std::uint8_t* src = bm.pitch >= 0
                                      ? bm.buffer + std::ptrdiff_t{bm.pitch} * y
                                      : bm.buffer + std::ptrdiff_t{-bm.pitch} * (bm.rows - 1 - y);
        std::uint8_t* dst = out.rgba.data() + std::size_t{y} * bm.width * 4;
        for (unsigned x = 0; x < bm.width; ++x) {
            dst[4 * x + 0] = src[4 * x + 2];
            dst[4 * x + 1] = src[4 * x + 1];
            dst[4 * x + 2] = src[4 * x + 0];
            dst[4 * x + 3] = src[4 * x + 3];
        }
    }
    return out;
}

}  // namespace bezel
