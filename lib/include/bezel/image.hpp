// bezel/image.hpp — coverage masks: non-owning views into caller memory, an owning A8 mask, and
// gray PNG files.
//
// Pixel (x, y) is the unit square [x, x+1] × [y, y+1]; y points DOWN (row 0 is the top row).
// A view's `stride` is the distance between the starts of two rows, in ELEMENTS of the pixel type
// (bytes for MaskView, floats for FloatMaskView). It may exceed the width (a sub-rectangle of a
// glyph atlas) and may be negative (bottom-up memory). Views never own or free their memory.
//
// Colour images: `Image` holds straight (non-premultiplied) sRGB-encoded RGBA8; a PixelView is a
// caller's pixels in any of the PixelFormats (gray, RGBA, BGRA, straight or premultiplied), with
// its stride in BYTES, and every blend function draws into one. Coverage masks
// are LINEAR (area fractions); blending converts colours to linear light (the sRGB transfer
// function, IEC 61966-2-1), mixes there, and encodes back, so anti-aliased edges keep their
// weight on any background. The formula and tables are at the implementation. Text may map its
// coverage through a CoverageCurve first, for the weight readers expect (TextRendering, below).
//
// Only this module sees libpng.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "bezel/expected.hpp"
#include "bezel/limits.hpp"

#pragma GCC visibility push(default)  // the public API of libbezel.so (docs/architecture.md)
namespace bezel {

// 8-bit alpha (0 = empty, 255 = fully covered), writable.
struct MaskView {
    std::uint8_t* data = nullptr;
    int width = 0, height = 0;
    std::ptrdiff_t stride = 0;  // bytes from one row to the next

    std::uint8_t* row(int y) const { return data + static_cast<std::ptrdiff_t>(y) * stride; }
    std::uint8_t& at(int x, int y) const { return row(y)[x]; }
    // The sub-rectangle [x, x+w) × [y, y+h). Precondition: it lies inside this view.
    MaskView sub(int x, int y, int w, int h) const { return {row(y) + x, w, h, stride}; }
};

// Read-only 8-bit alpha.
struct ConstMaskView {
    const std::uint8_t* data = nullptr;
    int width = 0, height = 0;
    std::ptrdiff_t stride = 0;

    ConstMaskView() = default;
    ConstMaskView(const std::uint8_t* d, int w, int h, std::ptrdiff_t s)
        : data(d), width(w), height(h), stride(s) {}
    ConstMaskView(const MaskView& v)  // NOLINT: a writable view is readable
        : data(v.data), width(v.width), height(v.height), stride(v.stride) {}
    const std::uint8_t* row(int y) const { return data + static_cast<std::ptrdiff_t>(y) * stride; }
    std::uint8_t at(int x, int y) const { return row(y)[x]; }
};

// Float coverage in [0, 1], writable. `stride` counts floats, not bytes.
struct FloatMaskView {
    float* data = nullptr;
    int width = 0, height = 0;
    std::ptrdiff_t stride = 0;  // floats from one row to the next

    float* row(int y) const { return data + static_cast<std::ptrdiff_t>(y) * stride; }
    float& at(int x, int y) const { return row(y)[x]; }
};

// An owning A8 mask, rows packed (stride == width). A value type: copying copies the pixels.
class Mask {
public:
    Mask() = default;
    // A mask of `fill` (zeroed by default), written once. Precondition: 0 ≤ width, height ≤
    // kMaxImageDim (checked by the callers that take sizes from input, e.g. read_png_gray).
    Mask(int width, int height, std::uint8_t fill = 0)
        : width_(width), height_(height),
          pixels_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), fill) {}

    int width() const { return width_; }
    int height() const { return height_; }
    MaskView view() { return {pixels_.data(), width_, height_, width_}; }
    ConstMaskView view() const { return {pixels_.data(), width_, height_, width_}; }
    std::uint8_t& at(int x, int y) { return pixels_[index(x, y)]; }
    std::uint8_t at(int x, int y) const { return pixels_[index(x, y)]; }
    const std::vector<std::uint8_t>& pixels() const { return pixels_; }

    bool operator==(const Mask& o) const {
        return width_ == o.width_ && height_ == o.height_ && pixels_ == o.pixels_;
    }
    bool operator!=(const Mask& o) const { return !(*this == o); }

private:
    std::size_t index(int x, int y) const {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
               static_cast<std::size_t>(x);
    }
    int width_ = 0, height_ = 0;
    std::vector<std::uint8_t> pixels_;
};

// Copies a view into a new owning mask.
Mask to_mask(ConstMaskView view);

// Writes an 8-bit grayscale PNG (value = coverage, 0 black). Errors name the file: it cannot be
// created, or libpng failed while writing it. An empty (0×0) mask is an error: PNG has no such
// image.
Status write_png_gray(const std::string& file, ConstMaskView mask);

// Reads a PNG as 8-bit gray. Gray 1/2/4/8/16-bit are converted to 8 bits; RGB is converted to
// gray with libpng's default weights; an alpha channel is dropped (a mask file is its gray
// values). Errors name the file: unreadable, not a PNG, corrupt, or larger than kMaxImageDim.
Expected<Mask> read_png_gray(const std::string& file);

// --- Colour images ------------------------------------------------------------------------------
// An sRGB-encoded colour with straight alpha.
struct Rgba8 {
    std::uint8_t r = 0, g = 0, b = 0, a = 255;
    bool operator==(const Rgba8& o) const { return r == o.r && g == o.g && b == o.b && a == o.a; }
    bool operator!=(const Rgba8& o) const { return !(*this == o); }
};

// Parses a colour as hb-view does: "#RRGGBB", "#RRGGBBAA", "RRGGBB", "RRGGBBAA", "#RGB", "#RGBA"
// (hex, case-insensitive), plus the 148 CSS named colours ("yellow", "rebeccapurple"; CSS's
// values, so "green" is #008000) and "transparent", case-insensitive. The error names the text.
Expected<Rgba8> parse_color(std::string_view text);

// An owning RGBA8 image, rows packed. A value type.
struct PixelView;
struct ConstPixelView;

class Image {
public:
    Image() = default;
    // Filled with `fill`. Precondition: 0 ≤ width, height ≤ kMaxImageDim.
    Image(int width, int height, Rgba8 fill = {0, 0, 0, 0});
    // The image's pixels as a PixelFormat::Rgba8 view (straight alpha, rows packed), valid until
    // the image is resized, moved from or destroyed.
    PixelView view();
    ConstPixelView view() const;
    int width() const { return width_; }
    int height() const { return height_; }
    Rgba8& at(int x, int y) { return pixels_[index(x, y)]; }
    const Rgba8& at(int x, int y) const { return pixels_[index(x, y)]; }
    Rgba8* row(int y) { return pixels_.data() + index(0, y); }
    const Rgba8* row(int y) const { return pixels_.data() + index(0, y); }
    bool operator==(const Image& o) const;
    bool operator!=(const Image& o) const { return !(*this == o); }

private:
    std::size_t index(int x, int y) const {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
               static_cast<std::size_t>(x);
    }
    int width_ = 0, height_ = 0;
    std::vector<Rgba8> pixels_;
};

// Order of the subpixels in a display pixel, left to right (an LCD panel's layout), and so the
// order of the three coverage bytes of a display pixel in an LCD mask: an LCD mask's bytes are
// its subpixels left to right, which on an Rgb panel are R, G, B and on a Bgr panel B, G, R
// (FreeType's FT_PIXEL_MODE_LCD is laid out the same way). The Rasterizer's CoverageFormat::Lcd
// writes masks in this layout and blend_lcd_mask reads them in it: give both the same order.
enum class LcdOrder : std::uint8_t { Rgb, Bgr };

// --- Caller-owned colour targets ----------------------------------------------------------------
// How a PixelView's pixels are laid out in memory. Colour values are sRGB-ENCODED bytes in every
// format (as Image's, and as toolkits and PNG store them).
//   Gray8:  1 byte, the sRGB-encoded gray; always opaque (no alpha is stored).
//   Rgba8, Bgra8: 4 bytes, in memory order R, G, B, A or B, G, R, A; STRAIGHT alpha (the colour
//           bytes do not depend on A).
//   Rgba8Premultiplied, Bgra8Premultiplied: the same orders, colour PREMULTIPLIED by alpha in the
//           encoded values, P = round(C·A/255), so each colour byte ≤ A (as Cairo, Skia and
//           Direct2D store premultiplied 8-bit colour: Bgra8Premultiplied is Cairo's ARGB32 and
//           Skia's N32 on a little-endian machine, and paint.hpp's RgbaView is
//           Rgba8Premultiplied).
// Blending reads and writes a pixel through load_pixel and store_pixel, below, and mixes in
// linear light between them (the formulas at blend_mask). A premultiplied pixel of alpha 255 is
// its straight colour, so on opaque pixels every RGBA/BGRA format blends to the same colour bit
// for bit.
enum class PixelFormat : std::uint8_t {
    Gray8,
    Rgba8,
    Bgra8,
    Rgba8Premultiplied,
    Bgra8Premultiplied,
};
// 1 for Gray8, 4 for the others.
constexpr int bytes_per_pixel(PixelFormat format) { return format == PixelFormat::Gray8 ? 1 : 4; }

// A writable view of a caller's pixels. Pixel (x, y) starts at data + y·stride +
// x·bytes_per_pixel(format); y points down. `stride` is in BYTES from one row's start to the
// next: at least width·bytes_per_pixel (padding, or a sub-rectangle of a larger surface), or
// negative for bottom-up memory. No alignment is required. The view never owns or frees the
// memory; blend functions write only the pixels they blend (nothing is cleared or filled).
struct PixelView {
    std::uint8_t* data = nullptr;
    int width = 0, height = 0;
    std::ptrdiff_t stride = 0;
    PixelFormat format = PixelFormat::Rgba8;

    std::uint8_t* row(int y) const { return data + static_cast<std::ptrdiff_t>(y) * stride; }
    std::uint8_t* pixel(int x, int y) const {
        return row(y) + static_cast<std::ptrdiff_t>(x) * bytes_per_pixel(format);
    }
    // The sub-rectangle [x, x+w) × [y, y+h). Precondition: it lies inside this view.
    PixelView sub(int x, int y, int w, int h) const { return {pixel(x, y), w, h, stride, format}; }
};

// Read-only pixels (a source image to composite).
struct ConstPixelView {
    const std::uint8_t* data = nullptr;
    int width = 0, height = 0;
    std::ptrdiff_t stride = 0;
    PixelFormat format = PixelFormat::Rgba8;

    ConstPixelView() = default;
    ConstPixelView(const std::uint8_t* d, int w, int h, std::ptrdiff_t s, PixelFormat f)
        : data(d), width(w), height(h), stride(s), format(f) {}
    ConstPixelView(const PixelView& v)  // NOLINT: a writable view is readable
        : data(v.data), width(v.width), height(v.height), stride(v.stride), format(v.format) {}
    const std::uint8_t* row(int y) const { return data + static_cast<std::ptrdiff_t>(y) * stride; }
    const std::uint8_t* pixel(int x, int y) const {
        return row(y) + static_cast<std::ptrdiff_t>(x) * bytes_per_pixel(format);
    }
};

// One pixel of `format` at `p` as a straight sRGB-encoded colour, exactly as the blend
// functions read it: Gray8 g is {g, g, g, 255}; straight formats are their bytes; a
// premultiplied pixel of alpha A > 0 has colour C = min(255, round(255·P/A)) (integer
// rounding, half up), and of alpha 0 is transparent black {0, 0, 0, 0} (its colour bytes,
// which should be 0, are ignored).
Rgba8 load_pixel(PixelFormat format, const std::uint8_t* p);
// `c` written at `p` in `format`, exactly as the blend functions write: Gray8 takes the luma of
// the encoded values (Rec. 709 weights, 8.8 fixed point, rounded: r = g = b stays that byte)
// and drops alpha; straight formats store the bytes; premultiplied formats store
// P = round(C·A/255) (so alpha 0 stores 0, 0, 0, 0). For every premultiplied pixel with P ≤ A
// (and colour 0 where A = 0), store_pixel(load_pixel(P)) == P: an untouched pixel round-trips.
void store_pixel(PixelFormat format, std::uint8_t* p, Rgba8 c);

// --- Text weight: how coverage becomes ink ------------------------------------------------------
// Mixing exact coverage in linear light is right for compositing, but readers judge text by the
// weight renderers that mix sRGB-encoded values (cairo, hence hb-view, and most toolkits) give
// it: by that measure linear-light text is thin dark on light and heavy light on dark, the more
// so the smaller it is (docs/text.md has the figures). A CoverageCurve maps each coverage to the
// alpha the linear-light blend then uses, made for one foreground / background pair so that the
// page comes out as such a renderer's would, in both polarities.
enum class TextRendering : std::uint8_t {
    // Coverage mixed in linear light as it is (alpha = coverage / 255): exact, for compositing
    // and measuring. Bit for bit what the blend functions without a curve do.
    Linear,
    // Coverage mixed as if pixel values v were light v^gamma (Skia's gamma hint: 1 mixes the
    // encoded values as they are, as cairo and hb-view do; about 2.2 is linear light again),
    // after a contrast lift c + contrast·c·(1 − c) (Skia's contrast hint). Formula at the
    // implementation (image/coverage_curve.cpp).
    Perceptual,
};
// Valid ranges of CoverageCurveOptions. Gamma runs from 1 (the encoded values as they are) to a
// little past sRGB's own ~2.2 (linear light): outside that span a curve only exaggerates one
// polarity further than any renderer's gamma hint does; weight in both polarities is the
// contrast's job. Contrast past 1 would make the lift non-monotone (dc1/dc = 1 + k(1 − 2c) turns
// negative near c = 1).
inline constexpr double kMinTextGamma = 1.0;
inline constexpr double kMaxTextGamma = 3.0;
inline constexpr double kMaxTextContrast = 1.0;
// The default, chosen by measurement against hb-view (tools/bench/text_weight.py, docs/text.md):
// of the settings swept it is the one nearest hb-view's ink, within 2 % at 8-24 px in both
// polarities on DejaVu Sans and Cantarell (tests/text_weight_test.cpp holds it to 10 %).
inline constexpr double kDefaultTextGamma = 1.0;
inline constexpr double kDefaultTextContrast = 0.0;

struct CoverageCurveOptions {
    TextRendering rendering = TextRendering::Perceptual;
    double gamma = kDefaultTextGamma;        // Perceptual: [kMinTextGamma, kMaxTextGamma]
    double contrast = kDefaultTextContrast;  // Perceptual: [0, kMaxTextContrast]
};

// The alpha (in [0, 1]) the linear-light blend uses for each 8-bit coverage. Immutable; cheap to
// compare (curves made by one call, and their copies, share an identity), so the blend functions
// key their per-thread tables on it. Invariants (tested): alpha(0) = 0, alpha(255) = 1,
// non-decreasing.
class CoverageCurve {
public:
    // The identity, TextRendering::Linear: alpha = coverage / 255.
    CoverageCurve();
    float operator[](std::uint8_t coverage) const { return alpha_[coverage]; }
    const std::array<float, 256>& alphas() const { return alpha_; }
    bool linear() const { return id_ == 0; }
    // Equal identities mean equal tables (the converse need not hold).
    bool same_as(const CoverageCurve& o) const { return id_ == o.id_; }

private:
    friend Expected<CoverageCurve> coverage_curve(Rgba8, Rgba8, const CoverageCurveOptions&);
    std::array<float, 256> alpha_;
    std::uint64_t id_ = 0;
};

// The curve for text in `foreground` on `background`, computed once (a few hundred pow calls)
// for a page; both colours' alpha is ignored except that a background which is not opaque is
// taken over the backdrop text of that colour is usually read on (white under text darker than
// mid gray, black under lighter text). Errors name the option out of range (or NaN).
Expected<CoverageCurve> coverage_curve(Rgba8 foreground, Rgba8 background,
                                       const CoverageCurveOptions& options);

// --- Blending into a PixelView ---------------------------------------------------------------------
// Every blend function below draws a source (a coverage mask in a colour, or an image) onto
// `target` with the source's top-left pixel at (x, y) of the target (parts outside the target are
// clipped; any int position is safe), touching only the pixels the source covers with nonzero
// coverage or alpha. A null target or source, or an empty one, draws nothing.
//
// The mix, per pixel, in LINEAR light (dec/enc: the sRGB transfer function, srgb_decode and
// srgb_encode below), with D = load_pixel(target pixel) straight, S the source's straight colour
// and α in [0, 1] the source's weight (how α is made is stated at each function):
//   D.a = 255:  out.c = enc(dec(D.c) + (dec(S.c) − dec(D.c))·α)        out.a = 255
//   otherwise:  out.a = α + Da·(1 − α)   (Da = D.a/255; "over")
//               out.c = enc((dec(S.c)·α + dec(D.c)·Da·(1 − α)) / out.a), out.a stored as
//               round(out.a·255); when out.a is 0 the pixel is left as it was.
// then store_pixel(out). So a premultiplied target is un-premultiplied (load_pixel's rounding),
// mixed in straight linear light, and premultiplied again (store_pixel's rounding); on an opaque
// pixel that is the straight formula exactly. A Gray8 target is opaque: S.c is the luma of the
// source colour (as store_pixel takes it) and out = enc(dec(D) + (dec(S) − dec(D))·α).
// Arithmetic is float, the same operations in every format, so an RGBA and a BGRA target (or a
// straight and a premultiplied one, on opaque pixels) come out equal byte for byte after the
// channel swap.

// Blends `color` through the coverage `mask` (8-bit, LINEAR area fractions) onto `target`:
// α = curve[coverage]·color.a/255 (α = coverage/255·color.a/255 without a curve, the identity).
void blend_mask(const PixelView& target, ConstMaskView mask, int x, int y, Rgba8 color);
void blend_mask(const PixelView& target, ConstMaskView mask, int x, int y, Rgba8 color,
                const CoverageCurve& curve);
// The same for an LCD mask: 3 bytes per display pixel (`mask.width` = 3 × display pixels), its
// subpixels left to right, which are the colours in the panel's `order` (R, G, B or B, G, R; the
// Rasterizer's CoverageFormat::Lcd writes this layout for its FillOptions::lcd_order: pass the
// same order). Each colour channel mixes with its own subpixel's α_k = curve[coverage_k]·
// color.a/255; the alpha channel takes α = max_k α_k (the pixel is at least that covered), and a
// channel's mix on a pixel that is not opaque uses its own α_k in the "over" formula above
// (in both the numerator and out.a's normalisation). Subpixel text is meant for opaque pixels
// (one alpha channel cannot hold three coverages). On a Gray8 target, which has no subpixels,
// α = (α_R + α_G + α_B)/3, the pixel's mean ink.
void blend_lcd_mask(const PixelView& target, ConstMaskView mask, int x, int y, Rgba8 color,
                    LcdOrder order);
void blend_lcd_mask(const PixelView& target, ConstMaskView mask, int x, int y, Rgba8 color,
                    LcdOrder order, const CoverageCurve& curve);
// Composites the image `source` (any PixelFormat; e.g. a colour glyph, Rgba8Premultiplied)
// "over" `target`: S = load_pixel(source pixel), α = S.a/255·opacity (opacity clamped to
// [0, 1]; 0 or NaN draws nothing). Pixels of source alpha 0 are skipped.
void blend_image(const PixelView& target, ConstPixelView source, int x, int y,
                 float opacity = 1);

// --- The same onto an Image and a gray page (what the renderers have always called) ---------------
// blend_mask and blend_lcd_mask onto an Image: exactly the PixelView functions on image.view()
// (PixelFormat::Rgba8), bit for bit.
void blend_mask(Image& image, ConstMaskView mask, int x, int y, Rgba8 color);
void blend_mask(Image& image, ConstMaskView mask, int x, int y, Rgba8 color,
                const CoverageCurve& curve);
void blend_lcd_mask(Image& image, ConstMaskView mask, int x, int y, Rgba8 color, LcdOrder order);
void blend_lcd_mask(Image& image, ConstMaskView mask, int x, int y, Rgba8 color, LcdOrder order,
                    const CoverageCurve& curve);

// blend_mask for a gray page (one sRGB-encoded byte per pixel, opaque) and an opaque gray colour:
// out = enc(lerp(dec(dst), dec(gray), α)). Equal, pixel for pixel, to blend_mask on a Gray8
// PixelView of the same memory with colour {gray, gray, gray, 255}, and to blend_mask on an
// RGBA page of the same grays (r = g = b = that byte), at a quarter of the memory.
void blend_mask_gray(MaskView page, ConstMaskView mask, int x, int y, std::uint8_t gray);
void blend_mask_gray(MaskView page, ConstMaskView mask, int x, int y, std::uint8_t gray,
                     const CoverageCurve& curve);

// The sRGB transfer function (IEC 61966-2-1) exactly as the blend functions above apply it, for
// the modules that mix colour themselves (the paint module's colour bitmaps and blend_rgba must
// agree with blend_mask bit for bit). srgb_decode is a table of the exact function rounded to
// float; srgb_encode quantizes linear light to 1/4095 and returns the byte nearest its encoding,
// within ±1 byte of the exact one, with srgb_encode(srgb_decode(v)) == v for every byte v. Inputs
// outside [0, 1] are clamped.
float srgb_decode(std::uint8_t encoded);
std::uint8_t srgb_encode(float linear);

// PNG colour layouts for writing.
enum class PngColor : std::uint8_t { Gray, Rgb, Rgba };

// How hard the PNG writers deflate: every level writes the same pixels (no row filter; PNG
// viewers see no difference), they differ in time and file size. Rows are never filtered: on
// text pages (long runs of the paper's byte) filtering made files larger at every level.
//   Fast:    igzip level 1: images on one thread as one stream; the banded gray writer's
//            64-row bands each deflated with an empty history (the cheapest deflate there is
//            here; largest file).
//   Default: igzip level 2: images on one thread as one stream (a few % smaller than Fast for
//            about the same time on small images). Banded gray writer: each band primed with
//            the 32 KiB of scanlines above it (a deflate window's worth), so bands find their
//            matches in the lines above as one stream would: on a page of text ~14 % smaller
//            than Fast for ~25 % more deflate time, still spread over the threads.
//   Small:   zlib level 6 through libpng (zlib's and libpng's default), one stream on the
//            calling thread, for every writer (the banded writer falls back to it). Levels 7-9
//            made text pages at most 2 % smaller for 1.2-14x the time.
//   (The one-stream writer holds a copy of every scanline while it deflates: an image of more
//   than 64 MiB of scanlines, a 4096 px square RGBA page, streams through libpng and zlib at
//   level 1 instead, with a buffer of one row.)
enum class PngCompression : std::uint8_t { Fast, Default, Small };
struct PngOptions {
    PngCompression compression = PngCompression::Default;
};

// Writes `image` as PNG in `color` (Gray: luma of the sRGB values, Rec. 709 weights; alpha
// dropped unless Rgba); errors name the file.
Status write_png(const std::string& file, const Image& image, PngColor color = PngColor::Rgba,
                 const PngOptions& options = {});
// PNG bytes in memory (for stdout and atomic writes).
Expected<std::vector<std::uint8_t>> encode_png(const Image& image, PngColor color,
                                               const PngOptions& options = {});
Expected<std::vector<std::uint8_t>> encode_png_gray(ConstMaskView mask,
                                                    const PngOptions& options = {});
// The same image, deflated on up to `threads` threads (at most kMaxPngThreads; 1 or fewer, a
// mask under 2·kPngBandRows rows, or PngCompression::Small, is the call above): the rows are
// cut into bands of kPngBandRows, each band deflated on its own by igzip and ended on a byte
// boundary (a sync flush), and the pieces joined into one zlib stream, as pigz does. A valid
// PNG that decodes to the same pixels; its bytes do not depend on `threads` (> 1). Errors as
// encode_png_gray.
inline constexpr int kMaxPngThreads = 8;
inline constexpr int kPngBandRows = 64;
Expected<std::vector<std::uint8_t>> encode_png_gray(ConstMaskView mask, int threads,
                                                    const PngOptions& options = {});

// The banded gray PNG writer above, fed while the page is still being drawn: bands are deflated
// on `workers` threads (0..kMaxPngThreads; a thread the system refuses is one fewer) as soon as
// the caller declares their rows final, so compressing overlaps drawing (bezel render draws a
// page of text top to bottom: TextRenderer::render_gray_streaming's PageRowsSink feeds this).
// Contract: `page` stays valid until finish() returns or the stream is destroyed; once rows
// [0, n) are declared final the caller no longer writes them (other rows it may write at any
// time: the workers read only final rows). The result equals encode_png_gray(page, threads)
// for any threads > 1 and the same options. One stream encodes one page; it is not itself
// shared between threads. With PngCompression::Small nothing is deflated before finish().
class PngGrayStream {
public:
    PngGrayStream(ConstMaskView page, int workers, const PngOptions& options = {});
    ~PngGrayStream();  // stops and joins the workers (after an abandoned page, too)
    PngGrayStream(const PngGrayStream&) = delete;
    PngGrayStream& operator=(const PngGrayStream&) = delete;

    // Rows [0, rows) will not change any more (monotone: a smaller value than before is
    // ignored). Costs an integer compare unless a band boundary is crossed.
    void rows_final(int rows);
    // Every row is final: this thread deflates the bands no worker has taken, joins the workers
    // and assembles the PNG. Call once.
    Expected<std::vector<std::uint8_t>> finish();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Netpbm: binary PGM (P5, luma) or PPM (P6, RGB), alpha dropped.
std::vector<std::uint8_t> encode_pgm(const Image& image);
std::vector<std::uint8_t> encode_ppm(const Image& image);
std::vector<std::uint8_t> encode_pgm(ConstMaskView mask);
// A terminal preview: 24-bit colour ANSI escapes, two image rows per text line (the upper half
// block U+2580 with foreground = upper pixel, background = lower pixel), at most `max_columns`
// characters wide (the image is box-filtered down to fit; 0 = no limit).
std::string encode_ansi(const Image& image, int max_columns = 0);

}  // namespace bezel
#pragma GCC visibility pop
