// The merge step every segment-pair solver ends with: endpoint snapping, validation, removal of
// points that belong to an overlap, merging of duplicates and near-tangent twins, classification.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "intersect/curve_ops.hpp"

namespace bezel::isect {

namespace {

// If parameter x of curve X is within kSnapParam of an end and that end lies on Y (within kTouch)
// near parameter y, make x the exact end and y the foot of that end on Y.
void snap(const Curve& x_curve, const Curve& y_curve, double& x, double& y) {
    for (double e : {0.0, 1.0}) {
        if (std::fabs(x - e) > kSnapParam || x == e) continue;
        Point p = x_curve.eval(e);
        double yy = project(y_curve, p, y, 0.0, 1.0);
        if (distance(p, y_curve.eval(yy)) <= kTouch) {
            x = e;
            y = yy;
        }
    }
}

bool is_end(double t) { return t == 0.0 || t == 1.0; }

double sine_between(Vec2 u, Vec2 v) {
    double l = std::sqrt(u.length_squared() * v.length_squared());
    return l > 0.0 ? std::fabs(u.cross(v)) / l : 1.0;
}

int rank(const Hit& h) {  // which twin of a merged group represents it
    return (is_end(h.s) || is_end(h.t) ? 4 : 0) + (h.source == Source::Endpoint ? 2 : 0) +
           (h.source == Source::Tangent ? 1 : 0);
}

void merge_overlaps(std::vector<CurveOverlap>& ov) {
    std::sort(ov.begin(), ov.end(),
              [](const CurveOverlap& l, const CurveOverlap& r) { return l.t_a0 < r.t_a0; });
    std::vector<CurveOverlap> out;
    for (const CurveOverlap& o : ov) {
        if (!out.empty()) {
            CurveOverlap& p = out.back();
            // One stretch cut at a turning point of x′ that is not a fold: join it back.
            if (std::fabs(p.t_a1 - o.t_a0) <= 1e-12 && std::fabs(p.t_b1 - o.t_b0) <= 1e-12 &&
                (p.t_b1 - p.t_b0 >= 0) == (o.t_b1 - o.t_b0 >= 0)) {
                p.t_a1 = o.t_a1;
                p.t_b1 = o.t_b1;
                continue;
            }
        }
        out.push_back(o);
    }
    ov = std::move(out);
}

}  // namespace

void finish(const Curve& a, const Curve& b, const Curve& orig_a, Raw& raw,
            CurveIntersections& out) {
    std::vector<Hit>& hits = raw.hits;
    // Endpoints shared by both curves, exactly.
    for (double ea : {0.0, 1.0})
        for (double eb : {0.0, 1.0})
            if (distance(a.eval(ea), b.eval(eb)) <= kTouch) hits.push_back({ea, eb, Source::Endpoint});

    // Clamp, snap, validate.
    std::vector<Hit> kept;
    kept.reserve(hits.size());
    for (Hit h : hits) {
        h.s = std::clamp(h.s, 0.0, 1.0);
        h.t = std::clamp(h.t, 0.0, 1.0);
        snap(a, b, h.s, h.t);
        snap(b, a, h.t, h.s);
        if (distance(a.eval(h.s), b.eval(h.t)) > 2.0 * kTouch) continue;  // invents nothing
        kept.push_back(h);
    }

    // Points inside (or at the ends of) an overlap are part of it.
    merge_overlaps(raw.overlaps);
    const double m = kTangentMergeParam;
    kept.erase(std::remove_if(kept.begin(), kept.end(),
                              [&](const Hit& h) {
                                  for (const CurveOverlap& o : raw.overlaps) {
                                      double b0 = std::min(o.t_b0, o.t_b1), b1 = std::max(o.t_b0, o.t_b1);
                                      if (h.s >= o.t_a0 - m && h.s <= o.t_a1 + m && h.t >= b0 - m &&
                                          h.t <= b1 + m)
                                          return true;
                                  }
                                  return false;
                              }),
               kept.end());

    // Merge twins: the same root found twice, or the noisy sign changes around one contact.
    const int n = static_cast<int>(kept.size());
    std::vector<int> group(kept.size());
    std::iota(group.begin(), group.end(), 0);
    auto root = [&](int i) {
        while (group[i] != i) i = group[i] = group[group[i]];
        return i;
    };
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j) {
            const Hit &p = kept[i], &q = kept[j];
            if (std::fabs(p.s - q.s) > m || std::fabs(p.t - q.t) > m) continue;
            // Two real crossings this close keep apart only if the curves separate between them.
            Point mid_a = a.eval(0.5 * (p.s + q.s)), mid_b = b.eval(0.5 * (p.t + q.t));
            if (distance(mid_a, mid_b) > 4.0 * kTouch) continue;
            group[root(j)] = root(i);
        }
    std::vector<int> best(kept.size(), -1), members(kept.size(), 0);
    std::vector<bool> spread(kept.size(), false);
    for (int i = 0; i < n; ++i) {
        int r = root(i);
        ++members[r];
        if (best[r] < 0 || rank(kept[i]) > rank(kept[best[r]])) best[r] = i;
    }
    for (int i = 0; i < n; ++i) {
        int r = root(i), b0 = best[r];
        if (std::fabs(kept[i].s - kept[b0].s) > 1e-12 || std::fabs(kept[i].t - kept[b0].t) > 1e-12)
            spread[r] = true;
    }

    out.points.clear();
    for (int r = 0; r < n; ++r) {
        if (root(r) != r) continue;
        const Hit& h = kept[best[r]];
        CurveIntersection ci;
        ci.t_a = h.s;
        ci.t_b = h.t;
        ci.point = orig_a.eval(h.s);
        if (is_end(h.s) || is_end(h.t))
            ci.kind = IntersectionKind::Endpoint;
        else if (h.source == Source::Tangent || spread[r] ||
                 sine_between(a.deriv_at(h.s), b.deriv_at(h.t)) < kTangentSine)
            ci.kind = IntersectionKind::Tangent;
        else
            ci.kind = IntersectionKind::Cross;
        out.points.push_back(ci);
    }
    std::sort(out.points.begin(), out.points.end(),
              [](const CurveIntersection& l, const CurveIntersection& r) {
                  return l.t_a != r.t_a ? l.t_a < r.t_a : l.t_b < r.t_b;
              });
    out.overlaps = raw.overlaps;
}

}  // namespace bezel::isect
