// The paint graph's invariants (validate) and the box it can ink (paint_bounds).
//
// Both walk the graph from the root depth first, as the painter does. The walk is bounded before
// it starts trusting the graph: recursion stops at kMaxPaintDepth levels (so a graph that loops
// or nests 10,000 deep costs 64 frames), and every node reached counts, a shared node at each
// visit, so a DAG of exponentially many paths is refused after kMaxPaintNodes steps rather than
// walked for 2^64.
#include <cmath>
#include <string>

#include "bezel/limits.hpp"
#include "paint/graph.hpp"

namespace bezel {
namespace paint_detail {
namespace {

bool finite(double v) { return std::isfinite(v); }
bool finite(Point p) { return p.is_finite(); }

bool color_ok(const PaintColor& c) {
    return finite(c.color.r) && finite(c.color.g) && finite(c.color.b) && finite(c.color.a) &&
           finite(c.alpha);
}

const char* line_problem(const ColorLine& line) {
    if (line.stops.empty()) return "has a colour line without stops";
    for (std::size_t i = 0; i < line.stops.size(); ++i) {
        const ColorStop& s = line.stops[i];
        if (!finite(s.offset) || !color_ok(s.color)) return "has a colour stop that is not finite";
        if (i > 0 && s.offset < line.stops[i - 1].offset)
            return "has colour stops out of offset order";
    }
    return nullptr;
}

// What is wrong with one node on its own (its numbers; its indices are checked by the walk).
const char* node_problem(const ColorGlyph& g, const PaintNode& node) {
    struct Visitor {
        const ColorGlyph& g;
        const char* operator()(const PaintLayers&) const { return nullptr; }
        const char* operator()(const PaintSolid& n) const {
            return color_ok(n.color) ? nullptr : "has a colour that is not finite";
        }
        const char* operator()(const PaintLinearGradient& n) const {
            if (!finite(n.p0) || !finite(n.p1) || !finite(n.p2)) return "has a point that is not finite";
            return line_problem(n.line);
        }
        const char* operator()(const PaintRadialGradient& n) const {
            if (!finite(n.c0) || !finite(n.c1) || !finite(n.r0) || !finite(n.r1))
                return "has a circle that is not finite";
            if (n.r0 < 0 || n.r1 < 0) return "has a negative radius";
            return line_problem(n.line);
        }
        const char* operator()(const PaintSweepGradient& n) const {
            if (!finite(n.center) || !finite(n.start_deg) || !finite(n.end_deg))
                return "has an angle or centre that is not finite";
            return line_problem(n.line);
        }
        const char* operator()(const PaintGlyph& n) const {
            return n.outline < g.outlines.size() ? nullptr : "names an outline out of range";
        }
        const char* operator()(const PaintTransform& n) const {
            return n.transform.is_finite() ? nullptr : "has a transform that is not finite";
        }
        const char* operator()(const PaintColrGlyph& n) const {
            if (n.clip && !(finite(n.clip->x0) && finite(n.clip->y0) && finite(n.clip->x1) &&
                            finite(n.clip->y1)))
                return "has a clip box that is not finite";
            return nullptr;
        }
        const char* operator()(const PaintComposite& n) const {
            return static_cast<int>(n.mode) < kCompositeModeCount ? nullptr
                                                                  : "has an unknown composite mode";
        }
    };
    return std::visit(Visitor{g}, node);
}

struct Walk {
    const ColorGlyph& g;
    std::vector<std::uint8_t>& on_path;
    std::size_t visits = 0;
    std::string error;

    bool fail(std::string message) {
        error = std::move(message);
        return false;
    }

    bool visit(PaintIndex i, int depth) {
        if (i >= g.nodes.size())
            return fail("paint graph refers to node " + std::to_string(i) + " of " +
                        std::to_string(g.nodes.size()));
        if (on_path[i]) return fail("paint graph loops at node " + std::to_string(i));
        if (depth > kMaxPaintDepth)
            return fail("paint graph nests deeper than " + std::to_string(kMaxPaintDepth) +
                        " levels (at node " + std::to_string(i) + ")");
        if (++visits > kMaxPaintNodes)
            return fail("paint graph visits more than " + std::to_string(kMaxPaintNodes) +
                        " nodes");
        const PaintNode& node = g.nodes[i];
        if (const char* problem = node_problem(g, node))
            return fail("paint node " + std::to_string(i) + " " + problem);
        on_path[i] = 1;
        bool ok = true;
        if (const auto* n = std::get_if<PaintLayers>(&node)) {
            for (PaintIndex c : n->layers)
                if (!(ok = visit(c, depth + 1))) break;
        } else if (const auto* n = std::get_if<PaintGlyph>(&node)) {
            ok = visit(n->paint, depth + 1);
        } else if (const auto* n = std::get_if<PaintTransform>(&node)) {
            ok = visit(n->paint, depth + 1);
        } else if (const auto* n = std::get_if<PaintColrGlyph>(&node)) {
            ok = visit(n->paint, depth + 1);
        } else if (const auto* n = std::get_if<PaintComposite>(&node)) {
            ok = visit(n->backdrop, depth + 1) && visit(n->source, depth + 1);
        }
        on_path[i] = 0;
        return ok;
    }
};

// Box of the corners of `r` mapped by `m` (an affine map of a box's corners bounds its image).
Rect map_box(const Rect& r, const Affine& m) {
    if (r.is_empty()) return Rect::empty();
    Rect out = Rect::empty();
    for (Point p : {Point{r.x0, r.y0}, Point{r.x1, r.y0}, Point{r.x0, r.y1}, Point{r.x1, r.y1}})
        out = out.union_with(m * p);
    return out;
}

Rect intersect(const Rect& a, const Rect& b) {
    Rect r{std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
    return r.is_empty() ? Rect::empty() : r;
}

// The glyph-space box node i can ink, with `m` mapping its space to the glyph's. Called only on
// a validated graph, so its recursion and total work have the walk's bounds.
Rect bounds_of(const ColorGlyph& g, PaintIndex i, const Affine& m) {
    const PaintNode& node = g.nodes[i];
    if (const auto* n = std::get_if<PaintLayers>(&node)) {
        Rect r = Rect::empty();
        for (PaintIndex c : n->layers) r = r.union_with(bounds_of(g, c, m));
        return r;
    }
    if (const auto* n = std::get_if<PaintGlyph>(&node))
        return map_box(g.outlines[n->outline].control_box(), m);
    if (const auto* n = std::get_if<PaintTransform>(&node))
        return bounds_of(g, n->paint, m * n->transform);
    if (const auto* n = std::get_if<PaintColrGlyph>(&node)) {
        Rect r = bounds_of(g, n->paint, m);
        return n->clip ? intersect(r, map_box(*n->clip, m)) : r;
    }
    if (const auto* n = std::get_if<PaintComposite>(&node))
        return bounds_of(g, n->backdrop, m).union_with(bounds_of(g, n->source, m));
    // A fill outside every PaintGlyph is unbounded, which the specification forbids ("bounded
    // layers only"); it adds nothing to the box.
    return Rect::empty();
}

}  // namespace

Status validate(const ColorGlyph& glyph, std::vector<std::uint8_t>& on_path) {
    on_path.assign(glyph.nodes.size(), 0);
    if (glyph.clip && !(std::isfinite(glyph.clip->x0) && std::isfinite(glyph.clip->y0) &&
                        std::isfinite(glyph.clip->x1) && std::isfinite(glyph.clip->y1)))
        return Error{"colour glyph clip box is not finite"};
    Walk walk{glyph, on_path, 0, {}};
    if (!walk.visit(glyph.root, 1)) {
        on_path.assign(on_path.size(), 0);
        return Error{walk.error};
    }
    return ok_status();
}

}  // namespace paint_detail

Status validate(const ColorGlyph& glyph) {
    std::vector<std::uint8_t> on_path;
    return paint_detail::validate(glyph, on_path);
}

Rect paint_bounds(const ColorGlyph& glyph) {
    if (!validate(glyph).ok()) return Rect::empty();
    if (glyph.clip) return glyph.clip->is_empty() ? Rect::empty() : *glyph.clip;
    return paint_detail::bounds_of(glyph, glyph.root, Affine::identity());
}

}  // namespace bezel
