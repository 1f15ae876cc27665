// Rasterizer: input checks, the pixel box the fill can touch, bands, and the sweep into the
// caller's target.
//
// Pipeline for one fill:
//   1. Validate (sizes, contour_ends, finiteness) before touching the target.
//   2. Box = integer bounds of the polygon, intersected with the target. Pixels outside the box
//      get 0 (memset). Left of the box the polygon has nothing; edges left of the TARGET fold
//      into column 0 of the box through the clip (accumulate.hpp).
//   3. The box is processed in bands of rows whose deltas fit in kMaxBandCells floats: walk all
//      edges straight from the point array (no edge list, no per-segment callback), clip to the
//      band, draw deltas; then sweep each band row into the target.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "bezel/raster.hpp"
#include "raster/accumulate.hpp"
#include "raster/fill_common.hpp"
#include "raster/kernels.hpp"
#include "raster/overlap.hpp"
#include "raster/sweep.hpp"

namespace bezel {

namespace rd = raster_detail;

namespace {

Status check_polylines(const Polylines& lines) {
    if (lines.points.size() > kMaxEdges)
        return Error{"polylines have " + std::to_string(lines.points.size()) +
                     " segments, more than the " + std::to_string(kMaxEdges) + " a fill takes"};
    std::size_t prev = 0;
    for (std::size_t end : lines.contour_ends) {
        if (end < prev || end > lines.points.size())
            return Error{"polylines: contour end " + std::to_string(end) +
                         " is out of order or past the " + std::to_string(lines.points.size()) +
                         " points"};
        prev = end;
    }
    if (prev != lines.points.size())
        return Error{"polylines: " + std::to_string(lines.points.size() - prev) +
                     " points after the last contour end"};
    return ok_status();
}

struct Bounds {
    double x0 = HUGE_VAL, y0 = HUGE_VAL, x1 = -HUGE_VAL, y1 = -HUGE_VAL;
    bool finite = true;
};

Bounds bounds_of(const std::vector<Point>& pts) {
    Bounds b;
    // x·0 is 0 for finite x and NaN for NaN or ±inf, so one test at the end checks every point
    // without a branch in the loop.
    double poison = 0.0;
    for (const Point& p : pts) {
        b.x0 = std::min(b.x0, p.x);
        b.x1 = std::max(b.x1, p.x);
        b.y0 = std::min(b.y0, p.y);
        b.y1 = std::max(b.y1, p.y);
        poison += p.x * 0.0 + p.y * 0.0;
    }
    b.finite = poison == 0.0;
    return b;
}

// Every edge of every contour (closing edges included) into one band whose top-left pixel is
// (bx, by) of the target.
void draw_band(const Polylines& lines, Vec2 origin, int bx, int by, const rd::Band& band) {
    const double ox = origin.x - bx, oy = origin.y - by;
    const double W = band.width, H = band.rows;
    const Point* pts = lines.points.data();
    std::size_t start = 0;
    for (std::size_t end : lines.contour_ends) {
        if (end - start < 2) {  // a point contour encloses nothing
            start = end;
            continue;
        }
        double px = pts[end - 1].x + ox, py = pts[end - 1].y + oy;  // closing edge first
        bool p_in = px >= 0.0 && px <= W && py >= 0.0 && py <= H;
        for (std::size_t k = start; k < end; ++k) {
            const double qx = pts[k].x + ox, qy = pts[k].y + oy;
            const bool q_in = qx >= 0.0 && qx <= W && qy >= 0.0 && qy <= H;
            if (p_in && q_in) {
                rd::draw_line(band, px, py, qx, qy);
            } else {
                rd::clip_and_draw_line(band, px, py, qx, qy);
            }
            px = qx;
            py = qy;
            p_in = q_in;
        }
        start = end;
    }
}

}  // namespace

template <typename View>
Status Rasterizer::fill_impl(const Polylines& lines, FillRule rule, const View& target,
                             Vec2 origin) {
    if (Status s = rd::check_target(target); !s) return s;
    if (Status s = check_polylines(lines); !s) return s;
    if (!origin.is_finite()) return Error{"raster origin is not finite (NaN or infinity)"};
    const Bounds b = bounds_of(lines.points);
    if (!b.finite) return Error{"polylines contain a NaN or infinite coordinate"};

    const int W = target.width, H = target.height;
    if (W == 0 || H == 0) return ok_status();

    int bx0 = 0, bx1 = 0, by0 = 0, by1 = 0;
    if (!lines.points.empty()) {
        rd::pixel_range(b.x0, b.x1, origin.x, W, bx0, bx1);
        rd::pixel_range(b.y0, b.y1, origin.y, H, by0, by1);
    }
    if (bx0 >= bx1 || by0 >= by1) {
        bx0 = bx1 = 0;
        by0 = by1 = 0;
    }
    rd::clear_outside_box(target, bx0, bx1, by0, by1);
    if (bx0 >= bx1) return ok_status();

    const int box_w = bx1 - bx0, box_h = by1 - by0;
    const std::ptrdiff_t stride = rd::group_cells(box_w);
    const std::ptrdiff_t flag_stride = rd::row_flag_bytes(box_w);
    // Whole groups per band; at least one always fits.
    static_assert(rd::group_cells(kMaxBitmapDim) <= static_cast<std::ptrdiff_t>(kMaxBandCells));
    const int band_groups = std::max(
        1, std::min(rd::row_groups(box_h), static_cast<int>(kMaxBandCells / static_cast<std::size_t>(stride))));
    const int band_rows = band_groups * rd::kGroupRows;
    const std::size_t cells = static_cast<std::size_t>(band_groups) * static_cast<std::size_t>(stride);
    const std::size_t flags = static_cast<std::size_t>(band_groups) * static_cast<std::size_t>(flag_stride);
    // Grow only; the sweep leaves both all-zero, so no clearing here.
    float* const acc = rd::band_cells(acc_, cells);
    if (flags_.size() < flags) flags_.resize(flags, 0);

    const rd::KernelTable& kernels = rd::kernel_table();
    for (int y = by0; y < by1; y += band_rows) {
        const int rows = std::min(band_rows, by1 - y);
        const rd::Band band{acc, flags_.data(), stride, flag_stride, box_w, rows,
                            kernels.steep};
        draw_band(lines, origin, bx0, y, band);
        rd::sweep_marked_band(*kernels.sweep, rule, band, target.row(y) + bx0, target.stride);
    }
    return ok_status();
}

// path_fill.cpp calls these.
template Status Rasterizer::fill_impl<MaskView>(const Polylines&, FillRule, const MaskView&, Vec2);
template Status Rasterizer::fill_impl<FloatMaskView>(const Polylines&, FillRule,
                                                     const FloatMaskView&, Vec2);

// Out of line: FeatureScratch is complete only here (overlap.hpp).
Rasterizer::Rasterizer() = default;
Rasterizer::~Rasterizer() = default;
Rasterizer::Rasterizer(Rasterizer&&) noexcept = default;
Rasterizer& Rasterizer::operator=(Rasterizer&&) noexcept = default;

Rasterizer::FeatureScratch& Rasterizer::features() {
    if (!features_) features_ = std::make_unique<FeatureScratch>();
    return *features_;
}

namespace {

// What fill (polylines) does not implement, named; null when the options are fine.
const char* unsupported_for_polylines(const FillOptions& options) {
    if (options.overlap != OverlapMode::Accumulate)
        return "fill: OverlapMode::Accurate is not implemented for polylines (fill_path resolves "
               "overlaps)";
    if (options.format != CoverageFormat::Gray)
        return "fill: CoverageFormat::Lcd is not implemented for polylines (fill_path into a "
               "MaskView renders LCD coverage)";
    return nullptr;
}

}  // namespace

Status Rasterizer::fill(const Polylines& lines, const MaskView& target,
                        const FillOptions& options) {
    if (const char* why = unsupported_for_polylines(options)) return Error{why};
    if (options.combine != CoverageCombine::Replace) return fill_combined(lines, target, options);
    return fill_impl(lines, options.rule, target, options.origin);
}

Status Rasterizer::fill(const Polylines& lines, const FloatMaskView& target,
                        const FillOptions& options) {
    if (const char* why = unsupported_for_polylines(options)) return Error{why};
    if (options.combine != CoverageCombine::Replace) return fill_combined(lines, target, options);
    return fill_impl(lines, options.rule, target, options.origin);
}

std::size_t Rasterizer::scratch_capacity_bytes() const {
    return acc_.capacity() * sizeof(float) + flags_.capacity() +
           flattened_.points.capacity() * sizeof(Point) +
           flattened_.contour_ends.capacity() * sizeof(std::size_t);
}

}  // namespace bezel
