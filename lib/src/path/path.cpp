// Path builder: keeps the verb/point invariant (Move: 1 point, Line: 1, Quad: 2, Cubic: 3,
// Close: 0) and SVG's rule that drawing after close() or with no contour starts a new contour.
#include "bezel/path.hpp"

namespace bezel {

namespace {
// The point a new implicit contour starts at: the start of the last contour after a close, the
// last point otherwise, the origin for an empty path.
Point implicit_start(const std::vector<Verb>& verbs, const std::vector<Point>& points) {
    if (points.empty()) return Point{};
    if (!verbs.empty() && verbs.back() == Verb::Close) {
        // Walk back to the Move that started the closed contour.
        std::size_t pi = points.size();
        for (std::size_t vi = verbs.size(); vi-- > 0;) {
            switch (verbs[vi]) {
                case Verb::Move: return points[pi - 1];
                case Verb::Line: pi -= 1; break;
                case Verb::Quad: pi -= 2; break;
                case Verb::Cubic: pi -= 3; break;
                case Verb::Close: break;
            }
        }
    }
    return points.back();
}
}  // namespace

void Path::move_to(Point p) {
    if (!verbs_.empty() && verbs_.back() == Verb::Move) {
        points_.back() = p;  // consecutive moves: only the last one matters
        return;
    }
    verbs_.push_back(Verb::Move);
    points_.push_back(p);
}

// Starts a contour when there is none open, so every drawing verb follows a Move.
static void ensure_open(std::vector<Verb>& verbs, std::vector<Point>& points) {
    if (verbs.empty() || verbs.back() == Verb::Close) {
        Point s = implicit_start(verbs, points);
        verbs.push_back(Verb::Move);
        points.push_back(s);
    }
}

void Path::line_to(Point p) {
    ensure_open(verbs_, points_);
    verbs_.push_back(Verb::Line);
    points_.push_back(p);
}

void Path::quad_to(Point c, Point p) {
    ensure_open(verbs_, points_);
    verbs_.push_back(Verb::Quad);
    points_.push_back(c);
    points_.push_back(p);
}

void Path::cubic_to(Point c1, Point c2, Point p) {
    ensure_open(verbs_, points_);
    verbs_.push_back(Verb::Cubic);
    points_.push_back(c1);
    points_.push_back(c2);
    points_.push_back(p);
}

void Path::close() {
    if (verbs_.empty() || verbs_.back() == Verb::Close) return;
    verbs_.push_back(Verb::Close);
}

}  // namespace bezel
