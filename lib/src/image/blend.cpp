// Compositing coverage masks onto RGBA8 images in linear light.
//
// The sRGB tables and their precision: image/srgb.hpp.
//
// Straight alpha "over" in linear light, α = coverage · colour.a (both in [0, 1]):
//   out.a = α + dst.a·(1 − α)
//   out.c = enc((dec(src.c)·α + dec(dst.c)·dst.a·(1 − α)) / out.a)
// For an opaque destination this is out.c = enc(lerp(dec(dst.c), dec(src.c), α)).
// Coverage becomes α through a CoverageCurve (image/coverage_curve.cpp); without one the curve
// is the identity, whose entries i/255.0f are the very floats `coverage / 255.0f` gives, so the
// curve-less functions are these with the identity, bit for bit.
#include <algorithm>
#include <array>

#include "bezel/image.hpp"
#include "image/srgb.hpp"

namespace bezel {

namespace {

// One destination pixel blended with the source colour (already decoded) at alphas per channel
// (one alpha for gray masks, three for LCD); `a` is the alpha for the alpha channel.
inline void blend_pixel(const SrgbTables& t, Rgba8& d, const float src[3], const float alpha[3],
                        float a) {
    if (d.a == 255) {
        // Opaque destination: the common case, a lerp per channel.
        std::uint8_t* ch[3] = {&d.r, &d.g, &d.b};
        for (int k = 0; k < 3; ++k) {
            float dl = t.decode[*ch[k]];
            *ch[k] = t.enc(dl + (src[k] - dl) * alpha[k]);
        }
        return;
    }
    float da = d.a / 255.0f;
    float out_a = a + da * (1.0f - a);
    if (out_a <= 0.0f) return;
    std::uint8_t* ch[3] = {&d.r, &d.g, &d.b};
    for (int k = 0; k < 3; ++k) {
        float dl = t.decode[*ch[k]];
        // Per-channel alphas (LCD) weight each channel by its own α, the alpha channel by `a`.
        float mixed = src[k] * alpha[k] + dl * da * (1.0f - alpha[k]);
        float norm = alpha[k] + da * (1.0f - alpha[k]);
        *ch[k] = t.enc(norm > 0.0f ? mixed / norm : 0.0f);
    }
    d.a = static_cast<std::uint8_t>(std::lround(out_a * 255.0f));
}

// The part of a mask of `w` × `h` pixels at (x, y) that lies inside the image.
struct Clip {
    int x0, y0, x1, y1;  // mask pixel range [x0, x1) × [y0, y1)
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

}  // namespace

namespace {

// The result of blending `color` at each coverage onto one destination colour: text is mostly
// drawn onto untouched background, so most pixels are a lookup here instead of six table reads
// and a division. One per thread (blend functions may run on several threads at once), rebuilt
// when the pair or the curve changes.
struct CoverageLut {
    Rgba8 dst{0, 0, 0, 0}, color{0, 0, 0, 0};
    CoverageCurve curve;
    bool valid = false;
    std::array<Rgba8, 256> out;
};

const CoverageLut& coverage_lut(Rgba8 dst, Rgba8 color, const CoverageCurve& curve,
                                const SrgbTables& t, const float src[3]) {
    thread_local CoverageLut lut;
    if (lut.valid && lut.dst == dst && lut.color == color && lut.curve.same_as(curve)) return lut;
    const float color_a = color.a / 255.0f;
    for (int cov = 0; cov < 256; ++cov) {
        Rgba8 d = dst;
        if (cov > 0) {
            float a = curve[static_cast<std::uint8_t>(cov)] * color_a;
            const float alpha[3] = {a, a, a};
            if (cov == 255 && color.a == 255) d = color;
            else blend_pixel(t, d, src, alpha, a);
        }
        lut.out[static_cast<std::size_t>(cov)] = d;
    }
    lut.dst = dst;
    lut.color = color;
    lut.curve = curve;
    lut.valid = true;
    return lut;
}

const CoverageCurve& identity_curve() {
    static const CoverageCurve identity;
    return identity;
}

}  // namespace

void blend_mask(Image& image, ConstMaskView mask, int x, int y, Rgba8 color) {
    blend_mask(image, mask, x, y, color, identity_curve());
}

void blend_mask(Image& image, ConstMaskView mask, int x, int y, Rgba8 color,
                const CoverageCurve& curve) {
    Clip c = clip(image.width(), image.height(), mask.width, mask.height, x, y);
    if (c.empty() || color.a == 0) return;
    const SrgbTables& t = srgb_tables();
    const float src[3] = {t.decode[color.r], t.decode[color.g], t.decode[color.b]};
    const float color_a = color.a / 255.0f;
    // The colour under the mask's first visible pixel is almost always the page's background.
    const CoverageLut& lut = coverage_lut(image.row(y + c.y0)[x + c.x0], color, curve, t, src);
    for (int my = c.y0; my < c.y1; ++my) {
        const std::uint8_t* m = mask.row(my);
        // Indexed from the first visible pixel: `x` may be negative.
        Rgba8* d = image.row(y + my) + (x + c.x0);
        for (int mx = c.x0; mx < c.x1; ++mx, ++d) {
            std::uint8_t cov = m[mx];
            if (cov == 0) continue;
            if (*d == lut.dst) {
                *d = lut.out[cov];
                continue;
            }
            if (cov == 255 && color.a == 255) {
                *d = color;
                continue;
            }
            float a = curve[cov] * color_a;
            const float alpha[3] = {a, a, a};
            blend_pixel(t, *d, src, alpha, a);
        }
    }
}

void blend_mask_gray(MaskView page, ConstMaskView mask, int x, int y, std::uint8_t gray) {
    blend_mask_gray(page, mask, x, y, gray, identity_curve());
}

void blend_mask_gray(MaskView page, ConstMaskView mask, int x, int y, std::uint8_t gray,
                     const CoverageCurve& curve) {
    if (page.data == nullptr || mask.data == nullptr) return;
    Clip c = clip(page.width, page.height, mask.width, mask.height, x, y);
    if (c.empty()) return;
    const SrgbTables& t = srgb_tables();
    const float src = t.decode[gray];
    // As blend_mask's CoverageLut, for one byte: the background under the mask's first visible
    // pixel, blended at each coverage (the same float steps as blend_pixel's opaque case, so
    // the two functions agree exactly).
    thread_local std::uint8_t lut_dst = 0, lut_gray = 0;
    thread_local CoverageCurve lut_curve;
    thread_local bool lut_valid = false;
    thread_local std::array<std::uint8_t, 256> lut;
    const std::uint8_t under = page.row(y + c.y0)[x + c.x0];
    if (!lut_valid || lut_dst != under || lut_gray != gray || !lut_curve.same_as(curve)) {
        const float dl = t.decode[under];
        lut[0] = under;
        for (int cov = 1; cov < 255; ++cov)
            lut[cov] = t.enc(dl + (src - dl) * curve[static_cast<std::uint8_t>(cov)]);
        lut[255] = gray;
        lut_dst = under;
        lut_gray = gray;
        lut_curve = curve;
        lut_valid = true;
    }
    for (int my = c.y0; my < c.y1; ++my) {
        const std::uint8_t* m = mask.row(my);
        std::uint8_t* d = page.row(y + my) + (x + c.x0);
        for (int mx = c.x0; mx < c.x1; ++mx, ++d) {
            const std::uint8_t cov = m[mx];
            if (cov == 0) continue;
            if (*d == lut_dst) {
                *d = lut[cov];
            } else if (cov == 255) {
                *d = gray;
            } else {
                const float dl = t.decode[*d];
                *d = t.enc(dl + (src - dl) * curve[cov]);
            }
        }
    }
}

void blend_lcd_mask(Image& image, ConstMaskView mask, int x, int y, Rgba8 color, LcdOrder order) {
    blend_lcd_mask(image, mask, x, y, color, order, identity_curve());
}

void blend_lcd_mask(Image& image, ConstMaskView mask, int x, int y, Rgba8 color, LcdOrder order,
                    const CoverageCurve& curve) {
    Clip c = clip(image.width(), image.height(), mask.width / 3, mask.height, x, y);
    if (c.empty() || color.a == 0) return;
    const SrgbTables& t = srgb_tables();
    const float src[3] = {t.decode[color.r], t.decode[color.g], t.decode[color.b]};
    const float color_a = color.a / 255.0f;
    const bool bgr = order == LcdOrder::Bgr;
    const int r_at = bgr ? 2 : 0, b_at = bgr ? 0 : 2;
    for (int my = c.y0; my < c.y1; ++my) {
        const std::uint8_t* m = mask.row(my);
        Rgba8* d = image.row(y + my) + (x + c.x0);
        for (int mx = c.x0; mx < c.x1; ++mx, ++d) {
            const std::uint8_t* p = m + 3 * mx;
            std::uint8_t cr = p[r_at], cg = p[1], cb = p[b_at];
            if ((cr | cg | cb) == 0) continue;
            const float alpha[3] = {curve[cr] * color_a, curve[cg] * color_a,
                                    curve[cb] * color_a};
            // The alpha channel takes the strongest subpixel: the pixel is at least that covered.
            float a = std::max({alpha[0], alpha[1], alpha[2]});
            blend_pixel(t, *d, src, alpha, a);
        }
    }
}

}  // namespace bezel
