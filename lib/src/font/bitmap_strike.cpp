// Monochrome and gray bitmap strikes (EBLC/EBDT, bloc/bdat) through FreeType's sbit loader.
//
// A strike is selected on the face's strike size object (StrikeSizeScope), so the size hinted
// outline loads set stays; the glyph is loaded with FT_LOAD_SBITS_ONLY (never an outline in its
// place). FreeType gives 1-, 2-, 4- or 8-bit pixels (FT_PIXEL_MODE_MONO, GRAY2, GRAY4, GRAY);
// FT_Bitmap_Convert unpacks them to a byte each with values 0..num_grays − 1, and coverage is
// v · 255 / (num_grays − 1), rounded, so full ink is 255 at every depth.
#include <cmath>

#include "bezel/font.hpp"
#include "font/font_impl.hpp"
#include "font/ft_error.hpp"

#include FT_BITMAP_H
#include FT_TRUETYPE_TABLES_H
#include FT_TRUETYPE_TAGS_H

namespace bezel {

using font_detail::format_number;
using font_detail::ft_error_text;

namespace {

bool has_table(FT_Face face, FT_ULong tag) {
    FT_ULong length = 0;
    return FT_Load_Sfnt_Table(face, tag, 0, nullptr, &length) == 0 && length > 0;
}

// FT_Bitmap with its FT_Bitmap_Done.
struct ConvertedBitmap {
    FT_Library library;
    FT_Bitmap bitmap;
    explicit ConvertedBitmap(FT_Library l) : library(l) { FT_Bitmap_Init(&bitmap); }
    ConvertedBitmap(const ConvertedBitmap&) = delete;
    ConvertedBitmap& operator=(const ConvertedBitmap&) = delete;
    ~ConvertedBitmap() { FT_Bitmap_Done(library, &bitmap); }
};

}  // namespace

bool font_detail::find_gray_strikes(FT_Face face) {
    return face->num_fixed_sizes > 0 &&
           (has_table(face, TTAG_EBLC) || has_table(face, FT_MAKE_TAG('b', 'l', 'o', 'c')));
}

bool Font::has_bitmap_strikes() const { return impl_->gray_strikes; }

Expected<std::optional<StrikeBitmap>> Font::strike_bitmap(GlyphId gid, double size_px) {
    Impl& impl = *impl_;
    const std::string& file = impl.file;
    if (!(size_px > 0.0 && size_px <= kMaxFontSizePx)) {  // also rejects NaN
        return Error{file + ": font size " + format_number(size_px) + " px out of range (0, " +
                     format_number(kMaxFontSizePx) + "]"};
    }
    if (gid >= glyph_count()) {
        return Error{file + ": glyph id " + std::to_string(gid) + " out of range (the font has " +
                     std::to_string(glyph_count()) + " glyphs)"};
    }
    if (!impl.gray_strikes) return std::optional<StrikeBitmap>();
    const FT_Face face = impl.face.get();
    const FT_Pos wanted = std::lround(size_px * 64.0);
    int strike = -1;
    for (int i = 0; i < face->num_fixed_sizes; ++i)
        if (face->available_sizes[i].y_ppem == wanted) strike = i;
    if (strike < 0) return std::optional<StrikeBitmap>();

    const std::string label = file + ": glyph " + std::to_string(gid);
    font_detail::StrikeSizeScope scope(impl);
    if (!scope.ok()) return Error{label + ": cannot make a size object for the bitmap strikes"};
    if (FT_Error e = FT_Select_Size(face, strike))
        return Error{label + ": cannot select the bitmap strike: " + ft_error_text(e)};
    // A glyph the strike has no image of fails to load with SBITS_ONLY: drawn from its outline.
    if (FT_Load_Glyph(face, gid, FT_LOAD_SBITS_ONLY) != 0) return std::optional<StrikeBitmap>();
    const FT_GlyphSlot slot = face->glyph;
    if (slot->format != FT_GLYPH_FORMAT_BITMAP) return std::optional<StrikeBitmap>();
    const FT_Bitmap& src = slot->bitmap;
    int bit_depth = 0;
    switch (src.pixel_mode) {
        case FT_PIXEL_MODE_MONO: bit_depth = 1; break;
        case FT_PIXEL_MODE_GRAY2: bit_depth = 2; break;
        case FT_PIXEL_MODE_GRAY4: bit_depth = 4; break;
        case FT_PIXEL_MODE_GRAY: bit_depth = 8; break;
        default:   // BGRA: a colour strike, color_glyph.hpp's
            return std::optional<StrikeBitmap>();
    }
    if (src.width > static_cast<unsigned>(kMaxBitmapDim) ||
        src.rows > static_cast<unsigned>(kMaxBitmapDim))
        return Error{label + ": its " + std::to_string(src.width) + "x" +
                     std::to_string(src.rows) + " strike image is larger than the " +
                     std::to_string(kMaxBitmapDim) + " px a side bitmaps may have"};
    ConvertedBitmap bytes(impl.library.get());
    if (FT_Error e = FT_Bitmap_Convert(impl.library.get(), &src, &bytes.bitmap, 1))
        return Error{label + ": bitmap strike: " + ft_error_text(e)};
    const unsigned levels = bit_depth == 8 ? 256 : 1u << bit_depth;
    StrikeBitmap out;
    out.width = static_cast<int>(bytes.bitmap.width);
    out.height = static_cast<int>(bytes.bitmap.rows);
    out.left = slot->bitmap_left;
    out.top = slot->bitmap_top;
    out.ppem = static_cast<int>(face->available_sizes[strike].y_ppem / 64);
    out.bit_depth = bit_depth;
    out.advance_px = static_cast<double>(slot->advance.x) / 64.0;
    out.coverage.resize(static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height));
    for (int y = 0; y < out.height; ++y) {
        const unsigned char* row =
            bytes.bitmap.buffer + static_cast<std::ptrdiff_t>(y) * bytes.bitmap.pitch;
        for (int x = 0; x < out.width; ++x) {
            const unsigned v = row[x];
            out.coverage[static_cast<std::size_t>(y) * out.width + x] =
                static_cast<std::uint8_t>((v * 255 + (levels - 1) / 2) / (levels - 1));
        }
    }
    return std::optional<StrikeBitmap>(std::move(out));
}

}  // namespace bezel
