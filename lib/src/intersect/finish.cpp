// The merge step every segment-pair solver ends with: endpoint snapping, validation, removal of
// points that belong to an overlap, merging of duplicates and near-tangent twins, classification.
#include <algorithm>
#include <cmath>

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
    const double touch2 = kTouch * kTouch;
    for (int ea = 0; ea < 2; ++ea)
        for (int eb = 0; eb < 2; ++eb)
            if ((a.p[ea * a.degree] - b.p[eb * b.degree]).length_squared() <= touch2)
                hits.push_back({double(ea), double(eb), Source::Endpoint});

    // Clamp, snap, validate (nothing further than 2·kTouch apart survives: invents nothing);
    // points inside or at the ends of an overlap belong to it.
    merge_overlaps(raw.overlaps);
    const double m = kTangentMergeParam;
    auto in_overlap = [&](const Hit& h) {
        for (const CurveOverlap& o : raw.overlaps) {
            double b0 = std::min(o.t_b0, o.t_b1), b1 = std::max(o.t_b0, o.t_b1);
            if (h.s >= o.t_a0 - m && h.s <= o.t_a1 + m && h.t >= b0 - m && h.t <= b1 + m) return true;
        }
        return false;
    };
    std::size_t w = 0;
    for (Hit h : hits) {
        h.s = std::clamp(h.s, 0.0, 1.0);
        h.t = std::clamp(h.t, 0.0, 1.0);
        snap(a, b, h.s, h.t);
        snap(b, a, h.t, h.s);
        if ((a.eval(h.s) - b.eval(h.t)).length_squared() > 4.0 * touch2) continue;
        if (in_overlap(h)) continue;
        hits[w++] = h;
    }
    hits.resize(w);

    // Merge twins: the same root found twice, or the noisy sign changes around one contact.
    // Union–find over at most a few dozen hits; `best` is each group's representative.
    const int n = static_cast<int>(hits.size());
    std::vector<int> group(2 * hits.size());
    int* parent = group.data();
    int* best = parent + n;
    for (int i = 0; i < n; ++i) parent[i] = i, best[i] = -1;
    auto root = [&](int i) {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
    };
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j) {
            const Hit &p = hits[i], &q = hits[j];
            if (std::fabs(p.s - q.s) > m || std::fabs(p.t - q.t) > m) continue;
            // Two real crossings this close keep apart only if the curves separate between them.
            Point mid_a = a.eval(0.5 * (p.s + q.s)), mid_b = b.eval(0.5 * (p.t + q.t));
            if ((mid_a - mid_b).length_squared() > 16.0 * touch2) continue;
            parent[root(j)] = root(i);
        }
    for (int i = 0; i < n; ++i) {
        int r = root(i);
        if (best[r] < 0 || rank(hits[i]) > rank(hits[best[r]])) best[r] = i;
    }

    out.points.clear();
    for (int r = 0; r < n; ++r) {
        if (root(r) != r) continue;
        const Hit& h = hits[best[r]];
        // A group whose members differ is a contact seen as several nearby roots.
        bool spread = false;
        for (int i = 0; i < n; ++i)
            if (root(i) == r)
                spread |= std::fabs(hits[i].s - h.s) > 1e-12 || std::fabs(hits[i].t - h.t) > 1e-12;
        CurveIntersection ci;
        ci.t_a = h.s;
        ci.t_b = h.t;
        ci.point = orig_a.eval(h.s);
        if (is_end(h.s) || is_end(h.t))
            ci.kind = IntersectionKind::Endpoint;
        else if (h.source == Source::Tangent || spread ||
                 sine_between(a.deriv_at(h.s), b.deriv_at(h.t)) < kTangentSine)
            ci.kind = IntersectionKind::Tangent;
        else
            ci.kind = IntersectionKind::Cross;
        out.points.push_back(ci);
    }
    if (out.points.size() > 1)
        std::sort(out.points.begin(), out.points.end(),
                  [](const CurveIntersection& l, const CurveIntersection& r) {
                      return l.t_a != r.t_a ? l.t_a < r.t_a : l.t_b < r.t_b;
                  });
    out.overlaps = raw.overlaps;
}

}  // namespace bezel::isect
