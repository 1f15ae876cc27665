// OverlapMode::Accurate: the region's exact area per pixel, by slabs between edge crossings
// (the method and its bound are in overlap.hpp).
#include "raster/overlap.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <type_traits>

#include "raster/accumulate.hpp"
#include "raster/render_flatten.hpp"

namespace bezel {

namespace raster_detail {

namespace {

// The same flattening fill_path uses (path_fill.cpp), so that on outlines without overlaps the
// two modes see the same polygon.
void flatten_like_fill_path(const Path& path, const Affine& m, const FlattenOptions& options,
                            Polylines& out) {
    out.clear();
    const double tol = std::max(options.tolerance_px, kMinFlattenTolerancePx);
    if (options.method == FlattenMethod::WangUniform && options.tolerance_px > 0.0 &&
        std::isfinite(options.tolerance_px) && flatten_balanced(path, m, tol, out))
        return;
    out.clear();
    (void)flatten_checked(path, m, options, out);  // succeeded in fill_path already
}

// The polygon's edges clipped to the target box [0, W] × [0, H] as the plain fill clips them
// (accumulate.hpp: parts above or below dropped, parts left of it vertical at x = 0, parts right
// of it at x = W). Winding numbers inside the box are unchanged, and every coordinate stays in
// the box, so crossings keep pixel-level precision on edges up to kMaxFlattenCoordinatePx long.
void build_edges(const Polylines& lines, int width, int height, std::vector<UnionEdge>& edges) {
    edges.clear();
    const auto add = [&edges](double x0, double y0, double x1, double y1) {
        const bool down = y1 > y0;
        const Point p{x0, y0}, q{x1, y1};
        const Point t = down ? p : q, b = down ? q : p;
        edges.push_back({t.x, t.y, b.x, b.y, (b.x - t.x) / (b.y - t.y), down ? 1 : -1});
    };
    const Point* pts = lines.points.data();
    std::size_t start = 0;
    for (std::size_t end : lines.contour_ends) {
        if (end - start >= 2) {
            Point p = pts[end - 1];  // the closing edge first
            for (std::size_t k = start; k < end; ++k) {
                const Point q = pts[k];
                // A horizontal edge changes no winding number; clip_line drops it.
                clip_line(width, height, p.x, p.y, q.x, q.y, add);
                p = q;
            }
        }
        start = end;
    }
    std::sort(edges.begin(), edges.end(),
              [](const UnionEdge& a, const UnionEdge& b) { return a.y_top < b.y_top; });
}

// Adds a straight piece from x = xa to xb spanning `dy` of the row (signed: +1 per unit for an
// edge entering the region) to the row's cell deltas, as in accumulate.hpp: a piece inside
// column i with mean offset m gives cell i dy·(1 − m) and cell i+1 dy·m. Clipped to [0, W]: dy is
// linear in x along the piece, so the part left of 0 is a vertical piece at x = 0 (its cover
// reaches every pixel) and the part right of W reaches none.
void add_piece(double* cells, int width, double xa, double xb, double dy) {
    if (xa > xb) std::swap(xa, xb);
    const double W = width, len = xb - xa;
    if (xb <= 0.0) {
        cells[0] += dy;
        return;
    }
    if (xa >= W) return;
    if (xa < 0.0 || xb > W) {
        const double left = std::max(0.0, -xa), right = std::max(0.0, xb - W);
        cells[0] += dy * (left / len);
        dy *= (len - left - right) / len;
        xa = std::max(xa, 0.0);
        xb = std::min(xb, W);
    }
    const int i0 = static_cast<int>(xa), i1 = static_cast<int>(xb);
    if (i0 == i1 || xb <= i0 + 1.0) {
        const double m = 0.5 * (xa + xb) - i0;
        cells[i0] += dy * (1.0 - m);
        cells[i0 + 1] += dy * m;
        return;
    }
    const double s = dy / (xb - xa);
    for (int i = i0; i <= i1; ++i) {
        const double lo = std::max(xa, static_cast<double>(i));
        const double hi = std::min(xb, static_cast<double>(i) + 1.0);
        if (!(hi > lo)) continue;
        const double d = s * (hi - lo), m = 0.5 * (lo + hi) - i;
        cells[i] += d * (1.0 - m);
        cells[i + 1] += d * m;
    }
}

bool inside(FillRule rule, int w) { return rule == FillRule::NonZero ? w != 0 : (w & 1) != 0; }

// Slab boundaries of row [r, r + 1]: the row's ends, edge ends inside it, and crossings of two
// edges inside it. Returns the work done (pairs tested).
std::size_t row_events(const OverlapScratch& s, double r, std::vector<double>& events) {
    events.clear();
    events.push_back(r);
    events.push_back(r + 1.0);
    const std::size_t k = s.active.size();
    for (std::uint32_t a : s.active) {
        const UnionEdge& e = s.edges[a];
        if (e.y_top > r && e.y_top < r + 1.0) events.push_back(e.y_top);
        if (e.y_bot > r && e.y_bot < r + 1.0) events.push_back(e.y_bot);
    }
    for (std::size_t i = 0; i < k; ++i) {
        const UnionEdge& a = s.edges[s.active[i]];
        for (std::size_t j = i + 1; j < k; ++j) {
            const UnionEdge& b = s.edges[s.active[j]];
            const double lo = std::max({r, a.y_top, b.y_top});
            const double hi = std::min({r + 1.0, a.y_bot, b.y_bot});
            if (!(hi > lo)) continue;
            const double d0 = a.x_at(lo) - b.x_at(lo), d1 = a.x_at(hi) - b.x_at(hi);
            if ((d0 < 0.0 && d1 > 0.0) || (d0 > 0.0 && d1 < 0.0)) {
                const double y = lo + (hi - lo) * (d0 / (d0 - d1));
                if (y > lo && y < hi) events.push_back(y);
            }
        }
    }
    std::sort(events.begin(), events.end());
    return k * k / 2 + 1;
}

template <typename Pixel>
void write_row(const double* cells, int width, Pixel* out) {
    double acc = 0.0;
    for (int x = 0; x < width; ++x) {
        acc += cells[x];
        const double c = std::clamp(acc, 0.0, 1.0);
        if constexpr (std::is_same_v<Pixel, float>) {
            out[x] = static_cast<float>(c);
        } else {
            out[x] = static_cast<std::uint8_t>(c * 255.0 + 0.5);
        }
    }
}

}  // namespace

template <typename View>
void fill_region_exact(const Path& path, const Affine& transform, FillRule rule,
                       const FlattenOptions& options, const View& target, OverlapScratch& s) {
    const int W = target.width, H = target.height;
    if (W <= 0 || H <= 0) return;
    flatten_like_fill_path(path, transform, options, s.lines);
    build_edges(s.lines, W, H, s.edges);
    if (s.edges.empty()) return;  // fill_path has already written zeros
    s.cells.assign(static_cast<std::size_t>(W) + 2, 0.0);
    s.active.clear();

    double first = std::floor(s.edges.front().y_top);
    const int r0 = static_cast<int>(std::clamp(first, 0.0, static_cast<double>(H)));
    std::size_t next = 0, work = 0;
    for (int r = r0; r < H; ++r) {
        const double top = r, bottom = r + 1.0;
        // Active edges: those that overlap (top, bottom) in y.
        s.active.erase(std::remove_if(s.active.begin(), s.active.end(),
                                      [&](std::uint32_t a) { return s.edges[a].y_bot <= top; }),
                       s.active.end());
        for (; next < s.edges.size() && s.edges[next].y_top < bottom; ++next)
            if (s.edges[next].y_bot > top) s.active.push_back(static_cast<std::uint32_t>(next));
        if (s.active.empty()) {  // fill_path has written this row's zeros
            if (next == s.edges.size()) break;
            continue;
        }
        const std::size_t k = s.active.size();
        if (work + k * k / 2 > kMaxOverlapWork) return;  // the rest keeps the plain coverage
        if (k * k / 2 > kMaxOverlapRowWork) continue;    // so does this row
        std::size_t row_work = row_events(s, top, s.events);
        bool exact = true;
        for (std::size_t i = 0; i + 1 < s.events.size(); ++i) {
            const double y0 = s.events[i], y1 = s.events[i + 1];
            if (!(y1 > y0)) continue;
            const double ym = 0.5 * (y0 + y1);
            row_work += k;
            if (row_work > kMaxOverlapRowWork) {
                exact = false;
                break;
            }
            s.slab.clear();
            for (std::uint32_t a : s.active) {
                const UnionEdge& e = s.edges[a];
                if (e.y_top < ym && e.y_bot > ym) s.slab.push_back({e.x_at(ym), a});
            }
            std::sort(s.slab.begin(), s.slab.end(),
                      [](const SlabEdge& a, const SlabEdge& b) { return a.x_mid < b.x_mid; });
            int w = 0;
            for (const SlabEdge& se : s.slab) {
                const UnionEdge& e = s.edges[se.edge];
                const bool was_in = inside(rule, w);
                w += e.winding;
                if (inside(rule, w) == was_in) continue;  // inside the region on both sides
                const double dy = was_in ? -(y1 - y0) : (y1 - y0);
                add_piece(s.cells.data(), W, e.x_at(y0), e.x_at(y1), dy);
            }
        }
        work += row_work;
        if (exact) write_row(s.cells.data(), W, target.row(r));
        std::fill(s.cells.begin(), s.cells.end(), 0.0);
    }
}

template void fill_region_exact<MaskView>(const Path&, const Affine&, FillRule,
                                          const FlattenOptions&, const MaskView&, OverlapScratch&);
template void fill_region_exact<FloatMaskView>(const Path&, const Affine&, FillRule,
                                               const FlattenOptions&, const FloatMaskView&,
                                               OverlapScratch&);

}  // namespace raster_detail

}  // namespace bezel
