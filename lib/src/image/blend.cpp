// Compositing coverage masks and images onto PixelViews in linear light.
//
// The sRGB tables and their precision: image/srgb.hpp. The pixel formats: image/pixel_format.hpp.
//
// Straight alpha "over" in linear light, α = coverage · colour.a (both in [0, 1]):
//   out.a = α + dst.a·(1 − α)
//   out.c = enc((dec(src.c)·α + dec(dst.c)·dst.a·(1 − α)) / out.a)
// For an opaque destination this is out.c = enc(lerp(dec(dst.c), dec(src.c), α)).
// Coverage becomes α through a CoverageCurve (image/coverage_curve.cpp); without one the curve
// is the identity, whose entries i/255.0f are the very floats `coverage / 255.0f` gives, so the
// curve-less functions are these with the identity, bit for bit.
//
// Every 4-byte format runs the same float arithmetic on the straight colour load_pixel gives
// (a template per layout: the channel offsets and the premultiplication are compile-time), so
// formats differ only in how a pixel is read and written; Gray8 runs the one-channel lerp.
#include <algorithm>
#include <array>
#include <cmath>

#include "bezel/image.hpp"
#include "image/pixel_format.hpp"
#include "image/srgb.hpp"

namespace bezel {

using image_detail::with_quad;

namespace {

// One destination pixel, its straight channels at r, g, b and a, blended with the source colour
// (already decoded) at alphas per channel (one alpha for gray masks, three for LCD); `a` is the
// alpha for the alpha channel. In place, so a straight target is blended in its own memory.
inline void blend_channels(const SrgbTables& t, std::uint8_t* r, std::uint8_t* g, std::uint8_t* b,
                           std::uint8_t* da_byte, const float src[3], const float alpha[3],
                           float a) {
    std::uint8_t* ch[3] = {r, g, b};
    if (*da_byte == 255) {
        // Opaque destination: the common case, a lerp per channel.
        for (int k = 0; k < 3; ++k) {
            float dl = t.decode[*ch[k]];
            *ch[k] = t.enc(dl + (src[k] - dl) * alpha[k]);
        }
        return;
    }
    float da = *da_byte / 255.0f;
    float out_a = a + da * (1.0f - a);
    if (out_a <= 0.0f) return;
    for (int k = 0; k < 3; ++k) {
        float dl = t.decode[*ch[k]];
        // Per-channel alphas (LCD) weight each channel by its own α, the alpha channel by `a`.
        float mixed = src[k] * alpha[k] + dl * da * (1.0f - alpha[k]);
        float norm = alpha[k] + da * (1.0f - alpha[k]);
        *ch[k] = t.enc(norm > 0.0f ? mixed / norm : 0.0f);
    }
    *da_byte = static_cast<std::uint8_t>(std::lround(out_a * 255.0f));
}

inline void blend_pixel(const SrgbTables& t, Rgba8& d, const float src[3], const float alpha[3],
                        float a) {
    blend_channels(t, &d.r, &d.g, &d.b, &d.a, src, alpha, a);
}

// The same on a pixel of the target's layout: in place for straight formats, through
// load/store (un- and re-premultiplied) for premultiplied ones.
template <typename Layout>
inline void blend_at(const SrgbTables& t, std::uint8_t* p, const float src[3],
                     const float alpha[3], float a) {
    if (Layout::kPremultiplied) {
        Rgba8 px = Layout::load(p);
        blend_pixel(t, px, src, alpha, a);
        Layout::store(p, px);
    } else {
        blend_channels(t, p + Layout::kR, p + 1, p + Layout::kB, p + 3, src, alpha, a);
    }
}

// The one-channel mix of a Gray8 target: the opaque case of blend_pixel.
inline std::uint8_t blend_gray(const SrgbTables& t, std::uint8_t d, float src, float alpha) {
    const float dl = t.decode[d];
    return t.enc(dl + (src - dl) * alpha);
}

// The part of a source of `w` × `h` pixels at (x, y) that lies inside the target.
struct Clip {
    int x0, y0, x1, y1;  // source pixel range [x0, x1) × [y0, y1)
    bool empty() const { return x0 >= x1 || y0 >= y1; }
};
Clip clip(int page_w, int page_h, int w, int h, int x, int y) {
    // 64-bit sums: a mask placed near INT_MAX must not overflow.
    long long x0 = std::max(0LL, -static_cast<long long>(x));
    long long y0 = std::max(0LL, -static_cast<long long>(y));
    long long x1 = std::min<long long>(w, static_cast<long long>(page_w) - x);
    long long y1 = std::min<long long>(h, static_cast<long long>(page_h) - y);
    return {static_cast<int>(x0), static_cast<int>(y0), static_cast<int>(std::max(x0, x1)),
            static_cast<int>(std::max(y0, y1))};
}

const CoverageCurve& identity_curve() {
    static const CoverageCurve identity;
    return identity;
}

// The result of blending `color` at each coverage onto one destination pixel (its bytes in the
// target's format): text is mostly drawn onto untouched background, so most pixels are a lookup
// here instead of six table reads and a division. One per thread (blend functions may run on
// several threads at once), rebuilt when the pixel, the colour, the curve or the format changes.
struct CoverageLut {
    std::uint32_t dst = 0;
    Rgba8 color{0, 0, 0, 0};
    PixelFormat format = PixelFormat::Gray8;
    CoverageCurve curve;
    bool valid = false;
    std::array<std::uint32_t, 256> out;
};

template <typename Layout>
const CoverageLut& coverage_lut(PixelFormat format, std::uint32_t dst, Rgba8 color,
                                const CoverageCurve& curve, const SrgbTables& t,
                                const float src[3]) {
    thread_local CoverageLut lut;
    if (lut.valid && lut.dst == dst && lut.color == color && lut.format == format &&
        lut.curve.same_as(curve))
        return lut;
    std::uint8_t bytes[4];
    Layout::put_word(bytes, dst);
    const Rgba8 under = Layout::load(bytes);
    const float color_a = color.a / 255.0f;
    lut.out[0] = dst;
    for (int cov = 1; cov < 256; ++cov) {
        Rgba8 d = under;
        float a = curve[static_cast<std::uint8_t>(cov)] * color_a;
        const float alpha[3] = {a, a, a};
        if (cov == 255 && color.a == 255) d = color;
        else blend_pixel(t, d, src, alpha, a);
        lut.out[static_cast<std::size_t>(cov)] = Layout::word_of(d);
    }
    lut.dst = dst;
    lut.color = color;
    lut.format = format;
    lut.curve = curve;
    lut.valid = true;
    return lut;
}

template <typename Layout>
void mask_onto_quad(const PixelView& target, ConstMaskView mask, const Clip& c, int x, int y,
                    Rgba8 color, const CoverageCurve& curve) {
    const SrgbTables& t = srgb_tables();
    const float src[3] = {t.decode[color.r], t.decode[color.g], t.decode[color.b]};
    const float color_a = color.a / 255.0f;
    const std::uint32_t full = Layout::word_of(color);
    // The pixel under the mask's first visible pixel is almost always the page's background.
    const std::uint8_t* under = target.row(y + c.y0) + 4 * static_cast<std::ptrdiff_t>(x + c.x0);
    const CoverageLut& lut =
        coverage_lut<Layout>(target.format, Layout::word(under), color, curve, t, src);
    for (int my = c.y0; my < c.y1; ++my) {
        const std::uint8_t* m = mask.row(my);
        // Indexed from the first visible pixel: `x` may be negative.
        std::uint8_t* d = target.row(y + my) + 4 * static_cast<std::ptrdiff_t>(x + c.x0);
        for (int mx = c.x0; mx < c.x1; ++mx, d += 4) {
            const std::uint8_t cov = m[mx];
            if (cov == 0) continue;
            if (Layout::word(d) == lut.dst) {
                Layout::put_word(d, lut.out[cov]);
                continue;
            }
            if (cov == 255 && color.a == 255) {
                Layout::put_word(d, full);
                continue;
            }
            const float a = curve[cov] * color_a;
            const float alpha[3] = {a, a, a};
            blend_at<Layout>(t, d, src, alpha, a);
        }
    }
}

// A gray mask onto a Gray8 target, in the gray `gray` of alpha color_a; Opaque: color_a is 255,
// so α = curve[coverage] with no product (the same float: curve[c]·1.0f is curve[c]) and full
// coverage writes the gray itself.
template <bool Opaque>
void mask_onto_gray(const PixelView& page, ConstMaskView mask, const Clip& c, int x, int y,
                    std::uint8_t gray, std::uint8_t color_a, const CoverageCurve& curve) {
    const SrgbTables& t = srgb_tables();
    const float src = t.decode[gray];
    const float ca = color_a / 255.0f;
    auto alpha = [&](std::uint8_t cov) { return Opaque ? curve[cov] : curve[cov] * ca; };
    // As the 4-byte formats' CoverageLut, for one byte: the background under the mask's first
    // visible pixel, blended at each coverage (the same float steps as blend_pixel's opaque
    // case, so a gray page and an RGBA page of the same grays agree exactly).
    thread_local std::uint8_t lut_dst = 0, lut_gray = 0, lut_a = 0;
    thread_local CoverageCurve lut_curve;
    thread_local bool lut_valid = false;
    thread_local std::array<std::uint8_t, 256> lut;
    const std::uint8_t under = page.row(y + c.y0)[x + c.x0];
    if (!lut_valid || lut_dst != under || lut_gray != gray || lut_a != color_a ||
        !lut_curve.same_as(curve)) {
        lut[0] = under;
        for (int cov = 1; cov < 255; ++cov)
            lut[cov] = blend_gray(t, under, src, alpha(static_cast<std::uint8_t>(cov)));
        lut[255] = Opaque ? gray : blend_gray(t, under, src, alpha(255));
        lut_dst = under;
        lut_gray = gray;
        lut_a = color_a;
        lut_curve = curve;
        lut_valid = true;
    }
    for (int my = c.y0; my < c.y1; ++my) {
        const std::uint8_t* m = mask.row(my);
        std::uint8_t* d = page.row(y + my) + (x + c.x0);
        for (int mx = c.x0; mx < c.x1; ++mx, ++d) {
            const std::uint8_t cov = m[mx];
            if (cov == 0) continue;
            if (*d == lut_dst) *d = lut[cov];
            else if (Opaque && cov == 255) *d = gray;
            else *d = blend_gray(t, *d, src, alpha(cov));
        }
    }
}

// blend_mask onto a Gray8 target, after its checks.
void mask_onto_gray(const PixelView& page, ConstMaskView mask, int x, int y, Rgba8 color,
                    const CoverageCurve& curve) {
    const Clip c = clip(page.width, page.height, mask.width, mask.height, x, y);
    if (c.empty()) return;
    if (color.a == 255) mask_onto_gray<true>(page, mask, c, x, y, luma(color), 255, curve);
    else mask_onto_gray<false>(page, mask, c, x, y, luma(color), color.a, curve);
}

template <typename Layout>
void lcd_onto_quad(const PixelView& target, ConstMaskView mask, const Clip& c, int x, int y,
                   Rgba8 color, int r_at, int b_at, const CoverageCurve& curve) {
    const SrgbTables& t = srgb_tables();
    const float src[3] = {t.decode[color.r], t.decode[color.g], t.decode[color.b]};
    const float color_a = color.a / 255.0f;
    for (int my = c.y0; my < c.y1; ++my) {
        const std::uint8_t* m = mask.row(my);
        std::uint8_t* d = target.row(y + my) + 4 * static_cast<std::ptrdiff_t>(x + c.x0);
        for (int mx = c.x0; mx < c.x1; ++mx, d += 4) {
            const std::uint8_t* p = m + 3 * mx;
            const std::uint8_t cr = p[r_at], cg = p[1], cb = p[b_at];
            if ((cr | cg | cb) == 0) continue;
            const float alpha[3] = {curve[cr] * color_a, curve[cg] * color_a,
                                    curve[cb] * color_a};
            // The alpha channel takes the strongest subpixel: the pixel is at least that covered.
            const float a = std::max({alpha[0], alpha[1], alpha[2]});
            blend_at<Layout>(t, d, src, alpha, a);
        }
    }
}

void lcd_onto_gray(const PixelView& page, ConstMaskView mask, const Clip& c, int x, int y,
                   Rgba8 color, const CoverageCurve& curve) {
    const SrgbTables& t = srgb_tables();
    const float src = t.decode[luma(color)];
    const float color_a = color.a / 255.0f;
    for (int my = c.y0; my < c.y1; ++my) {
        const std::uint8_t* m = mask.row(my);
        std::uint8_t* d = page.row(y + my) + (x + c.x0);
        for (int mx = c.x0; mx < c.x1; ++mx, ++d) {
            const std::uint8_t* p = m + 3 * mx;
            if ((p[0] | p[1] | p[2]) == 0) continue;
            const float a = (curve[p[0]] + curve[p[1]] + curve[p[2]]) * (1.0f / 3.0f) * color_a;
            *d = blend_gray(t, *d, src, a);
        }
    }
}

template <typename Layout>
void image_onto_quad(const PixelView& target, ConstPixelView source, const Clip& c, int x, int y,
                     float opacity) {
    const SrgbTables& t = srgb_tables();
    const int sbpp = bytes_per_pixel(source.format);
    for (int sy = c.y0; sy < c.y1; ++sy) {
        const std::uint8_t* s = source.row(sy) + static_cast<std::ptrdiff_t>(c.x0) * sbpp;
        std::uint8_t* d = target.row(y + sy) + 4 * static_cast<std::ptrdiff_t>(x + c.x0);
        for (int sx = c.x0; sx < c.x1; ++sx, s += sbpp, d += 4) {
            const Rgba8 sp = load_pixel(source.format, s);
            if (sp.a == 0) continue;
            const float a = (sp.a / 255.0f) * opacity;
            const float src[3] = {t.decode[sp.r], t.decode[sp.g], t.decode[sp.b]};
            const float alpha[3] = {a, a, a};
            blend_at<Layout>(t, d, src, alpha, a);
        }
    }
}

void image_onto_gray(const PixelView& page, ConstPixelView source, const Clip& c, int x, int y,
                     float opacity) {
    const SrgbTables& t = srgb_tables();
    const int sbpp = bytes_per_pixel(source.format);
    for (int sy = c.y0; sy < c.y1; ++sy) {
        const std::uint8_t* s = source.row(sy) + static_cast<std::ptrdiff_t>(c.x0) * sbpp;
        std::uint8_t* d = page.row(y + sy) + (x + c.x0);
        for (int sx = c.x0; sx < c.x1; ++sx, s += sbpp, ++d) {
            const Rgba8 sp = load_pixel(source.format, s);
            if (sp.a == 0) continue;
            *d = blend_gray(t, *d, t.decode[luma(sp)], (sp.a / 255.0f) * opacity);
        }
    }
}

}  // namespace

void blend_mask(const PixelView& target, ConstMaskView mask, int x, int y, Rgba8 color) {
    blend_mask(target, mask, x, y, color, identity_curve());
}

void blend_mask(const PixelView& target, ConstMaskView mask, int x, int y, Rgba8 color,
                const CoverageCurve& curve) {
    if (target.data == nullptr || mask.data == nullptr || color.a == 0) return;
    if (target.format == PixelFormat::Gray8) {
        mask_onto_gray(target, mask, x, y, color, curve);
        return;
    }
    const Clip c = clip(target.width, target.height, mask.width, mask.height, x, y);
    if (c.empty()) return;
    with_quad(target.format, [&](auto layout) {
        mask_onto_quad<decltype(layout)>(target, mask, c, x, y, color, curve);
    });
}

void blend_mask(Image& image, ConstMaskView mask, int x, int y, Rgba8 color) {
    blend_mask(image.view(), mask, x, y, color, identity_curve());
}

void blend_mask(Image& image, ConstMaskView mask, int x, int y, Rgba8 color,
                const CoverageCurve& curve) {
    blend_mask(image.view(), mask, x, y, color, curve);
}

void blend_mask_gray(MaskView page, ConstMaskView mask, int x, int y, std::uint8_t gray) {
    blend_mask_gray(page, mask, x, y, gray, identity_curve());
}

void blend_mask_gray(MaskView page, ConstMaskView mask, int x, int y, std::uint8_t gray,
                     const CoverageCurve& curve) {
    if (page.data == nullptr || mask.data == nullptr) return;
    mask_onto_gray(PixelView{page.data, page.width, page.height, page.stride, PixelFormat::Gray8},
                   mask, x, y, Rgba8{gray, gray, gray, 255}, curve);
}

void blend_lcd_mask(const PixelView& target, ConstMaskView mask, int x, int y, Rgba8 color,
                    LcdOrder order) {
    blend_lcd_mask(target, mask, x, y, color, order, identity_curve());
}

void blend_lcd_mask(const PixelView& target, ConstMaskView mask, int x, int y, Rgba8 color,
                    LcdOrder order, const CoverageCurve& curve) {
    if (target.data == nullptr || mask.data == nullptr || color.a == 0) return;
    const Clip c = clip(target.width, target.height, mask.width / 3, mask.height, x, y);
    if (c.empty()) return;
    // The mask's bytes are the subpixels left to right: the panel's colours in its order.
    const bool bgr = order == LcdOrder::Bgr;
    const int r_at = bgr ? 2 : 0, b_at = bgr ? 0 : 2;
    if (!with_quad(target.format, [&](auto layout) {
            lcd_onto_quad<decltype(layout)>(target, mask, c, x, y, color, r_at, b_at, curve);
        }))
        lcd_onto_gray(target, mask, c, x, y, color, curve);
}

void blend_lcd_mask(Image& image, ConstMaskView mask, int x, int y, Rgba8 color, LcdOrder order) {
    blend_lcd_mask(image.view(), mask, x, y, color, order, identity_curve());
}

void blend_lcd_mask(Image& image, ConstMaskView mask, int x, int y, Rgba8 color, LcdOrder order,
                    const CoverageCurve& curve) {
    blend_lcd_mask(image.view(), mask, x, y, color, order, curve);
}

void blend_image(const PixelView& target, ConstPixelView source, int x, int y, float opacity) {
    if (target.data == nullptr || source.data == nullptr || !(opacity > 0.0f)) return;
    opacity = std::min(opacity, 1.0f);
    const Clip c = clip(target.width, target.height, source.width, source.height, x, y);
    if (c.empty()) return;
    if (!with_quad(target.format, [&](auto layout) {
            image_onto_quad<decltype(layout)>(target, source, c, x, y, opacity);
        }))
        image_onto_gray(target, source, c, x, y, opacity);
}

}  // namespace bezel
