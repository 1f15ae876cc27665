// Offset accuracy: the cubics stroke() uses for the two sides of a curve stay within the
// tolerance of the true offset C(t) ± h·N(t), both ways (every point of the approximation near
// the true offset, every point of the true offset near the approximation), over 1000 random
// cubics with a fixed seed — loops, inflections, cusps and tight curvature included.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "stroke/stroke_internal.hpp"

namespace bezel {
namespace {

using stroke_detail::Budget;
using stroke_detail::CurvePiece;
using stroke_detail::offset_cubic;
using stroke_detail::split_cubic;

// A curve f on [0, 1] as a polyline whose chords' midpoints are within 2e-4 of the curve's
// (bisection from 16 steps): distances to it are the curve's to that accuracy, 50× below the
// tolerance under test.
template <typename F>
void polyline(const F& f, std::vector<Point>& out) {
    out.clear();
    struct Rec {
        const F& f;
        std::vector<Point>& out;
        void go(double a, double b, Point pa, Point pb, int depth) {
            double m = 0.5 * (a + b);
            Point pm = f(m);
            if (depth < 24 && distance(pm, (pa + pb) * 0.5) > 2e-4) {
                go(a, m, pa, pm, depth + 1);
                go(m, b, pm, pb, depth + 1);
            } else {
                out.push_back(pm);
                out.push_back(pb);
            }
        }
    } rec{f, out};
    out.push_back(f(0.0));
    for (int i = 0; i < 16; ++i) rec.go(i / 16.0, (i + 1) / 16.0, f(i / 16.0), f((i + 1) / 16.0), 0);
}

double seg_distance(Point q, Point a, Point b) {
    Vec2 ab = b - a;
    double l2 = ab.length_squared();
    double t = l2 > 0 ? std::clamp((q - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
    return distance(q, a + ab * t);
}

double polyline_distance(Point q, const std::vector<Point>& pts) {
    double best = HUGE_VAL;
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) best = std::min(best, seg_distance(q, pts[i], pts[i + 1]));
    return best;
}

TEST(StrokeOffset, FittedCubicsStayWithinToleranceOfTrueOffset) {
    std::mt19937 rng(1234);
    std::uniform_real_distribution<double> coord(0, 50), half(0.25, 10);
    const double tol = 0.01;
    double worst_out = 0, worst_in = 0;  // approximation → true offset, true → approximation
    std::size_t pieces_total = 0, cubics_total = 0;
    std::vector<CurvePiece> pieces;
    std::vector<CubicBez> fit;
    std::vector<Point> truth_line, fit_line, part;
    for (int trial = 0; trial < 1000; ++trial) {
        CubicBez c{{coord(rng), coord(rng)}, {coord(rng), coord(rng)}, {coord(rng), coord(rng)},
                   {coord(rng), coord(rng)}};
        double h = half(rng);
        pieces.clear();
        split_cubic(c, h, 50.0, tol, pieces);
        for (const CurvePiece& p : pieces) {
            ++pieces_total;
            for (double d : {h, -h}) {
                fit.clear();
                Budget budget;
                offset_cubic(p.c, d, tol, budget, fit);
                cubics_total += fit.size();
                polyline([&](double t) { return p.c.eval(t) + p.c.normal(t) * d; }, truth_line);
                fit_line.clear();
                for (const CubicBez& f : fit) {
                    polyline([&](double u) { return f.eval(u); }, part);
                    fit_line.insert(fit_line.end(), part.begin(), part.end());
                    for (int k = 1; k < 4; ++k) {
                        double e = polyline_distance(f.eval(k / 4.0), truth_line);
                        worst_out = std::max(worst_out, e);
                        ASSERT_LE(e, tol) << "trial " << trial << " h=" << h << " d=" << d;
                    }
                }
                std::size_t stride = std::max<std::size_t>(1, truth_line.size() / 16);
                for (std::size_t k = 0; k < truth_line.size(); k += stride) {
                    double e = polyline_distance(truth_line[k], fit_line);
                    worst_in = std::max(worst_in, e);
                    ASSERT_LE(e, tol) << "trial " << trial << " h=" << h << " d=" << d;
                }
            }
        }
    }
    std::printf("[ measured ] tolerance %g: worst approximation->offset %.3g, offset->approximation "
                "%.3g; %.2f cubics per side per piece (%zu pieces)\n",
                tol, worst_out, worst_in, cubics_total / (2.0 * pieces_total), pieces_total);
}

}  // namespace
}  // namespace bezel
