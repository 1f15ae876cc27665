// tools/bezel/picture.hpp — the one convention for the pictures bezel's commands write (fill,
// glyph, stroke, smooth, intersect; render and surface draw their own, in the same colours):
// ink on paper, black on white unless --foreground / --background say otherwise. Raw coverage
// (255 = covered) is a separate, named output (--coverage), not a picture.
//
// A pixel covered by the amount a (0..1) is paper + (ink − paper)·a per channel, alpha too, in
// sRGB bytes: black on white is exactly 255 − coverage, so the picture keeps the coverage
// losslessly. (render blends text in linear light instead, as compositing needs.)
#pragma once

#include <cstdint>
#include <string>

#include "bezel/expected.hpp"
#include "bezel/image.hpp"

namespace CLI { class App; }

namespace bezel::cli {

struct PictureColours {
    Rgba8 ink{0, 0, 0, 255};
    Rgba8 paper{255, 255, 255, 255};
    // Both opaque grays: the picture is one byte per pixel (gray PNG, PGM).
    bool gray() const;
    // Either translucent: the picture needs alpha (RGBA PNG).
    bool translucent() const;
};

// Registers --foreground (ink) and --background (paper) on `cmd`, storing the text into the
// given strings (which must outlive parsing); malformed colours are usage errors at parsing,
// named by CLI11 ("--foreground: colour 'yelow': not a CSS colour name ...").
void add_colour_options(CLI::App& cmd, std::string& foreground, std::string& background);
// The parsed colours (checked at parsing already; the error names the option).
Expected<PictureColours> picture_colours(const std::string& foreground, const std::string& background);

// One pixel: `paper` inked by `amount` (0..1) of `ink`, each channel rounded to a byte.
Rgba8 paint(const PictureColours& colours, double amount);
// The same with one amount per colour channel (LCD subpixel coverage); alpha follows their mean.
Rgba8 paint_rgb(const PictureColours& colours, double r, double g, double b);

// `coverage` (0..255 per pixel) painted in `colours`.
Image paint_coverage(ConstMaskView coverage, const PictureColours& colours);

// A painted picture as PNG: gray when `gray` (every pixel has r = g = b and opaque), RGBA when
// `alpha`, RGB otherwise.
Expected<std::string> picture_png(const Image& picture, bool gray, bool alpha,
                                  const PngOptions& png);
// As binary PGM when `gray`, else PPM (alpha dropped: PNM has none).
std::string picture_pnm(const Image& picture, bool gray);

}  // namespace bezel::cli
