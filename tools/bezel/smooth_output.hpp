// tools/bezel/smooth_output.hpp — what `bezel smooth` and `bezel continuity` read and print.
//
// Coordinates are the caller's own (SVG user units, y down), printed so that they read back to
// the same doubles (JSON through nlohmann's shortest round-trip form, SVG path data through
// to_svg_path at 17 digits).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "bezel/expected.hpp"
#include "bezel/image.hpp"
#include "bezel/path.hpp"
#include "bezel/smooth.hpp"
#include "picture.hpp"

namespace bezel::cli {

// ---- Input -------------------------------------------------------------------------------------

// Largest --points-file read, in bytes: room for ~2 million points as text, more than
// kMaxSmoothPoints, so the library's limit is the one a user meets.
inline constexpr std::size_t kMaxPointsFileBytes = std::size_t{64} << 20;

// "x,y x,y …": numbers separated by commas and/or whitespace, taken in pairs (so "1,2 3,4" and
// "1 2 3 4" are the same). Errors name `what` (e.g. "--points") and the bad token's position:
// a token that is not a finite number, an odd count of numbers.
Expected<std::vector<Vec2>> parse_vec2_list(std::string_view text, const std::string& what);

// The JSON `bezel smooth` writes for a polyline, {"points": [[x, y], …]}, or a bare array
// [[x, y], …]. Errors name `what` and the entry at fault.
Expected<std::vector<Vec2>> parse_points_json(std::string_view text, const std::string& what);

// Reads a points file ("-" is stdin): JSON when its first non-blank character is '{' or '[',
// else the text form. Errors name the file.
Expected<std::vector<Vec2>> read_points_file(const std::string& file);

// ---- Output ------------------------------------------------------------------------------------

struct SmoothReport {
    std::string method;          // as given to --method, for titles
    std::vector<Point> input;    // the points as given
    bool closed = false;
    bool polyline = false;       // Chaikin without --limit: `points` is the result, `curve` unused
    std::vector<Point> points;   // Chaikin's polygon
    Path curve;                  // every other method
};

// The stable JSON contract:
//   curve:    {"segments": [[[x,y],[x,y],[x,y],[x,y]], …]}  every piece as cubic control points
//             (lines and quadratics elevated exactly), in path order;
//   polyline: {"points": [[x,y], …]}                         readable back with --points-file.
std::string format_smooth_json(const SmoothReport& r);
// SVG path data: the curve (to_svg_path), or the polyline as M … L … (Z when closed).
std::string format_smooth_path(const SmoothReport& r);
// The input points (red dots, numbered), the input polygon (gray, dashed), each cubic piece's
// Bézier handles (purple) and the result (blue).
std::string format_smooth_svg(const SmoothReport& r);
// The same picture as a PNG, kSmoothPngSizePx on its longer side, drawn by bezel's rasterizer in
// shades of the ink on the paper (picture.hpp; black on white, an 8-bit gray PNG, by default):
// result full ink, input polygon mid, handles light, points dark dots. Returns the file's bytes.
inline constexpr int kSmoothPngSizePx = 512;
Expected<std::string> format_smooth_png(const SmoothReport& r, const PictureColours& colours,
                                  const PngOptions& png);

// `bezel continuity`: one line per joint, or the JSON
//   {"tolerance": t, "joints": [{"contour": c, "incoming": i, "outgoing": j, "point": [x, y],
//     "class": "C0"|"G1"|"C1"|"C2"|"broken", "gap": g, "angle_rad": a, "d1_error": e1,
//     "d2_error": e2}, …]}
std::string format_continuity_text(const std::vector<JointReport>& joints, double tolerance);
std::string format_continuity_json(const std::vector<JointReport>& joints, double tolerance);

}  // namespace bezel::cli
