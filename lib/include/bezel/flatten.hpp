// bezel/flatten.hpp — curves to polylines within a tolerance in pixels.
//
// SKELETON (interface fixed for the rasterizer; the flattening work fills in the methods and the
// proofs of their bounds). Coordinates y down, in the path's units (pixels for rendering).
#pragma once

#include <cstddef>
#include <vector>

#include "bezel/geometry.hpp"
#include "bezel/path.hpp"

namespace bezel {

// Flattened contours, all closed implicitly (a filler joins each last point to its first).
// Reused across calls: flatten() clears and refills it without freeing, so a caller that keeps
// one allocates nothing once it has grown to the largest outline.
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

struct FlattenOptions {
    // Bound on the Hausdorff distance between each curve and its polyline, in output units
    // (pixels when rendering).
    double tolerance_px = 0.1;
    FlattenMethod method = FlattenMethod::WangUniform;
};

// Appends the flattened, transformed contours of `path` to `out` (call out.clear() first to
// reuse it). Open contours are closed implicitly, as a filler would.
void flatten(const Path& path, const Affine& transform, const FlattenOptions& options,
             Polylines& out);

}  // namespace bezel
