// bezel_font: a FontFace read once, a Font of it for face-wide facts, and its coordinates.
#include <cstdint>
#include <fstream>
#include <memory>
#include <optional>
#include <sys/stat.h>

#include "bezel/limits.hpp"
#include "capi/handles.hpp"

using namespace bezel;
using namespace bezel::capi_detail;

namespace {

FontMemoryOptions memory_options(const bezel_font_options& o) {
    FontMemoryOptions m;
    m.face_index = o.face_index;
    if (o.name) m.name = o.name;
    return m;
}

// The status of a failed FontFace::open: FILE_ERROR when the file itself cannot be read (missing,
// a directory, unreadable), FONT_ERROR when it can and FreeType refuses its bytes. The message
// is FontFace's either way.
bezel_status open_failure_status(const char* path) {
    struct stat st {};
    if (stat(path, &st) != 0 || !S_ISREG(st.st_mode)) return BEZEL_STATUS_FILE_ERROR;
    std::ifstream in(path, std::ios::binary);
    return in ? BEZEL_STATUS_FONT_ERROR : BEZEL_STATUS_FILE_ERROR;
}

// The font of `face` at `variations`, as a new handle in *out.
bezel_status make_font(FontFace face, std::vector<VariationSetting> variations, bezel_font** out) {
    Expected<Font> font = Font::open(face);
    if (!font) return fail(nullptr, BEZEL_STATUS_FONT_ERROR, font.error().message);
    if (!variations.empty()) {
        Status set = font->set_variations(variations);
        if (!set) return fail(nullptr, BEZEL_STATUS_FONT_ERROR, set.error().message);
    }
    *out = new bezel_font{std::move(face), std::move(*font), std::move(variations), {}};
    return BEZEL_STATUS_OK;
}

bezel_status check_face_index(const char* function, int face_index) {
    if (face_index < 0 || face_index > kMaxFaceIndex)
        return fail(nullptr, BEZEL_STATUS_OUT_OF_RANGE,
                    std::string(function) + ": face index " + std::to_string(face_index) +
                        " is outside 0.." + std::to_string(kMaxFaceIndex));
    return BEZEL_STATUS_OK;
}

}  // namespace

extern "C" {

void bezel_font_options_init(bezel_font_options* options) {
    if (options) *options = bezel_font_options{0, nullptr, 0, 0, nullptr};
}

bezel_status bezel_font_open_file(const char* path, const bezel_font_options* options,
                                  bezel_font** out) {
    static const char* const fn = "bezel_font_open_file";
    return guarded(nullptr, fn, [&]() -> bezel_status {
        if (!path) return null_argument(nullptr, fn, "path");
        if (!out) return null_argument(nullptr, fn, "out");
        bezel_font_options o;
        bezel_font_options_init(&o);
        if (options) o = *options;
        if (bezel_status s = check_face_index(fn, o.face_index)) return s;
        std::vector<VariationSetting> variations;
        if (bezel_status s =
                to_variations(nullptr, fn, o.variations, o.variation_count, variations))
            return s;
        Expected<FontFace> face = FontFace::open(path, o.face_index);
        if (!face) return fail(nullptr, open_failure_status(path), face.error().message);
        return make_font(std::move(*face), std::move(variations), out);
    });
}

bezel_status bezel_font_open_memory(const void* data, std::size_t size,
                                    const bezel_font_options* options, bezel_font** out) {
    static const char* const fn = "bezel_font_open_memory";
    return guarded(nullptr, fn, [&]() -> bezel_status {
        if (!data) return null_argument(nullptr, fn, "data");
        if (!out) return null_argument(nullptr, fn, "out");
        bezel_font_options o;
        bezel_font_options_init(&o);
        if (options) o = *options;
        if (size == 0)
            return fail(nullptr, BEZEL_STATUS_INVALID_ARGUMENT,
                        std::string(fn) + ": " + (o.name ? o.name : "<memory>") +
                            ": no data (size 0)");
        if (size > kMaxFontBytes)
            return fail(nullptr, BEZEL_STATUS_OUT_OF_RANGE,
                        std::string(fn) + ": " + (o.name ? o.name : "<memory>") + ": " +
                            std::to_string(size) + " bytes is more than kMaxFontBytes (" +
                            std::to_string(kMaxFontBytes) + ")");
        if (bezel_status s = check_face_index(fn, o.face_index)) return s;
        std::vector<VariationSetting> variations;
        if (bezel_status s =
                to_variations(nullptr, fn, o.variations, o.variation_count, variations))
            return s;
        std::optional<Expected<FontFace>> face;
        if (o.copy_data) {
            const auto* bytes = static_cast<const std::uint8_t*>(data);
            auto copy = std::make_shared<const std::vector<std::uint8_t>>(bytes, bytes + size);
            face.emplace(FontFace::from_memory(std::move(copy), memory_options(o)));
        } else {
            face.emplace(FontFace::from_memory(data, size, memory_options(o)));
        }
        if (!*face) return fail(nullptr, BEZEL_STATUS_FONT_ERROR, face->error().message);
        return make_font(std::move(**face), std::move(variations), out);
    });
}

void bezel_font_destroy(bezel_font* font) { delete font; }

const char* bezel_font_last_error(const bezel_font* font) {
    return font ? font->error.c_str() : bezel_last_error();
}

bezel_status bezel_font_get_info(bezel_font* font, bezel_font_info* out) {
    static const char* const fn = "bezel_font_get_info";
    if (!font) return null_argument(nullptr, fn, "font");
    return guarded(&font->error, fn, [&]() -> bezel_status {
        if (!out) return null_argument(&font->error, fn, "out");
        const FontMetrics m = font->font.metrics();
        bezel_font_info info{};
        info.units_per_em = m.units_per_em;
        info.face_count = font->font.face_count();
        info.glyph_count = font->font.glyph_count();
        info.ascender = m.ascender;
        info.descender = m.descender;
        info.line_gap = m.line_gap;
        info.has_color = font->font.has_color_bitmaps() ? 1 : 0;
        *out = info;
        return BEZEL_STATUS_OK;
    });
}

bezel_status bezel_font_glyph_index(bezel_font* font, std::uint32_t code_point,
                                    std::uint32_t* gid) {
    static const char* const fn = "bezel_font_glyph_index";
    if (!font) return null_argument(nullptr, fn, "font");
    return guarded(&font->error, fn, [&]() -> bezel_status {
        if (!gid) return null_argument(&font->error, fn, "gid");
        if (code_point > 0x10FFFF)
            return fail(&font->error, BEZEL_STATUS_OUT_OF_RANGE,
                        font->font.file() + ": code point " + std::to_string(code_point) +
                            " is above U+10FFFF");
        *gid = font->font.glyph_for_char(static_cast<char32_t>(code_point)).value_or(0);
        return BEZEL_STATUS_OK;
    });
}

bezel_status bezel_font_set_variations(bezel_font* font, const bezel_variation* variations,
                                       std::size_t count) {
    static const char* const fn = "bezel_font_set_variations";
    if (!font) return null_argument(nullptr, fn, "font");
    return guarded(&font->error, fn, [&]() -> bezel_status {
        std::vector<VariationSetting> settings;
        if (bezel_status s = to_variations(&font->error, fn, variations, count, settings)) return s;
        Status set = font->font.set_variations(settings);
        if (!set) {
            // Back to the coordinates the handle had: a failed call changes nothing.
            (void)font->font.set_variations(font->variations);
            return fail(&font->error, BEZEL_STATUS_FONT_ERROR, set.error().message);
        }
        font->variations = std::move(settings);
        return BEZEL_STATUS_OK;
    });
}

}  // extern "C"
