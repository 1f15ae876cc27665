// fuzz_intersect — intersections of random lines, quadratics and cubics (and of small paths):
// never a crash or hang; every parameter in [0, 1], every point finite, points sorted by t_a and
// never duplicated, overlaps ordered as intersect.hpp states.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "bezel/intersect.hpp"
#include "fuzz_reader.hpp"

namespace {

using bezel::fuzz::FuzzReader;

bezel::Curve read_curve(FuzzReader& in) {
    bezel::Curve c;
    c.degree = 1 + static_cast<int>(in.byte() % 3);
    // Often reuse a point: shared end points and collapsed control polygons are the hard cases.
    for (int i = 0; i <= c.degree; ++i) c.p[i] = (i > 0 && in.byte() < 48) ? c.p[i - 1] : in.point();
    return c;
}

bool in_unit(double t) { return t >= 0.0 && t <= 1.0; }

void check(const bezel::CurveIntersections& r) {
    for (std::size_t i = 0; i < r.points.size(); ++i) {
        const auto& p = r.points[i];
        BEZEL_FUZZ_CHECK(in_unit(p.t_a) && in_unit(p.t_b));
        BEZEL_FUZZ_CHECK(std::isfinite(p.point.x) && std::isfinite(p.point.y));
        if (i > 0) {
            const auto& q = r.points[i - 1];
            BEZEL_FUZZ_CHECK(q.t_a < p.t_a || (q.t_a == p.t_a && q.t_b <= p.t_b));
            BEZEL_FUZZ_CHECK(!(q.t_a == p.t_a && q.t_b == p.t_b));
        }
    }
    for (const auto& o : r.overlaps) {
        BEZEL_FUZZ_CHECK(in_unit(o.t_a0) && in_unit(o.t_a1) && in_unit(o.t_b0) && in_unit(o.t_b1));
        BEZEL_FUZZ_CHECK(o.t_a0 < o.t_a1);
    }
}

void check(const bezel::PathIntersections& r) {
    for (const auto& p : r.intersections) {
        BEZEL_FUZZ_CHECK(in_unit(p.t_a) && in_unit(p.t_b));
        BEZEL_FUZZ_CHECK(std::isfinite(p.point.x) && std::isfinite(p.point.y));
    }
    for (const auto& o : r.overlaps)
        BEZEL_FUZZ_CHECK(in_unit(o.t_a0) && in_unit(o.t_a1) && in_unit(o.t_b0) && in_unit(o.t_b1));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzReader in(data, size);
    const bezel::Curve a = read_curve(in), b = read_curve(in);
    const bool finite = a.is_finite() && b.is_finite();
    auto ab = bezel::intersect(a, b);
    if (ab) check(*ab);
    BEZEL_FUZZ_CHECK(ab.ok() || !finite || !ab.error().message.empty());
    if (!finite) BEZEL_FUZZ_CHECK(!ab.ok());
    if (auto self = bezel::self_intersect(a)) {
        check(*self);
        for (const auto& p : self->points) BEZEL_FUZZ_CHECK(p.t_a < p.t_b);
    }
    if (auto base = bezel::intersect_baseline(a, b)) {
        for (const auto& p : *base) BEZEL_FUZZ_CHECK(in_unit(p.t_a) && in_unit(p.t_b));
    }

    const bezel::Path pa = bezel::fuzz::read_path(in, 8), pb = bezel::fuzz::read_path(in, 8);
    if (auto r = bezel::intersect_paths(pa, pb)) check(*r);
    if (auto r = bezel::self_intersect_path(pa)) check(*r);
    return 0;
}
