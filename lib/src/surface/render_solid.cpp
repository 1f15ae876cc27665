// Shaded pictures of triangle meshes: exact-area coverage from the Rasterizer, Lambert shading,
// depth sort front to back with saturating coverage (the reasons are in surface.hpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include "bezel/raster.hpp"
#include "bezel/surface.hpp"
#include "surface/framebuffer.hpp"

namespace bezel {
namespace {

using surface_detail::Framebuffer;
using surface_detail::LinearRgb;

// A triangle corner: where it is in the world, its normal and its projection.
struct Corner {
    Vec3 world, normal, screen;
};
using Triangle = std::array<Corner, 3>;

// The mesh's triangles as the camera sees them: those wholly in front of the near plane as they
// are, those crossing it cut along it (Sutherland–Hodgman against one plane: the part in front
// is a triangle or a quadrilateral, split in two), those wholly behind dropped. View depth is
// an affine function of the world position, so the cut points, and their normals, are linear
// interpolations along the crossing edges.
std::vector<Triangle> clip_to_near_plane(const TriangleMesh& mesh, const View& view) {
    std::vector<Triangle> out;
    out.reserve(mesh.triangles.size());
    const double near = view.near_depth();
    auto corner = [&](Vec3 world, Vec3 normal) { return Corner{world, normal, view.project(world)}; };
    for (const auto& t : mesh.triangles) {
        Vec3 p[3], n[3];
        double d[3];
        int front = 0;
        for (int k = 0; k < 3; ++k) {
            p[k] = mesh.positions[t[k]];
            n[k] = mesh.normals[t[k]];
            d[k] = view.depth(p[k]);
            front += d[k] >= near;
        }
        if (front == 3) {
            out.push_back({corner(p[0], n[0]), corner(p[1], n[1]), corner(p[2], n[2])});
            continue;
        }
        if (front == 0) continue;
        Corner poly[4];
        int count = 0;
        for (int k = 0; k < 3; ++k) {
            const int j = (k + 1) % 3;
            if (d[k] >= near) poly[count++] = corner(p[k], n[k]);
            if ((d[k] >= near) != (d[j] >= near)) {
                const double s = (near - d[k]) / (d[j] - d[k]);
                poly[count++] = corner(p[k] + (p[j] - p[k]) * s, n[k] + (n[j] - n[k]) * s);
            }
        }
        out.push_back({poly[0], poly[1], poly[2]});
        if (count == 4) out.push_back({poly[0], poly[2], poly[3]});
    }
    return out;
}

double lambert(const SolidStyle& style, Vec3 n, Vec3 light) {
    return style.ambient + (1.0 - style.ambient) * std::max(0.0, n.dot(light));
}

LinearRgb shade(LinearRgb base, double k) {
    float f = static_cast<float>(k);
    return {base.r * f, base.g * f, base.b * f};
}

}  // namespace

Expected<Image> render_solid(const TriangleMesh& mesh, const View& view, const SolidStyle& style) {
    if (mesh.triangles.size() > kMaxMeshTriangles)
        return Error{"render: " + std::to_string(mesh.triangles.size()) + " triangles, more than " +
                     std::to_string(kMaxMeshTriangles)};
    if (mesh.normals.size() != mesh.positions.size())
        return Error{"render: mesh has " + std::to_string(mesh.normals.size()) + " normals for " +
                     std::to_string(mesh.positions.size()) + " vertices"};
    for (const auto& t : mesh.triangles)
        for (std::uint32_t v : t)
            if (v >= mesh.positions.size()) return Error{"render: triangle index out of range"};
    if (!(style.ambient >= 0.0 && style.ambient <= 1.0))
        return Error{"render: ambient must be in [0, 1]"};
    Vec3 light = (view.right() * style.light.x + view.up() * style.light.y -
                  view.forward() * style.light.z).normalized();
    if (light == Vec3{}) return Error{"render: light direction is zero or not finite"};

    // Triangles cut at the near plane, their corners projected; ordered nearest first by
    // centroid depth.
    const std::vector<Triangle> tris = clip_to_near_plane(mesh, view);
    std::vector<std::uint32_t> order;
    order.reserve(tris.size());
    std::vector<double> key(tris.size());
    for (std::size_t m = 0; m < tris.size(); ++m) {
        const Triangle& t = tris[m];
        bool finite = true;
        for (const Corner& c : t) finite = finite && c.screen.is_finite();
        if (!finite) continue;
        key[m] = t[0].screen.z + t[1].screen.z + t[2].screen.z;
        order.push_back(static_cast<std::uint32_t>(m));
    }
    std::stable_sort(order.begin(), order.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });

    double zmin = HUGE_VAL, zmax = -HUGE_VAL;
    for (std::uint32_t m : order)
        for (const Corner& c : tris[m])
            zmin = std::min(zmin, c.screen.z), zmax = std::max(zmax, c.screen.z);
    const double depth_range = zmax > zmin ? zmax - zmin : 0.0;
    const int W = view.width(), H = view.height();
    Framebuffer fb(W, H);
    const LinearRgb base = surface_detail::linear(style.color);
    const float alpha = style.color.a / 255.0f;
    Rasterizer rasterizer;
    Polylines tri;
    std::vector<std::uint8_t> cover;
    for (std::uint32_t m : order) {
        const Triangle& t = tris[m];
        const Vec3 a = t[0].screen, b = t[1].screen, c = t[2].screen;
        const Vec2 pa{a.x, a.y}, pb{b.x, b.y}, pc{c.x, c.y};
        const double area2 = (pb - pa).cross(pc - pa);
        if (!(std::fabs(area2) > 1e-12)) continue;
        const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.x, b.x, c.x}))));
        const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a.y, b.y, c.y}))));
        const int x1 = std::min(W, static_cast<int>(std::ceil(std::max({a.x, b.x, c.x}))));
        const int y1 = std::min(H, static_cast<int>(std::ceil(std::max({a.y, b.y, c.y}))));
        if (x0 >= x1 || y0 >= y1) continue;
        const int bw = x1 - x0, bh = y1 - y0;
        cover.resize(static_cast<std::size_t>(bw) * static_cast<std::size_t>(bh));
        tri.clear();
        tri.points = {pa, pb, pc};
        tri.contour_ends = {3};
        MaskView target{cover.data(), bw, bh, bw};
        FillOptions fill;  // NonZero
        fill.origin = Vec2{-double(x0), -double(y0)};
        if (auto ok = rasterizer.fill(tri, target, fill); !ok) return ok.error();

        // Two-sided lighting: the facet and its vertex normals turned towards the viewer.
        const Vec3 wa = t[0].world, wb = t[1].world, wc = t[2].world;
        const Vec3 facet = (wb - wa).cross(wc - wa).normalized();
        const double side = facet.dot(view.to_viewer((wa + wb + wc) / 3.0)) < 0.0 ? -1.0 : 1.0;
        const LinearRgb flat = shade(base, lambert(style, facet * side, light));
        const Vec3 n[3] = {t[0].normal * side, t[1].normal * side, t[2].normal * side};
        const bool perspective = view.projection() == Projection::Perspective;
        // Depth-test margin: how much depth can change across a pixel on this triangle (its
        // screen-space depth gradient; the clamped barycentrics of an edge pixel move the sample
        // up to ~0.7 px), with room for the neighbour's gradient, plus a sliver of the scene.
        const double gx = ((b.z - a.z) * (pc.y - pa.y) - (c.z - a.z) * (pb.y - pa.y)) / area2;
        const double gy = ((c.z - a.z) * (pb.x - pa.x) - (b.z - a.z) * (pc.x - pa.x)) / area2;
        const float margin =
            static_cast<float>(1.5 * (std::fabs(gx) + std::fabs(gy)) + 1e-4 * depth_range);
        for (int y = y0; y < y1; ++y) {
            const std::uint8_t* row = cover.data() + static_cast<std::size_t>(y - y0) * bw;
            for (int x = x0; x < x1; ++x) {
                const std::uint8_t cv = row[x - x0];
                if (cv == 0) continue;
                // Screen-space barycentrics of the pixel centre, clamped into the triangle (edge
                // pixels have centres outside it). Under perspective 1/z is linear on screen, so
                // λᵢ/zᵢ are the perspective-correct weights and 1/Σ(λᵢ/zᵢ) the depth.
                const Vec2 p{x + 0.5, y + 0.5};
                double l[3] = {(pb - p).cross(pc - p) / area2, (pc - p).cross(pa - p) / area2, 0};
                l[2] = 1.0 - l[0] - l[1];
                for (double& w : l) w = std::max(0.0, w);
                const double lsum = l[0] + l[1] + l[2];
                const double z[3] = {a.z, b.z, c.z};
                double sum = 0.0, depth = 0.0;
                for (int k = 0; k < 3; ++k) {
                    l[k] /= lsum;
                    if (perspective) l[k] /= z[k];
                    sum += l[k];
                    depth += l[k] * z[k];
                }
                depth = perspective ? 1.0 / sum : depth;
                LinearRgb colour = flat;
                if (style.shading == Shading::Smooth) {
                    Vec3 ni = ((n[0] * l[0] + n[1] * l[1] + n[2] * l[2]) / sum).normalized();
                    if (ni == Vec3{}) ni = facet * side;
                    colour = shade(base, lambert(style, ni, light));
                }
                fb.add_with_depth(x, y, alpha * static_cast<float>(cv) * (1.0f / 255.0f), colour,
                                  static_cast<float>(depth), margin);
            }
        }
    }
    return fb.resolve(style.background);
}

}  // namespace bezel
