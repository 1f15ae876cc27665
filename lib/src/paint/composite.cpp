// PaintComposite's modes, per W3C Compositing and Blending Level 1 (the COLR specification
// takes its modes from there), on premultiplied values.
//
// Porter-Duff (§9.1): with premultiplied source cs, αs and backdrop cb, αb,
//   co = cs·Fa + cb·Fb,   αo = αs·Fa + αb·Fb
// and Fa, Fb per mode as tabulated in porter_duff() below. Plus adds and clamps at 1.
//
// Blend modes (§5, "the general formula" with Porter-Duff source-over):
//   co = cs·(1 − αb) + cb·(1 − αs) + αs·αb·B(Cb, Cs),   αo = αs + αb·(1 − αs)
// where Cb = cb/αb and Cs = cs/αs are the straight colours and B the blend function: separable
// modes apply B to each channel (§5.8 – 5.10), non-separable ones (Hue, Saturation, Color,
// Luminosity, §5.8) to the colour as a whole through Lum / SetLum / Sat / SetSat / ClipColor.
#include "paint/composite.hpp"

#include <algorithm>
#include <cmath>

namespace bezel {

const char* composite_mode_name(CompositeMode mode) {
    switch (mode) {
        case CompositeMode::Clear: return "clear";
        case CompositeMode::Src: return "src";
        case CompositeMode::Dest: return "dest";
        case CompositeMode::SrcOver: return "src_over";
        case CompositeMode::DestOver: return "dest_over";
        case CompositeMode::SrcIn: return "src_in";
        case CompositeMode::DestIn: return "dest_in";
        case CompositeMode::SrcOut: return "src_out";
        case CompositeMode::DestOut: return "dest_out";
        case CompositeMode::SrcAtop: return "src_atop";
        case CompositeMode::DestAtop: return "dest_atop";
        case CompositeMode::Xor: return "xor";
        case CompositeMode::Plus: return "plus";
        case CompositeMode::Screen: return "screen";
        case CompositeMode::Overlay: return "overlay";
        case CompositeMode::Darken: return "darken";
        case CompositeMode::Lighten: return "lighten";
        case CompositeMode::ColorDodge: return "color_dodge";
        case CompositeMode::ColorBurn: return "color_burn";
        case CompositeMode::HardLight: return "hard_light";
        case CompositeMode::SoftLight: return "soft_light";
        case CompositeMode::Difference: return "difference";
        case CompositeMode::Exclusion: return "exclusion";
        case CompositeMode::Multiply: return "multiply";
        case CompositeMode::Hue: return "hue";
        case CompositeMode::Saturation: return "saturation";
        case CompositeMode::Color: return "color";
        case CompositeMode::Luminosity: return "luminosity";
    }
    return "unknown";
}

namespace paint_detail {
namespace {

struct Rgb {
    float r, g, b;
};

// --- Separable blend functions B(Cb, Cs), straight colours in [0, 1] ---------------------------
float multiply(float cb, float cs) { return cb * cs; }
float screen(float cb, float cs) { return cb + cs - cb * cs; }
// HardLight: Multiply(Cb, 2·Cs) below Cs = ½, Screen(Cb, 2·Cs − 1) above.
float hard_light(float cb, float cs) {
    return cs <= 0.5f ? multiply(cb, 2.0f * cs) : screen(cb, 2.0f * cs - 1.0f);
}
// ColorDodge: 0 where Cb = 0, 1 where Cs = 1, else min(1, Cb / (1 − Cs)).
float color_dodge(float cb, float cs) {
    if (cb == 0.0f) return 0.0f;
    if (cs >= 1.0f) return 1.0f;
    return std::min(1.0f, cb / (1.0f - cs));
}
// ColorBurn: 1 where Cb = 1, 0 where Cs = 0, else 1 − min(1, (1 − Cb) / Cs).
float color_burn(float cb, float cs) {
    if (cb >= 1.0f) return 1.0f;
    if (cs == 0.0f) return 0.0f;
    return 1.0f - std::min(1.0f, (1.0f - cb) / cs);
}
// SoftLight: Cb − (1 − 2Cs)·Cb·(1 − Cb) below Cs = ½; above, Cb + (2Cs − 1)·(D(Cb) − Cb) with
// D(Cb) = ((16Cb − 12)·Cb + 4)·Cb for Cb ≤ ¼, √Cb otherwise.
float soft_light(float cb, float cs) {
    if (cs <= 0.5f) return cb - (1.0f - 2.0f * cs) * cb * (1.0f - cb);
    const float d = cb <= 0.25f ? ((16.0f * cb - 12.0f) * cb + 4.0f) * cb : std::sqrt(cb);
    return cb + (2.0f * cs - 1.0f) * (d - cb);
}

float separable(CompositeMode mode, float cb, float cs) {
    switch (mode) {
        case CompositeMode::Screen: return screen(cb, cs);
        case CompositeMode::Overlay: return hard_light(cs, cb);  // HardLight with roles swapped
        case CompositeMode::Darken: return std::min(cb, cs);
        case CompositeMode::Lighten: return std::max(cb, cs);
        case CompositeMode::ColorDodge: return color_dodge(cb, cs);
        case CompositeMode::ColorBurn: return color_burn(cb, cs);
        case CompositeMode::HardLight: return hard_light(cb, cs);
        case CompositeMode::SoftLight: return soft_light(cb, cs);
        case CompositeMode::Difference: return std::fabs(cb - cs);
        case CompositeMode::Exclusion: return cb + cs - 2.0f * cb * cs;
        default: return multiply(cb, cs);
    }
}

// --- Non-separable helpers (§5.8) ---------------------------------------------------------------
// Lum(C) = 0.3·R + 0.59·G + 0.11·B
float lum(Rgb c) { return 0.3f * c.r + 0.59f * c.g + 0.11f * c.b; }
// ClipColor: pulls a colour whose channels left [0, 1] back toward its luminosity L.
Rgb clip_color(Rgb c) {
    const float l = lum(c);
    const float n = std::min({c.r, c.g, c.b});
    const float x = std::max({c.r, c.g, c.b});
    auto toward = [&](float k, float num, float den) { return l + (k - l) * num / den; };
    if (n < 0.0f && l - n > 0.0f)
        c = {toward(c.r, l, l - n), toward(c.g, l, l - n), toward(c.b, l, l - n)};
    if (x > 1.0f && x - l > 0.0f)
        c = {toward(c.r, 1.0f - l, x - l), toward(c.g, 1.0f - l, x - l),
             toward(c.b, 1.0f - l, x - l)};
    return c;
}
// SetLum(C, l): C shifted by l − Lum(C), then clipped.
Rgb set_lum(Rgb c, float l) {
    const float d = l - lum(c);
    return clip_color({c.r + d, c.g + d, c.b + d});
}
// Sat(C) = max − min.
float sat(Rgb c) { return std::max({c.r, c.g, c.b}) - std::min({c.r, c.g, c.b}); }
// SetSat(C, s): the largest channel becomes s, the smallest 0, the middle one scaled between
// them ((mid − min)·s / (max − min)); a grey (max = min) becomes black.
Rgb set_sat(Rgb c, float s) {
    float* ch[3] = {&c.r, &c.g, &c.b};
    std::sort(ch, ch + 3, [](const float* p, const float* q) { return *p < *q; });
    float& mn = *ch[0];
    float& mid = *ch[1];
    float& mx = *ch[2];
    if (mx > mn) {
        mid = (mid - mn) * s / (mx - mn);
        mx = s;
    } else {
        mid = 0.0f;
        mx = 0.0f;
    }
    mn = 0.0f;
    return c;
}

Rgb non_separable(CompositeMode mode, Rgb cb, Rgb cs) {
    switch (mode) {
        case CompositeMode::Hue: return set_lum(set_sat(cs, sat(cb)), lum(cb));
        case CompositeMode::Saturation: return set_lum(set_sat(cb, sat(cs)), lum(cb));
        case CompositeMode::Color: return set_lum(cs, lum(cb));
        default: return set_lum(cb, lum(cs));  // Luminosity
    }
}

// Fa, Fb of the Porter-Duff modes (§9.1.x).
void porter_duff(CompositeMode mode, float as, float ab, float& fa, float& fb) {
    switch (mode) {
        case CompositeMode::Clear: fa = 0; fb = 0; return;
        case CompositeMode::Src: fa = 1; fb = 0; return;
        case CompositeMode::Dest: fa = 0; fb = 1; return;
        case CompositeMode::SrcOver: fa = 1; fb = 1 - as; return;
        case CompositeMode::DestOver: fa = 1 - ab; fb = 1; return;
        case CompositeMode::SrcIn: fa = ab; fb = 0; return;
        case CompositeMode::DestIn: fa = 0; fb = as; return;
        case CompositeMode::SrcOut: fa = 1 - ab; fb = 0; return;
        case CompositeMode::DestOut: fa = 0; fb = 1 - as; return;
        case CompositeMode::SrcAtop: fa = ab; fb = 1 - as; return;
        case CompositeMode::DestAtop: fa = 1 - ab; fb = as; return;
        case CompositeMode::Xor: fa = 1 - ab; fb = 1 - as; return;
        default: fa = 1; fb = 1; return;  // Plus (clamped by the caller)
    }
}

Rgb straight(const Pixel& p) {
    if (p.a <= 0.0f) return {0, 0, 0};
    return {std::min(p.r / p.a, 1.0f), std::min(p.g / p.a, 1.0f), std::min(p.b / p.a, 1.0f)};
}

}  // namespace

Pixel composite(CompositeMode mode, const Pixel& s, const Pixel& b) {
    Pixel o;
    if (mode <= CompositeMode::Plus) {
        float fa = 0, fb = 0;
        porter_duff(mode, s.a, b.a, fa, fb);
        o = {s.r * fa + b.r * fb, s.g * fa + b.g * fb, s.b * fa + b.b * fb, s.a * fa + b.a * fb};
        if (mode == CompositeMode::Plus) {
            o.a = std::min(o.a, 1.0f);
            o.r = std::min(o.r, o.a);
            o.g = std::min(o.g, o.a);
            o.b = std::min(o.b, o.a);
        }
        return o;
    }
    const Rgb cs = straight(s), cb = straight(b);
    Rgb blended;
    if (mode >= CompositeMode::Hue) {
        blended = non_separable(mode, cb, cs);
    } else {
        blended = {separable(mode, cb.r, cs.r), separable(mode, cb.g, cs.g),
                   separable(mode, cb.b, cs.b)};
    }
    const float ks = 1.0f - b.a, kb = 1.0f - s.a, both = s.a * b.a;
    o.a = s.a + b.a * kb;
    o.r = std::clamp(s.r * ks + b.r * kb + both * blended.r, 0.0f, o.a);
    o.g = std::clamp(s.g * ks + b.g * kb + both * blended.g, 0.0f, o.a);
    o.b = std::clamp(s.b * ks + b.b * kb + both * blended.b, 0.0f, o.a);
    return o;
}

}  // namespace paint_detail
}  // namespace bezel
