// Patches to triangle meshes on a uniform parameter grid whose step comes from a bound on the
// second derivatives (see steps_for_tolerance in surface.hpp).
#include <algorithm>
#include <cmath>

#include "bezel/surface.hpp"

namespace bezel {

int steps_for_tolerance(const Patch& patch, double tolerance) {
    const Patch b = patch.to_bezier();
    double dss = 0.0, dtt = 0.0, dst = 0.0;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            if (i + 2 < 4) dss = std::max(dss, (b.g[i + 2][j] - b.g[i + 1][j] * 2.0 + b.g[i][j]).length());
            if (j + 2 < 4) dtt = std::max(dtt, (b.g[i][j + 2] - b.g[i][j + 1] * 2.0 + b.g[i][j]).length());
            if (i + 1 < 4 && j + 1 < 4)
                dst = std::max(dst, (b.g[i + 1][j + 1] - b.g[i + 1][j] - b.g[i][j + 1] + b.g[i][j]).length());
        }
    // M_ss + 2·M_st + M_tt with the Bézier bounds 6·Δ², 9·ΔΔ, 6·Δ².
    const double m = 6.0 * dss + 18.0 * dst + 6.0 * dtt;
    const double n = std::ceil(std::sqrt(m / (8.0 * tolerance)));
    if (!(n <= 1e9)) return 1 << 30;  // also NaN: reported as "too many" by the caller
    return std::max(1, static_cast<int>(n));
}

Expected<TriangleMesh> tessellate(const std::vector<Patch>& patches,
                                  const TessellateOptions& options) {
    if (auto ok = validate_patches(patches, "tessellate"); !ok) return ok.error();
    if (options.steps < 0) return Error{"tessellate: steps must be ≥ 0"};
    int n = options.steps;
    std::size_t worst = 0;
    if (n == 0) {
        if (!(options.tolerance > 0.0) || !std::isfinite(options.tolerance))
            return Error{"tessellate: tolerance must be positive and finite"};
        for (std::size_t k = 0; k < patches.size(); ++k) {
            int nk = steps_for_tolerance(patches[k], options.tolerance);
            if (nk > n) n = nk, worst = k;
        }
    }
    if (n > kMaxTessellationSteps)
        return Error{"tessellate: patch " + std::to_string(worst) + " needs " + std::to_string(n) +
                     " steps per side, more than " + std::to_string(kMaxTessellationSteps) +
                     " (raise the tolerance)"};
    const std::size_t per_patch = 2 * static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
    if (per_patch * patches.size() > kMaxMeshTriangles)
        return Error{"tessellate: " + std::to_string(per_patch * patches.size()) +
                     " triangles, more than " + std::to_string(kMaxMeshTriangles)};

    TriangleMesh mesh;
    const std::size_t side = static_cast<std::size_t>(n) + 1;
    mesh.positions.reserve(patches.size() * side * side);
    mesh.normals.reserve(patches.size() * side * side);
    mesh.params.reserve(patches.size() * side * side);
    mesh.triangles.reserve(per_patch * patches.size());
    mesh.patch_of.reserve(per_patch * patches.size());
    for (std::size_t k = 0; k < patches.size(); ++k) {
        const Patch& p = patches[k];
        const auto base = static_cast<std::uint32_t>(mesh.positions.size());
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n; ++j) {
                // i/n, not i·(1/n): the last row lands exactly on 1, where neighbours meet.
                double s = static_cast<double>(i) / n, t = static_cast<double>(j) / n;
                mesh.positions.push_back(p.eval(s, t));
                mesh.normals.push_back(p.normal(s, t));
                mesh.params.push_back({s, t});
            }
        auto at = [&](int i, int j) { return base + static_cast<std::uint32_t>(i * (n + 1) + j); };
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                // (s,t) → (s+h,t) → (s,t+h) turns from ∂s towards ∂t: facet normal along ∂s × ∂t.
                mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
                mesh.triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
                mesh.patch_of.push_back(static_cast<std::uint32_t>(k));
                mesh.patch_of.push_back(static_cast<std::uint32_t>(k));
            }
    }
    return mesh;
}

}  // namespace bezel
