// Private: turning one row of accumulated deltas into coverage (the hot loop at large sizes).
//
// coverage(i) = f(acc[0] + … + acc[i]) where f is the fill rule:
//   NonZero: f(a) = min(|a|, 1)
//   EvenOdd: f(a) = 1 − |1 − (|a| mod 2)|, the triangle wave (0 at even windings, 1 at odd)
// 8-bit output is round(255·f). Every kernel also ZEROES the acc entries it reads, plus the two
// guard entries acc[n] and acc[n+1], so the band is clean for the next fill without a memset.
//
// Kernels: a scalar reference, SSE2 (the x86-64 baseline) and AVX2 (chosen at run time). SIMD
// kernels compute the prefix sum in registers (log-step shifts) and chain the running total
// across blocks of 4 vectors through a single add, so the loop is bound by throughput, not by
// the latency of the carry.
#pragma once

#include <cstdint>

#include "bezel/raster.hpp"

namespace bezel::raster_detail {

using SweepU8Fn = void (*)(float* acc, int n, std::uint8_t* out);
using SweepF32Fn = void (*)(float* acc, int n, float* out);

struct SweepKernels {
    SweepU8Fn u8[2];    // indexed by FillRule
    SweepF32Fn f32[2];
    const char* name;   // "scalar", "sse2", "avx2"
};

const SweepKernels& scalar_kernels();
const SweepKernels& sse2_kernels();
// Null when the CPU (or the build) has no AVX2.
const SweepKernels* avx2_kernels();
// The fastest kernels this CPU supports, decided once.
const SweepKernels& best_kernels();

// Scalar f(a) for both rules, shared by every kernel's tail.
inline float coverage_of(float a, FillRule rule) {
    float v = a < 0 ? -a : a;
    if (rule == FillRule::EvenOdd) {
        v -= 2.0f * static_cast<float>(static_cast<std::int64_t>(v * 0.5f));
        v = v > 1.0f ? 2.0f - v : v;
    }
    return v < 1.0f ? v : 1.0f;
}
inline std::uint8_t coverage_u8(float a, FillRule rule) {
    return static_cast<std::uint8_t>(coverage_of(a, rule) * 255.0f + 0.5f);
}

}  // namespace bezel::raster_detail
