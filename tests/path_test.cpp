// Path model: builder, segment iteration with stable indices, transform, boxes, reverse, area.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <ostream>
#include <random>
#include <vector>

#include "bezel/path.hpp"

// gtest prints points readably instead of as bytes.
namespace bezel {
inline void PrintTo(const Vec2& v, std::ostream* os) { *os << "(" << v.x << ", " << v.y << ")"; }
}  // namespace bezel

using namespace bezel;

namespace {

// A random path of 1–4 contours mixing every verb, some closed, some ending back at their start
// (so that the closing-segment rule is exercised both ways), coordinates in [-100, 100].
Path random_path(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> coord(-100.0, 100.0);
    std::uniform_int_distribution<int> verb(0, 2), count(1, 6), contours(1, 4), coin(0, 3);
    auto pt = [&] { return Point{coord(rng), coord(rng)}; };
    Path p;
    int nc = contours(rng);
    for (int c = 0; c < nc; ++c) {
        Point start = pt();
        p.move_to(start);
        int n = count(rng);
        for (int i = 0; i < n; ++i) {
            // Sometimes end the contour exactly at its start.
            Point end = (i == n - 1 && coin(rng) == 0) ? start : pt();
            switch (verb(rng)) {
                case 0: p.line_to(end); break;
                case 1: p.quad_to(pt(), end); break;
                default: p.cubic_to(pt(), pt(), end); break;
            }
        }
        if (coin(rng) != 0) p.close();
    }
    return p;
}

bool bitwise_equal(const Path& a, const Path& b) {
    return a.verbs() == b.verbs() && a.points().size() == b.points().size() &&
           (a.points().empty() ||
            std::memcmp(a.points().data(), b.points().data(), a.points().size() * sizeof(Point)) == 0);
}

// ½∫ B(t) × B′(t) dt by 5-point Gauss–Legendre quadrature, exact for polynomials of degree ≤ 9
// (B × B′ of a cubic has degree 5). Independent of the closed forms in the library.
double quadrature_area(const PathSeg& s, Point origin) {
    static const double x[5] = {-0.9061798459386640, -0.5384693101056831, 0.0,
                                0.5384693101056831, 0.9061798459386640};
    static const double w[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                0.4786286704993665, 0.2369268850561891};
    CubicBez c = s.to_cubic();
    double sum = 0.0;
    for (int i = 0; i < 5; ++i) {
        double t = 0.5 * (x[i] + 1.0), u = 1.0 - t;
        Point b = c.eval(t) - origin;
        Vec2 d = 3.0 * (u * u * (c.p1 - c.p0) + 2.0 * u * t * (c.p2 - c.p1) + t * t * (c.p3 - c.p2));
        sum += 0.5 * w[i] * b.cross(d);
    }
    return 0.5 * sum;  // the interval [0, 1] is half of [-1, 1]
}

}  // namespace

TEST(PathBuilder, DrawingAfterCloseStartsNewContourAtStart) {
    Path p;
    p.move_to({1, 2});
    p.line_to({5, 2});
    p.line_to({5, 6});
    p.close();
    p.line_to({0, 0});
    ASSERT_EQ(p.verbs().size(), 6u);
    EXPECT_EQ(p.verbs()[4], Verb::Move);
    EXPECT_EQ(p.points()[3], (Point{1, 2}));
}

TEST(PathSegments, ClosedContourGetsClosingLineOnlyWhenNotBackAtStart) {
    Path p;
    // Contour 0: closed, ends away from its start → a closing line.
    p.move_to({0, 0});
    p.line_to({10, 0});
    p.quad_to({10, 10}, {0, 10});
    p.close();
    // Contour 1: closed, already back at its start → no closing line.
    p.move_to({20, 0});
    p.cubic_to({30, 0}, {30, 10}, {20, 0});
    p.close();
    // Contour 2: open → never a closing line.
    p.move_to({40, 0});
    p.line_to({50, 0});

    std::vector<PathSeg> segs;
    for (const PathSeg& s : p.segments()) segs.push_back(s);
    ASSERT_EQ(segs.size(), 5u);
    ASSERT_EQ(p.segment_count(), 5u);
    EXPECT_EQ(p.contour_count(), 3u);

    const SegKind kinds[] = {SegKind::Line, SegKind::Quad, SegKind::Line, SegKind::Cubic,
                             SegKind::Line};
    const std::size_t contours[] = {0, 0, 0, 1, 2};
    const bool closing[] = {false, false, true, false, false};
    for (std::size_t i = 0; i < segs.size(); ++i) {
        SCOPED_TRACE(i);
        EXPECT_EQ(segs[i].index, i);
        EXPECT_EQ(segs[i].kind, kinds[i]);
        EXPECT_EQ(segs[i].contour, contours[i]);
        EXPECT_EQ(segs[i].closing, closing[i]);
    }
    EXPECT_EQ(segs[2].start(), (Point{0, 10}));
    EXPECT_EQ(segs[2].end(), (Point{0, 0}));
    EXPECT_EQ(segs[1].start(), (Point{10, 0}));  // each segment starts where the last ended
    EXPECT_EQ(segs[3].as_cubic().p3, (Point{20, 0}));
    EXPECT_EQ(segs[4].as_line().p0, (Point{40, 0}));
}

TEST(PathSegments, EmptyContoursAreCountedButYieldNothing) {
    Path p;
    p.move_to({1, 1});
    p.close();             // contour 0: Move + Close, back at start: no segment
    p.move_to({2, 2});
    p.line_to({3, 3});     // contour 1
    p.move_to({9, 9});     // contour 2: a lone Move
    EXPECT_EQ(p.contour_count(), 3u);
    ASSERT_EQ(p.segment_count(), 1u);
    EXPECT_EQ(p.segment(0).contour, 1u);
    EXPECT_EQ(p.segment(0).index, 0u);
    EXPECT_EQ(p.contour_areas().size(), 3u);
    const Path none;
    EXPECT_TRUE(none.segments().begin() == none.segments().end());
}

TEST(PathSegments, RandomAccessAgreesWithIteration) {
    std::mt19937_64 rng(7);
    for (int trial = 0; trial < 500; ++trial) {
        Path p = random_path(rng);
        std::size_t i = 0;
        for (const PathSeg& s : p.segments()) {
            ASSERT_EQ(s.index, i);
            PathSeg r = p.segment(i);
            ASSERT_EQ(r.kind, s.kind);
            ASSERT_EQ(r.contour, s.contour);
            ASSERT_EQ(r.closing, s.closing);
            for (int k = 0; k < 4; ++k) ASSERT_EQ(r.p[k], s.p[k]);
            ++i;
        }
        ASSERT_EQ(i, p.segment_count());
    }
}

TEST(PathSegments, SegmentsChainEndToStartWithinEachContour) {
    std::mt19937_64 rng(11);
    for (int trial = 0; trial < 1000; ++trial) {
        Path p = random_path(rng);
        bool have_prev = false;
        PathSeg prev;
        for (const PathSeg& s : p.segments()) {
            if (have_prev && prev.contour == s.contour) {
                ASSERT_EQ(prev.end(), s.start());
            }
            if (s.closing) {
                ASSERT_NE(s.start(), s.end());
            }
            prev = s;
            have_prev = true;
        }
    }
}

TEST(PathSeg, ToCubicTracesTheSameCurveAtTheSameParameter) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> coord(-50.0, 50.0), unit(0.0, 1.0);
    auto pt = [&] { return Point{coord(rng), coord(rng)}; };
    for (int trial = 0; trial < 2000; ++trial) {
        PathSeg s;
        s.kind = trial % 2 ? SegKind::Line : SegKind::Quad;
        s.p[0] = pt(), s.p[1] = pt(), s.p[2] = s.kind == SegKind::Quad ? pt() : Point{};
        CubicBez c = s.to_cubic();
        double t = unit(rng);
        // Degree elevation is exact in real arithmetic; 1e-12 covers rounding at |x| ≤ 50.
        EXPECT_NEAR(c.eval(t).x, s.eval(t).x, 1e-12);
        EXPECT_NEAR(c.eval(t).y, s.eval(t).y, 1e-12);
        EXPECT_EQ(c.p0, s.start());
        EXPECT_EQ(c.p3, s.end());
    }
}

TEST(PathTransform, MapsEveryPointAndKeepsVerbs) {
    std::mt19937_64 rng(5);
    Affine m{1.5, 0.25, -0.75, 2.0, 10.0, -3.0};
    Path p = random_path(rng);
    Path q = p.transformed(m);
    ASSERT_EQ(q.verbs(), p.verbs());
    for (std::size_t i = 0; i < p.points().size(); ++i) EXPECT_EQ(q.points()[i], m * p.points()[i]);
    Path r = p;
    r.transform(m);
    EXPECT_TRUE(bitwise_equal(r, q));
}

TEST(PathBoxes, ControlBoxIsTheBoxOfSegmentPoints) {
    Path p;
    p.move_to({100, 100});  // a lone Move draws nothing and is not counted
    p.move_to({0, 0});
    p.cubic_to({-5, 20}, {30, -10}, {10, 5});
    EXPECT_EQ(p.control_box(), Rect(-5, -10, 30, 20));
    EXPECT_TRUE(Path{}.control_box().is_empty());
}

namespace {

// The largest value of f over [0, 1], found without derivatives: samples, then a ternary search
// around every sample that is a discrete local maximum (a polynomial of degree ≤ 3 has at most
// one interior maximum, and near it, it is unimodal), keeping the best.
template <typename F>
double max_by_sampling(F f) {
    const int n = 200;
    double v[n + 1];
    for (int i = 0; i <= n; ++i) v[i] = f(double(i) / n);
    double best = std::max(v[0], v[n]);
    for (int i = 0; i <= n; ++i) {
        if ((i > 0 && v[i - 1] > v[i]) || (i < n && v[i + 1] > v[i])) continue;
        double lo = std::max(0.0, (i - 1.0) / n), hi = std::min(1.0, (i + 1.0) / n);
        for (int it = 0; it < 80; ++it) {  // (2/3)^80 · 0.01 ≈ 1e-16
            double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
            if (f(m1) < f(m2)) lo = m1; else hi = m2;
        }
        best = std::max({best, v[i], f(0.5 * (lo + hi))});
    }
    return best;
}

}  // namespace

TEST(PathBoxes, TightBoundsContainTheCurvesAndTouchThem) {
    std::mt19937_64 rng(41);
    for (int trial = 0; trial < 300; ++trial) {
        Path p = random_path(rng);
        Rect b = p.bounds();
        Rect c = p.control_box();
        ASSERT_TRUE(b.x0 >= c.x0 && b.y0 >= c.y0 && b.x1 <= c.x1 && b.y1 <= c.y1);
        // The extremes of the sampled curves, per side.
        double x0 = HUGE_VAL, y0 = HUGE_VAL, x1 = -HUGE_VAL, y1 = -HUGE_VAL;
        for (const PathSeg& s : p.segments()) {
            x1 = std::max(x1, max_by_sampling([&](double t) { return s.eval(t).x; }));
            y1 = std::max(y1, max_by_sampling([&](double t) { return s.eval(t).y; }));
            x0 = std::min(x0, -max_by_sampling([&](double t) { return -s.eval(t).x; }));
            y0 = std::min(y0, -max_by_sampling([&](double t) { return -s.eval(t).y; }));
            for (int i = 0; i <= 200; ++i) {
                Point q = s.eval(i / 200.0);
                // Contains every point of the curve (1e-9 absorbs rounding at |x| ≤ 100) …
                ASSERT_TRUE(b.inflated(1e-9).contains(q)) << trial;
            }
        }
        // … and every side touches the curves.
        ASSERT_NEAR(b.x0, x0, 1e-9) << trial;
        ASSERT_NEAR(b.y0, y0, 1e-9) << trial;
        ASSERT_NEAR(b.x1, x1, 1e-9) << trial;
        ASSERT_NEAR(b.y1, y1, 1e-9) << trial;
    }
    EXPECT_TRUE(Path{}.bounds().is_empty());
}

// bounds() solves only the curves whose control points leave the box of the end points; the
// plain reference solves every segment. Same box (to rounding of the skipped curves' extrema,
// which lie inside the hull), lone Moves and Closes included.
TEST(PathBoxes, BoundsEqualTheUnionOfEverySegmentsTightBox) {
    std::mt19937_64 rng(37);
    for (int trial = 0; trial < 300; ++trial) {
        Path p = random_path(rng);
        if (trial % 3 == 0) p.move_to({1000, -1000});  // a trailing Move that starts nothing
        Rect reference = Rect::empty();
        for (const PathSeg& s : p.segments()) {
            const Rect box = s.kind == SegKind::Line   ? s.as_line().bounding_box()
                             : s.kind == SegKind::Quad ? s.as_quad().bounding_box()
                                                       : s.as_cubic().bounding_box();
            reference = reference.union_with(box);
        }
        const Rect b = p.bounds();
        ASSERT_NEAR(b.x0, reference.x0, 1e-12) << trial;
        ASSERT_NEAR(b.y0, reference.y0, 1e-12) << trial;
        ASSERT_NEAR(b.x1, reference.x1, 1e-12) << trial;
        ASSERT_NEAR(b.y1, reference.y1, 1e-12) << trial;
    }
    Path lone;
    lone.move_to({5, 5});
    lone.close();
    EXPECT_TRUE(lone.bounds().is_empty());
}

TEST(PathBoxes, BoundsOfACubicBulgeAreExact) {
    Path p;  // symmetric arch: y extreme at t = ½, y = ¾·(−40) = −30
    p.move_to({0, 0});
    p.cubic_to({0, -40}, {100, -40}, {100, 0});
    EXPECT_EQ(p.bounds(), Rect(0, -30, 100, 0));
    EXPECT_EQ(p.control_box(), Rect(0, -40, 100, 0));
}

TEST(PathReverse, ReversesEachContourKeepingOrderAndClosedness) {
    Path p;
    p.move_to({0, 0});
    p.line_to({1, 0});
    p.quad_to({2, 0}, {2, 1});
    p.cubic_to({2, 2}, {1, 3}, {0, 3});
    p.close();
    p.move_to({5, 5});
    p.line_to({6, 6});
    Path r = p.reversed();
    const std::vector<Verb> verbs = {Verb::Move, Verb::Cubic, Verb::Quad, Verb::Line, Verb::Close,
                                     Verb::Move, Verb::Line};
    const std::vector<Point> points = {{0, 3}, {1, 3}, {2, 2}, {2, 1}, {2, 0}, {1, 0},
                                       {0, 0}, {6, 6}, {5, 5}};
    EXPECT_EQ(r.verbs(), verbs);
    EXPECT_EQ(r.points(), points);
}

TEST(PathReverse, IsAnInvolutionAndKeepsSegmentCount) {
    std::mt19937_64 rng(13);
    for (int trial = 0; trial < 2000; ++trial) {
        Path p = random_path(rng);
        Path r = p.reversed();
        ASSERT_EQ(r.segment_count(), p.segment_count());
        ASSERT_EQ(r.contour_count(), p.contour_count());
        ASSERT_TRUE(bitwise_equal(r.reversed(), p));
    }
}

TEST(PathArea, RectangleIsExactAndClockwiseOnScreenIsPositive) {
    Path p;  // right, down, left on a y-down screen: clockwise
    p.move_to({1, 2});
    p.line_to({5, 2});
    p.line_to({5, 5});
    p.line_to({1, 5});
    p.close();
    EXPECT_EQ(p.signed_area(), 12.0);
    EXPECT_EQ(p.reversed().signed_area(), -12.0);
    EXPECT_EQ(p.contour_windings(), std::vector<Winding>{Winding::Clockwise});
    EXPECT_EQ(p.reversed().contour_windings(), std::vector<Winding>{Winding::CounterClockwise});
    // The same contour left open is closed implicitly, as a filler closes it.
    Path open;
    open.move_to({1, 2});
    open.line_to({5, 2});
    open.line_to({5, 5});
    open.line_to({1, 5});
    EXPECT_EQ(open.signed_area(), 12.0);
}

TEST(PathArea, DegenerateContourHasNoWinding) {
    Path p;
    p.move_to({0, 0});
    p.line_to({4, 4});
    p.close();
    EXPECT_EQ(p.contour_windings(), std::vector<Winding>{Winding::None});
    EXPECT_EQ(winding_of_area(std::nan("")), Winding::None);
}

TEST(PathArea, QuadAndCubicClosedFormsMatchQuadrature) {
    std::mt19937_64 rng(17);
    for (int trial = 0; trial < 3000; ++trial) {
        Path p = random_path(rng);
        std::vector<double> expected(p.contour_count(), 0.0);
        Point origin;
        std::size_t contour = SIZE_MAX;
        for (const PathSeg& s : p.segments()) {
            if (s.contour != contour) origin = s.start(), contour = s.contour;
            expected[s.contour] += quadrature_area(s, origin);
        }
        std::vector<double> got = p.contour_areas();
        ASSERT_EQ(got.size(), expected.size());
        // Coordinates ≤ 100, so areas ≤ ~1e5; both sides round at ~1e-16 relative per term.
        for (std::size_t c = 0; c < got.size(); ++c) ASSERT_NEAR(got[c], expected[c], 1e-8);
    }
}

TEST(PathArea, ReversingNegatesArea) {
    std::mt19937_64 rng(19);
    for (int trial = 0; trial < 3000; ++trial) {
        Path p = random_path(rng);
        // Reversal changes the evaluation origin (the contour's new start), so the sums round
        // differently: 1e-9 at areas up to ~1e5.
        ASSERT_NEAR(p.reversed().signed_area(), -p.signed_area(), 1e-9);
    }
}

TEST(PathArea, AffineMapScalesAreaByDeterminant) {
    std::mt19937_64 rng(23);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    for (int trial = 0; trial < 3000; ++trial) {
        Path p = random_path(rng);
        Affine m{u(rng), u(rng), u(rng), u(rng), 50 * u(rng), 50 * u(rng)};
        double a = p.signed_area();
        // |det| ≤ 8 and translations shift coordinates to ~400: 1e-8 absolute is ~1e-13 relative.
        ASSERT_NEAR(p.transformed(m).signed_area(), m.determinant() * a, 1e-8);
    }
}

TEST(PathFinite, DetectsNanAndInfinity) {
    Path p;
    p.move_to({0, 0});
    p.line_to({1, 1});
    EXPECT_TRUE(p.is_finite());
    p.line_to({HUGE_VAL, 0});
    EXPECT_FALSE(p.is_finite());
    Path q;
    q.move_to({std::nan(""), 0});
    EXPECT_FALSE(q.is_finite());
}
