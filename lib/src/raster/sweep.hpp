// Private: turning one row of accumulated deltas into coverage (the hot loop at large sizes).
//
// coverage(i) = f(acc[0] + … + acc[i]) where f is the fill rule:
//   NonZero: f(a) = min(|a|, 1)
//   EvenOdd: f(a) = 1 − |1 − (|a| mod 2)|, the triangle wave (0 at even windings, 1 at odd)
// 8-bit output is round(255·f).
//
// The band is stored in GROUPS of kGroupRows = 8 rows, column-major inside a group: the delta of
// cell x of row r of group g is acc[g·group_stride + x·8 + r], group_stride = group_cells(n).
// Why: the prefix sum along a row is then a chain of VERTICAL adds, one per column for eight
// rows at once, instead of log-step shifts inside a vector (the row-major sweep spent 11
// shuffles — shifts, permutes, packs — on every 16 pixels). The price is a transpose of the
// 8-bit results back to rows, 24 shuffles per 16 × 8 pixels. Measured on a bare dense band
// (150 × 192 px, AVX2): 0.229 → 0.108 ns per pixel; glyphs at 192-512 px 20-25 % faster.
//
// Sparse in blocks of kBlock columns of a group. Edge drawing marks each block it writes deltas
// into (`flags[b] = 1`, one flag row per group). An unmarked block has all-zero deltas, so each
// of its rows has the constant coverage f(running sum of that row): it is FILLED, not summed.
// That is the "run filling" of sparse rasterizers (FreeType's spans) without a cell list: at
// 512 px a glyph row is mostly empty or solid, and only the few blocks an edge crosses pay for a
// prefix sum.
//
// Contract of every kernel, for a group of `rows` (1..8) output rows of n pixels:
//   acc   has group_cells(n) floats, zero except in marked blocks (and zero in rows ≥ `rows`);
//         flags has row_flag_bytes(n) bytes, 0 or 1.
//   On return acc and flags are all zero again, so the band needs no memset before the next
//   fill, and out rows [0, rows) (out_stride apart) hold the coverage in pixels [0, n).
#pragma once

#include <cstddef>
#include <cstdint>

#include "bezel/raster.hpp"

namespace bezel::raster_detail {

inline constexpr int kBlockShift = 4;
inline constexpr int kBlock = 1 << kBlockShift;  // columns per block
inline constexpr int kGroupShift = 3;
inline constexpr int kGroupRows = 1 << kGroupShift;  // rows per group (one AVX2 vector of floats)

// Cells a row of n pixels needs: n, three guard cells (a narrow piece at x = n writes acc[n] to
// acc[n+2], accumulate.hpp), rounded up to whole blocks so kernels never read past the row.
constexpr int row_cells(int n) { return (n + 3 + kBlock - 1) & ~(kBlock - 1); }
constexpr int row_blocks(int n) { return row_cells(n) >> kBlockShift; }
// Floats one group of rows of n pixels takes.
constexpr std::ptrdiff_t group_cells(int n) {
    return static_cast<std::ptrdiff_t>(row_cells(n)) * kGroupRows;
}
constexpr int row_groups(int rows) { return (rows + kGroupRows - 1) >> kGroupShift; }
// Flag bytes a group of n pixels has: one per block, rounded up to whole 8-byte words so the
// sweep can test eight flags with one load; the padding flags are never set.
constexpr int row_flag_bytes(int n) { return (row_blocks(n) + 7) & ~7; }
// The band's first float is aligned to this many bytes (whole AVX2 vectors per column).
inline constexpr std::size_t kBandAlign = 32;

using SweepU8Fn = void (*)(float* acc, std::uint8_t* flags, int n, int rows, std::uint8_t* out,
                           std::ptrdiff_t out_stride);
using SweepF32Fn = void (*)(float* acc, std::uint8_t* flags, int n, int rows, float* out,
                            std::ptrdiff_t out_stride);
// DENSE bands (narrow boxes, direct_fill.hpp): `rows` rows in row_groups(rows) groups,
// `group_stride` floats apart, every block summed, no flags read or written; output rows
// `out_stride` pixels apart. One call per band instead of per group. On return acc is all zero.
using SweepDenseU8Fn = void (*)(float* acc, std::ptrdiff_t group_stride, int n, int rows,
                                std::uint8_t* out, std::ptrdiff_t out_stride);
using SweepDenseF32Fn = void (*)(float* acc, std::ptrdiff_t group_stride, int n, int rows,
                                 float* out, std::ptrdiff_t out_stride);

struct SweepKernels {
    SweepU8Fn u8[2];    // indexed by FillRule
    SweepF32Fn f32[2];
    SweepDenseU8Fn dense_u8[2];
    SweepDenseF32Fn dense_f32[2];
    const char* name;   // "scalar", "sse2", "avx2"
};

// Whether this CPU runs AVX2, asked once; what the AVX2 kernel tables (sweep_avx2.cpp,
// draw_avx2.cpp) consult. Baseline code: those files include this header before their pragma.
inline bool cpu_has_avx2() {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
    static const bool supported = __builtin_cpu_supports("avx2");
    return supported;
#else
    return false;
#endif
}

// The scalar kernels ignore the flags (they sum every cell) and serve as the reference.
const SweepKernels& scalar_kernels();
const SweepKernels& sse2_kernels();
// Null when the CPU (or the build) has no AVX2.
const SweepKernels* avx2_kernels();
// Which of them fills use is kernel_table()'s choice (kernels.hpp).

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
