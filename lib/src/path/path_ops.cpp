// Whole-path operations that keep the verb/point layout: transform, reverse, boxes, finiteness.
#include <algorithm>
#include <iterator>

#include "bezel/path.hpp"

namespace bezel {

void Path::transform(const Affine& m) {
    for (Point& p : points_) p = m * p;
}

Path Path::transformed(const Affine& m) const {
    Path out = *this;
    out.transform(m);
    return out;
}

bool Path::is_finite() const {
    return std::all_of(points_.begin(), points_.end(), [](Point p) { return p.is_finite(); });
}

// Reversing a contour is reversing two slices. Its points, Move point first, read
//   P₀ | a₁… | a₂… | … | aₖ…   (each verb's points end with its end point)
// and read backwards they are exactly the points of the reversed verbs in reversed order: each
// verb's control points come out reversed and its end point becomes the previous verb's start.
// So the reversed contour is Move(last point), the drawing verbs in reverse order, the point
// slice reversed, and the Close (if any) kept at the end.
Path Path::reversed() const {
    Path out;
    out.verbs_.reserve(verbs_.size());
    out.points_.reserve(points_.size());
    std::size_t vi = 0, pi = 0;
    while (vi < verbs_.size()) {
        // verbs_[vi] is a Move (builder invariant); find the end of its contour.
        std::size_t v_end = vi + 1, p_end = pi + 1;
        bool closed = false;
        while (v_end < verbs_.size() && verbs_[v_end] != Verb::Move) {
            switch (verbs_[v_end]) {
                case Verb::Line: p_end += 1; break;
                case Verb::Quad: p_end += 2; break;
                case Verb::Cubic: p_end += 3; break;
                case Verb::Close: closed = true; break;
                case Verb::Move: break;
            }
            ++v_end;
        }
        std::size_t draw_end = closed ? v_end - 1 : v_end;  // the Close is last when present
        auto at = [](auto& v, std::size_t i) { return v.begin() + static_cast<std::ptrdiff_t>(i); };
        out.verbs_.push_back(Verb::Move);
        std::reverse_copy(at(verbs_, vi + 1), at(verbs_, draw_end), std::back_inserter(out.verbs_));
        if (closed) out.verbs_.push_back(Verb::Close);
        std::reverse_copy(at(points_, pi), at(points_, p_end), std::back_inserter(out.points_));
        vi = v_end;
        pi = p_end;
    }
    return out;
}

Rect Path::control_box() const {
    Rect box = Rect::empty();
    for (const PathSeg& s : segments()) {
        switch (s.kind) {
            case SegKind::Line: box = box.union_with(s.as_line().control_box()); break;
            case SegKind::Quad: box = box.union_with(s.as_quad().control_box()); break;
            case SegKind::Cubic: box = box.union_with(s.as_cubic().control_box()); break;
        }
    }
    return box;
}

// Each curve's own tight box (end points plus the parameters where a derivative component
// vanishes, from bezier.hpp); the union of tight boxes is the tight box of the union. Most curves
// of an outline never reach past the box of all the end points (a Bézier lies in the convex hull
// of its control points, so one whose control points are inside that box stays inside), so the
// end points go first and only a curve with a control point outside the box so far has its
// derivative roots solved: on a line of text about one curve in ten.
//
// Both passes walk the verbs and points directly (segments() builds a PathSeg per step, which
// cost as much as the whole test). A segment is a drawing verb from the current point (the
// Move's, then the last end point); a Close adds only a line back to the contour's first
// point, which the first segment already holds, and a Move that starts nothing adds nothing:
// as segments() counts them.
Rect Path::bounds() const {
    Rect box = Rect::empty();
    Point current{};
    std::size_t pi = 0;
    for (Verb v : verbs_) {
        std::size_t n = 0;  // the verb's points; its last is its end point
        switch (v) {
            case Verb::Move: current = points_[pi]; pi += 1; continue;
            case Verb::Line: n = 1; break;
            case Verb::Quad: n = 2; break;
            case Verb::Cubic: n = 3; break;
            case Verb::Close: continue;
        }
        box = box.union_with(current).union_with(points_[pi + n - 1]);
        current = points_[pi + n - 1];
        pi += n;
    }
    pi = 0;
    for (Verb v : verbs_) {
        switch (v) {
            case Verb::Move:
            case Verb::Line: current = points_[pi]; pi += 1; break;
            case Verb::Quad:
                if (!box.contains(points_[pi]))
                    box = box.union_with(
                        QuadBez{current, points_[pi], points_[pi + 1]}.bounding_box());
                current = points_[pi + 1];
                pi += 2;
                break;
            case Verb::Cubic:
                if (!box.contains(points_[pi]) || !box.contains(points_[pi + 1]))
                    box = box.union_with(
                        CubicBez{current, points_[pi], points_[pi + 1], points_[pi + 2]}
                            .bounding_box());
                current = points_[pi + 2];
                pi += 3;
                break;
            case Verb::Close: break;
        }
    }
    return box;
}

}  // namespace bezel
