// DistanceSubdivision: halve (de Casteljau at t = 1/2) until the chord is provably within the
// tolerance of the piece, using the control-point bounds of curve_math.hpp:
//   quadratic  Hausdorff(piece, chord) ≤ |y₁|/2,
//   cubic      Hausdorff(piece, chord) ≤ (3/4)·max(|y₁|, |y₂|),
// where yᵢ is the offset of control point i from the chord line, valid when the control points
// project inside the chord; otherwise the convex-hull bound max distᵢ(control point, chord
// segment). Either way the bound is proven, so the polyline's Hausdorff distance to the curve is
// ≤ tolerance_px (the Hausdorff distance of a union of pieces is the max over the pieces).
//
// A straight curve (control points on the chord, in order) is one segment. Each halving cuts the
// control points' offsets about 4× (they are second differences), so a curve needing n segments
// is split about log₂ n deep; kMaxFlattenDepth caps that.
#include "flatten/methods.hpp"
#include "flatten/subdivide.hpp"

namespace bezel::flatten_detail {

bool distance_subdivision(const QuadBez& q, double tolerance_px, std::vector<Point>& out) {
    double tol2 = tolerance_px * tolerance_px;
    auto is_flat = [tol2](const QuadBez& p) { return quad_chord_bound_squared(p.p0, p.p1, p.p2) <= tol2; };
    std::size_t budget = kMaxSegmentsPerCurve - 1;
    return subdivide(q, is_flat, budget, out);
}

bool distance_subdivision(const CubicBez& c, double tolerance_px, std::vector<Point>& out) {
    double tol2 = tolerance_px * tolerance_px;
    auto is_flat = [tol2](const CubicBez& p) {
        return cubic_chord_bound_squared(p.p0, p.p1, p.p2, p.p3) <= tol2;
    };
    std::size_t budget = kMaxSegmentsPerCurve - 1;
    return subdivide(c, is_flat, budget, out);
}

}  // namespace bezel::flatten_detail
