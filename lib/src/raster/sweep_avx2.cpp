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

// Inclusive prefix sum of 8 floats: log steps inside each 128-bit lane, then the low lane's
// total added to the high lane.
inline __m256 prefix8(__m256 x) {
    x = _mm256_add_ps(x, _mm256_castsi256_ps(_mm256_slli_si256(_mm256_castps_si256(x), 4)));
    x = _mm256_add_ps(x, _mm256_castsi256_ps(_mm256_slli_si256(_mm256_castps_si256(x), 8)));
    // permute2f128 0x08: low lane zeroed, high lane = low lane of x; then broadcast element 3.
    __m256 low_total = _mm256_permute2f128_ps(x, x, 0x08);
    low_total = _mm256_shuffle_ps(low_total, low_total, 0xFF);
    return _mm256_add_ps(x, low_total);
}
// All lanes = element 7.
inline __m256 last8(__m256 x) {
    __m256 t = _mm256_shuffle_ps(x, x, 0xFF);
    return _mm256_permute2f128_ps(t, t, 0x11);
}

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
        // 16 int32 → 16 bytes with 128-bit packs (the 256-bit ones interleave lanes).
        const __m128i w0 = _mm_packs_epi32(_mm256_castsi256_si128(q0), _mm256_extracti128_si256(q0, 1));
        const __m128i w1 = _mm_packs_epi32(_mm256_castsi256_si128(q1), _mm256_extracti128_si256(q1, 1));
        const __m128i bytes = _mm_packus_epi16(w0, w1);
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
