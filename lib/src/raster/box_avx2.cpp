// AVX2 box of a translated path's points for the direct route (direct_fill.hpp): two points a
// vector, four a step. Everything after the pragma is compiled for AVX2 and only called after
// cpu_has_avx2() said yes; the headers come first, so that their inline functions stay
// baseline code.
#include <cmath>
#include <cstddef>

#include "raster/direct_fill.hpp"
#include "raster/sweep.hpp"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>

#include "raster/target_avx2.hpp"

BEZEL_AVX2_BEGIN

namespace bezel::raster_detail {

namespace {

// Two accumulators of each kind, as the baseline loop (a min, max or or chain per point was the
// loop's limit); min, max and or are exact, so the order of the points does not change the box.
void translated_box(const Point* p, std::size_t n, __m128d ef, __m128d& lo, __m128d& hi,
                    __m128d& nan) {
    const __m256d e = _mm256_set_m128d(ef, ef);
    __m256d lo0 = _mm256_set1_pd(HUGE_VAL), lo1 = lo0;
    __m256d hi0 = _mm256_set1_pd(-HUGE_VAL), hi1 = hi0;
    __m256d nan0 = _mm256_setzero_pd(), nan1 = nan0;
    std::size_t i = 0;
    for (; i + 4 <= n; i += 4) {
        const __m256d t0 = _mm256_add_pd(_mm256_loadu_pd(&p[i].x), e);
        const __m256d t1 = _mm256_add_pd(_mm256_loadu_pd(&p[i + 2].x), e);
        lo0 = _mm256_min_pd(lo0, t0);
        lo1 = _mm256_min_pd(lo1, t1);
        hi0 = _mm256_max_pd(hi0, t0);
        hi1 = _mm256_max_pd(hi1, t1);
        nan0 = _mm256_or_pd(nan0, _mm256_cmp_pd(t0, t0, _CMP_UNORD_Q));
        nan1 = _mm256_or_pd(nan1, _mm256_cmp_pd(t1, t1, _CMP_UNORD_Q));
    }
    if (i + 2 <= n) {
        const __m256d t = _mm256_add_pd(_mm256_loadu_pd(&p[i].x), e);
        lo0 = _mm256_min_pd(lo0, t);
        hi0 = _mm256_max_pd(hi0, t);
        nan0 = _mm256_or_pd(nan0, _mm256_cmp_pd(t, t, _CMP_UNORD_Q));
        i += 2;
    }
    const __m256d l = _mm256_min_pd(lo0, lo1), h = _mm256_max_pd(hi0, hi1);
    const __m256d q = _mm256_or_pd(nan0, nan1);
    __m128d l2 = _mm_min_pd(_mm256_castpd256_pd128(l), _mm256_extractf128_pd(l, 1));
    __m128d h2 = _mm_max_pd(_mm256_castpd256_pd128(h), _mm256_extractf128_pd(h, 1));
    __m128d q2 = _mm_or_pd(_mm256_castpd256_pd128(q), _mm256_extractf128_pd(q, 1));
    if (i < n) {
        const __m128d t = _mm_add_pd(_mm_loadu_pd(&p[i].x), ef);
        l2 = _mm_min_pd(l2, t);
        h2 = _mm_max_pd(h2, t);
        q2 = _mm_or_pd(q2, _mm_cmpunord_pd(t, t));
    }
    lo = l2;
    hi = h2;
    nan = q2;
}

}  // namespace
}  // namespace bezel::raster_detail
BEZEL_AVX2_END

namespace bezel::raster_detail {

// Baseline code (outside the pragma): it runs on every CPU.
TranslatedBoxFn avx2_translated_box() { return cpu_has_avx2() ? translated_box : nullptr; }

}  // namespace bezel::raster_detail

#else
namespace bezel::raster_detail {
TranslatedBoxFn avx2_translated_box() { return nullptr; }
}  // namespace bezel::raster_detail
#endif
