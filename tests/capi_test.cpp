// The C API (bezel/bezel.h) against hostile calls: every entry point with NULL handles and NULL
// pointers, NULL and short buffers, zero and huge sizes, negative and too-small strides, invalid
// UTF-8, bad SVG data, a missing font file, truncated font bytes, options out of range. Every such
// call must return a non-OK status with a message (naming the function or the input) and leave
// the caller's memory untouched; none may crash (./dev test runs this under ASan + UBSan). And
// what the C API promises on good input that C++ callers could not see: sets equal single
// renders, copied and borrowed memory fonts equal file fonts, variations and their rollback,
// thread-local errors.
#include <gtest/gtest.h>

#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include "bezel/bezel.h"

namespace {

const std::string kFonts = BEZEL_FONTS_DIR;
const std::string kDejaVu = kFonts + "/dejavu-sans/DejaVuSans.ttf";
const std::string kVariable = kFonts + "/edge-cases/EdgeCasesVariable.ttf";

std::vector<std::uint8_t> read_bytes(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Stores the int `value` in an enum field as a C caller may (C allows any int there; in C++ an
// enum object holding a value outside its enumerators' range must not be loaded, so the bytes
// are written directly and the test never reads the field back). Enum ARGUMENTS out of range
// are tested from C, by tests/consumer/capi.c.
template <typename Enum>
void set_raw(Enum& field, int value) {
    static_assert(sizeof(Enum) == sizeof(int), "bezel.h's enums are int-sized");
    std::memcpy(&field, &value, sizeof value);
}

// A failed call: not OK, and the thread's message mentions `needle`.
void expect_failure(bezel_status status, const char* needle) {
    EXPECT_NE(status, BEZEL_STATUS_OK) << needle;
    const std::string message = bezel_last_error();
    EXPECT_NE(message.find(needle), std::string::npos)
        << "status " << bezel_status_name(status) << ", message \"" << message
        << "\" does not mention \"" << needle << "\"";
}

struct Font {
    bezel_font* font = nullptr;
    explicit Font(const std::string& file) {
        EXPECT_EQ(bezel_font_open_file(file.c_str(), nullptr, &font), BEZEL_STATUS_OK)
            << bezel_last_error();
    }
    ~Font() { bezel_font_destroy(font); }
};

struct Glyphs {
    bezel_glyph_rasterizer* r = nullptr;
    Glyphs(const bezel_font* font, double size_px, bezel_coverage coverage = BEZEL_COVERAGE_GRAY) {
        bezel_glyph_options o;
        bezel_glyph_options_init(&o);
        o.size_px = size_px;
        o.coverage = coverage;
        EXPECT_EQ(bezel_glyph_rasterizer_create(font, &o, &r), BEZEL_STATUS_OK) << bezel_last_error();
    }
    ~Glyphs() { bezel_glyph_rasterizer_destroy(r); }
};

struct Text {
    bezel_text_renderer* r = nullptr;
    explicit Text(bezel_font* font) {
        EXPECT_EQ(bezel_text_renderer_create(&font, 1, &r), BEZEL_STATUS_OK) << bezel_last_error();
    }
    ~Text() { bezel_text_renderer_destroy(r); }
};

TEST(CApi, NullHandlesFailWithAMessageNamingTheCall) {
    std::uint8_t byte = 0;
    std::uint32_t gid = 36;
    bezel_glyph_box box;
    bezel_glyph_target target{&byte, 1, 1};
    bezel_font_info info;
    bezel_int_rect rect;
    bezel_text_extent extent;
    expect_failure(bezel_font_get_info(nullptr, &info), "bezel_font_get_info: font is NULL");
    expect_failure(bezel_font_glyph_index(nullptr, 65, &gid), "bezel_font_glyph_index");
    expect_failure(bezel_font_set_variations(nullptr, nullptr, 0), "bezel_font_set_variations");
    expect_failure(bezel_glyph_rasterizer_create(nullptr, nullptr, nullptr),
                   "bezel_glyph_rasterizer_create: font is NULL");
    expect_failure(bezel_glyph_measure(nullptr, 1, &box), "bezel_glyph_measure");
    expect_failure(bezel_glyph_render(nullptr, 1, &byte, 1, 1, &box), "bezel_glyph_render");
    expect_failure(bezel_glyph_measure_set(nullptr, &gid, 1, &box), "bezel_glyph_measure_set");
    expect_failure(bezel_glyph_render_set(nullptr, &gid, 1, &target, &box),
                   "bezel_glyph_render_set");
    expect_failure(bezel_path_move_to(nullptr, 0, 0), "bezel_path_move_to");
    expect_failure(bezel_path_line_to(nullptr, 0, 0), "bezel_path_line_to");
    expect_failure(bezel_path_quad_to(nullptr, 0, 0, 1, 1), "bezel_path_quad_to");
    expect_failure(bezel_path_cubic_to(nullptr, 0, 0, 1, 1, 2, 2), "bezel_path_cubic_to");
    expect_failure(bezel_path_close(nullptr), "bezel_path_close");
    expect_failure(bezel_path_pixel_bounds(nullptr, nullptr, &rect), "bezel_path_pixel_bounds");
    expect_failure(bezel_rasterizer_fill(nullptr, nullptr, nullptr, nullptr, &byte, 1, 1, 1, 1),
                   "bezel_rasterizer_fill: rasterizer is NULL");
    expect_failure(bezel_text_renderer_create(nullptr, 1, nullptr),
                   "bezel_text_renderer_create: fonts is NULL");
    expect_failure(bezel_text_measure(nullptr, "a", 1, nullptr, &extent), "bezel_text_measure");
    expect_failure(bezel_text_render(nullptr, "a", 1, nullptr, BEZEL_PIXEL_GRAY8, &byte, 1, 1,
                                     &extent),
                   "bezel_text_render");
    expect_failure(bezel_text_draw(nullptr, "a", 1, nullptr, BEZEL_PIXEL_GRAY8, &byte, 1, 1, 1, 1,
                                   0, 0),
                   "bezel_text_draw");
    // Constructors without somewhere to put the handle.
    expect_failure(bezel_font_open_file(kDejaVu.c_str(), nullptr, nullptr), "out is NULL");
    expect_failure(bezel_font_open_file(nullptr, nullptr, nullptr), "path is NULL");
    expect_failure(bezel_font_open_memory(nullptr, 10, nullptr, nullptr), "data is NULL");
    expect_failure(bezel_path_create(nullptr), "bezel_path_create: out is NULL");
    expect_failure(bezel_path_from_svg("M0 0", 4, nullptr), "out is NULL");
    expect_failure(bezel_rasterizer_create(nullptr), "bezel_rasterizer_create: out is NULL");
    // Accessors and destructors take NULL.
    EXPECT_STREQ(bezel_font_last_error(nullptr), bezel_last_error());
    EXPECT_STREQ(bezel_glyph_rasterizer_last_error(nullptr), bezel_last_error());
    EXPECT_STREQ(bezel_path_last_error(nullptr), bezel_last_error());
    EXPECT_STREQ(bezel_rasterizer_last_error(nullptr), bezel_last_error());
    EXPECT_STREQ(bezel_text_renderer_last_error(nullptr), bezel_last_error());
    bezel_font_destroy(nullptr);
    bezel_glyph_rasterizer_destroy(nullptr);
    bezel_path_destroy(nullptr);
    bezel_rasterizer_destroy(nullptr);
    bezel_text_renderer_destroy(nullptr);
    bezel_font_options_init(nullptr);
    bezel_glyph_options_init(nullptr);
    bezel_fill_options_init(nullptr);
    bezel_text_options_init(nullptr);
}

TEST(CApi, MissingUnreadableAndTruncatedFontsAreNamedErrors) {
    bezel_font* font = nullptr;
    EXPECT_EQ(bezel_font_open_file("/nonexistent/a.ttf", nullptr, &font), BEZEL_STATUS_FILE_ERROR);
    expect_failure(BEZEL_STATUS_FILE_ERROR, "/nonexistent/a.ttf");
    EXPECT_EQ(bezel_font_open_file(kFonts.c_str(), nullptr, &font), BEZEL_STATUS_FILE_ERROR);
    expect_failure(BEZEL_STATUS_FILE_ERROR, kFonts.c_str());
    EXPECT_EQ(font, nullptr);
    // A file that is not a font: a font error naming it.
    const std::string readme = kFonts + "/dejavu-sans/README.md";
    EXPECT_EQ(bezel_font_open_file(readme.c_str(), nullptr, &font), BEZEL_STATUS_FONT_ERROR);
    expect_failure(BEZEL_STATUS_FONT_ERROR, "README.md");

    const std::vector<std::uint8_t> bytes = read_bytes(kDejaVu);
    ASSERT_GT(bytes.size(), 1000u);
    bezel_font_options o;
    bezel_font_options_init(&o);
    o.name = "truncated.ttf";
    for (int copy = 0; copy < 2; ++copy) {
        o.copy_data = copy;
        for (std::size_t size : {std::size_t{1}, std::size_t{12}, std::size_t{100},
                                 std::size_t{1000}}) {
            const bezel_status s = bezel_font_open_memory(bytes.data(), size, &o, &font);
            EXPECT_EQ(s, BEZEL_STATUS_FONT_ERROR) << size;
            expect_failure(s, "truncated.ttf");
            EXPECT_EQ(font, nullptr);
        }
    }
    expect_failure(bezel_font_open_memory(bytes.data(), 0, &o, &font), "no data");
    // Face indices: negative and past the count.
    o.face_index = -1;
    EXPECT_EQ(bezel_font_open_file(kDejaVu.c_str(), &o, &font), BEZEL_STATUS_OUT_OF_RANGE);
    o.face_index = 3;
    expect_failure(bezel_font_open_file(kDejaVu.c_str(), &o, &font), "DejaVuSans.ttf");
    // Half a font may open (FreeType reads tables lazily) but every glyph it draws is either
    // drawn or an error, never a crash.
    o.face_index = 0;
    o.copy_data = 1;
    if (bezel_font_open_memory(bytes.data(), bytes.size() / 2, &o, &font) == BEZEL_STATUS_OK) {
        Glyphs g(font, 20);
        bezel_glyph_box box;
        std::vector<std::uint8_t> buffer(100 * 100);
        for (std::uint32_t gid = 0; gid < 3000 && g.r; gid += 7) {
            if (bezel_glyph_render(g.r, gid, buffer.data(), buffer.size(), 100, &box) !=
                BEZEL_STATUS_OK) {
                EXPECT_STRNE(bezel_glyph_rasterizer_last_error(g.r), "");
            }
        }
        bezel_font_destroy(font);
    }
}

TEST(CApi, OptionsOutOfRangeAreRefusedByName) {
    Font f(kDejaVu);
    bezel_glyph_rasterizer* r = nullptr;
    bezel_glyph_options o;
    const auto refused = [&](const char* needle) {
        expect_failure(bezel_glyph_rasterizer_create(f.font, &o, &r), needle);
        EXPECT_EQ(r, nullptr);
        bezel_glyph_options_init(&o);
    };
    bezel_glyph_options_init(&o);
    for (double size : {0.0, -1.0, 1e9, std::nan(""), HUGE_VAL}) {
        o.size_px = size;
        refused("size_px");
    }
    o.offset_x_px = std::nan("");
    refused("offset");
    o.slant = 2;
    refused("slant");
    o.bold = -0.1;
    refused("bold");
    set_raw(o.hinting, 99);
    refused("hinting 99");
    set_raw(o.coverage, -3);
    refused("coverage -3");

    bezel_variation bad_tag{"wg", 1};
    expect_failure(bezel_font_set_variations(f.font, &bad_tag, 1), "4 characters");
    bezel_variation unknown{"ZZZZ", 1};
    expect_failure(bezel_font_set_variations(f.font, &unknown, 1), "ZZZZ");
    expect_failure(bezel_font_set_variations(f.font, nullptr, 2), "variations");
    std::uint32_t gid = 0;
    EXPECT_EQ(bezel_font_glyph_index(f.font, 0x110000, &gid), BEZEL_STATUS_OUT_OF_RANGE);

    Text t(f.font);
    bezel_text_options to;
    bezel_text_extent extent;
    bezel_text_options_init(&to);
    to.size_px = 0;
    expect_failure(bezel_text_measure(t.r, "a", 1, &to, &extent), "size_px");
    bezel_text_options_init(&to);
    to.width_px = -5;
    EXPECT_NE(bezel_text_measure(t.r, "a", 1, &to, &extent), BEZEL_STATUS_OK);
    EXPECT_STRNE(bezel_text_renderer_last_error(t.r), "");
    bezel_text_options_init(&to);
    set_raw(to.align, 7);
    expect_failure(bezel_text_measure(t.r, "a", 1, &to, &extent), "align 7");
    bezel_text_options_init(&to);
    std::uint8_t px[16] = {};
    to.coverage = BEZEL_COVERAGE_LCD_RGB;
    expect_failure(bezel_text_render(t.r, "a", 1, &to, BEZEL_PIXEL_GRAY8, px, sizeof px, 4,
                                     nullptr),
                   "GRAY8");
    to.background.a = 0;
    expect_failure(bezel_text_render(t.r, "a", 1, &to, BEZEL_PIXEL_RGBA8, px, sizeof px, 16,
                                     nullptr),
                   "opaque");
    bezel_font* fonts[2] = {f.font, nullptr};
    bezel_text_renderer* tr = nullptr;
    expect_failure(bezel_text_renderer_create(fonts, 0, &tr), "font_count 0");
    expect_failure(bezel_text_renderer_create(fonts, 1000, &tr), "font_count 1000");
    expect_failure(bezel_text_renderer_create(fonts, 2, &tr), "fonts[1] is NULL");
}

// Buffers the call cannot write: NULL, empty, short by one byte, a stride below a row, negative,
// overflowing. Each is refused and the caller's bytes stay as they were.
TEST(CApi, BadBuffersAreRefusedAndLeftUntouched) {
    Font f(kDejaVu);
    Glyphs g(f.font, 32);
    bezel_glyph_box box;
    ASSERT_EQ(bezel_glyph_measure(g.r, 36, &box), BEZEL_STATUS_OK) << bezel_last_error();
    ASSERT_GT(box.width, 0);
    const std::size_t exact = box.buffer_size;
    std::vector<std::uint8_t> buffer(exact + 64, 0xCD);
    struct Case {
        std::uint8_t* data;
        std::size_t size;
        std::ptrdiff_t stride;
        bezel_status expected;
    };
    const Case cases[] = {
        {nullptr, 0, box.row_bytes, BEZEL_STATUS_BUFFER_TOO_SMALL},
        {nullptr, exact, box.row_bytes, BEZEL_STATUS_BUFFER_TOO_SMALL},
        {buffer.data(), 0, box.row_bytes, BEZEL_STATUS_BUFFER_TOO_SMALL},
        {buffer.data(), exact - 1, box.row_bytes, BEZEL_STATUS_BUFFER_TOO_SMALL},
        {buffer.data(), exact, box.row_bytes - 1, BEZEL_STATUS_BUFFER_TOO_SMALL},
        {buffer.data(), exact, 0, BEZEL_STATUS_BUFFER_TOO_SMALL},
        {buffer.data(), exact, -box.row_bytes, BEZEL_STATUS_INVALID_ARGUMENT},
        {buffer.data(), exact, PTRDIFF_MAX, BEZEL_STATUS_BUFFER_TOO_SMALL},
        {buffer.data(), SIZE_MAX, PTRDIFF_MAX, BEZEL_STATUS_BUFFER_TOO_SMALL},
    };
    for (const Case& c : cases) {
        EXPECT_EQ(bezel_glyph_render(g.r, 36, c.data, c.size, c.stride, nullptr), c.expected)
            << c.size << " " << c.stride;
        EXPECT_NE(std::string(bezel_glyph_rasterizer_last_error(g.r)).find("glyph 36"),
                  std::string::npos)
            << bezel_glyph_rasterizer_last_error(g.r);
        const bezel_glyph_target target{c.data, c.size, c.stride};
        const std::uint32_t gid = 36;
        EXPECT_EQ(bezel_glyph_render_set(g.r, &gid, 1, &target, nullptr), c.expected);
        expect_failure(c.expected, "glyph set index 0");
    }
    for (std::uint8_t b : buffer) ASSERT_EQ(b, 0xCD);
    EXPECT_EQ(bezel_glyph_render(g.r, 36, buffer.data(), exact, box.row_bytes, nullptr),
              BEZEL_STATUS_OK);
    EXPECT_EQ(buffer[exact], 0xCD);   // nothing past the box

    // The rasterizer: sizes past the limit, negative, and the same buffer cases.
    bezel_path* path = nullptr;
    ASSERT_EQ(bezel_path_from_svg("M1 1 L7 1 L4 7 Z", 16, &path), BEZEL_STATUS_OK);
    bezel_rasterizer* raster = nullptr;
    ASSERT_EQ(bezel_rasterizer_create(&raster), BEZEL_STATUS_OK);
    std::vector<std::uint8_t> mask(64, 0xCD);
    EXPECT_EQ(bezel_rasterizer_fill(raster, path, nullptr, nullptr, mask.data(), mask.size(),
                                    INT_MAX, 8, 8),
              BEZEL_STATUS_OUT_OF_RANGE);
    EXPECT_EQ(bezel_rasterizer_fill(raster, path, nullptr, nullptr, mask.data(), mask.size(), 8,
                                    -1, 8),
              BEZEL_STATUS_OUT_OF_RANGE);
    EXPECT_EQ(bezel_rasterizer_fill(raster, path, nullptr, nullptr, mask.data(), 63, 8, 8, 8),
              BEZEL_STATUS_BUFFER_TOO_SMALL);
    EXPECT_EQ(bezel_rasterizer_fill(raster, path, nullptr, nullptr, mask.data(), 64, 8, 8, 7),
              BEZEL_STATUS_BUFFER_TOO_SMALL);
    EXPECT_EQ(bezel_rasterizer_fill(raster, path, nullptr, nullptr, mask.data(), 64, 8, 8, -8),
              BEZEL_STATUS_INVALID_ARGUMENT);
    EXPECT_EQ(bezel_rasterizer_fill(raster, path, nullptr, nullptr, nullptr, 64, 8, 8, 8),
              BEZEL_STATUS_BUFFER_TOO_SMALL);
    bezel_fill_options lcd;
    bezel_fill_options_init(&lcd);
    lcd.coverage = BEZEL_COVERAGE_LCD_RGB;   // 3 bytes a pixel: 8 px need 24 a row
    EXPECT_EQ(bezel_rasterizer_fill(raster, path, nullptr, &lcd, mask.data(), 64, 8, 2, 8),
              BEZEL_STATUS_BUFFER_TOO_SMALL);
    for (std::uint8_t b : mask) ASSERT_EQ(b, 0xCD);
    // A zero-sized mask needs no buffer and writes nothing.
    EXPECT_EQ(bezel_rasterizer_fill(raster, path, nullptr, nullptr, nullptr, 0, 0, 0, 0),
              BEZEL_STATUS_OK);
    const bezel_transform nan_transform{std::nan(""), 0, 0, 1, 0, 0};
    EXPECT_NE(bezel_rasterizer_fill(raster, path, &nan_transform, nullptr, mask.data(), 64, 8, 8,
                                    8),
              BEZEL_STATUS_OK);
    EXPECT_STRNE(bezel_rasterizer_last_error(raster), "");
    bezel_fill_options bad_fill;
    bezel_fill_options_init(&bad_fill);
    bad_fill.tolerance_px = 0;
    expect_failure(bezel_rasterizer_fill(raster, path, nullptr, &bad_fill, mask.data(), 64, 8, 8,
                                         8),
                   "tolerance_px");
    bezel_fill_options_init(&bad_fill);
    set_raw(bad_fill.rule, 5);
    expect_failure(bezel_rasterizer_fill(raster, path, nullptr, &bad_fill, mask.data(), 64, 8, 8,
                                         8),
                   "rule 5");
    for (std::uint8_t b : mask) ASSERT_EQ(b, 0xCD);
    bezel_rasterizer_destroy(raster);
    bezel_path_destroy(path);

    // Text: render's query and short buffers; draw's surfaces.
    Text t(f.font);
    bezel_text_extent extent;
    ASSERT_EQ(bezel_text_measure(t.r, "Hi", 2, nullptr, &extent), BEZEL_STATUS_OK);
    const std::size_t page = static_cast<std::size_t>(extent.width) * extent.height * 4;
    std::vector<std::uint8_t> pixels(page, 0xCD);
    EXPECT_EQ(bezel_text_render(t.r, "Hi", 2, nullptr, BEZEL_PIXEL_RGBA8, pixels.data(), page - 1,
                                extent.width * 4, nullptr),
              BEZEL_STATUS_BUFFER_TOO_SMALL);
    EXPECT_EQ(bezel_text_render(t.r, "Hi", 2, nullptr, BEZEL_PIXEL_RGBA8, pixels.data(), page,
                                extent.width * 4 - 1, nullptr),
              BEZEL_STATUS_BUFFER_TOO_SMALL);
    EXPECT_EQ(bezel_text_render(t.r, "Hi", 2, nullptr, BEZEL_PIXEL_RGBA8, pixels.data(), page,
                                -extent.width * 4, nullptr),
              BEZEL_STATUS_INVALID_ARGUMENT);
    EXPECT_EQ(bezel_text_draw(t.r, "Hi", 2, nullptr, BEZEL_PIXEL_RGBA8, pixels.data(), page,
                              INT_MAX, 1, PTRDIFF_MAX, 0, 0),
              BEZEL_STATUS_OUT_OF_RANGE);
    EXPECT_EQ(bezel_text_draw(t.r, "Hi", 2, nullptr, BEZEL_PIXEL_RGBA8, pixels.data(), page,
                              extent.width, extent.height + 1, extent.width * 4, 0, 0),
              BEZEL_STATUS_BUFFER_TOO_SMALL);
    EXPECT_EQ(bezel_text_draw(t.r, "Hi", 2, nullptr, BEZEL_PIXEL_RGBA8, pixels.data(), page,
                              extent.width, extent.height, extent.width * 4, std::nan(""), 0),
              BEZEL_STATUS_INVALID_ARGUMENT);
    for (std::uint8_t b : pixels) ASSERT_EQ(b, 0xCD);
    EXPECT_EQ(bezel_text_draw(t.r, "Hi", 2, nullptr, BEZEL_PIXEL_RGBA8, nullptr, 0, 0, 0, 0, 0, 0),
              BEZEL_STATUS_OK);
}

TEST(CApi, InvalidUtf8IsAnErrorNamingTheByte) {
    Font f(kDejaVu);
    Text t(f.font);
    bezel_text_extent extent;
    std::vector<std::uint8_t> page(64 * 64 * 4, 0xCD);
    const std::string bad[] = {"\xff", "ab\xc3", "\xc0\xaf", "\xed\xa0\x80", "a\xf4\x90\x80\x80",
                               std::string("x\x80y", 3)};
    for (const std::string& text : bad) {
        expect_failure(bezel_text_measure(t.r, text.data(), text.size(), nullptr, &extent),
                       "UTF-8");
        expect_failure(bezel_text_render(t.r, text.data(), text.size(), nullptr,
                                         BEZEL_PIXEL_RGBA8, page.data(), page.size(), 256,
                                         nullptr),
                       "UTF-8");
        expect_failure(bezel_text_draw(t.r, text.data(), text.size(), nullptr, BEZEL_PIXEL_RGBA8,
                                       page.data(), page.size(), 64, 64, 256, 0, 0),
                       "UTF-8");
    }
    for (std::uint8_t b : page) ASSERT_EQ(b, 0xCD);
    expect_failure(bezel_text_measure(t.r, nullptr, 5, nullptr, &extent), "utf8");
    // An empty text is a page of one empty line, not an error.
    EXPECT_EQ(bezel_text_measure(t.r, nullptr, 0, nullptr, &extent), BEZEL_STATUS_OK);
    EXPECT_EQ(extent.line_count, 1u);
}

TEST(CApi, BadSvgPathDataNamesTheOffset) {
    const char* bad[] = {"L 1 1", "M 0 0 L 1", "M 0 0 Q 1 1 2", "M 1e999 0", "M 0 0 A 1 1 0 2 0 1 1",
                         "M 0 0 X 1 1", "M0,0 L1,1,", "M 0 0 L nan 0"};
    for (const char* data : bad) {
        bezel_path* path = nullptr;
        expect_failure(bezel_path_from_svg(data, std::strlen(data), &path), "path data offset");
        EXPECT_EQ(path, nullptr) << data;
    }
    bezel_path* path = nullptr;
    expect_failure(bezel_path_from_svg(nullptr, 4, &path), "data is NULL");
    expect_failure(bezel_path_from_svg("M0 0", SIZE_MAX, &path), "kMaxSvgPathLength");
    // Length is honoured: a valid prefix of a bad string parses.
    ASSERT_EQ(bezel_path_from_svg("M0 0 L4 0 L4 4 Zjunk", 15, &path), BEZEL_STATUS_OK);
    bezel_int_rect box;
    EXPECT_EQ(bezel_path_pixel_bounds(path, nullptr, &box), BEZEL_STATUS_OK);
    EXPECT_EQ(box.x1, 4);
    const bezel_transform huge{1e300, 0, 0, 1e300, 0, 0};
    expect_failure(bezel_path_pixel_bounds(path, &huge, &box), "2^30");
    // The builder refuses non-finite points and leaves the path as it was.
    expect_failure(bezel_path_line_to(path, std::nan(""), 0), "not finite");
    expect_failure(bezel_path_cubic_to(path, 0, 0, HUGE_VAL, 0, 1, 1), "not finite");
    EXPECT_EQ(bezel_path_pixel_bounds(path, nullptr, &box), BEZEL_STATUS_OK);
    EXPECT_EQ(box.x1, 4);
    bezel_path_destroy(path);
}

// A path built from verbs fills as the same SVG data does, byte for byte.
TEST(CApi, VerbsAndSvgDataFillTheSamePixels) {
    bezel_path* built = nullptr;
    bezel_path* parsed = nullptr;
    ASSERT_EQ(bezel_path_create(&built), BEZEL_STATUS_OK);
    EXPECT_EQ(bezel_path_move_to(built, 1, 1), BEZEL_STATUS_OK);
    EXPECT_EQ(bezel_path_line_to(built, 14, 2), BEZEL_STATUS_OK);
    EXPECT_EQ(bezel_path_quad_to(built, 15, 9, 9, 14), BEZEL_STATUS_OK);
    EXPECT_EQ(bezel_path_cubic_to(built, 6, 15, 2, 10, 1.5, 6.25), BEZEL_STATUS_OK);
    EXPECT_EQ(bezel_path_close(built), BEZEL_STATUS_OK);
    const char* svg = "M1 1 L14 2 Q15 9 9 14 C6 15 2 10 1.5 6.25 Z";
    ASSERT_EQ(bezel_path_from_svg(svg, std::strlen(svg), &parsed), BEZEL_STATUS_OK);
    bezel_rasterizer* raster = nullptr;
    ASSERT_EQ(bezel_rasterizer_create(&raster), BEZEL_STATUS_OK);
    std::vector<std::uint8_t> a(16 * 20, 7), b(16 * 20, 9);
    const bezel_transform shift{1, 0, 0, 1, 0.25, 0.5};
    ASSERT_EQ(bezel_rasterizer_fill(raster, built, &shift, nullptr, a.data(), a.size(), 16, 16, 20),
              BEZEL_STATUS_OK);
    ASSERT_EQ(bezel_rasterizer_fill(raster, parsed, &shift, nullptr, b.data(), b.size(), 16, 16, 20),
              BEZEL_STATUS_OK);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) ASSERT_EQ(a[y * 20 + x], b[y * 20 + x]) << x << "," << y;
    EXPECT_EQ(a[8 * 20 + 8], 255);
    EXPECT_EQ(a[15 * 20 + 15], 0);
    EXPECT_EQ(a[3 * 20 + 17], 7);   // the stride's padding
    bezel_rasterizer_destroy(raster);
    bezel_path_destroy(built);
    bezel_path_destroy(parsed);
}

// A set is drawn as each glyph alone would be, LCD boxes are three bytes a pixel, and memory
// fonts (borrowed or copied, the bytes freed) draw as the file does.
TEST(CApi, SetsAndMemoryFontsDrawAsSingleFileGlyphs) {
    Font file(kDejaVu);
    std::vector<std::uint8_t> bytes = read_bytes(kDejaVu);
    bezel_font* copied = nullptr;
    bezel_font_options o;
    bezel_font_options_init(&o);
    o.copy_data = 1;
    ASSERT_EQ(bezel_font_open_memory(bytes.data(), bytes.size(), &o, &copied), BEZEL_STATUS_OK);
    std::fill(bytes.begin(), bytes.end(), 0);   // the copy must not need them
    bytes.clear();
    bytes.shrink_to_fit();
    Glyphs from_file(file.font, 18, BEZEL_COVERAGE_LCD_BGR);
    Glyphs from_memory(copied, 18, BEZEL_COVERAGE_LCD_BGR);
    bezel_font_destroy(copied);   // the rasterizer keeps its own instance

    const std::vector<std::uint32_t> gids = {36, 3, 72, 0, 1000};
    std::vector<bezel_glyph_box> boxes(gids.size());
    ASSERT_EQ(bezel_glyph_measure_set(from_memory.r, gids.data(), gids.size(), boxes.data()),
              BEZEL_STATUS_OK)
        << bezel_last_error();
    std::vector<std::vector<std::uint8_t>> set(gids.size());
    std::vector<bezel_glyph_target> targets(gids.size());
    for (std::size_t k = 0; k < gids.size(); ++k) {
        EXPECT_EQ(boxes[k].row_bytes, boxes[k].width * 3);
        set[k].assign(boxes[k].buffer_size, 0x5A);
        targets[k] = {set[k].data(), set[k].size(), boxes[k].row_bytes};
    }
    ASSERT_EQ(bezel_glyph_render_set(from_memory.r, gids.data(), gids.size(), targets.data(),
                                     nullptr),
              BEZEL_STATUS_OK)
        << bezel_last_error();
    for (std::size_t k = 0; k < gids.size(); ++k) {
        std::vector<std::uint8_t> single(boxes[k].buffer_size, 0xA5);
        bezel_glyph_box box;
        ASSERT_EQ(bezel_glyph_render(from_file.r, gids[k], single.data(), single.size(),
                                     boxes[k].row_bytes, &box),
                  BEZEL_STATUS_OK);
        EXPECT_EQ(box.width, boxes[k].width);
        EXPECT_EQ(single, set[k]) << "glyph " << gids[k];
    }
    // A glyph id past the font fails the whole set before anything is drawn.
    const std::uint32_t with_bad[] = {36, 999999};
    std::vector<std::uint8_t> sentinel(boxes[0].buffer_size, 0x77);
    const bezel_glyph_target bad_targets[] = {{sentinel.data(), sentinel.size(), boxes[0].row_bytes},
                                              {nullptr, 0, 0}};
    EXPECT_EQ(bezel_glyph_render_set(from_file.r, with_bad, 2, bad_targets, nullptr),
              BEZEL_STATUS_FONT_ERROR);
    EXPECT_NE(std::string(bezel_glyph_rasterizer_last_error(from_file.r)).find("999999"),
              std::string::npos)
        << bezel_glyph_rasterizer_last_error(from_file.r);
    for (std::uint8_t b : sentinel) ASSERT_EQ(b, 0x77);
}

// Variations: set on the font, taken by a rasterizer made after; an unknown axis changes
// nothing.
TEST(CApi, VariationsReachRasterizersAndAFailedSetChangesNothing) {
    Font f(kVariable);
    std::uint32_t gid = 0;
    ASSERT_EQ(bezel_font_glyph_index(f.font, 'I', &gid), BEZEL_STATUS_OK);
    ASSERT_NE(gid, 0u);
    const auto advance = [&] {
        Glyphs g(f.font, 1000);
        bezel_glyph_box box{};
        EXPECT_EQ(bezel_glyph_measure(g.r, gid, &box), BEZEL_STATUS_OK) << bezel_last_error();
        return box.advance_px;
    };
    EXPECT_DOUBLE_EQ(advance(), 400);
    const bezel_variation black{"wght", 900};
    ASSERT_EQ(bezel_font_set_variations(f.font, &black, 1), BEZEL_STATUS_OK) << bezel_last_error();
    EXPECT_DOUBLE_EQ(advance(), 600);
    const bezel_variation bad[] = {{"wght", 100}, {"ZZZZ", 1}};
    EXPECT_EQ(bezel_font_set_variations(f.font, bad, 2), BEZEL_STATUS_FONT_ERROR);
    EXPECT_NE(std::string(bezel_font_last_error(f.font)).find("ZZZZ"), std::string::npos);
    EXPECT_DOUBLE_EQ(advance(), 600);
    // Opened at a coordinate.
    bezel_font_options o;
    bezel_font_options_init(&o);
    const bezel_variation light{"wght", 100};
    o.variations = &light;
    o.variation_count = 1;
    bezel_font* thin = nullptr;
    ASSERT_EQ(bezel_font_open_file(kVariable.c_str(), &o, &thin), BEZEL_STATUS_OK);
    {
        Glyphs g(thin, 1000);
        bezel_glyph_box box{};
        EXPECT_EQ(bezel_glyph_measure(g.r, gid, &box), BEZEL_STATUS_OK);
        EXPECT_DOUBLE_EQ(box.advance_px, 300);
    }
    bezel_font_destroy(thin);
}

// bezel_last_error is the calling thread's: another thread's failure does not change it.
TEST(CApi, ThreadLastErrorIsPerThread) {
    bezel_path* path = nullptr;
    ASSERT_NE(bezel_path_from_svg("M 0 0 L q", 9, &path), BEZEL_STATUS_OK);
    const std::string mine = bezel_last_error();
    std::string theirs;
    std::thread other([&] {
        bezel_font* font = nullptr;
        (void)bezel_font_open_file("/nonexistent/other.ttf", nullptr, &font);
        theirs = bezel_last_error();
    });
    other.join();
    EXPECT_NE(theirs.find("other.ttf"), std::string::npos);
    EXPECT_EQ(mine, bezel_last_error());
}

TEST(CApi, VersionMacrosAreTheLibraryVersion) {
    EXPECT_EQ(bezel_version(), BEZEL_VERSION);
    EXPECT_STREQ(bezel_version_string(), BEZEL_VERSION_STRING);
    EXPECT_EQ(std::to_string(BEZEL_VERSION_MAJOR) + "." + std::to_string(BEZEL_VERSION_MINOR) +
                  "." + std::to_string(BEZEL_VERSION_PATCH),
              BEZEL_VERSION_STRING);
}

}  // namespace
