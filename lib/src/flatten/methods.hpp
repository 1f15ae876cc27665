// Private to the flatten module: one function per method and curve degree.
//
// Each appends the polyline vertices that replace the curve *after* its start point (which the
// caller has already emitted), the last one being the curve's end point, copied exactly. Each
// returns false when a limit (kMaxFlattenDepth, kMaxSegmentsPerCurve) kept it from meeting its
// criterion; the points are still a valid polyline from start to end.
// Preconditions: control points finite and within kMaxFlattenCoordinatePx; tolerance_px ≥
// kMinFlattenTolerancePx; epsilon > 0.
#pragma once

#include <vector>

#include "bezel/bezier.hpp"
#include "bezel/geometry.hpp"

namespace bezel::flatten_detail {

bool classic_flatness(const QuadBez& q, double epsilon, std::vector<Point>& out);
bool classic_flatness(const CubicBez& c, double epsilon, std::vector<Point>& out);

bool distance_subdivision(const QuadBez& q, double tolerance_px, std::vector<Point>& out);
bool distance_subdivision(const CubicBez& c, double tolerance_px, std::vector<Point>& out);

bool wang_uniform(const QuadBez& q, double tolerance_px, std::vector<Point>& out);
bool wang_uniform(const CubicBez& c, double tolerance_px, std::vector<Point>& out);

bool parabola_integral(const QuadBez& q, double tolerance_px, std::vector<Point>& out);
bool parabola_integral(const CubicBez& c, double tolerance_px, std::vector<Point>& out);

// Wang's segment counts (see wang_uniform.cpp), exposed for the tests.
double wang_quad_count(const QuadBez& q, double tolerance_px);
double wang_cubic_count(const CubicBez& c, double tolerance_px);

}  // namespace bezel::flatten_detail
