// Coincident pieces of two curves that are not both straight.
//
// Two polynomial curves of degree ≤ 3 that are not lines and trace the same points over an
// interval lie on one algebraic curve, and a proper polynomial parametrisation of it is unique
// up to an affine change of parameter (a reparametrisation t ↦ φ(t) of degree k > 1 would raise
// the degree k-fold). So A(s) = B(α·s + β) on the shared stretch, which is one interval whose
// ends are endpoints of A or of B. Hence: collect the parameter pairs where an endpoint of one
// lies on the other; for every two of them, the affine map through them is checked by sampling
// A(lerp(s₀, s₁, u)) against B(lerp(t₀, t₁, u)) at seven interior u (four would pin a cubic down;
// seven guard the tolerance), and the longest confirmed pair is the overlap.
#include <algorithm>
#include <cmath>

#include "intersect/curve_ops.hpp"

namespace bezel::isect {

namespace {

struct Pair {
    double s, t;
};

bool same_piece(const Curve& a, const Curve& b, Pair p, Pair q) {
    for (int k = 1; k <= 7; ++k) {
        double u = k / 8.0;
        Point pa = a.eval(p.s + (q.s - p.s) * u), pb = b.eval(p.t + (q.t - p.t) * u);
        if (distance(pa, pb) > kOverlap) return false;
    }
    return true;
}

}  // namespace

bool find_overlap(const Curve& a, const Curve& b, CurveOverlap& out) {
    Rect ba = control_box(a).inflated(kOverlap), bb = control_box(b).inflated(kOverlap);
    Pair cand[16];
    int n = 0;
    double ts[3];
    for (int e = 0; e < 2; ++e) {
        Point pa = e == 0 ? a.start() : a.end();
        if (bb.contains(pa)) {
            int m = point_on_curve(pa, b, kOverlap, ts);
            for (int i = 0; i < m; ++i) cand[n++] = {double(e), ts[i]};
        }
        Point pb = e == 0 ? b.start() : b.end();
        if (ba.contains(pb)) {
            int m = point_on_curve(pb, a, kOverlap, ts);
            for (int i = 0; i < m; ++i) cand[n++] = {ts[i], double(e)};
        }
    }
    if (n < 2) return false;
    double best_len = 0.0;
    bool found = false;
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j) {
            Pair p = cand[i], q = cand[j];
            if (std::fabs(p.s - q.s) <= kTangentMergeParam || std::fabs(p.t - q.t) <= kTangentMergeParam)
                continue;
            if (p.s > q.s) std::swap(p, q);
            if (q.s - p.s <= best_len || !same_piece(a, b, p, q)) continue;
            best_len = q.s - p.s;
            out = {p.s, q.s, p.t, q.t};
            found = true;
        }
    return found;
}

}  // namespace bezel::isect
