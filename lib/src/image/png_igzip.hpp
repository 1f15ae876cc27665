// The one-stream igzip PNG writer that encode_png.cpp hands its Fast and Default images to
// (png_parallel.cpp, beside the banded writer whose deflater and file layout it shares).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "bezel/image.hpp"

namespace bezel::png_detail {

// The most scanline bytes the one-stream writer takes. It deflates a copy of every scanline at
// once, so this bounds the memory an encode adds to the image's own: a 4096 px square RGBA page
// (64 MiB). Larger images stream through libpng row by row (zlib level 1). It also keeps the
// input within igzip's 32-bit counts.
inline constexpr std::size_t kMaxIgzipScanlineBytes = std::size_t{64} << 20;

// A PNG (8 bits a sample, PNG colour type `color_type`, no interlace) of `height` scanlines of
// `width` pixels held in scanlines[0, bytes): each row its filter byte, then its samples, as
// the IDAT stream holds them. Deflated by igzip as one stream at the level `compression` names
// (Fast or Default; image.hpp); bytes <= kMaxIgzipScanlineBytes. Errors: deflate failure
// (the caller has checked the size).
Expected<std::vector<std::uint8_t>> encode_png_igzip(int width, int height,
                                                     std::uint8_t color_type,
                                                     const std::uint8_t* scanlines,
                                                     std::size_t bytes,
                                                     PngCompression compression);

}  // namespace bezel::png_detail
