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

// Appends the projected polyline of the cubic with control points `c`, cut where samples fall
// behind the near plane. Segment count from Wang's formula on the projected control points,
// n = ⌈√(¾·max|Δ²P| / tol)⌉: exact for orthographic views, an estimate under perspective.
void add_iso_curve(const Vec3 (&c)[4], const View& view, double tol_px, Path& path) {
    Vec2 q[4];
    bool all_front = true;
    for (int k = 0; k < 4; ++k) {
        Vec3 s = view.project(c[k]);
        q[k] = {s.x, s.y};
        all_front = all_front && view.in_front(c[k]);
    }
    int n = kMaxIsoSegments;
    if (all_front) {
        double dd = std::max((q[0] - q[1] * 2.0 + q[2]).length(), (q[1] - q[2] * 2.0 + q[3]).length());
        double est = std::ceil(std::sqrt(0.75 * dd / tol_px));
        n = std::isfinite(est) ? std::clamp(static_cast<int>(std::min(est, 1e6)), 1, kMaxIsoSegments)
                               : kMaxIsoSegments;
    }
    bool pen_down = false;
    for (int k = 0; k <= n; ++k) {
        Vec3 w = cubic_point(c, static_cast<double>(k) / n);
        if (!view.in_front(w)) {
            pen_down = false;
            continue;
        }
        Vec3 s = view.project(w);
        if (pen_down) {
            path.line_to({s.x, s.y});
        } else {
            path.move_to({s.x, s.y});
            pen_down = true;
        }
    }
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
            add_iso_curve(along_t, view, style.flatten_tolerance_px, lines);
            add_iso_curve(along_s, view, style.flatten_tolerance_px, lines);
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
