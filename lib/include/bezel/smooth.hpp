// bezel/smooth.hpp — smooth curves from point sequences (Chaikin, uniform B-splines, natural C²
// splines, Catmull-Rom, Hermite/cardinal) and the continuity analysis of any path's joints.
//
// Every curve comes back as a `Path` of Bézier pieces (cubics, or quadratics for Chaikin's limit),
// converted EXACTLY from the spline's own segment form with the basis data in bezier.hpp, so it
// flattens, rasterizes and intersects like any other path. A curve for n points is one contour:
// open (M C … C) or closed (M C … C Z, the last piece ending exactly on the first point, so
// there is no implicit closing line). Coordinates are the caller's (bezel: y down); nothing here
// depends on the orientation.
//
// Input rules shared by every method (each error message starts with the method's name, then
// names the offending input, e.g. "natural spline: points[3] is not finite (nan, 2)"):
//   - every point (and tangent) must be finite, with coordinates of magnitude at most
//     kMaxSmoothCoordinate;
//   - at most kMaxSmoothPoints points;
//   - each method needs a minimum number of points (stated at the function);
//   - points that all coincide are an error: there is no curve to draw;
//   - for a closed curve, a last point equal (==) to the first is dropped: "0,0 1,0 1,1 0,0
//     --closed" is the same triangle as "0,0 1,0 1,1 --closed".
// What each method does with REPEATED consecutive points is stated at the function.
//
// Parameter convention for derivatives: each piece of a result is parametrised by its own
// t ∈ [0, 1]. "Dᵢ" below are derivatives with respect to the spline's global parameter u
// (uniform: u = i at point i; chord length: u advances by |Pᵢ₊₁ − Pᵢ|); on a piece of parameter
// length h the Bézier derivative is h·D.
#pragma once

#include <cstddef>
#include <vector>

#include "bezel/expected.hpp"
#include "bezel/geometry.hpp"
#include "bezel/limits.hpp"
#include "bezel/path.hpp"

#pragma GCC visibility push(default)  // the public API of libbezel.so (docs/architecture.md)
namespace bezel {

// ---- Chaikin corner cutting ------------------------------------------------------------------
//
// One iteration replaces each edge PᵢPᵢ₊₁ of the polygon by the two points
//     Qᵢ = ¾Pᵢ + ¼Pᵢ₊₁,   Rᵢ = ¼Pᵢ + ¾Pᵢ₊₁          (Chaikin 1974)
// Point counts per iteration: closed n → 2n; open n → 2(n−1), plus the two end points when
// `keep_ends` (then n → 2n). Keeping the ends is the same as cutting the polygon with each end
// point doubled (edge P₀P₀ gives P₀, P₀), which is why the limit with kept ends still starts
// and ends on them.
struct ChaikinOptions {
    bool closed = false;
    bool keep_ends = true;  // open polygons only: keep P₀ and Pₙ₋₁ as the first and last points
};

// The polygon after `iterations` rounds (0 returns the input, closing duplicate dropped).
// Needs ≥ 2 points open, ≥ 3 closed; 0 ≤ iterations ≤ kMaxChaikinIterations; the output size
// must not exceed kMaxChaikinOutputPoints. Repeated points are allowed (they cut to themselves).
Expected<std::vector<Point>> chaikin(const std::vector<Point>& points, int iterations,
                                     const ChaikinOptions& options = {});

// The limit of chaikin() as iterations → ∞: the uniform QUADRATIC B-spline of the polygon, as
// exact quadratic Bézier pieces. Piece i has control point Pᵢ and runs between the edge
// midpoints (Pᵢ₋₁+Pᵢ)/2 and (Pᵢ+Pᵢ₊₁)/2; the curve is C¹ (second derivative jumps at joints).
// Closed: n pieces. Open with keep_ends: the polygon with doubled ends, so n pieces, the first
// and last straight (P₀ to the first midpoint and the last midpoint to Pₙ₋₁). Open without:
// n − 2 pieces from the first midpoint to the last (needs ≥ 3 points).
Expected<Path> chaikin_limit(const std::vector<Point>& points, const ChaikinOptions& options = {});

// ---- Uniform cubic B-spline -----------------------------------------------------------------
//
// Each 4 consecutive de Boor points B₀..B₃ give one cubic piece, converted exactly with
// basis::kBSplineToBezier: (1/6)[1 4 1 0; 0 4 2 0; 0 2 4 0; 0 1 4 1]. The curve is C² and each
// piece lies in the convex hull of its 4 de Boor points; it does not pass through them.
struct BSplineOptions {
    bool closed = false;
    // Open curves only. true: the first and last point are each repeated three times, which
    // pins the curve to them (B₀=B₁=B₂=P gives the Bézier point (P+4P+P)/6 = P); n points
    // give n + 1 pieces, the two end pieces straight. false: the curve starts near the second
    // point and ends near the second to last; n points give n − 3 pieces (needs ≥ 4).
    bool pin_ends = true;
};

// Needs ≥ 2 points open and pinned, ≥ 4 open and unpinned, ≥ 3 closed (n pieces, wrapping).
// Repeated points are allowed: repeating a de Boor point twice sharpens the curve towards it,
// three times makes it pass through it with a corner.
Expected<Path> bspline(const std::vector<Point>& de_boor_points, const BSplineOptions& options = {});

// ---- Natural C² interpolating cubic spline ------------------------------------------------
//
// Interpolates every point C₀..Cₘ with one cubic piece between consecutive points, C² at every
// point. The derivatives Dᵢ solve, for knot spacings hᵢ = uᵢ₊₁ − uᵢ,
//     hᵢ·Dᵢ₋₁ + 2(hᵢ₋₁ + hᵢ)·Dᵢ + hᵢ₋₁·Dᵢ₊₁ = 3(hᵢ·(Cᵢ − Cᵢ₋₁)/hᵢ₋₁ + hᵢ₋₁·(Cᵢ₊₁ − Cᵢ)/hᵢ)
// which for uniform spacing (h = 1) is the course notes' Dᵢ₋₁ + 4Dᵢ + Dᵢ₊₁ = 3(Cᵢ₊₁ − Cᵢ₋₁).
// Open ("natural") ends have zero second derivative: 2D₀ + D₁ = 3(C₁ − C₀)/h₀ and
// Dₘ₋₁ + 2Dₘ = 3(Cₘ − Cₘ₋₁)/hₘ₋₁. Closed curves use the same interior equation cyclically.
// The system is strictly diagonally dominant, solved in O(n) by forward elimination and back
// substitution (Sherman–Morrison for the cyclic one). Each piece is then the Hermite segment
// with tangents hᵢ·Dᵢ, hᵢ·Dᵢ₊₁ (hermite_to_bezier).
enum class SplineParam {
    Uniform,      // uᵢ = i: the notes' equations. Uneven spacing overshoots on the long spans.
    ChordLength,  // uᵢ₊₁ − uᵢ = |Cᵢ₊₁ − Cᵢ|: C² in u, hence only G² piece to piece (each
                  // piece's own t runs at a different speed).
};

struct NaturalSplineOptions {
    bool closed = false;
    SplineParam param = SplineParam::Uniform;
};

// Needs ≥ 2 points open (2 give a straight line), ≥ 3 closed. Two equal consecutive points are
// an error (naming them): chord length would divide by their zero distance, and uniform
// parametrisation would draw a loop through a point visited twice in a row.
Expected<Path> natural_spline(const std::vector<Point>& points,
                              const NaturalSplineOptions& options = {});

// ---- Catmull-Rom -------------------------------------------------------------------------------
//
// Interpolating, local: the piece from Pᵢ to Pᵢ₊₁ depends only on Pᵢ₋₁..Pᵢ₊₂. Knot spacing
// |Pᵢ₊₁ − Pᵢ|^α. With knots t₀..t₃ of the piece's four points, the tangent at P₁ with respect to
// t is (Yuksel, Schaefer, Keyser, "Parameterization and applications of Catmull-Rom curves", 2011)
//     m₁ = (P₁ − P₀)/(t₁ − t₀) − (P₂ − P₀)/(t₂ − t₀) + (P₂ − P₁)/(t₂ − t₁)
// and the piece is the Hermite segment with tangents 2τ·(t₂ − t₁)·m₁, 2τ·(t₂ − t₁)·m₂. For α = 0
// this is exactly basis::catmull_rom(τ) (tangent τ(P₂ − P₀)), and that form is what is used.
// Open ends use reflected phantom points P₋₁ = 2P₀ − P₁ and Pₙ = 2Pₙ₋₁ − Pₙ₋₂.
// Continuity: C¹ for α = 0; for α > 0 the tangent direction is shared but its length scales with
// each piece's knot span, so G¹ (C¹ in the knot parameter).
inline constexpr double kCatmullRomUniform = 0.0;
inline constexpr double kCatmullRomCentripetal = 0.5;  // no cusp or self-intersection in a piece
inline constexpr double kCatmullRomChordal = 1.0;
inline constexpr double kCatmullRomStandardTension = 0.5;

struct CatmullRomOptions {
    bool closed = false;
    double alpha = kCatmullRomCentripetal;          // in [0, 1]
    double tension = kCatmullRomStandardTension;    // τ, finite and ≥ 0 (0: straight pieces)
};

// Needs ≥ 2 distinct points open, ≥ 3 closed. Repeated consecutive points are merged first (the
// curve passes through them once): a zero knot span has no tangent, and the repeat adds nothing.
Expected<Path> catmull_rom(const std::vector<Point>& points, const CatmullRomOptions& options = {});

// ---- Hermite and cardinal splines --------------------------------------------------------------
//
// Piece i runs from Pᵢ to Pᵢ₊₁ with end derivatives tangents[i], tangents[i+1] (dQ/dt of the
// piece, t ∈ [0, 1]), converted with hermite_to_bezier; closed curves add the piece Pₙ₋₁ → P₀.
// C¹ by construction wherever consecutive pieces share a tangent.
//
// Needs ≥ 2 points open, ≥ 3 closed, and exactly one finite tangent per point (after dropping a
// closing duplicate point, its tangent is dropped too). Repeated consecutive points are allowed
// (the piece between them is a loop shaped by the two tangents).
Expected<Path> hermite(const std::vector<Point>& points, const std::vector<Vec2>& tangents,
                       bool closed = false);

// The cardinal-spline tangents τ(Pᵢ₊₁ − Pᵢ₋₁) (basis::catmull_rom's), with reflected phantom
// points at open ends (so τ·2(P₁ − P₀) at P₀). Needs ≥ 2 points open, ≥ 3 closed, and τ finite
// and ≥ 0; repeated points are kept. One tangent per point (after dropping a closing duplicate).
Expected<std::vector<Vec2>> cardinal_tangents(const std::vector<Point>& points, double tension,
                                              bool closed = false);

// hermite(points, cardinal_tangents(points, tension, closed), closed): the uniform Catmull-Rom
// spline of tension τ, with repeated points kept rather than merged.
Expected<Path> cardinal_spline(const std::vector<Point>& points, double tension,
                               bool closed = false);

// ---- Continuity analysis ----------------------------------------------------------------------
//
// A joint is where one segment ends and the next begins: consecutive segments of a contour, and
// for a CLOSED contour (ending in Z) the last segment (the implicit closing line when there is
// one) back to the first. Each segment is viewed as a cubic (PathSeg::to_cubic, exact and
// parameter-preserving), with A the incoming and B the outgoing piece, each on its own t ∈ [0, 1].
// The classes form a chain, and a joint gets the highest whose test AND all lower tests pass:
//   Broken  A(1) ≠ B(0): the pieces do not meet (never within a Path, whose segments share end
//           points; possible for analyze_joints() on loose pieces);
//   C0      they meet;
//   G1      the unit tangents agree: angle(A.tangent(1), B.tangent(0)) ≤ tolerance radians
//           (CubicBez::tangent, so a vanishing derivative uses its limit direction);
//   C1      A′(1) = B′(0);
//   C2      A″(1) = B″(0).
// "=" means |a − b| ≤ tolerance · max(|a|, |b|, L), L the larger control-box diagonal of the two
// pieces (path units): relative to the vectors compared, but never to less than the pieces' size,
// so a second derivative that is zero up to rounding at an inflection is not called a jump.
// So a joint where both derivatives vanish is only as good as its tangent directions (a cusp
// stays C0), and G² (curvature continuity without C²) is reported as G1.
enum class Continuity { Broken, C0, G1, C1, C2 };

// "broken", "C0", "G1", "C1", "C2".
const char* continuity_name(Continuity c);

// The default relative tolerance: splines built here are C² to ~1e-13, so 1e-9 leaves room for
// paths that went through text (17 significant digits) or a few affine maps.
inline constexpr double kDefaultContinuityTolerance = 1e-9;

struct JointReport {
    std::size_t contour = 0;   // path contour (0 for analyze_joints)
    std::size_t incoming = 0;  // segment index of A (PathSeg::index; piece index for analyze_joints)
    std::size_t outgoing = 0;  // segment index of B
    Point point;               // B(0)
    Continuity continuity = Continuity::C0;
    // The measured quantities the class came from, each compared with the tolerance:
    double gap = 0.0;          // |A(1) − B(0)| / L (0 for L = 0)
    double angle_rad = 0.0;    // between the unit tangents, in [0, π]
    double d1_error = 0.0;     // |A′(1) − B′(0)| / max(|A′(1)|, |B′(0)|, L), 0 when all vanish
    double d2_error = 0.0;     // the same for A″(1), B″(0)
};

// One report per joint of `path`, in segment order. Errors: tolerance not finite and > 0, a
// path point that is not finite.
Expected<std::vector<JointReport>> analyze_continuity(
    const Path& path, double tolerance = kDefaultContinuityTolerance);

// The same for a sequence of pieces: joints i → i+1, plus last → first when `closed`.
Expected<std::vector<JointReport>> analyze_joints(
    const std::vector<CubicBez>& pieces, bool closed,
    double tolerance = kDefaultContinuityTolerance);

}  // namespace bezel
#pragma GCC visibility pop
