/* A C program using the installed C API (bezel/bezel.h, libbezel_c.so), compiled as C11 with
 * -Wall -Wextra -Werror -pedantic by tests/consumer/run.cmake, once through pkg-config and once
 * through CMake's bezel::bezel_c. It renders a glyph and a line of text from the font given as
 * argv[1] (DejaVu Sans) into its own buffers and checks the pixels, the size queries and the
 * errors of bad calls. Exit 0 when every check holds; each failure is printed. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <bezel/bezel.h>

static int failures = 0;

#define CHECK(cond)                                                        \
    do {                                                                   \
        if (!(cond)) {                                                     \
            fprintf(stderr, "capi.c:%d: check failed: %s\n", __LINE__, #cond); \
            ++failures;                                                    \
        }                                                                  \
    } while (0)

#define CHECK_OK(call)                                                                  \
    do {                                                                                \
        bezel_status s_ = (call);                                                       \
        if (s_ != BEZEL_STATUS_OK) {                                                    \
            fprintf(stderr, "capi.c:%d: %s: %s: %s\n", __LINE__, #call,                 \
                    bezel_status_name(s_), bezel_last_error());                         \
            ++failures;                                                                 \
        }                                                                               \
    } while (0)

/* The header's version is the library's. */
static void check_version(void) {
    CHECK(bezel_version() == BEZEL_VERSION);
    CHECK(strcmp(bezel_version_string(), BEZEL_VERSION_STRING) == 0);
    CHECK(BEZEL_VERSION == BEZEL_VERSION_MAJOR * 10000 + BEZEL_VERSION_MINOR * 100 +
                               BEZEL_VERSION_PATCH);
}

/* 'H' at 40 px: two stems joined by a bar; the size query first, then a padded buffer. */
static void check_glyph(bezel_font* font) {
    bezel_glyph_options options;
    bezel_glyph_rasterizer* raster = NULL;
    bezel_glyph_box box, queried;
    uint32_t gid = 0;
    uint8_t* buffer;
    ptrdiff_t stride;
    size_t size;
    int x, y, stem_left = 0, gap = 0, bar = 0, top_row_middle;

    bezel_glyph_options_init(&options);
    options.size_px = 40;
    CHECK_OK(bezel_glyph_rasterizer_create(font, &options, &raster));
    CHECK_OK(bezel_font_glyph_index(font, 'H', &gid));
    CHECK(gid != 0);
    CHECK_OK(bezel_glyph_measure(raster, gid, &box));
    /* DejaVu Sans 'H': cap height 0.729 em ≈ 29 px, about 0.6 em wide, on the baseline. */
    CHECK(box.height >= 29 && box.height <= 31);
    CHECK(box.width >= 20 && box.width <= 26);
    CHECK(box.top >= 29 && box.top <= 31);
    CHECK(box.row_bytes == box.width);
    CHECK(box.buffer_size == (size_t)box.width * (size_t)box.height);
    CHECK(box.advance_px > 29 && box.advance_px < 31);   /* 1540/2048 em */

    /* The query: no buffer, BUFFER_TOO_SMALL, the box filled in. */
    memset(&queried, 0, sizeof queried);
    CHECK(bezel_glyph_render(raster, gid, NULL, 0, box.row_bytes, &queried) ==
          BEZEL_STATUS_BUFFER_TOO_SMALL);
    CHECK(queried.width == box.width && queried.height == box.height);
    CHECK(strstr(bezel_glyph_rasterizer_last_error(raster), "glyph") != NULL);

    stride = box.row_bytes + 5;   /* padding that must stay untouched */
    size = (size_t)stride * (size_t)box.height;
    buffer = malloc(size);
    CHECK(buffer != NULL);
    if (!buffer) return;
    memset(buffer, 0xAB, size);
    /* One byte short: refused, nothing written. */
    CHECK(bezel_glyph_render(raster, gid, buffer, size - 6, stride, NULL) ==
          BEZEL_STATUS_BUFFER_TOO_SMALL);
    CHECK(buffer[0] == 0xAB);
    CHECK_OK(bezel_glyph_render(raster, gid, buffer, size, stride, NULL));
    for (y = 0; y < box.height; ++y)
        for (x = box.row_bytes; x < stride; ++x) CHECK(buffer[y * stride + x] == 0xAB);
    /* The left stem is solid ink down the glyph; between the stems, above the bar, is empty;
       the bar near mid-height is solid across. */
    top_row_middle = buffer[2 * stride + box.width / 2];
    for (y = 2; y < box.height - 2; ++y) stem_left += buffer[y * stride + 2] == 255;
    gap = top_row_middle;
    for (x = 2; x < box.width - 2; ++x) bar += buffer[(box.height / 2) * stride + x] == 255;
    CHECK(stem_left == box.height - 4);
    CHECK(gap == 0);
    CHECK(bar == box.width - 4);
    free(buffer);
    bezel_glyph_rasterizer_destroy(raster);
}

/* A line of text in gray: the page size from the query, white background, black ink on the
   line, nothing outside the page touched. */
static void check_text(bezel_font* font) {
    const char* text = "Hello, bezel";
    bezel_text_renderer* renderer = NULL;
    bezel_text_options options;
    bezel_text_extent extent, queried;
    uint8_t* page;
    ptrdiff_t stride;
    size_t size;
    int x, y, ink = 0, ink_above = 0, background_ok = 1;

    CHECK_OK(bezel_text_renderer_create(&font, 1, &renderer));
    bezel_text_options_init(&options);
    options.size_px = 24;
    options.margin_px = 4;
    CHECK_OK(bezel_text_measure(renderer, text, strlen(text), &options, &extent));
    CHECK(extent.line_count == 1);
    CHECK(extent.missing_glyphs == 0);
    CHECK(extent.width > 100 && extent.width < 200);   /* 12 characters at ~0.55 em */
    CHECK(extent.height >= 28 + 8 && extent.height <= 30 + 8);   /* line height + margins */
    CHECK(extent.first_baseline_px > 4 + 20 && extent.first_baseline_px < 4 + 24);

    memset(&queried, 0, sizeof queried);
    CHECK(bezel_text_render(renderer, text, strlen(text), &options, BEZEL_PIXEL_GRAY8, NULL, 0,
                            0, &queried) == BEZEL_STATUS_BUFFER_TOO_SMALL);
    CHECK(queried.width == extent.width && queried.height == extent.height);

    stride = extent.width + 3;
    size = (size_t)stride * (size_t)extent.height;
    page = malloc(size);
    CHECK(page != NULL);
    if (!page) return;
    memset(page, 0x11, size);
    CHECK_OK(bezel_text_render(renderer, text, strlen(text), &options, BEZEL_PIXEL_GRAY8, page,
                               size, stride, NULL));
    for (y = 0; y < extent.height; ++y) {
        for (x = 0; x < extent.width; ++x) {
            const int v = page[y * stride + x];
            if (v < 64 && y < (int)extent.first_baseline_px && y > 4) ++ink;
            if (v != 255 && (y < 3 || x < 3)) background_ok = 0;   /* inside the margin */
            if (v != 255 && y < 4) ++ink_above;
        }
        for (x = extent.width; x < stride; ++x) CHECK(page[y * stride + x] == 0x11);
    }
    CHECK(ink > 200);   /* a line of 24 px glyphs */
    CHECK(ink_above == 0);
    CHECK(background_ok);
    free(page);

    /* RGBA: white background, black text. */
    stride = extent.width * 4;
    size = (size_t)stride * (size_t)extent.height;
    page = calloc(size, 1);
    CHECK(page != NULL);
    if (!page) return;
    CHECK_OK(bezel_text_render(renderer, text, strlen(text), &options, BEZEL_PIXEL_RGBA8, page,
                               size, stride, NULL));
    CHECK(page[0] == 255 && page[1] == 255 && page[2] == 255 && page[3] == 255);
    ink = 0;
    for (x = 0; x < extent.width; ++x)
        ink += page[(size_t)(extent.first_baseline_px - 5) * (size_t)stride + (size_t)x * 4] < 64;
    CHECK(ink > 10);
    free(page);
    bezel_text_renderer_destroy(renderer);
}

/* Bad calls: a status that says what kind, and a message that names the input. */
static void check_errors(bezel_font* font) {
    bezel_font* missing = NULL;
    bezel_path* path = NULL;
    bezel_text_renderer* renderer = NULL;
    bezel_text_extent extent;
    const char bad_utf8[] = "ab\xff";

    CHECK(bezel_font_open_file("/nonexistent/NoSuch.ttf", NULL, &missing) ==
          BEZEL_STATUS_FILE_ERROR);
    CHECK(missing == NULL);
    CHECK(strstr(bezel_last_error(), "/nonexistent/NoSuch.ttf") != NULL);

    CHECK(bezel_path_from_svg("M 0 0 L 5 x", 11, &path) == BEZEL_STATUS_INVALID_ARGUMENT);
    CHECK(path == NULL);
    CHECK(strstr(bezel_last_error(), "offset 10") != NULL);

    CHECK(bezel_glyph_measure(NULL, 1, NULL) == BEZEL_STATUS_INVALID_ARGUMENT);
    CHECK(strstr(bezel_last_error(), "rasterizer is NULL") != NULL);

    CHECK_OK(bezel_text_renderer_create(&font, 1, &renderer));
    CHECK(bezel_text_measure(renderer, bad_utf8, 3, NULL, &extent) ==
          BEZEL_STATUS_INVALID_ARGUMENT);
    CHECK(strstr(bezel_text_renderer_last_error(renderer), "UTF-8") != NULL);
    /* C lets any int into an enum argument: the library checks them as ints. */
    CHECK(bezel_text_render(renderer, "a", 1, NULL, (bezel_pixel_format)9, NULL, 0, 0, NULL) ==
          BEZEL_STATUS_INVALID_ARGUMENT);
    CHECK(strstr(bezel_last_error(), "format 9") != NULL);
    CHECK(strcmp(bezel_status_name((bezel_status)99), "unknown status") == 0);
    CHECK(strcmp(bezel_status_name(BEZEL_STATUS_BUFFER_TOO_SMALL), "buffer too small") == 0);
    bezel_text_renderer_destroy(renderer);
    bezel_font_destroy(NULL);   /* a no-op */
}

/* A square path filled into a mask: exact-area coverage, inside, outside and on a half pixel. */
static void check_fill(void) {
    bezel_path* path = NULL;
    bezel_rasterizer* raster = NULL;
    bezel_int_rect box;
    uint8_t mask[12 * 16];

    CHECK_OK(bezel_path_from_svg("M2 2 H10 V10.5 H2 Z", 19, &path));
    CHECK_OK(bezel_path_pixel_bounds(path, NULL, &box));
    CHECK(box.x0 == 2 && box.y0 == 2 && box.x1 == 10 && box.y1 == 11);
    CHECK_OK(bezel_rasterizer_create(&raster));
    memset(mask, 0xAB, sizeof mask);
    CHECK_OK(bezel_rasterizer_fill(raster, path, NULL, NULL, mask, sizeof mask, 12, 12, 16));
    CHECK(mask[5 * 16 + 5] == 255);
    CHECK(mask[1 * 16 + 5] == 0);
    CHECK(mask[10 * 16 + 5] == 128);   /* half covered: round(0.5·255) */
    CHECK(mask[5 * 16 + 12] == 0xAB);  /* the stride's padding */
    bezel_rasterizer_destroy(raster);
    bezel_path_destroy(path);
}

int main(int argc, char** argv) {
    bezel_font* font = NULL;
    bezel_font_info info;
    if (argc != 2) {
        fprintf(stderr, "usage: capi FONT\n");
        return 2;
    }
    check_version();
    CHECK_OK(bezel_font_open_file(argv[1], NULL, &font));
    if (!font) return 1;
    CHECK_OK(bezel_font_get_info(font, &info));
    CHECK(info.units_per_em == 2048);
    CHECK(info.face_count == 1);
    CHECK(info.glyph_count > 1000);
    check_glyph(font);
    check_text(font);
    check_errors(font);
    check_fill();
    bezel_font_destroy(font);
    if (failures) {
        fprintf(stderr, "%d checks failed\n", failures);
        return 1;
    }
    printf("C API consumer: every check passed (bezel %s)\n", bezel_version_string());
    return 0;
}
