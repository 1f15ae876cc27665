// The CSS named colours (css_colours.cpp), the one table parse_color reads names from.
#pragma once

#include <optional>
#include <string_view>

#include "bezel/image.hpp"

namespace bezel::image_detail {

struct NamedColour {
    std::string_view name;  // lower case
    Rgba8 colour;
};

// The colour a CSS name stands for ("rebeccapurple", "transparent"); the name must already be
// lower case. nullopt for a name CSS does not define.
std::optional<Rgba8> css_colour(std::string_view lower_case_name);

}  // namespace bezel::image_detail
