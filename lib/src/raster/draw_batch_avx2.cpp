// The segment batches for AVX2: draw_batch.hpp's (marked bands) four segments at a time, and
// dense_batch.hpp's (dense bands) eight float segments at a time. Everything after the
// pragma is compiled for AVX2 and only called after __builtin_cpu_supports("avx2") said yes; the
// headers come first, so that their inline functions stay baseline code — all but
// dense_batch.hpp, included after the pragma to be compiled for AVX2 here (internal linkage).
//
// The lane arithmetic is draw_batch's, operation for operation in the same order (no FMA: this
// file is compiled for AVX2 only), so the band it leaves is the SSE2 loop's bit for bit, and the
// segments it turns down go the same way (draw_or_split, then draw_lines). What changes is the
// per-segment part: each lane's row, column and three values are read back from one store of
// each vector instead of being shuffled out one by one (the cell address is then scalar
// integer work, NarrowFour); and the segments kSplit cuts are listed, not
// appended as halves: after the fast lanes they are drawn four at a time, both pieces of each
// computed in registers (x at the row border as draw_or_split has it) and added in the order the
// SSE2 loop adds its appended halves. That saves classifying the halves a second time, which
// matters at small sizes, where cut segments are a large share of a glyph (docs/perf-log.md).
#include <cstdint>

#include "raster/draw_batch.hpp"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>

#include "raster/target_avx2.hpp"

BEZEL_AVX2_BEGIN

// Compiled here for AVX2 (internal linkage; see its header comment).
#include "raster/dense_batch.hpp"

namespace bezel::raster_detail {

namespace {

// dense_batch.hpp's lane policy for eight lanes of AVX2: F4's operations, eight floats each.
struct F8 {
    using V = __m256;
    using I = __m256i;
    static constexpr int kLanes = 8;
    static V set1(float v) { return _mm256_set1_ps(v); }
    static V add(V a, V b) { return _mm256_add_ps(a, b); }
    static V sub(V a, V b) { return _mm256_sub_ps(a, b); }
    static V mul(V a, V b) { return _mm256_mul_ps(a, b); }
    static V div(V a, V b) { return _mm256_div_ps(a, b); }
    static V min(V a, V b) { return _mm256_min_ps(a, b); }
    static V max(V a, V b) { return _mm256_max_ps(a, b); }
    static V cmp_le(V a, V b) { return _mm256_cmp_ps(a, b, _CMP_LE_OS); }
    static V cmp_gt(V a, V b) { return _mm256_cmp_ps(a, b, _CMP_GT_OS); }
    static V cmp_eq(V a, V b) { return _mm256_cmp_ps(a, b, _CMP_EQ_OQ); }
    static V bit_and(V a, V b) { return _mm256_and_ps(a, b); }
    static V andnot(V a, V b) { return _mm256_andnot_ps(a, b); }
    static I cvtt(V a) { return _mm256_cvttps_epi32(a); }
    static V cvt(I a) { return _mm256_cvtepi32_ps(a); }
    static int movemask(V a) { return _mm256_movemask_ps(a); }
    static void store(float* p, V a) { _mm256_store_ps(p, a); }
    static V load_f(const float* p) { return _mm256_load_ps(p); }
    static V iota() { return _mm256_setr_ps(0.0f, 1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f, 7.0f); }
    static void store_int(int* p, I a) { _mm256_store_si256(reinterpret_cast<__m256i*>(p), a); }
    // Eight (x0, y0, x1, y1) segments transposed to one coordinate per vector: lanes 0-3 from
    // s[0..3], lanes 4-7 from s[4..7], each half as F4::transpose.
    static __m256 pair(__m128 lo, __m128 hi) {
        return _mm256_insertf128_ps(_mm256_castps128_ps256(lo), hi, 1);
    }
    static DenseSegs<F8> transpose(const __m128* s[8]) {
        const __m256 v0 = pair(*s[0], *s[4]), v1 = pair(*s[1], *s[5]);
        const __m256 v2 = pair(*s[2], *s[6]), v3 = pair(*s[3], *s[7]);
        const __m256 t0 = _mm256_unpacklo_ps(v0, v1), t1 = _mm256_unpackhi_ps(v0, v1);
        const __m256 t2 = _mm256_unpacklo_ps(v2, v3), t3 = _mm256_unpackhi_ps(v2, v3);
        return {_mm256_shuffle_ps(t0, t2, 0x44), _mm256_shuffle_ps(t0, t2, 0xEE),
                _mm256_shuffle_ps(t1, t3, 0x44), _mm256_shuffle_ps(t1, t3, 0xEE)};
    }
    static DenseSegs<F8> load(const __m128* f) {
        const __m128* s[8] = {f, f + 1, f + 2, f + 3, f + 4, f + 5, f + 6, f + 7};
        return transpose(s);
    }
    static DenseSegs<F8> gather(const __m128* f, const int* idx) {
        const __m128* s[8] = {f + idx[0], f + idx[1], f + idx[2], f + idx[3],
                              f + idx[4], f + idx[5], f + idx[6], f + idx[7]};
        return transpose(s);
    }
};

// Four segments' ends, transposed to one coordinate per register: seg[k..k+3].
struct Four {
    __m256d x0, y0, x1, y1;
};
inline Four load_four(const SegmentBatch::Segment* s) {
    const __m256d a02 = _mm256_insertf128_pd(_mm256_castpd128_pd256(s[0].a), s[2].a, 1);
    const __m256d a13 = _mm256_insertf128_pd(_mm256_castpd128_pd256(s[1].a), s[3].a, 1);
    const __m256d b02 = _mm256_insertf128_pd(_mm256_castpd128_pd256(s[0].b), s[2].b, 1);
    const __m256d b13 = _mm256_insertf128_pd(_mm256_castpd128_pd256(s[1].b), s[3].b, 1);
    return {_mm256_unpacklo_pd(a02, a13), _mm256_unpackhi_pd(a02, a13),
            _mm256_unpacklo_pd(b02, b13), _mm256_unpackhi_pd(b02, b13)};
}

// Four segments gathered by index: s[idx[0..3]].
inline Four gather_four(const SegmentBatch::Segment* s, const int* idx) {
    const __m256d a02 =
        _mm256_insertf128_pd(_mm256_castpd128_pd256(s[idx[0]].a), s[idx[2]].a, 1);
    const __m256d a13 =
        _mm256_insertf128_pd(_mm256_castpd128_pd256(s[idx[1]].a), s[idx[3]].a, 1);
    const __m256d b02 =
        _mm256_insertf128_pd(_mm256_castpd128_pd256(s[idx[0]].b), s[idx[2]].b, 1);
    const __m256d b13 =
        _mm256_insertf128_pd(_mm256_castpd128_pd256(s[idx[1]].b), s[idx[3]].b, 1);
    return {_mm256_unpacklo_pd(a02, a13), _mm256_unpackhi_pd(a02, a13),
            _mm256_unpacklo_pd(b02, b13), _mm256_unpackhi_pd(b02, b13)};
}

// The cells four narrow pieces add to (draw_batch's lane arithmetic): three values and the row
// and first column of each lane. The cell's address is then found per lane by scalar integer
// code (add_narrow), not in the vector: more instructions, yet no slower and at small sizes
// slightly faster (docs/perf-log.md), plausibly because the integer ALUs are otherwise idle
// while the vector pipes carry the lane arithmetic (not confirmed with hardware counters).
struct NarrowFour {
    alignas(16) float c0[4], c1[4], c2[4];
    alignas(16) int row[4], col[4];
};

// Pieces s (each inside one row and two columns; the fast test) into `out`; the values of lanes
// whose `keep` is zero are zeros.
inline void narrow_four(const Four& s, __m128 keep, NarrowFour& out) {
    const __m256d one = _mm256_set1_pd(1.0), half = _mm256_set1_pd(0.5);
    const __m256d tiny = _mm256_set1_pd(1e-300);
    const __m256d ylo = _mm256_min_pd(s.y0, s.y1);
    const __m128i j = _mm256_cvttpd_epi32(ylo);  // floor: y > −1
    const __m256d lo = _mm256_min_pd(s.x0, s.x1), hi = _mm256_max_pd(s.x0, s.x1);
    const __m256d w = _mm256_sub_pd(hi, lo);
    const __m128i i = _mm256_cvttpd_epi32(lo);
    const __m256d X = _mm256_add_pd(_mm256_cvtepi32_pd(i), one);
    const __m256d xm = _mm256_min_pd(hi, X);
    const __m256d dy = _mm256_sub_pd(s.y1, s.y0);
    const __m256d dy1 =
        _mm256_mul_pd(dy, _mm256_div_pd(_mm256_sub_pd(hi, xm), _mm256_max_pd(w, tiny)));
    const __m256d dy0 = _mm256_sub_pd(dy, dy1);
    const __m256d r0 = _mm256_mul_pd(
        dy0, _mm256_sub_pd(_mm256_mul_pd(half, _mm256_add_pd(lo, xm)), _mm256_sub_pd(X, one)));
    const __m256d r1 =
        _mm256_mul_pd(dy1, _mm256_sub_pd(_mm256_mul_pd(half, _mm256_add_pd(xm, hi)), X));
    _mm_store_ps(out.c0, _mm_and_ps(keep, _mm256_cvtpd_ps(_mm256_sub_pd(dy0, r0))));
    _mm_store_ps(out.c1,
                 _mm_and_ps(keep, _mm256_cvtpd_ps(_mm256_add_pd(r0, _mm256_sub_pd(dy1, r1)))));
    _mm_store_ps(out.c2, _mm_and_ps(keep, _mm256_cvtpd_ps(r1)));
    _mm_store_si128(reinterpret_cast<__m128i*>(out.row), j);
    _mm_store_si128(reinterpret_cast<__m128i*>(out.col), i);
}

template <bool kMark>
inline void add_narrow(const Band& band, const NarrowFour& v, int l) {
    add_three_cells<kMark>(row_of(band, v.row[l]), flags_of(band, v.row[l]), v.col[l], v.c0[l],
                           v.c1[l], v.c2[l]);
}

template <bool kMark, bool kSplit>
void draw_batch_four(const Band& band, SegmentBatch& b, int n) {
    SegmentBatch::Segment* const seg = b.seg;
    constexpr int kSize = SegmentBatch::kSize;
    alignas(16) int cut_idx[kSize + 4];
    int ncut = 0, nslow = 0;
    const __m256d one = _mm256_set1_pd(1.0);
    const __m128 all = _mm_castsi128_ps(_mm_set1_epi32(-1));
    // A short tail is padded with horizontal segments, which draw nothing.
    for (int p = n; p < ((n + 3) & ~3); ++p) seg[p] = {_mm_setzero_pd(), _mm_setzero_pd()};
    for (int k = 0; k < n; k += 4) {
        const Four s = load_four(seg + k);
        const __m256d ylo = _mm256_min_pd(s.y0, s.y1), yhi = _mm256_max_pd(s.y0, s.y1);
        const __m128i j = _mm256_cvttpd_epi32(ylo);  // floor: y > −1
        const __m256d lo = _mm256_min_pd(s.x0, s.x1), hi = _mm256_max_pd(s.x0, s.x1);
        const __m256d X = _mm256_add_pd(_mm256_cvtepi32_pd(_mm256_cvttpd_epi32(lo)), one);
        const __m256d border = _mm256_add_pd(_mm256_cvtepi32_pd(j), one);
        const __m256d flat = _mm256_cmp_pd(s.y0, s.y1, _CMP_EQ_OQ);
        const __m256d fast = _mm256_andnot_pd(
            flat, _mm256_and_pd(_mm256_cmp_pd(yhi, border, _CMP_LE_OQ),
                                _mm256_cmp_pd(hi, _mm256_add_pd(X, one), _CMP_LE_OQ)));
        const int mask = _mm256_movemask_pd(fast);
        // Lanes the general code draws (stems, long or wide segments); horizontal ones draw
        // nothing anywhere, so they are dropped here rather than set aside.
        const int slow = ~(mask | _mm256_movemask_pd(flat)) & 15;
        if (slow != 0) {
            int cuts = 0;
            if constexpr (kSplit) {
                // draw_or_split's test for the four lanes at once: the cut ones are drawn after
                // the fast ones, both halves per lane (below).
                const __m256d cut = _mm256_and_pd(
                    _mm256_and_pd(_mm256_cmp_pd(yhi, border, _CMP_GT_OQ),
                                  _mm256_cmp_pd(yhi, _mm256_add_pd(border, one), _CMP_LE_OQ)),
                    _mm256_cmp_pd(_mm256_sub_pd(hi, lo), one, _CMP_LE_OQ));
                cuts = _mm256_movemask_pd(cut) & slow;
                for (int l = 0; l < 4; ++l)
                    if (cuts & (1 << l)) cut_idx[ncut++] = k + l;
            }
            for (int l = 0; l < 4; ++l)
                if ((slow & ~cuts) & (1 << l)) b.slow[nslow++] = seg[k + l];
            if (mask == 0) continue;
        }
        NarrowFour v;
        narrow_four(s, all, v);
        if (mask == 15) {
            add_narrow<kMark>(band, v, 0);
            add_narrow<kMark>(band, v, 1);
            add_narrow<kMark>(band, v, 2);
            add_narrow<kMark>(band, v, 3);
        } else {
            for (int l = 0; l < 4; ++l)
                if (mask & (1 << l)) add_narrow<kMark>(band, v, l);
        }
    }
    if (kSplit && ncut > 0) {
        // Each cut segment is two narrow pieces, one each side of the row border it crosses:
        // (a, m) and (m, b), m at the border with x by draw_or_split's formula. Added in that
        // order, segment after segment (the order the SSE2 loop adds its appended halves in),
        // four segments a step; the last step repeats its last segment with zero values.
        for (int p = ncut; p < ncut + 3; ++p) cut_idx[p] = cut_idx[ncut - 1];
        const __m128i lanes = _mm_setr_epi32(0, 1, 2, 3);
        for (int c = 0; c < ncut; c += 4) {
            const Four s = gather_four(seg, cut_idx + c);
            const __m256d border = _mm256_add_pd(
                _mm256_cvtepi32_pd(_mm256_cvttpd_epi32(_mm256_min_pd(s.y0, s.y1))), one);
            const __m256d xm = _mm256_add_pd(
                s.x0, _mm256_mul_pd(_mm256_sub_pd(border, s.y0),
                                    _mm256_div_pd(_mm256_sub_pd(s.x1, s.x0),
                                                  _mm256_sub_pd(s.y1, s.y0))));
            const __m128 keep =
                _mm_castsi128_ps(_mm_cmpgt_epi32(_mm_set1_epi32(ncut - c), lanes));
            NarrowFour first, second;
            narrow_four(Four{s.x0, s.y0, xm, border}, keep, first);
            narrow_four(Four{xm, border, s.x1, s.y1}, keep, second);
            for (int l = 0; l < 4; ++l) {
                add_narrow<kMark>(band, first, l);
                add_narrow<kMark>(band, second, l);
            }
        }
    }
    batch_detail::draw_lines<kMark>(band, b.slow, nslow);
}

}  // namespace
}  // namespace bezel::raster_detail
BEZEL_AVX2_END

namespace bezel::raster_detail {

// Baseline code (outside the pragma): it runs on every CPU.
const BatchKernels* avx2_batch_kernels() {
    static const BatchKernels k{draw_dense_batch<F8>,
                                {draw_batch_four<true, false>, draw_batch_four<true, true>}};
    return cpu_has_avx2() ? &k : nullptr;
}

}  // namespace bezel::raster_detail

#else
namespace bezel::raster_detail {
const BatchKernels* avx2_batch_kernels() { return nullptr; }
}  // namespace bezel::raster_detail
#endif
