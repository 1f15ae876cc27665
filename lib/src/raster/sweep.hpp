// Private: turning one row of accumulated deltas into coverage (the hot loop at large sizes).
//
// coverage(i) = f(acc[0] + … + acc[i]) where f is the fill rule:
//   NonZero: f(a) = min(|a|, 1)
//   EvenOdd: f(a) = 1 − |1 − (|a| mod 2)|, the triangle wave (0 at even windings, 1 at odd)
// 8-bit output is round(255·f).
//
// Sparse in blocks of kBlock pixels. Edge drawing marks each block it writes deltas into
// (`flags[b] = 1`). An unmarked block has all-zero deltas, so its coverage is the constant
// f(running sum): it is FILLED (memset), not summed. That is the "run filling" of sparse
// rasterizers (FreeType's spans) without a cell list: at 512 px a glyph row is mostly empty or
// solid, and only the few blocks an edge crosses pay for a prefix sum. Marked blocks are summed
// in registers (log-step shifts inside a vector, the running total chained through one add per
// block, so the loop is bound by throughput rather than by the carry's latency).
//
// Contract of every kernel, for a row of n output pixels:
//   acc   has row_cells(n) floats, zero except in marked blocks; flags has row_flag_bytes(n)
//         bytes, 0 or 1.
//   On return acc and flags are all zero again, so the band needs no memset before the next
//   fill, and out[0, n) holds the coverage.
#pragma once

#include <cstddef>
#include <cstdint>

#include "bezel/raster.hpp"

namespace bezel::raster_detail {

inline constexpr int kBlockShift = 4;
inline constexpr int kBlock = 1 << kBlockShift;  // pixels per block (two AVX2 vectors)

// Cells a row of n pixels needs: n, three guard cells (a narrow piece at x = n writes acc[n] to
// acc[n+2], accumulate.hpp), rounded up to whole blocks so kernels never read past the row.
constexpr int row_cells(int n) { return (n + 3 + kBlock - 1) & ~(kBlock - 1); }
constexpr int row_blocks(int n) { return row_cells(n) >> kBlockShift; }
// Flag bytes a row of n pixels has: one per block, rounded up to whole 8-byte words so the sweep
// can test eight flags with one load; the padding flags are never set.
constexpr int row_flag_bytes(int n) { return (row_blocks(n) + 7) & ~7; }

using SweepU8Fn = void (*)(float* acc, std::uint8_t* flags, int n, std::uint8_t* out);
using SweepF32Fn = void (*)(float* acc, std::uint8_t* flags, int n, float* out);
// DENSE bands (narrow boxes, direct_fill.hpp): `rows` rows of acc, `stride` floats apart, every
// block summed, no flags read or written; output rows `out_stride` pixels apart. One call per
// band instead of per row. On return acc is all zero.
using SweepDenseU8Fn = void (*)(float* acc, std::ptrdiff_t stride, int n, int rows,
                                std::uint8_t* out, std::ptrdiff_t out_stride);
using SweepDenseF32Fn = void (*)(float* acc, std::ptrdiff_t stride, int n, int rows, float* out,
                                 std::ptrdiff_t out_stride);

struct SweepKernels {
    SweepU8Fn u8[2];    // indexed by FillRule
    SweepF32Fn f32[2];
    SweepDenseU8Fn dense_u8[2];
    SweepDenseF32Fn dense_f32[2];
    const char* name;   // "scalar", "sse2", "avx2"
};

// The scalar kernels ignore the flags (they sum every cell) and serve as the reference.
const SweepKernels& scalar_kernels();
const SweepKernels& sse2_kernels();
// Null when the CPU (or the build) has no AVX2.
const SweepKernels* avx2_kernels();
// The fastest kernels this CPU supports, decided once.
const SweepKernels& best_kernels();

// Scalar f(a) for both rules.
inline float coverage_of(float a, FillRule rule) {
    float v = a < 0 ? -a : a;
    if (rule == FillRule::EvenOdd) {
        v -= 2.0f * static_cast<float>(static_cast<std::int64_t>(v * 0.5f));
        v = v > 1.0f ? 2.0f - v : v;
    }
    return v < 1.0f ? v : 1.0f;
}
// round(255·f); the SIMD kernels round half to even, which differs only on exact .5 values.
inline std::uint8_t coverage_u8(float a, FillRule rule) {
    return static_cast<std::uint8_t>(coverage_of(a, rule) * 255.0f + 0.5f);
}

}  // namespace bezel::raster_detail
