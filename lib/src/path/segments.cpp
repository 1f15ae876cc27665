// Segment iteration over the verb/point arrays, and the PathSeg accessors.
//
// The iterator carries the current contour's start point and the current point so that each
// segment can be handed out with its start point (which the storage shares with the previous
// verb) and so that a Close can produce the closing line. See path.hpp for the index rule.
#include <cassert>

#include "bezel/path.hpp"

namespace bezel {

Point PathSeg::end() const {
    switch (kind) {
        case SegKind::Line: return p[1];
        case SegKind::Quad: return p[2];
        case SegKind::Cubic: return p[3];
    }
    return p[1];
}

Point PathSeg::eval(double t) const {
    switch (kind) {
        case SegKind::Line: return Line{p[0], p[1]}.eval(t);
        case SegKind::Quad: return QuadBez{p[0], p[1], p[2]}.eval(t);
        case SegKind::Cubic: return CubicBez{p[0], p[1], p[2], p[3]}.eval(t);
    }
    return p[0];
}

CubicBez PathSeg::to_cubic() const {
    switch (kind) {
        case SegKind::Line:
            // A line is the cubic with control points evenly spaced on the chord.
            return {p[0], lerp(p[0], p[1], 1.0 / 3.0), lerp(p[0], p[1], 2.0 / 3.0), p[1]};
        case SegKind::Quad:
            // Degree elevation: C₁ = P₀ + ⅔(P₁ − P₀), C₂ = P₂ + ⅔(P₁ − P₂).
            return {p[0], lerp(p[0], p[1], 2.0 / 3.0), lerp(p[2], p[1], 2.0 / 3.0), p[2]};
        case SegKind::Cubic: return {p[0], p[1], p[2], p[3]};
    }
    return {p[0], p[1], p[2], p[3]};
}

Line PathSeg::as_line() const {
    assert(kind == SegKind::Line);
    return {p[0], p[1]};
}

QuadBez PathSeg::as_quad() const {
    assert(kind == SegKind::Quad);
    return {p[0], p[1], p[2]};
}

CubicBez PathSeg::as_cubic() const {
    assert(kind == SegKind::Cubic);
    return {p[0], p[1], p[2], p[3]};
}

SegmentIterator::SegmentIterator(const Verb* verbs, std::size_t verb_count, const Point* points)
    : verbs_(verbs), points_(points), verb_count_(verb_count), done_(false) {
    advance();
}

void SegmentIterator::advance() {
    while (vi_ < verb_count_) {
        PathSeg s;
        switch (verbs_[vi_++]) {
            case Verb::Move:
                start_ = last_ = points_[pi_++];
                ++moves_seen_;
                continue;
            case Verb::Line:
                s.kind = SegKind::Line;
                s.p[0] = last_;
                s.p[1] = points_[pi_];
                pi_ += 1;
                break;
            case Verb::Quad:
                s.kind = SegKind::Quad;
                s.p[0] = last_;
                s.p[1] = points_[pi_];
                s.p[2] = points_[pi_ + 1];
                pi_ += 2;
                break;
            case Verb::Cubic:
                s.kind = SegKind::Cubic;
                s.p[0] = last_;
                s.p[1] = points_[pi_];
                s.p[2] = points_[pi_ + 1];
                s.p[3] = points_[pi_ + 2];
                pi_ += 3;
                break;
            case Verb::Close:
                // The stable-index rule: a closing line exists exactly when the contour does not
                // already end at its start.
                if (last_ == start_) continue;
                s.kind = SegKind::Line;
                s.p[0] = last_;
                s.p[1] = start_;
                s.closing = true;
                break;
        }
        s.index = next_index_++;
        // The builder puts a Move before every drawing verb, so moves_seen_ ≥ 1 here.
        s.contour = moves_seen_ - 1;
        last_ = s.end();
        seg_ = s;
        return;
    }
    done_ = true;
}

std::size_t Path::segment_count() const {
    std::size_t n = 0;
    for (auto it = segments().begin(); it != SegmentIterator{}; ++it) ++n;
    return n;
}

std::size_t Path::contour_count() const {
    std::size_t n = 0;
    for (Verb v : verbs_) n += v == Verb::Move;
    return n;
}

PathSeg Path::segment(std::size_t i) const {
    for (const PathSeg& s : segments())
        if (s.index == i) return s;
    assert(false && "Path::segment: index out of range");
    return {};
}

}  // namespace bezel
