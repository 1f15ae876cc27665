// Private: the pixel formats of image.hpp as compile-time layouts, so each blend loop is one
// instantiation with the channel offsets and the premultiplication folded in (no per-pixel
// switch), and load_pixel / store_pixel in one place for the blends and the public functions.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>

#include "bezel/image.hpp"

namespace bezel::image_detail {

// C = min(255, round(255·P/A)) for A > 0; 0 for A = 0. `(255·P + ⌊A/2⌋) / A` rounds half up:
// a tie 255·P/A = k + ½ needs A even, where ⌊A/2⌋ is exactly half.
inline std::uint8_t unpremultiply(std::uint8_t p, std::uint8_t a) {
    if (a == 0) return 0;
    return static_cast<std::uint8_t>(std::min(255, (p * 255 + a / 2) / a));
}
// P = round(C·A/255); C·A/255 is never exactly k + ½ (255 is odd), so +127 then floor rounds.
inline std::uint8_t premultiply(std::uint8_t c, std::uint8_t a) {
    return static_cast<std::uint8_t>((c * a + 127) / 255);
}

// A 4-byte format: red at byte R, green at 1, blue at byte B, alpha at 3.
template <int R, int B, bool Premultiplied>
struct Quad {
    static constexpr bool kPremultiplied = Premultiplied;
    static constexpr int kR = R, kB = B;
    static Rgba8 load(const std::uint8_t* p) {
        if (!Premultiplied) return {p[R], p[1], p[B], p[3]};
        const std::uint8_t a = p[3];
        return {unpremultiply(p[R], a), unpremultiply(p[1], a), unpremultiply(p[B], a), a};
    }
    static void store(std::uint8_t* p, Rgba8 c) {
        if (!Premultiplied) {
            p[R] = c.r, p[1] = c.g, p[B] = c.b, p[3] = c.a;
            return;
        }
        p[R] = premultiply(c.r, c.a), p[1] = premultiply(c.g, c.a), p[B] = premultiply(c.b, c.a);
        p[3] = c.a;
    }
    // The pixel's four bytes as one value, for equality tests and copies of whole pixels.
    static std::uint32_t word(const std::uint8_t* p) {
        std::uint32_t w;
        std::memcpy(&w, p, 4);
        return w;
    }
    static void put_word(std::uint8_t* p, std::uint32_t w) { std::memcpy(p, &w, 4); }
    static std::uint32_t word_of(Rgba8 c) {
        std::uint8_t b[4];
        store(b, c);
        return word(b);
    }
};
using RgbaStraight = Quad<0, 2, false>;
using BgraStraight = Quad<2, 0, false>;
using RgbaPremultiplied = Quad<0, 2, true>;
using BgraPremultiplied = Quad<2, 0, true>;

// Calls fn(Layout{}) with the Quad of a 4-byte format; returns false for Gray8.
template <typename Fn>
bool with_quad(PixelFormat format, Fn&& fn) {
    switch (format) {
        case PixelFormat::Rgba8: fn(RgbaStraight{}); return true;
        case PixelFormat::Bgra8: fn(BgraStraight{}); return true;
        case PixelFormat::Rgba8Premultiplied: fn(RgbaPremultiplied{}); return true;
        case PixelFormat::Bgra8Premultiplied: fn(BgraPremultiplied{}); return true;
        case PixelFormat::Gray8: break;
    }
    return false;
}

}  // namespace bezel::image_detail
