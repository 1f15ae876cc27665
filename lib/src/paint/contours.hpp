// Private: whether an outline's contours can meet, which decides how its coverage is formed.
#pragma once

#include <vector>

#include "bezel/geometry.hpp"
#include "bezel/path.hpp"

namespace bezel::paint_detail {

// Most contours whose boxes are compared pairwise (O(n²)); an outline with more is taken to have
// contours that meet.
inline constexpr std::size_t kMaxContoursCompared = 64;

// True when two contours of `outline` may share an edge or overlap: the control-point boxes of
// some pair intersect without one containing the other. Disjoint contours (two eyes) and nested
// ones (a ring's hole) are left to plain accumulation, which is exact for them; contours that
// abut or cross are not (painter.cpp says why). `boxes` is scratch, reused.
bool contours_may_meet(const Path& outline, std::vector<Rect>& boxes);

}  // namespace bezel::paint_detail
