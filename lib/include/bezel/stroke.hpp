// bezel/stroke.hpp — the outline of a stroked path: joins, caps, dashes, offset curves.
//
// Coordinates are the path's own (pixels when rendering), y down. The result is a closed Path that
// fills correctly with FillRule::NonZero (its pieces may overlap; non-zero unions them). Curved
// pieces are offset by cubic approximations whose distance from the true offset curve is at most
// `tolerance` (checked by sampling in the tests); cusps and curvature tighter than the half-width
// are handled without spikes or holes (method at the implementation: lib/src/stroke/outline.cpp).
// Every piece of the result winds the same way (negative Path::signed_area), so non-zero never
// cancels one against another; a renderer that accumulates coverage may over-darken edge pixels
// where pieces overlap — Rasterizer's OverlapMode::Accurate resolves that exactly.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "bezel/expected.hpp"
#include "bezel/geometry.hpp"
#include "bezel/limits.hpp"
#include "bezel/path.hpp"

#pragma GCC visibility push(default)  // the public API of libbezel.so (docs/architecture.md)
namespace bezel {

enum class LineJoin : std::uint8_t { Miter, Round, Bevel };
enum class LineCap : std::uint8_t { Butt, Round, Square };

struct StrokeStyle {
    double width = 1;                  // full width, > 0, in path units
    LineJoin join = LineJoin::Miter;
    double miter_limit = 4;            // SVG's: miter length / width; beyond it a bevel, ≥ 1
    LineCap cap = LineCap::Butt;
    std::vector<double> dashes;        // on/off lengths (SVG stroke-dasharray); empty = solid;
                                       // an odd count repeats as SVG does
    double dash_offset = 0;            // SVG stroke-dashoffset
    double tolerance = 0.01;           // max distance of the result from the exact stroke outline
                                       // (raised to 1e-12 of the geometry's size if below it)
};

// The stroke outline of `path`. Open contours get caps at both ends; closed contours get a join
// where they close and no caps. A zero-length contour with a Round or Square cap becomes a dot
// (as SVG); with Butt nothing. Errors: a non-finite coordinate, width ≤ 0 or not finite, a
// negative or all-zero dash pattern, miter_limit < 1, tolerance ≤ 0, a result past
// kMaxStrokeSegments or kMaxDashes.
Expected<Path> stroke(const Path& path, const StrokeStyle& style);

// Only the dashing: the "on" pieces of `path` as open contours (so stroke() of the result with no
// dashes equals stroke() with them). Errors as stroke().
Expected<Path> dash(const Path& path, const std::vector<double>& dashes, double dash_offset);

}  // namespace bezel
#pragma GCC visibility pop
