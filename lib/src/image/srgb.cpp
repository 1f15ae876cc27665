// The public face of the sRGB tables (image/srgb.hpp), for modules outside image.
#include "bezel/image.hpp"
#include "image/srgb.hpp"

namespace bezel {

float srgb_decode(std::uint8_t encoded) { return srgb_tables().decode[encoded]; }

std::uint8_t srgb_encode(float linear) { return srgb_tables().enc(linear); }

}  // namespace bezel
