// Private: the segment batch of a DENSE band (direct_fill.cpp) in single precision, written once
// for a lane policy and compiled twice: four lanes of SSE (baseline, every x86-64 CPU, this
// header's own F4) and eight of AVX2 (draw_batch_avx2.cpp, which includes this header after its
// target pragma with its own policy). Both do the same IEEE single-precision operations per
// lane in the same order and add in the same order, so the band is the same bit for bit.
//
// Why single precision. In a dense box the batch's lane arithmetic (the classification of each
// segment, the three cell values of its narrow piece, the cut at a row border) is most of a
// glyph's vector work. Eight float lanes do per instruction what four double lanes do, in half
// the loop steps, mask branches and transposes; both copies are faster than the double batches
// (draw_batch.hpp), most at 12-64 px (docs/perf-log.md).
//
// What rounding to float costs. The walk hands over each vertex rounded to the nearest float, so
// the batch draws the polygon of the rounded vertices, exactly up to float arithmetic. The
// polygon stays closed (a shared vertex rounds the same way for both its segments), so every
// row's deltas still sum to zero past it. A vertex moves by at most half a float ulp of its band
// coordinate, at most 2⁻²⁴ of it: a dense band is at most 93 px wide (kDenseBlocks) and at most
// kMaxBitmapDim = 2¹⁴ rows, so the move is below 2⁻¹⁰ ≈ 1e-3 px in the tallest band and below
// 4e-6 px in a glyph box under 64 px. A vertex moved by δ changes a pixel's coverage by at most δ
// (the area between the two edges inside it). The cell values carry float rounding of about
// 2⁻²⁴ of a pixel's cover each, as the float cells always did.
//
// Internal linkage only (an unnamed namespace): the copy compiled for AVX2 in
// draw_batch_avx2.cpp must not be merged with a baseline copy by the linker, and that file must
// include this header after its pragma and nowhere before it.
#pragma once

#include "raster/sse2.hpp"

#include <algorithm>
#include <cstdint>

#include "raster/draw_batch.hpp"

namespace bezel::raster_detail {
namespace {

// Segments of a lane policy L, one coordinate per vector.
template <typename L>
struct DenseSegs {
    typename L::V x0, y0, x1, y1;
};

// Each lane's narrow piece (draw_batch's lane arithmetic in float): three cell values, the row
// and the first column.
template <typename L>
struct DensePieces {
    alignas(32) float c0[L::kLanes], c1[L::kLanes], c2[L::kLanes];
    alignas(32) int row[L::kLanes], col[L::kLanes];
};

// The narrow pieces of s (each inside one row and two columns, the fast test: i = ⌊lo⌋,
// xm = min(hi, i + 1), dy₁ = dy·(hi − xm)/|dx|, and add_narrow_piece's three values). A lane that
// fails the test gets values of no meaning, which the caller does not use.
template <typename L>
inline void dense_narrow(const DenseSegs<L>& s, DensePieces<L>& out) {
    using V = typename L::V;
    const V one = L::set1(1.0f), half = L::set1(0.5f), tiny = L::set1(1e-30f);
    const V lo = L::min(s.x0, s.x1), hi = L::max(s.x0, s.x1);
    const auto i = L::cvtt(lo);  // floor: lo > −1
    const V X = L::add(L::cvt(i), one);
    const V xm = L::min(hi, X);
    const V dy = L::sub(s.y1, s.y0);
    const V dy1 = L::mul(dy, L::div(L::sub(hi, xm), L::max(L::sub(hi, lo), tiny)));
    const V dy0 = L::sub(dy, dy1);
    const V r0 = L::mul(dy0, L::sub(L::mul(half, L::add(lo, xm)), L::sub(X, one)));
    const V r1 = L::mul(dy1, L::sub(L::mul(half, L::add(xm, hi)), X));
    L::store(out.c0, L::sub(dy0, r0));
    L::store(out.c1, L::add(r0, L::sub(dy1, r1)));
    L::store(out.c2, r1);
    L::store_int(out.row, L::cvtt(L::min(s.y0, s.y1)));  // floor: y > −1
    L::store_int(out.col, i);
}

template <typename L>
inline void dense_add(const Band& band, const DensePieces<L>& v, int l) {
    add_three_cells<false>(row_of(band, v.row[l]), nullptr, v.col[l], v.c0[l], v.c1[l], v.c2[l]);
}

// A float segment (x0, y0, x1, y1) as draw_line's double one.
inline SegmentBatch::Segment widen(__m128 f) {
    return {_mm_cvtps_pd(f), _mm_cvtps_pd(_mm_movehl_ps(f, f))};
}

// A stem: the segment f inside one column ic (max x ≤ ⌊min x⌋ + 1) that reaches past the row
// after its first. draw_line's stem case in float, a group's rows of the column at a time: each
// row r's piece runs from ya = max(y0, r) to yb = min(y1, r + 1) (row 0 from y0 even above 0,
// the direct route's excursions), and adds dy·(1 − m) and dy·m to columns ic and ic + 1, with
// dy = dir·max(yb − ya, 0) and m the mean of the piece's x ends minus ic. The rows of the
// group the edge misses add zeros (rows past the band's last are storage of its last group,
// which the sweep zeroes whole). The column of eight rows is one aligned vector (or two),
// as the sweep's (column-major groups), so a group is two vector adds, not sixteen cell adds.
// Drawn here rather than set aside for draw_line (1.6 stems a glyph at 12 px, DejaVu Sans; 5.3
// at 64 px), they skip the set-aside loop's per-segment prologue.
// The values are draw_line's formula in float: x at each row border from the end point
// (x₀ + (y − y₀)·dxdy, no drift), within float rounding of draw_line's double ones.
template <typename L>
inline void dense_stem(const Band& band, __m128 f) {
    using V = typename L::V;
    alignas(16) float e[4];
    _mm_store_ps(e, f);
    float x0 = e[0], y0 = e[1], x1 = e[2], y1 = e[3], dir = 1.0f;
    if (y0 > y1) {
        std::swap(x0, x1);
        std::swap(y0, y1);
        dir = -1.0f;
    }
    const int ic = static_cast<int>(std::min(x0, x1));  // floor: x > −1
    const int j0 = static_cast<int>(y0);                // floor: y > −1
    int j1 = static_cast<int>(y1);                      // the last row reached: ⌈y1⌉ − 1
    if (static_cast<float>(j1) == y1) --j1;
    const V vx0 = L::set1(x0), vy0 = L::set1(y0), vy1 = L::set1(y1), vdir = L::set1(dir);
    const V vd = L::set1((x1 - x0) / (y1 - y0)), vic = L::set1(static_cast<float>(ic));
    const V one = L::set1(1.0f), half = L::set1(0.5f), zero = L::set1(0.0f);
    for (int g = j0 >> kGroupShift; g <= j1 >> kGroupShift; ++g) {
        float* const cell = band.acc + g * band.stride + ic * kCell;
        for (int h = 0; h < kGroupRows; h += L::kLanes) {
            const V r = L::add(L::set1(static_cast<float>((g << kGroupShift) + h)), L::iota());
            const V rtop = L::sub(r, L::bit_and(L::cmp_eq(r, zero), one));  // row 0: −1
            const V ya = L::max(vy0, rtop), yb = L::min(vy1, L::add(r, one));
            const V dy = L::mul(vdir, L::max(L::sub(yb, ya), zero));
            const V xa = L::add(vx0, L::mul(L::sub(ya, vy0), vd));
            const V xb = L::add(vx0, L::mul(L::sub(yb, vy0), vd));
            const V right = L::mul(dy, L::sub(L::mul(half, L::add(xa, xb)), vic));
            L::store(cell + h, L::add(L::load_f(cell + h), L::sub(dy, right)));
            L::store(cell + kCell + h, L::add(L::load_f(cell + kCell + h), right));
        }
    }
}

// Narrow pieces f[0, n) (each inside one row and two columns), kLanes at a time, as the fast
// lanes of draw_dense_batch. A short tail is padded with horizontal pieces at (0, 0), whose
// three values are +0 and are added like the others (cheaper than a lane count test: fewer
// instructions, measured). f has room for n + kLanes − 1.
template <typename L>
inline void dense_pieces(const Band& band, __m128* f, int n) {
    constexpr int kLanes = L::kLanes;
    for (int p = n; p < ((n + kLanes - 1) & ~(kLanes - 1)); ++p) f[p] = _mm_setzero_ps();
    for (int k = 0; k < n; k += kLanes) {
        DensePieces<L> v;
        dense_narrow<L>(L::load(f + k), v);
        for (int l = 0; l < kLanes; ++l) dense_add<L>(band, v, l);
    }
}

// Room for the row pieces of steep segments before they are drawn (a chunk; a segment may
// have more rows than that and is then drawn in several chunks).
inline constexpr int kSteepChunk = 32;
// The tallest steep segment (in dy, px) cut into row pieces. Taller ones keep draw_line, whose
// vector kernel adds a whole group of eight rows per instruction (draw_avx2.cpp) and beats a
// piece per row there (docs/perf-log.md).
inline constexpr float kSteepPieceMaxDy = 8.0f;

// A steep segment f (|dx| ≤ |dy|) that crosses two row borders or more, cut at every row
// border into one-row pieces, each inside two columns (it moves ≤ 1 in x), queued in
// `pieces` (count `np`, drawn by dense_pieces when kSteepChunk are queued). Row r's piece runs
// from ya = max(y_lo, r) to yb = min(y_hi, r + 1) (row ⌊y_lo⌋ from y_lo even above 0, the
// direct route's excursions), x at a border from the end point, x₀ + (y − y₀)·(dx/dy) (no
// drift), clamped to the segment's x range against rounding; the piece keeps the segment's
// direction (its winding sign). draw_line's steep case in float.
template <typename L>
inline void dense_steep(const Band& band, __m128 f, __m128* pieces, int& np) {
    alignas(16) float e[4];
    _mm_store_ps(e, f);
    const float x0 = e[0], y0 = e[1], x1 = e[2], y1 = e[3];
    const bool down = y1 > y0;
    const float ylo = down ? y0 : y1, yhi = down ? y1 : y0;
    const float xlo = std::min(x0, x1), xhi = std::max(x0, x1);
    const float dxdy = (x1 - x0) / (y1 - y0);
    const int j0 = static_cast<int>(ylo);  // floor: y > −1
    int jl = static_cast<int>(yhi);        // the last row reached: ⌈yhi⌉ − 1
    if (static_cast<float>(jl) == yhi) --jl;
    float ya = ylo, xa = down ? x0 : x1;
    for (int r = j0; r <= jl; ++r) {
        const float yb = r == jl ? yhi : static_cast<float>(r + 1);
        const float xb = r == jl ? (down ? x1 : x0)
                                 : std::min(std::max(x0 + (yb - y0) * dxdy, xlo), xhi);
        pieces[np++] = down ? _mm_setr_ps(xa, ya, xb, yb) : _mm_setr_ps(xb, yb, xa, ya);
        if (np == kSteepChunk) {
            dense_pieces<L>(band, pieces, np);
            np = 0;
        }
        ya = yb;
        xa = xb;
    }
}

// Calls at(l) for each set bit l of mask, lowest first: as many steps as the lanes listed
// (one or two of eight in a step, typically), where a test of every lane's bit took sixteen
// instructions and as many branches per list per step.
template <typename At>
inline void for_each_lane(int mask, At&& at) {
    for (unsigned m = static_cast<unsigned>(mask); m != 0; m &= m - 1)
        at(__builtin_ctz(m));
}

// Draws the float segments b.fseg[0, n) into a dense band (no block flags), L::kLanes at a time.
// A segment inside one row and two columns is one narrow piece. One that crosses one row
// border and moves at most 1 in x is listed and, after the others, cut there into two
// narrow pieces, x at the border x₀ + (Y − y₀)·((x₁ − x₀)/(y₁ − y₀)). A longer one that stays
// in one column (a stem) is listed and drawn by dense_stem; a longer steep one (|dx| ≤ |dy|,
// |dy| ≤ kSteepPieceMaxDy) is listed and cut at every row border by dense_steep into narrow
// pieces (one a row: a lane of the narrow work each, cheaper than a row of draw_line's double
// steep case); anything else (taller steep segments, wide shallow ones) is set aside, widened
// to double, for draw_lines. Horizontal segments draw nothing and are dropped. Order of the
// adds: the narrow pieces in segment order, then the cut ones segment after
// segment (first piece, second piece), then the stems, then the steep ones' pieces, then the
// set-aside ones.
// (Every dense box cuts, on every CPU: direct_fill.cpp has the measurements.)
template <typename L>
void draw_dense_batch(const Band& band, SegmentBatch& b, int n) {
    using V = typename L::V;
    constexpr int kLanes = L::kLanes, kAll = (1 << kLanes) - 1;
    __m128* const f = b.fseg;
    int cut_idx[SegmentBatch::kSize + kLanes], stem_idx[SegmentBatch::kSize];
    int steep_idx[SegmentBatch::kSize];
    int ncut = 0, nslow = 0, nstem = 0, nsteep = 0;
    const V one = L::set1(1.0f), max_steep = L::set1(kSteepPieceMaxDy);
    // A short tail is padded with horizontal segments.
    for (int p = n; p < ((n + kLanes - 1) & ~(kLanes - 1)); ++p) f[p] = _mm_setzero_ps();
    for (int k = 0; k < n; k += kLanes) {
        const DenseSegs<L> s = L::load(f + k);
        const V ylo = L::min(s.y0, s.y1), yhi = L::max(s.y0, s.y1);
        const V lo = L::min(s.x0, s.x1), hi = L::max(s.x0, s.x1);
        const V X = L::add(L::cvt(L::cvtt(lo)), one);
        const V border = L::add(L::cvt(L::cvtt(ylo)), one);
        const V flat = L::cmp_eq(s.y0, s.y1);
        const V fast = L::andnot(flat, L::bit_and(L::cmp_le(yhi, border),
                                                  L::cmp_le(hi, L::add(X, one))));
        const int mask = L::movemask(fast);
        const int slow = ~(mask | L::movemask(flat)) & kAll;
        if (slow != 0) {
            const V cut = L::bit_and(
                L::bit_and(L::cmp_gt(yhi, border), L::cmp_le(yhi, L::add(border, one))),
                L::cmp_le(L::sub(hi, lo), one));
            const int cuts = L::movemask(cut) & slow;
            const int stems = L::movemask(L::cmp_le(hi, X)) & slow & ~cuts;
            const V dy = L::sub(yhi, ylo);
            const int steep = L::movemask(L::bit_and(L::cmp_le(L::sub(hi, lo), dy),
                                                     L::cmp_le(dy, max_steep))) &
                              slow & ~cuts & ~stems;
            for_each_lane(cuts, [&](int l) { cut_idx[ncut++] = k + l; });
            for_each_lane(stems, [&](int l) { stem_idx[nstem++] = k + l; });
            for_each_lane(steep, [&](int l) { steep_idx[nsteep++] = k + l; });
            for_each_lane(slow & ~cuts & ~stems & ~steep,
                          [&](int l) { b.slow[nslow++] = widen(f[k + l]); });
            if (mask == 0) continue;
        }
        DensePieces<L> v;
        dense_narrow<L>(s, v);
        if (mask == kAll) {
            for (int l = 0; l < kLanes; ++l) dense_add<L>(band, v, l);
        } else {
            for (int l = 0; l < kLanes; ++l)
                if (mask & (1 << l)) dense_add<L>(band, v, l);
        }
    }
    if (ncut > 0) {
        // The last step repeats its last segment; those lanes are not added.
        for (int p = ncut; p < ncut + kLanes - 1; ++p) cut_idx[p] = cut_idx[ncut - 1];
        for (int c = 0; c < ncut; c += kLanes) {
            const DenseSegs<L> s = L::gather(f, cut_idx + c);
            const V border = L::add(L::cvt(L::cvtt(L::min(s.y0, s.y1))), one);
            const V xm = L::add(s.x0, L::mul(L::sub(border, s.y0),
                                             L::div(L::sub(s.x1, s.x0), L::sub(s.y1, s.y0))));
            DensePieces<L> first, second;
            dense_narrow<L>(DenseSegs<L>{s.x0, s.y0, xm, border}, first);
            dense_narrow<L>(DenseSegs<L>{xm, border, s.x1, s.y1}, second);
            const int lanes = std::min(kLanes, ncut - c);
            for (int l = 0; l < lanes; ++l) {
                dense_add<L>(band, first, l);
                dense_add<L>(band, second, l);
            }
        }
    }
    for (int k = 0; k < nstem; ++k) dense_stem<L>(band, f[stem_idx[k]]);
    if (nsteep > 0) {
        alignas(16) __m128 pieces[kSteepChunk + kLanes];
        int np = 0;
        for (int k = 0; k < nsteep; ++k) dense_steep<L>(band, f[steep_idx[k]], pieces, np);
        dense_pieces<L>(band, pieces, np);
    }
    batch_detail::draw_lines<false>(band, b.slow, nslow);
}

// The baseline policy: four lanes of SSE (SSE2 only).
struct F4 {
    using V = __m128;
    using I = __m128i;
    static constexpr int kLanes = 4;
    static V set1(float v) { return _mm_set1_ps(v); }
    static V add(V a, V b) { return _mm_add_ps(a, b); }
    static V sub(V a, V b) { return _mm_sub_ps(a, b); }
    static V mul(V a, V b) { return _mm_mul_ps(a, b); }
    static V div(V a, V b) { return _mm_div_ps(a, b); }
    static V min(V a, V b) { return _mm_min_ps(a, b); }
    static V max(V a, V b) { return _mm_max_ps(a, b); }
    static V cmp_le(V a, V b) { return _mm_cmple_ps(a, b); }
    static V cmp_gt(V a, V b) { return _mm_cmpgt_ps(a, b); }
    static V cmp_eq(V a, V b) { return _mm_cmpeq_ps(a, b); }
    static V bit_and(V a, V b) { return _mm_and_ps(a, b); }
    static V andnot(V a, V b) { return _mm_andnot_ps(a, b); }
    static I cvtt(V a) { return _mm_cvttps_epi32(a); }
    static V cvt(I a) { return _mm_cvtepi32_ps(a); }
    static int movemask(V a) { return _mm_movemask_ps(a); }
    static void store(float* p, V a) { _mm_store_ps(p, a); }
    static V load_f(const float* p) { return _mm_load_ps(p); }
    static V iota() { return _mm_setr_ps(0.0f, 1.0f, 2.0f, 3.0f); }
    static void store_int(int* p, I a) { _mm_store_si128(reinterpret_cast<__m128i*>(p), a); }
    // Four (x0, y0, x1, y1) segments transposed to one coordinate per vector.
    static DenseSegs<F4> transpose(__m128 s0, __m128 s1, __m128 s2, __m128 s3) {
        const __m128 t0 = _mm_unpacklo_ps(s0, s1), t1 = _mm_unpackhi_ps(s0, s1);
        const __m128 t2 = _mm_unpacklo_ps(s2, s3), t3 = _mm_unpackhi_ps(s2, s3);
        return {_mm_movelh_ps(t0, t2), _mm_movehl_ps(t2, t0), _mm_movelh_ps(t1, t3),
                _mm_movehl_ps(t3, t1)};
    }
    static DenseSegs<F4> load(const __m128* f) { return transpose(f[0], f[1], f[2], f[3]); }
    static DenseSegs<F4> gather(const __m128* f, const int* idx) {
        return transpose(f[idx[0]], f[idx[1]], f[idx[2]], f[idx[3]]);
    }
};

}  // namespace
}  // namespace bezel::raster_detail
