// tools/bezel/intersect_output.hpp — what `bezel intersect` reports, and its four renderings.
//
// Coordinates are the paths' own (SVG user units, y down). Segment indices are PathSeg::index
// (the implicit closing line of a closed contour counts as a segment).
#pragma once

#include <string>

#include "bezel/expected.hpp"
#include "bezel/image.hpp"
#include "bezel/intersect.hpp"
#include "bezel/path.hpp"
#include "picture.hpp"

namespace bezel::cli {

struct IntersectReport {
    Path a, b;
    bool self = false;  // one path given: b is unused, the result is a's self-intersections
    PathIntersections result;
};

// Human-readable listing: one line per intersection and per overlap, numbers with 17
// significant digits.
std::string format_intersect_text(const IntersectReport& r);
// The stable JSON contract (keys in this order, numbers with 17 significant digits):
//   {"intersections": [{"seg_a": i, "t_a": t, "seg_b": j, "t_b": t, "x": x, "y": y,
//                       "kind": "cross"|"tangent"|"endpoint"}],
//    "overlaps": [{"seg_a": i, "t_a": [t0, t1], "seg_b": j, "t_b": [t0, t1]}]}
std::string format_intersect_json(const IntersectReport& r);
// Both paths stroked (A blue, B red), overlaps as wide translucent bands, points as rings
// (black: cross, orange: tangent, green: endpoint).
std::string format_intersect_svg(const IntersectReport& r);
// The same picture as a PNG, kIntersectPngSizePx on its longer side, in shades of the ink on the
// paper (picture.hpp; black on white, an 8-bit gray PNG, by default): A full ink, B mid, points
// as rings. Returns the file's bytes.
inline constexpr int kIntersectPngSizePx = 512;
Expected<std::string> format_intersect_png(const IntersectReport& r, const PictureColours& colours,
                                  const PngOptions& png);

}  // namespace bezel::cli
