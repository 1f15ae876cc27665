// Rasterizer::fill_paths: a set of fills in one call (raster.hpp states the contract).
//
// Two passes. The validation pass checks every job with the checks fill_path would make, so an
// invalid job is reported before any target is written. The fill pass then runs each job
// through the route fill_path would take, with what fill_path decides per call decided once for
// the set: the options (origin, format, overlap, combine, flattening method and tolerance) are
// dispatched once, and the job's transform and origin are not checked again.
//
// Why the validation pass costs little: it needs each path's control box (its untransformed
// points' min and max, one pass of packed min / max over the points) and the four corners of that
// box under the job's mapping. An affine map is monotone in each coordinate (each product and sum
// rounds monotonically: -ffp-contract=off keeps them unfused and alike everywhere), so every
// mapped point lies within the mapped corners' extremes: the corners being finite and within
// kMaxFlattenCoordinatePx proves every point is, which is the flattener's check. The same box
// gives the edge budget's cheap bound (segment_budget.hpp), the one glyphs always meet.
#include <cmath>
#include <string>
#include <utility>

#include "bezel/raster.hpp"
#include "raster/direct_fill.hpp"
#include "raster/fill_common.hpp"
#include "raster/segment_budget.hpp"
#include "raster/sse2.hpp"

namespace bezel {

namespace {

// Subpixels the LCD filter reads beyond each side of a target (lcd.cpp's kFilterReach): an LCD
// target's samples are this much wider on each side, and must stay within kMaxBitmapDim.
constexpr int kLcdSampleReach = 2;

std::string job_label(std::size_t k) { return "fill_paths: job " + std::to_string(k) + ": "; }

bool in_range(Point p) {
    // Written so NaN fails too.
    return std::fabs(p.x) <= kMaxFlattenCoordinatePx && std::fabs(p.y) <= kMaxFlattenCoordinatePx;
}

// The control box of `pts` (Rect::union_with's values: min and max are exact), and whether every
// coordinate is finite. Packed: one point a vector, two vectors a step for two independent chains.
Rect control_box(const std::vector<Point>& pts, bool& finite) {
    __m128d lo0 = _mm_set1_pd(HUGE_VAL), lo1 = lo0, hi0 = _mm_set1_pd(-HUGE_VAL), hi1 = hi0;
    // x − x is 0 for finite x and NaN for NaN or ±inf, so one unordered test at the end checks
    // every coordinate without a branch in the loop.
    __m128d poison0 = _mm_setzero_pd(), poison1 = poison0;
    const std::size_t n = pts.size();
    std::size_t i = 0;
    for (; i + 1 < n; i += 2) {
        const __m128d p0 = _mm_loadu_pd(&pts[i].x), p1 = _mm_loadu_pd(&pts[i + 1].x);
        lo0 = _mm_min_pd(lo0, p0);
        lo1 = _mm_min_pd(lo1, p1);
        hi0 = _mm_max_pd(hi0, p0);
        hi1 = _mm_max_pd(hi1, p1);
        poison0 = _mm_add_pd(poison0, _mm_sub_pd(p0, p0));
        poison1 = _mm_add_pd(poison1, _mm_sub_pd(p1, p1));
    }
    if (i < n) {
        const __m128d p = _mm_loadu_pd(&pts[i].x);
        lo0 = _mm_min_pd(lo0, p);
        hi0 = _mm_max_pd(hi0, p);
        poison0 = _mm_add_pd(poison0, _mm_sub_pd(p, p));
    }
    const __m128d lo = _mm_min_pd(lo0, lo1), hi = _mm_max_pd(hi0, hi1);
    const __m128d poison = _mm_add_pd(poison0, poison1);
    finite = _mm_movemask_pd(_mm_cmpunord_pd(poison, poison)) == 0;
    alignas(16) double l[2], h[2];
    _mm_store_pd(l, lo);
    _mm_store_pd(h, hi);
    return {l[0], l[1], h[0], h[1]};
}

// fill_path's message for the first point of `path` that `m` maps out of range (the flattener's
// words), found only once the box has shown there is one.
std::string bad_point(const Path& path, const Affine& m) {
    const std::vector<Point>& pts = path.points();
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const Point p = m * pts[i];
        if (in_range(p)) continue;
        return "path point " + std::to_string(i) +
               (std::isfinite(p.x) && std::isfinite(p.y)
                    ? " is beyond 2^50 px from the origin after the transform"
                    : " is not finite after the transform");
    }
    return "a path point is not finite or beyond 2^50 px after the transform";
}

// What fill_path would refuse in job `job` before writing its target; `m` is the mapping its
// flattening sees (the transform with the origin in it, scaled ×3 horizontally in Lcd format).
Status check_job(const FillJob& job, const Affine& m, const FillOptions& options, double tol) {
    if (job.path == nullptr) return Error{"path is null"};
    const MaskView& t = job.target;
    if (options.format == CoverageFormat::Lcd) {
        if (t.width % 3 != 0)
            return Error{"LCD target width " + std::to_string(t.width) +
                         " is not a multiple of 3 (3 bytes per display pixel)"};
        if (t.width > kMaxBitmapDim - 2 * kLcdSampleReach)
            return Error{"LCD target " + std::to_string(t.width) + "x" + std::to_string(t.height) +
                         " is outside 0.." + std::to_string(kMaxBitmapDim - 2 * kLcdSampleReach) +
                         "x" + std::to_string(kMaxBitmapDim) +
                         " (the bitmap limit less the filter's reach)"};
    }
    if (Status s = raster_detail::check_target(t); !s) return s;
    if (!job.origin.is_finite()) return Error{"raster origin is not finite (NaN or infinity)"};
    if (!job.transform.is_finite()) return Error{"transform is not finite"};
    const Path& path = *job.path;
    if (path.points().empty()) return ok_status();
    bool finite = true;
    const Rect box = control_box(path.points(), finite);
    if (!finite) return Error{bad_point(path, m)};
    for (Point c : {Point{box.x0, box.y0}, Point{box.x1, box.y0}, Point{box.x0, box.y1},
                    Point{box.x1, box.y1}})
        if (!in_range(m * c)) return Error{bad_point(path, m)};
    const double estimate = raster_detail::estimate_segments_in_box(path, box, m, tol);
    if (!(estimate <= static_cast<double>(kMaxEdges)))
        return Error{"path would flatten to about " +
                     (std::isfinite(estimate) ? std::to_string(static_cast<long long>(estimate))
                                              : std::string("infinitely many")) +
                     " segments, more than the " + std::to_string(kMaxEdges) + " a fill takes"};
    return ok_status();
}

// The transform with the job's origin in its translation: fill_path's moved_by, the same bits.
Affine placed(const FillJob& job) {
    Affine m = job.transform;
    if (job.origin.x != 0.0 || job.origin.y != 0.0) {
        m.e += job.origin.x;
        m.f += job.origin.y;
    }
    return m;
}

}  // namespace

Status Rasterizer::fill_paths(const FillJob* jobs, std::size_t count, const FillOptions& options,
                              std::size_t* failed_job) {
    const auto fail = [failed_job](std::size_t k, std::string message) {
        if (failed_job != nullptr) *failed_job = k;
        return Error{std::move(message)};
    };
    if (count == 0) return ok_status();
    if (jobs == nullptr)
        return fail(count, "fill_paths: the job array is null with " + std::to_string(count) +
                               " jobs");
    if (options.origin.x != 0.0 || options.origin.y != 0.0)
        return fail(count, "fill_paths: FillOptions::origin must be zero (each FillJob carries "
                           "its origin)");
    const double tol = std::max(options.flatten.tolerance_px, kMinFlattenTolerancePx);
    const bool lcd = options.format == CoverageFormat::Lcd;
    for (std::size_t k = 0; k < count; ++k) {
        const Affine m = lcd ? Affine::scale(3.0, 1.0) * placed(jobs[k]) : placed(jobs[k]);
        if (Status s = check_job(jobs[k], m, options, tol); !s)
            return fail(k, job_label(k) + s.error().message);
    }

    // The plain fill (what glyph atlases ask for): each job tries the direct route and falls back
    // to the general one, as fill_path_impl does, without fill_path's per-call dispatch.
    const FlattenOptions& flatten = options.flatten;
    const bool balanced = flatten.method == FlattenMethod::WangUniform &&
                          flatten.tolerance_px > 0.0 && std::isfinite(flatten.tolerance_px);
    if (balanced && !lcd && options.overlap == OverlapMode::Accumulate &&
        options.combine == CoverageCombine::Replace) {
        const raster_detail::DirectScratch scratch{acc_, flags_, flattened_.points};
        for (std::size_t k = 0; k < count; ++k) {
            const FillJob& job = jobs[k];
            const Affine m = placed(job);
            if (raster_detail::fill_path_direct(*job.path, m, options.rule, job.target, tol,
                                                scratch))
                continue;
            if (Status s = fill_path_general(*job.path, m, options.rule, job.target, flatten); !s)
                return fail(k, job_label(k) + s.error().message);
        }
        return ok_status();
    }
    // Every other combination is fill_path's own, job by job.
    FillOptions o = options;
    for (std::size_t k = 0; k < count; ++k) {
        o.origin = jobs[k].origin;
        if (Status s = fill_path(*jobs[k].path, jobs[k].transform, jobs[k].target, o); !s)
            return fail(k, job_label(k) + s.error().message);
    }
    return ok_status();
}

}  // namespace bezel
