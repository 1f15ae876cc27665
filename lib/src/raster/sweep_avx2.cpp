// AVX2 sweep kernels: a block of 16 cells is two 8-lane vectors. Everything after the pragma is
// compiled for AVX2 and only called after __builtin_cpu_supports("avx2") said yes, so the
// library still runs on any x86-64. Standard headers come first so that they stay baseline code.
#include <algorithm>
#include <cstdint>
#include <cstring>

#include "raster/sweep.hpp"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>

#pragma GCC push_options
#pragma GCC target("avx2")
#include "raster/sweep_blocks.hpp"


namespace bezel::raster_detail {

namespace {

// Shuffles are counted below: on Intel cores they share one port (5), where every shift,
// permute and pack of the block sum goes. Taking element 3 and element 7 with one permute each
// (instead of a lane swap and a shuffle) and packing in 256 bits measured 3-5 % faster at
// 192-512 px (bench_raster, alternating runs), though a bare dense-band loop moved by ±10 %
// either way with the width, so the port is not the whole story.

// Inclusive prefix sum of 8 floats: log steps inside each 128-bit lane (two shifts), then the
// low lane's total, element 3 broadcast to the high lane by one permute and masked off the low
// lane by a blend, added.
inline __m256 prefix8(__m256 x) {
    x = _mm256_add_ps(x, _mm256_castsi256_ps(_mm256_slli_si256(_mm256_castps_si256(x), 4)));
    x = _mm256_add_ps(x, _mm256_castsi256_ps(_mm256_slli_si256(_mm256_castps_si256(x), 8)));
    const __m256 low_total = _mm256_permutevar8x32_ps(x, _mm256_set1_epi32(3));
    return _mm256_add_ps(x, _mm256_blend_ps(_mm256_setzero_ps(), low_total, 0xF0));
}
// All lanes = element 7 (one permute).
inline __m256 last8(__m256 x) { return _mm256_permutevar8x32_ps(x, _mm256_set1_epi32(7)); }

template <FillRule R>
inline __m256 coverage8(__m256 a) {
    __m256 v = _mm256_andnot_ps(_mm256_set1_ps(-0.0f), a);
    if (R == FillRule::EvenOdd) {
        __m256 q = _mm256_round_ps(_mm256_mul_ps(v, _mm256_set1_ps(0.5f)),
                                   _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC);
        v = _mm256_sub_ps(v, _mm256_add_ps(q, q));
        v = _mm256_min_ps(v, _mm256_sub_ps(_mm256_set1_ps(2.0f), v));
    }
    return _mm256_min_ps(v, _mm256_set1_ps(1.0f));
}

// Four vectors of 8 int32 → 32 bytes in order, with three shuffles: the 256-bit packs work
// within 128-bit lanes, leaving 4-byte groups in the order a₀ b₀ c₀ d₀ | a₁ b₁ c₁ d₁ (x₀ the low
// four of x), which one dword permute puts back as a₀ a₁ b₀ b₁ c₀ c₁ d₀ d₁.
inline __m256i pack_bytes(__m256i a, __m256i b, __m256i c, __m256i d) {
    const __m256i bytes = _mm256_packus_epi16(_mm256_packs_epi32(a, b), _mm256_packs_epi32(c, d));
    return _mm256_permutevar8x32_epi32(bytes, _mm256_setr_epi32(0, 4, 1, 5, 2, 6, 3, 7));
}

struct Avx2Block {
    using Carry = __m256;
    static Carry zero() { return _mm256_setzero_ps(); }
    static float first(Carry c) { return _mm256_cvtss_f32(c); }

    static void prefix16(float* acc, Carry& carry, __m256& v0, __m256& v1) {
        v0 = prefix8(_mm256_loadu_ps(acc));
        v1 = prefix8(_mm256_loadu_ps(acc + 8));
        _mm256_storeu_ps(acc, _mm256_setzero_ps());
        _mm256_storeu_ps(acc + 8, _mm256_setzero_ps());
        v1 = _mm256_add_ps(v1, last8(v0));
        const __m256 before = carry;
        carry = _mm256_add_ps(carry, last8(v1));  // the only add on the loop-carried chain
        v0 = _mm256_add_ps(v0, before);
        v1 = _mm256_add_ps(v1, before);
    }

    template <FillRule R>
    static void sum(float* acc, Carry& carry, std::uint8_t* out, int count) {
        __m256 v0, v1;
        prefix16(acc, carry, v0, v1);
        const __m256 k255 = _mm256_set1_ps(255.0f);
        const __m256i q0 = _mm256_cvtps_epi32(_mm256_mul_ps(coverage8<R>(v0), k255));
        const __m256i q1 = _mm256_cvtps_epi32(_mm256_mul_ps(coverage8<R>(v1), k255));
        const __m128i bytes = _mm256_castsi256_si128(pack_bytes(q0, q1, q0, q1));  // 16 wanted
        if (count == kBlock) {
            _mm_storeu_si128(reinterpret_cast<__m128i*>(out), bytes);
        } else {
            alignas(16) std::uint8_t tmp[kBlock];
            _mm_store_si128(reinterpret_cast<__m128i*>(tmp), bytes);
            copy_tail(out, tmp, count);
        }
    }

    template <FillRule R>
    static void sum(float* acc, Carry& carry, float* out, int count) {
        __m256 v0, v1;
        prefix16(acc, carry, v0, v1);
        if (count == kBlock) {
            _mm256_storeu_ps(out, coverage8<R>(v0));
            _mm256_storeu_ps(out + 8, coverage8<R>(v1));
        } else {
            alignas(32) float tmp[kBlock];
            _mm256_store_ps(tmp, coverage8<R>(v0));
            _mm256_store_ps(tmp + 8, coverage8<R>(v1));
            std::memcpy(out, tmp, sizeof(float) * static_cast<std::size_t>(count));
        }
    }
};

template <FillRule R, typename Out>
void avx2_sweep(float* acc, std::uint8_t* flags, int n, Out* out) {
    sweep_blocks<Avx2Block, R>(acc, flags, n, out);
}

template <FillRule R, typename Out>
void avx2_dense(float* acc, std::ptrdiff_t stride, int n, int rows, Out* out,
              std::ptrdiff_t out_stride) {
    sweep_dense<Avx2Block, R>(acc, stride, n, rows, out, out_stride);
}

}  // namespace
}  // namespace bezel::raster_detail
#pragma GCC pop_options

namespace bezel::raster_detail {

// Baseline code (outside the pragma): it runs on every CPU, to ask whether AVX2 is there.
const SweepKernels* avx2_kernels() {
    static const SweepKernels k{
        {avx2_sweep<FillRule::NonZero, std::uint8_t>, avx2_sweep<FillRule::EvenOdd, std::uint8_t>},
        {avx2_sweep<FillRule::NonZero, float>, avx2_sweep<FillRule::EvenOdd, float>},
        {avx2_dense<FillRule::NonZero, std::uint8_t>, avx2_dense<FillRule::EvenOdd, std::uint8_t>},
        {avx2_dense<FillRule::NonZero, float>, avx2_dense<FillRule::EvenOdd, float>},
        "avx2"};
    static const bool supported = __builtin_cpu_supports("avx2");
    return supported ? &k : nullptr;
}

}  // namespace bezel::raster_detail

#else
namespace bezel::raster_detail {
const SweepKernels* avx2_kernels() { return nullptr; }
}  // namespace bezel::raster_detail
#endif
