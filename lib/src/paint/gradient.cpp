// Colour lines and the linear, radial and sweep gradients of COLR version 1.
//
// Interpolation: between two stops the STRAIGHT (unpremultiplied) sRGB-encoded colour and alpha
// are interpolated linearly and the result premultiplied. That is what Skia does for COLRv1, so
// what Chromium shows: its FreeType port (SkFontHost_FreeType_common.cpp,
// colrv1_configure_skpaint) builds each colour line as an SkGradientShader with no
// kInterpolateColorsInPremul flag, Skia's default of interpolating unpremultiplied colours in the
// destination's (sRGB-encoded) space. The CPAL section of the specification asks instead for
// interpolation of premultiplied linear-light values; the two agree whenever the stops share one
// alpha (nearly every emoji), and bezel follows the renderer its goldens are checked against.
// docs/colour.md states the difference.
#include "paint/gradient.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bezel::paint_detail {

namespace {

constexpr double kPi = 3.14159265358979323846;

// t folded onto [first, last] by the extend mode: Repeat takes t modulo the span, Reflect
// mirrors every other span. A span of zero length (all stops at one offset) pads.
double extend(const ColorLine& line, double t) {
    const double first = line.stops.front().offset, last = line.stops.back().offset;
    const double span = last - first;
    if (line.extend == Extend::Pad || !(span > 0.0)) return t;
    const double u = (t - first) / span;
    double m;
    if (line.extend == Extend::Repeat) {
        m = u - std::floor(u);
    } else {
        m = u - 2.0 * std::floor(u * 0.5);  // in [0, 2)
        if (m > 1.0) m = 2.0 - m;
    }
    return first + m * span;
}

// A colour line that repeats or reflects a span of zero length (every stop at one offset) has no
// period to repeat: it paints nothing, as the specification says of a sweep whose start and end
// angles are equal (and as Skia draws it). Pad extends its end colours either way.
bool repeats_nothing(const ColorLine& line) {
    return line.extend != Extend::Pad &&
           !(line.stops.back().offset - line.stops.front().offset > 0.0f);
}

}  // namespace

Pixel color_line_at(const ColorLine& line, double t, const Rgba8& foreground) {
    const auto& stops = line.stops;
    t = extend(line, t);
    // The first stop above t: stops at equal offsets make a hard edge, the earlier one's colour
    // below the offset and the later one's at and above it.
    std::size_t i = 0;
    while (i < stops.size() && !(t < stops[i].offset)) ++i;
    if (i == 0) return premultiplied(resolve(stops.front().color, foreground));
    if (i == stops.size()) return premultiplied(resolve(stops.back().color, foreground));
    const ColorStop& lo = stops[i - 1];
    const ColorStop& hi = stops[i];
    // lo.offset ≤ t < hi.offset, so the span is positive.
    const float f = static_cast<float>((t - lo.offset) / (static_cast<double>(hi.offset) - lo.offset));
    const ColorF a = resolve(lo.color, foreground), b = resolve(hi.color, foreground);
    const ColorF c{a.r + (b.r - a.r) * f, a.g + (b.g - a.g) * f, a.b + (b.b - a.b) * f,
                   a.a + (b.a - a.a) * f};
    return premultiplied(c);
}

// Linear (COLR's p0, p1, p2): the colour is constant along lines parallel to p0→p2, so p1 is
// replaced by its projection p1' onto the line through p0 perpendicular to p0→p2:
//   n = perp(p2 − p0),  p1' = p0 + n·((p1 − p0)·n / n·n),  t(p) = (p − p0)·(p1' − p0) / |p1' − p0|²
// p0 = p1 or p2 on the line p0 p1 (cross product 0) leaves no axis: nothing is painted.
Gradient::Gradient(const PaintLinearGradient& g) : kind_(Kind::Linear), line_(&g.line) {
    const Vec2 d1 = g.p1 - g.p0, d2 = g.p2 - g.p0;
    const Vec2 n = d2.perp();
    p0_ = g.p0;
    if (repeats_nothing(g.line) || d1.cross(d2) == 0.0 || n.length_squared() == 0.0) {
        paints_ = false;
        return;
    }
    const Vec2 p1p = n * (d1.dot(n) / n.length_squared());
    const double len2 = p1p.length_squared();
    if (!(len2 > 0.0) || !std::isfinite(len2)) {
        paints_ = false;
        return;
    }
    axis_ = p1p / len2;
}

// Radial (two circles, as HTML canvas's createRadialGradient): the largest t with
//   |p − c(t)| = r(t),  c(t) = c0 + t·cd,  r(t) = r0 + t·dr ≥ 0.
// Squaring, with pd = p − c0:  a·t² − 2·b·t + c = 0,
//   a = cd·cd − dr²,  b = pd·cd + r0·dr,  c = pd·pd − r0²
// so t = (b ± √(b² − a·c)) / a, the larger root whose radius is not negative; when a = 0 (one
// circle touches the other from inside) the equation is linear, t = c / (2b).
Gradient::Gradient(const PaintRadialGradient& g) : kind_(Kind::Radial), line_(&g.line) {
    p0_ = g.c0;
    cd_ = g.c1 - g.c0;
    r0_ = g.r0;
    dr_ = g.r1 - g.r0;
    a_ = cd_.length_squared() - dr_ * dr_;
    // Equal circles: no t is defined (canvas paints nothing).
    if (repeats_nothing(g.line) || (cd_.length_squared() == 0.0 && dr_ == 0.0)) paints_ = false;
    // a within rounding of 0 relative to its terms: the linear case.
    linear_equation_ = std::fabs(a_) <= 1e-12 * (cd_.length_squared() + dr_ * dr_);
}

// Sweep: angles counter-clockwise in glyph space (y up), so atan2 of glyph-space coordinates
// gives them directly; t = (angle − start) / (end − start) with the angle in [0, 360).
Gradient::Gradient(const PaintSweepGradient& g) : kind_(Kind::Sweep), line_(&g.line) {
    p0_ = g.center;
    start_deg_ = g.start_deg;
    end_deg_ = g.end_deg;
    if (repeats_nothing(g.line) || (start_deg_ == end_deg_ && g.line.extend != Extend::Pad))
        paints_ = false;
}

bool Gradient::t_at(Point p, double& t) const {
    const Vec2 pd = p - p0_;
    switch (kind_) {
        case Kind::Linear:
            t = pd.dot(axis_);
            break;
        case Kind::Radial: {
            const double b = pd.dot(cd_) + r0_ * dr_;
            const double c = pd.length_squared() - r0_ * r0_;
            if (linear_equation_) {
                if (b == 0.0) return false;
                t = c / (2.0 * b);
                if (r0_ + t * dr_ < 0.0) return false;
                break;
            }
            const double disc = b * b - a_ * c;
            if (disc < 0.0) return false;
            const double s = std::sqrt(disc);
            const double t1 = (b + s) / a_, t2 = (b - s) / a_;
            const double hi = std::max(t1, t2), lo = std::min(t1, t2);
            if (r0_ + hi * dr_ >= 0.0) t = hi;
            else if (r0_ + lo * dr_ >= 0.0) t = lo;
            else return false;
            break;
        }
        case Kind::Sweep: {
            double angle = std::atan2(pd.y, pd.x) * (180.0 / kPi);
            if (angle < 0.0) angle += 360.0;
            if (angle >= 360.0) angle -= 360.0;
            const double span = end_deg_ - start_deg_;
            if (span == 0.0) {
                // Only a padded line paints: the first colour before the start, the last after.
                t = angle < start_deg_ ? -std::numeric_limits<double>::infinity()
                                       : std::numeric_limits<double>::infinity();
                return true;
            }
            t = (angle - start_deg_) / span;
            break;
        }
    }
    return std::isfinite(t);
}

}  // namespace bezel::paint_detail
