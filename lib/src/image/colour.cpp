// Colours in hb-view's syntax and the owning RGBA8 image.
#include <algorithm>
#include <cctype>
#include <cstring>
#include <string>

#include "bezel/image.hpp"
#include "image/css_colours.hpp"

namespace bezel {

namespace {

int hex_digit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

}  // namespace

Expected<Rgba8> parse_color(std::string_view text) {
    std::string lower(text);
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (auto named = image_detail::css_colour(lower)) return *named;

    const std::string quoted = "colour '" + std::string(text) + "'";
    std::string_view hex = text;
    bool hash = !hex.empty() && hex.front() == '#';
    if (hash) hex.remove_prefix(1);
    const char* const expected = "expected #RRGGBB, #RRGGBBAA, #RGB, #RGBA or a CSS colour name";
    // A word without '#' that is not all hex digits was meant as a name ("yelow").
    if (!hash && std::any_of(hex.begin(), hex.end(), [](char c) { return hex_digit(c) < 0; }))
        return Error{quoted + ": not a CSS colour name (" + expected + ")"};
    int digits[8];
    for (std::size_t i = 0; i < hex.size() && i < 8; ++i) {
        digits[i] = hex_digit(hex[i]);
        if (digits[i] < 0)
            return Error{quoted + ": '" + std::string(1, hex[i]) +
                         "' is not a hex digit (" + expected + ")"};
    }
    // The short forms need the '#': "abc" alone reads more like a typo than a colour.
    bool short_form = hash && (hex.size() == 3 || hex.size() == 4);
    if (!short_form && hex.size() != 6 && hex.size() != 8)
        return Error{quoted + ": " + expected};
    std::uint8_t channel[4] = {0, 0, 0, 255};
    std::size_t count = short_form ? hex.size() : hex.size() / 2;
    for (std::size_t i = 0; i < count; ++i) {
        // #RGB repeats each digit: #F80 is #FF8800.
        int v = short_form ? digits[i] * 17 : digits[2 * i] * 16 + digits[2 * i + 1];
        channel[i] = static_cast<std::uint8_t>(v);
    }
    return Rgba8{channel[0], channel[1], channel[2], channel[3]};
}

Image::Image(int width, int height, Rgba8 fill)
    : width_(width), height_(height),
      pixels_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), fill) {}

bool Image::operator==(const Image& o) const {
    return width_ == o.width_ && height_ == o.height_ &&
           (pixels_.empty() ||
            std::memcmp(pixels_.data(), o.pixels_.data(), pixels_.size() * sizeof(Rgba8)) == 0);
}

}  // namespace bezel
