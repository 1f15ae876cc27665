#include "surface/framebuffer.hpp"

#include <array>
#include <cmath>

namespace bezel::surface_detail {

float srgb_to_linear(std::uint8_t v) {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) {
            double c = i / 255.0;
            t[static_cast<std::size_t>(i)] =
                static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
        }
        return t;
    }();
    return table[v];
}

std::uint8_t linear_to_srgb(float v) {
    double c = std::fmin(1.0, std::fmax(0.0, static_cast<double>(v)));
    double e = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
    return static_cast<std::uint8_t>(std::lround(e * 255.0));
}

LinearRgb linear(Rgba8 c) { return {srgb_to_linear(c.r), srgb_to_linear(c.g), srgb_to_linear(c.b)}; }

Framebuffer::Framebuffer(int width, int height)
    : width_(width), height_(height),
      rgb_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height)),
      cover_(rgb_.size(), 0.0f), depth_(rgb_.size(), HUGE_VALF), back_(rgb_.size()),
      back_cover_(rgb_.size(), 0.0f) {}

Image Framebuffer::resolve(Rgba8 background) const {
    Image out(width_, height_);
    const LinearRgb bg = linear(background);
    for (int y = 0; y < height_; ++y) {
        Rgba8* row = out.row(y);
        for (int x = 0; x < width_; ++x) {
            std::size_t k = index(x, y);
            const float back_rest = 1.0f - back_cover_[k], rest = 1.0f - cover_[k];
            const LinearRgb under{back_[k].r + back_rest * bg.r, back_[k].g + back_rest * bg.g,
                                  back_[k].b + back_rest * bg.b};
            row[x] = {linear_to_srgb(rgb_[k].r + rest * under.r),
                      linear_to_srgb(rgb_[k].g + rest * under.g),
                      linear_to_srgb(rgb_[k].b + rest * under.b), 255};
        }
    }
    return out;
}

}  // namespace bezel::surface_detail
