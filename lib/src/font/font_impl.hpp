// Private to the font module: what a Font owns. Shared by font.cpp (opening, glyphs, outlines)
// and variations.cpp (axes).
#pragma once

#include <memory>
#include <string>

#include <ft2build.h>
#include FT_FREETYPE_H

#include "bezel/font.hpp"

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
}  // namespace font_detail

struct Font::Impl {
    // Declaration order is destruction order reversed: the face goes before its library.
    font_detail::LibraryPtr library;
    font_detail::FacePtr face;
    std::string file;
    int face_index = 0;
    int face_count = 0;
    // The 26.6 char size last set with FT_Set_Char_Size (hinted loads only), 0 when none, so a
    // run of glyphs at one size sets it once.
    FT_F26Dot6 char_size_26_6 = 0;
};

}  // namespace bezel
