// Netpbm encoders: binary PGM (P5) and PPM (P6), maxval 255, alpha dropped.
#include <string>

#include "bezel/image.hpp"
#include "image/srgb.hpp"

namespace bezel {

namespace {

std::vector<std::uint8_t> header(const char* magic, int width, int height, std::size_t pixel_bytes) {
    std::string h = std::string(magic) + "\n" + std::to_string(width) + " " +
                    std::to_string(height) + "\n255\n";
    std::vector<std::uint8_t> out;
    out.reserve(h.size() + pixel_bytes);
    out.assign(h.begin(), h.end());
    return out;
}

std::size_t area(int width, int height) {
    return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
}

}  // namespace

std::vector<std::uint8_t> encode_pgm(const Image& image) {
    auto out = header("P5", image.width(), image.height(), area(image.width(), image.height()));
    for (int y = 0; y < image.height(); ++y) {
        const Rgba8* p = image.row(y);
        for (int x = 0; x < image.width(); ++x) out.push_back(luma(p[x]));
    }
    return out;
}

std::vector<std::uint8_t> encode_ppm(const Image& image) {
    auto out = header("P6", image.width(), image.height(), 3 * area(image.width(), image.height()));
    for (int y = 0; y < image.height(); ++y) {
        const Rgba8* p = image.row(y);
        for (int x = 0; x < image.width(); ++x) {
            out.push_back(p[x].r);
            out.push_back(p[x].g);
            out.push_back(p[x].b);
        }
    }
    return out;
}

std::vector<std::uint8_t> encode_pgm(ConstMaskView mask) {
    auto out = header("P5", mask.width, mask.height, area(mask.width, mask.height));
    for (int y = 0; y < mask.height; ++y) out.insert(out.end(), mask.row(y), mask.row(y) + mask.width);
    return out;
}

}  // namespace bezel
