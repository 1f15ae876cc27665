// One contour's stroke outline: offsets on both sides, joins, caps, and the extra contours that
// make tight curvature and cusps fill correctly.
//
// Why the pieces fill correctly with non-zero (after Nehab 2020, §4). The outline of one
// contour is: the left offset (s = +h) forward, the end cap, the right offset (s = −h)
// backward, the start cap. Summed as winding numbers it equals the sum of each element's own
// strip boundary, F(∂([0,1] × [−h, h])), plus one closed wedge per join and the caps — provided
// the INNER side of every join goes through the join point itself (offset end → pivot → next
// offset start): the two normals through the pivot then cancel against the strips' ends. Every
// one of those regions winds the same way (negative Path::signed_area, i.e. counter-clockwise on
// a y-down screen), so covered points wind ≠ 0 —
// except inside a fold. Where |κ|·h > 1 the strip's map F folds along the evolute s = 1/κ: the
// part Q beyond it (between the evolute and the inner offset) has a negative Jacobian, so a
// point covered once by Q and once by the unfolded part P winds 1 − 1 = 0, a hole. Adding Q's
// boundary twice, turned to wind like the rest, gives W_P − W_Q ≥ 1 wherever the strip covers.
// At a cusp (C′ = 0) the normal flips; both sides pass through the cusp point and a full disc
// of radius h is added there (the round join SVG renderers draw at a cusp).
#include <cmath>

#include "stroke/stroke_internal.hpp"

namespace bezel::stroke_detail {
namespace {

// One drawable element of a contour: a line or a cusp-free curve piece.
struct Elem {
    bool is_line = true;
    Point a, b;        // line ends
    CurvePiece piece;  // when !is_line
    Point p_start, p_end;
    Vec2 t_start, t_end;  // unit tangents
    bool cusp_before = false;
};

class ContourStroker {
public:
    ContourStroker(const StrokeStyle& style, double tol, double size, Budget& budget)
        : style_(style), h_(style.width / 2), tol_(tol), size_(size), budget_(budget) {}

    void run(const ContourInput& in, Path& out);

private:
    void collect(const ContourInput& in);
    void add_elem(const Elem& e);
    void join(const Elem& a, const Elem& b);
    void cap(Path& path, Point p, Vec2 d);
    void disc(Path& path, Point p);
    void fold_contours(const std::vector<CubicBez>& inner, const CurvePiece& piece);

    const StrokeStyle& style_;
    double h_, tol_, size_;
    Budget& budget_;
    std::vector<Elem> elems_;
    Path left_, right_, extras_;
    std::vector<CubicBez> lc_, rc_;
};

void ContourStroker::collect(const ContourInput& in) {
    std::vector<CurvePiece> pieces;
    for (const PathSeg& seg : in.segs) {
        if (seg.kind == SegKind::Line) {
            Vec2 d = seg.p[1] - seg.p[0];
            if (!(d.length() > 1e-12 * size_)) continue;
            Elem e;
            e.a = e.p_start = seg.p[0];
            e.b = e.p_end = seg.p[1];
            e.t_start = e.t_end = d.normalized();
            elems_.push_back(e);
            continue;
        }
        pieces.clear();
        split_cubic(seg.to_cubic(), h_, size_, tol_, pieces);
        for (const CurvePiece& p : pieces) {
            Elem e;
            e.is_line = false;
            e.piece = p;
            e.p_start = p.c.p0;
            e.p_end = p.c.p3;
            e.t_start = p.c.tangent(0.0);
            e.t_end = p.c.tangent(1.0);
            e.cusp_before = p.cusp_before;
            elems_.push_back(e);
        }
    }
}

// The full circle of radius h around p, wound like the strips (two round caps back to back).
void ContourStroker::disc(Path& path, Point p) {
    Vec2 d{1, 0}, n = d.perp();
    path.move_to(p + n * h_);
    arc_to(path, p, n, d, h_, tol_, budget_);
    arc_to(path, p, d, -n, h_, tol_, budget_);
    arc_to(path, p, -n, -d, h_, tol_, budget_);
    arc_to(path, p, -d, n, h_, tol_, budget_);
    path.close();
}

// From p + h·n to p − h·n (n = d.perp()), bulging towards d.
void ContourStroker::cap(Path& path, Point p, Vec2 d) {
    Vec2 n = d.perp();
    switch (style_.cap) {
        case LineCap::Butt: path.line_to(p - n * h_); break;
        case LineCap::Square:
            path.line_to(p + (n + d) * h_);
            path.line_to(p + (d - n) * h_);
            path.line_to(p - n * h_);
            break;
        case LineCap::Round:
            arc_to(path, p, n, d, h_, tol_, budget_);
            arc_to(path, p, d, -n, h_, tol_, budget_);
            break;
    }
    budget_.take(3);
}

void ContourStroker::join(const Elem& a, const Elem& b) {
    Point p = b.p_start;
    Vec2 d1 = a.t_end, d2 = b.t_start;
    Vec2 n1 = d1.perp(), n2 = d2.perp();
    Point left_to = p + n2 * h_, right_to = p - n2 * h_;
    budget_.take(4);
    if (b.cusp_before) {
        left_.line_to(p);
        left_.line_to(left_to);
        right_.line_to(p);
        right_.line_to(right_to);
        disc(extras_, p);
        return;
    }
    double cr = d1.cross(d2), dt = d1.dot(d2);
    if (dt > 0.0 && std::fabs(cr) * h_ <= 1e-3 * tol_) {  // continues straight on
        left_.line_to(left_to);
        right_.line_to(right_to);
        return;
    }
    // Turning towards +perp (cross > 0) puts the left side inside the turn.
    double s = cr > 0.0 ? -1.0 : 1.0;
    Path& outer = s > 0.0 ? left_ : right_;
    Path& inner = s > 0.0 ? right_ : left_;
    inner.line_to(p);
    inner.line_to(s > 0.0 ? right_to : left_to);
    Point outer_to = s > 0.0 ? left_to : right_to;
    Vec2 bis = (d1 - d2).normalized();  // the outer bisector of the corner
    switch (style_.join) {
        case LineJoin::Round:
            arc_to(outer, p, n1 * s, bis, h_, tol_, budget_);
            arc_to(outer, p, bis, n2 * s, h_, tol_, budget_);
            break;
        case LineJoin::Miter: {
            // Turn τ with cos τ = d1·d2: the miter tip sits h / cos(τ/2) out along the bisector,
            // and SVG's ratio (miter length / width) is 1 / cos(τ/2).
            double cos_half = std::sqrt(std::max(0.0, (1.0 + dt) / 2.0));
            if (cos_half * style_.miter_limit >= 1.0) outer.line_to(p + bis * (h_ / cos_half));
            outer.line_to(outer_to);
            break;
        }
        case LineJoin::Bevel: outer.line_to(outer_to); break;
    }
}

// Q of a tight piece (inner offset, then back along the evolute), twice, turned to wind like
// the strips: for sigma = −1 the inner offset is s = −h and this order is already that way.
void ContourStroker::fold_contours(const std::vector<CubicBez>& inner, const CurvePiece& piece) {
    Path q;
    q.move_to(inner.front().p0);
    for (const CubicBez& c : inner) q.cubic_to(c.p1, c.p2, c.p3);
    evolute_back(q, piece.c, tol_, budget_);
    q.close();
    if (piece.sigma > 0) q = q.reversed();
    budget_.take(2 * q.verbs().size());
    append_path(extras_, q);
    append_path(extras_, q);
}

void ContourStroker::add_elem(const Elem& e) {
    if (e.is_line) {
        Vec2 n = e.t_end.perp();
        left_.line_to(e.b + n * h_);
        right_.line_to(e.b - n * h_);
        budget_.take(2);
        return;
    }
    lc_.clear();
    rc_.clear();
    offset_cubic(e.piece.c, h_, tol_, budget_, lc_);
    offset_cubic(e.piece.c, -h_, tol_, budget_, rc_);
    if (budget_.exceeded()) return;
    for (const CubicBez& c : lc_) left_.cubic_to(c.p1, c.p2, c.p3);
    for (const CubicBez& c : rc_) right_.cubic_to(c.p1, c.p2, c.p3);
    if (e.piece.tight) fold_contours(e.piece.sigma > 0 ? lc_ : rc_, e.piece);
}

void ContourStroker::run(const ContourInput& in, Path& out) {
    collect(in);
    if (elems_.empty()) {
        // A zero-length contour: a dot for round and square caps (SVG), axis-aligned.
        if (style_.cap == LineCap::Butt || (in.segs.empty() && !in.closed)) return;
        Vec2 d{1, 0};
        out.move_to(in.start + d.perp() * h_);
        cap(out, in.start, d);
        cap(out, in.start, -d);
        out.close();
        return;
    }
    const Elem& first = elems_.front();
    left_.move_to(first.p_start + first.t_start.perp() * h_);
    right_.move_to(first.p_start - first.t_start.perp() * h_);
    for (std::size_t i = 0; i < elems_.size() && !budget_.exceeded(); ++i) {
        if (i > 0) join(elems_[i - 1], elems_[i]);
        add_elem(elems_[i]);
    }
    if (budget_.exceeded()) return;
    if (in.closed) {
        join(elems_.back(), first);
        left_.close();
        right_ = right_.reversed();
        right_.close();
        append_path(out, left_);
        append_path(out, right_);
    } else {
        const Elem& last = elems_.back();
        Path main = left_;
        cap(main, last.p_end, last.t_end);
        Path back = right_.reversed();
        // `back` starts where the cap ended: continue with its drawing verbs, not its Move.
        const auto& verbs = back.verbs();
        const auto& pts = back.points();
        std::size_t pi = 1;
        for (std::size_t v = 1; v < verbs.size(); ++v) {
            switch (verbs[v]) {
                case Verb::Line: main.line_to(pts[pi++]); break;
                case Verb::Quad: main.quad_to(pts[pi], pts[pi + 1]); pi += 2; break;
                case Verb::Cubic: main.cubic_to(pts[pi], pts[pi + 1], pts[pi + 2]); pi += 3; break;
                default: break;
            }
        }
        cap(main, first.p_start, -first.t_start);
        main.close();
        append_path(out, main);
    }
    append_path(out, extras_);
}

}  // namespace

void stroke_contour(const ContourInput& contour, const StrokeStyle& style, double tol,
                    double size, Budget& budget, Path& out) {
    ContourStroker stroker(style, tol, size, budget);
    stroker.run(contour, out);
}

}  // namespace bezel::stroke_detail
