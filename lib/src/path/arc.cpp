// SVG elliptical arcs (endpoint parameterization, SVG 1.1 appendix F.6) to cubic Béziers.
//
// Frame. The ellipse is E(t) = C + R_φ·(rx·cos t, ry·sin t). Undoing the rotation and dividing by
// the radii maps it to the unit circle, where the half chord from `to` to `from` becomes
//   v = ((R_−φ·(from − to)/2).x / rx, (R_−φ·(from − to)/2).y / ry),   s = |v|.
// (This is F.6.5.1's (x1′, y1′) divided by the radii; working with the ratios avoids F.6.5.2's
// rx²·ry² products, which overflow for large radii.) If s > 1 the radii are too small to reach
// `to` and F.6.6 scales them by s, which makes s = 1.
//
// Angles without the centre. On the unit circle a chord of half-length s spans 2·asin(s), so the
// small arc sweeps α = 2·asin(s) and the large one 2π − α; the sweep flag picks the sign
// (sweep = 1: angle increasing, F.6.5.6). With t₀, t₁ = t₀ + Δ and m = (t₀ + t₁)/2,
//   u(t₁) − u(t₀) = 2·sin(Δ/2)·(−sin m, cos m)  and  u(t₁) − u(t₀) = −2v
// give (sin m, −cos m) = v / sin(Δ/2), where sin(Δ/2) = ±s. Points are then placed relative to
// `from` with the sum-to-product forms
//   cos a − cos b = −2·sin((a+b)/2)·sin((a−b)/2),   sin a − sin b = 2·cos((a+b)/2)·sin((a−b)/2),
// which never subtract two nearly equal numbers. The centre-based route loses all precision
// when the radius dwarfs the chord (C is then far away and cos t + cₓ cancels).
//
// Cubics. Each piece of angle h gets the standard control arm k = (4/3)·tan(h/4) along the
// tangents. On the unit circle its radial error is at most
//   e(h) = (2/27)·sin⁶(h/4) / cos²(h/4)
// (Goldapp, "Approximation of circular arcs by cubic polynomials", CAGD 8, 1991); the cubic
// crosses each ray of the arc once, so e bounds the distance both ways. The map to the ellipse
// stretches distances by at most max(rx, ry), so n pieces with max(rx, ry)·e(|Δ|/n) ≤ tolerance
// meet the bound. We take the smallest such n (e is increasing, so a binary search finds it),
// at least one piece per quarter turn, at most kMaxCubicsPerArc.
#include <algorithm>
#include <cmath>

#include "bezel/path.hpp"

namespace bezel {

namespace {

constexpr double kPi = 3.14159265358979323846;

// cos and sin of an angle in degrees, exact at multiples of 90° (so an unrotated or quarter-
// turned ellipse keeps exact axis-aligned control points).
void cos_sin_deg(double deg, double& c, double& s) {
    double r = std::fmod(deg, 360.0);
    if (r < 0) r += 360.0;
    if (r == 0.0) { c = 1; s = 0; return; }
    if (r == 90.0) { c = 0; s = 1; return; }
    if (r == 180.0) { c = -1; s = 0; return; }
    if (r == 270.0) { c = 0; s = -1; return; }
    double rad = r * (kPi / 180.0);
    c = std::cos(rad);
    s = std::sin(rad);
}

// Goldapp's bound on the radial error of one cubic over a unit-circle arc of angle h.
double unit_arc_error(double h) {
    double sw = std::sin(h * 0.25), cw = std::cos(h * 0.25);
    double s2 = sw * sw;
    return (2.0 / 27.0) * s2 * s2 * s2 / (cw * cw);
}

int pieces_for(double sweep_abs, double relative_tolerance) {
    int lo = std::max(1, static_cast<int>(std::ceil(sweep_abs / (kPi / 2))));
    if (unit_arc_error(sweep_abs / lo) <= relative_tolerance) return lo;
    int hi = kMaxCubicsPerArc;
    if (!(unit_arc_error(sweep_abs / hi) <= relative_tolerance)) return hi;
    // Invariant: lo fails the bound, hi meets it.
    while (hi - lo > 1) {
        int mid = lo + (hi - lo) / 2;
        if (unit_arc_error(sweep_abs / mid) <= relative_tolerance)
            hi = mid;
        else
            lo = mid;
    }
    return hi;
}

}  // namespace

void append_svg_arc(Path& path, Point from, const SvgArc& arc, double tolerance) {
    const Point to = arc.to;
    if (from == to) return;  // F.6.2: an arc to the current point is omitted
    double rx = std::fabs(arc.radii.x), ry = std::fabs(arc.radii.y);
    if (rx == 0.0 || ry == 0.0) {  // F.6.2: a zero radius makes a straight line
        path.line_to(to);
        return;
    }
    double cphi, sphi;
    cos_sin_deg(arc.x_rotation_deg, cphi, sphi);

    const Vec2 h = (from - to) * 0.5;
    Vec2 v{(cphi * h.x + sphi * h.y) / rx, (-sphi * h.x + cphi * h.y) / ry};
    double s = std::hypot(v.x, v.y);
    if (!(s > 0.0)) {
        // The chord underflowed against the radii (chord/radius below ~1e-308): as flat as a
        // double can tell.
        path.line_to(to);
        return;
    }
    if (s >= 1.0) {  // F.6.6: radii too small, scale them up until the chord fits
        rx *= s;
        ry *= s;
        v = v / s;
        s = 1.0;
    }

    const double small = 2.0 * std::asin(s);
    const double sweep_abs = arc.large_arc ? 2.0 * kPi - small : small;
    const double delta = arc.sweep ? sweep_abs : -sweep_abs;
    // (sin m, −cos m) = v / sin(Δ/2), and sin(Δ/2) has the sign of Δ.
    const double m = arc.sweep ? std::atan2(v.x, -v.y) : std::atan2(-v.x, v.y);
    const double t0 = m - delta * 0.5;

    const int n = pieces_for(sweep_abs, tolerance / std::max(rx, ry));
    const double step = delta / n;
    const double k = (4.0 / 3.0) * std::tan(step * 0.25);

    // Ellipse frame → path frame for a vector: scale by the radii, then rotate by φ.
    auto to_path = [&](double ux, double uy) {
        double x = rx * ux, y = ry * uy;
        return Vec2{cphi * x - sphi * y, sphi * x + cphi * y};
    };
    auto tangent = [&](double t) { return to_path(-std::sin(t), std::cos(t)); };
    auto point = [&](int i) {
        // E(tᵢ) − E(t₀) by the sum-to-product forms, with (a+b)/2 = t₀ + i·step/2.
        double half = i * step * 0.5, mid = t0 + half, sh = std::sin(half);
        return from + to_path(-2.0 * std::sin(mid) * sh, 2.0 * std::cos(mid) * sh);
    };

    Point p0 = from;
    Vec2 d0 = tangent(t0);
    for (int i = 1; i <= n; ++i) {
        Point p1 = i == n ? to : point(i);
        Vec2 d1 = tangent(t0 + i * step);
        path.cubic_to(p0 + d0 * k, p1 - d1 * k, p1);
        p0 = p1;
        d0 = d1;
    }
}

}  // namespace bezel
