// Opening the font bytes ImGui holds (ImFontConfig::FontData) as a bezel::Font: the one place
// bezel_imgui loads fonts.
#pragma once

#include <cstddef>
#include <string>

#include "bezel/expected.hpp"
#include "bezel/font.hpp"

namespace bezel_imgui::detail {

// Face `face_index` of the `size` bytes at `data`, which stay valid and unchanged while the Font
// lives. Errors start with `name` (what messages call the font): empty data, bytes that are not a
// font, a face index out of range, each with bezel's reason.
bezel::Expected<bezel::Font> open_font_bytes(const void* data, std::size_t size, int face_index,
                                             const std::string& name);

}  // namespace bezel_imgui::detail
