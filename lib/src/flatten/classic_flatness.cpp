// ClassicFlatness: the course notes' test — accept a piece when its control polygon is barely
// longer than its chord, ‖P₀P₁‖ + … + ‖Pₙ₋₁Pₙ‖ < (1 + ε)·‖P₀Pₙ‖, otherwise halve it (de Casteljau).
//
// What it bounds. Every point Q of the control polygon has ‖P₀Q‖ + ‖QPₙ‖ ≤ polygon length
// ≤ (1 + ε)·L (L the chord length), so Q lies in the ellipse with foci P₀, Pₙ and major axis
// (1 + ε)·L; the ellipse is convex, so it holds the convex hull and with it the curve. Every point
// of that ellipse is within its semi-minor axis b = (L/2)·√((1 + ε)² − 1) = (L/2)·√(2ε + ε²) of
// the chord segment (past the foci the distance to the nearer focus is at most b²/a ≤ b), and
// every chord point has a curve point across from it (continuity), so
//     Hausdorff(piece, chord) ≤ (L/2)·√(2ε + ε²)      (≈ 0.00707·L at ε = 10⁻⁴).
// The bound grows with L: the test is scale-free and bounds no distance in pixels. Its error is
// therefore measured (flatten_bench) rather than promised, and the tests assert this bound.
#include <cmath>

#include "flatten/methods.hpp"
#include "flatten/subdivide.hpp"

namespace bezel::flatten_detail {

bool classic_flatness(const QuadBez& q, double epsilon, std::vector<Point>& out) {
    double ratio = 1.0 + epsilon;
    auto is_flat = [ratio](const QuadBez& p) {
        double polygon = distance(p.p0, p.p1) + distance(p.p1, p.p2);
        return polygon <= ratio * distance(p.p0, p.p2);  // a point (0 ≤ 0) is flat
    };
    std::size_t budget = kMaxSegmentsPerCurve - 1;
    return subdivide(q, is_flat, budget, out);
}

bool classic_flatness(const CubicBez& c, double epsilon, std::vector<Point>& out) {
    double ratio = 1.0 + epsilon;
    auto is_flat = [ratio](const CubicBez& p) {
        double polygon = distance(p.p0, p.p1) + distance(p.p1, p.p2) + distance(p.p2, p.p3);
        return polygon <= ratio * distance(p.p0, p.p3);
    };
    std::size_t budget = kMaxSegmentsPerCurve - 1;
    return subdivide(c, is_flat, budget, out);
}

}  // namespace bezel::flatten_detail
