// Private: the painter's pixel, float premultiplied RGBA in sRGB-encoded values (paint.hpp says
// why encoded), and the conversions at its edges.
#pragma once

#include <algorithm>
#include <cstdint>

#include "bezel/paint.hpp"

namespace bezel::paint_detail {

// Premultiplied: r, g, b ≤ a, all in [0, 1] for every pixel a paint produces (Plus clamps).
struct Pixel {
    float r = 0, g = 0, b = 0, a = 0;
};

// A straight colour premultiplied by its alpha.
inline Pixel premultiplied(const ColorF& c) { return {c.r * c.a, c.g * c.a, c.b * c.a, c.a}; }

// The colour a PaintColor names: the palette entry or the foreground, times its alpha.
inline ColorF resolve(const PaintColor& c, const Rgba8& foreground) {
    ColorF out = c.color;
    if (c.foreground)
        out = {foreground.r / 255.0f, foreground.g / 255.0f, foreground.b / 255.0f,
               foreground.a / 255.0f};
    out.a *= c.alpha;
    return out;
}

// src over dst, both premultiplied: dst' = src + dst·(1 − αs).
inline void src_over(Pixel& dst, const Pixel& src) {
    const float k = 1.0f - src.a;
    dst.r = src.r + dst.r * k;
    dst.g = src.g + dst.g * k;
    dst.b = src.b + dst.b * k;
    dst.a = src.a + dst.a * k;
}

// A float in [0, 1] (anything else clamped) to the nearest byte.
inline std::uint8_t to_byte(float v) {
    return static_cast<std::uint8_t>(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f);
}

}  // namespace bezel::paint_detail
