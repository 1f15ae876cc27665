// Internal: layout_text for the vertical directions (TopToBottom, BottomToTop), in columns.
#pragma once

#include <string_view>
#include <vector>

#include "bezel/layout.hpp"
#include "text/layout_fonts.hpp"
#include "text/script_runs.hpp"

namespace bezel::text_detail {

// layout_text once `layout`'s lengths are checked and the text decoded into `cps` (one entry per
// code point of `utf8`) and the first font's options checked; shape.direction is TopToBottom or
// BottomToTop. The rules are layout_text's (bezel/layout.hpp).
Expected<TextLayout> layout_vertical(LayoutFonts& fonts, std::string_view utf8,
                                     const std::vector<CodePoint>& cps, const ShapeOptions& shape,
                                     const LayoutOptions& layout);

}  // namespace bezel::text_detail
