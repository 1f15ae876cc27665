// Private: the flattener fill_path uses for WangUniform — uniform steps, Wang's count, and
// ERROR-BALANCED vertices, written straight into a reused Polylines (no callbacks, no allocation
// once it has grown).
//
// Why balanced. A chord always cuts inside a convex arc, so plain flattening loses area on one
// side only and the coverage error is biased (the mean error at 12 px grows linearly with the
// tolerance). Take uniform steps h = 1/n with curve points Bᵢ and second differences
// Δ²ᵢ = Bᵢ₋₁ − 2Bᵢ + Bᵢ₊₁. For a quadratic Δ² is constant, and the arc over one chord bulges
// out from the chord midpoint by −Δ²/8 (a parabola: B(t) + B(t+h) − 2B(t+h/2) = Δ²/4 for the
// half step); the area between chord and parabola is 2/3 of base × height, i.e. the arc lies on
// average −Δ²/12 off the chord. So emitting Bᵢ − Δ²ᵢ/12 instead of Bᵢ puts each chord where the
// arc is ON AVERAGE: the signed area error per chord is zero (exact for a quadratic, O(h³) for a
// cubic), the two ends (kept on the curve, being shared with the neighbouring segments) are
// half-corrected. The distance bound improves too: vertices lie |Δ²|/12 off the curve and chord
// midpoints |Δ²|/8 − |Δ²|/12 = |Δ²|/24, against |Δ²|/8 for the plain polyline.
#pragma once

#include "bezel/flatten.hpp"
#include "bezel/geometry.hpp"
#include "bezel/path.hpp"

namespace bezel::raster_detail {

// Appends the transformed, balanced flattening of `path` to `out` (same contour conventions as
// flatten(): implicit close, a lone move dropped). Uses n = ⌈√(d(d−1)·M / (8·tol))⌉ steps per
// curve (Wang's count, M the largest transformed second difference of the control points), so
// the polyline is within tol of the curve (within 2/3·tol for a quadratic). Returns false, with
// `out` in an unspecified state, when the input is outside its fast path: a control point not
// finite or beyond kMaxFlattenCoordinatePx after the transform, or a curve needing more than
// kMaxSegmentsPerCurve steps — the caller then uses flatten_checked, which reports those.
bool flatten_balanced(const Path& path, const Affine& m, double tol, Polylines& out);

}  // namespace bezel::raster_detail
