// Contours that may meet: the test that sends an outline to the accurate-overlap fill.
#include "paint/contours.hpp"

namespace bezel::paint_detail {

namespace {

// Each verb's share of Path::points(): a move and a line one point, a quadratic two, a cubic
// three, a close none.
std::size_t points_of(Verb v) {
    switch (v) {
        case Verb::Move: case Verb::Line: return 1;
        case Verb::Quad: return 2;
        case Verb::Cubic: return 3;
        case Verb::Close: return 0;
    }
    return 0;
}

bool contains(const Rect& a, const Rect& b) {
    return a.x0 <= b.x0 && a.y0 <= b.y0 && b.x1 <= a.x1 && b.y1 <= a.y1;
}
bool intersects(const Rect& a, const Rect& b) {
    return a.x0 <= b.x1 && b.x0 <= a.x1 && a.y0 <= b.y1 && b.y0 <= a.y1;
}

}  // namespace

bool contours_may_meet(const Path& outline, std::vector<Rect>& boxes) {
    boxes.clear();
    const auto& verbs = outline.verbs();
    const auto& points = outline.points();
    std::size_t p = 0;
    for (Verb v : verbs) {
        if (v == Verb::Move) {
            if (boxes.size() == kMaxContoursCompared) return true;
            boxes.push_back(Rect::empty());
        }
        for (std::size_t k = points_of(v); k > 0 && p < points.size(); --k, ++p)
            if (!boxes.empty()) boxes.back() = boxes.back().union_with(points[p]);
    }
    for (std::size_t i = 0; i < boxes.size(); ++i)
        for (std::size_t j = i + 1; j < boxes.size(); ++j)
            if (intersects(boxes[i], boxes[j]) && !contains(boxes[i], boxes[j]) &&
                !contains(boxes[j], boxes[i]))
                return true;
    return false;
}

}  // namespace bezel::paint_detail
