// Smoothing methods: Chaikin and its limit, uniform B-splines, natural C² splines, Catmull-Rom,
// Hermite/cardinal — exact values, interpolation, continuity, and the input errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>
#include <random>
#include <string>
#include <vector>

#include "bezel/bezier.hpp"
#include "bezel/smooth.hpp"

namespace bezel {
inline void PrintTo(const Vec2& v, std::ostream* os) { *os << "(" << v.x << ", " << v.y << ")"; }
}  // namespace bezel

using namespace bezel;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// n random points in [-100, 100]², no two consecutive ones equal (probability 0 anyway).
std::vector<Point> random_points(std::mt19937_64& rng, std::size_t n) {
    std::uniform_real_distribution<double> c(-100.0, 100.0);
    std::vector<Point> p(n);
    for (Point& q : p) q = {c(rng), c(rng)};
    return p;
}

std::vector<CubicBez> cubics(const Path& path) {
    std::vector<CubicBez> out;
    for (const PathSeg& s : path.segments()) out.push_back(s.to_cubic());
    return out;
}

std::vector<Continuity> classes(const Path& path) {
    auto joints = analyze_continuity(path);
    EXPECT_TRUE(joints.ok());
    std::vector<Continuity> out;
    if (joints)
        for (const JointReport& j : *joints) out.push_back(j.continuity);
    return out;
}

// Every joint (including the closing one of a closed curve) has class `c`; the count is checked
// so that an empty report cannot pass.
void expect_all_joints(const Path& path, Continuity c, std::size_t joint_count) {
    std::vector<Continuity> cls = classes(path);
    ASSERT_EQ(cls.size(), joint_count);
    for (std::size_t i = 0; i < cls.size(); ++i)
        EXPECT_EQ(cls[i], c) << "joint " << i << " is " << continuity_name(cls[i]);
}

bool ends_closed(const Path& path) { return !path.verbs().empty() && path.verbs().back() == Verb::Close; }

// Is p inside the convex hull of q[0..3] (up to `slack` in distance)? The hull is built by
// Andrew's monotone chain; p is inside when it is on the inner side of every hull edge.
bool in_hull(Point p, const Point (&q)[4], double slack) {
    std::vector<Point> pts(q, q + 4);
    std::sort(pts.begin(), pts.end(),
              [](Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    std::vector<Point> hull;
    for (int pass = 0; pass < 2; ++pass) {
        std::size_t base = hull.size();
        for (const Point& r : pts) {
            while (hull.size() >= base + 2 &&
                   (hull[hull.size() - 1] - hull[hull.size() - 2]).cross(r - hull[hull.size() - 2]) <= 0)
                hull.pop_back();
            hull.push_back(r);
        }
        hull.pop_back();
        std::reverse(pts.begin(), pts.end());
    }
    if (hull.size() < 3) {  // degenerate hull: a segment; distance to it
        Point a = pts.front(), b = pts.back();
        Vec2 ab = b - a;
        double t = ab.length_squared() > 0 ? std::clamp((p - a).dot(ab) / ab.length_squared(), 0.0, 1.0) : 0.0;
        return distance(p, a + ab * t) <= slack;
    }
    for (std::size_t i = 0; i < hull.size(); ++i) {
        Point a = hull[i], b = hull[(i + 1) % hull.size()];
        // Counter-clockwise hull (y up): inside is to the left, cross ≥ 0.
        if ((b - a).cross(p - a) / (b - a).length() < -slack) return false;
    }
    return true;
}

// Distance from p to a quadratic Bézier: the nearest point solves (Q(t) − p)·Q′(t) = 0, a cubic
// in t; the minimum is over its roots in [0, 1] and the two ends.
double distance_to_quad(Point p, const QuadBez& q) {
    // Q(t) = A t² + B t + C with A = P0 − 2P1 + P2, B = 2(P1 − P0), C = P0.
    Vec2 A = q.p0 - q.p1 * 2.0 + q.p2, B = (q.p1 - q.p0) * 2.0, C = q.p0 - p;
    // (A t² + B t + C)·(2A t + B) = 2A·A t³ + 3A·B t² + (B·B + 2A·C) t + B·C
    double roots[3];
    int n = solve_cubic_in(2 * A.dot(A), 3 * A.dot(B), B.dot(B) + 2 * A.dot(C), B.dot(C), 0.0, 1.0,
                           roots);
    double best = std::min(distance(p, q.p0), distance(p, q.p2));
    for (int i = 0; i < n; ++i) best = std::min(best, distance(p, q.eval(roots[i])));
    return best;
}

}  // namespace

// ---- Chaikin -------------------------------------------------------------------------------------

TEST(Chaikin, OneRoundCutsEachEdgeAtAQuarterAndThreeQuarters) {
    std::vector<Point> square{{0, 0}, {8, 0}, {8, 8}, {0, 8}};
    auto closed = chaikin(square, 1, {/*closed=*/true});
    ASSERT_TRUE(closed.ok()) << closed.error().message;
    std::vector<Point> expected{{2, 0}, {6, 0}, {8, 2}, {8, 6}, {6, 8}, {2, 8}, {0, 6}, {0, 2}};
    EXPECT_EQ(*closed, expected);

    auto open = chaikin(square, 1, {/*closed=*/false, /*keep_ends=*/true});
    ASSERT_TRUE(open.ok());
    std::vector<Point> expected_open{{0, 0}, {2, 0}, {6, 0}, {8, 2}, {8, 6}, {6, 8}, {2, 8}, {0, 8}};
    EXPECT_EQ(*open, expected_open);

    auto cut = chaikin(square, 1, {/*closed=*/false, /*keep_ends=*/false});
    ASSERT_TRUE(cut.ok());
    EXPECT_EQ(*cut, std::vector<Point>(expected_open.begin() + 1, expected_open.end() - 1));
}

// closed n → 2n; open n → 2(n − 1), plus the two kept ends.
TEST(Chaikin, PointCountsFollowTheDoublingRule) {
    std::mt19937_64 rng(61);
    for (std::size_t n = 3; n <= 9; ++n) {
        std::vector<Point> p = random_points(rng, n);
        for (int k = 0; k <= 6; ++k) {
            std::size_t closed_count = n, kept = n, cut = n;
            for (int i = 0; i < k; ++i) {
                closed_count *= 2;
                kept = 2 * (kept - 1) + 2;
                cut = 2 * (cut - 1);
            }
            auto a = chaikin(p, k, {true});
            auto b = chaikin(p, k, {false, true});
            auto c = chaikin(p, k, {false, false});
            ASSERT_TRUE(a.ok() && b.ok() && c.ok());
            EXPECT_EQ(a->size(), closed_count) << "n=" << n << " k=" << k;
            EXPECT_EQ(b->size(), kept) << "n=" << n << " k=" << k;
            EXPECT_EQ(b->size(), n << k);
            EXPECT_EQ(c->size(), cut) << "n=" << n << " k=" << k;
            EXPECT_EQ(c->size(), ((n - 2) << k) + 2);
            EXPECT_EQ(b->front(), p.front());
            EXPECT_EQ(b->back(), p.back());
        }
    }
}

// Closed polygons: vertex j after k rounds is the control point at knot u = ½ + (j − ½)/2^k of
// the same quadratic B-spline (each round maps knot x to x/2 + ¼), and its distance to the curve
// point C(u) — the middle of its piece — is |Pⱼ₋₁ − 2Pⱼ + Pⱼ₊₁|/8. A round divides every second
// difference by exactly 4 (¼Pᵢ − ½Pᵢ₊₁ + ¼Pᵢ₊₂ at both new vertices), so the largest distance
// shrinks 4× per round: checked to 1e-9 relative on 50 random polygons, rounds 1 to 8 (by
// then the distance is ~1e-4 of the coordinates, so rounding is still far below 1e-9 of it).
TEST(Chaikin, ClosedPolygonApproachesItsLimitExactlyFourTimesPerRound) {
    std::mt19937_64 rng(62);
    for (int trial = 0; trial < 50; ++trial) {
        const std::size_t n = 3 + trial % 6;
        std::vector<Point> p = random_points(rng, n);
        auto limit = chaikin_limit(p, {true});
        ASSERT_TRUE(limit.ok());
        std::vector<QuadBez> pieces;
        for (const PathSeg& s : limit->segments()) pieces.push_back(s.as_quad());
        ASSERT_EQ(pieces.size(), n);
        // Piece i covers knots [i − ½, i + ½].
        auto curve = [&](double u) {
            double w = u + 0.5;
            double i = std::floor(w);
            std::size_t piece = static_cast<std::size_t>(i) % n;
            return pieces[piece].eval(w - i);
        };
        double previous = 0.0;
        for (int k = 0; k <= 8; ++k) {
            auto poly = chaikin(p, k, {true});
            ASSERT_TRUE(poly.ok());
            double worst = 0.0, scale = std::ldexp(1.0, -k);
            for (std::size_t j = 0; j < poly->size(); ++j) {
                double u = 0.5 + (static_cast<double>(j) - 0.5) * scale;
                worst = std::max(worst, distance((*poly)[j], curve(u)));
            }
            if (k > 0) {
                EXPECT_NEAR(previous / worst, 4.0, 4.0 * 1e-9) << "trial " << trial << " k " << k;
            }
            previous = worst;
        }
    }
}

// Open polygons with kept ends: the largest distance from a vertex to the limit curve (exact
// nearest points) falls by 4³ = 64 every three rounds, within a factor 2 either way (the worst
// vertex moves around between rounds, so single rounds vary more; a 2× or 8× rate would give 8
// or 512), over 40 random polygons.
TEST(Chaikin, OpenPolygonApproachesItsLimitAboutFourTimesPerRound) {
    std::mt19937_64 rng(62);
    for (int trial = 0; trial < 40; ++trial) {
        std::vector<Point> p = random_points(rng, 4 + trial % 5);
        auto limit = chaikin_limit(p, {false, true});
        ASSERT_TRUE(limit.ok());
        std::vector<QuadBez> pieces;
        for (const PathSeg& s : limit->segments()) pieces.push_back(s.as_quad());
        std::vector<double> dist;
        for (int k = 0; k <= 8; ++k) {
            auto poly = chaikin(p, k, {false, true});
            ASSERT_TRUE(poly.ok());
            double worst = 0.0;
            for (const Point& v : *poly) {
                double d = HUGE_VAL;
                for (const QuadBez& q : pieces) d = std::min(d, distance_to_quad(v, q));
                worst = std::max(worst, d);
            }
            dist.push_back(worst);
        }
        for (int k = 3; k + 3 <= 8; ++k) {
            double ratio = dist[static_cast<std::size_t>(k)] / dist[static_cast<std::size_t>(k + 3)];
            EXPECT_GE(ratio, 64.0 / 2) << "trial " << trial << " k " << k;
            EXPECT_LE(ratio, 64.0 * 2) << "trial " << trial << " k " << k;
        }
    }
}

TEST(ChaikinLimit, IsTheQuadraticBSplineThroughEdgeMidpoints) {
    std::vector<Point> tri{{0, 0}, {4, 0}, {0, 4}};
    auto closed = chaikin_limit(tri, {true});
    ASSERT_TRUE(closed.ok());
    // M(0,2) Q(0,0)(2,0) Q(4,0)(2,2) Q(0,4)(0,2) Z
    Path expected;
    expected.move_to({0, 2});
    expected.quad_to({0, 0}, {2, 0});
    expected.quad_to({4, 0}, {2, 2});
    expected.quad_to({0, 4}, {0, 2});
    expected.close();
    EXPECT_EQ(*closed, expected);

    auto open = chaikin_limit(tri, {false, true});
    ASSERT_TRUE(open.ok());
    Path expected_open;
    expected_open.move_to({0, 0});
    expected_open.quad_to({0, 0}, {2, 0});
    expected_open.quad_to({4, 0}, {2, 2});
    expected_open.quad_to({0, 4}, {0, 4});
    EXPECT_EQ(*open, expected_open);

    auto cut = chaikin_limit(tri, {false, false});
    ASSERT_TRUE(cut.ok());
    Path expected_cut;
    expected_cut.move_to({2, 0});
    expected_cut.quad_to({4, 0}, {2, 2});
    EXPECT_EQ(*cut, expected_cut);
}

TEST(ChaikinLimit, IsC1AtEveryJointIncludingTheClosingOne) {
    std::mt19937_64 rng(63);
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<Point> p = random_points(rng, 3 + trial % 8);
        auto closed = chaikin_limit(p, {true});
        ASSERT_TRUE(closed.ok());
        EXPECT_TRUE(ends_closed(*closed));
        expect_all_joints(*closed, Continuity::C1, p.size());
        auto open = chaikin_limit(p, {false, true});
        ASSERT_TRUE(open.ok());
        expect_all_joints(*open, Continuity::C1, p.size() - 1);
    }
}

// ---- Uniform cubic B-spline ------------------------------------------------------------------

TEST(BSpline, IsC2AtEveryJointOpenPinnedUnpinnedAndClosed) {
    std::mt19937_64 rng(64);
    for (int trial = 0; trial < 500; ++trial) {
        std::vector<Point> p = random_points(rng, 4 + trial % 12);
        const std::size_t n = p.size();
        auto pinned = bspline(p, {false, true});
        auto free_ends = bspline(p, {false, false});
        auto closed = bspline(p, {true});
        ASSERT_TRUE(pinned.ok() && free_ends.ok() && closed.ok());
        expect_all_joints(*pinned, Continuity::C2, n);          // n + 1 pieces
        expect_all_joints(*free_ends, Continuity::C2, n - 4);   // n − 3 pieces
        expect_all_joints(*closed, Continuity::C2, n);          // n pieces, closing joint too
        EXPECT_TRUE(ends_closed(*closed));
        // Pinned: starts and ends exactly on the end points.
        EXPECT_EQ(pinned->points().front(), p.front());
        EXPECT_EQ(pinned->points().back(), p.back());
    }
}

// Each Bézier piece equals the matrix form T·M_B·G of its four de Boor points (1e-12 relative
// to the coordinates) and lies in their convex hull: control points and 33 curve samples.
TEST(BSpline, PiecesMatchTheMatrixFormAndStayInTheirDeBoorHull) {
    std::mt19937_64 rng(65);
    for (int trial = 0; trial < 1000; ++trial) {
        std::vector<Point> p = random_points(rng, 3 + trial % 10);
        auto closed = bspline(p, {true});
        ASSERT_TRUE(closed.ok());
        std::vector<CubicBez> pieces = cubics(*closed);
        ASSERT_EQ(pieces.size(), p.size());
        const std::size_t n = p.size();
        for (std::size_t j = 0; j < n; ++j) {
            const Point g[4] = {p[j], p[(j + 1) % n], p[(j + 2) % n], p[(j + 3) % n]};
            const CubicBez& c = pieces[j];
            for (int s = 0; s <= 32; ++s) {
                double t = s / 32.0;
                Point q = c.eval(t);
                EXPECT_LE(distance(q, basis::eval_matrix(basis::kBSpline, g, t)), 1e-12 * 100)
                    << "trial " << trial << " piece " << j << " t " << t;
                EXPECT_TRUE(in_hull(q, g, 1e-12 * 100)) << "trial " << trial << " piece " << j;
            }
            for (Point q : {c.p0, c.p1, c.p2, c.p3})
                EXPECT_TRUE(in_hull(q, g, 1e-12 * 100)) << "trial " << trial << " piece " << j;
        }
    }
}

TEST(BSpline, TwoPinnedPointsGiveTheStraightSegment) {
    auto line = bspline({{0, 0}, {6, 0}}, {false, true});
    ASSERT_TRUE(line.ok());
    ASSERT_EQ(line->segment_count(), 3u);
    for (const PathSeg& s : line->segments())
        for (const Point& q : s.p) EXPECT_EQ(q.y, 0.0);
    EXPECT_EQ(line->points().back(), (Point{6, 0}));
}

// ---- Natural spline -------------------------------------------------------------------------

// (0,0) (1,1) (2,0), uniform: D = (1, 1.5), (1, 0), (1, −1.5) solve 2D₀ + D₁ = 3(C₁ − C₀),
// D₀ + 4D₁ + D₂ = 3(C₂ − C₀), D₁ + 2D₂ = 3(C₂ − C₁); pieces are Hermite with those tangents.
TEST(NaturalSpline, ThreePointExampleHasTheHandSolvedDerivatives) {
    auto s = natural_spline({{0, 0}, {1, 1}, {2, 0}});
    ASSERT_TRUE(s.ok()) << s.error().message;
    std::vector<CubicBez> c = cubics(*s);
    ASSERT_EQ(c.size(), 2u);
    const double tol = 1e-15;
    EXPECT_NEAR(c[0].p1.x, 1.0 / 3, tol);
    EXPECT_NEAR(c[0].p1.y, 0.5, tol);
    EXPECT_NEAR(c[0].p2.x, 2.0 / 3, tol);
    EXPECT_NEAR(c[0].p2.y, 1.0, tol);
    EXPECT_NEAR(c[1].p1.x, 4.0 / 3, tol);
    EXPECT_NEAR(c[1].p1.y, 1.0, tol);
    EXPECT_NEAR(c[1].p2.x, 5.0 / 3, tol);
    EXPECT_NEAR(c[1].p2.y, 0.5, tol);
}

// Through every point (to 1e-12: the piece ends ARE the input points), C² at every joint
// (1e-9 relative), zero second derivative at both natural ends (1e-9 of the pieces' size).
TEST(NaturalSpline, InterpolatesIsC2AndHasZeroCurvatureAtTheEnds) {
    std::mt19937_64 rng(66);
    for (int trial = 0; trial < 1000; ++trial) {
        std::vector<Point> p = random_points(rng, 2 + trial % 30);
        auto s = natural_spline(p);
        ASSERT_TRUE(s.ok()) << s.error().message;
        std::vector<CubicBez> c = cubics(*s);
        ASSERT_EQ(c.size(), p.size() - 1);
        for (std::size_t i = 0; i < c.size(); ++i) {
            EXPECT_LE(distance(c[i].p0, p[i]), 1e-12);
            EXPECT_LE(distance(c[i].p3, p[i + 1]), 1e-12);
        }
        if (p.size() > 2) expect_all_joints(*s, Continuity::C2, p.size() - 2);
        auto size = [](const CubicBez& b) {
            Rect r = b.control_box();
            return std::hypot(r.width(), r.height());
        };
        EXPECT_LE(c.front().deriv2_at(0.0).length(), 1e-9 * size(c.front())) << "trial " << trial;
        EXPECT_LE(c.back().deriv2_at(1.0).length(), 1e-9 * size(c.back())) << "trial " << trial;
    }
}

// Chord length: C² in the knot parameter u, i.e. A″(1)/h_A² = B″(0)/h_B² and A′(1)/h_A = B′(0)/h_B
// with h the chord of each piece, while the pieces' own parameters make it G1 only.
TEST(NaturalSpline, ChordLengthIsC2InTheKnotParameter) {
    std::mt19937_64 rng(67);
    for (int trial = 0; trial < 1000; ++trial) {
        std::vector<Point> p = random_points(rng, 3 + trial % 20);
        bool closed = trial % 2 == 1;
        auto s = natural_spline(p, {closed, SplineParam::ChordLength});
        ASSERT_TRUE(s.ok()) << s.error().message;
        std::vector<CubicBez> c = cubics(*s);
        const std::size_t n = c.size();
        ASSERT_EQ(n, closed ? p.size() : p.size() - 1);
        const std::size_t joints = closed ? n : n - 1;
        for (std::size_t i = 0; i < joints; ++i) {
            const CubicBez& a = c[i];
            const CubicBez& b = c[(i + 1) % n];
            double ha = distance(a.p0, a.p3), hb = distance(b.p0, b.p3);
            Vec2 d1a = a.deriv_at(1.0) / ha, d1b = b.deriv_at(0.0) / hb;
            Vec2 d2a = a.deriv2_at(1.0) / (ha * ha), d2b = b.deriv2_at(0.0) / (hb * hb);
            double s1 = std::max({d1a.length(), d1b.length(), 1.0});
            double s2 = std::max({d2a.length(), d2b.length(), 1.0 / std::min(ha, hb)});
            EXPECT_LE((d1a - d1b).length(), 1e-9 * s1) << "trial " << trial << " joint " << i;
            EXPECT_LE((d2a - d2b).length(), 1e-9 * s2) << "trial " << trial << " joint " << i;
        }
        std::vector<Continuity> cls = classes(*s);
        ASSERT_EQ(cls.size(), joints);
        for (Continuity k : cls) EXPECT_GE(k, Continuity::G1);
    }
}

TEST(NaturalSpline, ClosedCurveClosesC2) {
    std::mt19937_64 rng(68);
    for (int trial = 0; trial < 500; ++trial) {
        std::vector<Point> p = random_points(rng, 3 + trial % 25);
        auto s = natural_spline(p, {true, SplineParam::Uniform});
        ASSERT_TRUE(s.ok()) << s.error().message;
        EXPECT_TRUE(ends_closed(*s));
        EXPECT_EQ(s->points().back(), p.front());
        expect_all_joints(*s, Continuity::C2, p.size());
    }
}

TEST(NaturalSpline, TwoPointsGiveTheStraightSegment) {
    auto s = natural_spline({{1, 1}, {4, 7}});
    ASSERT_TRUE(s.ok());
    std::vector<CubicBez> c = cubics(*s);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_NEAR(c[0].p1.x, 2.0, 1e-15);
    EXPECT_NEAR(c[0].p1.y, 3.0, 1e-15);
    EXPECT_NEAR(c[0].p2.x, 3.0, 1e-15);
    EXPECT_NEAR(c[0].p2.y, 5.0, 1e-15);
}

// ---- Catmull-Rom ---------------------------------------------------------------------------

// α = 0 is the matrix form T·M_CR(τ)·G of basis::catmull_rom for every interior piece.
TEST(CatmullRom, UniformMatchesTheCardinalBasisMatrix) {
    std::mt19937_64 rng(69);
    std::uniform_real_distribution<double> tension(0.0, 1.5);
    for (int trial = 0; trial < 500; ++trial) {
        std::vector<Point> p = random_points(rng, 4 + trial % 8);
        double tau = tension(rng);
        auto s = catmull_rom(p, {false, kCatmullRomUniform, tau});
        ASSERT_TRUE(s.ok());
        std::vector<CubicBez> c = cubics(*s);
        ASSERT_EQ(c.size(), p.size() - 1);
        basis::Mat4 m = basis::catmull_rom(tau);
        for (std::size_t i = 1; i + 2 < p.size(); ++i) {
            const Point g[4] = {p[i - 1], p[i], p[i + 1], p[i + 2]};
            for (int k = 0; k <= 16; ++k) {
                double t = k / 16.0;
                EXPECT_LE(distance(c[i].eval(t), basis::eval_matrix(m, g, t)), 1e-12 * 100);
            }
        }
    }
}

TEST(CatmullRom, InterpolatesEveryPointForEveryAlphaAndTension) {
    std::mt19937_64 rng(70);
    for (int trial = 0; trial < 600; ++trial) {
        std::vector<Point> p = random_points(rng, 2 + trial % 12);
        for (double alpha : {0.0, 0.25, 0.5, 1.0}) {
            for (bool closed : {false, true}) {
                if (closed && p.size() < 3) continue;
                auto s = catmull_rom(p, {closed, alpha, 0.5 + (trial % 5) * 0.1});
                ASSERT_TRUE(s.ok()) << s.error().message;
                std::vector<CubicBez> c = cubics(*s);
                ASSERT_EQ(c.size(), closed ? p.size() : p.size() - 1);
                for (std::size_t i = 0; i < c.size(); ++i) {
                    EXPECT_EQ(c[i].p0, p[i]);
                    EXPECT_EQ(c[i].p3, p[(i + 1) % p.size()]);
                }
            }
        }
    }
}

// Closed loops close with the continuity each parametrisation promises: C1 uniform, G1 otherwise.
TEST(CatmullRom, ClosedLoopsCloseC1UniformAndG1Centripetal) {
    std::mt19937_64 rng(71);
    for (int trial = 0; trial < 300; ++trial) {
        std::vector<Point> p = random_points(rng, 3 + trial % 10);
        auto uniform = catmull_rom(p, {true, kCatmullRomUniform});
        auto centripetal = catmull_rom(p, {true, kCatmullRomCentripetal});
        ASSERT_TRUE(uniform.ok() && centripetal.ok());
        EXPECT_TRUE(ends_closed(*uniform));
        std::vector<Continuity> u = classes(*uniform), c = classes(*centripetal);
        ASSERT_EQ(u.size(), p.size());
        ASSERT_EQ(c.size(), p.size());
        for (std::size_t i = 0; i < u.size(); ++i) {
            EXPECT_GE(u[i], Continuity::C1) << "trial " << trial << " joint " << i;
            EXPECT_GE(c[i], Continuity::G1) << "trial " << trial << " joint " << i;
        }
    }
}

namespace {

// Does the cubic cross itself, or have a cusp, at parameters within [0, 1]? Exact test from the
// power form C(t) = a t³ + b t² + c t + d: C(s) = C(t) with s ≠ t means
//     a(s² + st + t²) + b(s + t) + c = 0,
// two equations in σ = s + t and π = st. Crossing them eliminates σ² − π: (a × b)σ + a × c = 0,
// then σ² − π = −(bσ + c)·a/|a|², and s, t are the roots of x² − σx + π. A double root (σ² = 4π)
// is a cusp, C′ = 0. `margin` widens the test (parameters, dimensionless) so that near-misses
// count too.
bool loops_or_cusps(const CubicBez& c, double margin) {
    Vec2 a = c.p3 - c.p0 + (c.p1 - c.p2) * 3.0;
    Vec2 b = (c.p0 - c.p1 * 2.0 + c.p2) * 3.0;
    Vec2 k = (c.p1 - c.p0) * 3.0;
    double axb = a.cross(b);
    if (axb == 0.0) return false;  // no cubic term in some direction: no loop (collinear aside)
    double sigma = -a.cross(k) / axb;
    double pi = sigma * sigma + (b * sigma + k).dot(a) / a.dot(a);
    double disc = sigma * sigma - 4.0 * pi;
    if (disc < -margin) return false;
    double r = std::sqrt(std::max(disc, 0.0));
    return (sigma - r) / 2 >= -margin && (sigma + r) / 2 <= 1.0 + margin;
}

}  // namespace

TEST(CatmullRom, LoopDetectorFindsAKnownLoopAndAKnownCusp) {
    EXPECT_TRUE(loops_or_cusps({{0, 0}, {3, 2}, {-2, 2}, {1, 0}}, 0.0));  // crossing polygon
    // C′(½) = 3[¼(1,1) + ½(−1,0) + ¼(1,−1)] = 0.
    EXPECT_TRUE(loops_or_cusps({{0, 0}, {1, 1}, {0, 1}, {1, 0}}, 1e-12));
    EXPECT_FALSE(loops_or_cusps({{0, 0}, {1, 1}, {2, 1}, {3, 0}}, 1e-9));  // an arch
}

// Yuksel et al.: centripetal pieces have no cusp and no self-intersection. 20000 random
// quadruples, checked with a 1e-9 margin in parameter space; the same data gives uniform
// Catmull-Rom hundreds of loops, so the check has teeth.
TEST(CatmullRom, CentripetalHasNoCuspOrLoopOnRandomQuadruples) {
    std::mt19937_64 rng(72);
    int uniform_loops = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        std::vector<Point> q = random_points(rng, 4);
        auto centripetal = catmull_rom(q, {false, kCatmullRomCentripetal});
        auto uniform = catmull_rom(q, {false, kCatmullRomUniform});
        ASSERT_TRUE(centripetal.ok() && uniform.ok());
        // The middle piece, P₁ → P₂, has real neighbours on both sides.
        EXPECT_FALSE(loops_or_cusps(centripetal->segment(1).as_cubic(), 1e-9)) << "trial " << trial;
        uniform_loops += loops_or_cusps(uniform->segment(1).as_cubic(), 0.0);
    }
    EXPECT_GT(uniform_loops, 20);
}

// Repeated consecutive points are merged: the curve is the one through the distinct points.
TEST(CatmullRom, RepeatedPointsAreMerged) {
    std::vector<Point> p{{0, 0}, {0, 0}, {5, 5}, {10, 0}, {10, 0}, {10, 0}, {15, 5}};
    std::vector<Point> distinct{{0, 0}, {5, 5}, {10, 0}, {15, 5}};
    for (double alpha : {0.0, 0.5, 1.0}) {
        auto a = catmull_rom(p, {false, alpha});
        auto b = catmull_rom(distinct, {false, alpha});
        ASSERT_TRUE(a.ok() && b.ok()) << a.error().message;
        EXPECT_EQ(*a, *b);
        EXPECT_TRUE(a->is_finite());
    }
    auto closed = catmull_rom({{0, 0}, {4, 0}, {4, 0}, {0, 4}, {0, 0}}, {true});
    ASSERT_TRUE(closed.ok());
    EXPECT_EQ(closed->segment_count(), 3u);
}

TEST(CatmullRom, ZeroTensionGivesStraightPieces) {
    auto s = catmull_rom({{0, 0}, {3, 4}, {6, 0}, {9, 4}}, {false, kCatmullRomCentripetal, 0.0});
    ASSERT_TRUE(s.ok());
    for (const PathSeg& seg : s->segments()) {
        CubicBez c = seg.as_cubic();
        EXPECT_EQ(c.p1, c.p0);
        EXPECT_EQ(c.p2, c.p3);
    }
}

// ---- Hermite and cardinal ---------------------------------------------------------------------

// Each piece is the matrix form T·M_H·[P₀ P₁ T₀ T₁]ᵀ.
TEST(Hermite, PiecesMatchTheHermiteBasisMatrix) {
    std::mt19937_64 rng(73);
    for (int trial = 0; trial < 500; ++trial) {
        std::vector<Point> p = random_points(rng, 2 + trial % 8);
        std::vector<Vec2> t = random_points(rng, p.size());
        auto s = hermite(p, t, false);
        ASSERT_TRUE(s.ok()) << s.error().message;
        std::vector<CubicBez> c = cubics(*s);
        ASSERT_EQ(c.size(), p.size() - 1);
        for (std::size_t i = 0; i < c.size(); ++i) {
            const Point g[4] = {p[i], p[i + 1], t[i], t[i + 1]};
            for (int k = 0; k <= 16; ++k) {
                double u = k / 16.0;
                EXPECT_LE(distance(c[i].eval(u), basis::eval_matrix(basis::kHermite, g, u)), 1e-12 * 300);
            }
            EXPECT_LE((c[i].deriv_at(0.0) - t[i]).length(), 1e-12 * 300);
            EXPECT_LE((c[i].deriv_at(1.0) - t[i + 1]).length(), 1e-12 * 300);
        }
    }
}

TEST(Hermite, ClosedCurveClosesC1) {
    std::mt19937_64 rng(74);
    for (int trial = 0; trial < 300; ++trial) {
        std::vector<Point> p = random_points(rng, 3 + trial % 8);
        std::vector<Vec2> t = random_points(rng, p.size());
        auto s = hermite(p, t, true);
        ASSERT_TRUE(s.ok());
        EXPECT_TRUE(ends_closed(*s));
        std::vector<Continuity> cls = classes(*s);
        ASSERT_EQ(cls.size(), p.size());
        for (Continuity c : cls) EXPECT_GE(c, Continuity::C1);
    }
}

// The cardinal spline is uniform Catmull-Rom through hermite(): the same cubics, bit for bit.
TEST(Hermite, CardinalSplineIsUniformCatmullRom) {
    std::mt19937_64 rng(75);
    for (int trial = 0; trial < 300; ++trial) {
        std::vector<Point> p = random_points(rng, 3 + trial % 8);
        double tau = 0.1 * (trial % 11);
        for (bool closed : {false, true}) {
            auto a = cardinal_spline(p, tau, closed);
            auto b = catmull_rom(p, {closed, kCatmullRomUniform, tau});
            ASSERT_TRUE(a.ok() && b.ok());
            EXPECT_EQ(*a, *b) << "trial " << trial;
        }
    }
    auto t = cardinal_tangents({{0, 0}, {2, 0}, {2, 2}}, 0.5, false);
    ASSERT_TRUE(t.ok());
    std::vector<Vec2> expected{{2, 0}, {1, 1}, {0, 2}};  // ends: τ·2(P₁ − P₀), τ·2(P₂ − P₁)
    EXPECT_EQ(*t, expected);
}

// ---- Degenerate input ------------------------------------------------------------------------

namespace {
template <typename T>
void expect_error(const Expected<T>& r, const std::string& needle) {
    ASSERT_FALSE(r.ok()) << "expected an error containing '" << needle << "'";
    EXPECT_NE(r.error().message.find(needle), std::string::npos) << r.error().message;
}
}  // namespace

TEST(SmoothErrors, TooFewPointsNameTheMethodAndTheCount) {
    std::vector<Point> one{{1, 2}}, two{{0, 0}, {1, 1}};
    expect_error(chaikin(one, 2), "chaikin: 1 point, at least 2 needed");
    expect_error(chaikin(two, 2, {true}), "chaikin: 2 points in a closed curve, at least 3 needed");
    expect_error(chaikin_limit(two, {false, false}), "at least 3 needed");
    expect_error(bspline(one), "b-spline: 1 point");
    expect_error(bspline({{0, 0}, {1, 0}, {2, 1}}, {false, false}), "at least 4 needed");
    expect_error(natural_spline({}), "natural spline: 0 points");
    expect_error(natural_spline(two, {true}), "at least 3 needed");
    expect_error(catmull_rom(one), "catmull-rom: 1 point");
    expect_error(hermite(one, {{1, 0}}), "hermite: 1 point");
    // A closing duplicate does not count: a "triangle" (0,0) (1,1) (0,0) is two points.
    expect_error(natural_spline({{0, 0}, {1, 1}, {0, 0}}, {true}), "2 points in a closed curve");
}

TEST(SmoothErrors, NonFinitePointsAreNamedByIndex) {
    std::vector<Point> p{{0, 0}, {1, 1}, {2, kNaN}, {3, 0}};
    expect_error(chaikin(p, 1), "chaikin: points[2] is not finite");
    expect_error(chaikin_limit(p), "points[2] is not finite");
    expect_error(bspline(p), "b-spline: points[2] is not finite");
    expect_error(natural_spline(p), "natural spline: points[2] is not finite");
    expect_error(catmull_rom(p), "catmull-rom: points[2] is not finite");
    expect_error(hermite(p, std::vector<Vec2>(4, Vec2{1, 0})), "hermite: points[2] is not finite");
    std::vector<Point> inf{{0, 0}, {HUGE_VAL, 1}};
    expect_error(natural_spline(inf), "points[1] is not finite");
    expect_error(bspline({{0, 0}, {0x1p101, 0}}), "points[1] (2.5353012004564588e+30, 0) exceeds");
    std::vector<Vec2> bad_t{{1, 0}, {0, kNaN}};
    expect_error(hermite({{0, 0}, {1, 1}}, bad_t), "tangents[1] is not finite");
}

TEST(SmoothErrors, RepeatedAndCoincidentPoints) {
    // Natural splines reject a point repeated in a row, naming both indices.
    expect_error(natural_spline({{0, 0}, {1, 1}, {1, 1}, {2, 0}}),
                 "natural spline: points[1] and points[2] are both (1, 1)");
    expect_error(natural_spline({{0, 0}, {1, 1}, {1, 1}, {2, 0}}, {false, SplineParam::ChordLength}),
                 "points[1] and points[2]");
    // Every method rejects points that all coincide.
    std::vector<Point> same(5, Point{3, 3});
    expect_error(chaikin(same, 1), "all 5 points are (3, 3)");
    expect_error(bspline(same), "there is no curve");
    expect_error(catmull_rom(same), "there is no curve");
    expect_error(hermite(same, std::vector<Vec2>(5, Vec2{1, 0})), "there is no curve");
    // Catmull-Rom merges repeats, then needs enough distinct points.
    expect_error(catmull_rom({{0, 0}, {0, 0}, {1, 1}, {1, 1}, {0, 0}}, {true}),
                 "2 distinct points after merging repeats, at least 3 needed");
    // Chaikin, B-splines and Hermite curves accept repeats.
    std::vector<Point> rep{{0, 0}, {1, 1}, {1, 1}, {2, 0}};
    EXPECT_TRUE(chaikin(rep, 3).ok());
    EXPECT_TRUE(bspline(rep).ok());
    EXPECT_TRUE(hermite(rep, std::vector<Vec2>(4, Vec2{1, 0})).ok());
}

TEST(SmoothErrors, OptionsOutOfRange) {
    std::vector<Point> p{{0, 0}, {1, 1}, {2, 0}};
    expect_error(chaikin(p, -1), "chaikin: iterations -1 out of range 0..24");
    expect_error(chaikin(p, kMaxChaikinIterations + 1), "out of range");
    expect_error(chaikin(p, 21), "would give more than 4194304 points");  // 3·2^21 ≈ 6.3 Mi
    auto at_wall = chaikin(p, 20);  // 3·2^20 ≈ 3.1 Mi points: under the wall
    ASSERT_TRUE(at_wall.ok());
    EXPECT_EQ(at_wall->size(), std::size_t{3} << 20);
    expect_error(catmull_rom(p, {false, -0.1}), "catmull-rom: alpha -0.1");
    expect_error(catmull_rom(p, {false, 1.5}), "out of range [0, 1]");
    expect_error(catmull_rom(p, {false, 0.5, kNaN}), "tension");
    expect_error(catmull_rom(p, {false, 0.5, -1.0}), "tension");
    expect_error(cardinal_tangents(p, -1.0), "cardinal spline: tension");
    expect_error(hermite(p, {{1, 0}}), "hermite: 3 points but 1 tangents");
}

TEST(SmoothErrors, TooManyPointsIsRefusedBeforeAnyWork) {
    std::vector<Point> many(kMaxSmoothPoints + 1, Point{0, 0});
    many[1] = {1, 1};
    expect_error(natural_spline(many), "1048577 points, more than the 1048576 allowed");
    expect_error(chaikin(many, 0), "more than the 1048576 allowed");
}

// Points spaced 1e-300 and 1e30 apart overflow the chord-length spans' ratio: an error.
TEST(SmoothErrors, ExtremeSpacingOverflowIsAnErrorNotANaNPath) {
    auto s = natural_spline({{0, 0}, {1e-300, 0}, {1e30, 1e30}, {0, 1e30}},
                            {false, SplineParam::ChordLength});
    expect_error(s, "natural spline: ");
}

// Random small inputs salted with NaN, infinities, huge values and repeats: every call either
// fails with a message or returns a finite path — never a crash, a hang or a NaN curve.
TEST(SmoothErrors, HostileInputNeverCrashesOrYieldsNonFinitePaths) {
    std::mt19937_64 rng(76);
    const double specials[] = {kNaN, HUGE_VAL, -HUGE_VAL, 1e308, -1e308, 1e30, -1e30, 1e-310};
    std::uniform_int_distribution<int> size(0, 7), pick(0, 7), coin(0, 3);
    // 1e30 is within kMaxSmoothCoordinate: such inputs must succeed with a finite curve.
    std::uniform_real_distribution<double> c(-10, 10);
    int ok = 0, failed = 0;
    for (int trial = 0; trial < 5000; ++trial) {
        std::vector<Point> p(static_cast<std::size_t>(size(rng)));
        for (Point& q : p) {
            q = {c(rng), c(rng)};
            if (coin(rng) == 0) q.x = specials[pick(rng)];
            if (coin(rng) == 0 && &q != &p.front()) q = *(&q - 1);
        }
        std::vector<Vec2> t(p.size(), Vec2{1, 0});
        bool closed = coin(rng) == 0;
        auto check = [&](const Expected<Path>& r) {
            if (r.ok()) {
                ++ok;
                EXPECT_TRUE(r->is_finite()) << "trial " << trial;
            } else {
                ++failed;
                EXPECT_FALSE(r.error().message.empty());
            }
        };
        check(chaikin_limit(p, {closed}));
        check(bspline(p, {closed}));
        check(natural_spline(p, {closed, SplineParam::Uniform}));
        check(natural_spline(p, {closed, SplineParam::ChordLength}));
        check(catmull_rom(p, {closed, kCatmullRomCentripetal}));
        check(catmull_rom(p, {closed, kCatmullRomUniform}));
        check(hermite(p, t, closed));
        auto poly = chaikin(p, 3, {closed});
        if (poly) {
            for (const Point& q : *poly) EXPECT_TRUE(q.is_finite());
        }
    }
    EXPECT_GT(ok, 1000);
    EXPECT_GT(failed, 1000);
}
