// AVX2 sweep kernels: 8 lanes, 32 pixels per iteration. Compiled with the avx2 target attribute
// and only called after __builtin_cpu_supports("avx2") said yes, so the library still runs on
// any x86-64.
#include <immintrin.h>

#include "raster/sweep.hpp"

namespace bezel::raster_detail {

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define BEZEL_AVX2 __attribute__((target("avx2")))

namespace {

// Inclusive prefix sum of 8 floats: log steps inside each 128-bit lane, then the low lane's total
// added to the high lane.
BEZEL_AVX2 inline __m256 prefix8(__m256 x) {
    x = _mm256_add_ps(x, _mm256_castsi256_ps(_mm256_slli_si256(_mm256_castps_si256(x), 4)));
    x = _mm256_add_ps(x, _mm256_castsi256_ps(_mm256_slli_si256(_mm256_castps_si256(x), 8)));
    // permute2f128 0x08: low lane zeroed, high lane = low lane of x; then broadcast element 3.
    __m256 low_total = _mm256_permute2f128_ps(x, x, 0x08);
    low_total = _mm256_shuffle_ps(low_total, low_total, 0xFF);
    return _mm256_add_ps(x, low_total);
}
// All lanes = element 7.
BEZEL_AVX2 inline __m256 last8(__m256 x) {
    __m256 t = _mm256_shuffle_ps(x, x, 0xFF);
    return _mm256_permute2f128_ps(t, t, 0x11);
}

template <FillRule R>
BEZEL_AVX2 inline __m256 coverage8(__m256 a) {
    __m256 v = _mm256_andnot_ps(_mm256_set1_ps(-0.0f), a);
    if (R == FillRule::EvenOdd) {
        __m256 q = _mm256_round_ps(_mm256_mul_ps(v, _mm256_set1_ps(0.5f)),
                                   _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC);
        v = _mm256_sub_ps(v, _mm256_add_ps(q, q));
        v = _mm256_min_ps(v, _mm256_sub_ps(_mm256_set1_ps(2.0f), v));
    }
    return _mm256_min_ps(v, _mm256_set1_ps(1.0f));
}

// As prefix16 in sweep.cpp: four vectors, one add on the carried chain.
BEZEL_AVX2 inline void prefix32(float* acc, __m256& carry, __m256 (&v)[4]) {
    for (int k = 0; k < 4; ++k) {
        v[k] = prefix8(_mm256_loadu_ps(acc + 8 * k));
        _mm256_storeu_ps(acc + 8 * k, _mm256_setzero_ps());
    }
    const __m256 t0 = last8(v[0]);
    const __m256 t01 = _mm256_add_ps(t0, last8(v[1]));
    const __m256 t012 = _mm256_add_ps(t01, last8(v[2]));
    v[1] = _mm256_add_ps(v[1], t0);
    v[2] = _mm256_add_ps(v[2], t01);
    v[3] = _mm256_add_ps(v[3], t012);
    const __m256 before = carry;
    carry = _mm256_add_ps(carry, last8(v[3]));
    for (int k = 0; k < 4; ++k) v[k] = _mm256_add_ps(v[k], before);
}

template <FillRule R>
BEZEL_AVX2 void avx2_u8(float* acc, int n, std::uint8_t* out) {
    __m256 carry = _mm256_setzero_ps();
    const __m256 k255 = _mm256_set1_ps(255.0f);
    // packs/packus work per 128-bit lane; this puts the 32-bit groups back in pixel order.
    const __m256i order = _mm256_setr_epi32(0, 4, 1, 5, 2, 6, 3, 7);
    int i = 0;
    for (; i + 32 <= n; i += 32) {
        __m256 v[4];
        prefix32(acc + i, carry, v);
        __m256i q[4];
        for (int k = 0; k < 4; ++k) q[k] = _mm256_cvtps_epi32(_mm256_mul_ps(coverage8<R>(v[k]), k255));
        __m256i bytes = _mm256_packus_epi16(_mm256_packs_epi32(q[0], q[1]),
                                            _mm256_packs_epi32(q[2], q[3]));
        bytes = _mm256_permutevar8x32_epi32(bytes, order);
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + i), bytes);
    }
    float sum = _mm256_cvtss_f32(carry);
    for (; i < n; ++i) {
        sum += acc[i];
        acc[i] = 0.0f;
        out[i] = coverage_u8(sum, R);
    }
    acc[n] = acc[n + 1] = 0.0f;
}

template <FillRule R>
BEZEL_AVX2 void avx2_f32(float* acc, int n, float* out) {
    __m256 carry = _mm256_setzero_ps();
    int i = 0;
    for (; i + 32 <= n; i += 32) {
        __m256 v[4];
        prefix32(acc + i, carry, v);
        for (int k = 0; k < 4; ++k) _mm256_storeu_ps(out + i + 8 * k, coverage8<R>(v[k]));
    }
    float sum = _mm256_cvtss_f32(carry);
    for (; i < n; ++i) {
        sum += acc[i];
        acc[i] = 0.0f;
        out[i] = coverage_of(sum, R);
    }
    acc[n] = acc[n + 1] = 0.0f;
}

}  // namespace

const SweepKernels* avx2_kernels() {
    static const SweepKernels k{{avx2_u8<FillRule::NonZero>, avx2_u8<FillRule::EvenOdd>},
                                {avx2_f32<FillRule::NonZero>, avx2_f32<FillRule::EvenOdd>},
                                "avx2"};
    static const bool supported = __builtin_cpu_supports("avx2");
    return supported ? &k : nullptr;
}

#else
const SweepKernels* avx2_kernels() { return nullptr; }
#endif

}  // namespace bezel::raster_detail
