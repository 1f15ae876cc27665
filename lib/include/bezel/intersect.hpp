// bezel/intersect.hpp — where lines, quadratic and cubic Bézier curves meet: every crossing
// exactly once, tangencies once, coincident pieces as parameter intervals; for two segments, for
// a cubic against itself, and for whole paths (segment indices as path.hpp numbers them).
//
// Coordinates are the caller's (bezel paths: y down); nothing here depends on which way y points.
//
// What the results promise (ε = 2⁻⁵², "scale" = the largest coordinate magnitude of the inputs,
// measured from an exact local origin, so curves far from (0, 0) lose nothing):
// - Transversal crossings: both parameters to about 1e-12 (a few ulps when the crossing angle is
//   not small), the point on A evaluated at t_a.
// - Tangential contacts (the curves touch within kIntersectTouchTolerance·scale without crossing,
//   or cross at an angle below kTangentSine): reported ONCE, kind Tangent. Where the curvatures
//   differ the parameters are solved from cross(A′, B′) = 0, a simple root: ~1e-12 as well. Where
//   the curvatures are equal (third-order contact) the contact is a multiple root and parameters
//   are good to ~√ε ≈ 1e-8. Two genuine crossings closer than kTangentMergeParam in parameter
//   cannot be told from a tangency at double precision and are reported as one tangent point.
// - Endpoint hits: a parameter that is an endpoint is exactly 0 or 1; an endpoint shared by both
//   curves gives exactly (0|1, 0|1). Kind Endpoint whenever either parameter is 0 or 1.
// - Coincident pieces (the same points traced by both curves over an interval, up to
//   kIntersectOverlapTolerance·scale) are one CurveOverlap each, never a cloud of points; the
//   points where they begin and end are not repeated as intersections.
// - No duplicates: results closer than the accuracies above are merged.
//
// Method (see lib/src/intersect/): dispatch by type. Line–line in closed form; line–curve by
// moving the line onto the x axis and solving the curve's cubic (solve_cubic_in), then Newton
// polishing of both parameters; curve–curve by bounding-box subdivision down to pairs whose
// hodograph cones are disjoint (at most one crossing — Sederberg & Meyers, "Loop detection in
// surface patch intersections", 1988, the "normal cone" test in 2D), where 2D Newton converges,
// and near-tangent leftovers resolved by a signed-distance scan and the tangency equations. An
// overlap test runs first and a merge step last. `intersect_baseline` is the plain recursive
// subdivision of the course notes, kept as the slow oracle for tests and benchmarks.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "bezel/bezier.hpp"
#include "bezel/expected.hpp"
#include "bezel/geometry.hpp"
#include "bezel/limits.hpp"
#include "bezel/path.hpp"

#pragma GCC visibility push(default)  // the public API of libbezel.so (docs/architecture.md)
namespace bezel {

// ---- Limits and tolerances (relative to the inputs' coordinate scale) --------------------------

// Distance below which two curves count as touching, as a fraction of the coordinate scale.
// About 4500 ulps: far above the rounding of de Casteljau evaluation (a few ulps), far below
// anything a drawing can show.
inline constexpr double kIntersectTouchTolerance = 1e-12;
// Distance within which two pieces count as the same curve (an overlap), as a fraction of the
// coordinate scale. Looser than touching so that a sub-curve computed by splitting (rounded
// control points) still matches its parent.
inline constexpr double kIntersectOverlapTolerance = 1e-10;
// A crossing at an angle whose sine is below this is reported as a tangent point.
inline constexpr double kTangentSine = 1e-8;
// Intersection results closer than this in both parameters, where the curves stay within the
// touch tolerance between them, are one tangential contact (√ε, the resolution limit of a
// double root).
inline constexpr double kTangentMergeParam = 1e-7;

// ---- Inputs ------------------------------------------------------------------------------------

// One segment of any kind, by value: a line (degree 1), quadratic (2) or cubic (3) Bézier.
// Converts implicitly from Line, QuadBez and CubicBez, so intersect(line, cubic) just works.
struct Curve {
    int degree = 1;    // 1, 2 or 3; p[0..degree] are used, the rest stay (0, 0)
    Point p[4] = {};

    constexpr Curve() = default;
    constexpr Curve(const Line& c) : degree(1), p{c.p0, c.p1, {}, {}} {}              // NOLINT
    constexpr Curve(const QuadBez& c) : degree(2), p{c.p0, c.p1, c.p2, {}} {}         // NOLINT
    constexpr Curve(const CubicBez& c) : degree(3), p{c.p0, c.p1, c.p2, c.p3} {}      // NOLINT
    explicit Curve(const PathSeg& s);

    Point start() const { return p[0]; }
    Point end() const { return p[degree]; }
    Point eval(double t) const;    // de Casteljau (the Line/QuadBez/CubicBez eval)
    Vec2 deriv_at(double t) const; // dC/dt
    bool is_finite() const;
};

// ---- Results -----------------------------------------------------------------------------------

enum class IntersectionKind : std::uint8_t {
    Cross,     // a transversal crossing
    Tangent,   // a tangential contact (touching, or crossing at an angle below kTangentSine)
    Endpoint,  // t_a or t_b is exactly 0 or 1
};
// "cross", "tangent", "endpoint" (the JSON names).
const char* intersection_kind_name(IntersectionKind kind);

struct CurveIntersection {
    double t_a = 0.0, t_b = 0.0;  // parameters on A and B, in [0, 1]
    Point point;                  // A.eval(t_a)
    IntersectionKind kind = IntersectionKind::Cross;
};

// A coincident piece: A on [t_a0, t_a1] traces the same points as B on [t_b0, t_b1], with
// A(t_a0) = B(t_b0) and A(t_a1) = B(t_b1). t_a0 < t_a1 always; t_b0 > t_b1 when B runs the
// other way.
struct CurveOverlap {
    double t_a0 = 0.0, t_a1 = 0.0;
    double t_b0 = 0.0, t_b1 = 0.0;
};

struct CurveIntersections {
    std::vector<CurveIntersection> points;  // sorted by t_a, then t_b
    std::vector<CurveOverlap> overlaps;     // sorted by t_a0
};

// ---- Segment pairs -----------------------------------------------------------------------------

// Everything where A and B meet. Errors: a NaN or infinite coordinate ("intersect: curve B has a
// non-finite coordinate"), and work beyond kMaxIntersectWork. Degenerate curves (zero length,
// coincident control points) are fine; a curve collapsed to a point meets the other where that
// point lies on it, reported at parameter 0 on the collapsed curve.
Expected<CurveIntersections> intersect(const Curve& a, const Curve& b);

// A cubic's self-intersection: the double point of its loop (at most one, t_a < t_b), including
// one at t = 0 or t = 1. A cubic whose control points are collinear can fold back over itself:
// those stretches are returned as overlaps (t_a0 < t_a1 ≤ t_b1 < t_b0 style pairs). Lines and
// non-degenerate quadratics never self-intersect. Errors: non-finite coordinates.
Expected<CurveIntersections> self_intersect(const Curve& c);

// The course notes' plain recursive subdivision, kept as the slow, obviously-correct oracle:
// split both curves until each piece's control polygon is within `flatness` of its chord (a
// fraction of the coordinate scale), intersect the chords, merge results closer than 1e-7 in
// parameter. No overlap, tangent or endpoint handling: every result has kind Cross. Accuracy is
// ~flatness relative (1e-10 by default → parameters to ~1e-9). Non-finite input is an Error.
Expected<std::vector<CurveIntersection>> intersect_baseline(const Curve& a, const Curve& b,
                                                            double flatness = 1e-10);

// ---- Paths -------------------------------------------------------------------------------------

struct PathIntersection {
    std::size_t seg_a = 0, seg_b = 0;  // PathSeg::index in A and in B (B = A for self)
    double t_a = 0.0, t_b = 0.0;
    Point point;
    IntersectionKind kind = IntersectionKind::Cross;
};

struct PathOverlap {
    std::size_t seg_a = 0, seg_b = 0;
    double t_a0 = 0.0, t_a1 = 0.0, t_b0 = 0.0, t_b1 = 0.0;  // as in CurveOverlap
};

struct PathIntersections {
    std::vector<PathIntersection> intersections;  // sorted by (seg_a, t_a, seg_b, t_b)
    std::vector<PathOverlap> overlaps;            // sorted by (seg_a, t_a0, seg_b)
};

// Every intersection between the segments of A and those of B. A point where one path passes
// from segment i to segment i + 1 (the joint of a contour, including a closed contour's last
// segment into its first) is reported once, on the later segment at t = 0. Errors: non-finite
// points, more than kMaxPathSegmentPairs candidate pairs, more than kMaxPathIntersections
// results, or a segment pair beyond kMaxIntersectWork (the message names the segment indices).
Expected<PathIntersections> intersect_paths(const Path& a, const Path& b);

// Every intersection of a path with itself: between any two of its segments (seg_a < seg_b) and
// each cubic's own loop (seg_a == seg_b, t_a < t_b). The joints where consecutive segments of a
// contour meet are not intersections and are left out; anything else where they meet (a curve
// that comes back to cross its neighbour, a line that doubles back over the previous one) is
// reported. Errors as intersect_paths.
Expected<PathIntersections> self_intersect_path(const Path& path);

}  // namespace bezel
#pragma GCC visibility pop
