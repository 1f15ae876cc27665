// Private to the flatten module: recursive de Casteljau halving without recursion, shared by
// ClassicFlatness, DistanceSubdivision and ParabolaIntegral's repair step.
#pragma once

#include <cstddef>
#include <vector>

#include "bezel/flatten.hpp"
#include "flatten/curve_math.hpp"

namespace bezel::flatten_detail {

// Appends the end points of the pieces of `curve` in order (not its start), halving every piece
// for which `is_flat(piece)` is false. A piece at depth kMaxFlattenDepth, or met when `budget`
// (the number of further pieces allowed) is spent, is emitted as it is. Returns false when that
// happened to a piece that was not flat, i.e. when the criterion was not met everywhere.
//
// Explicit stack instead of recursion: halving pushes the right half then the left, so pieces
// come off left to right; each level adds one entry net, so depth + 1 entries suffice.
template <typename Curve, typename IsFlat>
bool subdivide(const Curve& curve, IsFlat is_flat, std::size_t& budget, std::vector<Point>& out) {
    Curve stack[kMaxFlattenDepth + 1];
    int depth[kMaxFlattenDepth + 1];
    int top = 0;
    stack[0] = curve;
    depth[0] = 0;
    bool met = true;
    while (top >= 0) {
        Curve c = stack[top];
        int d = depth[top];
        --top;
        if (is_flat(c)) {
            out.push_back(end_point(c));
            continue;
        }
        if (d >= kMaxFlattenDepth || budget == 0) {
            met = false;
            out.push_back(end_point(c));
            continue;
        }
        --budget;
        split_half(c, stack[top + 2], stack[top + 1]);
        depth[top + 1] = depth[top + 2] = d + 1;
        top += 2;
    }
    return met;
}

}  // namespace bezel::flatten_detail
