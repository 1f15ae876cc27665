// PNG encoding of colour images and masks into memory on one thread: Fast and Default deflate
// the scanlines as one igzip stream (png_parallel.cpp writes the file), Small goes through
// libpng's low-level API, which (unlike the simplified png_image API png.cpp uses for reading)
// lets us pick the zlib level (6) and filter. On a 1075×68 gray text line, igzip level 1 or 2
// takes about a fifth of zlib level 1's time for a slightly smaller file (docs/perf-log.md,
// "Dataset speed round").
//
// Never a row filter (no per-row filter search). Measured on the benchmark page
// (tools/bench/render_page.txt, 716×2361 gray): no filter encodes faster than SUB and gives a
// smaller file (266 KB against 285 KB: the flat background is long runs of one
// byte either way, and SUB turns glyph edges into more distinct values); Z_RLE was larger
// (548 KB) and no faster.
//
// libpng reports errors by longjmp. Only encode_rows() calls setjmp, and it keeps no object with a
// destructor in its frame (scratch rows and the output vector belong to the callers), so the jump
// never skips a C++ destructor. The write callback catches allocation failure and turns it into
// png_error outside the catch block.
#include <png.h>

#include <algorithm>
#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>

#include "bezel/image.hpp"
#include "image/png_igzip.hpp"
#include "image/srgb.hpp"

namespace bezel {

namespace {

int zlib_level(PngCompression compression) {
    return compression == PngCompression::Small ? 6 : 1;
}

struct WriteState {
    std::vector<std::uint8_t>* out;
    char message[256];
};

void on_error(png_structp png, png_const_charp msg) {
    auto* st = static_cast<WriteState*>(png_get_error_ptr(png));
    std::snprintf(st->message, sizeof st->message, "%s", msg ? msg : "unknown libpng error");
    std::longjmp(png_jmpbuf(png), 1);
}
void on_warning(png_structp, png_const_charp) {}

void on_write(png_structp png, png_bytep data, png_size_t length) {
    auto* st = static_cast<WriteState*>(png_get_io_ptr(png));
    bool failed = false;
    try {
        st->out->insert(st->out->end(), data, data + length);
    } catch (...) {
        failed = true;
    }
    if (failed) png_error(png, "out of memory");
}
void on_flush(png_structp) {}

// Produces row `y` of the image in the PNG's byte layout, possibly converting into `scratch`.
using RowFn = const std::uint8_t* (*)(const void* source, int y, std::uint8_t* scratch);

// Returns false with st.message set on failure. See the file comment on setjmp.
bool encode_rows(WriteState& st, int width, int height, int color_type, const void* source,
                 RowFn row_fn, std::uint8_t* scratch, int level) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &st, on_error, on_warning);
    if (!png) {
        std::snprintf(st.message, sizeof st.message, "cannot create the libpng writer");
        return false;
    }
    png_infop info = png_create_info_struct(png);
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        std::snprintf(st.message, sizeof st.message, "cannot create the libpng writer");
        return false;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_set_write_fn(png, &st, on_write, on_flush);
    png_set_compression_level(png, level);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
    png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8,
                 color_type, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < height; ++y)
        png_write_row(png, const_cast<png_bytep>(row_fn(source, y, scratch)));
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return true;
}

const std::uint8_t* image_rgba_row(const void* source, int y, std::uint8_t*) {
    return reinterpret_cast<const std::uint8_t*>(static_cast<const Image*>(source)->row(y));
}
const std::uint8_t* image_rgb_row(const void* source, int y, std::uint8_t* scratch) {
    const Image& image = *static_cast<const Image*>(source);
    const Rgba8* p = image.row(y);
    for (int x = 0; x < image.width(); ++x) {
        scratch[3 * x] = p[x].r;
        scratch[3 * x + 1] = p[x].g;
        scratch[3 * x + 2] = p[x].b;
    }
    return scratch;
}
const std::uint8_t* image_gray_row(const void* source, int y, std::uint8_t* scratch) {
    const Image& image = *static_cast<const Image*>(source);
    const Rgba8* p = image.row(y);
    for (int x = 0; x < image.width(); ++x) scratch[x] = luma(p[x]);
    return scratch;
}
const std::uint8_t* mask_row(const void* source, int y, std::uint8_t*) {
    return static_cast<const ConstMaskView*>(source)->row(y);
}

Status check_size(int width, int height) {
    std::string size = std::to_string(width) + "x" + std::to_string(height);
    if (width <= 0 || height <= 0) return Error{"cannot write an empty " + size + " image as PNG"};
    if (width > kMaxImageDim || height > kMaxImageDim)
        return Error{"image " + size + " is larger than the " + std::to_string(kMaxImageDim) +
                     " px a side images may have"};
    return ok_status();
}

// Bytes per pixel of the PNG colour types written here (gray, RGB, RGBA).
std::size_t channels(int color_type) {
    return color_type == PNG_COLOR_TYPE_GRAY ? 1 : color_type == PNG_COLOR_TYPE_RGB ? 3 : 4;
}

Expected<std::vector<std::uint8_t>> encode(int width, int height, int color_type,
                                           const void* source, RowFn row_fn,
                                           std::size_t scratch_bytes, PngCompression compression) {
    if (auto ok = check_size(width, height); !ok) return ok.error();
    std::vector<std::uint8_t> scratch(scratch_bytes);
    const std::size_t row_bytes = channels(color_type) * static_cast<std::size_t>(width);
    if (compression != PngCompression::Small &&
        (row_bytes + 1) * static_cast<std::size_t>(height) <= png_detail::kMaxIgzipScanlineBytes) {
        // igzip, one stream: the scanlines gathered as the IDAT holds them (filter byte 0, then
        // the row), then deflated in one call.
        std::vector<std::uint8_t> scanlines((row_bytes + 1) * static_cast<std::size_t>(height));
        for (int y = 0; y < height; ++y) {
            std::uint8_t* r = scanlines.data() + static_cast<std::size_t>(y) * (row_bytes + 1);
            r[0] = 0;
            std::memcpy(r + 1, row_fn(source, y, scratch.data()), row_bytes);
        }
        return png_detail::encode_png_igzip(width, height, static_cast<std::uint8_t>(color_type),
                                            scanlines.data(), scanlines.size(), compression);
    }
    std::vector<std::uint8_t> out;
    // Text pages compress to about 1/6 of a byte per pixel at level 1: reserving that much (and
    // a little) saves most of the regrowth copies.
    out.reserve(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) / 4 + 4096);
    WriteState st{&out, {}};
    if (!encode_rows(st, width, height, color_type, source, row_fn, scratch.data(),
                     zlib_level(compression)))
        return Error{std::string("PNG encoding failed: ") + st.message};
    return out;
}

}  // namespace

Expected<std::vector<std::uint8_t>> encode_png(const Image& image, PngColor color,
                                               const PngOptions& options) {
    const PngCompression c = options.compression;
    auto w = static_cast<std::size_t>(std::max(image.width(), 0));
    switch (color) {
        case PngColor::Gray:
            return encode(image.width(), image.height(), PNG_COLOR_TYPE_GRAY, &image,
                          image_gray_row, w, c);
        case PngColor::Rgb:
            return encode(image.width(), image.height(), PNG_COLOR_TYPE_RGB, &image,
                          image_rgb_row, 3 * w, c);
        case PngColor::Rgba:
            break;
    }
    return encode(image.width(), image.height(), PNG_COLOR_TYPE_RGBA, &image, image_rgba_row, 0,
                  c);
}

Expected<std::vector<std::uint8_t>> encode_png_gray(ConstMaskView mask, const PngOptions& options) {
    return encode(mask.width, mask.height, PNG_COLOR_TYPE_GRAY, &mask, mask_row, 0,
                  options.compression);
}

Status write_png(const std::string& file, const Image& image, PngColor color,
                 const PngOptions& options) {
    auto bytes = encode_png(image, color, options);
    if (!bytes) return Error{file + ": " + bytes.error().message};
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(file.c_str(), "wb"), std::fclose);
    if (!f) return Error{file + ": cannot create file: " + std::strerror(errno)};
    if (std::fwrite(bytes->data(), 1, bytes->size(), f.get()) != bytes->size() ||
        std::fflush(f.get()) != 0)
        return Error{file + ": write failed: " + std::strerror(errno)};
    return ok_status();
}

}  // namespace bezel
