// stroke/stroke_internal.hpp — the pieces stroke() is assembled from: offset curves, tight-curve
// splitting, arcs, and the per-contour outline builder.
//
// Notation used throughout the stroke module. A source curve C(t) has unit tangent T(t) and unit
// normal N(t) = T.perp(); signed curvature κ = (C′ × C″)/|C′|³, so the centre of curvature is
// C + N/κ. The stroke of width 2h is the image of
//     F(t, s) = C(t) + s·N(t),   t ∈ [0, 1],  s ∈ [−h, h],
// whose Jacobian is |C′|·(1 − s·κ): it folds where s·κ > 1, i.e. on the side of the centre of
// curvature where the radius 1/|κ| is below h ("tight" curvature). The "left" side offset is
// s = +h, the "right" side s = −h.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "bezel/bezier.hpp"
#include "bezel/path.hpp"
#include "bezel/stroke.hpp"

namespace bezel::stroke_detail {

// Counts emitted output segments against kMaxStrokeSegments; once exceeded, producers stop early
// and stroke() reports an Error.
struct Budget {
    std::size_t used = 0;
    std::size_t limit = kMaxStrokeSegments;
    bool exceeded() const { return used > limit; }
    bool take(std::size_t n) {
        used += n;
        return !exceeded();
    }
};

// Appends to `out` cubics approximating the offset C(t) + d·N(t) of `c` over t ∈ [0, 1], each
// within `tol` of the true offset (measured along the source normals, see offset.cpp). The first
// cubic starts exactly at C(0) + d·N(0), the last ends exactly at C(1) + d·N(1). Precondition:
// `c` has no cusp inside (0, 1) and 1 − d·κ keeps one sign on (0, 1) (split_cubic gives such
// pieces).
void offset_cubic(const CubicBez& c, double d, double tol, Budget& budget,
                  std::vector<CubicBez>& out);

// A cusp-free piece of a source cubic, over its own parameter range [0, 1].
struct CurvePiece {
    CubicBez c;
    bool tight = false;    // |κ|·h > 1 throughout: the side `sigma` folds
    int sigma = 0;         // sign of κ on a tight piece: the inner offset is s = sigma·h
    bool cusp_before = false;  // the piece starts at a cusp of the source curve
};

// Splits `c` at its speed minima (cutting out the window of a (near-)cusp, see split.cpp) and
// where |κ|·h = 1, dropping pieces of no extent. `size` is the scale of the input (for the
// relative thresholds), `tol` the stroke's tolerance.
void split_cubic(const CubicBez& c, double h, double size, double tol,
                 std::vector<CurvePiece>& out);

// Appends cubic arcs of the circle around `center` with radius r from the current point (which
// must be center + r·from) to center + r·to, turning the short way (|angle| ≤ π; pass an
// intermediate direction to go further). Each arc is within `tol` of the circle.
void arc_to(Path& path, Point center, Vec2 from, Vec2 to, double r, double tol, Budget& budget);

// Appends the evolute C + N/κ of a tight piece, from t = 1 back to t = 0, as lines within `tol`
// (the line_to of its first point included).
void evolute_back(Path& path, const CubicBez& c, double tol, Budget& budget);

// What one contour of the (already dashed) source path becomes: appended to `out`.
struct ContourInput {
    Point start;                // the Move's point
    std::vector<PathSeg> segs;  // the contour's segments, zero-length ones included
    bool closed = false;
};
void stroke_contour(const ContourInput& contour, const StrokeStyle& style, double tol,
                    double size, Budget& budget, Path& out);

// The contours of `path` in order, each with its segments (as Path::segments() yields them,
// closing line included) — also contours without segments.
std::vector<ContourInput> contours_of(const Path& path);

// dash() with a bound on what the caller makes of the dashes: with segments_per_dash > 0, a
// pattern whose dashes (those of positive length, or all when count_empty) times
// segments_per_dash would pass max_segments is an Error before any dash is made.
struct DashLimit {
    std::size_t segments_per_dash = 0;  // output verbs per dash at least; 0: only kMaxDashes
    std::size_t max_segments = 0;
    bool count_empty = true;  // zero-length dashes make output too (round or square caps)
};
Expected<Path> dash_limited(const Path& path, const std::vector<double>& dashes,
                            double dash_offset, const DashLimit& limit);

// Checks a dash pattern and offset; the message names the bad value.
Status check_dashes(const std::vector<double>& dashes, double dash_offset);

// "%g" of a number, for messages.
std::string num(double v);

// Copies every contour of `src` to the end of `dst`.
void append_path(Path& dst, const Path& src);

}  // namespace bezel::stroke_detail
