// Private: the sRGB transfer function as tables, shared by blending and the ANSI preview.
//
// The sRGB transfer function (IEC 61966-2-1):
//   decode: c ≤ 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055)^2.4        (c = byte / 255)
//   encode: l ≤ 0.0031308 ? 12.92·l : 1.055·l^(1/2.4) − 0.055
// Decoding is a 256-entry float table. Encoding is a table of kSrgbEncodeSize entries indexed by
// linear light quantized to 1/(kSrgbEncodeSize − 1), each holding the byte whose sRGB value is
// nearest the encoded midpoint. At 4096 entries the step near black (where sRGB's slope is
// steepest, 12.92) is 12.92·255/4095 ≈ 0.8 of a byte, so the error is within ±1 byte everywhere
// and enc(dec(v)) == v for every byte v (tested): an untouched pixel round-trips exactly.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "bezel/image.hpp"

namespace bezel {

inline constexpr int kSrgbEncodeSize = 4096;

struct SrgbTables {
    std::array<float, 256> decode;
    std::array<std::uint8_t, kSrgbEncodeSize> encode;

    SrgbTables() {
        for (int v = 0; v < 256; ++v) {
            double c = v / 255.0;
            decode[static_cast<std::size_t>(v)] = static_cast<float>(
                c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
        }
        for (int i = 0; i < kSrgbEncodeSize; ++i) {
            double l = static_cast<double>(i) / (kSrgbEncodeSize - 1);
            double c = l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055;
            encode[static_cast<std::size_t>(i)] =
                static_cast<std::uint8_t>(std::lround(std::clamp(c, 0.0, 1.0) * 255.0));
        }
    }
    std::uint8_t enc(float linear) const {
        // +0.5 rounds to the nearest entry; the clamp keeps float noise in range.
        int i = static_cast<int>(linear * (kSrgbEncodeSize - 1) + 0.5f);
        return encode[static_cast<std::size_t>(std::clamp(i, 0, kSrgbEncodeSize - 1))];
    }
};

inline const SrgbTables& srgb_tables() {
    static const SrgbTables t;
    return t;
}

// Rec. 709 luma of sRGB-encoded values in 8.8 fixed point: 0.2126, 0.7152, 0.0722 → 54/183/19
// (sum 256, so white stays 255). Applied to the encoded values, as PNG/PGM viewers expect.
inline std::uint8_t luma(Rgba8 p) {
    return static_cast<std::uint8_t>((54 * p.r + 183 * p.g + 19 * p.b + 128) >> 8);
}

}  // namespace bezel
