// AVX2 drawing of the full rows of long steep edges and stems, eight rows (one group) a step
// (SteepKernels in accumulate.hpp). Everything after the pragma is compiled for AVX2 and only
// called after __builtin_cpu_supports("avx2") said yes; the headers come first, so that their
// inline functions stay baseline code.
//
// Why: one vector add per column per group instead of three scalar cell updates per row, about
// half the cycles a row on long edges (a microbenchmark: 9-13 cycles a row instead of 21 for
// slanted ones, 2.4 instead of 5.3 for stems). Below ~128 px few edges cross a whole group,
// so the kernels also take the rows of partial groups (masked): see kVectorMinRows.
#include <algorithm>
#include <cstdint>

#include "raster/accumulate.hpp"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>

#include "raster/target_avx2.hpp"

BEZEL_AVX2_BEGIN

namespace bezel::raster_detail {

namespace {

// Four full rows, tops at y = ya (a vector of four consecutive rows), of the edge
// x(y) = x0 + (y − y0)·dxdy: the three cell values and the column of each row's narrow piece —
// the operations of draw_narrow_piece / add_narrow_piece with ady = 1, in their order, so the
// result is theirs bit for bit (no FMA: this file is compiled for AVX2 only).
struct FourRows {
    __m128 c0, c1, c2;
    __m128i i;
};
inline FourRows four_rows(__m256d ya, __m256d x0, __m256d y0, __m256d dxdy, __m256d inv_slope,
                          __m256d dir) {
    const __m256d one = _mm256_set1_pd(1.0), half = _mm256_set1_pd(0.5);
    const __m256d xa = _mm256_add_pd(x0, _mm256_mul_pd(_mm256_sub_pd(ya, y0), dxdy));
    const __m256d xb =
        _mm256_add_pd(x0, _mm256_mul_pd(_mm256_sub_pd(_mm256_add_pd(ya, one), y0), dxdy));
    const __m256d lo = _mm256_min_pd(xa, xb), hi = _mm256_max_pd(xa, xb);
    const __m128i i = _mm256_cvttpd_epi32(lo);  // truncation, as the scalar int conversion
    const __m256d X = _mm256_add_pd(_mm256_cvtepi32_pd(i), one);
    const __m256d xm = _mm256_min_pd(hi, X);
    const __m256d dy1 =
        _mm256_mul_pd(dir, _mm256_min_pd(_mm256_mul_pd(_mm256_sub_pd(hi, xm), inv_slope), one));
    const __m256d dy0 = _mm256_sub_pd(dir, dy1);
    const __m256d r0 = _mm256_mul_pd(
        dy0, _mm256_sub_pd(_mm256_mul_pd(half, _mm256_add_pd(lo, xm)), _mm256_sub_pd(X, one)));
    const __m256d r1 =
        _mm256_mul_pd(dy1, _mm256_sub_pd(_mm256_mul_pd(half, _mm256_add_pd(xm, hi)), X));
    return {_mm256_cvtpd_ps(_mm256_sub_pd(dy0, r0)),
            _mm256_cvtpd_ps(_mm256_add_pd(r0, _mm256_sub_pd(dy1, r1))), _mm256_cvtpd_ps(r1), i};
}

// All ones in the lanes l (lanes = 0..7) with lo ≤ l < hi, zero in the others.
inline __m256 row_mask(__m256i lanes, int lo, int hi) {
    return _mm256_castsi256_ps(
        _mm256_andnot_si256(_mm256_cmpgt_epi32(_mm256_set1_epi32(lo), lanes),
                            _mm256_cmpgt_epi32(_mm256_set1_epi32(hi), lanes)));
}

// Full rows [r0, r1) of the band (r0 < r1), a group of eight at a time; the rows of a partial
// group outside the range add zeros. Row r of a group adds c0, c1, c2 at columns i_r, i_r + 1,
// i_r + 2, and the group's rows of one column are one vector (column-major groups): so each
// column c the edge touches gets ONE vector add, lane r holding row r's value for that column
// (the one k with i_r + k = c, else 0). x is monotone in y, so the columns lie in
// [⌊min x⌋, ⌊max x⌋ + 2] over the top and bottom of the rows drawn.
template <bool kMark>
void steep_rows(const Band& band, int r0, int r1, double x0, double y0, double dxdy,
                double inv_slope, double dir) {
    const __m256d vx0 = _mm256_set1_pd(x0), vy0 = _mm256_set1_pd(y0);
    const __m256d vd = _mm256_set1_pd(dxdy), vinv = _mm256_set1_pd(inv_slope);
    const __m256d vdir = _mm256_set1_pd(dir);
    const __m256d step = _mm256_setr_pd(0.0, 1.0, 2.0, 3.0), four = _mm256_set1_pd(4.0);
    const __m256i lanes = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    for (int g = r0 >> kGroupShift; g <= (r1 - 1) >> kGroupShift; ++g) {
        const int gtop = g << kGroupShift;
        const double top = static_cast<double>(gtop);
        const __m256d ya = _mm256_add_pd(_mm256_set1_pd(top), step);
        const FourRows a = four_rows(ya, vx0, vy0, vd, vinv, vdir);
        const FourRows b = four_rows(_mm256_add_pd(ya, four), vx0, vy0, vd, vinv, vdir);
        // Rows of the group outside [r0, r1) add nothing.
        const __m256 keep = row_mask(lanes, r0 - gtop, r1 - gtop);
        const __m256 c0 = _mm256_and_ps(keep, _mm256_set_m128(b.c0, a.c0));
        const __m256 c1 = _mm256_and_ps(keep, _mm256_set_m128(b.c1, a.c1));
        const __m256 c2 = _mm256_and_ps(keep, _mm256_set_m128(b.c2, a.c2));
        const __m256i i = _mm256_set_m128i(b.i, a.i);
        // x at the top and bottom of the rows drawn; x is monotone in y.
        const double xt = x0 + (static_cast<double>(std::max(gtop, r0)) - y0) * dxdy;
        const double xe = x0 + (static_cast<double>(std::min(gtop + kGroupRows, r1)) - y0) * dxdy;
        const int cmin = static_cast<int>(xt < xe ? xt : xe);
        const int cmax = static_cast<int>(xt < xe ? xe : xt) + 2;
        float* group = band.acc + g * band.stride;
        __m256i c = _mm256_set1_epi32(cmin);
        const __m256i one = _mm256_set1_epi32(1);
        const __m256i i1 = _mm256_add_epi32(i, one), i2 = _mm256_add_epi32(i1, one);
        for (int col = cmin; col <= cmax; ++col, c = _mm256_add_epi32(c, one)) {
            const __m256 d = _mm256_or_ps(
                _mm256_or_ps(_mm256_and_ps(_mm256_castsi256_ps(_mm256_cmpeq_epi32(i, c)), c0),
                             _mm256_and_ps(_mm256_castsi256_ps(_mm256_cmpeq_epi32(i1, c)), c1)),
                _mm256_and_ps(_mm256_castsi256_ps(_mm256_cmpeq_epi32(i2, c)), c2));
            float* cell = group + col * kCell;
            _mm256_store_ps(cell, _mm256_add_ps(_mm256_load_ps(cell), d));
        }
        if constexpr (kMark) {
            // The columns span at most 8·|dxdy| + 3 ≤ 11, so at most two blocks: two stores
            // (a loop here became a memset call, 4 cycles a row in a microbenchmark).
            std::uint8_t* f = band.flags + g * band.flag_stride;
            f[cmin >> kBlockShift] = 1;
            f[cmax >> kBlockShift] = 1;
        }
    }
}

struct StemCells {
    __m128 first, second;  // four rows' values for columns ic and ic + 1
};

// Full rows [r0, r1) of an edge that stays inside column ic, by groups as steep_rows: row r
// adds dir·(1 − m_r) and dir·m_r at columns ic, ic + 1, m_r the mean of the row's x ends minus
// ic (the scalar stem loop of draw_line, with x at each row border from the formula rather than
// by accumulation).
template <bool kMark>
void stem_rows(const Band& band, int r0, int r1, int ic, double x0, double y0, double dxdy,
               double dir) {
    const __m256d vx0 = _mm256_set1_pd(x0), vy0 = _mm256_set1_pd(y0), vd = _mm256_set1_pd(dxdy);
    const __m256d vdir = _mm256_set1_pd(dir), half = _mm256_set1_pd(0.5);
    const __m256d one = _mm256_set1_pd(1.0), vic = _mm256_set1_pd(static_cast<double>(ic));
    const __m256d step = _mm256_setr_pd(0.0, 1.0, 2.0, 3.0), four = _mm256_set1_pd(4.0);
    const auto right = [&](__m256d ya) {
        const __m256d xa = _mm256_add_pd(vx0, _mm256_mul_pd(_mm256_sub_pd(ya, vy0), vd));
        const __m256d xb =
            _mm256_add_pd(vx0, _mm256_mul_pd(_mm256_sub_pd(_mm256_add_pd(ya, one), vy0), vd));
        const __m256d r =
            _mm256_mul_pd(vdir, _mm256_sub_pd(_mm256_mul_pd(half, _mm256_add_pd(xa, xb)), vic));
        return StemCells{_mm256_cvtpd_ps(_mm256_sub_pd(vdir, r)), _mm256_cvtpd_ps(r)};
    };
    const __m256i lanes = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    for (int g = r0 >> kGroupShift; g <= (r1 - 1) >> kGroupShift; ++g) {
        const int gtop = g << kGroupShift;
        const __m256d ya = _mm256_add_pd(_mm256_set1_pd(static_cast<double>(gtop)), step);
        const auto a = right(ya);
        const auto b = right(_mm256_add_pd(ya, four));
        const __m256 keep = row_mask(lanes, r0 - gtop, r1 - gtop);
        float* cell = band.acc + g * band.stride + ic * kCell;
        const __m256 first = _mm256_and_ps(keep, _mm256_set_m128(b.first, a.first));
        const __m256 second = _mm256_and_ps(keep, _mm256_set_m128(b.second, a.second));
        _mm256_store_ps(cell, _mm256_add_ps(_mm256_load_ps(cell), first));
        _mm256_store_ps(cell + kCell, _mm256_add_ps(_mm256_load_ps(cell + kCell), second));
        if constexpr (kMark) {
            std::uint8_t* f = band.flags + g * band.flag_stride;
            f[ic >> kBlockShift] = 1;
            f[(ic + 1) >> kBlockShift] = 1;
        }
    }
}

}  // namespace
}  // namespace bezel::raster_detail
BEZEL_AVX2_END

namespace bezel::raster_detail {

// Baseline code (outside the pragma): it runs on every CPU.
const SteepKernels* avx2_steep_kernels() {
    static const SteepKernels k{{steep_rows<false>, steep_rows<true>},
                                {stem_rows<false>, stem_rows<true>}};
    return cpu_has_avx2() ? &k : nullptr;
}

}  // namespace bezel::raster_detail

#else
namespace bezel::raster_detail {
const SteepKernels* avx2_steep_kernels() { return nullptr; }
}  // namespace bezel::raster_detail
#endif
