#include "font_source.hpp"

#include "bezel/font_face.hpp"

namespace bezel_imgui::detail {

// The bytes are borrowed, not copied: ImGui keeps ImFontConfig::FontData until the atlas is
// cleared, which is after every Font of a build is gone (they live inside Build()).
bezel::Expected<bezel::Font> open_font_bytes(const void* data, std::size_t size, int face_index,
                                             const std::string& name) {
    bezel::FontMemoryOptions options;
    options.face_index = face_index;
    options.name = name;
    auto face = bezel::FontFace::from_memory(data, size, options);
    if (!face) return face.error();
    return bezel::Font::open(*face);
}

}  // namespace bezel_imgui::detail
