// Scalar and SSE2 sweep kernels, and the run-time choice between them and AVX2.
#include "raster/sweep.hpp"

#include <emmintrin.h>

#include "raster/sweep_blocks.hpp"

namespace bezel::raster_detail {

namespace {

// The reference: every cell summed, flags only cleared.
template <FillRule R, typename Out>
void scalar_sweep(float* acc, std::uint8_t* flags, int n, Out* out) {
    float sum = 0.0f;
    for (int i = 0; i < n; ++i) {
        sum += acc[i];
        if constexpr (sizeof(Out) == 1) {
            out[i] = coverage_u8(sum, R);
        } else {
            out[i] = coverage_of(sum, R);
        }
    }
    std::fill(acc, acc + row_cells(n), 0.0f);
    std::fill(flags, flags + row_flag_bytes(n), std::uint8_t{0});
}

// The dense reference: each row as above, with a scratch flag row (ignored, then cleared).
template <FillRule R, typename Out>
void scalar_dense(float* acc, std::ptrdiff_t stride, int n, int rows, Out* out,
                  std::ptrdiff_t out_stride) {
    std::uint8_t flags[row_flag_bytes(kMaxBitmapDim)];
    for (int r = 0; r < rows; ++r) scalar_sweep<R>(acc + r * stride, flags, n, out + r * out_stride);
}

// In-register inclusive prefix sum of 4 floats: x + (x << 1 lane) + (x << 2 lanes).
inline __m128 prefix4(__m128 x) {
    x = _mm_add_ps(x, _mm_castsi128_ps(_mm_slli_si128(_mm_castps_si128(x), 4)));
    return _mm_add_ps(x, _mm_castsi128_ps(_mm_slli_si128(_mm_castps_si128(x), 8)));
}
inline __m128 last4(__m128 x) { return _mm_shuffle_ps(x, x, 0xFF); }

template <FillRule R>
inline __m128 coverage4(__m128 a) {
    __m128 v = _mm_andnot_ps(_mm_set1_ps(-0.0f), a);  // |a|
    if (R == FillRule::EvenOdd) {
        // v mod 2 = v − 2·trunc(v/2) (v ≥ 0, so trunc is floor), then the triangle min(v, 2 − v).
        __m128 q = _mm_cvtepi32_ps(_mm_cvttps_epi32(_mm_mul_ps(v, _mm_set1_ps(0.5f))));
        v = _mm_sub_ps(v, _mm_add_ps(q, q));
        v = _mm_min_ps(v, _mm_sub_ps(_mm_set1_ps(2.0f), v));
    }
    return _mm_min_ps(v, _mm_set1_ps(1.0f));
}

struct Sse2Block {
    using Carry = __m128;
    static Carry zero() { return _mm_setzero_ps(); }
    static float first(Carry c) { return _mm_cvtss_f32(c); }

    // 16 cells as 4 vectors. The totals of the earlier vectors are added off the carry's
    // dependency chain; the chain itself is one add per block.
    static void prefix16(float* acc, Carry& carry, __m128 (&v)[4]) {
        for (int k = 0; k < 4; ++k) {
            v[k] = prefix4(_mm_loadu_ps(acc + 4 * k));
            _mm_storeu_ps(acc + 4 * k, _mm_setzero_ps());
        }
        const __m128 t0 = last4(v[0]);
        const __m128 t01 = _mm_add_ps(t0, last4(v[1]));
        const __m128 t012 = _mm_add_ps(t01, last4(v[2]));
        v[1] = _mm_add_ps(v[1], t0);
        v[2] = _mm_add_ps(v[2], t01);
        v[3] = _mm_add_ps(v[3], t012);
        const __m128 before = carry;
        carry = _mm_add_ps(carry, last4(v[3]));
        for (int k = 0; k < 4; ++k) v[k] = _mm_add_ps(v[k], before);
    }

    template <FillRule R>
    static void sum(float* acc, Carry& carry, std::uint8_t* out, int count) {
        __m128 v[4];
        prefix16(acc, carry, v);
        // round(255·f): cvtps rounds to nearest (the default MXCSR mode).
        const __m128 k255 = _mm_set1_ps(255.0f);
        __m128i q[4];
        for (int k = 0; k < 4; ++k) q[k] = _mm_cvtps_epi32(_mm_mul_ps(coverage4<R>(v[k]), k255));
        const __m128i bytes = _mm_packus_epi16(_mm_packs_epi32(q[0], q[1]), _mm_packs_epi32(q[2], q[3]));
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
        __m128 v[4];
        prefix16(acc, carry, v);
        alignas(16) float tmp[kBlock];
        float* dst = count == kBlock ? out : tmp;
        for (int k = 0; k < 4; ++k) _mm_storeu_ps(dst + 4 * k, coverage4<R>(v[k]));
        if (dst == tmp) std::memcpy(out, tmp, sizeof(float) * static_cast<std::size_t>(count));
    }
};

template <FillRule R, typename Out>
void sse2_sweep(float* acc, std::uint8_t* flags, int n, Out* out) {
    sweep_blocks<Sse2Block, R>(acc, flags, n, out);
}

template <FillRule R, typename Out>
void sse2_dense(float* acc, std::ptrdiff_t stride, int n, int rows, Out* out,
              std::ptrdiff_t out_stride) {
    sweep_dense<Sse2Block, R>(acc, stride, n, rows, out, out_stride);
}

}  // namespace

const SweepKernels& scalar_kernels() {
    static const SweepKernels k{
        {scalar_sweep<FillRule::NonZero, std::uint8_t>, scalar_sweep<FillRule::EvenOdd, std::uint8_t>},
        {scalar_sweep<FillRule::NonZero, float>, scalar_sweep<FillRule::EvenOdd, float>},
        {scalar_dense<FillRule::NonZero, std::uint8_t>, scalar_dense<FillRule::EvenOdd, std::uint8_t>},
        {scalar_dense<FillRule::NonZero, float>, scalar_dense<FillRule::EvenOdd, float>},
        "scalar"};
    return k;
}

const SweepKernels& sse2_kernels() {
    static const SweepKernels k{
        {sse2_sweep<FillRule::NonZero, std::uint8_t>, sse2_sweep<FillRule::EvenOdd, std::uint8_t>},
        {sse2_sweep<FillRule::NonZero, float>, sse2_sweep<FillRule::EvenOdd, float>},
        {sse2_dense<FillRule::NonZero, std::uint8_t>, sse2_dense<FillRule::EvenOdd, std::uint8_t>},
        {sse2_dense<FillRule::NonZero, float>, sse2_dense<FillRule::EvenOdd, float>},
        "sse2"};
    return k;
}

const SweepKernels& best_kernels() {
    static const SweepKernels& k = avx2_kernels() ? *avx2_kernels() : sse2_kernels();
    return k;
}

}  // namespace bezel::raster_detail
