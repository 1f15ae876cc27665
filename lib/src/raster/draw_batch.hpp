// Private: drawing a batch of segments two at a time (SSE2, every x86-64 CPU).
//
// At small sizes most segments lie inside one pixel row and span at most two columns (DejaVu
// Sans at 12 px: 67 % of them, at 24 px 59 %; most of the others cross one row border, a few
// are stems), and such a segment is three cell updates of draw_line's narrow piece
// (accumulate.hpp). Scalar, that is about a hundred instructions a segment, most of them the
// prologue that decides which case applies and orients the edge. Here the decision and the
// arithmetic are done for two segments per instruction in double precision (the operations of
// add_narrow_piece, the scalar reference), and only the cell updates are per segment.
// Segments that are not narrow one-row pieces go to draw_line.
#pragma once

#include <emmintrin.h>

#include <cstdint>

#include "raster/accumulate.hpp"

namespace bezel::raster_detail {

// Segment k runs from seg[k].a to seg[k].b, band coordinates as draw_line takes them; an odd
// batch is padded with a horizontal segment, which draws nothing. Points are stored and loaded
// whole (16 bytes), so no load spans two smaller stores that may still sit in the store buffer
// (such a load cannot be forwarded); against separate x/y arrays this measured the same.
struct SegmentBatch {
    static constexpr int kSize = 64;
    struct Segment {
        __m128d a, b;  // (x, y)
    };
    Segment seg[kSize];
};

namespace batch_detail {

template <bool kMark>
inline void add_cells(const Band& band, int j, int i, float c0, float c1, float c2) {
    add_three_cells<kMark>(row_of(band, j), flags_of(band, j), i, c0, c1, c2);
}

template <bool kMark>
inline void draw_segment(const Band& band, const SegmentBatch::Segment& s) {
    draw_line<kMark>(band, _mm_cvtsd_f64(s.a), _mm_cvtsd_f64(_mm_unpackhi_pd(s.a, s.a)),
                     _mm_cvtsd_f64(s.b), _mm_cvtsd_f64(_mm_unpackhi_pd(s.b, s.b)));
}

}  // namespace batch_detail

// Draws segments [0, n) of `b` into `band` (draw_line's preconditions for each).
// A pair's lanes are tested together: fast = (y0 ≠ y1) ∧ (max y ≤ ⌊min y⌋ + 1) ∧ (|dx| ≤ 1);
// then, per lane, i = ⌊lo⌋, xm = min(hi, i + 1), dy₁ = dy·(hi − xm)/|dx| (the part right of
// the column border; 0 for a vertical piece, whose hi − xm is exactly 0) and the three cell
// values of add_narrow_piece. (Masking the slow lanes into harmless zero updates instead of
// branching was measured slower: all those updates then hit the same cells, one chain.)
template <bool kMark>
inline void draw_batch(const Band& band, const SegmentBatch& b, int n) {
    const __m128d one = _mm_set1_pd(1.0), half = _mm_set1_pd(0.5), tiny = _mm_set1_pd(1e-300);
    for (int k = 0; k < n; k += 2) {
        // Two segments' ends, transposed to one coordinate per register.
        const __m128d a0 = b.seg[k].a, b0 = b.seg[k].b, a1 = b.seg[k + 1].a, b1 = b.seg[k + 1].b;
        const __m128d x0 = _mm_unpacklo_pd(a0, a1), y0 = _mm_unpackhi_pd(a0, a1);
        const __m128d x1 = _mm_unpacklo_pd(b0, b1), y1 = _mm_unpackhi_pd(b0, b1);
        const __m128d ylo = _mm_min_pd(y0, y1), yhi = _mm_max_pd(y0, y1);
        const __m128i j = _mm_cvttpd_epi32(ylo);  // floor: y > −1
        const __m128d lo = _mm_min_pd(x0, x1), hi = _mm_max_pd(x0, x1);
        const __m128d w = _mm_sub_pd(hi, lo);
        const __m128d fast =
            _mm_and_pd(_mm_and_pd(_mm_cmple_pd(yhi, _mm_add_pd(_mm_cvtepi32_pd(j), one)),
                                  _mm_cmple_pd(w, one)),
                       _mm_cmpneq_pd(y0, y1));
        const int mask = _mm_movemask_pd(fast);
        if (mask != 3) {  // a lane the general code draws (stems, long or wide segments)
            if (!(mask & 1)) batch_detail::draw_segment<kMark>(band, b.seg[k]);
            if (!(mask & 2)) batch_detail::draw_segment<kMark>(band, b.seg[k + 1]);
            if (mask == 0) continue;
        }
        const __m128i i = _mm_cvttpd_epi32(lo);
        const __m128d X = _mm_add_pd(_mm_cvtepi32_pd(i), one);
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
}

}  // namespace bezel::raster_detail
