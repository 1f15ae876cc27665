// Private: the paint graph's children and the validating walk shared by validate(),
// paint_bounds() and the painter.
#pragma once

#include <cstdint>
#include <vector>

#include "bezel/paint.hpp"

namespace bezel::paint_detail {

// validate() with its scratch supplied (one flag per node: "on the current path"), so a warm
// Painter validates without allocating. `on_path` is resized to the node count and left all
// false.
Status validate(const ColorGlyph& glyph, std::vector<std::uint8_t>& on_path);

}  // namespace bezel::paint_detail
