// Private: the steps every fill route shares once it knows its pixel box — clearing the target
// outside the box, and sweeping one band row into the target.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "bezel/raster.hpp"
#include "raster/accumulate.hpp"
#include "raster/sweep.hpp"

namespace bezel::raster_detail {

// A target every fill accepts: within kMaxBitmapDim a side, with memory when not empty. The
// error names the size.
template <typename View>
Status check_target(const View& t) {
    if (t.width < 0 || t.height < 0 || t.width > kMaxBitmapDim || t.height > kMaxBitmapDim)
        return Error{"raster target " + std::to_string(t.width) + "x" + std::to_string(t.height) +
                     " is outside 0.." + std::to_string(kMaxBitmapDim) + " px a side"};
    if (t.data == nullptr && t.width > 0 && t.height > 0)
        return Error{"raster target " + std::to_string(t.width) + "x" + std::to_string(t.height) +
                     " has no pixel memory (null data)"};
    return ok_status();
}

// Subpixels the LCD filter (lcd.cpp, five taps) reads beyond each side of a target: an LCD
// fill samples a target this much wider on each side, which must stay within kMaxBitmapDim.
inline constexpr int kLcdFilterReach = 2;

// An LCD target every fill accepts: its samples within kMaxBitmapDim, whole display pixels of
// 3 bytes, memory when not empty. The errors name the size.
inline Status check_lcd_target(const MaskView& t) {
    const int W = t.width, H = t.height;
    if (W < 0 || H < 0 || W > kMaxBitmapDim - 2 * kLcdFilterReach || H > kMaxBitmapDim)
        return Error{"LCD target " + std::to_string(W) + "x" + std::to_string(H) +
                     " is outside 0.." + std::to_string(kMaxBitmapDim - 2 * kLcdFilterReach) +
                     "x" + std::to_string(kMaxBitmapDim) +
                     " (the bitmap limit less the filter's reach)"};
    if (W % 3 != 0)
        return Error{"LCD target width " + std::to_string(W) +
                     " is not a multiple of 3 (3 bytes per display pixel)"};
    if (t.data == nullptr && W > 0 && H > 0)
        return Error{"LCD target " + std::to_string(W) + "x" + std::to_string(H) +
                     " has no pixel memory (null data)"};
    return ok_status();
}

// The tolerance a fill flattens with (at least kMinFlattenTolerancePx), and whether it takes
// the balanced walk (render_flatten.hpp): WangUniform at a positive, finite tolerance.
inline double flatten_tolerance(const FlattenOptions& o) {
    return std::max(o.tolerance_px, kMinFlattenTolerancePx);
}
inline bool balanced_flattening(const FlattenOptions& o) {
    return o.method == FlattenMethod::WangUniform && o.tolerance_px > 0.0 &&
           std::isfinite(o.tolerance_px);
}

// `transform` with `origin` folded into its translation, so a path filled with an origin gives
// the bits of the same path under the moved transform. A zero origin leaves it as it is.
inline Affine moved_by(const Affine& transform, Vec2 origin) {
    Affine m = transform;
    if (origin.x != 0.0 || origin.y != 0.0) {
        m.e += origin.x;
        m.f += origin.y;
    }
    return m;
}

// Integer pixel range [lo, hi) of [a, b] + offset clamped to [0, n]. Computed in double: a
// coordinate of 1e300 clamps before any conversion to int.
inline void pixel_range(double a, double b, double offset, int n, int& lo, int& hi) {
    const double fa = std::floor(a + offset), fb = std::ceil(b + offset);
    lo = static_cast<int>(std::clamp(fa, 0.0, static_cast<double>(n)));
    hi = static_cast<int>(std::clamp(fb, 0.0, static_cast<double>(n)));
}

template <typename T>
inline void clear_pixels(T* p, int n) {
    if (n > 0) std::memset(p, 0, sizeof(T) * static_cast<std::size_t>(n));
}

// Writes 0 to every pixel of `target` outside the box [bx0, bx1) × [by0, by1).
template <typename View>
void clear_outside_box(const View& target, int bx0, int bx1, int by0, int by1) {
    for (int y = 0; y < by0; ++y) clear_pixels(target.row(y), target.width);
    if (bx0 > 0 || bx1 < target.width) {
        for (int y = by0; y < by1; ++y) {
            auto* row = target.row(y);
            clear_pixels(row, bx0);
            clear_pixels(row + bx1, target.width - bx1);
        }
    }
    for (int y = std::max(by1, 0); y < target.height; ++y) clear_pixels(target.row(y), target.width);
}

// The band's floats in `v`, grown (with zeros) to hold `cells` from a kBandAlign-aligned start.
// The sweep leaves them all zero, and growing keeps that, wherever the aligned start falls.
inline float* band_cells(std::vector<float>& v, std::size_t cells) {
    constexpr std::size_t kPad = kBandAlign / sizeof(float);
    if (v.size() < cells + kPad) v.resize(cells + kPad, 0.0f);
    const auto address = reinterpret_cast<std::uintptr_t>(v.data());
    const std::size_t skip = ((kBandAlign - address % kBandAlign) % kBandAlign) / sizeof(float);
    return v.data() + skip;
}

// The sweep kernel of one group of rows, for an output pixel type.
inline void sweep_group(const SweepKernels& k, FillRule rule, float* acc, std::uint8_t* flags,
                        int n, int rows, std::uint8_t* out, std::ptrdiff_t out_stride) {
    k.u8[static_cast<int>(rule)](acc, flags, n, rows, out, out_stride);
}
inline void sweep_group(const SweepKernels& k, FillRule rule, float* acc, std::uint8_t* flags,
                        int n, int rows, float* out, std::ptrdiff_t out_stride) {
    k.f32[static_cast<int>(rule)](acc, flags, n, rows, out, out_stride);
}

// Sweeps every group of a band whose blocks are marked into its output rows, `out` the first
// (row 0 of the band), `out_stride` apart.
template <typename Out>
void sweep_marked_band(const SweepKernels& k, FillRule rule, const Band& band, Out* out,
                       std::ptrdiff_t out_stride) {
    for (int y = 0; y < band.rows; y += kGroupRows)
        sweep_group(k, rule, band.acc + (y >> kGroupShift) * band.stride,
                    band.flags + (y >> kGroupShift) * band.flag_stride, band.width,
                    std::min(kGroupRows, band.rows - y), out + y * out_stride, out_stride);
}

inline void sweep_dense(const SweepKernels& k, FillRule rule, float* acc, std::ptrdiff_t stride,
                        int n, int rows, std::uint8_t* out, std::ptrdiff_t out_stride) {
    k.dense_u8[static_cast<int>(rule)](acc, stride, n, rows, out, out_stride);
}
inline void sweep_dense(const SweepKernels& k, FillRule rule, float* acc, std::ptrdiff_t stride,
                        int n, int rows, float* out, std::ptrdiff_t out_stride) {
    k.dense_f32[static_cast<int>(rule)](acc, stride, n, rows, out, out_stride);
}

}  // namespace bezel::raster_detail
