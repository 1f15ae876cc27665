// Private to the font module: what a Font owns. Shared by font.cpp (opening, glyphs, outlines)
// and variations.cpp (axes).
#pragma once

#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include <ft2build.h>
#include FT_FREETYPE_H

#include "bezel/font.hpp"
#include "bezel/font_face.hpp"
#include "font/colr_table.hpp"

namespace bezel {

namespace font_detail {
struct LibraryDeleter {
    void operator()(FT_Library library) const { FT_Done_FreeType(library); }
};
struct FaceDeleter {
    void operator()(FT_Face face) const { FT_Done_Face(face); }
};
using LibraryPtr = std::unique_ptr<FT_LibraryRec_, LibraryDeleter>;
using FacePtr = std::unique_ptr<FT_FaceRec_, FaceDeleter>;

// render_with_freetype's last loaded outline (freetype_render.cpp), kept so that a timing loop
// rendering one glyph again measures FreeType's rasterizer rather than its glyph loader.
struct FreeTypeRenderCache {
    bool valid = false;
    FT_UInt gid = 0;
    FT_F26Dot6 size_26_6 = 0;
    int axis_count = -1;              // the face's variation axes, looked up once
    std::vector<FT_Fixed> coords;     // variation blend coordinates the outline was loaded at
    std::vector<FT_Vector> loaded;    // the scaled outline as loaded (26.6, y up)
    std::vector<FT_Vector> points;    // the same, translated by (dx, dy)
    FT_Pos dx = 0, dy = 0;
    std::vector<std::remove_pointer_t<decltype(FT_Outline::tags)>> tags;
    std::vector<std::remove_pointer_t<decltype(FT_Outline::contours)>> contours;
    int outline_flags = 0;
};

// A new id for Font::instance_id(), never given out before in this process.
std::uint64_t next_instance_id();

// A number in an error message ("%g": 6 significant digits, no trailing zeros).
std::string format_number(double v);

// The design coordinates of named instance `instance` (1-based, as FreeType's face index bits
// 16–30 and fontconfig's index number it) of face `face_index` of `file`: one setting per axis,
// in the font's axis order (variations.cpp). Errors name the file: it does not open, has no
// variation axes, or has fewer instances.
Expected<std::vector<VariationSetting>> named_instance_coordinates(const std::string& file,
                                                                  int face_index, int instance);
}  // namespace font_detail

struct Font::Impl {
    // Declaration order is destruction order reversed: the FreeType face goes before its library,
    // and both before the FontFace that holds the bytes they read.
    explicit Impl(FontFace f) : source(std::move(f)) {}
    FontFace source;
    font_detail::LibraryPtr library;
    font_detail::FacePtr face;
    std::string file;
    int face_index = 0;
    int face_count = 0;
    // Font::instance_id(): the id of the current variation coordinates, and the last few
    // coordinates set with theirs, so that switching back to an instance finds its id again.
    std::uint64_t instance_id = 0;
    std::vector<std::pair<std::vector<FT_Fixed>, std::uint64_t>> recent_instances;
    // The 26.6 char size last set with FT_Set_Char_Size (hinted loads only), 0 when none, so a
    // run of glyphs at one size sets it once.
    FT_F26Dot6 char_size_26_6 = 0;
    font_detail::FreeTypeRenderCache render_cache;
    // The COLR table, read and checked on first use by color_glyph.cpp (it does not change with
    // variations); `colr` null after that means the font has none, or `colr_error` says why not.
    bool colr_read = false;
    std::unique_ptr<font_detail::ColrTable> colr;
    std::string colr_error;
    // A second size object for colour bitmap strikes (FT_Select_Size), so that selecting a strike
    // leaves the face's own size — char_size_26_6, the hinted loads' — untouched. Owned by the
    // face (FT_Done_Face frees it); null until the first colour bitmap.
    FT_Size strike_size = nullptr;
};

namespace font_detail {
// A Font's Impl, for the module's free functions (render_with_freetype).
struct Access {
    static Font::Impl& impl(Font& font) { return *font.impl_; }
};
}  // namespace font_detail

}  // namespace bezel
