// Scalar and SSE2 sweep kernels, and the run-time choice between them and AVX2.
#include "raster/sweep.hpp"

#include "raster/sse2.hpp"

#include <algorithm>
#include <utility>

#include "raster/sweep_blocks.hpp"

namespace bezel::raster_detail {

namespace {

// The reference: every cell of every row summed, flags only cleared.
template <FillRule R, typename Out>
void scalar_sweep(float* acc, std::uint8_t* flags, int n, int rows, Out* out,
                  std::ptrdiff_t out_stride) {
    for (int r = 0; r < rows; ++r) {
        float sum = 0.0f;
        for (int i = 0; i < n; ++i) {
            sum += acc[i * kGroupRows + r];
            if constexpr (sizeof(Out) == 1) {
                out[r * out_stride + i] = coverage_u8(sum, R);
            } else {
                out[r * out_stride + i] = coverage_of(sum, R);
            }
        }
    }
    std::fill(acc, acc + group_cells(n), 0.0f);
    std::fill(flags, flags + row_flag_bytes(n), std::uint8_t{0});
}

// The dense reference: each group as above, with a scratch flag row (ignored, then cleared).
template <FillRule R, typename Out>
void scalar_dense(float* acc, std::ptrdiff_t group_stride, int n, int rows, Out* out,
                  std::ptrdiff_t out_stride) {
    std::uint8_t flags[row_flag_bytes(kMaxBitmapDim)];
    for (int y = 0; y < rows; y += kGroupRows)
        scalar_sweep<R>(acc + (y >> kGroupShift) * group_stride, flags, n,
                        std::min(kGroupRows, rows - y), out + y * out_stride, out_stride);
}

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

// A group column as two 4-row halves.
struct Column {
    __m128 lo, hi;  // rows 0-3, 4-7
};
inline Column add(Column a, Column b) { return {_mm_add_ps(a.lo, b.lo), _mm_add_ps(a.hi, b.hi)}; }
inline Column load_column(const float* p) { return {_mm_load_ps(p), _mm_load_ps(p + 4)}; }

// round(255·f) of a column's eight rows as eight int16 (cvtps rounds to nearest).
template <FillRule R>
inline __m128i coverage_words(Column s) {
    const __m128 k255 = _mm_set1_ps(255.0f);
    return _mm_packs_epi32(_mm_cvtps_epi32(_mm_mul_ps(coverage4<R>(s.lo), k255)),
                           _mm_cvtps_epi32(_mm_mul_ps(coverage4<R>(s.hi), k255)));
}

struct Sse2Block {
    using Carry = Column;
    static Carry zero() { return {_mm_setzero_ps(), _mm_setzero_ps()}; }
    // Store by store, not a loop, which GCC would make a `rep stos` memset (sweep_avx2.cpp).
    template <int... C>
    static void zero_stores(float* acc, std::integer_sequence<int, C...>) {
        (_mm_store_ps(acc + 4 * C, _mm_setzero_ps()), ...);
    }
    static void clear(float* acc) {
        zero_stores(acc, std::make_integer_sequence<int, kBlock * kGroupRows / 4>{});
    }

    template <FillRule R, typename Out>
    static void fill(Carry c, Out* out, std::ptrdiff_t os, int rows, int x, int end, Out* value) {
        values<R>(c, value);
        fill_group_run(out, os, rows, x, end, value);
    }
    template <FillRule R>
    static void values(Carry c, std::uint8_t* v) {
        const __m128i w = coverage_words<R>(c);
        _mm_storel_epi64(reinterpret_cast<__m128i*>(v), _mm_packus_epi16(w, w));
    }
    template <FillRule R>
    static void values(Carry c, float* v) {
        _mm_storeu_ps(v, coverage4<R>(c.lo));
        _mm_storeu_ps(v + 4, coverage4<R>(c.hi));
    }

    // The running sums of 16 columns, the carry moving by one add per four columns.
    static void prefix16(float* acc, Carry& carry, Column (&s)[kBlock]) {
        for (int k = 0; k < kBlock; k += 4) {
            const float* a = acc + k * kGroupRows;
            const Column a0 = load_column(a), a1 = load_column(a + 8);
            const Column a2 = load_column(a + 16), a3 = load_column(a + 24);
            const Column a01 = add(a0, a1);
            s[k] = add(carry, a0);
            s[k + 1] = add(carry, a01);
            s[k + 2] = add(carry, add(a01, a2));
            s[k + 3] = add(carry, add(a01, add(a2, a3)));
            carry = s[k + 3];
        }
        clear(acc);
    }

    // Bytes: two columns per vector (column-major), transposed to rows by four rounds of
    // unpacks (SSE2 has no byte shuffle).
    template <FillRule R>
    static void sum(float* acc, Carry& carry, std::uint8_t* out, std::ptrdiff_t os, int count,
                    int rows) {
        Column s[kBlock];
        prefix16(acc, carry, s);
        __m128i p[8];  // p[k]: column 2k rows 0-7, column 2k+1 rows 0-7
        for (int k = 0; k < 8; ++k)
            p[k] = _mm_packus_epi16(coverage_words<R>(s[2 * k]), coverage_words<R>(s[2 * k + 1]));
        // Each row's two columns as one word: w[k] word r = (column 2k, column 2k+1) of row r.
        __m128i w[8];
        for (int k = 0; k < 8; ++k) w[k] = _mm_unpacklo_epi8(p[k], _mm_srli_si128(p[k], 8));
        // Four columns per dword: d[m] dword r = columns 4m..4m+3 of row r (rows 0-3 in lo).
        __m128i dlo[4], dhi[4];
        for (int m = 0; m < 4; ++m) {
            dlo[m] = _mm_unpacklo_epi16(w[2 * m], w[2 * m + 1]);
            dhi[m] = _mm_unpackhi_epi16(w[2 * m], w[2 * m + 1]);
        }
        alignas(16) std::uint8_t tile[kGroupRows][kBlock];
        const __m128i* half[2] = {dlo, dhi};
        for (int h = 0; h < 2; ++h) {
            const __m128i* d = half[h];
            // Rows (4h, 4h+1) of columns 0-7 and 8-15, then whole rows.
            const __m128i q01a = _mm_unpacklo_epi32(d[0], d[1]), q23a = _mm_unpackhi_epi32(d[0], d[1]);
            const __m128i q01b = _mm_unpacklo_epi32(d[2], d[3]), q23b = _mm_unpackhi_epi32(d[2], d[3]);
            _mm_store_si128(reinterpret_cast<__m128i*>(tile[4 * h]), _mm_unpacklo_epi64(q01a, q01b));
            _mm_store_si128(reinterpret_cast<__m128i*>(tile[4 * h + 1]), _mm_unpackhi_epi64(q01a, q01b));
            _mm_store_si128(reinterpret_cast<__m128i*>(tile[4 * h + 2]), _mm_unpacklo_epi64(q23a, q23b));
            _mm_store_si128(reinterpret_cast<__m128i*>(tile[4 * h + 3]), _mm_unpackhi_epi64(q23a, q23b));
        }
        for (int r = 0; r < rows; ++r) copy_bytes(out + r * os, tile[r], count);
    }

    template <FillRule R>
    static void sum(float* acc, Carry& carry, float* out, std::ptrdiff_t os, int count, int rows) {
        Column s[kBlock];
        prefix16(acc, carry, s);
        alignas(16) float tile[kBlock][kGroupRows];
        for (int c = 0; c < kBlock; ++c) {
            _mm_store_ps(tile[c], coverage4<R>(s[c].lo));
            _mm_store_ps(tile[c] + 4, coverage4<R>(s[c].hi));
        }
        for (int r = 0; r < rows; ++r)
            for (int c = 0; c < count; ++c) out[r * os + c] = tile[c][r];
    }
};

template <FillRule R, typename Out>
void sse2_sweep(float* acc, std::uint8_t* flags, int n, int rows, Out* out,
                std::ptrdiff_t out_stride) {
    sweep_group<Sse2Block, R>(acc, flags, n, rows, out, out_stride);
}

template <FillRule R, typename Out>
void sse2_dense(float* acc, std::ptrdiff_t group_stride, int n, int rows, Out* out,
                std::ptrdiff_t out_stride) {
    sweep_dense<Sse2Block, R>(acc, group_stride, n, rows, out, out_stride);
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

}  // namespace bezel::raster_detail
