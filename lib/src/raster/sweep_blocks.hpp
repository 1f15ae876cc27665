// Private: the group walk shared by the SIMD sweep kernels (see sweep.hpp). Header-only and
// written over a `Block` policy so each instruction-set file instantiates it inside its own
// target attribute: the policy supplies
//   Carry                        the running sums of the group's eight rows
//   Carry zero()
//   void values<R>(Carry, Out v[8])
//                                each row's coverage of its running sum (the value of a run)
//   void fill<R>(Carry, Out* out, ptrdiff_t out_stride, int rows, int x, int end, Out* scratch)
//                                writes the run [x, end) of rows [0, rows) with those values
//                                (fill_group_run's contract; `scratch` holds 8 values)
//   void sum<R>(float* acc, Carry&, Out* out, ptrdiff_t out_stride, int count, int rows)
//                                prefix-sums kBlock columns (column-major, eight rows each),
//                                zeroes them, writes columns [0, count) (1..kBlock) of output
//                                rows [0, rows) (1..8)
//   void clear(float* acc)       zeroes kBlock columns (a guard block), with the policy's own
//                                vector stores: a 512-byte memset compiles to `rep stos`,
//                                whose start-up cost is large against one guard block a
//                                group (3.7 % of the dense sweep at 96 px)
#pragma once

#include <algorithm>
#include <cstring>

#include "raster/sweep.hpp"

namespace bezel::raster_detail {
// Internal linkage: each kernel file compiles these for its own instruction set (the AVX2 file
// inside its BEZEL_AVX2_BEGIN region, target_avx2.hpp), and the copies must not be merged by
// the linker.
namespace {

// Writes the first `count` (0..15) bytes of `src` with fixed-size moves instead of a memcpy
// call (row tails and short runs; the call costs more than the copy).
inline void copy_tail(std::uint8_t* out, const std::uint8_t* src, int count) {
    if (count & 8) { std::memcpy(out, src, 8); out += 8; src += 8; }
    if (count & 4) { std::memcpy(out, src, 4); out += 4; src += 4; }
    if (count & 2) { std::memcpy(out, src, 2); out += 2; src += 2; }
    if (count & 1) *out = *src;
}

// Writes `count` bytes of `src` (0..kBlock).
inline void copy_bytes(std::uint8_t* out, const std::uint8_t* src, int count) {
    if (count == kBlock)
        std::memcpy(out, src, kBlock);
    else
        copy_tail(out, src, count);
}

// The group's runs [x, end) of constant coverage, one value per row, zero or not (the rows are
// not cleared beforehand: every output pixel is written once, by a run or by a block's sum).
// Bytes: the same stores for every row, so the only branches are per run, not per row: 32-byte
// stores with the last one ending at `end`, or 16-byte ones for shorter runs, pieces below 16.
// No store leaves [x, end).
inline void fill_group_run(std::uint8_t* out, std::ptrdiff_t out_stride, int rows, int x, int end,
                           const std::uint8_t* value) {
    const int len = end - x;
    std::uint8_t v[kGroupRows][2 * kBlock];
    for (int r = 0; r < kGroupRows; ++r) std::memset(v[r], value[r], sizeof v[r]);
    if (len >= 2 * kBlock) {
        for (int p = x; p + 2 * kBlock < end; p += 2 * kBlock)
            for (int r = 0; r < rows; ++r) std::memcpy(out + r * out_stride + p, v[r], 2 * kBlock);
        for (int r = 0; r < rows; ++r)
            std::memcpy(out + r * out_stride + end - 2 * kBlock, v[r], 2 * kBlock);
    } else if (len >= kBlock) {
        for (int r = 0; r < rows; ++r) {
            std::memcpy(out + r * out_stride + x, v[r], kBlock);
            std::memcpy(out + r * out_stride + end - kBlock, v[r], kBlock);
        }
    } else {
        for (int r = 0; r < rows; ++r) copy_tail(out + r * out_stride + x, v[r], len);
    }
}
inline void fill_group_run(float* out, std::ptrdiff_t out_stride, int rows, int x, int end,
                           const float* value) {
    for (int r = 0; r < rows; ++r) {
        float* row = out + r * out_stride;
        std::fill(row + x, row + end, value[r]);
    }
}

// The sparse group: marked blocks are summed, the runs between them filled, and every output
// pixel written exactly once, so the rows need no clearing first and a run of coverage 0 costs
// its stores and nothing more (a memset of every row before the fill wrote the glyph's interior
// and edges twice). The marked blocks are found eight flags at a time (a little-endian word of
// 0/1 bytes has a set bit at 8k for each marked block k, so ctz / 8 is the next one and
// word & (word − 1) drops it), which costs no branch per unmarked block: at large sizes a row is
// mostly runs. Guard blocks past the row's last pixel hold deltas of pieces at x ≈ n but no
// pixels: they are only cleared.
template <typename Block, FillRule R, typename Out>
inline void sweep_group(float* acc, std::uint8_t* flags, int n, int rows, Out* out,
                        std::ptrdiff_t out_stride) {
    const int words = row_flag_bytes(n) >> 3;
    typename Block::Carry carry = Block::zero();
    Out value[kGroupRows];
    int x = 0;  // pixels [0, x) of each row are written
    for (int w = 0; w < words; ++w) {
        std::uint64_t word;
        std::memcpy(&word, flags + 8 * w, 8);
        if (word == 0) continue;
        std::memset(flags + 8 * w, 0, 8);
        do {
            const int b = 8 * w + (__builtin_ctzll(word) >> 3);
            word &= word - 1;
            const int x0 = b << kBlockShift;
            float* cells = acc + static_cast<std::ptrdiff_t>(x0) * kGroupRows;
            if (x0 >= n) {
                Block::clear(cells);
                continue;
            }
            if (x0 > x) Block::template fill<R>(carry, out, out_stride, rows, x, x0, value);
            Block::template sum<R>(cells, carry, out + x0, out_stride, std::min(n - x0, kBlock),
                                   rows);
            x = x0 + kBlock;
        } while (word != 0);
    }
    if (x < n) Block::template fill<R>(carry, out, out_stride, rows, x, n, value);
}

// The dense band: every block of every group summed (no flags); the guard cells past the last
// output block, which hold deltas but no pixels, are only cleared.
template <typename Block, FillRule R, typename Out>
inline void sweep_dense(float* acc, std::ptrdiff_t group_stride, int n, int rows, Out* out,
                        std::ptrdiff_t out_stride) {
    const int nb = (n + kBlock - 1) >> kBlockShift;
    const int cells = row_cells(n);
    for (int y = 0; y < rows; y += kGroupRows) {
        const int group_rows = std::min(kGroupRows, rows - y);
        typename Block::Carry carry = Block::zero();
        for (int b = 0; b < nb; ++b) {
            const int x0 = b << kBlockShift;
            Block::template sum<R>(acc + static_cast<std::ptrdiff_t>(x0) * kGroupRows, carry,
                                   out + x0, out_stride, std::min(n - x0, kBlock), group_rows);
        }
        // At most one guard block (row_cells adds three cells).
        for (int c = nb << kBlockShift; c < cells; c += kBlock)
            Block::clear(acc + static_cast<std::ptrdiff_t>(c) * kGroupRows);
        acc += group_stride;
        out += kGroupRows * out_stride;
    }
}

}  // namespace
}  // namespace bezel::raster_detail
