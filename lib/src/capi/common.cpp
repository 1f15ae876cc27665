// Status names, last errors, buffer checks and the version: what every handle shares.
#include <cmath>
#include <cstring>
#include <limits>

#include "capi/handles.hpp"

namespace bezel::capi_detail {

void ErrorSlot::set(std::string_view message) noexcept {
    try {
        text_.assign(message.data(), message.size());
        lost_ = false;
    } catch (...) {
        text_.clear();   // clear() keeps the capacity and cannot throw
        lost_ = true;
    }
}

const char* ErrorSlot::c_str() const noexcept {
    return lost_ ? "out of memory (while storing an error message)" : text_.c_str();
}

ErrorSlot& thread_error() noexcept {
    thread_local ErrorSlot slot;
    return slot;
}

bezel_status fail(ErrorSlot* handle, bezel_status status, std::string_view message) noexcept {
    if (handle) handle->set(message);
    thread_error().set(message);
    return status;
}

bezel_status null_argument(ErrorSlot* handle, const char* function, const char* what) noexcept {
    try {
        return fail(handle, BEZEL_STATUS_INVALID_ARGUMENT,
                    std::string(function) + ": " + what + " is NULL");
    } catch (...) {
        return fail(handle, BEZEL_STATUS_INVALID_ARGUMENT, std::string_view("a NULL argument"));
    }
}

bezel_status check_buffer(ErrorSlot* handle, const std::string& what, const void* buffer,
                          std::size_t buffer_size, std::ptrdiff_t stride, std::size_t row_bytes,
                          std::size_t rows) noexcept {
    try {
        if (stride < 0)
            return fail(handle, BEZEL_STATUS_INVALID_ARGUMENT,
                        what + ": stride " + std::to_string(stride) +
                            " is negative (rows must go down in memory)");
        if (rows == 0 || row_bytes == 0) return BEZEL_STATUS_OK;
        const auto ustride = static_cast<std::size_t>(stride);
        // needed = stride·(rows − 1) + row_bytes, without overflowing size_t.
        const bool fits = ustride >= row_bytes &&
                          (rows == 1 || ustride <= (std::numeric_limits<std::size_t>::max() -
                                                    row_bytes) / (rows - 1));
        const std::size_t needed = fits ? ustride * (rows - 1) + row_bytes : 0;
        if (buffer && fits && buffer_size >= needed) return BEZEL_STATUS_OK;
        std::string why;
        if (!buffer)
            why = "the buffer is NULL";
        else if (ustride < row_bytes)
            why = "stride " + std::to_string(stride) + " is less than a row's " +
                  std::to_string(row_bytes) + " bytes";
        else if (!fits)
            why = "stride " + std::to_string(stride) + " overflows the buffer size";
        else
            why = "buffer of " + std::to_string(buffer_size) + " bytes, stride " +
                  std::to_string(stride) + ", needs " + std::to_string(needed);
        return fail(handle, BEZEL_STATUS_BUFFER_TOO_SMALL,
                    what + " (" + std::to_string(rows) + " rows of " + std::to_string(row_bytes) +
                        " bytes) does not fit: " + why);
    } catch (...) {
        return fail(handle, BEZEL_STATUS_OUT_OF_MEMORY, std::string_view("out of memory"));
    }
}

bezel_status to_hinting(ErrorSlot* handle, const char* function, int in, Hinting& out) {
    switch (in) {
    case BEZEL_HINTING_NONE: out = Hinting::None; return BEZEL_STATUS_OK;
    case BEZEL_HINTING_LIGHT: out = Hinting::Light; return BEZEL_STATUS_OK;
    case BEZEL_HINTING_FULL: out = Hinting::Full; return BEZEL_STATUS_OK;
    case BEZEL_HINTING_AUTO: out = Hinting::Auto; return BEZEL_STATUS_OK;
    }
    return fail(handle, BEZEL_STATUS_INVALID_ARGUMENT,
                std::string(function) + ": hinting " + std::to_string(in) +
                    " is not a bezel_hinting (0..3)");
}

bezel_status to_coverage(ErrorSlot* handle, const char* function, int in,
                         CoverageFormat& format, LcdOrder& order) {
    switch (in) {
    case BEZEL_COVERAGE_GRAY: format = CoverageFormat::Gray; return BEZEL_STATUS_OK;
    case BEZEL_COVERAGE_LCD_RGB:
        format = CoverageFormat::Lcd;
        order = LcdOrder::Rgb;
        return BEZEL_STATUS_OK;
    case BEZEL_COVERAGE_LCD_BGR:
        format = CoverageFormat::Lcd;
        order = LcdOrder::Bgr;
        return BEZEL_STATUS_OK;
    }
    return fail(handle, BEZEL_STATUS_INVALID_ARGUMENT,
                std::string(function) + ": coverage " + std::to_string(in) +
                    " is not a bezel_coverage (0..2)");
}

bezel_status to_variations(ErrorSlot* handle, const char* function, const bezel_variation* in,
                           std::size_t count, std::vector<VariationSetting>& out) {
    out.clear();
    if (count == 0) return BEZEL_STATUS_OK;
    if (!in) return null_argument(handle, function, "variations (with a nonzero count)");
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t length = strnlen(in[i].tag, sizeof in[i].tag);
        if (length != 4)
            return fail(handle, BEZEL_STATUS_INVALID_ARGUMENT,
                        std::string(function) + ": variation " + std::to_string(i) +
                            ": the tag must be 4 characters and NUL-terminated");
        if (!std::isfinite(in[i].value))
            return fail(handle, BEZEL_STATUS_INVALID_ARGUMENT,
                        std::string(function) + ": variation " + std::string(in[i].tag, 4) +
                            ": the value is not finite");
        out.push_back({std::string(in[i].tag, 4), in[i].value});
    }
    return BEZEL_STATUS_OK;
}

}  // namespace bezel::capi_detail

using namespace bezel::capi_detail;

// BEZEL_PROJECT_VERSION_* come from CMake's project() (CMakeLists.txt): the header's macros
// cannot drift from the version the library is built as.
static_assert(BEZEL_VERSION_MAJOR == BEZEL_PROJECT_VERSION_MAJOR &&
                  BEZEL_VERSION_MINOR == BEZEL_PROJECT_VERSION_MINOR &&
                  BEZEL_VERSION_PATCH == BEZEL_PROJECT_VERSION_PATCH,
              "bezel.h's BEZEL_VERSION_* differ from CMakeLists.txt's project(VERSION)");

namespace {
constexpr bool same_text(const char* a, const char* b) {
    return *a == *b && (*a == '\0' || same_text(a + 1, b + 1));
}
}  // namespace
static_assert(same_text(BEZEL_VERSION_STRING, BEZEL_PROJECT_VERSION_STRING),
              "bezel.h's BEZEL_VERSION_STRING differs from CMakeLists.txt's project(VERSION)");

extern "C" {

const char* bezel_status_name(bezel_status status) {
    switch (raw_enum(status)) {
    case BEZEL_STATUS_OK: return "ok";
    case BEZEL_STATUS_INVALID_ARGUMENT: return "invalid argument";
    case BEZEL_STATUS_OUT_OF_RANGE: return "out of range";
    case BEZEL_STATUS_FILE_ERROR: return "file error";
    case BEZEL_STATUS_FONT_ERROR: return "font error";
    case BEZEL_STATUS_BUFFER_TOO_SMALL: return "buffer too small";
    case BEZEL_STATUS_OUT_OF_MEMORY: return "out of memory";
    case BEZEL_STATUS_INTERNAL: return "internal error";
    }
    return "unknown status";
}

const char* bezel_last_error(void) { return thread_error().c_str(); }

int bezel_version(void) {
    return BEZEL_VERSION_ENCODE(BEZEL_PROJECT_VERSION_MAJOR, BEZEL_PROJECT_VERSION_MINOR,
                                BEZEL_PROJECT_VERSION_PATCH);
}

const char* bezel_version_string(void) { return BEZEL_PROJECT_VERSION_STRING; }

}  // extern "C"
