#include "picture.hpp"

#include <CLI/CLI.hpp>
#include <cmath>

#include "parse_check.hpp"

namespace bezel::cli {

bool PictureColours::gray() const {
    return !translucent() && ink.r == ink.g && ink.g == ink.b && paper.r == paper.g &&
           paper.g == paper.b;
}

bool PictureColours::translucent() const { return ink.a != 255 || paper.a != 255; }

void add_colour_options(CLI::App& cmd, std::string& foreground, std::string& background) {
    auto colour = parse_check([](const std::string& v) { return parse_color(v); }, "colour");
    cmd.add_option("--foreground", foreground,
                   "Ink colour of pictures: #RRGGBB, #RRGGBBAA, #RGB, #RGBA or a CSS name "
                   "(default black)")
        ->type_name("COLOR")
        ->check(colour);
    cmd.add_option("--background", background, "Paper colour of pictures (default white)")
        ->type_name("COLOR")
        ->check(colour);
}

Expected<PictureColours> picture_colours(const std::string& foreground,
                                         const std::string& background) {
    PictureColours colours;
    if (!foreground.empty()) {
        auto ink = parse_color(foreground);
        if (!ink) return Error{"--foreground: " + ink.error().message};
        colours.ink = *ink;
    }
    if (!background.empty()) {
        auto paper = parse_color(background);
        if (!paper) return Error{"--background: " + paper.error().message};
        colours.paper = *paper;
    }
    return colours;
}

namespace {

std::uint8_t mix(std::uint8_t paper, std::uint8_t ink, double amount) {
    return static_cast<std::uint8_t>(std::lround(paper + (ink - paper) * amount));
}

}  // namespace

Rgba8 paint(const PictureColours& c, double amount) {
    return {mix(c.paper.r, c.ink.r, amount), mix(c.paper.g, c.ink.g, amount),
            mix(c.paper.b, c.ink.b, amount), mix(c.paper.a, c.ink.a, amount)};
}

Rgba8 paint_rgb(const PictureColours& c, double r, double g, double b) {
    return {mix(c.paper.r, c.ink.r, r), mix(c.paper.g, c.ink.g, g), mix(c.paper.b, c.ink.b, b),
            mix(c.paper.a, c.ink.a, (r + g + b) / 3.0)};
}

Image paint_coverage(ConstMaskView coverage, const PictureColours& colours) {
    // 256 coverage values, 256 colours: painted once each.
    Rgba8 lut[256];
    for (int v = 0; v < 256; ++v) lut[v] = paint(colours, v / 255.0);
    Image out(coverage.width, coverage.height);
    for (int y = 0; y < coverage.height; ++y)
        for (int x = 0; x < coverage.width; ++x) out.at(x, y) = lut[coverage.at(x, y)];
    return out;
}

Expected<std::string> picture_png(const Image& picture, bool gray, bool alpha,
                                  const PngOptions& png_options) {
    auto png = encode_png(picture, gray ? PngColor::Gray : alpha ? PngColor::Rgba : PngColor::Rgb,
                          png_options);
    if (!png) return png.error();
    return std::string(png->begin(), png->end());
}

std::string picture_pnm(const Image& picture, bool gray) {
    const std::vector<std::uint8_t> bytes = gray ? encode_pgm(picture) : encode_ppm(picture);
    return std::string(bytes.begin(), bytes.end());
}

}  // namespace bezel::cli
