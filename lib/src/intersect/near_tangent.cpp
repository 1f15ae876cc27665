// Near-tangent regions: the leaf boxes subdivision could neither separate nor isolate.
//
// Adjacent leaves are grouped into clusters. In each, one curve (the "driver" X, the longer
// piece) is sampled, every sample projected onto the other curve Y, and the signed distance
//   g(u) = Y′(v) × (X(u) − Y(v)) / |Y′(v)|,  v = the foot of X(u) on Y,
// tabulated. A sign change of g brackets a crossing (refined by 2D Newton, else bisection on g);
// a local minimum of |g| without sign change is a candidate contact, refined by Newton on the
// tangency equations (newton_tangent) and kept when the curves there are within kTouch. The
// merge step (finish) then folds hits closer than kTangentMergeParam into one tangent point —
// the rounding noise of an exact contact can make g change sign around it.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <numeric>

#include "intersect/curve_ops.hpp"

namespace bezel::isect {

namespace {

int find_root(std::vector<int>& parent, int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

struct Sample {
    double u, v, g;
    bool clamped;  // the foot landed on the end of Y's range: g is not a perpendicular distance
};

struct Scan {
    const Curve& x;
    const Curve& y;
    double u0, u1, v0, v1;
    bool swapped;  // x is B

    Sample sample(double u, double v_guess) const {
        Point p = x.eval(u);
        double v = project(y, p, v_guess, v0, v1);
        Vec2 dy = y.deriv_at(v);
        Vec2 d = p - y.eval(v);
        double len = dy.length();
        double g = len > 0.0 ? dy.cross(d) / len : d.length();
        // At the range ends the foot is only a true foot if the gradient vanishes there.
        bool at_end = (v == v0 && v0 > 0.0) || (v == v1 && v1 < 1.0);
        bool clamped = at_end && std::fabs(d.dot(dy)) > 1e-9 * std::max(len, 1e-300);
        return {u, v, g, clamped};
    }

    void emit(double u, double v, Source src, Raw& raw) const {
        if (swapped)
            raw.hits.push_back({v, u, src});
        else
            raw.hits.push_back({u, v, src});
    }

    // A crossing between two samples of opposite sign.
    void crossing(const Sample& l, const Sample& r, Raw& raw) const {
        double u = 0.5 * (l.u + r.u), v = 0.5 * (l.v + r.v);
        if (newton_cross(x, y, u, v, l.u, r.u, v0, v1, 1e-12)) {
            emit(u, v, Source::Newton, raw);
            return;
        }
        // Bisection on g: slow, certain. 64 halvings exhaust a double interval.
        Sample lo = l, hi = r;
        for (int i = 0; i < 64 && hi.u - lo.u > 0.0; ++i) {
            double um = 0.5 * (lo.u + hi.u);
            if (um <= lo.u || um >= hi.u) break;
            Sample m = sample(um, 0.5 * (lo.v + hi.v));
            if (m.g == 0.0) {
                lo = hi = m;
                break;
            }
            ((m.g < 0.0) == (lo.g < 0.0) ? lo : hi) = m;
        }
        emit(lo.u, lo.v, Source::Newton, raw);
    }

    // A contact candidate at a local minimum of |g|.
    void contact(const Sample& m, double u_lo, double u_hi, Raw& raw) const {
        double u = m.u, v = m.v;
        if (newton_tangent(x, y, u, v, u0, u1, v0, v1, 0.0) &&
            distance(x.eval(u), y.eval(v)) <= kTouch) {
            emit(u, v, Source::Tangent, raw);
            return;
        }
        // Equal curvature or a cusp: minimise |g| by golden section instead.
        double a = u_lo, b = u_hi, v_guess = m.v;
        const double k = 0.5 * (std::sqrt(5.0) - 1.0);
        for (int i = 0; i < 80 && b - a > 1e-16; ++i) {
            double c = b - k * (b - a), d = a + k * (b - a);
            Sample sc = sample(c, v_guess), sd = sample(d, v_guess);
            if (std::fabs(sc.g) < std::fabs(sd.g)) {
                b = d;
                v_guess = sc.v;
            } else {
                a = c;
                v_guess = sd.v;
            }
        }
        Sample best = sample(0.5 * (a + b), v_guess);
        if (std::fabs(m.g) < std::fabs(best.g)) best = m;
        if (std::fabs(best.g) <= kTouch && !best.clamped) emit(best.u, best.v, Source::Tangent, raw);
    }

    void run(int n_samples, Raw& raw) const {
        std::vector<Sample> s;
        s.reserve(static_cast<std::size_t>(n_samples) + 1);
        // Starting foot: the nearest of a few points of Y's range.
        Point p0 = x.eval(u0);
        double v_guess = v0, best = HUGE_VAL;
        for (int k = 0; k <= 8; ++k) {
            double v = v0 + (v1 - v0) * k / 8.0;
            double d = distance(y.eval(v), p0);
            if (d < best) best = d, v_guess = v;
        }
        for (int k = 0; k <= n_samples; ++k) {
            double u = k == n_samples ? u1 : u0 + (u1 - u0) * k / n_samples;
            s.push_back(sample(u, v_guess));
            v_guess = s.back().v;
        }
        const int n = static_cast<int>(s.size());
        for (int k = 0; k < n; ++k) {
            if (s[k].clamped) continue;
            if (s[k].g == 0.0) {
                emit(s[k].u, s[k].v, Source::Newton, raw);
                continue;
            }
            if (k + 1 < n && !s[k + 1].clamped && s[k + 1].g != 0.0 &&
                (s[k].g < 0.0) != (s[k + 1].g < 0.0))
                crossing(s[k], s[k + 1], raw);
            // Local minimum of |g| (plateaus count once, at their first sample). Next to a sign
            // change it is the crossing's own dip (or, between two close crossings, the gap
            // between them): crossing() has it, so it is not a contact.
            auto flips = [&](int i, int j) {
                return i >= 0 && j < n && (s[i].g < 0.0) != (s[j].g < 0.0) && s[i].g != 0.0 &&
                       s[j].g != 0.0;
            };
            if (flips(k - 1, k) || flips(k, k + 1)) continue;
            double here = std::fabs(s[k].g);
            bool left_higher = k == 0 || std::fabs(s[k - 1].g) > here;
            bool right_higher = k + 1 == n || std::fabs(s[k + 1].g) >= here;
            if (left_higher && right_higher) {
                double lo = s[std::max(k - 1, 0)].u, hi = s[std::min(k + 1, n - 1)].u;
                contact(s[k], lo, hi, raw);
            }
        }
    }
};

}  // namespace

void resolve_leaves(const Curve& a, const Curve& b, std::vector<Leaf>& leaves, Raw& raw) {
    const double w = std::ldexp(1.0, -kIntersectLeafDepth);
    const int n = static_cast<int>(leaves.size());
    std::vector<int> parent(leaves.size());
    std::iota(parent.begin(), parent.end(), 0);
    // Leaves touching (within one leaf width) in both parameters belong to one cluster. Every
    // leaf is at most w wide (curve_curve stops halving there), so touching leaves i, j have
    // |s0_j − s0_i| ≤ 2w and |t0_j − t0_i| ≤ 2w: their grid cells (s0/w, t0/w) differ by at
    // most 2 in each direction. Looking up those 25 cells in the sorted cell list keeps this
    // O(n log n); comparing all pairs in a band of s was quadratic when many leaves share a
    // stretch of s (a fuzzer's near-coincident pair took minutes).
    auto cell = [w](double v) { return static_cast<std::int64_t>(std::floor(v / w)); };
    std::vector<std::pair<std::pair<std::int64_t, std::int64_t>, int>> cells(leaves.size());
    for (int i = 0; i < n; ++i) cells[i] = {{cell(leaves[i].s0), cell(leaves[i].t0)}, i};
    std::sort(cells.begin(), cells.end());
    for (int i = 0; i < n; ++i) {
        const std::int64_t cs = cell(leaves[i].s0), ct = cell(leaves[i].t0);
        for (std::int64_t ds = -2; ds <= 2; ++ds) {
            auto lo = std::lower_bound(cells.begin(), cells.end(),
                                       std::make_pair(std::make_pair(cs + ds, ct - 2), -1));
            for (auto it = lo; it != cells.end() && it->first.first == cs + ds &&
                               it->first.second <= ct + 2;
                 ++it) {
                const int j = it->second;
                if (j == i) continue;
                if (leaves[j].s0 <= leaves[i].s1 + w && leaves[i].s0 <= leaves[j].s1 + w &&
                    leaves[j].t0 <= leaves[i].t1 + w && leaves[i].t0 <= leaves[j].t1 + w)
                    parent[find_root(parent, j)] = find_root(parent, i);
            }
        }
    }

    std::vector<Leaf> box(leaves.size(), Leaf{HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL});
    std::vector<int> count(leaves.size(), 0);
    for (int i = 0; i < n; ++i) {
        int r = find_root(parent, i);
        Leaf& c = box[r];
        c.s0 = std::min(c.s0, leaves[i].s0);
        c.s1 = std::max(c.s1, leaves[i].s1);
        c.t0 = std::min(c.t0, leaves[i].t0);
        c.t1 = std::max(c.t1, leaves[i].t1);
        ++count[r];
    }
    for (int i = 0; i < n; ++i) {
        if (count[i] == 0) continue;
        // Widen by a leaf on each side so a contact on the cluster's edge is bracketed.
        Leaf c{std::max(0.0, box[i].s0 - w), std::min(1.0, box[i].s1 + w),
               std::max(0.0, box[i].t0 - w), std::min(1.0, box[i].t1 + w)};
        double len_a = distance(a.eval(c.s0), a.eval(c.s1));
        double len_b = distance(b.eval(c.t0), b.eval(c.t1));
        int samples = std::clamp(4 * count[i], 16, 1024);
        if (len_a >= len_b)
            Scan{a, b, c.s0, c.s1, c.t0, c.t1, false}.run(samples, raw);
        else
            Scan{b, a, c.t0, c.t1, c.s0, c.s1, true}.run(samples, raw);
    }
}

}  // namespace bezel::isect
