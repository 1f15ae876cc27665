// Clipping edges to the accumulation band (the slow path; edges inside the band go straight to
// draw_line). See accumulate.hpp for why pointwise clamping in x is exact.
#include "raster/accumulate.hpp"

#include <utility>

namespace bezel::raster_detail {

namespace {

// Parameter t at which a + t·(b − a) = v, for a ≠ b. Halved operands: b − a may overflow a
// double when a and b are huge with opposite signs; b/2 − a/2 cannot.
double param_at(double a, double b, double v) {
    return (0.5 * v - 0.5 * a) / (0.5 * b - 0.5 * a);
}

// a + t·(b − a) for t in [0, 1], overflow-free for any finite a, b: each partial sum lies
// between a and b.
double lerp_safe(double a, double b, double t) {
    const double half = t * (0.5 * b - 0.5 * a);
    return a + half + half;
}

}  // namespace

void clip_and_draw_line(const Band& band, double x0, double y0, double x1, double y1) {
    const double W = band.width, H = band.rows;
    if (y0 == y1 || (y0 <= 0.0 && y1 <= 0.0) || (y0 >= H && y1 >= H)) return;

    // Clip in y, keeping the edge's direction (its winding sign).
    if (y0 < 0.0 || y0 > H || y1 < 0.0 || y1 > H) {
        const double ya = std::clamp(y0, 0.0, H), yb = std::clamp(y1, 0.0, H);
        const double xa = ya == y0 ? x0 : lerp_safe(x0, x1, param_at(y0, y1, ya));
        const double xb = yb == y1 ? x1 : lerp_safe(x0, x1, param_at(y0, y1, yb));
        x0 = xa; y0 = ya; x1 = xb; y1 = yb;
        if (y0 == y1) return;
    }

    if (x0 >= 0.0 && x0 <= W && x1 >= 0.0 && x1 <= W) {
        draw_line(band, x0, y0, x1, y1);
        return;
    }
    if (x0 >= W && x1 >= W) return;  // right of the band: touches no pixel
    if (x0 <= 0.0 && x1 <= 0.0) {     // left of the band: its cover, as a vertical edge at x = 0
        draw_line(band, 0.0, y0, 0.0, y1);
        return;
    }

    // Crosses x = 0 and/or x = W: cut there (at most two cuts), then each piece is wholly left,
    // inside or right.
    struct Cut { double t, x, y; };
    Cut cuts[4];
    int n = 0;
    cuts[n++] = {0.0, x0, y0};
    for (double X : {0.0, W}) {
        if ((x0 < X && x1 > X) || (x0 > X && x1 < X)) {
            const double t = param_at(x0, x1, X);
            cuts[n++] = {t, X, std::clamp(lerp_safe(y0, y1, t), std::min(y0, y1), std::max(y0, y1))};
        }
    }
    if (n == 3 && cuts[2].t < cuts[1].t) std::swap(cuts[1], cuts[2]);
    cuts[n++] = {1.0, x1, y1};
    for (int k = 0; k + 1 < n; ++k) {
        const Cut& a = cuts[k];
        const Cut& b = cuts[k + 1];
        const double xm = 0.5 * a.x + 0.5 * b.x;
        if (xm >= W) continue;
        if (xm <= 0.0) {
            draw_line(band, 0.0, a.y, 0.0, b.y);
        } else {
            draw_line(band, std::clamp(a.x, 0.0, W), a.y, std::clamp(b.x, 0.0, W), b.y);
        }
    }
}

}  // namespace bezel::raster_detail
