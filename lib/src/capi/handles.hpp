// The C API's handles and its boundary: every bezel_* entry point runs its body through
// guarded(), so no exception leaves the library, and reports failures through fail(), which
// stores the message in the handle's slot and the thread's.
#pragma once

#include <cstddef>
#include <cstring>
#include <new>
#include <string>
#include <string_view>
#include <vector>

#include "bezel/bezel.h"
#include "bezel/expected.hpp"
#include "bezel/font.hpp"
#include "bezel/font_face.hpp"
#include "bezel/glyph.hpp"
#include "bezel/path.hpp"
#include "bezel/raster.hpp"
#include "bezel/text_renderer.hpp"

namespace bezel::capi_detail {

// A last-error message. Storing it may itself run out of memory; the slot then says so instead
// of holding a stale or partial message (fail() must not throw).
class ErrorSlot {
public:
    void set(std::string_view message) noexcept;
    const char* c_str() const noexcept;

private:
    std::string text_;
    bool lost_ = false;
};

// The calling thread's slot (bezel_last_error).
ErrorSlot& thread_error() noexcept;

// Stores `message` in `handle` (may be null) and in the thread's slot; returns `status`.
bezel_status fail(ErrorSlot* handle, bezel_status status, std::string_view message) noexcept;

// Runs `body` (returning bezel_status) with every exception turned into a status and message:
// std::bad_alloc into OUT_OF_MEMORY, anything else into INTERNAL (a bug: bezel's public calls
// report input errors as values, never by throwing).
template <typename Body>
bezel_status guarded(ErrorSlot* handle, const char* function, Body&& body) noexcept {
    try {
        return body();
    } catch (const std::bad_alloc&) {
        return fail(handle, BEZEL_STATUS_OUT_OF_MEMORY, std::string_view("out of memory"));
    } catch (const std::exception& e) {
        try {
            return fail(handle, BEZEL_STATUS_INTERNAL,
                        std::string(function) + ": internal error: " + e.what());
        } catch (...) {
            return fail(handle, BEZEL_STATUS_INTERNAL, std::string_view("internal error"));
        }
    } catch (...) {
        return fail(handle, BEZEL_STATUS_INTERNAL, std::string_view("internal error"));
    }
}

// "<function>: <what> is NULL", for the thread's slot and `handle`.
bezel_status null_argument(ErrorSlot* handle, const char* function, const char* what) noexcept;

// Whether `buffer_size` bytes at `buffer` with `stride` hold `rows` rows of `row_bytes` bytes:
// OK, INVALID_ARGUMENT (a negative stride) or BUFFER_TOO_SMALL; `what` names the picture in the
// message ("glyph 36"). Nothing is needed when rows or row_bytes is 0.
bezel_status check_buffer(ErrorSlot* handle, const std::string& what, const void* buffer,
                          std::size_t buffer_size, std::ptrdiff_t stride, std::size_t row_bytes,
                          std::size_t rows) noexcept;

// The integer a C caller stored in an enum field or passed as an enum argument. C lets any int
// through; in C++ loading an enum object whose value lies outside the enumerators' range is
// undefined, so enum inputs are read as their bytes and checked as ints.
template <typename Enum>
int raw_enum(const Enum& value) noexcept {
    static_assert(sizeof(Enum) == sizeof(int), "bezel.h's enums are int-sized in C and C++");
    int raw;
    std::memcpy(&raw, &value, sizeof raw);
    return raw;
}

// Options checked and converted; a failure is reported through `handle` (a non-OK status).
bezel_status to_hinting(ErrorSlot* handle, const char* function, int in, Hinting& out);
bezel_status to_coverage(ErrorSlot* handle, const char* function, int in,
                         CoverageFormat& format, LcdOrder& order);
bezel_status to_variations(ErrorSlot* handle, const char* function, const bezel_variation* in,
                           std::size_t count, std::vector<VariationSetting>& out);

}  // namespace bezel::capi_detail

struct bezel_font {
    bezel::FontFace face;
    bezel::Font font;                                  // reads face-wide facts and glyph indices
    std::vector<bezel::VariationSetting> variations;   // what rasterizers and renderers take
    bezel::capi_detail::ErrorSlot error;
};

struct bezel_glyph_rasterizer {
    bezel::Font font;   // this rasterizer's own instance of the face (one thread at a time)
    bezel::GlyphRasterizer raster;
    bezel::GlyphRenderOptions options;
    std::vector<bezel::PreparedGlyph> set;   // bezel_glyph_render_set's, reused
    std::vector<bezel::GlyphDrawJob> jobs;
    bezel::capi_detail::ErrorSlot error;
};

struct bezel_path {
    bezel::Path path;
    bezel::capi_detail::ErrorSlot error;
};

struct bezel_rasterizer {
    bezel::Rasterizer raster;
    bezel::capi_detail::ErrorSlot error;
};

struct bezel_text_renderer {
    bezel::TextRenderer renderer;
    bezel::capi_detail::ErrorSlot error;
};
