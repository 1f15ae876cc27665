// Private: the edge budget of fill_path (path_fill.cpp), shared with fill_paths (fill_set.cpp),
// whose validation pass applies it to every job before any target is written.
#pragma once

#include "bezel/geometry.hpp"
#include "bezel/path.hpp"

namespace bezel::raster_detail {

// Segments `path` mapped by `m` would flatten to at tolerance `tol` (px, > 0), estimated by
// Wang's bound and saturating: the callers only compare it with kMaxEdges (NaN counts as too
// many). A cheap bound from the control box first, the per-curve bound when that one fails.
double estimate_segments(const Path& path, const Affine& m, double tol);
// The same with the path's control box (of its untransformed points) already known.
double estimate_segments_in_box(const Path& path, const Rect& box, const Affine& m, double tol);

}  // namespace bezel::raster_detail
