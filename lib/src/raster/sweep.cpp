// Scalar and SSE2 sweep kernels, and the run-time choice between them and AVX2.
#include "raster/sweep.hpp"

#include <emmintrin.h>

namespace bezel::raster_detail {

namespace {

template <FillRule R>
void scalar_u8(float* acc, int n, std::uint8_t* out) {
    float sum = 0.0f;
    for (int i = 0; i < n; ++i) {
        sum += acc[i];
        acc[i] = 0.0f;
        out[i] = coverage_u8(sum, R);
    }
    acc[n] = acc[n + 1] = 0.0f;
}

template <FillRule R>
void scalar_f32(float* acc, int n, float* out) {
    float sum = 0.0f;
    for (int i = 0; i < n; ++i) {
        sum += acc[i];
        acc[i] = 0.0f;
        out[i] = coverage_of(sum, R);
    }
    acc[n] = acc[n + 1] = 0.0f;
}

// In-register inclusive prefix sum of 4 floats: x + (x << 1 lane) + (x << 2 lanes).
inline __m128 prefix4(__m128 x) {
    x = _mm_add_ps(x, _mm_castsi128_ps(_mm_slli_si128(_mm_castps_si128(x), 4)));
    return _mm_add_ps(x, _mm_castsi128_ps(_mm_slli_si128(_mm_castps_si128(x), 8)));
}
inline __m128 last4(__m128 x) { return _mm_shuffle_ps(x, x, 0xFF); }

template <FillRule R>
inline __m128 coverage4(__m128 a) {
    const __m128 one = _mm_set1_ps(1.0f);
    __m128 v = _mm_andnot_ps(_mm_set1_ps(-0.0f), a);  // |a|
    if (R == FillRule::EvenOdd) {
        // v mod 2 = v − 2·trunc(v/2) (v ≥ 0, so trunc is floor), then the triangle min(v, 2 − v).
        __m128 q = _mm_cvtepi32_ps(_mm_cvttps_epi32(_mm_mul_ps(v, _mm_set1_ps(0.5f))));
        v = _mm_sub_ps(v, _mm_add_ps(q, q));
        v = _mm_min_ps(v, _mm_sub_ps(_mm_set1_ps(2.0f), v));
    }
    return _mm_min_ps(v, one);
}

// Prefix sums of 16 deltas starting at acc, carried in `carry` (all lanes equal); zeroes them.
inline void prefix16(float* acc, __m128& carry, __m128& a, __m128& b, __m128& c, __m128& d) {
    a = prefix4(_mm_loadu_ps(acc));
    b = prefix4(_mm_loadu_ps(acc + 4));
    c = prefix4(_mm_loadu_ps(acc + 8));
    d = prefix4(_mm_loadu_ps(acc + 12));
    const __m128 z = _mm_setzero_ps();
    _mm_storeu_ps(acc, z);
    _mm_storeu_ps(acc + 4, z);
    _mm_storeu_ps(acc + 8, z);
    _mm_storeu_ps(acc + 12, z);
    // Totals of the earlier vectors, off the carry's dependency chain.
    const __m128 ta = last4(a);
    const __m128 tab = _mm_add_ps(ta, last4(b));
    const __m128 tabc = _mm_add_ps(tab, last4(c));
    b = _mm_add_ps(b, ta);
    c = _mm_add_ps(c, tab);
    d = _mm_add_ps(d, tabc);
    const __m128 before = carry;
    carry = _mm_add_ps(carry, last4(d));  // the only add on the loop-carried chain
    a = _mm_add_ps(a, before);
    b = _mm_add_ps(b, before);
    c = _mm_add_ps(c, before);
    d = _mm_add_ps(d, before);
}

template <FillRule R>
void sse2_u8(float* acc, int n, std::uint8_t* out) {
    __m128 carry = _mm_setzero_ps();
    const __m128 k255 = _mm_set1_ps(255.0f);
    int i = 0;
    for (; i + 16 <= n; i += 16) {
        __m128 a, b, c, d;
        prefix16(acc + i, carry, a, b, c, d);
        // round(255·f): cvtps uses the current rounding mode, round-to-nearest by default.
        __m128i ia = _mm_cvtps_epi32(_mm_mul_ps(coverage4<R>(a), k255));
        __m128i ib = _mm_cvtps_epi32(_mm_mul_ps(coverage4<R>(b), k255));
        __m128i ic = _mm_cvtps_epi32(_mm_mul_ps(coverage4<R>(c), k255));
        __m128i id = _mm_cvtps_epi32(_mm_mul_ps(coverage4<R>(d), k255));
        __m128i bytes = _mm_packus_epi16(_mm_packs_epi32(ia, ib), _mm_packs_epi32(ic, id));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(out + i), bytes);
    }
    float sum = _mm_cvtss_f32(carry);
    for (; i < n; ++i) {
        sum += acc[i];
        acc[i] = 0.0f;
        out[i] = coverage_u8(sum, R);
    }
    acc[n] = acc[n + 1] = 0.0f;
}

template <FillRule R>
void sse2_f32(float* acc, int n, float* out) {
    __m128 carry = _mm_setzero_ps();
    int i = 0;
    for (; i + 16 <= n; i += 16) {
        __m128 a, b, c, d;
        prefix16(acc + i, carry, a, b, c, d);
        _mm_storeu_ps(out + i, coverage4<R>(a));
        _mm_storeu_ps(out + i + 4, coverage4<R>(b));
        _mm_storeu_ps(out + i + 8, coverage4<R>(c));
        _mm_storeu_ps(out + i + 12, coverage4<R>(d));
    }
    float sum = _mm_cvtss_f32(carry);
    for (; i < n; ++i) {
        sum += acc[i];
        acc[i] = 0.0f;
        out[i] = coverage_of(sum, R);
    }
    acc[n] = acc[n + 1] = 0.0f;
}

}  // namespace

const SweepKernels& scalar_kernels() {
    static const SweepKernels k{{scalar_u8<FillRule::NonZero>, scalar_u8<FillRule::EvenOdd>},
                                {scalar_f32<FillRule::NonZero>, scalar_f32<FillRule::EvenOdd>},
                                "scalar"};
    return k;
}

const SweepKernels& sse2_kernels() {
    static const SweepKernels k{{sse2_u8<FillRule::NonZero>, sse2_u8<FillRule::EvenOdd>},
                                {sse2_f32<FillRule::NonZero>, sse2_f32<FillRule::EvenOdd>},
                                "sse2"};
    return k;
}

const SweepKernels& best_kernels() {
    static const SweepKernels& k = avx2_kernels() ? *avx2_kernels() : sse2_kernels();
    return k;
}

}  // namespace bezel::raster_detail
