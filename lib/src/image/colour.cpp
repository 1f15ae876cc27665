// Colours in hb-view's syntax and the owning RGBA8 image.
#include <algorithm>
#include <cctype>
#include <cstring>
#include <string>

#include "bezel/image.hpp"

namespace bezel {

namespace {

int hex_digit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

struct NamedColor {
    const char* name;
    Rgba8 color;
};
// CSS's values for the few names accepted (CSS "green" is #008000, not #00FF00).
constexpr NamedColor kNamedColors[] = {
    {"black", {0, 0, 0, 255}},       {"white", {255, 255, 255, 255}},
    {"red", {255, 0, 0, 255}},       {"green", {0, 128, 0, 255}},
    {"blue", {0, 0, 255, 255}},      {"transparent", {0, 0, 0, 0}},
};

}  // namespace

Expected<Rgba8> parse_color(std::string_view text) {
    std::string lower(text);
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (const NamedColor& n : kNamedColors)
        if (lower == n.name) return n.color;

    const std::string quoted = "colour '" + std::string(text) + "'";
    std::string_view hex = text;
    bool hash = !hex.empty() && hex.front() == '#';
    if (hash) hex.remove_prefix(1);
    int digits[8];
    for (std::size_t i = 0; i < hex.size() && i < 8; ++i) {
        digits[i] = hex_digit(hex[i]);
        if (digits[i] < 0)
            return Error{quoted + ": '" + std::string(1, hex[i]) +
                         "' is not a hex digit (expected #RRGGBB, #RRGGBBAA, #RGB, #RGBA or a name)"};
    }
    // The short forms need the '#': "abc" alone reads more like a typo than a colour.
    bool short_form = hash && (hex.size() == 3 || hex.size() == 4);
    if (!short_form && hex.size() != 6 && hex.size() != 8)
        return Error{quoted + ": expected #RRGGBB, #RRGGBBAA, #RGB, #RGBA or a colour name"};
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
