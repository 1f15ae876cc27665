// Gray PNG files through libpng's simplified API (png_image_*), which reports errors as return
// values and a message instead of longjmp, so no setjmp crosses C++ frames here.
#include <png.h>

#include <cstdio>
#include <memory>
#include <string>

#include "bezel/image.hpp"

namespace bezel {

namespace {

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

// png_image_free on every exit path, including the failure ones.
struct ImageGuard {
    png_image* image;
    ~ImageGuard() { png_image_free(image); }
};

}  // namespace

Status write_png_gray(const std::string& file, ConstMaskView mask) {
    if (mask.width <= 0 || mask.height <= 0)
        return Error{file + ": cannot write an empty " + std::to_string(mask.width) + "x" +
                     std::to_string(mask.height) + " image as PNG"};
    if (mask.width > kMaxImageDim || mask.height > kMaxImageDim)
        return Error{file + ": image " + std::to_string(mask.width) + "x" +
                     std::to_string(mask.height) + " is larger than the " +
                     std::to_string(kMaxImageDim) + " px a side images may have"};
    FilePtr f(std::fopen(file.c_str(), "wb"));
    if (!f) return Error{file + ": cannot create file"};
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    image.width = static_cast<png_uint_32>(mask.width);
    image.height = static_cast<png_uint_32>(mask.height);
    image.format = PNG_FORMAT_GRAY;
    ImageGuard guard{&image};
    // libpng's row_stride is in components (bytes here) and may be negative for bottom-up rows.
    auto row_stride = static_cast<png_int_32>(mask.stride);
    if (!png_image_write_to_stdio(&image, f.get(), 0, mask.data, row_stride, nullptr))
        return Error{file + ": PNG write failed: " + image.message};
    if (std::fflush(f.get()) != 0) return Error{file + ": write failed (disk full?)"};
    return ok_status();
}

Expected<Mask> read_png_gray(const std::string& file) {
    FilePtr f(std::fopen(file.c_str(), "rb"));
    if (!f) return Error{file + ": cannot open file"};
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    ImageGuard guard{&image};
    if (!png_image_begin_read_from_stdio(&image, f.get()))
        return Error{file + ": not a readable PNG: " + image.message};
    if (image.width == 0 || image.height == 0 || image.width > kMaxImageDim ||
        image.height > kMaxImageDim)
        return Error{file + ": PNG size " + std::to_string(image.width) + "x" +
                     std::to_string(image.height) + " is outside 1.." +
                     std::to_string(kMaxImageDim)};
    // 8-bit gray files come back byte for byte; other formats go through libpng's conversion
    // (16-bit and colour inputs are linearised by libpng's rules, which goldens never use).
    image.format = PNG_FORMAT_GRAY;
    Mask mask(static_cast<int>(image.width), static_cast<int>(image.height));
    MaskView v = mask.view();
    if (!png_image_finish_read(&image, nullptr, v.data, static_cast<png_int_32>(v.stride), nullptr))
        return Error{file + ": corrupt PNG: " + image.message};
    return mask;
}

}  // namespace bezel
