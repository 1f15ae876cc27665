// Rasterizer::fill_path: the options are dispatched (origin, coverage format, overlap mode), the
// path is flattened into reused polylines and filled. The only new concern of the plain route is
// the edge budget: a path under a huge scale would flatten into millions of segments, so the
// count is bounded BEFORE flattening allocates anything.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "bezel/raster.hpp"
#include "raster/direct_fill.hpp"
#include "raster/fill_common.hpp"
#include "raster/overlap.hpp"
#include "raster/render_flatten.hpp"

namespace bezel {

namespace {

// The tolerance in a message: "%g" (6 significant digits), not std::to_string's "%f".
std::string tolerance_text(double px) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%g", px);
    return buf;
}

// Wang's formula: a Bézier of degree d flattened into n uniform steps deviates at most
// d(d−1)/8 · M / n² from its polyline, M = max |Pᵢ − 2Pᵢ₊₁ + Pᵢ₊₂| (second differences of the
// control points), so n = ⌈√(d(d−1)·M / (8·tol))⌉ steps suffice. Every flattening method meets
// its tolerance with about this many segments or fewer (the uniform method uses exactly this),
// so it is the estimate the budget is checked against.
double wang_segments(const Point* p, int degree, const Affine& m, double tol) {
    double max_dd = 0.0;
    for (int i = 0; i + 2 <= degree; ++i) {
        Vec2 dd = m.apply_vector(p[i] - 2.0 * p[i + 1] + p[i + 2]);
        max_dd = std::max(max_dd, std::sqrt(dd.length_squared()));  // hypot is slow, range is not an issue
    }
    const double n = std::ceil(std::sqrt(degree * (degree - 1) * max_dd / (8.0 * tol)));
    // A NaN control point is flatten_checked's to report, with its index; count it as one.
    return std::isnan(n) ? 1.0 : n;
}

// Estimated segments of the flattened path, saturating: the caller only compares with kMaxEdges.
double estimate_segments(const Path& path, const Affine& m, double tol) {
    const std::vector<Point>& pts = path.points();
    // Cheap bound first. Every control point lies in the control box, of diagonal D after the
    // transform, so each second difference is ≤ 2D (two steps each ≤ D), and a cubic — the worse
    // degree — needs at most ⌈√(6·2D / (8·tol))⌉ = ⌈√(1.5·D/tol)⌉ steps. If even every verb at
    // that count fits, skip the per-curve pass (always, for glyphs).
    Rect box = Rect::empty();
    for (const Point& p : pts) box = box.union_with(p);
    if (!pts.empty()) {
        Rect tb = Rect::empty();
        for (Point c : {Point{box.x0, box.y0}, Point{box.x1, box.y0}, Point{box.x0, box.y1},
                        Point{box.x1, box.y1}})
            tb = tb.union_with(m * c);
        const double diag = std::sqrt(tb.width() * tb.width() + tb.height() * tb.height());
        const double worst = static_cast<double>(path.verbs().size()) *
                             (std::ceil(std::sqrt(1.5 * diag / tol)) + 1.0);
        if (worst <= static_cast<double>(kMaxEdges)) return worst;
    }
    std::size_t pi = 0;
    double total = 0.0;
    const double per_curve_cap = static_cast<double>(kMaxSegmentsPerCurve);
    for (Verb v : path.verbs()) {
        switch (v) {
            case Verb::Move: total += 1; pi += 1; break;
            case Verb::Line: total += 1; pi += 1; break;
            case Verb::Quad:
                total += std::min(per_curve_cap, std::max(1.0, wang_segments(&pts[pi - 1], 2, m, tol)));
                pi += 2;
                break;
            case Verb::Cubic:
                total += std::min(per_curve_cap, std::max(1.0, wang_segments(&pts[pi - 1], 3, m, tol)));
                pi += 3;
                break;
            case Verb::Close: total += 1; break;
        }
        if (!(total <= static_cast<double>(kMaxEdges))) return total;  // NaN counts as too many
    }
    return total;
}

}  // namespace

template <typename View>
Status Rasterizer::fill_path_impl(const Path& path, const Affine& transform, FillRule rule,
                                  const View& target, const FlattenOptions& options) {
    if (!transform.is_finite()) return Error{"fill_path: transform is not finite"};
    const double tol = raster_detail::flatten_tolerance(options);
    const bool balanced = raster_detail::balanced_flattening(options);
    // The direct route (direct_fill.hpp) for glyph-like fills; false means it left the target
    // alone and the general route below runs.
    if (balanced && raster_detail::fill_path_direct(path, transform, rule, target, tol,
                                                    {acc_, flags_, flattened_.points}))
        return ok_status();
    return fill_path_general(path, transform, rule, target, options);
}

template <typename View>
Status Rasterizer::fill_path_general(const Path& path, const Affine& transform, FillRule rule,
                                     const View& target, const FlattenOptions& options) {
    const double tol = raster_detail::flatten_tolerance(options);
    const bool balanced = raster_detail::balanced_flattening(options);
    const double estimate = estimate_segments(path, transform, tol);
    if (!(estimate <= static_cast<double>(kMaxEdges)))
        return Error{"fill_path: path would flatten to about " +
                     (std::isfinite(estimate) ? std::to_string(static_cast<long long>(estimate))
                                              : std::string("infinitely many")) +
                     " segments at tolerance " + tolerance_text(options.tolerance_px) +
                     " px, more than the " + std::to_string(kMaxEdges) + " a fill takes"};
    flattened_.clear();
    // WangUniform (the default) goes through the balanced flattener (render_flatten.hpp): same
    // step count, vertices moved so each chord has zero mean area error. Anything it does not
    // take (huge or non-finite points, a curve past the step cap) goes to flatten_checked, which
    // names the problem.
    if (balanced && raster_detail::flatten_balanced(path, transform, tol, flattened_))
        return fill_impl(flattened_, rule, target, Vec2{});
    flattened_.clear();
    if (Status s = flatten_checked(path, transform, options, flattened_); !s)
        return Error{"fill_path: " + s.error().message};
    return fill_impl(flattened_, rule, target, Vec2{});
}

// Gray (or float) coverage with the chosen overlap handling. The plain fill checks every input,
// bounds the edges and writes every pixel; for OverlapMode::Accurate the exact pass then
// rewrites the rows it covers.
template <typename View>
Status Rasterizer::fill_path_gray(const Path& path, const Affine& transform, const View& target,
                                  const FillOptions& options) {
    if (Status st = fill_path_impl(path, transform, options.rule, target, options.flatten); !st)
        return st;
    if (options.overlap == OverlapMode::Accumulate) return ok_status();
    raster_detail::fill_region_exact(path, transform, options.rule, options.flatten, target,
                                     features().overlap);
    return ok_status();
}

// fill_set.cpp fills the jobs the direct route refuses through this.
template Status Rasterizer::fill_path_general<MaskView>(const Path&, const Affine&, FillRule,
                                                        const MaskView&, const FlattenOptions&);

// lcd.cpp samples through these, combine.cpp fills its scratch through them.
template Status Rasterizer::fill_path_gray<FloatMaskView>(const Path&, const Affine&,
                                                          const FloatMaskView&, const FillOptions&);
template Status Rasterizer::fill_path_gray<MaskView>(const Path&, const Affine&, const MaskView&,
                                                     const FillOptions&);

namespace {

constexpr char kOriginNotFinite[] = "raster origin is not finite (NaN or infinity)";

}  // namespace

Status Rasterizer::fill_path(const Path& path, const Affine& transform, const MaskView& target,
                             const FillOptions& options) {
    if (!options.origin.is_finite()) return Error{kOriginNotFinite};
    const Affine m = raster_detail::moved_by(transform, options.origin);
    if (options.combine != CoverageCombine::Replace)
        return fill_path_combined(path, m, target, options);
    if (options.format == CoverageFormat::Lcd) return fill_path_lcd(path, m, target, options);
    return fill_path_gray(path, m, target, options);
}

Status Rasterizer::fill_path(const Path& path, const Affine& transform,
                             const FloatMaskView& target, const FillOptions& options) {
    if (options.format != CoverageFormat::Gray)
        return Error{"fill_path: CoverageFormat::Lcd is not implemented for a float target (LCD "
                     "coverage is written as bytes into a MaskView)"};
    if (!options.origin.is_finite()) return Error{kOriginNotFinite};
    if (options.combine != CoverageCombine::Replace)
        return fill_path_combined(path, raster_detail::moved_by(transform, options.origin), target, options);
    return fill_path_gray(path, raster_detail::moved_by(transform, options.origin), target, options);
}

}  // namespace bezel
