// Whole paths: every segment pair whose boxes meet (sort-and-sweep on x), each cubic's own loop
// for self-intersection, and the joint rule — a point at the end of segment i that is the start
// of its successor in the contour is reported on the successor at t = 0, which makes the two
// reports of one crossing identical (then merged) and turns the joint of two neighbours into
// (i + 1, 0) against (i + 1, 0), which is dropped.
#include <algorithm>
#include <cmath>
#include <string>

#include "intersect/curve_ops.hpp"

namespace bezel {

namespace {

constexpr std::size_t kNone = static_cast<std::size_t>(-1);

struct Segs {
    std::vector<Curve> curves;
    std::vector<Rect> boxes;
    std::vector<std::size_t> next;  // the successor at the segment's end, or kNone
};

Segs collect(const Path& path) {
    // Which contours were closed: a Close verb before the next Move.
    std::vector<bool> closed;
    for (Verb v : path.verbs()) {
        if (v == Verb::Move) closed.push_back(false);
        if (v == Verb::Close && !closed.empty()) closed.back() = true;
    }
    Segs s;
    std::vector<PathSeg> segs;
    for (const PathSeg& seg : path.segments()) segs.push_back(seg);
    s.next.assign(segs.size(), kNone);
    for (std::size_t i = 0; i < segs.size(); ++i) {
        s.curves.push_back(Curve(segs[i]));
        s.boxes.push_back(isect::control_box(s.curves.back()));
        if (i + 1 < segs.size() && segs[i + 1].contour == segs[i].contour) {
            if (segs[i + 1].start() == segs[i].end()) s.next[i] = i + 1;
        } else {
            // Last segment of its contour: a closed contour continues into its first segment.
            std::size_t first = i;
            while (first > 0 && segs[first - 1].contour == segs[i].contour) --first;
            std::size_t c = segs[i].contour;
            if (c < closed.size() && closed[c] && segs[first].start() == segs[i].end())
                s.next[i] = first;
        }
    }
    return s;
}

void canonical(const Segs& s, std::size_t& seg, double& t) {
    if (t == 1.0 && s.next[seg] != kNone) {
        seg = s.next[seg];
        t = 0.0;
    }
}

struct Collector {
    const Segs& a;
    const Segs& b;
    bool self;
    PathIntersections out;

    void add(std::size_t i, std::size_t j, const CurveIntersections& r) {
        for (const CurveIntersection& c : r.points) {
            PathIntersection p{i, j, c.t_a, c.t_b, c.point, c.kind};
            canonical(a, p.seg_a, p.t_a);
            canonical(b, p.seg_b, p.t_b);
            if (self) {
                if (p.seg_a == p.seg_b && p.t_a == p.t_b) continue;  // a joint
                if (p.seg_a > p.seg_b || (p.seg_a == p.seg_b && p.t_a > p.t_b)) {
                    std::swap(p.seg_a, p.seg_b);
                    std::swap(p.t_a, p.t_b);
                }
            }
            out.intersections.push_back(p);
        }
        for (const CurveOverlap& o : r.overlaps)
            out.overlaps.push_back({i, j, o.t_a0, o.t_a1, o.t_b0, o.t_b1});
    }

    void finish() {
        auto& v = out.intersections;
        std::sort(v.begin(), v.end(), [](const PathIntersection& l, const PathIntersection& r) {
            if (l.seg_a != r.seg_a) return l.seg_a < r.seg_a;
            if (l.t_a != r.t_a) return l.t_a < r.t_a;
            if (l.seg_b != r.seg_b) return l.seg_b < r.seg_b;
            return l.t_b < r.t_b;
        });
        // One point met through a joint comes from two segment pairs: keep the first report.
        std::vector<PathIntersection> u;
        for (const PathIntersection& p : v) {
            bool dup = false;
            for (auto it = u.rbegin(); it != u.rend() && it->seg_a == p.seg_a; ++it)
                if (it->seg_b == p.seg_b && std::fabs(it->t_a - p.t_a) <= kTangentMergeParam &&
                    std::fabs(it->t_b - p.t_b) <= kTangentMergeParam) {
                    dup = true;
                    break;
                }
            if (!dup) u.push_back(p);
        }
        v = std::move(u);
        std::sort(out.overlaps.begin(), out.overlaps.end(), [](const PathOverlap& l, const PathOverlap& r) {
            if (l.seg_a != r.seg_a) return l.seg_a < r.seg_a;
            if (l.t_a0 != r.t_a0) return l.t_a0 < r.t_a0;
            return l.seg_b < r.seg_b;
        });
    }
};

std::string seg_name(std::size_t i, std::size_t j) {
    return "segments " + std::to_string(i) + " and " + std::to_string(j);
}

// Candidate pairs by sort-and-sweep on the boxes' x extents.
Expected<std::vector<std::pair<std::size_t, std::size_t>>> candidate_pairs(const Segs& a,
                                                                          const Segs& b, bool self,
                                                                          double tol) {
    std::vector<std::size_t> order(b.boxes.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](std::size_t l, std::size_t r) { return b.boxes[l].x0 < b.boxes[r].x0; });
    std::vector<double> x0s;
    for (std::size_t k : order) x0s.push_back(b.boxes[k].x0);
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    for (std::size_t i = 0; i < a.boxes.size(); ++i) {
        const Rect& ra = a.boxes[i];
        auto end = std::upper_bound(x0s.begin(), x0s.end(), ra.x1 + tol);
        for (auto it = x0s.begin(); it != end; ++it) {
            std::size_t j = order[static_cast<std::size_t>(it - x0s.begin())];
            if (self && j <= i) continue;
            const Rect& rb = b.boxes[j];
            if (rb.x1 + tol < ra.x0 || rb.y0 > ra.y1 + tol || ra.y0 > rb.y1 + tol) continue;
            if (pairs.size() >= kMaxPathSegmentPairs)
                return Error{"intersect: more than " + std::to_string(kMaxPathSegmentPairs) +
                             " segment pairs with overlapping boxes"};
            pairs.emplace_back(i, j);
        }
    }
    return pairs;
}

Expected<PathIntersections> run(const Path& pa, const Path& pb, bool self) {
    if (!pa.is_finite() || !pb.is_finite())
        return Error{"intersect: path has a non-finite coordinate"};
    Segs a = collect(pa);
    Segs b = self ? a : collect(pb);
    Rect all = pa.control_box().union_with(pb.control_box());
    double scale = all.is_empty() ? 0.0
                                  : std::max({std::fabs(all.x0), std::fabs(all.x1), std::fabs(all.y0),
                                              std::fabs(all.y1)});
    auto pairs = candidate_pairs(a, b, self, kIntersectOverlapTolerance * scale);
    if (!pairs) return pairs.error();
    Collector col{a, b, self, {}};
    for (auto [i, j] : *pairs) {
        auto r = intersect(a.curves[i], b.curves[j]);
        if (!r) return Error{r.error().message + " (" + seg_name(i, j) + ")"};
        col.add(i, j, *r);
        if (col.out.intersections.size() + col.out.overlaps.size() > kMaxPathIntersections)
            return Error{"intersect: more than " + std::to_string(kMaxPathIntersections) + " results"};
    }
    if (self)
        for (std::size_t i = 0; i < a.curves.size(); ++i) {
            auto r = self_intersect(a.curves[i]);
            if (!r) return Error{r.error().message + " (segment " + std::to_string(i) + ")"};
            col.add(i, i, *r);
        }
    col.finish();
    return std::move(col.out);
}

}  // namespace

Expected<PathIntersections> intersect_paths(const Path& a, const Path& b) { return run(a, b, false); }

Expected<PathIntersections> self_intersect_path(const Path& path) { return run(path, path, true); }

}  // namespace bezel
