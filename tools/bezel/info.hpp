// tools/bezel/info.hpp — `bezel info`'s two output forms of bezel::FontInfo.
#pragma once

#include <string>

#include "bezel/text.hpp"

namespace bezel::cli {

// Aligned "key  value" lines, then the table directory.
std::string format_info_text(const FontInfo& info);
// The JSON contract (see info_format.cpp), one object, keys in a fixed order.
std::string format_info_json(const FontInfo& info);

}  // namespace bezel::cli
