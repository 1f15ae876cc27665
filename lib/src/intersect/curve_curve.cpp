// Curve–curve intersection: bounding-box subdivision down to isolated pairs, then Newton.
//
// Isolation test (the 2D "normal cone" argument, Sederberg & Meyers 1988): the chord between
// two points of a Bézier piece is ∫C′, and C′ is a positive combination of the hodograph's
// control vectors dᵢ = Pᵢ₊₁ − Pᵢ, so every chord direction lies in the cone spanned by the dᵢ.
// Two intersections P ≠ Q of pieces A and B would make the chord PQ lie in A's cone and, up to
// sign, in B's. So when A's cone and ±B's cone are disjoint the pair meets at most once, A′ × B′
// never vanishes there, and 2D Newton is well posed: we run it from the centre and accept a root
// inside the box. Otherwise both pieces are halved (de Casteljau at ½) and the children whose
// boxes overlap are examined. Pairs still neither separated nor isolated at parameter width
// 2^-kIntersectLeafDepth are near-tangent: they become leaves for resolve_leaves.
#include <algorithm>
#include <cmath>

#include "intersect/curve_ops.hpp"

namespace bezel::isect {

namespace {

struct Piece {
    Curve c;
    double t0, t1;
    Rect box;
};

struct Cone {
    Vec2 lo, hi;  // unit vectors; the cone runs counter-clockwise (y up) from lo to hi
    bool ok = false;
};

// The cone of the hodograph control vectors, when it is narrower than 90° (wider cones never
// isolate anything useful and make the extreme-ray search ambiguous).
Cone cone_of(const Curve& c) {
    Cone k;
    bool any = false;
    Vec2 d[3];
    int n = 0;
    for (int i = 0; i < c.degree; ++i) {
        Vec2 v = c.p[i + 1] - c.p[i];
        if (v.x == 0.0 && v.y == 0.0) continue;  // adds nothing to ∫C′
        d[n++] = v;
        if (!any) {
            k.lo = k.hi = v;
            any = true;
        } else if (k.lo.cross(v) < 0.0) {
            k.lo = v;
        } else if (k.hi.cross(v) > 0.0) {
            k.hi = v;
        }
    }
    if (!any) return k;
    if (!(k.lo.dot(k.hi) > 0.0) || k.lo.cross(k.hi) < 0.0) return k;
    for (int i = 0; i < n; ++i)
        if (k.lo.cross(d[i]) < 0.0 || d[i].cross(k.hi) < 0.0) return k;
    k.lo = k.lo.normalized();
    k.hi = k.hi.normalized();
    k.ok = true;
    return k;
}

// v inside the cone, with a small angular margin so that rounding in the split control points
// can only make us more cautious.
constexpr double kConeMargin = 1e-12;
bool contains(const Cone& k, Vec2 v) {
    return k.lo.cross(v) >= -kConeMargin && v.cross(k.hi) >= -kConeMargin;
}

bool isolated(const Cone& a, const Cone& b) {
    if (!a.ok || !b.ok) return false;
    Cone nb{-b.lo, -b.hi, true};
    // Arcs shorter than 90° meet iff one contains the other's first ray.
    bool meet = contains(a, b.lo) || contains(b, a.lo) || contains(a, nb.lo) || contains(nb, a.lo);
    return !meet;
}

bool overlaps(const Rect& a, const Rect& b, double tol) {
    return a.x0 <= b.x1 + tol && b.x0 <= a.x1 + tol && a.y0 <= b.y1 + tol && b.y0 <= a.y1 + tol;
}

Piece make_piece(const Curve& c, double t0, double t1) { return {c, t0, t1, control_box(c)}; }

std::pair<Piece, Piece> halve(const Piece& p) {
    auto [l, r] = split(p.c, 0.5);
    double tm = 0.5 * (p.t0 + p.t1);
    return {make_piece(l, p.t0, tm), make_piece(r, tm, p.t1)};
}

// Newton's acceptance margin on a piece boundary: interior boundaries are shared with a
// neighbour, which also accepts the root (the merge removes the twin); at 0 and 1 the wider
// slack lets the endpoint snap decide.
double margin_lo(double t) { return t == 0.0 ? kParamSlack : 1e-12; }
double margin_hi(double t) { return t == 1.0 ? kParamSlack : 1e-12; }

struct Node {
    Piece a, b;
};

}  // namespace

void curve_curve(const Curve& a, const Curve& b, Raw& raw) {
    const double leaf_width = std::ldexp(1.0, -kIntersectLeafDepth);
    // The boxes are grown by half the touch tolerance each, so pieces within kTouch of each
    // other are examined (and become tangent contacts), as the contract promises.
    const double box_tol = 0.5 * kTouch;
    // Depth-first with an explicit stack: each level pushes at most 4 children, and levels are
    // bounded by the leaf depth, so 4·(depth + 1) entries suffice.
    constexpr int kStack = 4 * (kIntersectLeafDepth + 2);
    Node stack[kStack];
    int top = 0;
    stack[top++] = {make_piece(a, 0.0, 1.0), make_piece(b, 0.0, 1.0)};
    std::vector<Leaf> leaves;

    while (top > 0) {
        Node n = stack[--top];
        if (!overlaps(n.a.box, n.b.box, box_tol)) continue;
        if (++raw.work > kMaxIntersectWork) {
            raw.over_budget = true;
            return;
        }
        const bool iso = isolated(cone_of(n.a.c), cone_of(n.b.c));
        if (iso) {
            double s = 0.5 * (n.a.t0 + n.a.t1), t = 0.5 * (n.b.t0 + n.b.t1);
            double ms = std::max(margin_lo(n.a.t0), margin_hi(n.a.t1));
            double mt = std::max(margin_lo(n.b.t0), margin_hi(n.b.t1));
            if (newton_cross(a, b, s, t, n.a.t0, n.a.t1, n.b.t0, n.b.t1, std::max(ms, mt))) {
                if (s >= n.a.t0 - margin_lo(n.a.t0) && s <= n.a.t1 + margin_hi(n.a.t1) &&
                    t >= n.b.t0 - margin_lo(n.b.t0) && t <= n.b.t1 + margin_hi(n.b.t1)) {
                    raw.hits.push_back({s, t, Source::Newton});
                    continue;  // isolated: that was the only one
                }
            }
        }
        const bool split_a = n.a.t1 - n.a.t0 > leaf_width;
        const bool split_b = n.b.t1 - n.b.t0 > leaf_width;
        if (!split_a && !split_b) {
            leaves.push_back({n.a.t0, n.a.t1, n.b.t0, n.b.t1});
            continue;
        }
        if (top + 4 > kStack) {  // unreachable: both pieces halve together down to the leaves
            raw.over_budget = true;
            return;
        }
        if (split_a && split_b) {
            auto [a0, a1] = halve(n.a);
            auto [b0, b1] = halve(n.b);
            stack[top++] = {a1, b1};
            stack[top++] = {a1, b0};
            stack[top++] = {a0, b1};
            stack[top++] = {a0, b0};
        } else if (split_a) {
            auto [a0, a1] = halve(n.a);
            stack[top++] = {a1, n.b};
            stack[top++] = {a0, n.b};
        } else {
            auto [b0, b1] = halve(n.b);
            stack[top++] = {n.a, b1};
            stack[top++] = {n.a, b0};
        }
    }
    if (!leaves.empty()) resolve_leaves(a, b, leaves, raw);
}

}  // namespace bezel::isect
