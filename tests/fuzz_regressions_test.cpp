// Regression tests for what fuzzing found (tests/fuzz/, `./dev fuzz`), each named after what
// broke, with the input inline (decoded from the fuzzer's bytes: the crash file is named).
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>
#include <vector>

#include "bezel/intersect.hpp"
#include "bezel/path.hpp"
#include "bezel/smooth.hpp"
#include "bezel/stroke.hpp"
#include "bezel/text.hpp"

namespace bezel {
namespace {

// fuzz_smooth crash-9f5b56b9e8eb20724d5d8ef13a8e19913d4c4986: a finite tension of DBL_MAX gave
// cardinal_tangents infinite tangents (lib/src/smooth/hermite.cpp, cardinal_tangents), which
// cardinal_spline then reported as hermite's error about tangents[0].
TEST(FuzzRegressions, CardinalTangentsWithTensionDblMaxAreAnErrorNotInfinite) {
    const std::vector<Point> points{{-39, 15},    {-30.5, -31}, {6.5, -31},   {-47, -49.5},
                                    {-47, -49.5}, {-20.5, -8.5}, {8.5, -55},  {-45.5, -5},
                                    {-45.5, -5},  {11.5, -47.5}, {-20.5, -8.5}};
    auto tangents = cardinal_tangents(points, DBL_MAX, false);
    ASSERT_FALSE(tangents.ok());
    EXPECT_NE(tangents.error().message.find("cardinal"), std::string::npos)
        << tangents.error().message;
    EXPECT_NE(tangents.error().message.find("overflows"), std::string::npos)
        << tangents.error().message;
    auto spline = cardinal_spline(points, DBL_MAX, false);
    ASSERT_FALSE(spline.ok());
    EXPECT_EQ(spline.error().message, tangents.error().message);
    // The largest tension that does not overflow still works, and stays finite.
    auto fine = cardinal_tangents(points, 1e300, false);
    ASSERT_TRUE(fine.ok());
    for (const Vec2& t : *fine) EXPECT_TRUE(std::isfinite(t.x) && std::isfinite(t.y));
}

// fuzz_text crash-9e6395058ff06cfcd00b683f5a52fe8209c206e5: a size of 4e-297 px passes the
// (0, kMaxFontSizePx] check, but HarfBuzz's scale lround(size·1024) is 0, so px_per_unit =
// size / 0 = inf (lib/src/text/shape.cpp:199-204): every advance came back inf, every offset
// NaN. Either an Error or finite positions is right; infinite ones are not.
TEST(FuzzRegressions, ShapingAtA4em297PxSizeGivesFinitePositionsOrAnError) {
    auto shaper = Shaper::open(BEZEL_FONTS_DIR "/dejavu-sans/DejaVuSans.ttf");
    ASSERT_TRUE(shaper);
    ShapeOptions options;
    options.size_px = 3.9761557023620982e-297;
    auto run = shaper->shape(" worl ", options);
    if (!run.ok()) {
        EXPECT_NE(run.error().message.find("size"), std::string::npos) << run.error().message;
        return;
    }
    for (const ShapedGlyph& g : run->glyphs) {
        EXPECT_TRUE(std::isfinite(g.x_advance_px) && std::isfinite(g.y_advance_px)) << g.gid;
        EXPECT_TRUE(std::isfinite(g.x_offset_px) && std::isfinite(g.y_offset_px)) << g.gid;
    }
}

// fuzz_stroke timeout-812e47756bff0129bb1e1d83608fa05a4fc7bb44: dashing this path (length
// ~1e5, period 15, ~7000 dashes, 20253 output segments) took 23 s at -O2 (dash.cpp cut every
// dash from the start of its segment); fixed, it takes ~0.1 s.

// The one below is a timeout: the only symptom is time, which tests do not assert, and it
// takes tens of seconds even without sanitizers, so it is DISABLED_ (run it with
// --gtest_also_run_disabled_tests). It pins the input until the code is fixed.
TEST(FuzzRegressions, DashingALongCurvedPathFinishes) {
    auto path = parse_svg_path(
        "M0 0C-9.5 5-42.5 6.5 63 16.5C-12.5 11-18.5-15-41.5-52.5C-15-39-49 63-52.5-32"
        "C-59.5-23.5-33-52 11-30.5C-42.5 6.5 63-52.5-32-101058.05500000001Z");
    ASSERT_TRUE(path);
    auto dashed = dash(*path, {1.5, 9, 4.5}, 0.5);
    ASSERT_TRUE(dashed);
    EXPECT_TRUE(dashed->is_finite());
}

// fuzz_intersect timeout-59fce1c871a4937a2a87abf56a3e3de078561765: the baseline oracle took
// a minute merging its hits pairwise: a 1e30-wide quadratic ends ~10 units from a tiny one, far
// below the oracle's precision at that scale (1e-10 of 1e30), so 65 536 chord pairs all report
// a crossing at one t_a. The merge is bucketed now; the hits stay (the oracle has no notion of
// a precision limit), each at least 1e-7 from the others in t_a or t_b.
TEST(FuzzRegressions, BaselineIntersectionOfA1e30QuadMergesItsHitsInLinearTime) {
    const QuadBez a{{-42.5, 1e30}, {1e30, 63.5}, {-43.5, -61}};
    const QuadBez b{{-31.5, -17}, {1.3537398696050155e-321, -64}, {1.3537398696050155e-321, -64}};
    auto r = intersect_baseline(a, b);
    ASSERT_TRUE(r);
    ASSERT_GT(r->size(), 1000u);  // the many hits this regression is about
    std::vector<CurveIntersection> hits = *r;
    std::sort(hits.begin(), hits.end(), [](const auto& l, const auto& m) {
        return l.t_b < m.t_b || (l.t_b == m.t_b && l.t_a < m.t_a);
    });
    for (std::size_t i = 1; i < hits.size(); ++i)  // no two within 1e-7 in both parameters
        EXPECT_FALSE(std::fabs(hits[i].t_b - hits[i - 1].t_b) <= 1e-7 &&
                     std::fabs(hits[i].t_a - hits[i - 1].t_a) <= 1e-7) << i;
    for (const auto& h : hits) EXPECT_TRUE(h.t_a >= 0 && h.t_a <= 1 && h.t_b >= 0 && h.t_b <= 1);
}

}  // namespace
}  // namespace bezel
