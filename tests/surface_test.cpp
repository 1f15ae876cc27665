// Bicubic patches: basis properties, evaluation, derivatives and normals, subdivision, basis
// conversion, B-spline grids, tessellation error, mesh export. Pictures: surface_render_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <sstream>

#include "bezel/surface.hpp"

namespace bezel {
namespace {

constexpr SurfaceBasis kBases[] = {SurfaceBasis::Bezier, SurfaceBasis::Hermite,
                                   SurfaceBasis::BSpline};

Patch random_patch(std::mt19937_64& rng, SurfaceBasis basis) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Patch p;
    p.basis = basis;
    for (auto& row : p.g)
        for (Vec3& q : row) q = {u(rng), u(rng), u(rng)};
    return p;
}

double dist(Vec3 a, Vec3 b) { return (a - b).length(); }

// Σᵢⱼ aᵢ·bⱼ·G[i][j], for derivatives the Patch API does not offer.
Vec3 contract(const std::array<double, 4>& a, const std::array<double, 4>& b, const Patch& p) {
    Vec3 q;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) q += p.g[i][j] * (a[i] * b[j]);
    return q;
}

TEST(SurfaceBasisTest, PartitionOfUnity) {
    for (int k = 0; k <= 100; ++k) {
        double u = k / 100.0;
        for (SurfaceBasis b : {SurfaceBasis::Bezier, SurfaceBasis::BSpline}) {
            auto w = blend(b, u);
            EXPECT_NEAR(w[0] + w[1] + w[2] + w[3], 1.0, 1e-15) << basis_name(b) << " u=" << u;
            auto d = blend_deriv(b, u);
            EXPECT_NEAR(d[0] + d[1] + d[2] + d[3], 0.0, 1e-14) << basis_name(b) << " u=" << u;
        }
        auto h = blend(SurfaceBasis::Hermite, u);
        EXPECT_NEAR(h[0] + h[1], 1.0, 1e-15) << "hermite u=" << u;
        // Bézier weights are the Bernstein polynomials: non-negative.
        for (double w : blend(SurfaceBasis::Bezier, u)) EXPECT_GE(w, -1e-16);
    }
}

TEST(SurfaceBasisTest, ConversionMatrixIsTheGeometryCoresBSplineToBezier) {
    const basis::Mat4 c = to_bezier_matrix(SurfaceBasis::BSpline);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            EXPECT_NEAR(c.m[i][j], basis::kBSplineToBezier.m[i][j], 1e-15) << i << "," << j;
    // Hermite → Bézier: P1 = P0 + T0/3, P2 = P3 − T1/3 (bezier.hpp's hermite_to_bezier).
    const basis::Mat4 h = to_bezier_matrix(SurfaceBasis::Hermite);
    const double expected[4][4] = {{1, 0, 0, 0}, {1, 0, 1.0 / 3, 0}, {0, 1, 0, -1.0 / 3}, {0, 1, 0, 0}};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) EXPECT_NEAR(h.m[i][j], expected[i][j], 1e-15);
}

TEST(SurfacePatchTest, BezierPatchInterpolatesCorners) {
    std::mt19937_64 rng(1);
    for (int n = 0; n < 50; ++n) {
        Patch p = random_patch(rng, SurfaceBasis::Bezier);
        EXPECT_LE(dist(p.eval(0, 0), p.g[0][0]), 1e-15);
        EXPECT_LE(dist(p.eval(0, 1), p.g[0][3]), 1e-15);
        EXPECT_LE(dist(p.eval(1, 0), p.g[3][0]), 1e-15);
        EXPECT_LE(dist(p.eval(1, 1), p.g[3][3]), 1e-15);
        // The boundary curve s = 0 is the Bézier curve of the first row (its tangent: 3(b01 − b00)).
        EXPECT_LE(dist(p.deriv_t(0, 0), (p.g[0][1] - p.g[0][0]) * 3.0), 1e-14);
        EXPECT_LE(dist(p.deriv_s(0, 0), (p.g[1][0] - p.g[0][0]) * 3.0), 1e-14);
    }
}

TEST(SurfacePatchTest, MatrixFormMatchesDeCasteljau) {
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int n = 0; n < 200; ++n) {
        Patch p = random_patch(rng, SurfaceBasis::Bezier);
        double s = u(rng), t = u(rng);
        EXPECT_LE(dist(p.eval(s, t), eval_de_casteljau(p, s, t)), 1e-14);
    }
}

TEST(SurfacePatchTest, HermitePatchInterpolatesItsData) {
    std::mt19937_64 rng(3);
    Patch p = random_patch(rng, SurfaceBasis::Hermite);
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) {
            EXPECT_LE(dist(p.eval(i, j), p.g[i][j]), 1e-15);
            EXPECT_LE(dist(p.deriv_s(i, j), p.g[2 + i][j]), 1e-14);
            EXPECT_LE(dist(p.deriv_t(i, j), p.g[i][2 + j]), 1e-14);
            Vec3 twist = contract(blend_deriv(p.basis, i), blend_deriv(p.basis, j), p);
            EXPECT_LE(dist(twist, p.g[2 + i][2 + j]), 1e-14);
        }
}

TEST(SurfacePatchTest, ConversionToBezierEqualsDirectEvaluation) {
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (SurfaceBasis b : kBases)
        for (int n = 0; n < 100; ++n) {
            Patch p = random_patch(rng, b);
            Patch z = p.to_bezier();
            ASSERT_EQ(z.basis, SurfaceBasis::Bezier);
            double s = u(rng), t = u(rng);
            EXPECT_LE(dist(p.eval(s, t), z.eval(s, t)), 1e-14) << basis_name(b);
            EXPECT_LE(dist(p.eval(s, t), eval_de_casteljau(z, s, t)), 1e-14) << basis_name(b);
            EXPECT_LE(dist(p.deriv_s(s, t), z.deriv_s(s, t)), 1e-13) << basis_name(b);
            EXPECT_LE(dist(p.deriv_t(s, t), z.deriv_t(s, t)), 1e-13) << basis_name(b);
        }
}

TEST(SurfacePatchTest, PartialsMatchFiniteDifferences) {
    std::mt19937_64 rng(5);
    const double h = 1e-6;
    for (SurfaceBasis b : kBases) {
        Patch p = random_patch(rng, b);
        for (double s : {0.1, 0.5, 0.9})
            for (double t : {0.2, 0.7}) {
                Vec3 ds = (p.eval(s + h, t) - p.eval(s - h, t)) / (2 * h);
                Vec3 dt = (p.eval(s, t + h) - p.eval(s, t - h)) / (2 * h);
                EXPECT_LE(dist(ds, p.deriv_s(s, t)), 1e-8) << basis_name(b);
                EXPECT_LE(dist(dt, p.deriv_t(s, t)), 1e-8) << basis_name(b);
            }
    }
}

TEST(SurfacePatchTest, NormalsPerpendicularToBothPartials) {
    std::mt19937_64 rng(6);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (SurfaceBasis b : kBases)
        for (int n = 0; n < 300; ++n) {
            Patch p = random_patch(rng, b);
            double s = u(rng), t = u(rng);
            Vec3 nrm = p.normal(s, t), ds = p.deriv_s(s, t), dt = p.deriv_t(s, t);
            EXPECT_NEAR(nrm.length(), 1.0, 1e-14);
            EXPECT_LE(std::fabs(nrm.dot(ds)), 1e-12 * ds.length()) << basis_name(b);
            EXPECT_LE(std::fabs(nrm.dot(dt)), 1e-12 * dt.length()) << basis_name(b);
            // Oriented along ∂s × ∂t.
            EXPECT_GT(nrm.dot(ds.cross(dt)), 0.0);
        }
}

TEST(SurfacePatchTest, NormalAtCollapsedEdgeIsTheLimit) {
    // A cone-like patch: the whole row s = 0 is one point (the teapot lid's pole), so ∂Q/∂t = 0
    // there; the normal is still the limit, here the cone's axis direction side.
    Patch p;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) p.g[i][j] = {i * (j - 1.5), i * 1.0, -i * 0.5};
    Vec3 n0 = p.normal(0.0, 0.5), n1 = p.normal(1e-3, 0.5);
    ASSERT_NEAR(n0.length(), 1.0, 1e-12);
    EXPECT_GT(n0.dot(n1), 0.999);
}

TEST(SurfaceSubdivisionTest, SplitsReproduceTheSurface) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (SurfaceBasis b : kBases)
        for (int n = 0; n < 30; ++n) {
            Patch p = random_patch(rng, b);
            const double c = 0.1 + 0.8 * u(rng);
            auto [s_lo, s_hi] = split_s(p, c);
            auto [t_lo, t_hi] = split_t(p, c);
            for (int k = 0; k < 10; ++k) {
                double x = u(rng), y = u(rng);
                EXPECT_LE(dist(s_lo.eval(x, y), p.eval(c * x, y)), 1e-13);
                EXPECT_LE(dist(s_hi.eval(x, y), p.eval(c + (1 - c) * x, y)), 1e-13);
                EXPECT_LE(dist(t_lo.eval(x, y), p.eval(x, c * y)), 1e-13);
                EXPECT_LE(dist(t_hi.eval(x, y), p.eval(x, c + (1 - c) * y)), 1e-13);
            }
            // The halves meet exactly along the cut.
            for (int j = 0; j < 4; ++j) EXPECT_EQ(s_lo.g[3][j], s_hi.g[0][j]);
            Patch sub = subpatch(p, 0.2, 0.7, 0.9, 0.4);  // t reversed
            for (int k = 0; k < 10; ++k) {
                double x = u(rng), y = u(rng);
                EXPECT_LE(dist(sub.eval(x, y), p.eval(0.2 + 0.5 * x, 0.9 - 0.5 * y)), 1e-13);
            }
        }
}

TEST(SurfaceMeshTest, BSplineGridPatchesAreC2) {
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const int rows = 6, cols = 5;
    std::vector<Vec3> pts(rows * cols);
    for (Vec3& q : pts) q = {u(rng), u(rng), u(rng)};
    auto patches = bspline_grid(pts, rows, cols);
    ASSERT_TRUE(patches.ok()) << patches.error().message;
    ASSERT_EQ(patches->size(), 3u * 2u);
    const auto B = SurfaceBasis::BSpline;
    auto d = [&](const Patch& p, int order_s, int order_t, double s, double t) {
        auto f = [&](int o, double x) {
            return o == 0 ? blend(B, x) : o == 1 ? blend_deriv(B, x) : blend_deriv2(B, x);
        };
        return contract(f(order_s, s), f(order_t, t), p);
    };
    for (double t : {0.0, 0.3, 1.0}) {
        // Patch (0,0) meets (1,0) along s: value, ∂s, ∂ss continuous; and (0,0) meets (0,1) along t.
        const Patch& a = (*patches)[0];
        const Patch& below = (*patches)[2];
        const Patch& right = (*patches)[1];
        for (int o = 0; o <= 2; ++o) {
            EXPECT_LE(dist(d(a, o, 0, 1.0, t), d(below, o, 0, 0.0, t)), 1e-13) << "order " << o;
            EXPECT_LE(dist(d(a, 0, o, t, 1.0), d(right, 0, o, t, 0.0)), 1e-13) << "order " << o;
        }
    }
}

TEST(SurfaceMeshTest, BSplineGridRejectsBadInput) {
    std::vector<Vec3> pts(16);
    EXPECT_FALSE(bspline_grid(pts, 3, 5).ok());
    EXPECT_FALSE(bspline_grid(pts, 4, 5).ok());  // 16 points for 20
    EXPECT_FALSE(bspline_grid(std::vector<Vec3>(4 * 300), 4, 300).ok());
    pts[5].y = std::nan("");
    auto bad = bspline_grid(pts, 4, 4);
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().message.find("point 5"), std::string::npos);
}

// Max distance between mesh points and the surface at the same parameters, sampled inside
// every triangle (barycentric grid incl. edges and centroid).
double sampled_mesh_error(const std::vector<Patch>& patches, const TriangleMesh& mesh) {
    double worst = 0.0;
    for (std::size_t m = 0; m < mesh.triangles.size(); ++m) {
        const auto& t = mesh.triangles[m];
        const Patch& p = patches[mesh.patch_of[m]];
        for (int i = 0; i <= 6; ++i)
            for (int j = 0; i + j <= 6; ++j) {
                double a = i / 6.0, b = j / 6.0, c = 1.0 - a - b;
                Vec3 on_mesh = mesh.positions[t[0]] * a + mesh.positions[t[1]] * b + mesh.positions[t[2]] * c;
                Vec2 st = mesh.params[t[0]] * a + mesh.params[t[1]] * b + mesh.params[t[2]] * c;
                worst = std::max(worst, dist(on_mesh, p.eval(st.x, st.y)));
            }
    }
    return worst;
}

TEST(SurfaceTessellateTest, ErrorWithinTolerance) {
    std::mt19937_64 rng(9);
    for (SurfaceBasis b : kBases)
        for (double tol : {0.05, 0.005}) {
            std::vector<Patch> patches = {random_patch(rng, b), random_patch(rng, b)};
            auto mesh = tessellate(patches, {0, tol});
            ASSERT_TRUE(mesh.ok()) << mesh.error().message;
            double err = sampled_mesh_error(patches, *mesh);
            EXPECT_LE(err, tol) << basis_name(b);
            // The bound is not absurdly loose: the error reaches a fair share of it.
            EXPECT_GE(err, tol / 20) << basis_name(b);
        }
}

TEST(SurfaceTessellateTest, CountsAndSharedEdges) {
    std::mt19937_64 rng(10);
    Patch p = random_patch(rng, SurfaceBasis::Bezier);
    auto halves = split_s(p, 0.5);
    std::vector<Patch> patches = {halves.first, halves.second};
    auto mesh = tessellate(patches, {7, 0});
    ASSERT_TRUE(mesh.ok());
    EXPECT_EQ(mesh->triangles.size(), 2u * 2 * 7 * 7);
    EXPECT_EQ(mesh->positions.size(), 2u * 8 * 8);
    // Row s = 1 of the first half and row s = 0 of the second are the same points: no crack.
    for (int j = 0; j <= 7; ++j) EXPECT_EQ(mesh->positions[7 * 8 + j], mesh->positions[64 + j]);
    // Facets wound along ∂s × ∂t.
    const auto& t = mesh->triangles[0];
    Vec3 facet = (mesh->positions[t[1]] - mesh->positions[t[0]]).cross(mesh->positions[t[2]] - mesh->positions[t[0]]);
    EXPECT_GT(facet.dot(mesh->normals[t[0]]), 0.0);
}

TEST(SurfaceTessellateTest, RejectsBadInput) {
    std::vector<Patch> none;
    EXPECT_FALSE(tessellate(none, {}).ok());
    std::vector<Patch> one(1);
    one[0].g[0][0] = {1, 2, 3};
    one[0].g[1][1] = {0, 5, 0};
    EXPECT_FALSE(tessellate(one, {0, 0.0}).ok());
    EXPECT_FALSE(tessellate(one, {0, std::nan("")}).ok());
    EXPECT_FALSE(tessellate(one, {-1, 0.1}).ok());
    auto tiny = tessellate(one, {0, 1e-12});  // would need millions of steps
    ASSERT_FALSE(tiny.ok());
    EXPECT_NE(tiny.error().message.find("steps"), std::string::npos);
    EXPECT_FALSE(tessellate(one, {kMaxTessellationSteps + 1, 0}).ok());
    one[0].g[2][3].z = INFINITY;
    EXPECT_FALSE(tessellate(one, {4, 0}).ok());
}

std::size_t count_lines_starting(const std::string& text, const std::string& prefix) {
    std::istringstream in(text);
    std::size_t n = 0;
    for (std::string line; std::getline(in, line);) n += line.rfind(prefix, 0) == 0;
    return n;
}

TEST(SurfaceExportTest, ObjAndStlAreWellFormed) {
    std::mt19937_64 rng(11);
    std::vector<Patch> patches = {random_patch(rng, SurfaceBasis::Bezier)};
    auto mesh = tessellate(patches, {3, 0});
    ASSERT_TRUE(mesh.ok());
    const std::size_t nv = mesh->positions.size(), nt = mesh->triangles.size();
    std::string obj = to_obj(*mesh);
    EXPECT_EQ(count_lines_starting(obj, "v "), nv);
    EXPECT_EQ(count_lines_starting(obj, "vn "), nv);
    EXPECT_EQ(count_lines_starting(obj, "f "), nt);
    // Face indices are 1-based and in range.
    std::istringstream in(obj);
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("f ", 0) != 0) continue;
        unsigned long a, a2, b, b2, c, c2;
        ASSERT_EQ(std::sscanf(line.c_str(), "f %lu//%lu %lu//%lu %lu//%lu", &a, &a2, &b, &b2, &c, &c2), 6);
        for (unsigned long v : {a, b, c}) EXPECT_TRUE(v >= 1 && v <= nv);
    }
    // OBJ keeps 17 digits: positions read back exactly.
    std::istringstream in2(obj);
    std::string line;
    while (std::getline(in2, line) && line.rfind("v ", 0) != 0) {}
    double x, y, z;
    ASSERT_EQ(std::sscanf(line.c_str(), "v %lf %lf %lf", &x, &y, &z), 3);
    EXPECT_EQ(Vec3(x, y, z), mesh->positions[0]);

    std::string stl = to_stl_binary(*mesh);
    ASSERT_EQ(stl.size(), 84 + 50 * nt);
    std::uint32_t count;
    std::memcpy(&count, stl.data() + 80, 4);
    EXPECT_EQ(count, nt);
    float first_x;
    std::memcpy(&first_x, stl.data() + 84 + 12, 4);  // after the facet normal
    EXPECT_EQ(first_x, static_cast<float>(mesh->positions[mesh->triangles[0][0]].x));

    std::string ascii = to_stl_ascii(*mesh);
    EXPECT_EQ(ascii.rfind("solid bezel\n", 0), 0u);
    EXPECT_EQ(count_lines_starting(ascii, "  facet normal"), nt);
    EXPECT_EQ(count_lines_starting(ascii, "      vertex"), 3 * nt);
    EXPECT_NE(ascii.find("endsolid bezel\n"), std::string::npos);
}

}  // namespace
}  // namespace bezel
