// Bicubic patches in matrix form: blending functions, evaluation, conversion to Bézier nets.
#include <cmath>

#include "bezel/surface.hpp"

namespace bezel {
namespace {

// Gauss–Jordan with partial pivoting. Only used on the basis matrices, whose determinants are
// far from zero (|det M_bez| = 9), so no singular case arises.
basis::Mat4 inverse(const basis::Mat4& m) {
    double a[4][8];
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            a[i][j] = m.m[i][j];
            a[i][j + 4] = i == j ? 1.0 : 0.0;
        }
    for (int c = 0; c < 4; ++c) {
        int p = c;
        for (int r = c + 1; r < 4; ++r)
            if (std::fabs(a[r][c]) > std::fabs(a[p][c])) p = r;
        for (int j = 0; j < 8; ++j) std::swap(a[c][j], a[p][j]);
        double d = a[c][c];
        for (int j = 0; j < 8; ++j) a[c][j] /= d;
        for (int r = 0; r < 4; ++r) {
            if (r == c) continue;
            double f = a[r][c];
            for (int j = 0; j < 8; ++j) a[r][j] -= f * a[c][j];
        }
    }
    basis::Mat4 out{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) out.m[i][j] = a[i][j + 4];
    return out;
}

std::array<double, 4> row_times(const double (&u)[4], const basis::Mat4& m) {
    std::array<double, 4> w{};
    for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 4; ++row) w[col] += u[row] * m.m[row][col];
    return w;
}

// Σᵢⱼ a_i·b_j·G[i][j]: S·M·G·Mᵀ·Tᵀ once the two blending rows are known.
Vec3 contract(const std::array<double, 4>& a, const std::array<double, 4>& b, const Vec3 (&g)[4][4]) {
    Vec3 q;
    for (int i = 0; i < 4; ++i) {
        Vec3 r;
        for (int j = 0; j < 4; ++j) r += g[i][j] * b[j];
        q += r * a[i];
    }
    return q;
}

Vec3 lerp3(Vec3 a, Vec3 b, double t) {
    if (t < 0.5) return a + (b - a) * t;
    return b - (b - a) * (1.0 - t);
}

// de Casteljau on four points; also returns the halves when asked.
Vec3 casteljau(const Vec3 (&p)[4], double t, Vec3* left = nullptr, Vec3* right = nullptr) {
    Vec3 a = lerp3(p[0], p[1], t), b = lerp3(p[1], p[2], t), c = lerp3(p[2], p[3], t);
    Vec3 ab = lerp3(a, b, t), bc = lerp3(b, c, t), m = lerp3(ab, bc, t);
    if (left) left[0] = p[0], left[1] = a, left[2] = ab, left[3] = m;
    if (right) right[0] = m, right[1] = bc, right[2] = c, right[3] = p[3];
    return m;
}

// Blossom of a cubic: f(u,v,w), one parameter per de Casteljau level.
Vec3 blossom(const Vec3 (&p)[4], double u, double v, double w) {
    Vec3 a = lerp3(p[0], p[1], u), b = lerp3(p[1], p[2], u), c = lerp3(p[2], p[3], u);
    return lerp3(lerp3(a, b, v), lerp3(b, c, v), w);
}

}  // namespace

const char* basis_name(SurfaceBasis b) {
    switch (b) {
        case SurfaceBasis::Bezier: return "bezier";
        case SurfaceBasis::Hermite: return "hermite";
        case SurfaceBasis::BSpline: return "bspline";
    }
    return "?";
}

const basis::Mat4& basis_matrix(SurfaceBasis b) {
    switch (b) {
        case SurfaceBasis::Hermite: return basis::kHermite;
        case SurfaceBasis::BSpline: return basis::kBSpline;
        case SurfaceBasis::Bezier: break;
    }
    return basis::kBezier;
}

basis::Mat4 to_bezier_matrix(SurfaceBasis b) {
    static const basis::Mat4 kBezierInverse = inverse(basis::kBezier);
    return basis::mul(kBezierInverse, basis_matrix(b));
}

std::array<double, 4> blend(SurfaceBasis b, double u) {
    const double p[4] = {u * u * u, u * u, u, 1.0};
    return row_times(p, basis_matrix(b));
}
std::array<double, 4> blend_deriv(SurfaceBasis b, double u) {
    const double p[4] = {3 * u * u, 2 * u, 1.0, 0.0};
    return row_times(p, basis_matrix(b));
}
std::array<double, 4> blend_deriv2(SurfaceBasis b, double u) {
    const double p[4] = {6 * u, 2.0, 0.0, 0.0};
    return row_times(p, basis_matrix(b));
}

Vec3 Patch::eval(double s, double t) const { return contract(blend(basis, s), blend(basis, t), g); }
Vec3 Patch::deriv_s(double s, double t) const {
    return contract(blend_deriv(basis, s), blend(basis, t), g);
}
Vec3 Patch::deriv_t(double s, double t) const {
    return contract(blend(basis, s), blend_deriv(basis, t), g);
}

Vec3 Patch::normal(double s, double t) const {
    Vec3 n = deriv_s(s, t).cross(deriv_t(s, t));
    double size2 = 0.0;
    for (const auto& row : g)
        for (const Vec3& p : row) size2 = std::fmax(size2, (p - g[0][0]).dot(p - g[0][0]));
    if (n.length() > 1e-12 * size2) return n.normalized();
    // A collapsed edge or corner: the normal's limit along the way to the patch centre.
    constexpr double kStep = 1e-5;
    double s2 = s + (s < 0.5 ? kStep : -kStep), t2 = t + (t < 0.5 ? kStep : -kStep);
    return deriv_s(s2, t2).cross(deriv_t(s2, t2)).normalized();
}

Patch Patch::to_bezier() const {
    if (basis == SurfaceBasis::Bezier) return *this;
    const basis::Mat4 c = to_bezier_matrix(basis);
    Patch out;
    // B = C·G·Cᵀ: B[i][j] = Σₖₗ C[i][k]·G[k][l]·C[j][l].
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            Vec3 q;
            for (int k = 0; k < 4; ++k) {
                Vec3 r;
                for (int l = 0; l < 4; ++l) r += g[k][l] * c.m[j][l];
                q += r * c.m[i][k];
            }
            out.g[i][j] = q;
        }
    return out;
}

bool Patch::is_finite() const {
    for (const auto& row : g)
        for (const Vec3& p : row)
            if (!p.is_finite()) return false;
    return true;
}

Vec3 eval_de_casteljau(const Patch& bezier, double s, double t) {
    Vec3 column[4];
    for (int i = 0; i < 4; ++i) column[i] = casteljau(bezier.g[i], t);
    return casteljau(column, s);
}

std::pair<Patch, Patch> split_s(const Patch& patch, double s) {
    Patch b = patch.to_bezier(), lo, hi;
    for (int j = 0; j < 4; ++j) {
        Vec3 col[4] = {b.g[0][j], b.g[1][j], b.g[2][j], b.g[3][j]}, l[4], r[4];
        casteljau(col, s, l, r);
        for (int i = 0; i < 4; ++i) lo.g[i][j] = l[i], hi.g[i][j] = r[i];
    }
    return {lo, hi};
}

std::pair<Patch, Patch> split_t(const Patch& patch, double t) {
    Patch b = patch.to_bezier(), lo, hi;
    for (int i = 0; i < 4; ++i) casteljau(b.g[i], t, lo.g[i], hi.g[i]);
    return {lo, hi};
}

Patch subpatch(const Patch& patch, double s0, double s1, double t0, double t1) {
    Patch b = patch.to_bezier(), rows, out;
    // Along t on every row, then along s on every column: the tensor product of the curve
    // blossoms f(t0,t0,t0), f(t0,t0,t1), f(t0,t1,t1), f(t1,t1,t1).
    for (int i = 0; i < 4; ++i) {
        rows.g[i][0] = blossom(b.g[i], t0, t0, t0);
        rows.g[i][1] = blossom(b.g[i], t0, t0, t1);
        rows.g[i][2] = blossom(b.g[i], t0, t1, t1);
        rows.g[i][3] = blossom(b.g[i], t1, t1, t1);
    }
    for (int j = 0; j < 4; ++j) {
        Vec3 col[4] = {rows.g[0][j], rows.g[1][j], rows.g[2][j], rows.g[3][j]};
        out.g[0][j] = blossom(col, s0, s0, s0);
        out.g[1][j] = blossom(col, s0, s0, s1);
        out.g[2][j] = blossom(col, s0, s1, s1);
        out.g[3][j] = blossom(col, s1, s1, s1);
    }
    return out;
}

Expected<std::vector<Patch>> bspline_grid(const std::vector<Vec3>& points, int rows, int cols) {
    if (rows < 4 || cols < 4 || rows > kMaxBSplineGridSide || cols > kMaxBSplineGridSide)
        return Error{"B-spline grid " + std::to_string(rows) + "×" + std::to_string(cols) +
                     ": each side must be 4 to " + std::to_string(kMaxBSplineGridSide)};
    if (points.size() != static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols))
        return Error{"B-spline grid " + std::to_string(rows) + "×" + std::to_string(cols) + ": " +
                     std::to_string(points.size()) + " points given"};
    for (std::size_t k = 0; k < points.size(); ++k)
        if (!points[k].is_finite())
            return Error{"B-spline grid: point " + std::to_string(k) + " is not finite"};
    std::vector<Patch> out;
    out.reserve(static_cast<std::size_t>(rows - 3) * static_cast<std::size_t>(cols - 3));
    for (int a = 0; a + 3 < rows; ++a)
        for (int b = 0; b + 3 < cols; ++b) {
            Patch p;
            p.basis = SurfaceBasis::BSpline;
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j)
                    p.g[i][j] = points[static_cast<std::size_t>((a + i) * cols + (b + j))];
            out.push_back(p);
        }
    return out;
}

Status validate_patches(const std::vector<Patch>& patches, const std::string& what) {
    if (patches.empty()) return Error{what + ": no patches"};
    if (patches.size() > kMaxSurfacePatches)
        return Error{what + ": " + std::to_string(patches.size()) + " patches, more than " +
                     std::to_string(kMaxSurfacePatches)};
    for (std::size_t k = 0; k < patches.size(); ++k)
        if (!patches[k].is_finite())
            return Error{what + ": patch " + std::to_string(k) + " has a non-finite point"};
    return ok_status();
}

}  // namespace bezel
