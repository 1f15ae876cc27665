// A terminal preview of an image: 24-bit colour escapes and upper half blocks.
//
// Each character cell shows two image pixels stacked (U+2580 "▀": foreground = upper pixel,
// background = lower), which makes cells roughly square on a terminal whose cells are twice as
// tall as wide. To fit `max_columns`, the image is reduced by the integer factor
// f = ceil(width / max_columns), each output pixel the mean of an f × f box computed in LINEAR
// light (averaging sRGB bytes would darken anti-aliased text). Translucent pixels are shown
// composited over white, the paper colour of the renderer's defaults.
#include <algorithm>
#include <cstdio>
#include <string>

#include "bezel/image.hpp"
#include "image/srgb.hpp"

namespace bezel {

namespace {

// The box [x0, x0 + f) × [y0, y0 + f) of `image`, clipped, averaged in linear light over white.
Rgba8 box_mean(const Image& image, int x0, int y0, int f) {
    const SrgbTables& t = srgb_tables();
    float sum[3] = {0, 0, 0};
    int n = 0;
    for (int y = y0; y < std::min(y0 + f, image.height()); ++y) {
        for (int x = x0; x < std::min(x0 + f, image.width()); ++x) {
            Rgba8 p = image.at(x, y);
            float a = p.a / 255.0f;
            sum[0] += t.decode[p.r] * a + (1 - a);
            sum[1] += t.decode[p.g] * a + (1 - a);
            sum[2] += t.decode[p.b] * a + (1 - a);
            ++n;
        }
    }
    return Rgba8{t.enc(sum[0] / n), t.enc(sum[1] / n), t.enc(sum[2] / n), 255};
}

void append_color(std::string& out, int sgr, Rgba8 c) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "\x1b[%d;2;%d;%d;%dm", sgr, c.r, c.g, c.b);
    out += buf;
}

}  // namespace

std::string encode_ansi(const Image& image, int max_columns) {
    std::string out;
    if (image.width() <= 0 || image.height() <= 0) return out;
    int f = 1;
    if (max_columns > 0 && image.width() > max_columns)
        f = (image.width() + max_columns - 1) / max_columns;
    const int cols = (image.width() + f - 1) / f;
    const int rows = (image.height() + f - 1) / f;
    for (int r = 0; r < rows; r += 2) {
        bool have_fg = false, have_bg = false;
        Rgba8 fg{}, bg{};
        for (int c = 0; c < cols; ++c) {
            Rgba8 upper = box_mean(image, c * f, r * f, f);
            if (!have_fg || upper != fg) append_color(out, 38, upper);
            fg = upper;
            have_fg = true;
            if (r + 1 < rows) {
                Rgba8 lower = box_mean(image, c * f, (r + 1) * f, f);
                if (!have_bg || lower != bg) append_color(out, 48, lower);
                bg = lower;
                have_bg = true;
            }
            out += "\xe2\x96\x80";  // U+2580 UPPER HALF BLOCK
        }
        out += "\x1b[0m\n";
    }
    return out;
}

}  // namespace bezel
