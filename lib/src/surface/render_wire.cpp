// Wireframe pictures: iso-curves of constant s and t, flattened in 3D and projected (a projected
// cubic is not a cubic under perspective, so it is sampled, not mapped), stroked and filled.
#include <algorithm>
#include <cmath>

#include "bezel/raster.hpp"
#include "bezel/stroke.hpp"
#include "bezel/surface.hpp"
#include "surface/framebuffer.hpp"

namespace bezel {
namespace {

// Most segments one iso-curve is cut into.
constexpr int kMaxIsoSegments = 1024;

Vec3 cubic_point(const Vec3 (&p)[4], double t) {
    Vec3 a = p[0] + (p[1] - p[0]) * t, b = p[1] + (p[2] - p[1]) * t, c = p[2] + (p[3] - p[2]) * t;
    Vec3 ab = a + (b - a) * t, bc = b + (c - b) * t;
    return ab + (bc - ab) * t;
}

// Halvings of an iso-curve that crosses the near plane before its pieces are sampled as they are:
// a piece at this depth spans 1/1024 of the curve's parameter.
constexpr int kMaxNearSplitDepth = 10;
// Chords of such a last piece.
constexpr int kStraddlingPieceSegments = 8;

// The polyline being drawn: whether a subpath is open, so that consecutive pieces join.
struct IsoPen {
    bool down = false;
    void to(Vec2 p, Path& path) {
        if (down) {
            path.line_to(p);
        } else {
            path.move_to(p);
            down = true;
        }
    }
};

void add_iso_piece(const Vec3 (&c)[4], const View& view, double tol_px, double margin_px,
                   Path& path, IsoPen& pen, int split_depth);

// The two halves of `c` (de Casteljau at t = ½), each added in turn.
void split_and_add(const Vec3 (&c)[4], const View& view, double tol_px, double margin_px,
                   Path& path, IsoPen& pen, int split_depth) {
    const Vec3 ab = (c[0] + c[1]) * 0.5, bc = (c[1] + c[2]) * 0.5, cd = (c[2] + c[3]) * 0.5;
    const Vec3 abc = (ab + bc) * 0.5, bcd = (bc + cd) * 0.5, mid = (abc + bcd) * 0.5;
    const Vec3 left[4] = {c[0], ab, abc, mid}, right[4] = {mid, bcd, cd, c[3]};
    add_iso_piece(left, view, tol_px, margin_px, path, pen, split_depth + 1);
    add_iso_piece(right, view, tol_px, margin_px, path, pen, split_depth + 1);
}

// Appends the projected polyline of the cubic `c`, clipped at the near plane. A piece whose
// control points are all in front is wholly in front (convex hull) and sampled with the segment
// count of Wang's formula on its projected control points, n = ⌈√(¾·max|Δ²P| / tol)⌉ (exact for
// orthographic views, an estimate under perspective); one whose control points are all behind
// is dropped; one that straddles the plane is halved (de Casteljau) up to kMaxNearSplitDepth,
// then sampled, the chords that cross the plane ending at their point on it (view depth is
// affine in the world position).
void add_iso_piece(const Vec3 (&c)[4], const View& view, double tol_px, double margin_px,
                   Path& path, IsoPen& pen, int split_depth) {
    const double near = view.near_depth();
    int front = 0;
    for (const Vec3& p : c) front += view.depth(p) >= near;
    if (front == 0) {
        pen.down = false;
        return;
    }
    if (front == 4) {
        Vec2 q[4];
        Rect box = Rect::empty();
        for (int k = 0; k < 4; ++k) {
            const Vec3 s = view.project(c[k]);
            q[k] = {s.x, s.y};
            box = box.union_with(q[k]);
        }
        // In front of the eye, projection keeps a piece inside the hull of its projected
        // control points: a hull off the picture (by more than the pen) draws nothing there.
        const double w = view.width(), h = view.height();
        if (box.x1 < -margin_px || box.y1 < -margin_px || box.x0 > w + margin_px ||
            box.y0 > h + margin_px) {
            pen.down = false;
            return;
        }
        // A piece reaching far beyond the picture (near the eye) is halved so that its parts off
        // the picture are dropped, not sampled at the tolerance.
        if (split_depth < kMaxNearSplitDepth &&
            std::max(box.x1 - box.x0, box.y1 - box.y0) > 4.0 * std::max(w, h)) {
            split_and_add(c, view, tol_px, margin_px, path, pen, split_depth);
            return;
        }
        const double dd = std::max((q[0] - q[1] * 2.0 + q[2]).length(),
                                   (q[1] - q[2] * 2.0 + q[3]).length());
        const double est = std::ceil(std::sqrt(0.75 * dd / tol_px));
        const int n = std::isfinite(est)
                          ? std::clamp(static_cast<int>(std::min(est, 1e6)), 1, kMaxIsoSegments)
                          : kMaxIsoSegments;
        for (int k = pen.down ? 1 : 0; k <= n; ++k) {
            const Vec3 s = view.project(cubic_point(c, static_cast<double>(k) / n));
            pen.to({s.x, s.y}, path);
        }
        return;
    }
    if (split_depth < kMaxNearSplitDepth) {
        split_and_add(c, view, tol_px, margin_px, path, pen, split_depth);
        return;
    }
    Vec3 prev;
    double prev_depth = 0;
    for (int k = 0; k <= kStraddlingPieceSegments; ++k) {
        const Vec3 w = cubic_point(c, static_cast<double>(k) / kStraddlingPieceSegments);
        const double depth = view.depth(w);
        const bool in_front = depth >= near;
        if (k > 0 && in_front != (prev_depth >= near)) {
            const Vec3 s =
                view.project(prev + (w - prev) * ((near - prev_depth) / (depth - prev_depth)));
            pen.to({s.x, s.y}, path);
            if (!in_front) pen.down = false;
        }
        if (in_front && (k > 0 || !pen.down)) {
            const Vec3 s = view.project(w);
            pen.to({s.x, s.y}, path);
        }
        prev = w;
        prev_depth = depth;
    }
}

void add_iso_curve(const Vec3 (&c)[4], const View& view, double tol_px, double margin_px,
                   Path& path) {
    IsoPen pen;
    add_iso_piece(c, view, tol_px, margin_px, path, pen, 0);
}

}  // namespace

Expected<Image> render_wireframe(const std::vector<Patch>& patches, const View& view,
                                 const WireStyle& style) {
    if (auto ok = validate_patches(patches, "wireframe"); !ok) return ok.error();
    if (style.iso_lines < 2 || style.iso_lines > 64)
        return Error{"wireframe: iso_lines must be 2 to 64"};
    if (!(style.line_width_px > 0.0 && style.line_width_px <= 64.0))
        return Error{"wireframe: line width must be in (0, 64] px"};
    if (!(style.flatten_tolerance_px > 0.0) || !std::isfinite(style.flatten_tolerance_px))
        return Error{"wireframe: flatten tolerance must be positive"};

    Path lines;
    const double margin_px = style.line_width_px + 1.0;   // the pen reaches this far off a line
    for (const Patch& patch : patches) {
        const Patch b = patch.to_bezier();
        for (int k = 0; k < style.iso_lines; ++k) {
            const double u = static_cast<double>(k) / (style.iso_lines - 1);
            // s = u: the curve in t has control points Σᵢ Bᵢ(u)·b[i][j]; t = u likewise by rows.
            Vec3 along_t[4], along_s[4];
            for (int j = 0; j < 4; ++j) {
                const Vec3 col[4] = {b.g[0][j], b.g[1][j], b.g[2][j], b.g[3][j]};
                along_t[j] = cubic_point(col, u);
                along_s[j] = cubic_point(b.g[j], u);
            }
            add_iso_curve(along_t, view, style.flatten_tolerance_px, margin_px, lines);
            add_iso_curve(along_s, view, style.flatten_tolerance_px, margin_px, lines);
        }
    }
    StrokeStyle pen;
    pen.width = style.line_width_px;
    pen.join = LineJoin::Round;
    pen.cap = LineCap::Round;
    pen.tolerance = 0.02;
    auto outline = stroke(lines, pen);
    if (!outline) return Error{"wireframe: " + outline.error().message};

    const int W = view.width(), H = view.height();
    std::vector<std::uint8_t> cover(static_cast<std::size_t>(W) * static_cast<std::size_t>(H));
    Rasterizer rasterizer;
    if (auto ok =
            rasterizer.fill_path(*outline, Affine::identity(), MaskView{cover.data(), W, H, W});
        !ok)
        return Error{"wireframe: " + ok.error().message};
    surface_detail::Framebuffer fb(W, H);
    const surface_detail::LinearRgb ink = surface_detail::linear(style.color);
    const float alpha = style.color.a / 255.0f;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            std::uint8_t cv = cover[static_cast<std::size_t>(y) * W + x];
            if (cv) fb.add_saturating(x, y, alpha * cv * (1.0f / 255.0f), ink);
        }
    return fb.resolve(style.background);
}

}  // namespace bezel
