// Arc length and its inverse for Line, QuadBez and CubicBez.
//
//   L(t0, t1) = ∫ |C′(t)| dt over [t0, t1]
//
// is integrated by Gauss–Legendre quadrature, adaptively: on each piece the 8- and 16-point rules
// are compared; their difference estimates the 8-point rule's error (the 16-point result is
// far better, exact for polynomials of degree 31), so a piece is accepted when the difference is
// within its share of the requested accuracy and halved otherwise, each half getting half the
// share. That estimate is only trusted where |C′| is smooth (see speed_is_smooth); near a cusp,
// where |C′| has a kink and both rules can agree on a wrong value, pieces are halved until the
// rigorous chord ≤ L ≤ control polygon bracket is tight enough. The bracket's width shrinks 4×
// per halving at a cusp while the share halves, so the recursion ends.
#include <algorithm>
#include <cmath>

#include "bezel/bezier.hpp"

namespace bezel {

namespace {

// Work limit: at most this many halvings per call (each costs 24 evaluations of C′). Reached
// only for accuracies near the rounding floor below; the result is then the best estimate found.
constexpr int kArclenMaxSplits = 4096;
constexpr double kPi = 3.14159265358979323846;
// Requested accuracies are raised to this fraction of the control polygon's length (an upper
// bound of the arc length): below it, rounding in summing the pieces dominates anyway.
constexpr double kArclenMinRelAccuracy = 1e-13;

// Nodes xᵢ ∈ (−1, 1) and weights wᵢ of the n-point Gauss–Legendre rule: xᵢ are the roots of the
// Legendre polynomial Pₙ, found by Newton's method from Chebyshev-like guesses
// cos(π(i + ¾)/(n + ½)), and wᵢ = 2/((1 − xᵢ²)·Pₙ′(xᵢ)²) (Abramowitz & Stegun 25.4.29).
// Pₙ comes from Bonnet's recurrence (k+1)P_{k+1} = (2k+1)x·P_k − k·P_{k−1}.
template <int N>
struct GaussLegendre {
    double x[N];
    double w[N];
    GaussLegendre() {
        for (int i = 0; i < N; ++i) {
            double z = std::cos(kPi * (i + 0.75) / (N + 0.5));
            double dp = 1.0;
            for (int iter = 0; iter < 100; ++iter) {
                double p0 = 1.0, p1 = z;
                for (int k = 1; k < N; ++k) {
                    double p2 = ((2.0 * k + 1.0) * z * p1 - k * p0) / (k + 1.0);
                    p0 = p1;
                    p1 = p2;
                }
                // Pₙ′(z) = n(z·Pₙ − Pₙ₋₁)/(z² − 1)
                dp = N * (z * p1 - p0) / (z * z - 1.0);
                double dz = p1 / dp;
                z -= dz;
                if (std::fabs(dz) <= 1e-16) break;
            }
            x[i] = z;
            w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
        }
    }
};

template <int N>
const GaussLegendre<N>& rule() {
    static const GaussLegendre<N> r;  // thread-safe one-time initialisation
    return r;
}

template <int N, class Curve>
double gauss_speed_integral(const Curve& c, double t0, double t1) {
    const GaussLegendre<N>& g = rule<N>();
    double half = 0.5 * (t1 - t0), mid = 0.5 * (t0 + t1);
    double sum = 0.0;
    for (int i = 0; i < N; ++i) sum += g.w[i] * c.deriv_at(mid + half * g.x[i]).length();
    return sum * half;
}

double polygon_length(const QuadBez& c) { return distance(c.p0, c.p1) + distance(c.p1, c.p2); }
double polygon_length(const CubicBez& c) {
    return distance(c.p0, c.p1) + distance(c.p1, c.p2) + distance(c.p2, c.p3);
}
double chord_length(const QuadBez& c) { return distance(c.p0, c.p2); }
double chord_length(const CubicBez& c) { return distance(c.p0, c.p3); }

// Is |C′| smooth enough on [t0, t1] for the Gauss rules' difference to be a trustworthy error
// estimate? Gauss–Legendre converges like ρ^(−2n), ρ the sum of the semi-axes of the largest
// ellipse (foci at the piece's ends, semi-axes relative to its half-width) in which the integrand
// is analytic. For |C′| = √(x′² + y′²) the nearest singularity (where x′² + y′² = 0 off the real
// axis) is about |C′|/|C″| away. Asking (t1 − t0)·|C″| ≤ 4·|C′| at every node puts it at least a
// quarter of the width away: δ ≥ ½, ρ ≥ ½ + √(5/4) ≈ 1.62, so the 16-point rule's error is
// below the 8-point rule's by ρ¹⁶ ≈ 2000× and their difference bounds it with room to spare.
// Near a cusp (C′ → 0) the test fails and the piece is halved instead: that is what stops the two
// rules from agreeing on a wrong answer there.
template <class Curve>
bool speed_is_smooth(const Curve& c, double t0, double t1) {
    const GaussLegendre<16>& g = rule<16>();
    double half = 0.5 * (t1 - t0), mid = 0.5 * (t0 + t1);
    auto dd = c.deriv();
    for (int i = 0; i < 16; ++i) {
        double t = mid + half * g.x[i];
        if (2.0 * half * dd.deriv_at(t).length() > 4.0 * c.deriv_at(t).length()) return false;
    }
    return true;
}

// A piece is accepted when either
//  (a) its control polygon and chord differ by ≤ 2·accuracy: the arc length lies between the
//      two (chord ≤ L by the triangle inequality; L ≤ polygon because de Casteljau subdivision
//      only shortens the polygon and converges to the curve), so their mean is within
//      `accuracy` — rigorous, and what ends the recursion at cusps;
//  (b) |C′| is smooth on it (above) and the 8- and 16-point rules differ by ≤ accuracy.
template <class Curve>
double adaptive(const Curve& c, double t0, double t1, double accuracy, int& splits_left) {
    Curve piece = c.subsegment(t0, t1);
    double poly = polygon_length(piece), chord = chord_length(piece);
    if (poly - chord <= 2.0 * accuracy) return 0.5 * (poly + chord);
    double fine = gauss_speed_integral<16>(c, t0, t1);
    if (splits_left <= 0) return fine;
    if (speed_is_smooth(c, t0, t1)) {
        double coarse = gauss_speed_integral<8>(c, t0, t1);
        if (std::fabs(fine - coarse) <= accuracy) return fine;
    }
    --splits_left;
    double tm = 0.5 * (t0 + t1);
    return adaptive(c, t0, tm, 0.5 * accuracy, splits_left) +
           adaptive(c, tm, t1, 0.5 * accuracy, splits_left);
}

template <class Curve>
double effective_accuracy(const Curve& c, double accuracy) {
    double floor = kArclenMinRelAccuracy * polygon_length(c);
    return accuracy > floor ? accuracy : floor;  // also replaces NaN and ≤ 0
}

// L(t0, t1) within `accuracy` (already floored).
template <class Curve>
double arclen_range(const Curve& c, double t0, double t1, double accuracy) {
    if (!(t1 > t0)) return 0.0;
    int splits_left = kArclenMaxSplits;
    return adaptive(c, t0, t1, accuracy, splits_left);
}

template <class Curve>
double arclen_impl(const Curve& c, double accuracy) {
    if (!c.is_finite()) return std::nan("");
    return arclen_range(c, 0.0, 1.0, effective_accuracy(c, accuracy));
}

// Solves L(0, t) = s for t. L is non-decreasing with L′(t) = |C′(t)|, so safeguarded Newton on a
// shrinking bracket [lo, hi] converges: Newton's step when it stays inside, bisection otherwise.
// Each L is computed to accuracy/2 and iteration stops at |L − s| ≤ accuracy/2, so the true
// |L(0, t) − s| ≤ accuracy.
template <class Curve>
double inv_arclen_impl(const Curve& c, double s, double accuracy) {
    if (!c.is_finite() || !(s > 0.0)) return 0.0;
    double acc = 0.5 * effective_accuracy(c, accuracy);
    double total = arclen_range(c, 0.0, 1.0, acc);
    if (!(total > 0.0)) return 0.0;  // a point: every t has length 0
    if (!(s < total)) return 1.0;
    double lo = 0.0, hi = 1.0;
    double t = s / total;
    for (int iter = 0; iter < 100; ++iter) {
        double err = arclen_range(c, 0.0, t, acc) - s;
        if (std::fabs(err) <= acc) return t;
        if (err < 0.0) lo = t; else hi = t;
        double speed = c.deriv_at(t).length();
        double tn = speed > 0.0 ? t - err / speed : lo;
        if (!(tn > lo && tn < hi)) tn = 0.5 * (lo + hi);
        if (tn == t || hi - lo <= 1e-16) return t;  // t resolved to the last bits
        t = tn;
    }
    return t;
}

}  // namespace

double Line::inv_arclen(double s, double /*accuracy*/) const {
    double len = length();
    if (!(s > 0.0) || !(len > 0.0)) return 0.0;
    if (!(s < len)) return 1.0;
    return s / len;
}

double QuadBez::arclen(double accuracy) const { return arclen_impl(*this, accuracy); }
double QuadBez::inv_arclen(double s, double accuracy) const {
    return inv_arclen_impl(*this, s, accuracy);
}
double CubicBez::arclen(double accuracy) const { return arclen_impl(*this, accuracy); }
double CubicBez::inv_arclen(double s, double accuracy) const {
    return inv_arclen_impl(*this, s, accuracy);
}

}  // namespace bezel
