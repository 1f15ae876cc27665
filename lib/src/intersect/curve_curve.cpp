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
#include <new>
#include <type_traits>

#include "intersect/curve_ops.hpp"

namespace bezel::isect {

namespace {

struct Piece {
    Curve c;
    double t0, t1;
    Rect box;
};

struct Cone {
    Vec2 lo, hi;  // extreme rays; the cone runs counter-clockwise (y up) from lo to hi
    double lo_l1 = 0.0, hi_l1 = 0.0;  // |lo|₁, |hi|₁ for the relative margin
    bool ok = false;
};

double l1(Vec2 v) { return std::fabs(v.x) + std::fabs(v.y); }

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
    k.lo_l1 = l1(k.lo);
    k.hi_l1 = l1(k.hi);
    k.ok = true;
    return k;
}

// v inside the cone, with a small angular margin (relative, ~1e-12 rad) so that rounding in the
// split control points can only make us more cautious. |u × v| ≤ |u|₁·|v|₁, so the margin is
// scaled by L1 norms instead of Euclidean ones: no square root in the hot loop.
constexpr double kConeMargin = 1e-12;
bool contains(const Cone& k, Vec2 v) {
    double m = kConeMargin * l1(v);
    return k.lo.cross(v) >= -m * k.lo_l1 && v.cross(k.hi) >= -m * k.hi_l1;
}

bool isolated(const Cone& a, const Cone& b) {
    if (!a.ok || !b.ok) return false;
    Cone nb = b;
    nb.lo = -b.lo;
    nb.hi = -b.hi;
    // Arcs shorter than 90° meet iff one contains the other's first ray.
    bool meet = contains(a, b.lo) || contains(b, a.lo) || contains(a, nb.lo) || contains(nb, a.lo);
    return !meet;
}

bool overlaps(const Rect& a, const Rect& b, double tol) {
    return a.x0 <= b.x1 + tol && b.x0 <= a.x1 + tol && a.y0 <= b.y1 + tol && b.y0 <= a.y1 + tol;
}

Piece make_piece(const Curve& c, double t0, double t1) { return {c, t0, t1, control_box(c)}; }

// de Casteljau at ½: every lerp is a midpoint (a + b)·½, exact up to one rounding, no branch.
std::pair<Piece, Piece> halve(const Piece& p) {
    const Curve& c = p.c;
    Curve l = c, r = c;
    if (c.degree == 3) {
        Point ab = (c.p[0] + c.p[1]) * 0.5, bc = (c.p[1] + c.p[2]) * 0.5, cd = (c.p[2] + c.p[3]) * 0.5;
        Point abc = (ab + bc) * 0.5, bcd = (bc + cd) * 0.5, m = (abc + bcd) * 0.5;
        l.p[1] = ab, l.p[2] = abc, l.p[3] = m;
        r.p[0] = m, r.p[1] = bcd, r.p[2] = cd;
    } else if (c.degree == 2) {
        Point ab = (c.p[0] + c.p[1]) * 0.5, bc = (c.p[1] + c.p[2]) * 0.5, m = (ab + bc) * 0.5;
        l.p[1] = ab, l.p[2] = m;
        r.p[0] = m, r.p[1] = bc;
    } else {
        Point m = (c.p[0] + c.p[1]) * 0.5;
        l.p[1] = m;
        r.p[0] = m;
    }
    double tm = 0.5 * (p.t0 + p.t1);
    return {make_piece(l, p.t0, tm), make_piece(r, tm, p.t1)};
}

// Fat-line test (the first step of Sederberg–Nishita Bézier clipping): A lies in the band of
// signed distances [d_min, d_max] of its control points from its chord's line; if all of B's
// control points lie on one side beyond that band (by more than tol), the pieces cannot meet.
// Much tighter than boxes for the thin, slanted pieces subdivision produces.
bool fat_line_separates(const Curve& a, const Curve& b, double tol) {
    Vec2 chord = a.p[a.degree] - a.p[0];
    double len2 = chord.length_squared();
    if (!(len2 > 0.0)) return false;
    double dmin = 0.0, dmax = 0.0;
    for (int i = 1; i < a.degree; ++i) {
        double d = chord.cross(a.p[i] - a.p[0]);
        dmin = std::min(dmin, d);
        dmax = std::max(dmax, d);
    }
    // Distances are scaled by |chord|: so is the tolerance.
    double t = tol * std::sqrt(len2);
    bool above = true, below = true;
    for (int i = 0; i <= b.degree; ++i) {
        double e = chord.cross(b.p[i] - a.p[0]);
        above &= e > dmax + t;
        below &= e < dmin - t;
    }
    return above || below;
}

// Newton's acceptance margin on a piece boundary: interior boundaries are shared with a
// neighbour, which also accepts the root (the merge removes the twin); at 0 and 1 the wider
// slack lets the endpoint snap decide.
double margin_lo(double t) { return t == 0.0 ? kParamSlack : 1e-12; }
double margin_hi(double t) { return t == 1.0 ? kParamSlack : 1e-12; }

struct Node {
    Piece a, b;
};
static_assert(std::is_trivially_copyable_v<Node> && std::is_trivially_destructible_v<Node>);

}  // namespace

bool curve_curve(const Curve& a, const Curve& b, Raw& raw, CurveOverlap* probe) {
    const double leaf_width = 1.0 / double(1 << kIntersectLeafDepth);
    bool probed = probe == nullptr;
    // The boxes are grown by half the touch tolerance each, so pieces within kTouch of each
    // other are examined (and become tangent contacts), as the contract promises.
    const double box_tol = 0.5 * kTouch;
    // Depth-first with an explicit stack: a node leaves at most 3 siblings behind per level, and
    // each step halves at least one piece, so there are at most 2·kIntersectLeafDepth levels.
    constexpr int kStack = 3 * (2 * kIntersectLeafDepth + 1) + 4;
    // Raw storage: Curve's member initialisers would otherwise zero all kStack nodes per call
    // (more work than a typical intersection). Node is trivially copyable and destructible.
    alignas(Node) unsigned char storage[sizeof(Node) * kStack];
    Node* stack = reinterpret_cast<Node*>(storage);
    int top = 0;
    new (&stack[top++]) Node{make_piece(a, 0.0, 1.0), make_piece(b, 0.0, 1.0)};
    std::vector<Leaf> leaves;

    while (top > 0) {
        const Node n = stack[--top];
        if (fat_line_separates(n.a.c, n.b.c, kTouch) || fat_line_separates(n.b.c, n.a.c, kTouch))
            continue;
        if (++raw.work > kMaxIntersectWork) {
            raw.over_budget = true;
            return false;
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
        // Coincident curves never isolate: once a pair is still entangled this deep, check (once)
        // whether the curves share a stretch. Random pairs rarely get here, so the endpoint
        // projections this costs are paid almost only when they are needed.
        if (!iso && !probed && n.a.t1 - n.a.t0 <= kOverlapProbeWidth) {
            probed = true;
            if (find_overlap(a, b, *probe)) return true;
        }
        const bool split_a = n.a.t1 - n.a.t0 > leaf_width;
        const bool split_b = n.b.t1 - n.b.t0 > leaf_width;
        if (!split_a && !split_b) {
            leaves.push_back({n.a.t0, n.a.t1, n.b.t0, n.b.t1});
            continue;
        }
        if (top + 4 > kStack) {  // unreachable: see kStack
            raw.over_budget = true;
            return false;
        }
        // Halve the bigger piece, or both when they are of a size: a small piece against a big
        // one gains nothing from being cut further. Children whose boxes miss are not pushed.
        const double size_a = std::max(n.a.box.width(), n.a.box.height());
        const double size_b = std::max(n.b.box.width(), n.b.box.height());
        const bool cut_a = split_a && (!split_b || size_a * 2.0 >= size_b);
        const bool cut_b = split_b && (!split_a || size_b * 2.0 >= size_a);
        auto push = [&](const Piece& pa, const Piece& pb) {
            if (overlaps(pa.box, pb.box, box_tol)) new (&stack[top++]) Node{pa, pb};
        };
        if (cut_a && cut_b) {
            auto [a0, a1] = halve(n.a);
            auto [b0, b1] = halve(n.b);
            push(a1, b1);
            push(a1, b0);
            push(a0, b1);
            push(a0, b0);
        } else if (cut_a) {
            auto [a0, a1] = halve(n.a);
            push(a1, n.b);
            push(a0, n.b);
        } else {
            auto [b0, b1] = halve(n.b);
            push(n.a, b1);
            push(n.a, b0);
        }
    }
    if (!leaves.empty()) resolve_leaves(a, b, leaves, raw);
    return false;
}

}  // namespace bezel::isect
