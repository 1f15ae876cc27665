// AVX2 sweep kernels: a column of a group (eight rows) is one 8-lane vector. Everything after
// the pragma is compiled for AVX2 and only called after __builtin_cpu_supports("avx2") said
// yes, so the library still runs on any x86-64. Standard headers come first so that they stay
// baseline code.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <utility>

#include "raster/sweep.hpp"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>

#include "raster/target_avx2.hpp"

BEZEL_AVX2_BEGIN
#include "raster/sweep_blocks.hpp"


namespace bezel::raster_detail {

namespace {

template <FillRule R>
inline __m256 coverage8(__m256 a) {
    __m256 v = _mm256_andnot_ps(_mm256_set1_ps(-0.0f), a);
    if (R == FillRule::EvenOdd) {
        __m256 q = _mm256_round_ps(_mm256_mul_ps(v, _mm256_set1_ps(0.5f)),
                                   _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC);
        v = _mm256_sub_ps(v, _mm256_add_ps(q, q));
        // min(v, 2 − v) ≤ 1 for any v (2 − v is exact for v in [1, 2]): no clamp to 1 after it.
        return _mm256_min_ps(v, _mm256_sub_ps(_mm256_set1_ps(2.0f), v));
    }
    return _mm256_min_ps(v, _mm256_set1_ps(1.0f));
}

// round(255·f) as eight int32 (cvtps rounds to nearest, the default MXCSR mode), VALID ONLY
// THROUGH A SATURATING PACK to bytes (every caller packs with packs_epi32 then packus_epi16).
// Non-zero skips coverage8's min(·, 1): round(255·|a|) saturates to 255 exactly when
// min(|a|, 1) would have given 255, so the bytes are the same. |a| is at most the winding count,
// ≤ kMaxEdges = 2²² (plus rounding), so 255·|a| < 2³¹ and the conversion cannot overflow.
// One instruction fewer per eight pixels, which shows at the larger sizes, where the sweep is
// a large share of a glyph.
template <FillRule R>
inline __m256i coverage8_u8(__m256 a) {
    static_assert(255.0 * 2.0 * kMaxEdges < 2147483648.0, "255·|winding| must fit an int32");
    if constexpr (R == FillRule::NonZero)
        return _mm256_cvtps_epi32(
            _mm256_mul_ps(_mm256_andnot_ps(_mm256_set1_ps(-0.0f), a), _mm256_set1_ps(255.0f)));
    return _mm256_cvtps_epi32(_mm256_mul_ps(coverage8<R>(a), _mm256_set1_ps(255.0f)));
}

// Four columns' running sums s₀..s₃ of the group from their deltas a₀..a₃: the carry moves by
// one add per four columns (a₀ + a₁ + a₂ + a₃ is summed off the chain), not one per column.
inline void prefix4_columns(const float* acc, __m256& carry, __m256 (&s)[4]) {
    const __m256 a0 = _mm256_load_ps(acc), a1 = _mm256_load_ps(acc + 8);
    const __m256 a2 = _mm256_load_ps(acc + 16), a3 = _mm256_load_ps(acc + 24);
    const __m256 a01 = _mm256_add_ps(a0, a1);
    s[0] = _mm256_add_ps(carry, a0);
    s[1] = _mm256_add_ps(carry, a01);
    s[2] = _mm256_add_ps(carry, _mm256_add_ps(a01, a2));
    s[3] = _mm256_add_ps(carry, _mm256_add_ps(a01, _mm256_add_ps(a2, a3)));
    carry = s[3];
}

// Zeroes a block's kBlock columns. Written out store by store: as a loop, GCC turns it into a
// memset, which it emits as `rep stos` (seen in the float sum), and that instruction's start-up
// costs more than the sixteen stores.
template <int... C>
inline void zero_stores(float* acc, std::integer_sequence<int, C...>) {
    (_mm256_store_ps(acc + 8 * C, _mm256_setzero_ps()), ...);
}
inline void zero_block(float* acc) { zero_stores(acc, std::make_integer_sequence<int, kBlock>{}); }

// Four columns of a group (acc, eight rows each) prefix-summed onto `carry` and turned into
// 8-bit coverage, as one vector whose dword r of each 128-bit lane is row r's four bytes (rows
// 0-3 in the low lane, 4-7 in the high one): the packs leave the bytes column-major
// (c₀r₀ c₀r₁ c₀r₂ c₀r₃ c₁r₀ …) and a byte shuffle makes each dword one row.
template <FillRule R>
inline __m256i four_columns_u8(const float* acc, __m256& carry) {
    const __m256i to_rows = _mm256_setr_epi8(0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15,
                                             0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15);
    __m256 s[4];
    prefix4_columns(acc, carry, s);
    const __m256i q = _mm256_packus_epi16(
        _mm256_packs_epi32(coverage8_u8<R>(s[0]), coverage8_u8<R>(s[1])),
        _mm256_packs_epi32(coverage8_u8<R>(s[2]), coverage8_u8<R>(s[3])));
    return _mm256_shuffle_epi8(q, to_rows);
}

struct Avx2Block {
    using Carry = __m256;  // lane r: the running sum of row r
    static Carry zero() { return _mm256_setzero_ps(); }
    static void clear(float* acc) { zero_block(acc); }

    // A run of 8-bit coverage, zero or not: each row's value broadcast in a register (every
    // 64-bit lane of bb holds the eight row values, so a byte shuffle by index r spreads value r
    // over the vector), then the stores of fill_group_run without its stack copies of the
    // values (a store and reload per row and run). Runs under 16 pixels (only a row's last
    // one: the others end at block borders) go through fill_group_run.
    template <FillRule R>
    static void fill(Carry c, std::uint8_t* out, std::ptrdiff_t os, int rows, int x, int end,
                     std::uint8_t*) {
        const __m256i q = coverage8_u8<R>(c);
        const __m128i w = _mm_packs_epi32(_mm256_castsi256_si128(q), _mm256_extracti128_si256(q, 1));
        const __m128i b = _mm_packus_epi16(w, w);
        const __m256i bb = _mm256_broadcastq_epi64(b);
        const int len = end - x;
        if (len >= 2 * kBlock) {
            for (int r = 0; r < rows; ++r) {
                const __m256i v = _mm256_shuffle_epi8(bb, _mm256_set1_epi8(static_cast<char>(r)));
                std::uint8_t* row = out + r * os;
                for (int p = x; p + 2 * kBlock < end; p += 2 * kBlock)
                    _mm256_storeu_si256(reinterpret_cast<__m256i*>(row + p), v);
                _mm256_storeu_si256(reinterpret_cast<__m256i*>(row + end - 2 * kBlock), v);
            }
        } else if (len >= kBlock) {
            for (int r = 0; r < rows; ++r) {
                const __m128i v = _mm256_castsi256_si128(
                    _mm256_shuffle_epi8(bb, _mm256_set1_epi8(static_cast<char>(r))));
                std::uint8_t* row = out + r * os;
                _mm_storeu_si128(reinterpret_cast<__m128i*>(row + x), v);
                _mm_storeu_si128(reinterpret_cast<__m128i*>(row + end - kBlock), v);
            }
        } else {
            alignas(8) std::uint8_t value[kGroupRows];
            _mm_storel_epi64(reinterpret_cast<__m128i*>(value), b);
            fill_group_run(out, os, rows, x, end, value);
        }
    }
    template <FillRule R>
    static void fill(Carry c, float* out, std::ptrdiff_t os, int rows, int x, int end,
                     float* value) {
        values<R>(c, value);
        fill_group_run(out, os, rows, x, end, value);
    }
    template <FillRule R>
    static void values(Carry c, std::uint8_t* v) {
        const __m256i q = coverage8_u8<R>(c);
        const __m128i w = _mm_packs_epi32(_mm256_castsi256_si128(q), _mm256_extracti128_si256(q, 1));
        _mm_storel_epi64(reinterpret_cast<__m128i*>(v), _mm_packus_epi16(w, w));
    }
    template <FillRule R>
    static void values(Carry c, float* v) {
        _mm256_storeu_ps(v, coverage8<R>(c));
    }

    // 16 columns × 8 rows to bytes, rows written out: four_columns_u8 per four columns, then two
    // rounds of unpacks gather a row's sixteen columns (low lane: row r, high lane: row r + 4).
    // 24 shuffles per 128 pixels in all.
    template <FillRule R>
    static void sum(float* acc, Carry& carry, std::uint8_t* out, std::ptrdiff_t os, int count,
                    int rows) {
        __m256i t[4];
        for (int k = 0; k < 4; ++k) t[k] = four_columns_u8<R>(acc + 32 * k, carry);
        zero_block(acc);
        const __m256i a = _mm256_unpacklo_epi32(t[0], t[1]), b = _mm256_unpackhi_epi32(t[0], t[1]);
        const __m256i c = _mm256_unpacklo_epi32(t[2], t[3]), d = _mm256_unpackhi_epi32(t[2], t[3]);
        const __m256i r[4] = {_mm256_unpacklo_epi64(a, c), _mm256_unpackhi_epi64(a, c),
                              _mm256_unpacklo_epi64(b, d), _mm256_unpackhi_epi64(b, d)};
        if (count == kBlock && rows == kGroupRows) {
            for (int k = 0; k < 4; ++k) {
                _mm_storeu_si128(reinterpret_cast<__m128i*>(out + k * os), _mm256_castsi256_si128(r[k]));
                _mm_storeu_si128(reinterpret_cast<__m128i*>(out + (k + 4) * os),
                                 _mm256_extracti128_si256(r[k], 1));
            }
            return;
        }
        alignas(32) std::uint8_t tile[kGroupRows][kBlock];
        for (int k = 0; k < 4; ++k) {
            _mm_store_si128(reinterpret_cast<__m128i*>(tile[k]), _mm256_castsi256_si128(r[k]));
            _mm_store_si128(reinterpret_cast<__m128i*>(tile[k + 4]), _mm256_extracti128_si256(r[k], 1));
        }
        for (int k = 0; k < rows; ++k) copy_bytes(out + k * os, tile[k], count);
    }

    // Floats: coverage column by column into a column-major tile, then copied out by rows.
    template <FillRule R>
    static void sum(float* acc, Carry& carry, float* out, std::ptrdiff_t os, int count, int rows) {
        alignas(32) float tile[kBlock][kGroupRows];
        for (int k = 0; k < 4; ++k) {
            __m256 s[4];
            prefix4_columns(acc + 32 * k, carry, s);
            for (int c = 0; c < 4; ++c) _mm256_store_ps(tile[4 * k + c], coverage8<R>(s[c]));
        }
        zero_block(acc);
        for (int r = 0; r < rows; ++r)
            for (int c = 0; c < count; ++c) out[r * os + c] = tile[c][r];
    }
};

template <FillRule R, typename Out>
void avx2_sweep(float* acc, std::uint8_t* flags, int n, int rows, Out* out,
                std::ptrdiff_t out_stride) {
    sweep_group<Avx2Block, R>(acc, flags, n, rows, out, out_stride);
}

// A dense band at most eight pixels wide (most glyphs at 12 px) into 8-bit coverage: per group,
// Avx2Block::sum's steps for the eight columns that are output instead of all sixteen of the
// block (the prefix sums, coverage and packing of columns 8..15 would be thrown away), each
// output row one 8-byte store. The block's sixteen columns are still zeroed: drawing writes up
// to three guard cells past the width.
template <FillRule R>
void dense_narrow_u8(float* acc, std::ptrdiff_t group_stride, int n, int rows, std::uint8_t* out,
                     std::ptrdiff_t os) {
    for (int y = 0; y < rows; y += kGroupRows, acc += group_stride, out += kGroupRows * os) {
        __m256 carry = _mm256_setzero_ps();
        const __m256i t[2] = {four_columns_u8<R>(acc, carry), four_columns_u8<R>(acc + 32, carry)};
        zero_block(acc);
        // Each 64-bit lane: one row's eight bytes, rows 0, 1 | 4, 5 and 2, 3 | 6, 7.
        const __m256i a = _mm256_unpacklo_epi32(t[0], t[1]), b = _mm256_unpackhi_epi32(t[0], t[1]);
        alignas(32) std::uint8_t tile[kGroupRows][8];
        _mm_store_si128(reinterpret_cast<__m128i*>(tile[0]), _mm256_castsi256_si128(a));
        _mm_store_si128(reinterpret_cast<__m128i*>(tile[2]), _mm256_castsi256_si128(b));
        _mm_store_si128(reinterpret_cast<__m128i*>(tile[4]), _mm256_extracti128_si256(a, 1));
        _mm_store_si128(reinterpret_cast<__m128i*>(tile[6]), _mm256_extracti128_si256(b, 1));
        const int group_rows = std::min(kGroupRows, rows - y);
        if (n == 8) {
            for (int r = 0; r < group_rows; ++r) std::memcpy(out + r * os, tile[r], 8);
        } else {
            for (int r = 0; r < group_rows; ++r) copy_tail(out + r * os, tile[r], n);
        }
    }
}

template <FillRule R, typename Out>
void avx2_dense(float* acc, std::ptrdiff_t group_stride, int n, int rows, Out* out,
                std::ptrdiff_t out_stride) {
    if constexpr (std::is_same_v<Out, std::uint8_t>) {
        if (n <= 8) return dense_narrow_u8<R>(acc, group_stride, n, rows, out, out_stride);
    }
    sweep_dense<Avx2Block, R>(acc, group_stride, n, rows, out, out_stride);
}

}  // namespace
}  // namespace bezel::raster_detail
BEZEL_AVX2_END

namespace bezel::raster_detail {

// Baseline code (outside the pragma): it runs on every CPU.
const SweepKernels* avx2_kernels() {
    static const SweepKernels k{
        {avx2_sweep<FillRule::NonZero, std::uint8_t>, avx2_sweep<FillRule::EvenOdd, std::uint8_t>},
        {avx2_sweep<FillRule::NonZero, float>, avx2_sweep<FillRule::EvenOdd, float>},
        {avx2_dense<FillRule::NonZero, std::uint8_t>, avx2_dense<FillRule::EvenOdd, std::uint8_t>},
        {avx2_dense<FillRule::NonZero, float>, avx2_dense<FillRule::EvenOdd, float>},
        "avx2"};
    return cpu_has_avx2() ? &k : nullptr;
}

}  // namespace bezel::raster_detail

#else
namespace bezel::raster_detail {
const SweepKernels* avx2_kernels() { return nullptr; }
}  // namespace bezel::raster_detail
#endif
