// Real roots of quadratics and cubics (the contracts are in bezel/geometry.hpp).
//
// Both solvers first scale the coefficients by a power of two so the largest has magnitude in
// [0.5, 1): exact, and it makes every later tolerance relative without a division. Cubics are
// then searched in |x| ≤ kMaxRootMagnitude = 2³⁴⁰, where |coef|·|x|³ ≤ 2¹⁰²⁰ cannot overflow, so
// every evaluation below is finite.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "bezel/geometry.hpp"

namespace bezel {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();  // 2⁻⁵²

// The exponent e with max|coef| = f·2ᵉ, f ∈ [0.5, 1); dividing by 2ᵉ is exact (bar underflow of
// coefficients 2¹⁰⁷⁴ times smaller than the largest, which cannot matter).
int scale_exponent(double max_abs) {
    int e = 0;
    std::frexp(max_abs, &e);
    return e;
}

// Sorts, drops duplicates and roots beyond kMaxRootMagnitude (incl. ±∞ from a/0-like quotients),
// writes at most `capacity` survivors to `out`, returns how many.
int finish(double* r, int n, double* out, int capacity) {
    std::sort(r, r + n);
    int m = 0;
    for (int i = 0; i < n && m < capacity; ++i) {
        if (!(std::fabs(r[i]) <= kMaxRootMagnitude)) continue;
        if (m > 0 && out[m - 1] == r[i]) continue;
        out[m++] = r[i];
    }
    return m;
}

int filter_in(const double* r, int n, double t_min, double t_max, double* out) {
    int m = 0;
    for (int i = 0; i < n; ++i)
        if (r[i] >= t_min && r[i] <= t_max) out[m++] = r[i];
    return m;
}

// Quadratic on coefficients already scaled to max magnitude ~1. Writes unsorted candidates.
int quadratic_scaled(double a, double b, double c, double* r) {
    if (a == 0.0) {
        if (b == 0.0) return 0;  // a non-zero constant (or all zero): no isolated root
        r[0] = -c / b;
        return 1;
    }
    // Δ = b² − 4ac to nearly full precision (Kahan, "On the Cost of Floating-Point Computation
    // Without Extra-Precise Arithmetic", 2004): fma recovers each product's rounding error, so the
    // only error left in Δ is the final additions'. 4a is exact.
    double p = b * b, dp = std::fma(b, b, -p);
    double q = 4.0 * a * c, dq = std::fma(4.0 * a, c, -q);
    double disc = (p - q) + (dp - dq);
    // Rounding the coefficients (½ ulp each) already moves Δ by up to ε·(b² + |4ac|); a Δ that
    // small cannot be told from 0, so it is a double root. 2ε leaves room for the caller's own
    // rounding in forming the coefficients.
    if (std::fabs(disc) <= 2.0 * kEps * (p + std::fabs(q))) {
        r[0] = -b / (2.0 * a);
        return 1;
    }
    if (disc < 0.0) return 0;
    // Citardauq: q = −(b + sign(b)·√Δ)/2 adds two numbers of the same sign (no cancellation);
    // the roots are q/a and c/q (Vieta: x₁x₂ = c/a). |q| ≥ √Δ/2 > 0.
    double s = std::sqrt(disc);
    double qq = -0.5 * (b + std::copysign(s, b));
    r[0] = qq / a;  // ±∞ or huge when a is tiny: dropped by finish()
    r[1] = c / qq;
    return 2;
}

struct Cubic {
    double a, b, c, d;
    // Horner.
    double f(double x) const { return ((a * x + b) * x + c) * x + d; }
    double df(double x) const { return (3.0 * a * x + 2.0 * b) * x + c; }
    // Σ|coefᵢ|·|x|ⁱ: Horner's rounding error in f(x) is at most γ₆ times this (Higham, "Accuracy
    // and Stability of Numerical Algorithms", §5.1), γ₆ ≈ 3ε.
    double magnitude(double x) const {
        double ax = std::fabs(x);
        return ((std::fabs(a) * ax + std::fabs(b)) * ax + std::fabs(c)) * ax + std::fabs(d);
    }
};

// Doubles mapped to integers in the same order (−0 and +0 both to 0): the midpoint of two keys
// is the middle in binades, so halving a bracket like [1, 2³⁴⁰] takes ~9 steps where halving the
// real interval would take ~340.
std::int64_t order_key(double x) {
    std::int64_t i = 0;
    std::memcpy(&i, &x, sizeof i);
    return i >= 0 ? i : std::numeric_limits<std::int64_t>::min() - i;
}
double from_order_key(std::int64_t k) {
    std::int64_t i = k >= 0 ? k : std::numeric_limits<std::int64_t>::min() - k;
    double x = 0.0;
    std::memcpy(&x, &i, sizeof x);
    return x;
}

// The bisection point of [lo, hi] when the ends are more than 16× apart in magnitude (roots of
// very different sizes, or a bracket from a root bound): 0 if the bracket straddles it, else the
// middle in binades. Otherwise the arithmetic middle. Why not always binades: across 0 the
// middle in binades is ~1e-300, far from any root a moderate bracket holds, and each bisection
// after that climbs back only a few binades. (0 is never a root here: p(0) = d ≠ 0.)
double bisection_point(double lo, double hi) {
    double alo = std::fabs(lo), ahi = std::fabs(hi);
    if (std::max(alo, ahi) > 16.0 * std::min(alo, ahi)) {
        if (lo < 0.0 && hi > 0.0) return 0.0;
        if (lo != 0.0 && hi != 0.0) {
            std::int64_t kl = order_key(lo), kh = order_key(hi);
            return from_order_key(kl + (kh - kl) / 2);  // same sign: no overflow in kh − kl
        }
    }
    return 0.5 * (lo + hi);  // |lo|, |hi| ≤ 2³⁴⁰: no overflow
}

// Work limit of one root search (evaluations of p); the most seen over 2·10⁵ random cubics is 63
// (see the starting points in solve_cubic). It turns a logic error into a slightly inaccurate
// root instead of a hang.
constexpr int kMaxRootIterations = 300;
// Newton steps allowed in a row before a bisection is forced (see bracketed_root).
constexpr int kMaxNewtonRun = 16;

// The root of p in (lo, hi), where p is monotone and p(lo), p(hi) are non-zero with opposite
// signs, starting from `start` in [lo, hi]. Newton's step when it lands inside the bracket and
// is shorter than the previous step (after rtsafe, Numerical Recipes §9.4), bisection
// otherwise. Newton converges quadratically once close, but far from the root it can crawl (a
// step that exactly halves each time, as on x² far out), so after kMaxNewtonRun Newton steps in
// a row one bisection is forced. Ends when the bracket is a few ulps wide or Newton's step is
// below an ulp or two; typically after 5–8 evaluations.
double bracketed_root(const Cubic& p, double lo, double hi, bool f_lo_negative, double start) {
    double x = start;
    double prev_step = hi - lo;
    int newton_run = 0;
    for (int iter = 0; iter < kMaxRootIterations; ++iter) {
        double fx = p.f(x);
        if (fx == 0.0) return x;
        if ((fx < 0.0) == f_lo_negative) lo = x; else hi = x;
        if (hi - lo <= 2.0 * kEps * std::max(std::fabs(lo), std::fabs(hi)) ||
            std::nextafter(lo, hi) >= hi) {
            // The sign change is pinned to an ulp or two: pick the smaller residual.
            return std::fabs(p.f(lo)) <= std::fabs(p.f(hi)) ? lo : hi;
        }
        double dfx = p.df(x);
        double xn = dfx != 0.0 ? x - fx / dfx : lo;
        double step = xn - x;
        // Newton converges quadratically near a simple root: a step this small means x is
        // already correct to the last bit or two (even if rounding put xn just outside).
        if (std::fabs(step) <= 2.0 * kEps * std::fabs(x)) return x;
        if (newton_run < kMaxNewtonRun && xn > lo && xn < hi &&
            std::fabs(step) < std::fabs(prev_step)) {
            ++newton_run;
            prev_step = step;
            x = xn;
        } else {
            newton_run = 0;
            x = bisection_point(lo, hi);
            prev_step = hi - lo;
        }
    }
    return x;
}

}  // namespace

int solve_quadratic(double a, double b, double c, double roots[2]) {
    if (!std::isfinite(a) || !std::isfinite(b) || !std::isfinite(c)) return 0;
    double m = std::max({std::fabs(a), std::fabs(b), std::fabs(c)});
    if (m == 0.0) return 0;
    int e = scale_exponent(m);
    double r[2];
    int n = quadratic_scaled(std::ldexp(a, -e), std::ldexp(b, -e), std::ldexp(c, -e), r);
    return finish(r, n, roots, 2);
}

int solve_cubic(double a, double b, double c, double d, double roots[3]) {
    if (!std::isfinite(a) || !std::isfinite(b) || !std::isfinite(c) || !std::isfinite(d)) return 0;
    double m = std::max({std::fabs(a), std::fabs(b), std::fabs(c), std::fabs(d)});
    if (m == 0.0) return 0;
    int e = scale_exponent(m);
    Cubic p{std::ldexp(a, -e), std::ldexp(b, -e), std::ldexp(c, -e), std::ldexp(d, -e)};

    double r[8];
    int n = 0;
    if (p.a == 0.0) {
        n = quadratic_scaled(p.b, p.c, p.d, r);
        return finish(r, n, roots, 3);
    }
    if (p.d == 0.0) {
        // x = 0 is a root; the rest are the quadratic's (exact deflation, as in Kahan's QBC).
        r[0] = 0.0;
        n = 1 + quadratic_scaled(p.a, p.b, p.c, r + 1);
        return finish(r, n, roots, 3);
    }

    // Every root lies in |x| ≤ B (Fujiwara's bound, with 1/8 to spare for rounding):
    //   B = 2·max(|b/a|, |c/a|^½, |d/(2a)|^⅓).
    double bound = 2.25 * std::max({std::fabs(p.b / p.a), std::sqrt(std::fabs(p.c / p.a)),
                                    std::cbrt(std::fabs(p.d / (2.0 * p.a)))});
    bound = std::min(bound, kMaxRootMagnitude);

    // Break points: −B, the critical points (roots of p′) inside (−B, B), B. Between two of them
    // p is monotone, so it has at most one root there, found by bracketing.
    double xs[4], fs[4];
    int k = 0;
    xs[k++] = -bound;
    // solve_quadratic, not quadratic_scaled: p′'s coefficients need their own normalisation
    // (with p.a ~ 1e-270 and p.c ~ 1e-90, as for roots near 1e90, b² would underflow).
    double crit[2];
    int nc = solve_quadratic(3.0 * p.a, 2.0 * p.b, p.c, crit);
    for (int i = 0; i < nc; ++i)
        if (crit[i] > -bound && crit[i] < bound && crit[i] > xs[k - 1]) xs[k++] = crit[i];
    xs[k++] = bound;

    for (int i = 0; i < k; ++i) {
        fs[i] = p.f(xs[i]);
        // At a critical point, a value within Horner's rounding error (3ε·Σ|coef||x|ⁱ) plus the
        // coefficients' own rounding is indistinguishable from 0: a double root sits there. 8ε
        // covers both with room to spare.
        bool is_crit = i > 0 && i < k - 1;
        if (is_crit && std::fabs(fs[i]) <= 8.0 * kEps * p.magnitude(xs[i])) fs[i] = 0.0;
    }
    // Starting points: between two critical points, the inflection −b/3a, where |p′| is largest,
    // so Newton's first step cannot overshoot (|p(x)|/|p′(x)| ≤ |x − root| by the mean value
    // theorem) and it converges monotonically from there. Elsewhere the bisection point. (Measured
    // over 10⁵ random cubics: 6.5 evaluations per root on average for coefficients uniform in
    // [−100, 100], 13 for roots spread over ±12 decades; at most 63.)
    double inflection = -p.b / (3.0 * p.a);
    for (int i = 0; i < k; ++i) {
        if (fs[i] == 0.0) r[n++] = xs[i];
        if (i + 1 < k && fs[i] != 0.0 && fs[i + 1] != 0.0 && (fs[i] < 0.0) != (fs[i + 1] < 0.0)) {
            double lo = xs[i], hi = xs[i + 1];
            bool between_critical_points = i > 0 && i + 2 < k;
            double start = between_critical_points ? std::clamp(inflection, lo, hi)
                                                   : bisection_point(lo, hi);
            r[n++] = bracketed_root(p, lo, hi, fs[i] < 0.0, start);
        }
    }
    return finish(r, n, roots, 3);
}

int solve_quadratic_in(double a, double b, double c, double t_min, double t_max, double roots[2]) {
    double r[2];
    int n = solve_quadratic(a, b, c, r);
    return filter_in(r, n, t_min, t_max, roots);
}

int solve_cubic_in(double a, double b, double c, double d, double t_min, double t_max,
                   double roots[3]) {
    double r[3];
    int n = solve_cubic(a, b, c, d, r);
    return filter_in(r, n, t_min, t_max, roots);
}

}  // namespace bezel
