// Splitting a source cubic where its stroke changes character: at cusps (C′ = 0, where the
// normal flips and the stroke gets a round join), and where the radius of curvature crosses the
// half-width h (|κ|·h = 1: the inner offset has a cusp there and beyond it folds back, Nehab,
// "Converting stroked primitives to filled primitives", SIGGRAPH 2020). Also the evolute, the
// locus of the centres of curvature C + N/κ, which bounds the folded part of a tight piece.
#include <algorithm>
#include <cmath>

#include "stroke/stroke_internal.hpp"

namespace bezel::stroke_detail {
namespace {

// Near-cusps. At a speed minimum t* with A = C′(t*), B = C″(t*), the tangent A + B·u turns by
// nearly π within |u| ≲ |A|/|B|, where the curve moves only ~|A|²/|B|. Sampling in t cannot see
// that window, so the curve is always split at t* (the fast turn then sits at a piece's end,
// where the exact end point and tangent expose it to the fitting). When even the window
// u ∈ ±kCuspWindow·|A|/|B|, over which the curve moves ≈ kCuspWindow²·|A|²/(2|B|), lies within
// tol/2 of the cusp point, the window is cut out and the point treated as a cusp: outside it the
// tangent is within atan(1/kCuspWindow) < 1° of its limit, so the pieces on each side fit
// easily, and the disc at the cusp covers what the window would have drawn.
constexpr double kCuspWindow = 64.0;
// Samples of |κ|·h − 1 between consecutive inflections / speed extrema, to bracket the crossings.
constexpr int kTightSamples = 8;
constexpr int kBisections = 60;
constexpr int kMaxEvoluteDepth = 16;

// C′(t)/3 = q0 + q1·t + q2·t² (the hodograph in power form).
struct Hodograph {
    Vec2 q0, q1, q2;
    explicit Hodograph(const CubicBez& c) {
        Vec2 a = c.p1 - c.p0, b = c.p2 - c.p1, d = c.p3 - c.p2;
        q0 = a;
        q1 = (b - a) * 2.0;
        q2 = a - b * 2.0 + d;
    }
    Vec2 at(double t) const { return q0 + (q1 + q2 * t) * t; }
};

double tightness(const CubicBez& c, double h, double t) { return h * std::fabs(c.curvature(t)) - 1.0; }

// Parameters in (lo, hi) where tightness changes sign, appended to `out`.
void tight_crossings(const CubicBez& c, double h, double lo, double hi, std::vector<double>& out) {
    double prev_t = lo, prev_f = tightness(c, h, lo);
    for (int i = 1; i <= kTightSamples; ++i) {
        double t = lo + (hi - lo) * i / kTightSamples;
        double f = tightness(c, h, t);
        if ((prev_f > 0.0) != (f > 0.0)) {
            double a = prev_t, b = t;
            bool a_pos = prev_f > 0.0;
            for (int k = 0; k < kBisections && b - a > 1e-15; ++k) {
                double m = 0.5 * (a + b);
                if ((tightness(c, h, m) > 0.0) == a_pos) a = m; else b = m;
            }
            out.push_back(0.5 * (a + b));
        }
        prev_t = t;
        prev_f = f;
    }
}

}  // namespace

void split_cubic(const CubicBez& c, double h, double size, double tol,
                 std::vector<CurvePiece>& out) {
    Rect box = c.control_box();
    double poly = std::max(box.width(), box.height());
    if (!(poly > 1e-12 * size)) return;
    Hodograph hod(c);
    Vec2 q0 = hod.q0, q1 = hod.q1, q2 = hod.q2;

    // Speed extrema: d/dt |C′|² ∝ C′·C″ = 0, a cubic in t. Cusps and near-cusps are among them.
    double speed_ext[3];
    int n_speed = solve_cubic_in(2 * q2.dot(q2), 3 * q1.dot(q2), 2 * q0.dot(q2) + q1.dot(q1),
                                 q0.dot(q1), 0.0, 1.0, speed_ext);
    // Inflections: C′ × C″ = 0, a quadratic.
    double inflect[2];
    int n_inflect = solve_quadratic_in(q1.cross(q2), 2 * q0.cross(q2), q0.cross(q1), 0.0, 1.0,
                                       inflect);

    // Break parameters: cusp windows [lo, hi] (lo == hi for an exact cusp) and smooth splits at
    // the other speed minima; `cusp_at[k]` says whether the piece after cut k starts at a cusp.
    std::vector<double> cuts0{0.0};
    std::vector<bool> cusp_at{false};
    for (int i = 0; i < n_speed; ++i) {
        double t = speed_ext[i];
        if (!(t > 0.0 && t < 1.0)) continue;
        Vec2 a = hod.at(t) * 3.0, b = (q1 + q2 * (2 * t)) * 3.0;
        double al = a.length(), bl = b.length();
        if (bl == 0.0) continue;  // a straight, uniformly moving stretch: no turn here
        double window = kCuspWindow * al / bl;
        if (0.5 * bl * window * window <= 0.5 * tol) {
            double lo = std::max(t - window, cuts0.back()), hi = std::min(t + window, 1.0);
            cuts0.push_back(lo);
            cusp_at.push_back(false);
            cuts0.push_back(hi);
            cusp_at.push_back(true);
        } else {
            cuts0.push_back(std::max(t, cuts0.back()));
            cusp_at.push_back(false);
        }
    }
    cuts0.push_back(1.0);
    cusp_at.push_back(false);

    std::vector<double> grid;
    bool pending_cusp = false;
    for (std::size_t k = 0; k + 1 < cuts0.size(); ++k) {
        double lo = cuts0[k], hi = cuts0[k + 1];
        if (cusp_at[k + 1]) {  // [lo, hi] is a cusp's window: dropped, the next piece starts at it
            pending_cusp = true;
            continue;
        }
        if (!(hi > lo)) continue;
        grid.assign({lo});
        for (int i = 0; i < n_inflect; ++i)
            if (inflect[i] > lo && inflect[i] < hi) grid.push_back(inflect[i]);
        grid.push_back(hi);
        std::sort(grid.begin(), grid.end());
        std::vector<double> cuts{lo};
        for (std::size_t g = 0; g + 1 < grid.size(); ++g)
            tight_crossings(c, h, grid[g], grid[g + 1], cuts);
        cuts.push_back(hi);
        for (std::size_t j = 0; j + 1 < cuts.size(); ++j) {
            double u = cuts[j], v = cuts[j + 1];
            if (!(v > u)) continue;
            CurvePiece piece;
            piece.c = c.subsegment(u, v);
            Rect pb = piece.c.control_box();
            if (!(std::max(pb.width(), pb.height()) > 1e-12 * size)) continue;
            double kappa = c.curvature(0.5 * (u + v));
            piece.tight = h * std::fabs(kappa) > 1.0;
            piece.sigma = kappa > 0.0 ? 1 : -1;
            piece.cusp_before = pending_cusp;
            pending_cusp = false;
            out.push_back(piece);
        }
    }
}

namespace {

Point evolute_point(const CubicBez& c, double t) {
    double kappa = c.curvature(t);
    double radius = std::isfinite(kappa) && kappa != 0.0 ? 1.0 / kappa : 0.0;
    return c.eval(t) + c.normal(t) * radius;
}

void evolute_rec(Path& path, const CubicBez& c, double t0, double t1, Point e0, Point e1,
                 double tol, int depth, Budget& budget) {
    double tm = 0.5 * (t0 + t1);
    Point em = evolute_point(c, tm);
    bool flat = depth >= 2 && distance(em, (e0 + e1) * 0.5) <= tol;
    if (flat || depth >= kMaxEvoluteDepth || budget.exceeded()) {
        path.line_to(e1);
        budget.take(1);
        return;
    }
    evolute_rec(path, c, t0, tm, e0, em, tol, depth + 1, budget);
    evolute_rec(path, c, tm, t1, em, e1, tol, depth + 1, budget);
}

}  // namespace

void evolute_back(Path& path, const CubicBez& c, double tol, Budget& budget) {
    Point e1 = evolute_point(c, 1.0), e0 = evolute_point(c, 0.0);
    path.line_to(e1);
    budget.take(1);
    evolute_rec(path, c, 1.0, 0.0, e1, e0, tol, 0, budget);
}

}  // namespace bezel::stroke_detail
