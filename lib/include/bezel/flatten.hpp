// bezel/flatten.hpp — curves to polylines within a tolerance in pixels.
//
// Coordinates y down, in the path's units after `transform` (pixels when rendering). The
// transform is applied to the control points first (Bézier curves are affine-invariant), so the
// tolerance is measured where it matters: in the output.
//
// What the tolerance bounds: for every method except ClassicFlatness, the Hausdorff distance
// between each curve and the part of the polyline that replaces it is ≤ tolerance_px — every
// point of the curve is within tolerance_px of the polyline and every point of the polyline is
// within tolerance_px of the curve. Each method's file in lib/src/flatten/ carries the proof.
// Polyline vertices lie on the curve (up to rounding) and curve end points are copied exactly.
//
// Methods. Segments over all glyphs of DejaVu Sans at 512 px, tolerance 0.0625 px, measured max
// error in px (tools/bench/flatten_bench; the full table is in docs/curves.md):
//   WangUniform          831 k, 0.0615. n = ⌈√(d(d−1)·M / (8·tol))⌉ uniform steps, points by
//                        forward differencing. Branch-free, predictable, fastest: the default.
//   DistanceSubdivision  960 k, 0.0625. de Casteljau halving until the control points are close
//                        to the chord (power-of-two counts: the most segments of the bounded three).
//   ParabolaIntegral     736 k, 0.0625. Levien's analytic spacing for quadratics (cubics via
//                        quadratics): fewest segments on quadratic fonts, slowest per point.
//   ClassicFlatness      2.57 M, 0.32. The course notes' test, polygon length / chord length < 1 + ε.
//                        Scale-free, so it bounds no distance: the same 2.57 M segments at 12 px,
//                        where 0.2 M suffice. Kept as the baseline the others are measured
//                        against. Its error per piece is ≤ (chord/2)·√(2ε + ε²) (see its file).
#pragma once

#include <cstddef>
#include <vector>

#include "bezel/expected.hpp"
#include "bezel/geometry.hpp"
#include "bezel/limits.hpp"
#include "bezel/path.hpp"

#pragma GCC visibility push(default)  // the public API of libbezel.so (docs/architecture.md)
namespace bezel {

// Flattened contours, all closed implicitly (a filler joins each last point to its first).
// flatten() appends to it; out.clear() keeps the capacity, so a caller that keeps one Polylines
// allocates nothing once it has grown to the largest outline.
struct Polylines {
    std::vector<Point> points;
    std::vector<std::size_t> contour_ends;  // one past the last point of each contour
    void clear() { points.clear(); contour_ends.clear(); }
};

enum class FlattenMethod {
    ClassicFlatness,      // course notes: control polygon length / chord length < 1 + ε (baseline)
    DistanceSubdivision,  // recursive de Casteljau, control-point-to-chord distance bound
    WangUniform,          // uniform steps, count from Wang's formula, forward differencing
    ParabolaIntegral,     // Levien's analytic method: fewest segments at equal error
};

// --- Limits ------------------------------------------------------------------------------------
// Smallest tolerance used; flatten() raises smaller (or NaN) tolerances to it.
inline constexpr double kMinFlattenTolerancePx = 1e-9;

// --- Defaults ----------------------------------------------------------------------------------
// Default tolerance: 1/16 px. Why: an edge displaced by at most δ changes the coverage of any
// pixel it crosses by at most √2·δ (the area between the two edges inside a unit square), so the
// tolerance bounds the coverage error. FreeType's own flattening errs up to about 0.09 px on
// conics and 0.17 px on cubics; a guaranteed 0.0625 px stays below both for every glyph. The
// bounds are tight — on the test fonts the measured error is 0.060–0.0625 px at this setting, and
// 0.098–0.100 px at 0.1 px, above FreeType's conic error — so the default has to be the bound
// itself, not a hope. It costs 23% more segments than 0.1 px (1.00 M vs 0.82 M for both fonts at
// 512 px with WangUniform; segments grow as 1/√tol).
inline constexpr double kDefaultFlattenTolerancePx = 0.0625;
// Default ε for ClassicFlatness. The test is scale-free: a piece of chord length L passes with a
// deviation up to (L/2)·√(2ε + ε²) ≈ 0.007·L at this ε, so at 12 px glyph size it is far finer than
// needed and at 512 px coarser (its measured error is in the bench table).
inline constexpr double kDefaultClassicFlatnessEpsilon = 1e-4;

struct FlattenOptions {
    // Bound on the Hausdorff distance between each curve and its polyline, in output units
    // (pixels when rendering). Ignored by ClassicFlatness.
    double tolerance_px = kDefaultFlattenTolerancePx;
    FlattenMethod method = FlattenMethod::WangUniform;
    // ClassicFlatness only: accept a piece when polygon length < (1 + ε)·chord length.
    double classic_flatness_epsilon = kDefaultClassicFlatnessEpsilon;
};

// Appends the flattened, transformed contours of `path` to `out` (call out.clear() first to
// reuse it). Open contours are closed implicitly, as a filler would; a contour whose last point
// equals its first does not repeat it; a contour that is a lone move (no drawing verb) is dropped.
// Never fails and never allocates without bound:
//  - a contour with a control point that is not finite or exceeds kMaxFlattenCoordinatePx after
//    the transform is dropped whole (a non-finite transform drops every contour);
//  - a curve that would need more than kMaxSegmentsPerCurve segments gets that many;
//  - tolerance_px below kMinFlattenTolerancePx (or NaN) is raised to it.
void flatten(const Path& path, const Affine& transform, const FlattenOptions& options,
             Polylines& out);

// The same, but reports what flatten() tolerates silently, naming the input: a tolerance (or
// ClassicFlatness ε) that is not a finite positive number, a non-finite transform, a point that
// is not finite or too large ("path point 7 is not finite after the transform"), or a curve the
// limits keep from meeting the tolerance ("path verb 12: tolerance not met within
// kMaxSegmentsPerCurve segments"). On error `out` is left as it was on entry.
Status flatten_checked(const Path& path, const Affine& transform, const FlattenOptions& options,
                       Polylines& out);

}  // namespace bezel
#pragma GCC visibility pop
