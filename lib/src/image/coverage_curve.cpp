// CoverageCurve: the alpha the linear-light blend uses for each coverage, for one text colour on
// one background (TextRendering::Perceptual), so text keeps the weight renderers that mix
// encoded values give it, in both polarities.
//
// For coverage c = i/255, with Yf, Yb the linear-light luminances (Rec. 709 weights of the
// decoded channels) of the foreground and the background, ef = enc(Yf), eb = enc(Yb) their sRGB
// encodings, G the gamma and k the contrast:
//   c1 = c + k·c·(1 − c)                       contrast lift (Skia's "contrast hint")
//   e  = (eb^G + (ef^G − eb^G)·c1)^(1/G)       the pixel value a renderer mixing the light v^G
//                                              of pixel values v would write (G = 1: the
//                                              encoded values mixed as they are, as cairo does)
//   alpha = (dec(e) − Yb) / (Yf − Yb)          the linear-light mix giving that pixel value
// Each step is non-decreasing in c (c1 because dc1/dc = 1 + k(1 − 2c) ≥ 1 − k ≥ 0; e because
// x ↦ x^G and its inverse are increasing; alpha because dec is increasing and the division's sign
// is that of Yf − Yb, the direction e moves in), c = 0 gives e = eb and alpha 0, c = 1 gives
// e = ef and alpha 1 (set exactly, against float rounding). Dark text on light gains weight
// (alpha ≥ c1 for G below sRGB's ~2.2) and light text on dark loses it, as both do in cairo.
// When the two luminances are (nearly) equal the text is invisible whatever alpha is: alpha = c1.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <sstream>
#include <string>

#include "bezel/image.hpp"

namespace bezel {

namespace {

// The continuous sRGB transfer function (IEC 61966-2-1), in double: the curve is made once per
// page, and the tables of image/srgb.hpp are quantized for blending, not for this.
double srgb_decode(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }
double srgb_encode(double l) {
    return l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055;
}

double luminance(Rgba8 c) {
    return 0.2126 * srgb_decode(c.r / 255.0) + 0.7152 * srgb_decode(c.g / 255.0) +
           0.0722 * srgb_decode(c.b / 255.0);
}

// A setting as a person would write it ("0.5", not std::to_string's "0.500000").
std::string number(double v) {
    std::ostringstream out;
    out << v;
    return out.str();
}

// Curves made by coverage_curve get ids from 1 up; 0 is the identity.
std::atomic<std::uint64_t> g_next_curve_id{1};

// Below this difference of luminances text and page are indistinguishable (under half a level of
// an 8-bit channel near black, where levels are finest).
constexpr double kInvisibleLuminance = 1e-4;

}  // namespace

CoverageCurve::CoverageCurve() {
    for (int i = 0; i < 256; ++i) alpha_[static_cast<std::size_t>(i)] = static_cast<float>(i) / 255.0f;
}

Expected<CoverageCurve> coverage_curve(Rgba8 foreground, Rgba8 background,
                                       const CoverageCurveOptions& options) {
    CoverageCurve curve;
    if (options.rendering == TextRendering::Linear) return curve;
    const double gamma = options.gamma, k = options.contrast;
    // Written so that NaN fails too.
    if (!(gamma >= kMinTextGamma && gamma <= kMaxTextGamma))
        return Error{"text gamma " + number(gamma) + " is out of range (" + number(kMinTextGamma) +
                     " to " + number(kMaxTextGamma) + ")"};
    if (!(k >= 0.0 && k <= kMaxTextContrast))
        return Error{"text contrast " + number(k) + " is out of range (0 to " +
                     number(kMaxTextContrast) + ")"};

    const double yf = luminance(foreground);
    double yb = luminance(background);
    if (background.a != 255) {
        // A translucent page is composited later over something unknown: assume the backdrop
        // text of this colour is normally read on (as Skia assumes the opposite luminance).
        const double backdrop = srgb_encode(yf) < 0.5 ? 1.0 : 0.0;
        const double a = background.a / 255.0;
        yb = yb * a + backdrop * (1.0 - a);
    }
    const double lf = std::pow(srgb_encode(yf), gamma), lb = std::pow(srgb_encode(yb), gamma);
    const bool visible = std::fabs(yf - yb) >= kInvisibleLuminance;
    for (int i = 1; i < 255; ++i) {
        const double c = i / 255.0;
        const double c1 = c + k * c * (1.0 - c);
        double alpha = c1;
        if (visible) {
            const double e = std::pow(lb + (lf - lb) * c1, 1.0 / gamma);
            alpha = (srgb_decode(e) - yb) / (yf - yb);
        }
        curve.alpha_[static_cast<std::size_t>(i)] = static_cast<float>(std::clamp(alpha, 0.0, 1.0));
    }
    curve.alpha_[0] = 0.0f;
    curve.alpha_[255] = 1.0f;
    curve.id_ = g_next_curve_id.fetch_add(1, std::memory_order_relaxed);
    return curve;
}

}  // namespace bezel
