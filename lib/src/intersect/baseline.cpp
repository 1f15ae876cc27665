// The course notes' recursive subdivision, kept as the oracle (intersect_baseline).
//
// Split both curves at ½ until the control boxes separate, or until both control polygons are
// within `flatness` of their chords; then the chords stand in for the pieces and are intersected
// as lines. A piece's deviation from its chord shrinks 4× per halving, so the depth needed is
// log₄(size/flatness) ≈ 17 for the default 1e-10. Nothing clever: no isolation, no Newton, no
// tangent or overlap handling — which is what makes it a trustworthy reference for crossings.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "intersect/curve_ops.hpp"

namespace bezel {

namespace {

using isect::control_box;

struct Piece {
    Curve c;
    double t0, t1;
};

double chord_deviation(const Curve& c) {
    Vec2 r = c.end() - c.start();
    double len = r.length(), dev = 0.0;
    for (int i = 1; i < c.degree; ++i)
        dev = std::max(dev, len > 0.0 ? std::fabs(r.cross(c.p[i] - c.p[0])) / len
                                      : distance(c.p[i], c.p[0]));
    return dev;
}

struct Baseline {
    double flatness;
    std::vector<CurveIntersection> found;
    std::size_t work = 0;

    void run(const Piece& a, const Piece& b, int depth) {
        Rect ba = control_box(a.c), bb = control_box(b.c);
        const double tol = flatness;
        if (ba.x0 > bb.x1 + tol || bb.x0 > ba.x1 + tol || ba.y0 > bb.y1 + tol || bb.y0 > ba.y1 + tol)
            return;
        if (++work > 4 * kMaxIntersectWork) return;
        bool flat_a = chord_deviation(a.c) <= flatness, flat_b = chord_deviation(b.c) <= flatness;
        if ((flat_a && flat_b) || depth >= 60) {
            // Chord against chord: P + s·r = Q + t·u.
            Vec2 r = a.c.end() - a.c.start(), u = b.c.end() - b.c.start(), w = b.c.start() - a.c.start();
            double d = r.cross(u);
            if (d == 0.0) return;
            double s = w.cross(u) / d, t = w.cross(r) / d;
            const double slack = 1e-9;
            if (s < -slack || s > 1 + slack || t < -slack || t > 1 + slack) return;
            s = std::clamp(s, 0.0, 1.0);
            t = std::clamp(t, 0.0, 1.0);
            CurveIntersection ci;
            ci.t_a = a.t0 + (a.t1 - a.t0) * s;
            ci.t_b = b.t0 + (b.t1 - b.t0) * t;
            found.push_back(ci);
            return;
        }
        auto halves = [](const Piece& p) {
            auto [l, r] = isect::split(p.c, 0.5);
            double m = 0.5 * (p.t0 + p.t1);
            return std::pair<Piece, Piece>{{l, p.t0, m}, {r, m, p.t1}};
        };
        // Both halves every time (a flat piece stays flat, and its box keeps shrinking).
        auto [a0, a1] = halves(a);
        auto [b0, b1] = halves(b);
        run(a0, b0, depth + 1), run(a0, b1, depth + 1);
        run(a1, b0, depth + 1), run(a1, b1, depth + 1);
    }
};

}  // namespace

Expected<std::vector<CurveIntersection>> intersect_baseline(const Curve& a, const Curve& b,
                                                            double flatness) {
    if (!a.is_finite() || !b.is_finite())
        return Error{"intersect_baseline: non-finite coordinate"};
    if (!(flatness > 0.0) || !std::isfinite(flatness))
        return Error{"intersect_baseline: flatness must be finite and > 0"};
    isect::Frame f = isect::make_frame(a, b);
    Baseline bl{flatness, {}, 0};
    bl.run({f.to_frame(a), 0.0, 1.0}, {f.to_frame(b), 0.0, 1.0}, 0);
    if (bl.work > 4 * kMaxIntersectWork)
        return Error{"intersect_baseline: work limit exceeded (coincident curves?)"};
    // Neighbouring chord pairs report a crossing on their shared end twice: merge hits closer
    // than kMergeParam in both parameters. Hits are bucketed on a kMergeParam grid, so a twin is
    // in one of the 3×3 buckets around a hit: linear, where comparing every pair was quadratic
    // (a fuzzer's 1e30-wide quadratic gives 65 536 hits at one t_a, which took a minute).
    constexpr double kMergeParam = 1e-7;
    std::sort(bl.found.begin(), bl.found.end(),
              [](const CurveIntersection& l, const CurveIntersection& r) { return l.t_a < r.t_a; });
    auto cell = [](double t) { return static_cast<std::int64_t>(std::floor(t / kMergeParam)); };
    auto key = [](std::int64_t ca, std::int64_t cb) {
        return static_cast<std::uint64_t>(ca) << 32 ^ static_cast<std::uint64_t>(cb);
    };
    std::unordered_multimap<std::uint64_t, std::size_t> buckets;
    std::vector<CurveIntersection> out;
    for (CurveIntersection ci : bl.found) {
        const std::int64_t ca = cell(ci.t_a), cb = cell(ci.t_b);
        bool dup = false;
        for (std::int64_t da = -1; da <= 1 && !dup; ++da)
            for (std::int64_t db = -1; db <= 1 && !dup; ++db) {
                auto [lo, hi] = buckets.equal_range(key(ca + da, cb + db));
                for (auto it = lo; it != hi && !dup; ++it) {
                    const CurveIntersection& o = out[it->second];
                    dup = std::fabs(o.t_a - ci.t_a) <= kMergeParam &&
                          std::fabs(o.t_b - ci.t_b) <= kMergeParam;
                }
            }
        if (dup) continue;
        ci.point = a.eval(ci.t_a);
        buckets.emplace(key(ca, cb), out.size());
        out.push_back(ci);
    }
    return out;
}

}  // namespace bezel
