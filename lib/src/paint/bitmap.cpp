// Colour bitmaps: premultiplied RGBA scaled in linear light, converted to and from straight
// alpha, and composited onto a page.
//
// Linear light on premultiplied values: a pixel (c, a) of premultiplied sRGB-encoded bytes is
// the straight colour s = c·255/a (rounded to a byte, the precision it had before it was
// premultiplied), decoded, L = dec(s)·a/255. Filters average L and a; the result is encoded back
// as s' = enc(L/a), c' = round(s'·a'/255). A flat colour stays flat (round(round(c·255/a)·a/255)
// = c for every c ≤ a), and averaging in light keeps a shrunk emoji as bright as the original.
#include <algorithm>
#include <cmath>
#include <vector>

#include "bezel/image.hpp"
#include "bezel/paint.hpp"

namespace bezel {

namespace {

std::uint8_t straight_byte(std::uint8_t c, std::uint8_t a) {
    if (a == 0) return 0;
    return static_cast<std::uint8_t>(std::min(255, (c * 255 + a / 2) / a));
}

std::uint8_t premultiply_byte(std::uint8_t s, std::uint8_t a) {
    return static_cast<std::uint8_t>((s * a + 127) / 255);
}

// How one axis of n source pixels maps onto m target pixels: target pixel i is
// Σ weights[k]·source[start + k - first] over its taps, the weights summing to 1.
struct AxisTaps {
    std::vector<int> start, count;
    std::vector<std::size_t> first;   // index of pixel i's first weight
    std::vector<float> weights;

    AxisTaps(int n, int m, BitmapFilter filter) {
        const double scale = static_cast<double>(n) / m;
        for (int i = 0; i < m; ++i) {
            first.push_back(weights.size());
            if (filter == BitmapFilter::Box) {
                // Target pixel i covers source [i·scale, (i+1)·scale]; each source pixel j
                // weighs its overlap with that span, over the span's length.
                const double lo = i * scale, hi = (i + 1) * scale;
                const int j0 = std::clamp(static_cast<int>(std::floor(lo)), 0, n - 1);
                const int j1 = std::clamp(static_cast<int>(std::ceil(hi)), j0 + 1, n);
                start.push_back(j0);
                count.push_back(j1 - j0);
                for (int j = j0; j < j1; ++j) {
                    const double overlap = std::min<double>(hi, j + 1) - std::max<double>(lo, j);
                    weights.push_back(static_cast<float>(std::max(0.0, overlap) / scale));
                }
            } else {
                // The source sampled at target pixel i's centre, u in source pixel-centre units,
                // clamped to the edge pixels' centres: weights 1 − f and f of the two nearest.
                const double u = std::clamp((i + 0.5) * scale - 0.5, 0.0, n - 1.0);
                const int j0 = std::min(static_cast<int>(std::floor(u)), n - 1);
                const float f = static_cast<float>(u - j0);
                start.push_back(j0);
                if (j0 + 1 < n && f > 0.0f) {
                    count.push_back(2);
                    weights.push_back(1.0f - f);
                    weights.push_back(f);
                } else {
                    count.push_back(1);
                    weights.push_back(1.0f);
                }
            }
        }
    }
};

}  // namespace

void scale_rgba(ConstRgbaView source, const RgbaView& target, BitmapFilter filter) {
    if (source.data == nullptr || target.data == nullptr || source.width <= 0 ||
        source.height <= 0 || target.width <= 0 || target.height <= 0)
        return;
    const int sw = source.width, sh = source.height, tw = target.width, th = target.height;
    const AxisTaps xs(sw, tw, filter), ys(sh, th, filter);
    // Horizontal pass: every source row decoded to linear premultiplied and resampled to tw.
    std::vector<float> row(static_cast<std::size_t>(sw) * 4);
    std::vector<float> mid(static_cast<std::size_t>(sh) * static_cast<std::size_t>(tw) * 4);
    for (int y = 0; y < sh; ++y) {
        const std::uint8_t* s = source.row(y);
        for (int x = 0; x < sw; ++x, s += 4) {
            const float a = s[3] / 255.0f;
            float* r = &row[static_cast<std::size_t>(x) * 4];
            for (int k = 0; k < 3; ++k) r[k] = srgb_decode(straight_byte(s[k], s[3])) * a;
            r[3] = a;
        }
        float* m = &mid[static_cast<std::size_t>(y) * static_cast<std::size_t>(tw) * 4];
        for (int i = 0; i < tw; ++i, m += 4) {
            float acc[4] = {0, 0, 0, 0};
            const float* w = &xs.weights[xs.first[static_cast<std::size_t>(i)]];
            for (int k = 0; k < xs.count[static_cast<std::size_t>(i)]; ++k) {
                const float* p = &row[static_cast<std::size_t>(xs.start[static_cast<std::size_t>(i)] + k) * 4];
                for (int c = 0; c < 4; ++c) acc[c] += w[k] * p[c];
            }
            std::copy(acc, acc + 4, m);
        }
    }
    // Vertical pass, then encoding.
    for (int j = 0; j < th; ++j) {
        std::uint8_t* d = target.row(j);
        const float* w = &ys.weights[ys.first[static_cast<std::size_t>(j)]];
        const int y0 = ys.start[static_cast<std::size_t>(j)], n = ys.count[static_cast<std::size_t>(j)];
        for (int i = 0; i < tw; ++i, d += 4) {
            float acc[4] = {0, 0, 0, 0};
            for (int k = 0; k < n; ++k) {
                const float* p = &mid[(static_cast<std::size_t>(y0 + k) * static_cast<std::size_t>(tw) +
                                       static_cast<std::size_t>(i)) * 4];
                for (int c = 0; c < 4; ++c) acc[c] += w[k] * p[c];
            }
            const float a = std::clamp(acc[3], 0.0f, 1.0f);
            const auto ab = static_cast<std::uint8_t>(a * 255.0f + 0.5f);
            d[3] = ab;
            for (int c = 0; c < 3; ++c)
                d[c] = ab == 0 ? 0 : premultiply_byte(srgb_encode(acc[c] / a), ab);
        }
    }
}

Image to_image(ConstRgbaView premultiplied) {
    if (premultiplied.data == nullptr || premultiplied.width <= 0 || premultiplied.height <= 0)
        return Image();
    Image out(premultiplied.width, premultiplied.height);
    for (int y = 0; y < premultiplied.height; ++y) {
        const std::uint8_t* s = premultiplied.row(y);
        Rgba8* d = out.row(y);
        for (int x = 0; x < premultiplied.width; ++x, s += 4, ++d)
            *d = {straight_byte(s[0], s[3]), straight_byte(s[1], s[3]), straight_byte(s[2], s[3]),
                  s[3]};
    }
    return out;
}

void premultiply(const Image& image, const RgbaView& target) {
    if (target.data == nullptr) return;
    const int w = std::min(image.width(), target.width), h = std::min(image.height(), target.height);
    for (int y = 0; y < h; ++y) {
        const Rgba8* s = image.row(y);
        std::uint8_t* d = target.row(y);
        for (int x = 0; x < w; ++x, ++s, d += 4) {
            d[0] = premultiply_byte(s->r, s->a);
            d[1] = premultiply_byte(s->g, s->a);
            d[2] = premultiply_byte(s->b, s->a);
            d[3] = s->a;
        }
    }
}

// image.hpp's blend_image on the page's view, the glyph read as Rgba8Premultiplied: the same
// arithmetic as blend_mask, so an opaque-colour glyph blends as its mask would.
void blend_rgba(Image& page, ConstRgbaView glyph, int x, int y, float opacity) {
    blend_image(page.view(),
                ConstPixelView(glyph.data, glyph.width, glyph.height, glyph.stride,
                               PixelFormat::Rgba8Premultiplied),
                x, y, opacity);
}

}  // namespace bezel
