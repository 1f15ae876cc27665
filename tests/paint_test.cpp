// The paint module: every composite mode against the W3C formulas, gradients at known points for
// each extend mode, glyph clips equal to the rasterizer's coverage, exact transforms, the graph's
// walls (cycles, depth, out-of-range indices, exponential DAGs), colour bitmap scaling in linear
// light, blend_rgba agreeing with blend_mask, and no allocation once a Painter is warm.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <new>
#include <string>
#include <vector>

#include "bezel/paint.hpp"
#include "support/shapes.hpp"

#include "support/allocation_counter.hpp"

using bezel::test::g_allocations;

namespace bezel {
namespace {

// --- Helpers --------------------------------------------------------------------------------------
struct Target {
    int w, h;
    std::vector<std::uint8_t> px;
    Target(int w_, int h_, std::uint8_t fill = 0)
        : w(w_), h(h_), px(static_cast<std::size_t>(w_ * h_ * 4), fill) {}
    RgbaView view() { return {px.data(), w, h, static_cast<std::ptrdiff_t>(w) * 4}; }
    std::array<int, 4> at(int x, int y) const {
        const std::uint8_t* p = &px[static_cast<std::size_t>((y * w + x) * 4)];
        return {p[0], p[1], p[2], p[3]};
    }
};

PaintColor color(float r, float g, float b, float a = 1) { return {{r, g, b, a}, false, 1}; }

// Glyph space y up, `h` px tall target: glyph (x, y) lands at pixel (x, h − y).
Affine flip(int h) { return {1, 0, 0, -1, 0, static_cast<double>(h)}; }

// Paints `g` into a new target of w × h; the paint must succeed.
Target paint(const ColorGlyph& g, int w, int h, const Affine& transform,
             Rgba8 foreground = {0, 0, 0, 255}) {
    Target t(w, h, 77);
    Painter painter;
    PaintOptions o;
    o.transform = transform;
    o.foreground = foreground;
    Status s = painter.paint(g, o, t.view());
    EXPECT_TRUE(s.ok()) << (s.ok() ? "" : s.error().message);
    return t;
}

int byte(double v) { return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); }

// Premultiplied double RGBA, as the reference computes it.
struct P {
    double r, g, b, a;
};
P premul(const ColorF& c) { return {c.r * c.a, c.g * c.a, c.b * c.a, c.a}; }

void expect_pixel(const Target& t, int x, int y, const P& want, int tolerance,
                  const std::string& what) {
    const auto got = t.at(x, y);
    const int a = byte(want.a);
    const int w[4] = {std::min(byte(want.r), a), std::min(byte(want.g), a),
                      std::min(byte(want.b), a), a};
    for (int k = 0; k < 4; ++k)
        EXPECT_NEAR(got[static_cast<std::size_t>(k)], w[k], tolerance)
            << what << " at (" << x << ", " << y << ") channel " << k;
}

// --- Composite modes: an independent scalar reference of W3C Compositing Level 1 ---------------
struct C3 {
    double r, g, b;
};
double lum(C3 c) { return 0.3 * c.r + 0.59 * c.g + 0.11 * c.b; }
C3 clip_color(C3 c) {
    double l = lum(c), n = std::min({c.r, c.g, c.b}), x = std::max({c.r, c.g, c.b});
    if (n < 0) c = {l + (c.r - l) * l / (l - n), l + (c.g - l) * l / (l - n), l + (c.b - l) * l / (l - n)};
    if (x > 1)
        c = {l + (c.r - l) * (1 - l) / (x - l), l + (c.g - l) * (1 - l) / (x - l),
             l + (c.b - l) * (1 - l) / (x - l)};
    return c;
}
C3 set_lum(C3 c, double l) {
    double d = l - lum(c);
    return clip_color({c.r + d, c.g + d, c.b + d});
}
double sat(C3 c) { return std::max({c.r, c.g, c.b}) - std::min({c.r, c.g, c.b}); }
C3 set_sat(C3 c, double s) {
    // Written per the spec's case analysis on which channel is max / mid / min.
    double v[3] = {c.r, c.g, c.b};
    int imax = 0, imin = 0;
    for (int i = 1; i < 3; ++i) {
        if (v[i] > v[imax]) imax = i;
        if (v[i] < v[imin]) imin = i;
    }
    if (imax == imin) return {0, 0, 0};
    int imid = 3 - imax - imin;
    double out[3];
    out[imid] = (v[imid] - v[imin]) * s / (v[imax] - v[imin]);
    out[imax] = s;
    out[imin] = 0;
    return {out[0], out[1], out[2]};
}
double blend(CompositeMode m, double cb, double cs) {
    switch (m) {
        case CompositeMode::Multiply: return cb * cs;
        case CompositeMode::Screen: return cb + cs - cb * cs;
        case CompositeMode::Overlay: return cb <= 0.5 ? cs * 2 * cb : cs + (2 * cb - 1) - cs * (2 * cb - 1);
        case CompositeMode::Darken: return std::min(cb, cs);
        case CompositeMode::Lighten: return std::max(cb, cs);
        case CompositeMode::ColorDodge: return cb == 0 ? 0 : cs == 1 ? 1 : std::min(1.0, cb / (1 - cs));
        case CompositeMode::ColorBurn: return cb == 1 ? 1 : cs == 0 ? 0 : 1 - std::min(1.0, (1 - cb) / cs);
        case CompositeMode::HardLight: return cs <= 0.5 ? cb * 2 * cs : cb + (2 * cs - 1) - cb * (2 * cs - 1);
        case CompositeMode::SoftLight: {
            if (cs <= 0.5) return cb - (1 - 2 * cs) * cb * (1 - cb);
            double d = cb <= 0.25 ? ((16 * cb - 12) * cb + 4) * cb : std::sqrt(cb);
            return cb + (2 * cs - 1) * (d - cb);
        }
        case CompositeMode::Difference: return std::fabs(cb - cs);
        case CompositeMode::Exclusion: return cb + cs - 2 * cb * cs;
        default: return 0;
    }
}
P reference(CompositeMode m, P s, P b) {
    const int mode = static_cast<int>(m);
    if (mode <= static_cast<int>(CompositeMode::Plus)) {
        // Fa, Fb: Clear 0 0, Src 1 0, Dest 0 1, SrcOver 1 1-as, DestOver 1-ab 1, SrcIn ab 0,
        // DestIn 0 as, SrcOut 1-ab 0, DestOut 0 1-as, SrcAtop ab 1-as, DestAtop 1-ab as,
        // Xor 1-ab 1-as, Plus 1 1.
        const double as = s.a, ab = b.a;
        const double fa[] = {0, 1, 0, 1, 1 - ab, ab, 0, 1 - ab, 0, ab, 1 - ab, 1 - ab, 1};
        const double fb[] = {0, 0, 1, 1 - as, 1, 0, as, 0, 1 - as, 1 - as, as, 1 - as, 1};
        P o{s.r * fa[mode] + b.r * fb[mode], s.g * fa[mode] + b.g * fb[mode],
            s.b * fa[mode] + b.b * fb[mode], s.a * fa[mode] + b.a * fb[mode]};
        if (m == CompositeMode::Plus) o = {std::min(o.r, 1.0), std::min(o.g, 1.0), std::min(o.b, 1.0), std::min(o.a, 1.0)};
        return o;
    }
    const C3 cs{s.r / s.a, s.g / s.a, s.b / s.a}, cb{b.r / b.a, b.g / b.a, b.b / b.a};
    C3 bl;
    switch (m) {
        case CompositeMode::Hue: bl = set_lum(set_sat(cs, sat(cb)), lum(cb)); break;
        case CompositeMode::Saturation: bl = set_lum(set_sat(cb, sat(cs)), lum(cb)); break;
        case CompositeMode::Color: bl = set_lum(cs, lum(cb)); break;
        case CompositeMode::Luminosity: bl = set_lum(cb, lum(cs)); break;
        default: bl = {blend(m, cb.r, cs.r), blend(m, cb.g, cs.g), blend(m, cb.b, cs.b)};
    }
    auto ch = [&](double sc, double bc, double bx) {
        return sc * (1 - b.a) + bc * (1 - s.a) + s.a * b.a * bx;
    };
    return {ch(s.r, b.r, bl.r), ch(s.g, b.g, bl.g), ch(s.b, b.b, bl.b), s.a + b.a * (1 - s.a)};
}

ColorGlyph composite_glyph(CompositeMode mode, ColorF source, ColorF backdrop) {
    ColorGlyph g;
    g.nodes = {PaintComposite{1, 2, mode}, PaintSolid{{source, false, 1}},
               PaintSolid{{backdrop, false, 1}}};
    g.root = 0;
    return g;
}

TEST(Paint, EveryCompositeModeFollowsTheW3CFormulas) {
    // Pairs (source, backdrop) chosen to reach each branch: partial alphas, a light and a dark
    // backdrop, a source of 1 and of 0 (ColorDodge / ColorBurn ends), greys (SetSat's max = min).
    const std::pair<ColorF, ColorF> pairs[] = {
        {{0.8f, 0.3f, 0.1f, 0.6f}, {0.2f, 0.5f, 0.9f, 0.7f}},
        {{0.1f, 0.9f, 0.4f, 1.0f}, {0.7f, 0.2f, 0.6f, 0.5f}},
        {{1.0f, 0.0f, 0.6f, 0.4f}, {0.0f, 0.25f, 1.0f, 1.0f}},
        {{0.5f, 0.5f, 0.5f, 0.8f}, {0.9f, 0.1f, 0.3f, 0.9f}},
        {{0.2f, 0.6f, 1.0f, 1.0f}, {0.4f, 0.4f, 0.4f, 1.0f}},
    };
    for (int m = 0; m < kCompositeModeCount; ++m) {
        const auto mode = static_cast<CompositeMode>(m);
        for (const auto& [s, b] : pairs) {
            // The stated colours are what the painter holds: bytes are floats of those values.
            const Target t = paint(composite_glyph(mode, s, b), 2, 2, Affine::identity());
            expect_pixel(t, 1, 1, reference(mode, premul(s), premul(b)), 1,
                         composite_mode_name(mode));
        }
    }
}

TEST(Paint, CompositeModeNamesAreTheSpecs) {
    EXPECT_STREQ(composite_mode_name(CompositeMode::Clear), "clear");
    EXPECT_STREQ(composite_mode_name(CompositeMode::SrcOver), "src_over");
    EXPECT_STREQ(composite_mode_name(CompositeMode::ColorDodge), "color_dodge");
    EXPECT_STREQ(composite_mode_name(CompositeMode::Luminosity), "luminosity");
    EXPECT_EQ(static_cast<int>(CompositeMode::Luminosity) + 1, kCompositeModeCount);
}

// --- Gradients -------------------------------------------------------------------------------------
const ColorF kRed{1, 0, 0, 1}, kBlue{0, 0, 1, 1}, kGreen{0, 1, 0, 1};

ColorLine line(Extend e, std::vector<std::pair<float, ColorF>> stops) {
    ColorLine l;
    l.extend = e;
    for (auto& [o, c] : stops) l.stops.push_back({o, {c, false, 1}});
    return l;
}

// The colour line at t by the header's definitions, written plainly: fold t by the extend mode,
// then interpolate straight colours between the surrounding stops.
P line_at(const ColorLine& l, double t) {
    const double first = l.stops.front().offset, last = l.stops.back().offset, span = last - first;
    if (l.extend == Extend::Repeat && span > 0) t = first + std::fmod(std::fmod(t - first, span) + span, span);
    if (l.extend == Extend::Reflect && span > 0) {
        double u = std::fmod(std::fmod(t - first, 2 * span) + 2 * span, 2 * span);
        t = first + (u > span ? 2 * span - u : u);
    }
    if (t < first) return premul(l.stops.front().color.color);
    if (t >= last) return premul(l.stops.back().color.color);
    for (std::size_t i = 1; i < l.stops.size(); ++i) {
        const auto& lo = l.stops[i - 1];
        const auto& hi = l.stops[i];
        if (t >= lo.offset && t < hi.offset) {
            double f = (t - lo.offset) / (hi.offset - lo.offset);
            const ColorF a = lo.color.color, b = hi.color.color;
            return premul({float(a.r + (b.r - a.r) * f), float(a.g + (b.g - a.g) * f),
                           float(a.b + (b.b - a.b) * f), float(a.a + (b.a - a.a) * f)});
        }
    }
    return premul(l.stops.back().color.color);
}

ColorGlyph single(PaintNode node) {
    ColorGlyph g;
    g.nodes = {std::move(node)};
    return g;
}

// Glyph-space centre of pixel (x, y) under flip(h).
Point centre(int x, int y, int h) { return {x + 0.5, h - (y + 0.5)}; }

TEST(Paint, LinearGradientFollowsEachExtendMode) {
    const int w = 60, h = 3;
    for (Extend e : {Extend::Pad, Extend::Repeat, Extend::Reflect}) {
        // Stops spanning [0, 1], and a narrower span [0.25, 0.75] that repeats with period ½.
        for (const ColorLine& l : {line(e, {{0.0f, kRed}, {0.5f, kGreen}, {1.0f, kBlue}}),
                                   line(e, {{0.25f, kRed}, {0.75f, kBlue}})}) {
            // Axis from x = 20 to x = 40; p2 straight above p0, so t = (x − 20) / 20.
            const Target t = paint(single(PaintLinearGradient{l, {20, 0}, {40, 0}, {20, 10}}), w, h, flip(h));
            for (int x = 0; x < w; ++x) {
                const double tt = (centre(x, 1, h).x - 20) / 20;
                expect_pixel(t, x, 1, line_at(l, tt), 1, "linear t=" + std::to_string(tt));
            }
        }
    }
    // Pixel 11's centre is t = −0.425: Reflect folds it onto 0.425, Repeat onto 0.575.
    const Target rf = paint(single(PaintLinearGradient{line(Extend::Reflect, {{0.0f, kRed}, {1.0f, kBlue}}), {20, 0}, {40, 0}, {20, 10}}), w, h, flip(h));
    const Target rp = paint(single(PaintLinearGradient{line(Extend::Repeat, {{0.0f, kRed}, {1.0f, kBlue}}), {20, 0}, {40, 0}, {20, 10}}), w, h, flip(h));
    EXPECT_NEAR(rf.at(11, 1)[2], byte(0.425), 1);
    EXPECT_NEAR(rp.at(11, 1)[2], byte(0.575), 1);
}

TEST(Paint, GradientsInterpolateStraightColourAsSkiaDoes) {
    // Opaque red to transparent blue: halfway, straight interpolation gives colour (½, 0, ½) at
    // alpha ½, premultiplied (¼, 0, ¼, ½); premultiplied interpolation would give (½, 0, 0, ½).
    const ColorLine l = line(Extend::Pad, {{0.0f, kRed}, {1.0f, ColorF{0, 0, 1, 0}}});
    const Target t = paint(single(PaintLinearGradient{l, {0, 0}, {2, 0}, {0, 1}}), 2, 1, flip(1));
    // Pixel 0's centre is t = ¼: colour (¾, 0, ¼) at alpha ¾.
    expect_pixel(t, 0, 0, {0.75 * 0.75, 0, 0.25 * 0.75, 0.75}, 1, "t = 1/4");
    expect_pixel(t, 1, 0, {0.25 * 0.25, 0, 0.75 * 0.25, 0.25}, 1, "t = 3/4");
}

TEST(Paint, LinearGradientRotatesP1OntoTheNormalOfP2) {
    // p1 = (10, 10) with p2 straight above p0: p1' = (10, 0), so t = x / 10 on every row.
    const int w = 24, h = 8;
    const ColorLine l = line(Extend::Pad, {{0.0f, kRed}, {1.0f, kBlue}});
    const Target t = paint(single(PaintLinearGradient{l, {0, 0}, {10, 10}, {0, 10}}), w, h, flip(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) expect_pixel(t, x, y, line_at(l, (x + 0.5) / 10), 1, "rotated");
    // Degenerate: p2 on the line p0 p1 paints nothing.
    const Target none = paint(single(PaintLinearGradient{l, {0, 0}, {10, 0}, {20, 0}}), 4, 4, flip(4));
    expect_pixel(none, 2, 2, {0, 0, 0, 0}, 0, "degenerate");
}

TEST(Paint, HardStopsAndStopsOutsideTheUnitSpan) {
    const int w = 40, h = 2;
    // Equal offsets at 0.5: red strictly below, blue from it on.
    const ColorLine hard = line(Extend::Pad, {{0.0f, kRed}, {0.5f, kRed}, {0.5f, kBlue}, {1.0f, kBlue}});
    const Target t = paint(single(PaintLinearGradient{hard, {0, 0}, {40, 0}, {0, 10}}), w, h, flip(h));
    expect_pixel(t, 19, 0, premul(kRed), 0, "below the hard stop");
    expect_pixel(t, 20, 0, premul(kBlue), 0, "above the hard stop");
    // Every stop at 0.5: Pad splits there; Repeat and Reflect have no span and paint nothing.
    for (Extend e : {Extend::Pad, Extend::Repeat, Extend::Reflect}) {
        const ColorLine one = line(e, {{0.5f, kRed}, {0.5f, kBlue}});
        const Target z = paint(single(PaintLinearGradient{one, {0, 0}, {40, 0}, {0, 10}}), w, h, flip(h));
        expect_pixel(z, 5, 0, e == Extend::Pad ? premul(kRed) : P{0, 0, 0, 0}, 0, "coincident stops");
        expect_pixel(z, 30, 0, e == Extend::Pad ? premul(kBlue) : P{0, 0, 0, 0}, 0, "coincident stops");
    }
    // Stops at −1 and 2: t = 0.5 is halfway.
    const ColorLine wide = line(Extend::Pad, {{-1.0f, kRed}, {2.0f, kBlue}});
    const Target u = paint(single(PaintLinearGradient{wide, {0, 0}, {40, 0}, {0, 10}}), w, h, flip(h));
    expect_pixel(u, 20, 0, line_at(wide, 20.5 / 40), 1, "stops outside [0, 1]");
    EXPECT_NEAR(u.at(20, 0)[0], 127, 2);
}

// The largest t with |p − c(t)| = r(t) ≥ 0, found by scanning t ∈ [−12, 12] (wider than any t
// of the cases below) for sign changes of
// f(t) = |p − c(t)| − r(t) and bisecting: independent of the painter's closed form.
// `near_tangent`: |f| came within 0.05 somewhere, so a scan this coarse may have stepped over a
// pair of close roots (the edge of a cone): the caller does not judge such points.
bool radial_t(const PaintRadialGradient& g, Point p, double& out, bool& near_tangent) {
    auto f = [&](double t) {
        Point c = g.c0 + (g.c1 - g.c0) * t;
        return distance(p, c) - (g.r0 + t * (g.r1 - g.r0));
    };
    auto r = [&](double t) { return g.r0 + t * (g.r1 - g.r0); };
    bool found = false;
    const double step = 1e-2;
    near_tangent = false;
    for (double t = 12; t > -12; t -= step) {
        double a = t - step, b = t;
        if (r(a) >= 0 && std::fabs(f(a)) < 0.05) near_tangent = true;
        if ((f(a) <= 0) != (f(b) <= 0)) {
            for (int i = 0; i < 60; ++i) {
                double m = (a + b) / 2;
                ((f(a) <= 0) == (f(m) <= 0) ? a : b) = m;
            }
            if (r(b) >= -1e-9) {
                out = b;
                found = true;
                break;
            }
        }
    }
    return found;
}

TEST(Paint, RadialGradientConcentricFocalAndOutsideTheCone) {
    const int w = 40, h = 40;
    struct Case {
        const char* name;
        PaintRadialGradient g;
    };
    for (Extend e : {Extend::Pad, Extend::Repeat, Extend::Reflect}) {
        const ColorLine l = line(e, {{0.0f, kRed}, {0.5f, kGreen}, {1.0f, kBlue}});
        const Case cases[] = {
            {"concentric", {l, {20, 20}, {20, 20}, 0, 8}},
            {"focal inside", {l, {20, 20}, {24, 20}, 0, 10}},
            {"r0 = r1", {l, {12, 20}, {26, 20}, 5, 5}},
            {"cone", {l, {10, 20}, {24, 22}, 2, 6}},
            {"large r0", {l, {20, 20}, {22, 21}, 12, 3}},
        };
        for (const Case& c : cases) {
            const Target t = paint(single(c.g), w, h, flip(h));
            int painted = 0, empty = 0;
            for (int y = 1; y < h; y += 3)
                for (int x = 0; x < w; x += 3) {
                    double tt;
                    bool near_tangent;
                    const Point p = centre(x, y, h);
                    if (radial_t(c.g, p, tt, near_tangent)) {
                        ++painted;
                        // Near a repeat seam or hard edge a tiny t error flips the colour: skip
                        // points within 1e-3 of a span boundary.
                        if (e != Extend::Pad && std::fabs(tt - std::round(tt)) < 1e-3) continue;
                        expect_pixel(t, x, y, line_at(l, tt), 2, std::string(c.name) + " t=" + std::to_string(tt));
                    } else if (!near_tangent) {
                        ++empty;
                        expect_pixel(t, x, y, {0, 0, 0, 0}, 0, std::string(c.name) + " (no t)");
                    }
                }
            EXPECT_GT(painted, 0) << c.name;
            if (std::string(c.name) == "cone") {
                EXPECT_GT(empty, 0) << "a cone leaves points unpainted";
            }
        }
    }
}

TEST(Paint, SweepGradientRunsCounterClockwiseInGlyphSpace) {
    const int w = 40, h = 40;
    const ColorLine l = line(Extend::Pad, {{0.0f, kRed}, {1.0f, kBlue}});
    struct Case {
        double start, end;
    };
    for (Case c : {Case{0, 90}, Case{270, 90}, Case{45, 315}}) {
        for (Extend e : {Extend::Pad, Extend::Repeat, Extend::Reflect}) {
            ColorLine le = l;
            le.extend = e;
            const Target t = paint(single(PaintSweepGradient{le, {20, 20}, c.start, c.end}), w, h, flip(h));
            for (int y = 0; y < h; y += 3)
                for (int x = 0; x < w; x += 3) {
                    const Point p = centre(x, y, h);
                    double angle = std::atan2(p.y - 20, p.x - 20) * 180 / M_PI;
                    if (angle < 0) angle += 360;
                    const double tt = (angle - c.start) / (c.end - c.start);
                    if (std::fabs(tt - std::round(tt)) < 1e-3) continue;  // a seam
                    expect_pixel(t, x, y, line_at(le, tt), 1, "sweep");
                }
        }
    }
    // y up: a point nearly straight above the centre is near 90°, the end of a 0 → 90 sweep
    // (blue); one to the right, near 0°, is red. (y down would swap them.)
    const Target t = paint(single(PaintSweepGradient{l, {20, 20}, 0, 90}), w, h, flip(h));
    EXPECT_GT(t.at(20, 2)[2], 240);
    EXPECT_LT(t.at(20, 2)[0], 15);
    EXPECT_GT(t.at(38, 19)[0], 240);
    EXPECT_LT(t.at(38, 19)[2], 15);
}

// Every stop at one offset (test_glyphs-glyf_colr_1's sweep_coincident_stops_*): repeating or
// reflecting a span of zero length has no period, so nothing is painted (Chromium draws nothing
// there too); Pad still paints the first stop's colour below the offset and the last one's above.
TEST(Paint, ZeroSpanColourLineThatRepeatsOrReflectsPaintsNothing) {
    const int w = 20, h = 20;
    for (Extend e : {Extend::Pad, Extend::Repeat, Extend::Reflect}) {
        const ColorLine l = line(e, {{0.5f, kRed}, {0.5f, kBlue}});
        const std::vector<PaintNode> gradients = {
            PaintLinearGradient{l, {0, 0}, {20, 0}, {0, 10}},
            PaintRadialGradient{l, {10, 10}, {10, 10}, 0, 12},
            PaintSweepGradient{l, {10, 10}, 45, 90},
        };
        for (const PaintNode& node : gradients) {
            const Target t = paint(single(node), w, h, flip(h));
            int inked = 0;
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) inked += t.at(x, y)[3] != 0;
            if (e == Extend::Pad) {
                EXPECT_EQ(inked, w * h) << "pad, node kind " << node.index();
            } else {
                EXPECT_EQ(inked, 0) << "repeat/reflect, node kind " << node.index();
            }
        }
    }
}

// --- Clips and transforms ---------------------------------------------------------------------------
TEST(Paint, GlyphClipIsTheRasterizersCoverageTimesTheColour) {
    const int w = 24, h = 24;
    ColorGlyph g;
    Path circle;
    test::add_circle(circle, {11.3, 12.6}, 7.7);
    g.outlines = {circle};
    const ColorF c{0.9f, 0.4f, 0.2f, 0.8f};
    g.nodes = {PaintGlyph{0, 1}, PaintSolid{{c, false, 1}}};
    const Target t = paint(g, w, h, flip(h));
    std::vector<float> cov(static_cast<std::size_t>(w * h));
    Rasterizer r;
    ASSERT_TRUE(r.fill_path(circle, flip(h), FloatMaskView{cov.data(), w, h, w}));
    int partial = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double k = cov[static_cast<std::size_t>(y * w + x)];
            if (k > 0 && k < 1) ++partial;
            const P p = premul(c);
            expect_pixel(t, x, y, {p.r * k, p.g * k, p.b * k, p.a * k}, 1, "glyph clip");
        }
    EXPECT_GT(partial, 20);
}

// Regression: test_glyphs-glyf_colr_1.ttf's solid_colorline_alpha (U+F1000) showed a light
// cross through its circles at 96 px. circle_r350 is four pie slices, two wound each way, meeting
// on lines through the centre; where those lines cross a pixel, plain signed-area accumulation
// gave |a − (1 − a)| instead of 1.
TEST(Paint, AbuttingContoursOfOppositeWindingLeaveNoSeam) {
    Path pie;
    const Point c{33.6, 38.4};
    const Point corner[4] = {{10, 10}, {60, 10}, {60, 70}, {10, 70}};
    for (int i = 0; i < 4; ++i) {
        // Slices 0 and 2 run c → corner i → corner i+1, slices 1 and 3 the other way round.
        const Point a = corner[i], b = corner[(i + 1) % 4];
        pie.move_to(c);
        pie.line_to(i % 2 ? b : a);
        pie.line_to(i % 2 ? a : b);
        pie.close();
    }
    ColorGlyph g;
    g.outlines = {pie};
    g.nodes = {PaintGlyph{0, 1}, PaintSolid{color(0, 0, 1)}};
    const Target t = paint(g, 80, 80, Affine::identity());
    for (int x = 12; x < 58; ++x) expect_pixel(t, x, 38, {0, 0, 1, 1}, 0, "row through the centre");
    for (int y = 12; y < 68; ++y) expect_pixel(t, 33, y, {0, 0, 1, 1}, 0, "column through the centre");
}

// Two rectangles sharing the edge x = 10.5 (mid-pixel), wound in opposite directions: the
// nonzero fill is their union, so the pixel the edge crosses is fully covered. Plain signed-area
// accumulation would give it |0.5 − 0.5| = 0 there, a hairline seam (test_glyphs-glyf_colr_1's
// circles are four quarter-disc contours, two of each winding, and showed such seams).
TEST(Paint, RectanglesSharingAnEdgeWithOppositeWindingLeaveNoSeam) {
    const int w = 24, h = 12;
    Path p;
    p.move_to({2, 2});   // clockwise on the page (y up: counter-clockwise)
    p.line_to({10.5, 2});
    p.line_to({10.5, 10});
    p.line_to({2, 10});
    p.close();
    p.move_to({10.5, 2});   // the other way round
    p.line_to({10.5, 10});
    p.line_to({20, 10});
    p.line_to({20, 2});
    p.close();
    ColorGlyph g;
    g.outlines = {p};
    g.nodes = {PaintGlyph{0, 1}, PaintSolid{color(0, 0, 1)}};
    const Target t = paint(g, w, h, flip(h));
    for (int x = 2; x < 20; ++x) EXPECT_EQ(t.at(x, 6)[3], 255) << "pixel " << x << " of row 6";
}

TEST(Paint, NestedClipsMultiplyAndARotatedClipBoxIsAPolygon) {
    const int w = 32, h = 32;
    ColorGlyph g;
    Path a, b;
    test::add_rect(a, 4, 4, 20.5, 20.5);
    test::add_rect(b, 10.25, 10.25, 28, 28);
    g.outlines = {a, b};
    g.nodes = {PaintGlyph{0, 1}, PaintGlyph{1, 2}, PaintSolid{color(0, 0, 1)}};
    const Target t = paint(g, w, h, Affine::identity());
    expect_pixel(t, 15, 15, {0, 0, 1, 1}, 0, "inside both");
    expect_pixel(t, 6, 6, {0, 0, 0, 0}, 0, "inside one");
    // Pixel (10, 20): 0.75 of the second square's width, 0.5 of the first's height.
    expect_pixel(t, 10, 20, {0, 0, 0.375, 0.375}, 1, "both partial edges");

    // A clip box rotated 45° about its centre (16, 16): a diamond. Its corners lie at distance
    // 8√2 along the axes; pixel centres near the axis ends are outside the unrotated box's
    // square but inside the diamond, and the box's corners are outside it.
    ColorGlyph d;
    const double s = std::sqrt(0.5);
    const Affine rot = Affine::translate({16, 16}) * Affine{s, s, -s, s, 0, 0} * Affine::translate({-16, -16});
    d.nodes = {PaintTransform{rot, 1}, PaintColrGlyph{2, Rect{8, 8, 24, 24}}, PaintSolid{color(1, 0, 0)}};
    const Target dt = paint(d, w, h, Affine::identity());
    expect_pixel(dt, 15, 7, {1, 0, 0, 1}, 0, "inside the diamond, above the unrotated box");
    expect_pixel(dt, 9, 9, {0, 0, 0, 0}, 0, "box corner outside the diamond");
    // And the root clip box clips everything.
    ColorGlyph rc = single(PaintSolid{color(0, 1, 0)});
    rc.clip = Rect{2, 2, 6, 6};
    const Target rt = paint(rc, 8, 8, Affine::identity());
    expect_pixel(rt, 3, 3, {0, 1, 0, 1}, 0, "inside the root clip");
    expect_pixel(rt, 7, 7, {0, 0, 0, 0}, 0, "outside the root clip");
}

TEST(Paint, TranslateMovesASquareByExactlyItsOffset) {
    const int w = 20, h = 20;
    ColorGlyph plain, moved;
    Path sq;
    test::add_rect(sq, 2.25, 3.5, 7.75, 8);
    plain.outlines = moved.outlines = {sq};
    plain.nodes = {PaintGlyph{0, 1}, PaintSolid{color(0.2f, 0.7f, 0.3f)}};
    moved.nodes = {PaintTransform{Affine::translate({5, 7}), 1}, PaintGlyph{0, 2},
                   PaintSolid{color(0.2f, 0.7f, 0.3f)}};
    const Target a = paint(plain, w, h, Affine::identity());
    const Target b = paint(moved, w, h, Affine::identity());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const auto want = (x >= 5 && y >= 7) ? a.at(x - 5, y - 7) : std::array<int, 4>{0, 0, 0, 0};
            EXPECT_EQ(b.at(x, y), want) << x << "," << y;
        }
    // Scale 2 about the glyph origin doubles the square to [4.5, 15.5] × [7, 16].
    ColorGlyph scaled = plain;
    scaled.nodes = {PaintTransform{Affine::scale(2), 1}, PaintGlyph{0, 2}, PaintSolid{color(0, 0, 0)}};
    const Target s = paint(scaled, w, h, Affine::identity());
    EXPECT_EQ(s.at(5, 7)[3], 255);
    EXPECT_EQ(s.at(14, 15)[3], 255);
    EXPECT_EQ(s.at(15, 15)[3], 128);
    EXPECT_EQ(s.at(16, 16)[3], 0);
    EXPECT_EQ(s.at(4, 7)[3], 128);
}

TEST(Paint, ForegroundColourComesFromTheOptions) {
    PaintColor fg;
    fg.foreground = true;
    fg.alpha = 0.5f;
    const Target t = paint(single(PaintSolid{fg}), 2, 2, Affine::identity(), {255, 0, 0, 255});
    expect_pixel(t, 0, 0, {0.5, 0, 0, 0.5}, 1, "foreground at half alpha");
}

TEST(Paint, LayersCompositeSrcOverInOrder) {
    ColorGlyph g;
    g.nodes = {PaintLayers{{1, 2}}, PaintSolid{color(1, 0, 0)}, PaintSolid{color(0, 0, 1, 0.5f)}};
    const Target t = paint(g, 2, 2, Affine::identity());
    expect_pixel(t, 0, 0, {0.5, 0, 0.5, 1}, 1, "blue half over red");
}

// --- The graph's walls ---------------------------------------------------------------------------
TEST(Paint, ValidateRefusesCyclesDeepChainsBadIndicesAndExponentialDags) {
    ColorGlyph cycle;
    cycle.nodes = {PaintTransform{Affine::identity(), 1}, PaintLayers{{2, 0}}, PaintSolid{}};
    Status s = validate(cycle);
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message.find("loops at node 0"), std::string::npos) << s.error().message;

    ColorGlyph deep;
    for (PaintIndex i = 0; i < 10000; ++i) deep.nodes.push_back(PaintTransform{Affine::identity(), i + 1});
    deep.nodes.push_back(PaintSolid{});
    s = validate(deep);
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message.find("deeper than 64"), std::string::npos) << s.error().message;
    // 64 levels is allowed.
    ColorGlyph ok_chain;
    for (PaintIndex i = 0; i < 63; ++i) ok_chain.nodes.push_back(PaintTransform{Affine::identity(), i + 1});
    ok_chain.nodes.push_back(PaintSolid{});
    EXPECT_TRUE(validate(ok_chain).ok());

    ColorGlyph bad_root = single(PaintSolid{});
    bad_root.root = 1;
    EXPECT_FALSE(validate(bad_root).ok());
    ColorGlyph bad_child;
    bad_child.nodes = {PaintComposite{1, 7, CompositeMode::Xor}, PaintSolid{}};
    s = validate(bad_child);
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message.find("node 7"), std::string::npos) << s.error().message;
    ColorGlyph bad_outline;
    bad_outline.nodes = {PaintGlyph{3, 1}, PaintSolid{}};
    EXPECT_FALSE(validate(bad_outline).ok());
    ColorGlyph no_stops = single(PaintLinearGradient{ColorLine{}, {0, 0}, {1, 0}, {0, 1}});
    EXPECT_FALSE(validate(no_stops).ok());

    // 40 levels of a layer list naming the next level twice: 2^40 paths, refused after
    // kMaxPaintNodes visits (quickly), not walked.
    ColorGlyph dag;
    for (PaintIndex i = 0; i < 40; ++i) dag.nodes.push_back(PaintLayers{{i + 1, i + 1}});
    dag.nodes.push_back(PaintSolid{});
    const auto t0 = std::chrono::steady_clock::now();
    s = validate(dag);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message.find(std::to_string(kMaxPaintNodes)), std::string::npos) << s.error().message;
    EXPECT_LT(seconds, 5.0);
    EXPECT_TRUE(paint_bounds(dag).is_empty());

    // The painter refuses the same graphs and leaves the target untouched.
    Target t(2, 2, 9);
    Painter p;
    EXPECT_FALSE(p.paint(cycle, {}, t.view()).ok());
    EXPECT_EQ(t.at(1, 1), (std::array<int, 4>{9, 9, 9, 9}));
}

TEST(Paint, PainterRefusesBadTargetsAndTransforms) {
    const ColorGlyph g = single(PaintSolid{color(1, 1, 1)});
    Painter p;
    Target t(2, 2, 9);
    PaintOptions singular;
    singular.transform = Affine::scale(0);
    EXPECT_FALSE(p.paint(g, singular, t.view()).ok());
    EXPECT_EQ(t.at(0, 0), (std::array<int, 4>{9, 9, 9, 9}));
    EXPECT_FALSE(p.paint(g, {}, RgbaView{t.px.data(), kMaxBitmapDim + 1, 1, 4 * (kMaxBitmapDim + 1)}).ok());
    EXPECT_FALSE(p.paint(g, {}, RgbaView{nullptr, 2, 2, 8}).ok());
    EXPECT_TRUE(p.paint(g, {}, RgbaView{nullptr, 0, 0, 0}).ok());
}

TEST(Paint, BoundsAreTheClipBoxOrTheTransformedOutlines) {
    ColorGlyph g;
    Path sq;
    test::add_rect(sq, 0, 0, 10, 20);
    g.outlines = {sq};
    g.nodes = {PaintLayers{{1, 3}}, PaintGlyph{0, 2}, PaintSolid{},
               PaintTransform{Affine::translate({100, -5}), 1}};
    EXPECT_EQ(paint_bounds(g), (Rect{0, -5, 110, 20}));
    g.clip = Rect{1, 2, 3, 4};
    EXPECT_EQ(paint_bounds(g), (Rect{1, 2, 3, 4}));
    EXPECT_TRUE(paint_bounds(single(PaintSolid{})).is_empty());
}

// --- Colour bitmaps ---------------------------------------------------------------------------------
TEST(Paint, ScaleKeepsAFlatColourFlatAndTheMeanInLinearLight) {
    for (BitmapFilter f : {BitmapFilter::Box, BitmapFilter::Bilinear}) {
        for (auto [sw, sh, tw, th] : {std::array<int, 4>{17, 13, 5, 4}, {3, 3, 7, 7}, {136, 128, 32, 30}}) {
            Target src(sw, sh);
            for (int i = 0; i < sw * sh; ++i) {
                src.px[static_cast<std::size_t>(i * 4) + 0] = 120;
                src.px[static_cast<std::size_t>(i * 4) + 1] = 60;
                src.px[static_cast<std::size_t>(i * 4) + 2] = 30;
                src.px[static_cast<std::size_t>(i * 4) + 3] = 200;
            }
            Target dst(tw, th, 1);
            scale_rgba(src.view(), dst.view(), f);
            for (int y = 0; y < th; ++y)
                for (int x = 0; x < tw; ++x)
                    ASSERT_EQ(dst.at(x, y), (std::array<int, 4>{120, 60, 30, 200})) << x << "," << y;
        }
    }
    // A black and white checkerboard boxed down to one pixel is linear-light grey 0.5, which is
    // sRGB 188 (not the 128 of averaging encoded values).
    Target cb(8, 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            for (int k = 0; k < 4; ++k)
                cb.px[static_cast<std::size_t>((y * 8 + x) * 4 + k)] =
                    (k == 3 || (x + y) % 2 == 0) ? 255 : 0;
    Target one(1, 1);
    scale_rgba(cb.view(), one.view(), BitmapFilter::Box);
    EXPECT_EQ(one.at(0, 0), (std::array<int, 4>{188, 188, 188, 255}));
    // Half the pixels transparent: alpha halves, the colour stays white (premultiplied 128).
    Target half(2, 1);
    half.px = {255, 255, 255, 255, 0, 0, 0, 0};
    scale_rgba(half.view(), one.view(), BitmapFilter::Box);
    EXPECT_EQ(one.at(0, 0), (std::array<int, 4>{128, 128, 128, 128}));
    // Bilinear halfway between two pixels of a 2 × 1 image enlarged to 4 × 1: the inner two
    // target pixels sample at 0.25 and 0.75 of the way.
    Target bw(2, 1);
    bw.px = {0, 0, 0, 255, 255, 255, 255, 255};
    Target four(4, 1);
    scale_rgba(bw.view(), four.view(), BitmapFilter::Bilinear);
    EXPECT_EQ(four.at(0, 0)[0], 0);
    EXPECT_EQ(four.at(1, 0)[0], srgb_encode(0.25f));
    EXPECT_EQ(four.at(2, 0)[0], srgb_encode(0.75f));
    EXPECT_EQ(four.at(3, 0)[0], 255);
}

TEST(Paint, ToImageAndPremultiplyRoundTrip) {
    Target t(3, 1);
    t.px = {100, 50, 0, 200, 0, 0, 0, 0, 255, 255, 255, 255};
    const Image img = to_image(t.view());
    EXPECT_EQ(img.at(0, 0), (Rgba8{128, 64, 0, 200}));
    EXPECT_EQ(img.at(1, 0).a, 0);
    Target back(3, 1);
    premultiply(img, back.view());
    EXPECT_EQ(back.px, t.px);
}

TEST(Paint, BlendRgbaOfAnOpaqueColourGlyphEqualsBlendMask) {
    const Rgba8 colour{200, 100, 50, 255};
    const int w = 16, h = 16;
    Mask mask(w, h);
    Target glyph(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int m = (x * 16 + y * 7 * 16) % 256;
            mask.at(x, y) = static_cast<std::uint8_t>(m);
            std::uint8_t* p = &glyph.px[static_cast<std::size_t>((y * w + x) * 4)];
            p[0] = static_cast<std::uint8_t>((colour.r * m + 127) / 255);
            p[1] = static_cast<std::uint8_t>((colour.g * m + 127) / 255);
            p[2] = static_cast<std::uint8_t>((colour.b * m + 127) / 255);
            p[3] = static_cast<std::uint8_t>(m);
        }
    for (Rgba8 paper : {Rgba8{255, 255, 255, 255}, Rgba8{30, 90, 160, 255}, Rgba8{240, 230, 10, 100}}) {
        Image a(w + 4, h + 4, paper), b(w + 4, h + 4, paper);
        blend_mask(a, mask.view(), 2, 3, colour);
        blend_rgba(b, glyph.view(), 2, 3);
        // Where the premultiplied bytes still carry the colour (round(c·255/a) gives it back),
        // the two blends are the same arithmetic: equal bytes. Elsewhere (low alpha, where
        // premultiplying to bytes rounded the colour away by up to ½·255/a) they differ by the
        // rounding of that lost colour, weighted by α: at most 2.
        int exact = 0;
        for (int y = 0; y < h + 4; ++y)
            for (int x = 0; x < w + 4; ++x) {
                const Rgba8 p = a.at(x, y), q = b.at(x, y);
                bool carried = true;
                if (x >= 2 && x < w + 2 && y >= 3 && y < h + 3) {
                    const auto g = glyph.at(x - 2, y - 3);
                    const int want[3] = {colour.r, colour.g, colour.b};
                    for (int k = 0; k < 3 && g[3] > 0; ++k)
                        carried &= (g[static_cast<std::size_t>(k)] * 255 + g[3] / 2) / g[3] == want[k];
                }
                if (carried) {
                    EXPECT_EQ(p, q) << x << "," << y;
                    ++exact;
                } else {
                    EXPECT_NEAR(p.r, q.r, 2);
                    EXPECT_NEAR(p.g, q.g, 2);
                    EXPECT_NEAR(p.b, q.b, 2);
                    EXPECT_EQ(p.a, q.a);
                }
            }
        EXPECT_GT(exact, (w + 4) * (h + 4) / 2);
    }
    // Fully covered pixels are the colour itself.
    Image c(2, 2, Rgba8{0, 0, 0, 255});
    Target solid(1, 1);
    solid.px = {200, 100, 50, 255};
    blend_rgba(c, solid.view(), 1, 1);
    EXPECT_EQ(c.at(1, 1), colour);
    EXPECT_EQ(c.at(0, 0), (Rgba8{0, 0, 0, 255}));
}

// --- Hostile graphs ---------------------------------------------------------------------------------
TEST(Paint, RandomGraphsEitherPaintPremultipliedPixelsOrFailCleanly) {
    // Fixed seed; every node kind, indices sometimes out of range or looping, extreme numbers
    // (huge, tiny, zero scales, degenerate gradients). Each paint must return, and a success
    // must write premultiplied bytes (colour ≤ alpha) everywhere.
    std::uint64_t state = 0x9E3779B97F4A7C15ull;
    auto next = [&]() {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        return state;
    };
    auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * (next() % 1000000) / 1e6; };
    auto pick = [&](std::initializer_list<double> v) { return *(v.begin() + next() % v.size()); };
    auto num = [&]() { return next() % 8 == 0 ? pick({0.0, 1e12, -1e12, 1e-12, 1e300}) : uniform(-40, 40); };
    Path sq, circle;
    test::add_rect(sq, -5, -5, 25, 30);
    test::add_circle(circle, {10, 10}, 12);
    int painted = 0, refused = 0;
    Painter painter;
    for (int iter = 0; iter < 400; ++iter) {
        ColorGlyph g;
        g.outlines = {sq, circle};
        const PaintIndex n = static_cast<PaintIndex>(1 + next() % 12);
        auto child = [&]() { return static_cast<PaintIndex>(next() % 17 == 0 ? n + 3 : next() % n); };
        auto stops = [&]() {
            ColorLine l;
            l.extend = static_cast<Extend>(next() % 3);
            const int k = static_cast<int>(1 + next() % 4);
            float o = static_cast<float>(uniform(-2, 0));
            for (int i = 0; i < k; ++i) {
                o += static_cast<float>(next() % 3 == 0 ? 0.0 : uniform(0, 1.5));
                l.stops.push_back({o, color(float(uniform(0, 1)), float(uniform(0, 1)),
                                            float(uniform(0, 1)), float(uniform(0, 1)))});
            }
            return l;
        };
        for (PaintIndex i = 0; i < n; ++i) {
            switch (next() % 9) {
                case 0: g.nodes.push_back(PaintLayers{{child(), child()}}); break;
                case 1: g.nodes.push_back(PaintSolid{color(0.3f, 0.6f, 0.9f, 0.7f)}); break;
                case 2: g.nodes.push_back(PaintLinearGradient{stops(), {num(), num()}, {num(), num()}, {num(), num()}}); break;
                case 3: g.nodes.push_back(PaintRadialGradient{stops(), {num(), num()}, {num(), num()}, std::fabs(num()), std::fabs(num())}); break;
                case 4: g.nodes.push_back(PaintSweepGradient{stops(), {num(), num()}, uniform(-720, 720), uniform(-720, 720)}); break;
                case 5: g.nodes.push_back(PaintGlyph{static_cast<std::uint32_t>(next() % 3), child()}); break;
                case 6: g.nodes.push_back(PaintTransform{Affine{num() / 20, num() / 20, num() / 20, num() / 20, num(), num()}, child()}); break;
                case 7: g.nodes.push_back(PaintColrGlyph{child(), next() % 2 ? std::optional<Rect>(Rect{num(), num(), num(), num()}) : std::nullopt}); break;
                default: g.nodes.push_back(PaintComposite{child(), child(), static_cast<CompositeMode>(next() % kCompositeModeCount)}); break;
            }
        }
        if (next() % 4 == 0) g.clip = Rect{-2, -2, 30, 30};
        Target t(24, 24, 5);
        PaintOptions o;
        o.transform = flip(24);
        if (painter.paint(g, o, t.view()).ok()) {
            ++painted;
            for (int y = 0; y < 24; ++y)
                for (int x = 0; x < 24; ++x) {
                    const auto p = t.at(x, y);
                    ASSERT_LE(std::max({p[0], p[1], p[2]}), p[3]) << "iteration " << iter;
                }
        } else {
            ++refused;
            ASSERT_EQ(t.at(3, 3), (std::array<int, 4>{5, 5, 5, 5})) << "a refused paint wrote";
        }
    }
    EXPECT_GT(painted, 100);
    EXPECT_GT(refused, 20);
}

// --- Scratch ----------------------------------------------------------------------------------------
TEST(Paint, SecondPaintAllocatesNothing) {
    ColorGlyph g;
    Path circle, sq;
    test::add_circle(circle, {20, 20}, 15);
    test::add_rect(sq, 5, 5, 30, 25);
    test::add_circle(sq, {30, 25}, 6);   // two contours: the accurate-overlap fill's scratch too
    g.outlines = {circle, sq};
    const ColorLine l = line(Extend::Reflect, {{0.0f, kRed}, {0.3f, kGreen}, {1.0f, kBlue}});
    g.nodes = {PaintLayers{{1, 4}},
               PaintGlyph{0, 2},
               PaintRadialGradient{l, {20, 20}, {24, 22}, 1, 12},
               PaintSolid{},
               PaintColrGlyph{5, Rect{0, 0, 35, 35}},
               PaintComposite{6, 8, CompositeMode::Multiply},
               PaintGlyph{1, 7},
               PaintSweepGradient{l, {18, 18}, 30, 300},
               PaintTransform{Affine::rotate(0.3), 9},
               PaintGlyph{0, 10},
               PaintLinearGradient{l, {0, 0}, {30, 5}, {0, 30}}};
    g.uses_foreground = false;
    ASSERT_TRUE(validate(g).ok());
    Painter p;
    PaintOptions o;
    o.transform = flip(40);
    Target t(40, 40);
    ASSERT_TRUE(p.paint(g, o, t.view()).ok());
    EXPECT_GT(t.at(20, 20)[3], 0);
    const long before = g_allocations.load();
    ASSERT_TRUE(p.paint(g, o, t.view()).ok());
    EXPECT_EQ(g_allocations.load() - before, 0);
}

}  // namespace
}  // namespace bezel
