// Private: drawing a batch of segments two at a time (SSE2, every x86-64 CPU).
//
// At small sizes most segments lie inside one pixel row and span at most two columns (DejaVu
// Sans at 12 px: 67 % of them, at 24 px 59 %; most of the others cross one row border, a few
// are stems), and such a segment is three cell updates of draw_line's narrow piece
// (accumulate.hpp). Scalar, that is about a hundred instructions a segment, most of them the
// prologue that decides which case applies and orients the edge. Here the decision and the
// arithmetic are done for two segments per instruction in double precision (the operations of
// add_narrow_piece, the scalar reference), and only the cell updates are per segment.
// With kSplit, a segment that crosses one row border and moves at most 1 in x is cut there into
// two such pieces (at 48 px: 30 of 69 segments a glyph, two thirds of them stems); other
// segments are set aside and drawn by draw_line after the pair loop (see draw_lines). Cutting
// here pays in dense boxes of 32 rows or more (48-96 px) and costs in smaller boxes and in
// sparse bands, so with this loop direct_fill.cpp asks for it only there (docs/perf-log.md).
// On AVX2 CPUs the direct route uses the four-lane copy of this loop (draw_batch_avx2.cpp),
// which leaves the same band. This loop stays the
// reference and the baseline for marked (sparse) bands. Dense bands now take the float batch
// of dense_batch.hpp instead, on every CPU; this loop, in double, is the reference it is
// tested against (within float rounding).
#pragma once

#include "raster/sse2.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "raster/accumulate.hpp"

namespace bezel::raster_detail {

// Segment k runs from seg[k].a to seg[k].b, band coordinates as draw_line takes them; an odd
// batch is padded with a horizontal segment, which draws nothing. Points are stored and loaded
// whole (16 bytes), so no load spans two smaller stores that may still sit in the store buffer
// (such a load cannot be forwarded); against separate x/y arrays this measured the same.
struct SegmentBatch {
    static constexpr int kSize = 64;  // queued by the walk
    struct Segment {
        __m128d a, b;  // (x, y)
    };
    // kSize queued segments, then room for the halves of every one cut in two and for padding
    // to a multiple of four (draw_batch_avx2.cpp).
    Segment seg[3 * kSize + 4];
    Segment slow[kSize + 1];  // those the pair kernel turned down (the padding one included)
    // A dense band's segments instead (dense_batch.hpp): (x0, y0, x1, y1) in float, and room to
    // pad to a multiple of eight.
    __m128 fseg[kSize + 8];
};

namespace batch_detail {

template <bool kMark>
inline void add_cells(const Band& band, int j, int i, float c0, float c1, float c2) {
    add_three_cells<kMark>(row_of(band, j), flags_of(band, j), i, c0, c1, c2);
}

// A segment the pair test turned down. One that crosses exactly one row border and moves at
// most 1 in x is cut at the border into two one-row pieces, appended at seg[end] for the pair
// kernel (DejaVu Sans at 12 px: about 10 of 39 segments a glyph, 30 of 69 at 48 px); anything
// else is set aside in b.slow for draw_lines. x at the border is draw_line's formula.
template <bool kMark, bool kSplit>
inline void draw_or_split(SegmentBatch& b, const SegmentBatch::Segment& s, int& end, int& nslow) {
    SegmentBatch::Segment* const seg = b.seg;
    const double x0 = _mm_cvtsd_f64(s.a), y0 = _mm_cvtsd_f64(_mm_unpackhi_pd(s.a, s.a));
    const double x1 = _mm_cvtsd_f64(s.b), y1 = _mm_cvtsd_f64(_mm_unpackhi_pd(s.b, s.b));
    const double ylo = std::min(y0, y1), yhi = std::max(y0, y1);
    const double border = static_cast<double>(static_cast<int>(ylo) + 1);  // ylo > −1
    if (kSplit && yhi > border && yhi <= border + 1.0 && std::fabs(x1 - x0) <= 1.0) {
        const double xm = x0 + (border - y0) * ((x1 - x0) / (y1 - y0));
        const __m128d m = _mm_set_pd(border, xm);
        seg[end++] = {s.a, m};
        seg[end++] = {m, s.b};
        return;
    }
    b.slow[nslow++] = s;
}

// The set-aside segments, after the pair loop, with draw_line inlined into one loop. Called from
// the pair loop instead, each draw_line would pay a call (about 60 instructions of saves,
// restores and moving the lane's coordinates out) and the pair loop would spill its constants
// around it.
// Deferring only reorders float additions into the band.
// Internal linkage: draw_batch_avx2.cpp calls it too; it includes this header before its AVX2
// region, but should a copy ever be compiled for AVX2, the linker must not pick it for the
// baseline callers (target_avx2.hpp).
namespace {
template <bool kMark>
[[gnu::noinline, gnu::flatten]] void draw_lines(const Band& band, const SegmentBatch::Segment* s,
                                                int n) {
    for (int k = 0; k < n; ++k) {
        const __m128d a = s[k].a, b = s[k].b;
        draw_line<kMark>(band, _mm_cvtsd_f64(a), _mm_cvtsd_f64(_mm_unpackhi_pd(a, a)),
                         _mm_cvtsd_f64(b), _mm_cvtsd_f64(_mm_unpackhi_pd(b, b)));
    }
}
}  // namespace

}  // namespace batch_detail

// The AVX2 batches (draw_batch_avx2.cpp), each the same band bit for bit as its baseline loop;
// n need not be even (no padding segment).
using BatchFn = void (*)(const Band& band, SegmentBatch& b, int n);
struct BatchKernels {
    BatchFn dense;      // draw_dense_batch (dense_batch.hpp), eight float segments a step
    BatchFn marked[2];  // draw_batch for marked (sparse) bands, four a step; [kSplit]
};
// Null when the CPU (or the build) has no AVX2; kernel_table() (kernels.hpp) says whether
// fills use them.
const BatchKernels* avx2_batch_kernels();

// Draws segments [0, n) of `b` into `band` (draw_line's preconditions for each; an odd batch
// padded at seg[n] with a horizontal segment, which draws nothing). The halves of cut segments
// are appended behind the queue and drawn by the same loop: two at a time, so the count stays
// even.
// A pair's lanes are tested together: fast = (y0 ≠ y1) ∧ (max y ≤ ⌊min y⌋ + 1) ∧
// (max x ≤ ⌊min x⌋ + 2); then, per lane, i = ⌊lo⌋, xm = min(hi, i + 1),
// dy₁ = dy·(hi − xm)/|dx| (the part right of the column border; 0 for a vertical piece, whose
// hi − xm is exactly 0) and the three cell values of add_narrow_piece.
// The test is "inside one row and two columns", which add_narrow_piece draws exactly whatever
// the width (within_two_columns; a piece ending on the far border at ⌊min x⌋ + 2 adds its
// second column's half to the cell after it, as it should). So the one-row shallow pieces of
// 48-96 px (about 9 a glyph at 64 px) are drawn here too, not by draw_line.
// Slow lanes are branched around, not masked into zero updates: the branches predict well,
// and masked lanes add work to every step (slower in both forms tried, docs/perf-log.md).
template <bool kMark, bool kSplit>
inline void draw_batch(const Band& band, SegmentBatch& b, int n) {
    SegmentBatch::Segment* const seg = b.seg;
    int end = (n + 1) & ~1;  // with the padding segment
    int nslow = 0;
    const __m128d one = _mm_set1_pd(1.0), half = _mm_set1_pd(0.5), tiny = _mm_set1_pd(1e-300);
    for (int k = 0; k < end; k += 2) {
        // Two segments' ends, transposed to one coordinate per register.
        const __m128d a0 = seg[k].a, b0 = seg[k].b, a1 = seg[k + 1].a, b1 = seg[k + 1].b;
        const __m128d x0 = _mm_unpacklo_pd(a0, a1), y0 = _mm_unpackhi_pd(a0, a1);
        const __m128d x1 = _mm_unpacklo_pd(b0, b1), y1 = _mm_unpackhi_pd(b0, b1);
        const __m128d ylo = _mm_min_pd(y0, y1), yhi = _mm_max_pd(y0, y1);
        const __m128i j = _mm_cvttpd_epi32(ylo);  // floor: y > −1
        const __m128d lo = _mm_min_pd(x0, x1), hi = _mm_max_pd(x0, x1);
        const __m128d w = _mm_sub_pd(hi, lo);
        const __m128i i = _mm_cvttpd_epi32(lo);
        const __m128d X = _mm_add_pd(_mm_cvtepi32_pd(i), one);
        const __m128d fast =
            _mm_and_pd(_mm_and_pd(_mm_cmple_pd(yhi, _mm_add_pd(_mm_cvtepi32_pd(j), one)),
                                  _mm_cmple_pd(hi, _mm_add_pd(X, one))),
                       _mm_cmpneq_pd(y0, y1));
        const int mask = _mm_movemask_pd(fast);
        if (mask != 3) {  // a lane the general code draws (stems, long or wide segments)
            if (!(mask & 1)) batch_detail::draw_or_split<kMark, kSplit>(b, seg[k], end, nslow);
            if (!(mask & 2)) batch_detail::draw_or_split<kMark, kSplit>(b, seg[k + 1], end, nslow);
            if (mask == 0) continue;
        }
        const __m128d xm = _mm_min_pd(hi, X);
        const __m128d dy = _mm_sub_pd(y1, y0);
        const __m128d dy1 = _mm_mul_pd(dy, _mm_div_pd(_mm_sub_pd(hi, xm), _mm_max_pd(w, tiny)));
        const __m128d dy0 = _mm_sub_pd(dy, dy1);
        const __m128d r0 =
            _mm_mul_pd(dy0, _mm_sub_pd(_mm_mul_pd(half, _mm_add_pd(lo, xm)), _mm_sub_pd(X, one)));
        const __m128d r1 = _mm_mul_pd(dy1, _mm_sub_pd(_mm_mul_pd(half, _mm_add_pd(xm, hi)), X));
        const __m128 c0 = _mm_cvtpd_ps(_mm_sub_pd(dy0, r0));
        const __m128 c1 = _mm_cvtpd_ps(_mm_add_pd(r0, _mm_sub_pd(dy1, r1)));
        const __m128 c2 = _mm_cvtpd_ps(r1);
        if (mask & 1)
            batch_detail::add_cells<kMark>(band, _mm_cvtsi128_si32(j), _mm_cvtsi128_si32(i),
                                           _mm_cvtss_f32(c0), _mm_cvtss_f32(c1),
                                           _mm_cvtss_f32(c2));
        if (mask & 2)
            batch_detail::add_cells<kMark>(
                band, _mm_cvtsi128_si32(_mm_shuffle_epi32(j, 1)),
                _mm_cvtsi128_si32(_mm_shuffle_epi32(i, 1)),
                _mm_cvtss_f32(_mm_shuffle_ps(c0, c0, 1)), _mm_cvtss_f32(_mm_shuffle_ps(c1, c1, 1)),
                _mm_cvtss_f32(_mm_shuffle_ps(c2, c2, 1)));
    }
    batch_detail::draw_lines<kMark>(band, b.slow, nslow);
}

}  // namespace bezel::raster_detail
