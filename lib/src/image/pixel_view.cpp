// Pixels of every PixelFormat read and written as straight colour, and Image's view of itself.
#include "bezel/image.hpp"
#include "image/pixel_format.hpp"
#include "image/srgb.hpp"

namespace bezel {

// Rgba8 is four bytes R, G, B, A with no padding: Image's pixels are PixelFormat::Rgba8 memory.
static_assert(sizeof(Rgba8) == 4 && alignof(Rgba8) == 1, "Image::view relies on Rgba8's layout");

PixelView Image::view() {
    return {reinterpret_cast<std::uint8_t*>(pixels_.data()), width_, height_,
            static_cast<std::ptrdiff_t>(width_) * 4, PixelFormat::Rgba8};
}

ConstPixelView Image::view() const {
    return {reinterpret_cast<const std::uint8_t*>(pixels_.data()), width_, height_,
            static_cast<std::ptrdiff_t>(width_) * 4, PixelFormat::Rgba8};
}

Rgba8 load_pixel(PixelFormat format, const std::uint8_t* p) {
    Rgba8 c{p[0], p[0], p[0], 255};
    image_detail::with_quad(format, [&](auto layout) { c = decltype(layout)::load(p); });
    return c;
}

void store_pixel(PixelFormat format, std::uint8_t* p, Rgba8 c) {
    if (!image_detail::with_quad(format, [&](auto layout) { decltype(layout)::store(p, c); }))
        p[0] = luma(c);
}

}  // namespace bezel
