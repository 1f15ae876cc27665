// Input checks shared by every smoothing method (the rules at the top of smooth.hpp), so each
// method's file starts from points it may trust.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "bezel/expected.hpp"
#include "bezel/geometry.hpp"

namespace bezel::smooth_detail {

// "(1.5, nan)" with up to 17 significant digits, for error messages.
std::string format_point(Point p);

// Error{"<method>: <what>"}.
Error method_error(const char* method, const std::string& what);

// Validates `points` for `method` and returns the points to use:
//   - more than kMaxSmoothPoints → error (checked before anything else is read);
//   - a point that is not finite or beyond kMaxSmoothCoordinate → error naming its index and value;
//   - closed: a last point == the first is dropped;
//   - fewer than `min_open` (open) or `min_closed` (closed) points → error;
//   - all points equal → error.
Expected<std::vector<Point>> prepare_points(const char* method, const std::vector<Point>& points,
                                            bool closed, std::size_t min_open,
                                            std::size_t min_closed);

// Removes consecutive duplicates (by ==), and for a closed sequence a last point equal to the
// first. The result keeps the first of each run.
std::vector<Point> merge_repeats(const std::vector<Point>& points, bool closed);

// `v` (entry `index` of the input called `what`, e.g. "tangents") is finite and within
// kMaxSmoothCoordinate.
Status check_vector(const char* method, const char* what, std::size_t index, Vec2 v);

// The count check of prepare_points alone (used again after merging).
Status check_count(const char* method, std::size_t count, bool closed, std::size_t min_open,
                   std::size_t min_closed);

}  // namespace bezel::smooth_detail
