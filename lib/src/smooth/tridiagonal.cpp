#include "smooth/tridiagonal.hpp"

#include <cassert>
#include <cmath>
#include <cstddef>

namespace bezel::smooth_detail {
namespace {

bool finite(double v) { return std::isfinite(v); }
bool finite(Vec2 v) { return v.is_finite(); }

// Thomas on (sub, diag, super) with the corner entries ignored. `scratch` receives the modified
// super-diagonal c′ᵢ = superᵢ / (diagᵢ − subᵢ·c′ᵢ₋₁).
template <typename V>
bool thomas(const std::vector<double>& sub, const std::vector<double>& diag,
            const std::vector<double>& super, std::vector<V>& x, std::vector<double>& scratch) {
    const std::size_t n = diag.size();
    scratch.assign(n, 0.0);
    double pivot = diag[0];
    if (pivot == 0.0) return false;
    scratch[0] = n > 1 ? super[0] / pivot : 0.0;
    x[0] = x[0] / pivot;
    for (std::size_t i = 1; i < n; ++i) {
        pivot = diag[i] - sub[i] * scratch[i - 1];
        if (pivot == 0.0 || !std::isfinite(pivot)) return false;
        scratch[i] = i + 1 < n ? super[i] / pivot : 0.0;
        x[i] = (x[i] - x[i - 1] * sub[i]) / pivot;
    }
    for (std::size_t i = n - 1; i-- > 0;) x[i] = x[i] - x[i + 1] * scratch[i];
    for (const V& v : x)
        if (!finite(v)) return false;
    return true;
}

}  // namespace

bool solve_tridiagonal(const Tridiagonal& m, std::vector<Vec2>& rhs) {
    assert(m.sub.size() == m.diag.size() && m.super.size() == m.diag.size());
    assert(rhs.size() == m.diag.size() && !rhs.empty());
    std::vector<double> scratch;
    return thomas(m.sub, m.diag, m.super, rhs, scratch);
}

bool solve_cyclic_tridiagonal(const Tridiagonal& m, std::vector<Vec2>& rhs) {
    const std::size_t n = m.diag.size();
    assert(n >= 3 && m.sub.size() == n && m.super.size() == n && rhs.size() == n);
    // A = T + u·vᵀ with u = [γ 0 … 0 α]ᵀ, v = [1 0 … 0 β/γ]ᵀ, where α = A[n−1][0] and
    // β = A[0][n−1]; T is A without its corners and with diag[0] − γ, diag[n−1] − αβ/γ.
    // γ = −diag[0] keeps T's first pivot away from cancellation (Numerical Recipes' choice).
    const double alpha = m.super[n - 1];
    const double beta = m.sub[0];
    const double gamma = -m.diag[0];
    if (gamma == 0.0) return false;
    std::vector<double> diag = m.diag;
    diag[0] -= gamma;
    diag[n - 1] -= alpha * beta / gamma;

    std::vector<double> scratch;
    if (!thomas(m.sub, diag, m.super, rhs, scratch)) return false;  // rhs is now y
    std::vector<double> z(n, 0.0);
    z[0] = gamma;
    z[n - 1] = alpha;
    if (!thomas(m.sub, diag, m.super, z, scratch)) return false;

    // x = y − z·(v·y)/(1 + v·z)
    const double denom = 1.0 + z[0] + beta * z[n - 1] / gamma;
    if (denom == 0.0 || !std::isfinite(denom)) return false;
    const Vec2 factor = (rhs[0] + rhs[n - 1] * (beta / gamma)) / denom;
    for (std::size_t i = 0; i < n; ++i) rhs[i] -= factor * z[i];
    for (const Vec2& v : rhs)
        if (!v.is_finite()) return false;
    return true;
}

}  // namespace bezel::smooth_detail
