// Private: the block walk shared by the SIMD sweep kernels (see sweep.hpp). Header-only and
// written over a `Block` policy so each instruction-set file instantiates it inside its own
// target attribute: the policy supplies
//   Carry                        the running sum, broadcast in a vector
//   Carry zero()
//   float first(Carry)           its scalar value
//   void sum(float* acc, Carry&, Out* out, int count)
//                                prefix-sums kBlock cells, zeroes them, writes the first
//                                `count` (1..kBlock) outputs
#pragma once

#include <algorithm>
#include <cstring>

#include "raster/sweep.hpp"

namespace bezel::raster_detail {
// Internal linkage: each kernel file compiles these for its own instruction set (the AVX2 file
// inside `#pragma GCC target("avx2")`), and the copies must not be merged by the linker.
namespace {

inline void fill_run(std::uint8_t* out, int count, float a, FillRule rule) {
    std::memset(out, coverage_u8(a, rule), static_cast<std::size_t>(count));
}
inline void fill_run(float* out, int count, float a, FillRule rule) {
    std::fill(out, out + count, coverage_of(a, rule));
}

// Index of the first marked block at or after b (nb when none). Eight flags at a time: a
// glyph row at large sizes is mostly unmarked.
inline int next_marked(const std::uint8_t* flags, int b, int nb) {
    while (b + 8 <= nb) {
        std::uint64_t word;
        std::memcpy(&word, flags + b, 8);
        if (word != 0) break;
        b += 8;
    }
    while (b < nb && !flags[b]) ++b;
    return b;
}

template <typename Block, FillRule R, typename Out>
inline void sweep_blocks(float* acc, std::uint8_t* flags, int n, Out* out) {
    const int nb = row_blocks(n);
    typename Block::Carry carry = Block::zero();
    int b = 0;
    while (b < nb) {
        if (!flags[b]) {
            const int e = next_marked(flags, b, nb);
            const int x0 = b << kBlockShift, x1 = std::min(e << kBlockShift, n);
            if (x1 > x0) fill_run(out + x0, x1 - x0, Block::first(carry), R);
            b = e;
            continue;
        }
        flags[b] = 0;
        const int x0 = b << kBlockShift;
        Block::template sum<R>(acc + x0, carry, out + x0, std::clamp(n - x0, 0, kBlock));
        ++b;
    }
}

}  // namespace
}  // namespace bezel::raster_detail
