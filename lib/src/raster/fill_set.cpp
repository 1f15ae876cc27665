// Rasterizer::fill_paths: a set of fills in one call (raster.hpp states the contract).
//
// Two passes. The validation pass checks what each job brings besides its path (the path
// pointer, the target, the transform and origin) before any target is written. The fill pass
// runs each job through the route fill_path would take, with what fill_path decides per call
// decided once for the set: the options (origin, format, overlap, combine, flattening method
// and tolerance) are dispatched once, and the job's transform and origin are not checked again.
//
// The path's own points are not checked in the validation pass: proving them finite and within
// kMaxFlattenCoordinatePx takes a pass over every point, a sizeable share of a small glyph's
// fill (docs/perf-log.md), and the fill already makes that proof as it goes (the direct
// route's box pass refuses a path its target does not hold, the general route reports it
// before writing). So a bad path stops the set at its job, the jobs before it written.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "bezel/raster.hpp"
#include "raster/direct_fill.hpp"
#include "raster/fill_common.hpp"

namespace bezel {

namespace {

std::string job_label(std::size_t k) { return "fill_paths: job " + std::to_string(k) + ": "; }

// What fill_path would refuse in job `job` before looking at its path, or ok.
Status check_job(const FillJob& job, const FillOptions& options) {
    if (job.path == nullptr) return Error{"path is null"};
    if (Status s = options.format == CoverageFormat::Lcd ? raster_detail::check_lcd_target(job.target)
                                                         : raster_detail::check_target(job.target);
        !s)
        return s;
    if (!job.origin.is_finite()) return Error{"raster origin is not finite (NaN or infinity)"};
    if (!job.transform.is_finite()) return Error{"transform is not finite"};
    return ok_status();
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
    for (std::size_t k = 0; k < count; ++k) {
        if (Status s = check_job(jobs[k], options); !s)
            return fail(k, job_label(k) + s.error().message);
    }

    // The plain fill (what glyph atlases ask for): each job tries the direct route and falls back
    // to the general one, as fill_path_impl does, without fill_path's per-call dispatch.
    const FlattenOptions& flatten = options.flatten;
    const double tol = raster_detail::flatten_tolerance(flatten);
    const bool lcd = options.format == CoverageFormat::Lcd;
    const bool balanced = raster_detail::balanced_flattening(flatten);
    if (balanced && !lcd && options.overlap == OverlapMode::Accumulate &&
        options.combine == CoverageCombine::Replace) {
        const raster_detail::DirectScratch scratch{acc_, flags_, flattened_.points};
        for (std::size_t k = 0; k < count; ++k) {
            const FillJob& job = jobs[k];
            const Affine m = raster_detail::moved_by(job.transform, job.origin);
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
