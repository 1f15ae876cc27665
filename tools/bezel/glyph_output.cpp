// `bezel glyph`'s output formats: ASCII art, the JSON contract, and one picture (PNG, PGM/PPM)
// of all glyphs side by side.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>

#include "bezel/image.hpp"
#include "cli_common.hpp"
#include "glyph_bitmap.hpp"

namespace bezel::cli {

namespace {

std::string char_label(const GlyphBitmap& g) {
    if (!g.code_point) return "";
    std::string utf8;
    append_utf8(utf8, *g.code_point);
    // Control and space characters print as their code point only.
    if (*g.code_point <= 0x20 || *g.code_point == 0x7F) return " " + format_code_point(*g.code_point);
    return " '" + utf8 + "' " + format_code_point(*g.code_point);
}

std::string six_digits(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

// Nine steps of ink after the blank: any nonzero coverage shows.
constexpr char kRamp[] = " .:-=+*#%@";
char ramp(std::uint8_t v) { return v == 0 ? ' ' : kRamp[1 + (v - 1) * 9 / 255]; }

// The common picture: glyph i's column offset, and the baseline row.
struct Layout {
    int width = 0, height = 0, baseline = 0;
    std::vector<int> x;
};

// `margin` empty pixels on every side.
Layout layout(const std::vector<GlyphBitmap>& glyphs, int margin) {
    Layout l;
    int above = 0, below = 0;
    bool any = false;
    for (const GlyphBitmap& g : glyphs) {
        if (g.box.width == 0 || g.box.height == 0) continue;
        above = any ? std::max(above, g.box.top) : g.box.top;
        below = any ? std::max(below, g.box.height - g.box.top) : g.box.height - g.box.top;
        any = true;
    }
    if (!any) return l;   // no picture: width and height stay 0
    l.baseline = margin + above;
    l.height = above + below + 2 * margin;
    int x = 0;
    for (const GlyphBitmap& g : glyphs) {
        if (x > 0 && g.box.width > 0) x += 1;  // one empty column between glyphs
        l.x.push_back(margin + x);
        x += g.box.width;
    }
    l.width = x + 2 * margin;
    return l;
}

// Copies every glyph's bytes into one image, `bpp` bytes per pixel, background 0.
Expected<std::vector<std::uint8_t>> compose(const std::vector<GlyphBitmap>& glyphs, Layout& l,
                                            int bpp, int margin) {
    l = layout(glyphs, margin);
    if (l.width == 0 || l.height == 0)
        return Error{"every glyph is empty: there is no picture to write"};
    std::vector<std::uint8_t> px(static_cast<std::size_t>(l.width) * bpp * l.height, 0);
    for (std::size_t i = 0; i < glyphs.size(); ++i) {
        const GlyphBitmap& g = glyphs[i];
        const int row0 = l.baseline - g.box.top;
        for (int y = 0; y < g.box.height; ++y)
            std::copy_n(g.pixels.data() + static_cast<std::size_t>(y) * g.box.width * bpp,
                        static_cast<std::size_t>(g.box.width) * bpp,
                        px.data() + (static_cast<std::size_t>(row0 + y) * l.width + l.x[i]) * bpp);
    }
    return px;
}

// The R, G, B coverages of an LCD pixel, whose bytes are its subpixels left to right, i.e. in
// the panel's order (raster.hpp's CoverageFormat::Lcd).
Rgba8 lcd_rgb(const std::uint8_t* p, LcdOrder order) {
    return order == LcdOrder::Bgr ? Rgba8{p[2], p[1], p[0], 255} : Rgba8{p[0], p[1], p[2], 255};
}

// LCD coverage as an image, each subpixel's coverage in its channel; painted when `colours`.
Image rgb_image(const std::vector<std::uint8_t>& px, int w, int h,
                const std::optional<PictureColours>& colours, LcdOrder order) {
    Image img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const Rgba8 c = lcd_rgb(px.data() + (static_cast<std::size_t>(y) * w + x) * 3, order);
            img.at(x, y) = colours ? paint_rgb(*colours, c.r / 255.0, c.g / 255.0, c.b / 255.0) : c;
        }
    return img;
}

// One call's glyphs share one panel order.
LcdOrder lcd_order_of(const std::vector<GlyphBitmap>& glyphs) {
    return glyphs.empty() ? LcdOrder::Rgb : glyphs.front().lcd_order;
}

int picture_bpp(const std::vector<GlyphBitmap>& glyphs) {
    return glyphs.empty() ? 1 : glyphs.front().bytes_per_pixel();
}

bool any_color(const std::vector<GlyphBitmap>& glyphs) {
    for (const GlyphBitmap& g : glyphs)
        if (g.box.color) return true;
    return false;
}

// The picture of glyphs some of which are colour: every glyph drawn onto the paper (transparent
// without colours) by its own kind, premultiplied "over" in sRGB bytes.
Expected<Image> color_picture(const std::vector<GlyphBitmap>& glyphs,
                              const std::optional<PictureColours>& colours, int margin) {
    Layout l = layout(glyphs, margin);
    if (l.width == 0 || l.height == 0)
        return Error{"every glyph is empty: there is no picture to write"};
    const PictureColours ink_only{{0, 0, 0, 255}, {0, 0, 0, 0}};
    const PictureColours& c = colours ? *colours : ink_only;
    Image picture(l.width, l.height, c.paper);
    for (std::size_t i = 0; i < glyphs.size(); ++i) {
        const GlyphBitmap& g = glyphs[i];
        const int row0 = l.baseline - g.box.top;
        const int bpp = g.bytes_per_pixel();
        for (int y = 0; y < g.box.height; ++y)
            for (int x = 0; x < g.box.width; ++x) {
                const std::uint8_t* p =
                    g.pixels.data() + (static_cast<std::size_t>(y) * g.box.width + x) * bpp;
                Rgba8& out = picture.at(l.x[i] + x, row0 + y);
                if (bpp == 1) {
                    out = paint(c, p[0] / 255.0);
                } else if (bpp == 3) {
                    const Rgba8 rgb = lcd_rgb(p, g.lcd_order);
                    out = paint_rgb(c, rgb.r / 255.0, rgb.g / 255.0, rgb.b / 255.0);
                } else {
                    // Premultiplied source over the straight paper, back to straight alpha.
                    const double a = p[3] / 255.0, pa = out.a / 255.0;
                    const double alpha = a + pa * (1 - a);
                    auto channel = [&](std::uint8_t src, std::uint8_t dst) {
                        const double premul = src + dst * pa * (1 - a);
                        return static_cast<std::uint8_t>(
                            alpha > 0 ? std::min(255.0, premul / alpha + 0.5) : 0);
                    };
                    out = {channel(p[0], out.r), channel(p[1], out.g), channel(p[2], out.b),
                           static_cast<std::uint8_t>(alpha * 255 + 0.5)};
                }
            }
    }
    return picture;
}

}  // namespace

const char* mode_name(const GlyphBitmap& g) {
    if (g.box.color) return "rgba";
    if (g.format == CoverageFormat::Gray) return "gray";
    return g.lcd_order == LcdOrder::Bgr ? "lcd-bgr" : "lcd-rgb";
}

std::string ascii_art(ConstMaskView mask) {
    std::string out;
    for (int y = 0; y < mask.height; ++y) {
        std::string line;
        for (int x = 0; x < mask.width; ++x) line += ramp(mask.at(x, y));
        while (!line.empty() && line.back() == ' ') line.pop_back();
        out += "|" + line + "\n";
    }
    return out;
}

std::string glyphs_ascii(const std::vector<GlyphBitmap>& glyphs, const GlyphRenderOptions& options) {
    std::string out;
    for (const GlyphBitmap& g : glyphs) {
        out += "glyph " + std::to_string(g.gid) + " " + g.name + char_label(g) + ", " +
               six_digits(options.size_px) + " px, " + mode_name(g) + ": " + std::to_string(g.box.width) +
               "x" + std::to_string(g.box.height) + ", left " + std::to_string(g.box.left) + ", top " +
               std::to_string(g.box.top) + ", advance " + six_digits(g.box.advance_px);
        if (g.box.overlap == OverlapMode::Accurate) out += ", accurate overlap";
        if (g.box.color) {
            out += " (colour; its alpha shown)\n";
            std::vector<std::uint8_t> alpha(g.pixels.size() / 4);
            for (std::size_t k = 0; k < alpha.size(); ++k) alpha[k] = g.pixels[4 * k + 3];
            out += ascii_art(ConstMaskView{alpha.data(), g.box.width, g.box.height, g.box.width});
            continue;
        }
        if (g.format == CoverageFormat::Lcd) out += " (one character per subpixel)";
        out += "\n";
        const int row_bytes = g.box.width * g.bytes_per_pixel();
        out += ascii_art(ConstMaskView{g.pixels.data(), row_bytes, g.box.height, row_bytes});
    }
    return out;
}

std::string glyphs_json(const std::vector<GlyphBitmap>& glyphs, const GlyphRenderOptions& options) {
    using nlohmann::ordered_json;
    ordered_json arr = ordered_json::array();
    static const char kHex[] = "0123456789abcdef";
    for (const GlyphBitmap& g : glyphs) {
        ordered_json o;
        o["gid"] = g.gid;
        o["name"] = g.name;
        if (g.code_point) {
            std::string utf8;
            append_utf8(utf8, *g.code_point);
            o["char"] = utf8;
            o["code_point"] = format_code_point(*g.code_point);
        }
        if (!g.font.empty()) o["font"] = g.font;
        o["size"] = options.size_px;
        o["left"] = g.box.left;
        o["top"] = g.box.top;
        o["width"] = g.box.width;
        o["height"] = g.box.height;
        o["advance"] = g.box.advance_px;
        o["mode"] = mode_name(g);
        o["overlap"] = g.box.overlap == OverlapMode::Accurate ? "accurate" : "accumulate";
        ordered_json rows = ordered_json::array();
        const int row_bytes = g.box.width * g.bytes_per_pixel();
        for (int y = 0; y < g.box.height; ++y) {
            std::string hex;
            hex.reserve(static_cast<std::size_t>(row_bytes) * 2);
            for (int x = 0; x < row_bytes; ++x) {
                const std::uint8_t v = g.pixels[static_cast<std::size_t>(y) * row_bytes + x];
                hex += kHex[v >> 4];
                hex += kHex[v & 15];
            }
            rows.push_back(std::move(hex));
        }
        o["rows"] = std::move(rows);
        arr.push_back(std::move(o));
    }
    return arr.dump(2) + "\n";
}

Expected<std::string> glyphs_png(const std::vector<GlyphBitmap>& glyphs,
                                 const GlyphPictureOptions& options) {
    const std::optional<PictureColours>& colours = options.colours;
    const PngOptions& png_options = options.png;
    if (any_color(glyphs)) {
        auto picture = color_picture(glyphs, colours, options.margin_px);
        if (!picture) return picture.error();
        return picture_png(*picture, false, !colours || colours->translucent(), png_options);
    }
    Layout l;
    const int bpp = picture_bpp(glyphs);
    auto px = compose(glyphs, l, bpp, options.margin_px);
    if (!px) return px.error();
    const LcdOrder order = lcd_order_of(glyphs);
    const ConstMaskView gray{px->data(), l.width, l.height, l.width};
    if (!colours) {
        auto png = bpp == 1 ? encode_png_gray(gray, png_options)
                            : encode_png(rgb_image(*px, l.width, l.height, colours, order),
                                         PngColor::Rgb, png_options);
        if (!png) return png.error();
        return std::string(png->begin(), png->end());
    }
    const Image picture = bpp == 1 ? paint_coverage(gray, *colours)
                                   : rgb_image(*px, l.width, l.height, colours, order);
    return picture_png(picture, bpp == 1 && colours->gray(), colours->translucent(),
                       png_options);
}

Expected<std::string> glyphs_pnm(const std::vector<GlyphBitmap>& glyphs,
                                 const GlyphPictureOptions& options) {
    const std::optional<PictureColours>& colours = options.colours;
    if (any_color(glyphs)) {
        auto picture = color_picture(glyphs, colours, options.margin_px);
        if (!picture) return picture.error();
        return picture_pnm(*picture, false);
    }
    Layout l;
    const int bpp = picture_bpp(glyphs);
    auto px = compose(glyphs, l, bpp, options.margin_px);
    if (!px) return px.error();
    const LcdOrder order = lcd_order_of(glyphs);
    const ConstMaskView gray{px->data(), l.width, l.height, l.width};
    if (!colours) {
        const std::vector<std::uint8_t> bytes =
            bpp == 1 ? encode_pgm(gray)
                     : encode_ppm(rgb_image(*px, l.width, l.height, colours, order));
        return std::string(bytes.begin(), bytes.end());
    }
    const Image picture = bpp == 1 ? paint_coverage(gray, *colours)
                                   : rgb_image(*px, l.width, l.height, colours, order);
    return picture_pnm(picture, bpp == 1 && colours->gray());
}

}  // namespace bezel::cli
