// fuzz_smooth — random point lists (repeats, collinear runs, NaN, inf, 1e30) through every
// smoothing method and the continuity analysis. Properties: no crash; every curve a method
// returns is finite (smooth.hpp: "never a non-finite path") and has one contour; the analysis
// of a returned curve succeeds and finds no Broken joint (a Path's segments share end points).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "bezel/smooth.hpp"
#include "fuzz_reader.hpp"

namespace {

using bezel::fuzz::FuzzReader;

void check_curve(const bezel::Expected<bezel::Path>& curve) {
    if (!curve) {
        BEZEL_FUZZ_CHECK(!curve.error().message.empty());
        return;
    }
    BEZEL_FUZZ_CHECK(curve->is_finite());
    BEZEL_FUZZ_CHECK(curve->contour_count() <= 1);
    auto joints = bezel::analyze_continuity(*curve);
    BEZEL_FUZZ_CHECK(joints.ok());
    for (const bezel::JointReport& j : *joints) BEZEL_FUZZ_CHECK(j.continuity != bezel::Continuity::Broken);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzReader in(data, size);
    const bool closed = in.flag();
    const std::size_t n = in.below(40);
    std::vector<bezel::Point> points;
    for (std::size_t i = 0; i < n; ++i)
        points.push_back(i > 0 && in.byte() < 40 ? points.back() : in.point());
    std::vector<bezel::Vec2> tangents;
    for (std::size_t i = 0; i < n; ++i) tangents.push_back(in.point());

    bezel::ChaikinOptions chaikin{closed, in.flag()};
    // Bounded rounds keep each run fast; the wall itself (kMaxChaikinIterations, the output
    // limit) is crossed by the limits tests.
    const int rounds = static_cast<int>(in.byte() % 8) - 1;
    if (auto cut = bezel::chaikin(points, rounds, chaikin))
        for (const bezel::Point& p : *cut) BEZEL_FUZZ_CHECK(std::isfinite(p.x) && std::isfinite(p.y));
    check_curve(bezel::chaikin_limit(points, chaikin));
    check_curve(bezel::bspline(points, {closed, in.flag()}));
    check_curve(bezel::natural_spline(points, {closed, bezel::SplineParam::Uniform}));
    check_curve(bezel::natural_spline(points, {closed, bezel::SplineParam::ChordLength}));
    bezel::CatmullRomOptions cr;
    cr.closed = closed;
    cr.alpha = in.byte() < 200 ? (in.byte() % 5) * 0.25 : in.number();
    cr.tension = in.byte() < 200 ? (in.byte() % 5) * 0.25 : in.number();
    check_curve(bezel::catmull_rom(points, cr));
    check_curve(bezel::hermite(points, tangents, closed));
    const double tension = in.byte() < 200 ? 0.5 : in.number();
    if (auto t = bezel::cardinal_tangents(points, tension, closed))
        for (const bezel::Vec2& v : *t) BEZEL_FUZZ_CHECK(std::isfinite(v.x) && std::isfinite(v.y));
    check_curve(bezel::cardinal_spline(points, tension, closed));

    // The analysis of arbitrary paths and loose pieces (not only of smooth ones).
    const double tolerance = in.byte() < 200 ? bezel::kDefaultContinuityTolerance : in.number();
    const bezel::Path path = bezel::fuzz::read_path(in, 16);
    (void)bezel::analyze_continuity(path, tolerance);
    std::vector<bezel::CubicBez> pieces;
    for (std::size_t i = 0, m = in.below(6); i < m; ++i) {
        bezel::Point p0 = in.point(), p1 = in.point(), p2 = in.point();
        pieces.push_back({p0, p1, p2, in.point()});
    }
    (void)bezel::analyze_joints(pieces, in.flag(), tolerance);
    return 0;
}
