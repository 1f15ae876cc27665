/* bezel/bezel.h — bezel's C API (C11; also compiles as C++, inside extern "C").
 *
 * A stable C ABI over the C++ library, for C programs and for languages that bind C (Rust, Go,
 * .NET, Zig, Python's ctypes/cffi). Linked as libbezel_c.so (pkg-config `bezel`, CMake
 * `bezel::bezel_c`); it exports only the bezel_* functions declared here. docs/capi.md is the
 * guide; this header is the contract.
 *
 * Conventions, for every function below:
 *   Status   every call that can fail returns a bezel_status; BEZEL_STATUS_OK is 0. No C++
 *            exception crosses this boundary (out of memory is BEZEL_STATUS_OUT_OF_MEMORY).
 *            On failure nothing is written to the caller's output arguments or buffers, except
 *            where a function says so (the size queries fill in the size they need).
 *   Errors   a failed call stores a one-line message naming the input and what is wrong with it
 *            (bezel's own messages: "fonts/x.ttf: no such file", "path data offset 7: expected a
 *            number, found 'x'"). It is read with the handle's *_last_error(handle), and with
 *            bezel_last_error(), which holds the message of the last failed call on the calling
 *            thread whatever the handle (so constructors, which have no handle yet, and calls
 *            given a NULL handle report there). Successful calls leave both unchanged. The
 *            pointer stays valid until the next call on that handle (per handle) or the next
 *            failed call on that thread (thread-local).
 *   Handles  opaque; each *_create / *_open has a *_destroy, and destroying NULL does nothing.
 *   Options  every options struct has an *_init function that fills in the defaults; a NULL
 *            options pointer means those defaults.
 *   Threads  one handle must not be used from two threads at once; separate handles (even of
 *            the same font) are independent. A bezel_font may be read by several threads at
 *            once only through the *_create functions that take it (they copy what they need).
 *   Units    pixels, y DOWN (bitmaps, paths, pen positions) unless a field says font units
 *            (y up, as the font stores them). Buffers are the caller's: `stride` is in BYTES
 *            from one row to the next, at least the row's bytes (no negative strides), and
 *            `buffer_size` the bytes the caller owns from `buffer` on.
 */
#ifndef BEZEL_BEZEL_H
#define BEZEL_BEZEL_H

#include <stddef.h>
#include <stdint.h>

/* The version of the bezel this header belongs to. CMakeLists.txt refuses to configure when
 * these differ from its project() version, and bezel_version() returns the library's. */
#define BEZEL_VERSION_MAJOR 0
#define BEZEL_VERSION_MINOR 1
#define BEZEL_VERSION_PATCH 0
#define BEZEL_VERSION_STRING "0.1.0"
/* One number per version, ordered as versions are: major·10000 + minor·100 + patch. */
#define BEZEL_VERSION_ENCODE(major, minor, patch) ((major) * 10000 + (minor) * 100 + (patch))
#define BEZEL_VERSION \
    BEZEL_VERSION_ENCODE(BEZEL_VERSION_MAJOR, BEZEL_VERSION_MINOR, BEZEL_VERSION_PATCH)

#if defined(__GNUC__)
#define BEZEL_API __attribute__((visibility("default")))
#else
#define BEZEL_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ---- Status, errors, version ----------------------------------------------------------------- */

typedef enum bezel_status {
    BEZEL_STATUS_OK = 0,
    BEZEL_STATUS_INVALID_ARGUMENT = 1,   /* a NULL handle or pointer, a bad value, bad data
                                            (SVG path data, UTF-8, a non-finite number) */
    BEZEL_STATUS_OUT_OF_RANGE = 2,       /* a size, index or count beyond a limit of bezel's
                                            (lib/include/bezel/limits.hpp, named in the message) */
    BEZEL_STATUS_FILE_ERROR = 3,         /* a file that cannot be read (missing, a directory) */
    BEZEL_STATUS_FONT_ERROR = 4,         /* font bytes FreeType refuses, a glyph it cannot load,
                                            an unknown variation axis */
    BEZEL_STATUS_BUFFER_TOO_SMALL = 5,   /* the caller's buffer is smaller than the size query
                                            says; nothing was written to it */
    BEZEL_STATUS_OUT_OF_MEMORY = 6,
    BEZEL_STATUS_INTERNAL = 7            /* a bug in bezel: please report the message */
} bezel_status;

/* "ok", "invalid argument", "out of range", "file error", "font error", "buffer too small",
 * "out of memory", "internal error"; "unknown status" for any other value. Never NULL. */
BEZEL_API const char* bezel_status_name(bezel_status status);

/* The message of the last failed call on the calling thread ("" before any). Never NULL. */
BEZEL_API const char* bezel_last_error(void);

/* The library's version: BEZEL_VERSION_ENCODE of its major, minor and patch, and "0.1.0". */
BEZEL_API int bezel_version(void);
BEZEL_API const char* bezel_version_string(void);

/* ---- Shared enums ---------------------------------------------------------------------------- */

/* Which of FreeType's hinters fits outlines to the pixel grid (bezel/font.hpp's Hinting). */
typedef enum bezel_hinting {
    BEZEL_HINTING_NONE = 0,    /* the design scaled exactly */
    BEZEL_HINTING_LIGHT = 1,   /* vertical snapping only */
    BEZEL_HINTING_FULL = 2,    /* the font's instructions */
    BEZEL_HINTING_AUTO = 3     /* FreeType's auto-hinter */
} bezel_hinting;

/* What a mask holds. LCD masks have 3 bytes per DISPLAY pixel, subpixels left to right in the
 * panel's order (R, G, B or B, G, R). */
typedef enum bezel_coverage {
    BEZEL_COVERAGE_GRAY = 0,
    BEZEL_COVERAGE_LCD_RGB = 1,
    BEZEL_COVERAGE_LCD_BGR = 2
} bezel_coverage;

/* Colour pixel layouts (bezel/image.hpp's PixelFormat): sRGB-encoded bytes, straight or
 * premultiplied alpha; GRAY8 is one byte per pixel (colours become their luma). */
typedef enum bezel_pixel_format {
    BEZEL_PIXEL_GRAY8 = 0,
    BEZEL_PIXEL_RGBA8 = 1,
    BEZEL_PIXEL_BGRA8 = 2,
    BEZEL_PIXEL_RGBA8_PREMULTIPLIED = 3,
    BEZEL_PIXEL_BGRA8_PREMULTIPLIED = 4
} bezel_pixel_format;

typedef struct bezel_rgba {
    uint8_t r, g, b, a;   /* sRGB-encoded, straight alpha */
} bezel_rgba;

/* ---- Fonts ----------------------------------------------------------------------------------- */

typedef struct bezel_font bezel_font;

/* One design coordinate of a variable font: a four-character axis tag ("wght", NUL-terminated)
 * and a value in the axis's user units (wght 100..900). */
typedef struct bezel_variation {
    char tag[5];
    double value;
} bezel_variation;

typedef struct bezel_font_options {
    int face_index;                        /* 0..face count − 1 (TTC/OTC collections); 0 */
    const bezel_variation* variations;     /* design coordinates; NULL/0: the font's defaults */
    size_t variation_count;
    /* bezel_font_open_memory only: */
    int copy_data;       /* nonzero: the bytes are copied (the caller may free them on return);
                            0 (default): BORROWED, see bezel_font_open_memory */
    const char* name;    /* what messages call a font from memory; NULL: "<memory>" */
} bezel_font_options;

BEZEL_API void bezel_font_options_init(bezel_font_options* options);

/* Opens a font file (TTF, OTF, TTC/OTC), read once (mapped read-only: the file must not be
 * truncated while the font or anything made from it exists). On success *out is a new font.
 * Errors: NULL path or out (INVALID_ARGUMENT); a missing or unreadable file (FILE_ERROR); bytes
 * that are not a font, a face index past the file's faces, an unknown variation axis or value
 * (FONT_ERROR); a negative face index (OUT_OF_RANGE). The message names the file. */
BEZEL_API bezel_status bezel_font_open_file(const char* path, const bezel_font_options* options,
                                            bezel_font** out);
/* A font from `size` bytes at `data`. Borrowed (options->copy_data 0): the bytes must stay valid
 * and unchanged until this font AND every glyph rasterizer and text renderer made from it are
 * destroyed. Copied (copy_data nonzero): the caller may free them on return. Errors as the file
 * form, naming options->name; NULL data or size 0 is INVALID_ARGUMENT. */
BEZEL_API bezel_status bezel_font_open_memory(const void* data, size_t size,
                                              const bezel_font_options* options, bezel_font** out);
BEZEL_API void bezel_font_destroy(bezel_font* font);
/* The message of this font's last failed call ("" before any); bezel_last_error() for NULL. */
BEZEL_API const char* bezel_font_last_error(const bezel_font* font);

/* Face-wide facts. Metrics in FONT UNITS, y UP as the font stores them. */
typedef struct bezel_font_info {
    int units_per_em;
    int face_count;            /* faces in the file (a collection has more than one) */
    size_t glyph_count;
    double ascender;           /* > 0 */
    double descender;          /* < 0 */
    double line_gap;
    int has_color;             /* nonzero: colour glyphs (COLR/CPAL, CBDT, sbix) */
} bezel_font_info;
BEZEL_API bezel_status bezel_font_get_info(bezel_font* font, bezel_font_info* out);

/* The glyph for a Unicode code point; *gid = 0 (.notdef) when the font does not map it (that is
 * not an error). Errors: a NULL argument, a code point above U+10FFFF (OUT_OF_RANGE). */
BEZEL_API bezel_status bezel_font_glyph_index(bezel_font* font, uint32_t code_point,
                                              uint32_t* gid);

/* Sets design coordinates (unnamed axes return to their defaults). Rasterizers and renderers
 * made before keep the coordinates they were made with. Errors (FONT_ERROR) name an unknown
 * tag or an out-of-range value; the font keeps its previous coordinates. */
BEZEL_API bezel_status bezel_font_set_variations(bezel_font* font,
                                                 const bezel_variation* variations, size_t count);

/* ---- Glyph rasterizer: single glyphs into caller masks --------------------------------------- */

typedef struct bezel_glyph_rasterizer bezel_glyph_rasterizer;

typedef struct bezel_glyph_options {
    double size_px;              /* em size, (0, 16384]; 16 */
    bezel_hinting hinting;       /* NONE */
    bezel_coverage coverage;     /* GRAY */
    /* The pen relative to the glyph's whole-pixel origin, pixels, y down: a toolkit passes its
     * pen's fractional part in [0, 1) and adds the whole part to the box itself. 0, 0. A glyph
     * hinted horizontally (FULL, AUTO) should be drawn at offset x 0. */
    double offset_x_px, offset_y_px;
    int embedded_bitmaps;        /* nonzero: a gray/mono strike of exactly size_px is used; 0 */
    double slant;                /* synthetic slant, |slant| ≤ 1; 0 */
    double bold;                 /* synthetic bold, a fraction of the em in [0, 0.25]; 0 */
} bezel_glyph_options;

BEZEL_API void bezel_glyph_options_init(bezel_glyph_options* options);

/* A rasterizer of `font`'s glyphs at the font's current variation coordinates, with `options`.
 * It has its own instance of the font (shared bytes, no copy): `font` may be destroyed
 * afterwards (a borrowed memory font's bytes must still outlive the rasterizer), and
 * rasterizers of one font may run on separate threads. Errors: NULL font or out, options out of
 * range (a size outside (0, 16384], a non-finite or too large offset, slant, bold), a font
 * without outlines. */
BEZEL_API bezel_status bezel_glyph_rasterizer_create(const bezel_font* font,
                                                     const bezel_glyph_options* options,
                                                     bezel_glyph_rasterizer** out);
BEZEL_API void bezel_glyph_rasterizer_destroy(bezel_glyph_rasterizer* rasterizer);
BEZEL_API const char* bezel_glyph_rasterizer_last_error(const bezel_glyph_rasterizer* rasterizer);

/* Where a glyph's mask sits and how big it is. The mask's first row is at pen y − top, its
 * first column at pen x + left (FreeType's bitmap_left / bitmap_top). */
typedef struct bezel_glyph_box {
    int left, top;
    int width, height;         /* DISPLAY pixels */
    int row_bytes;             /* bytes of one row: width, or 3·width for LCD coverage */
    size_t buffer_size;        /* the least buffer_size a render at stride row_bytes needs:
                                  row_bytes·height */
    double advance_px;         /* horizontal advance */
    int color;                 /* nonzero: a colour glyph; the mask holds its alpha */
} bezel_glyph_box;

/* The box of glyph `gid`, without drawing. Errors: gid ≥ glyph count (FONT_ERROR, named), a box
 * larger than 16384 px a side (OUT_OF_RANGE). */
BEZEL_API bezel_status bezel_glyph_measure(bezel_glyph_rasterizer* rasterizer, uint32_t gid,
                                           bezel_glyph_box* box);
/* Draws glyph `gid` into the top-left box.width × box.height corner of `buffer` (row_bytes
 * bytes a row, `stride` apart), writing every byte of that corner and nothing else; `box` (may
 * be NULL) receives its box. The size query: when `buffer` is NULL or smaller than the glyph
 * (stride < row_bytes, or buffer_size < stride·(height − 1) + row_bytes) the call returns
 * BUFFER_TOO_SMALL, fills in `box` and writes nothing. A glyph with an empty box needs no
 * buffer. Errors as bezel_glyph_measure, plus a negative stride (INVALID_ARGUMENT). */
BEZEL_API bezel_status bezel_glyph_render(bezel_glyph_rasterizer* rasterizer, uint32_t gid,
                                          uint8_t* buffer, size_t buffer_size, ptrdiff_t stride,
                                          bezel_glyph_box* box);

/* One glyph's target in a set (an atlas rectangle): as bezel_glyph_render's arguments. */
typedef struct bezel_glyph_target {
    uint8_t* buffer;
    size_t buffer_size;
    ptrdiff_t stride;
} bezel_glyph_target;

/* A set of glyphs, as an atlas is filled: boxes[k] receives the box of gids[k] (so a caller
 * measures the set, packs the rectangles, then draws it). */
BEZEL_API bezel_status bezel_glyph_measure_set(bezel_glyph_rasterizer* rasterizer,
                                               const uint32_t* gids, size_t count,
                                               bezel_glyph_box* boxes);
/* Draws gids[k] into targets[k] as bezel_glyph_render would, in one rasterizer pass per run of
 * outline glyphs. Every glyph is loaded and every target checked BEFORE anything is drawn: a
 * glyph that fails or a target too small (BUFFER_TOO_SMALL) names its set index and leaves
 * every target untouched. `boxes` (may be NULL) receives the boxes. count 0 is a success. */
BEZEL_API bezel_status bezel_glyph_render_set(bezel_glyph_rasterizer* rasterizer,
                                              const uint32_t* gids, size_t count,
                                              const bezel_glyph_target* targets,
                                              bezel_glyph_box* boxes);

/* ---- Paths ----------------------------------------------------------------------------------- */

typedef struct bezel_path bezel_path;

/* An empty path, built with the verb calls below (pixels, y down, as the rasterizer draws). */
BEZEL_API bezel_status bezel_path_create(bezel_path** out);
/* A path from SVG path data (every command of SVG 1.1/2: M L H V C S Q T A Z, relative forms;
 * arcs become cubics within 0.001 units). `length` bytes of `data` (no NUL needed). Errors
 * (INVALID_ARGUMENT) name the byte offset and what was expected; data longer than 16 MiB or
 * giving more than 8 Mi points is OUT_OF_RANGE. */
BEZEL_API bezel_status bezel_path_from_svg(const char* data, size_t length, bezel_path** out);
BEZEL_API void bezel_path_destroy(bezel_path* path);
BEZEL_API const char* bezel_path_last_error(const bezel_path* path);

/* The builder (bezel/path.hpp's Path): a drawing call with no open contour starts one at the
 * last point; close() ends the contour. Errors: a NULL path, a coordinate that is not finite
 * (INVALID_ARGUMENT), a path past 8 Mi points (OUT_OF_RANGE); the path is then unchanged. */
BEZEL_API bezel_status bezel_path_move_to(bezel_path* path, double x, double y);
BEZEL_API bezel_status bezel_path_line_to(bezel_path* path, double x, double y);
BEZEL_API bezel_status bezel_path_quad_to(bezel_path* path, double cx, double cy, double x,
                                          double y);
BEZEL_API bezel_status bezel_path_cubic_to(bezel_path* path, double c1x, double c1y, double c2x,
                                           double c2y, double x, double y);
BEZEL_API bezel_status bezel_path_close(bezel_path* path);

/* An affine map of points: x' = a·x + c·y + e, y' = b·x + d·y + f. Identity: {1,0,0,1,0,0}. */
typedef struct bezel_transform {
    double a, b, c, d, e, f;
} bezel_transform;

/* The whole-pixel box covering the path's drawn geometry after `transform` (NULL: identity):
 * x0, y0 inclusive, x1, y1 exclusive (floor / ceil of the tight bounds). An empty path gives
 * 0, 0, 0, 0. What a caller sizes a fill's buffer with. Errors: a transform or result that is
 * not finite. */
typedef struct bezel_int_rect {
    int x0, y0, x1, y1;
} bezel_int_rect;
BEZEL_API bezel_status bezel_path_pixel_bounds(bezel_path* path, const bezel_transform* transform,
                                               bezel_int_rect* out);

/* ---- Rasterizer: paths into caller masks ----------------------------------------------------- */

typedef struct bezel_rasterizer bezel_rasterizer;

typedef enum bezel_fill_rule {
    BEZEL_FILL_NONZERO = 0,
    BEZEL_FILL_EVENODD = 1
} bezel_fill_rule;

typedef struct bezel_fill_options {
    bezel_fill_rule rule;       /* NONZERO */
    int accurate_overlap;       /* nonzero: overlapping contours' edges are not over-darkened */
    double tolerance_px;        /* flattening distance bound, pixels, > 0; 0.01 */
    bezel_coverage coverage;    /* GRAY; LCD: width counts DISPLAY pixels, 3 bytes each */
} bezel_fill_options;

BEZEL_API void bezel_fill_options_init(bezel_fill_options* options);

/* Exact-area anti-aliased coverage. Holds scratch memory reused by every fill. */
BEZEL_API bezel_status bezel_rasterizer_create(bezel_rasterizer** out);
BEZEL_API void bezel_rasterizer_destroy(bezel_rasterizer* rasterizer);
BEZEL_API const char* bezel_rasterizer_last_error(const bezel_rasterizer* rasterizer);

/* Fills `path` mapped by `transform` (NULL: identity) into the width × height mask at `buffer`:
 * one byte per pixel, round(coverage·255) (3 bytes per pixel for LCD coverage), writing EVERY
 * byte of the width × height rectangle (0 where nothing covers it). Pixel (x, y) is the square
 * [x, x+1] × [y, y+1]; parts outside the mask are clipped. Needs stride ≥ width (·3 for LCD) and
 * buffer_size ≥ stride·(height − 1) + that, else BUFFER_TOO_SMALL. Errors: width or height
 * negative or above 16384 (OUT_OF_RANGE), a non-finite transform, a path over the edge budget. */
BEZEL_API bezel_status bezel_rasterizer_fill(bezel_rasterizer* rasterizer, const bezel_path* path,
                                             const bezel_transform* transform,
                                             const bezel_fill_options* options, uint8_t* buffer,
                                             size_t buffer_size, int width, int height,
                                             ptrdiff_t stride);

/* ---- Text renderer: lines and paragraphs into caller pixels ---------------------------------- */

typedef struct bezel_text_renderer bezel_text_renderer;

typedef enum bezel_align {
    BEZEL_ALIGN_START = 0,    /* left for left-to-right paragraphs, right for right-to-left */
    BEZEL_ALIGN_CENTER = 1,
    BEZEL_ALIGN_END = 2
} bezel_align;

typedef struct bezel_text_options {
    double size_px;            /* em size, (0, 16384]; 16 */
    double width_px;           /* wrap lines to this width; 0: no wrapping (default) */
    double line_height;        /* multiple of the fonts' line height; 0 (default) means 1 */
    double margin_px;          /* around the text on all four sides; 0 */
    bezel_align align;         /* START */
    const char* language;      /* BCP 47 ("ar"); NULL: HarfBuzz's default */
    const char* script;        /* ISO 15924 ("Arab"); NULL: from the text */
    bezel_hinting hinting;     /* NONE */
    bezel_coverage coverage;   /* GRAY; LCD needs an opaque background and a colour format */
    bezel_rgba foreground;     /* black */
    bezel_rgba background;     /* opaque white */
} bezel_text_options;

BEZEL_API void bezel_text_options_init(bezel_text_options* options);

/* A renderer over `font_count` fonts: text is drawn with fallback (each cluster from the first
 * font that has it; characters none has are the first font's .notdef). Each font is used at the
 * variation coordinates it had here; the fonts may be destroyed afterwards (borrowed memory
 * must outlive the renderer). The fonts are only read (the array's type lets C pass `&font` or a
 * `bezel_font* fonts[]` without a cast). Errors: NULL fonts or out, font_count 0 or above 64
 * (OUT_OF_RANGE), a font the list cannot take. */
BEZEL_API bezel_status bezel_text_renderer_create(bezel_font* const* fonts,
                                                  size_t font_count,
                                                  bezel_text_renderer** out);
BEZEL_API void bezel_text_renderer_destroy(bezel_text_renderer* renderer);
BEZEL_API const char* bezel_text_renderer_last_error(const bezel_text_renderer* renderer);

/* The page a text makes: its size (margins included) and lines, pixels, y down. */
typedef struct bezel_text_extent {
    int width, height;          /* the page, whole pixels */
    double first_baseline_px;   /* y of the first line's baseline */
    size_t line_count;
    size_t missing_glyphs;      /* .notdef glyphs drawn: characters no font has */
} bezel_text_extent;

/* Lays out `length` bytes of UTF-8 (\n starts a line; wrapped at options->width_px). Errors:
 * invalid UTF-8 (INVALID_ARGUMENT, naming the byte offset), more than 16 MiB of text,
 * options out of range. */
BEZEL_API bezel_status bezel_text_measure(bezel_text_renderer* renderer, const char* utf8,
                                          size_t length, const bezel_text_options* options,
                                          bezel_text_extent* extent);
/* Renders the page of bezel_text_measure into the top-left extent.width × extent.height corner
 * of `buffer` in `format` (1 byte per pixel for GRAY8, else 4): the background filled, the text
 * blended over it in linear light. `extent` (may be NULL) receives the page. The size query:
 * when `buffer` is NULL or too small (stride < width·bytes per pixel, or buffer_size <
 * stride·(height − 1) + width·bytes per pixel) it returns BUFFER_TOO_SMALL with `extent` filled
 * in and nothing written. Errors as bezel_text_measure, plus a negative stride, a page above
 * 32768 px a side (OUT_OF_RANGE), LCD coverage into GRAY8 or over a background that is not
 * opaque. */
BEZEL_API bezel_status bezel_text_render(bezel_text_renderer* renderer, const char* utf8,
                                         size_t length, const bezel_text_options* options,
                                         bezel_pixel_format format, uint8_t* buffer,
                                         size_t buffer_size, ptrdiff_t stride,
                                         bezel_text_extent* extent);
/* Blends the text onto the width × height pixels already at `buffer` (a toolkit's surface),
 * the page's top-left corner at (x_px, y_px), which may be fractional or put the text partly
 * outside: it is clipped to the surface. Only pixels under glyphs change; options->background
 * is not drawn (it should be the colour under the text: the text weight is made for it). Errors
 * as bezel_text_render, plus a non-finite origin; BUFFER_TOO_SMALL when buffer_size or stride
 * cannot hold width × height pixels. */
BEZEL_API bezel_status bezel_text_draw(bezel_text_renderer* renderer, const char* utf8,
                                       size_t length, const bezel_text_options* options,
                                       bezel_pixel_format format, uint8_t* buffer,
                                       size_t buffer_size, int width, int height,
                                       ptrdiff_t stride, double x_px, double y_px);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif /* BEZEL_BEZEL_H */
