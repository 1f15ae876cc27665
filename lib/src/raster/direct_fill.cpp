// The direct fill route; see direct_fill.hpp.
#include "raster/direct_fill.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <type_traits>

#include "raster/accumulate.hpp"
#include "raster/dense_batch.hpp"
#include "raster/draw_batch.hpp"
#include "raster/fill_common.hpp"
#include "raster/kernels.hpp"
#include "raster/render_flatten.hpp"

namespace bezel::raster_detail {

namespace {

// Receives the balanced walk and draws each segment, closing every contour.
//
// Vertices lie within 2/3·tol of the control box (curve points lie in it; a balanced vertex is
// moved by |Δ²|/12 ≤ 8·tol/12). Above the band a vertex must be clamped: x to the width (exact,
// accumulate.hpp), y to the rows (moves it by < tol). Below 0 it is clamped with kFloor, which
// the stored-point walks set: their control points may lie up to tol outside the band
// (fill_path_direct's slack), so x is clamped to 0 (exact) and y to 0 (a move of < 2·tol; the
// part of the outline above the target is not drawn into row 0). Without kFloor (translated
// paths, whose control points are inside the band) a coordinate is > −1/3 and needs no clamp:
// draw_line's int conversion truncates toward zero, so such a point lands in column / row 0
// as if it were at 0 (within its excursion), one instruction a vertex saved.
//
// Segments are queued and drawn a SegmentBatch at a time (draw_batch.hpp) rather than one
// draw_line call per vertex: a call in the middle of the flattening loop makes the caller spill
// its forward differences (every vector register is caller-saved), the two loops are each
// tighter alone, and the batch draws several segments per instruction. For a dense band the
// queue holds the segments in float (dense_batch.hpp: why, and what the rounding costs); each
// vertex is rounded once, after the clamp, and shared by its two segments.
//
// The queue is a separate object (draw_path's), not a member: the segment stores are vector
// stores, which may alias anything, and into a member array they would make the compiler
// reload `queued` and `cur` from the sink after every push (one store-to-load chain through the
// walk); into another object they cannot touch the sink's fields.
template <bool kMark, bool kSplit, bool kFloor>
struct DrawSink {
    static_assert(kMark || kSplit, "a dense band always cuts (draw_dense_batch)");
    DrawSink(const Band& b, SegmentBatch& q, BatchFn four)
        : band(b), batch(q), four(four),
          wh(_mm_set_pd(static_cast<double>(b.rows), static_cast<double>(b.width))) {}

    const Band& band;
    SegmentBatch& batch;
    BatchFn four;  // the AVX2 batch, or null
    __m128d wh;  // (width, rows)
    // The contour's first point and the current one: a marked band's in double, a dense band's
    // rounded to float (dense_batch.hpp), (x, y) in the low half.
    __m128d first = _mm_setzero_pd(), cur = _mm_setzero_pd();
    __m128 first_f = _mm_setzero_ps(), cur_f = _mm_setzero_ps();
    int queued = 0;

    // min(x, width), min(y, rows), and with kFloor max(·, 0); the points are finite
    // (fill_path_direct checked).
    __m128d clamp(V2 p) const {
        const __m128d q = _mm_min_pd(p.v, wh);
        if constexpr (kFloor) return _mm_max_pd(q, _mm_setzero_pd());
        return q;
    }
    void push(__m128d a, __m128d b) {
        batch.seg[queued] = {a, b};
        if (++queued == SegmentBatch::kSize) flush();
    }
    void push_f(__m128 a, __m128 b) {
        batch.fseg[queued] = _mm_movelh_ps(a, b);
        if (++queued == SegmentBatch::kSize) flush();
    }
    void flush() {
        if constexpr (!kMark) {
            if (four != nullptr)
                four(band, batch, queued);
            else
                draw_dense_batch<F4>(band, batch, queued);
        } else if (four != nullptr) {
            four(band, batch, queued);
        } else {
            if (queued & 1)  // pad to a pair with a horizontal segment, which draws nothing
                batch.seg[queued] = {_mm_setzero_pd(), _mm_setzero_pd()};
            draw_batch<kMark, kSplit>(band, batch, queued);
        }
        queued = 0;
    }
    void move(V2 p) {
        if constexpr (!kMark)
            first_f = cur_f = _mm_cvtpd_ps(clamp(p));
        else
            first = cur = clamp(p);
    }
    // Room for a curve's n points (render_flatten.hpp, emit): flushes first when the queue
    // lacks it; false when n is more than a queue holds. The queue is never left full (push
    // flushes at kSize and tests for nothing else), so a reservation keeps queued < kSize.
    bool reserve(int n) {
        if (n >= SegmentBatch::kSize) return false;
        if (queued + n >= SegmentBatch::kSize) flush();
        return true;
    }
    void line_reserved(V2 p) {
        const __m128d q = clamp(p);
        if constexpr (!kMark) {
            const __m128 qf = _mm_cvtpd_ps(q);
            batch.fseg[queued++] = _mm_movelh_ps(cur_f, qf);
            cur_f = qf;
        } else {
            batch.seg[queued++] = {cur, q};
            cur = q;
        }
    }
    void line(V2 p) {
        line_reserved(p);
        if (queued == SegmentBatch::kSize) flush();
    }
    void close() {
        if constexpr (!kMark) {
            push_f(cur_f, first_f);
            cur_f = first_f;
        } else {
            push(cur, first);
            cur = first;
        }
    }
};

// `points` are the transformed control points, or with kTranslate the path's own, which the
// transform moves by `offset`; `shift` is the band's top-left pixel, `four` the AVX2 batch
// kernels (kernel_table().batch, or null). With kTranslate a point is (p + offset) − shift,
// the value the stored transform gives (1·x + 0·y + e = x + e exactly), so both produce the
// same polyline bit for bit; the stored points' walk also clamps vertices at 0 (DrawSink's
// kFloor), which changes the band only where a vertex lies above or left of it.
template <bool kMark, bool kSplit, bool kTranslate>
void draw_path(const Path& path, const Point* points, V2 offset, V2 shift, double tol,
               const Band& band, const BatchKernels* four) {
    SegmentBatch batch;
    DrawSink<kMark, kSplit, !kTranslate> sink(
        band, batch, four == nullptr ? nullptr : kMark ? four->marked[kSplit] : four->dense);
    walk_balanced(path.verbs(), tol,
                  [points, offset, shift](std::size_t i, V2& p) {
                      if constexpr (kTranslate) {
                          p = (V2::of(points[i]) + offset) - shift;
                      } else {
                          (void)offset;  // captured for the translated walk only
                          p = V2::of(points[i]) - shift;
                      }
                      return true;
                  },
                  sink);
    sink.flush();
}

// Maps `src` by `m` into `out` (when kStore) and returns the box of the results (lo, hi) and
// `nan`, all ones in a lane where a result was NaN (an infinite one leaves the box unbounded,
// which the caller's box test refuses). Packed, (x, y) = (a, b)·x + (c, d)·y + (e, f): the
// operations of Affine's product, in its order. Two points a step with their own min, max and
// NaN accumulators: one chain of each was the loop's limit (4 cycles a point for the add that
// found NaN and infinity before), and the or of an unordered compare is a 1-cycle chain.
// With kTranslate (m a translation) only the box and NaN are found, as q + (e, f): the same
// values (1·x + 0·y = x exactly for finite x, y; an infinite coordinate still leaves the box
// unbounded), without the products or the stores, since draw_path then adds (e, f) itself.
template <bool kStore, bool kTranslate = false>
void transform_points(const std::vector<Point>& src, const Affine& m, Point* out, __m128d& lo,
                      __m128d& hi, __m128d& nan) {
    static_assert(!(kStore && kTranslate), "a translation is applied by draw_path, not stored");
    const __m128d ab = _mm_set_pd(m.b, m.a), cd = _mm_set_pd(m.d, m.c), ef = _mm_set_pd(m.f, m.e);
    const auto map = [&](std::size_t i) {
        const __m128d q = _mm_loadu_pd(&src[i].x);
        if constexpr (kTranslate) return _mm_add_pd(q, ef);
        const __m128d t = _mm_add_pd(_mm_add_pd(_mm_mul_pd(ab, _mm_unpacklo_pd(q, q)),
                                                _mm_mul_pd(cd, _mm_unpackhi_pd(q, q))),
                                     ef);
        if constexpr (kStore) _mm_storeu_pd(&out[i].x, t);
        return t;
    };
    __m128d lo0 = _mm_set1_pd(HUGE_VAL), lo1 = lo0, hi0 = _mm_set1_pd(-HUGE_VAL), hi1 = hi0;
    __m128d nan0 = _mm_setzero_pd(), nan1 = nan0;
    const std::size_t n = src.size();
    std::size_t i = 0;
    for (; i + 1 < n; i += 2) {
        const __m128d t0 = map(i), t1 = map(i + 1);
        lo0 = _mm_min_pd(lo0, t0);
        lo1 = _mm_min_pd(lo1, t1);
        hi0 = _mm_max_pd(hi0, t0);
        hi1 = _mm_max_pd(hi1, t1);
        nan0 = _mm_or_pd(nan0, _mm_cmpunord_pd(t0, t0));
        nan1 = _mm_or_pd(nan1, _mm_cmpunord_pd(t1, t1));
    }
    if (i < n) {
        const __m128d t = map(i);
        lo0 = _mm_min_pd(lo0, t);
        hi0 = _mm_max_pd(hi0, t);
        nan0 = _mm_or_pd(nan0, _mm_cmpunord_pd(t, t));
    }
    lo = _mm_min_pd(lo0, lo1);
    hi = _mm_max_pd(hi0, hi1);
    nan = _mm_or_pd(nan0, nan1);
}

}  // namespace

template <typename View>
bool fill_path_direct(const Path& path, const Affine& m, FillRule rule, const View& target,
                      double tol, const DirectScratch& scratch) {
    const int W = target.width, H = target.height;
    if (!(tol <= kDirectMaxTolerancePx)) return false;
    if (W <= 0 || H <= 0 || W > kMaxBitmapDim || H > kMaxBitmapDim || target.data == nullptr)
        return false;
    const std::vector<Point>& src = path.points();
    if (src.empty()) return false;

    // The transformed control points and their box, in one pass that also stores them when the
    // scratch already has room; a first, larger path is measured before anything is allocated
    // for it (a refused path allocates nothing).
    // A translation (glyphs placed at a pen position, and the identity) is not stored: the
    // walk reads the path's own points and adds (e, f) as it goes, which skips the products
    // and a store per point (the transform was a noticeable share of a small glyph's time).
    // The walk's x + e is the same double as the stored product's, so the polyline is the same.
    std::vector<Point>& tp = scratch.points;
    const bool translate = m.a == 1.0 && m.b == 0.0 && m.c == 0.0 && m.d == 1.0;
    // tp only grows (a resize per fill was a call, and zeroed what the transform overwrites).
    const bool fits = tp.size() >= src.size();
    __m128d lo, hi, nan;
    if (translate)
        transform_points<false, true>(src, m, nullptr, lo, hi, nan);
    else if (fits)
        transform_points<true>(src, m, tp.data(), lo, hi, nan);
    else
        transform_points<false>(src, m, nullptr, lo, hi, nan);
    if (_mm_movemask_pd(nan) != 0) return false;
    const double x0 = _mm_cvtsd_f64(lo), y0 = _mm_cvtsd_f64(_mm_unpackhi_pd(lo, lo));
    const double x1 = _mm_cvtsd_f64(hi), y1 = _mm_cvtsd_f64(_mm_unpackhi_pd(hi, hi));
    // Control points may stray past the target by up to tol: a box from rounded coordinates,
    // FreeType's 26.6 control box among them, misses the outline's own by up to 1/128 px (5-6 %
    // of a font's glyphs at 12 px, which the general route draws at about 2.5 times the cost).
    // Such a path takes the stored-point walk, whose vertices are clamped into the band on
    // both sides (DrawSink's kFloor): x exactly, y by less than 2·tol. (Clamping the control
    // points instead moves the curves by as little, but the coverage error is larger:
    // docs/perf-log.md.) Farther out the path needs clipping: the general route.
    bool stray = false;
    if (!(x0 >= 0.0 && y0 >= 0.0 && x1 <= W && y1 <= H)) {
        if (!(x0 >= -tol && y0 >= -tol && x1 <= W + tol && y1 <= H + tol)) return false;
        stray = true;
    }

    // Edge budget, the cheap bound of path_fill.cpp: a cubic in a control box of diagonal D needs
    // at most ⌈√(1.5·D/tol)⌉ ≤ √(1.5·D/tol) + 1 steps, so with L = min(kMaxSegmentsPerCurve,
    // kMaxEdges / verbs) every curve and the whole path fit when √(1.5·D/tol) + 2 ≤ L, that is
    // D² ≤ ((L − 2)²·tol/1.5)²: no curve can pass kMaxSegmentsPerCurve, so the walk below never
    // stops halfway. Squared, without the two dependent square roots (measured: that chain was
    // the hottest line of a fill's setup at 12 px).
    const double limit = std::min(static_cast<double>(kMaxSegmentsPerCurve),
                                  static_cast<double>(kMaxEdges) /
                                      static_cast<double>(path.verbs().size()));
    const double bound = (limit - 2.0) * (limit - 2.0) * tol / 1.5;
    const double diagonal2 = (x1 - x0) * (x1 - x0) + (y1 - y0) * (y1 - y0);
    if (!(limit >= 2.0 && diagonal2 <= bound * bound)) return false;

    // The pixel box of the clamped points: −tol ≤ x0 ≤ x1 ≤ W + tol here (and so for y), with
    // tol < 1, so ⌊·⌋ and ⌈·⌉ are int conversions, truncation taking a coordinate in (−1, 0) to
    // 0 as the clamp does, and ⌈·⌉ capped at the target's edge as the clamp does (SSE2 has no
    // rounding instruction: std::floor / std::ceil are long sequences, measured the hottest
    // line left in a fill's setup).
    const auto floor_int = [](double v) { return static_cast<int>(v); };
    const auto ceil_int = [](double v) {
        const int i = static_cast<int>(v);
        return i + (static_cast<double>(i) < v);
    };
    const int bx0 = floor_int(x0), bx1 = std::min(ceil_int(x1), W);
    const int by0 = floor_int(y0), by1 = std::min(ceil_int(y1), H);
    if (bx0 >= bx1 || by0 >= by1) return false;  // no area: the general route clears
    const int box_w = bx1 - bx0, box_h = by1 - by0;
    const std::ptrdiff_t stride = group_cells(box_w), flag_stride = row_flag_bytes(box_w);
    const std::size_t groups = static_cast<std::size_t>(row_groups(box_h));
    const std::size_t cells = groups * static_cast<std::size_t>(stride);
    if (cells > kMaxBandCells) return false;  // several bands: the general route
    const std::size_t flags = groups * static_cast<std::size_t>(flag_stride);
    float* const acc = band_cells(scratch.acc, cells);
    if (scratch.flags.size() < flags) scratch.flags.resize(flags, 0);

    // Stored points: a general transform's, or a translated path's that strays.
    const bool stored = !translate || stray;
    if (stored && !(fits && !translate)) {
        if (!fits) tp.resize(src.size());  // the largest path so far
        transform_points<true>(src, m, tp.data(), lo, hi, nan);
    }
    clear_outside_box(target, bx0, bx1, by0, by1);
    const V2 shift{_mm_set_pd(static_cast<double>(by0), static_cast<double>(bx0))};
    const V2 offset{_mm_set_pd(m.f, m.e)};
    const Point* const points = stored ? tp.data() : src.data();
    const KernelTable& kernels = kernel_table();
    const Band band{acc, scratch.flags.data(), stride, flag_stride, box_w, box_h,
                    kernels.steep};
    const BatchKernels* const four = kernels.batch;
    // draw_path for a band mode, with the point source (stored or translated) chosen here.
    const auto draw = [&](auto mark, auto split) {
        constexpr bool kMark = decltype(mark)::value, kSplit = decltype(split)::value;
        if (!stored)
            draw_path<kMark, kSplit, true>(path, points, offset, shift, tol, band, four);
        else
            draw_path<kMark, kSplit, false>(path, points, offset, shift, tol, band, four);
    };
    if (row_blocks(box_w) <= kDenseBlocks) {
        // Every dense box cuts segments across one row border (dense_batch.hpp), on every CPU:
        // the float batch cuts a whole step's lanes at once, so cutting pays in small boxes too
        // (unlike draw_batch.hpp's double pair loop, which cuts only from 32 rows).
        draw(std::false_type{}, std::true_type{});
        sweep_dense(*kernels.sweep, rule, acc, stride, box_w, box_h, target.row(by0) + bx0,
                    target.stride);
        return true;
    }
    draw(std::true_type{}, std::false_type{});
    sweep_marked_band(*kernels.sweep, rule, band, target.row(by0) + bx0, target.stride);
    return true;
}

template bool fill_path_direct<MaskView>(const Path&, const Affine&, FillRule, const MaskView&,
                                         double, const DirectScratch&);
template bool fill_path_direct<FloatMaskView>(const Path&, const Affine&, FillRule,
                                              const FloatMaskView&, double, const DirectScratch&);

}  // namespace bezel::raster_detail
