// Segment-pair intersection: the hard cases, exact-endpoint and degenerate behaviour,
// and fixed-seed property tests against the subdivision baseline.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "bezel/intersect.hpp"

namespace bezel {
namespace {

CubicBez cubic(double x0, double y0, double x1, double y1, double x2, double y2, double x3,
               double y3) {
    return {{x0, y0}, {x1, y1}, {x2, y2}, {x3, y3}};
}

CurveIntersections must(const Expected<CurveIntersections>& r) {
    EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().message);
    return r.ok() ? r.value() : CurveIntersections{};
}

// One Newton step in long double from (s, t): how far the reported parameters are from the
// exact root of the given double control points (for a transversal crossing).
double newton_error(const Curve& a, const Curve& b, double s, double t) {
    auto eval = [](const Curve& c, long double u, long double& x, long double& y, long double& dx,
                   long double& dy) {
        long double px[4], py[4];
        for (int i = 0; i <= c.degree; ++i) px[i] = c.p[i].x, py[i] = c.p[i].y;
        long double dpx[3], dpy[3];
        for (int i = 0; i < c.degree; ++i)
            dpx[i] = c.degree * (px[i + 1] - px[i]), dpy[i] = c.degree * (py[i + 1] - py[i]);
        for (int k = c.degree; k > 0; --k)
            for (int i = 0; i < k; ++i)
                px[i] += (px[i + 1] - px[i]) * u, py[i] += (py[i + 1] - py[i]) * u;
        for (int k = c.degree - 1; k > 0; --k)
            for (int i = 0; i < k; ++i)
                dpx[i] += (dpx[i + 1] - dpx[i]) * u, dpy[i] += (dpy[i + 1] - dpy[i]) * u;
        x = px[0], y = py[0], dx = dpx[0], dy = dpy[0];
    };
    long double ax, ay, adx, ady, bx, by, bdx, bdy;
    eval(a, s, ax, ay, adx, ady);
    eval(b, t, bx, by, bdx, bdy);
    long double fx = bx - ax, fy = by - ay;
    long double det = adx * bdy - ady * bdx;
    long double ds = (fx * bdy - fy * bdx) / det;
    long double dt = (adx * fy - ady * fx) / det;
    return static_cast<double>(std::max(std::fabs(ds), std::fabs(dt)));
}

// ---- The public hard cases -------------------------------------------------------------

TEST(Intersect, LasserExampleHasNineCrossings) {
    CubicBez a = cubic(0, 0, 0, 14, 3, -9, 3, 5);
    CubicBez b = cubic(-1, 4, 13, 4, -10, 1, 4, 1);
    auto r = must(intersect(a, b));
    ASSERT_EQ(r.points.size(), 9u);
    EXPECT_TRUE(r.overlaps.empty());
    for (const auto& p : r.points) {
        EXPECT_EQ(p.kind, IntersectionKind::Cross);
        EXPECT_LE(distance(a.eval(p.t_a), b.eval(p.t_b)), 1e-13);
        EXPECT_LE(newton_error(a, b, p.t_a, p.t_b), 1e-14);
    }
    for (std::size_t i = 1; i < r.points.size(); ++i) EXPECT_GT(r.points[i].t_a, r.points[i - 1].t_a);
    auto base = intersect_baseline(a, b);
    ASSERT_TRUE(base.ok());
    EXPECT_EQ(base->size(), 9u);
}

TEST(Intersect, EqualCurvatureTangentIsOnePointAtOrigin) {
    QuadBez a{{12, 4}, {-4, -4}, {-4, 4}};
    QuadBez b{{6, 1}, {-2, -1}, {-2, 1}};
    auto r = must(intersect(a, b));
    ASSERT_EQ(r.points.size(), 1u);
    EXPECT_EQ(r.points[0].kind, IntersectionKind::Tangent);
    // Third-order contact: a multiple root, good to ~√ε (the contract says 1e-8; we ask 1e-6).
    EXPECT_NEAR(r.points[0].t_a, 0.5, 1e-6);
    EXPECT_NEAR(r.points[0].t_b, 0.5, 1e-6);
    EXPECT_NEAR(r.points[0].point.x, 0.0, 1e-5);
    EXPECT_NEAR(r.points[0].point.y, 0.0, 1e-5);
    EXPECT_TRUE(r.overlaps.empty());
}

TEST(Intersect, IdenticalCubicsAreOneOverlap) {
    CubicBez a = cubic(10, 10, 40, -20, 80, 90, 100, 30);
    auto r = must(intersect(a, a));
    EXPECT_TRUE(r.points.empty());
    ASSERT_EQ(r.overlaps.size(), 1u);
    EXPECT_EQ(r.overlaps[0].t_a0, 0.0);
    EXPECT_EQ(r.overlaps[0].t_a1, 1.0);
    EXPECT_EQ(r.overlaps[0].t_b0, 0.0);
    EXPECT_EQ(r.overlaps[0].t_b1, 1.0);
}

TEST(Intersect, CubicAgainstItsSubcurveIsOneOverlap) {
    CubicBez a = cubic(10, 10, 40, -20, 80, 90, 100, 30);
    CubicBez sub = a.subsegment(0.25, 1.0);
    auto r = must(intersect(a, sub));
    EXPECT_TRUE(r.points.empty());
    ASSERT_EQ(r.overlaps.size(), 1u);
    EXPECT_NEAR(r.overlaps[0].t_a0, 0.25, 1e-12);
    EXPECT_EQ(r.overlaps[0].t_a1, 1.0);
    EXPECT_EQ(r.overlaps[0].t_b0, 0.0);
    EXPECT_EQ(r.overlaps[0].t_b1, 1.0);
    // Reversed sub-curve: the B interval runs backwards.
    auto rr = must(intersect(a, sub.reversed()));
    ASSERT_EQ(rr.overlaps.size(), 1u);
    EXPECT_EQ(rr.overlaps[0].t_b0, 1.0);
    EXPECT_EQ(rr.overlaps[0].t_b1, 0.0);
    EXPECT_TRUE(rr.points.empty());
}

TEST(Intersect, CubicWithDoubledControlPointsCrossesLineOnce) {
    Point c{580.1377046525328, 325.5830744834947}, d{289.35338528516013, 450.62476639303753};
    CubicBez a{c, c, d, d};
    Line l{{486, 597}, {313, 285}};
    auto r = must(intersect(a, l));
    ASSERT_EQ(r.points.size(), 1u);
    EXPECT_EQ(r.points[0].kind, IntersectionKind::Cross);
    EXPECT_LE(distance(a.eval(r.points[0].t_a), l.eval(r.points[0].t_b)), 1e-10);
    EXPECT_LE(newton_error(a, l, r.points[0].t_a, r.points[0].t_b), 1e-14);
}

TEST(Intersect, TwoArcsCrossTwiceAtKnownPoints) {
    // The reference points are those of the exact curves, whose control points are
    // thirds (183.33 stands for 550/3); the path data as written crosses twice nearby.
    CubicBez a{{150, 150}, {550.0 / 3, 650.0 / 3}, {700.0 / 3, 650.0 / 3}, {300, 150}};
    CubicBez b{{100, 200}, {500.0 / 3, 400.0 / 3}, {700.0 / 3, 400.0 / 3}, {300, 200}};
    auto r = must(intersect(a, b));
    ASSERT_EQ(r.points.size(), 2u);
    EXPECT_NEAR(r.points[0].point.x, 155.388971, 1e-6);
    EXPECT_NEAR(r.points[0].point.y, 159.950720, 1e-6);
    EXPECT_NEAR(r.points[1].point.x, 271.265313, 1e-6);
    EXPECT_NEAR(r.points[1].point.y, 175.393724, 1e-6);
    for (const auto& p : r.points) EXPECT_EQ(p.kind, IntersectionKind::Cross);

    auto pa = parse_svg_path("M150,150 C183.33,216.67 233.33,216.67 300,150");
    auto pb = parse_svg_path("M100,200 C166.67,133.33 233.33,133.33 300,200");
    ASSERT_TRUE(pa.ok() && pb.ok());
    auto rp = must(intersect(Curve(pa->segment(0)), Curve(pb->segment(0))));
    ASSERT_EQ(rp.points.size(), 2u);
    EXPECT_NEAR(rp.points[0].point.x, 155.3876, 1e-3);
    EXPECT_NEAR(rp.points[1].point.x, 271.2659, 1e-3);
}

TEST(Intersect, SelfIntersectionWithDoublePointAtStart) {
    CubicBez c = cubic(2, 3, 0, 4, 3, 2, 5, 3);
    auto r = must(self_intersect(c));
    ASSERT_EQ(r.points.size(), 1u);
    EXPECT_EQ(r.points[0].t_a, 0.0);
    EXPECT_NEAR(r.points[0].t_b, 0.5, 1e-12);
    EXPECT_EQ(r.points[0].kind, IntersectionKind::Endpoint);
    // And mirrored in t: the double point at the end.
    auto m = must(self_intersect(c.reversed()));
    ASSERT_EQ(m.points.size(), 1u);
    EXPECT_NEAR(m.points[0].t_a, 0.5, 1e-12);
    EXPECT_EQ(m.points[0].t_b, 1.0);
}

// ---- Tangents and near-tangents --------------------------------------------------------------

TEST(IntersectTangent, DifferentCurvaturesGiveOneTangentToFullPrecision) {
    // y = x² and y = 2x² (x = 2t − 1 on both): they touch at the origin, t = ½, and nowhere else.
    QuadBez a{{-1, 1}, {0, -1}, {1, 1}};
    QuadBez b{{-1, 2}, {0, -2}, {1, 2}};
    auto r = must(intersect(a, b));
    ASSERT_EQ(r.points.size(), 1u);
    EXPECT_EQ(r.points[0].kind, IntersectionKind::Tangent);
    // A simple root of the tangency equations: good to rounding, not just √ε.
    EXPECT_NEAR(r.points[0].t_a, 0.5, 1e-12);
    EXPECT_NEAR(r.points[0].t_b, 0.5, 1e-12);
}

TEST(IntersectTangent, NearTangentCrossingPairsAreBothFound) {
    // y = x² against y = 2x² − δ: crossings at x = ±√δ, i.e. t = (1 ± √δ)/2.
    QuadBez a{{-1, 1}, {0, -1}, {1, 1}};
    for (double delta : {1e-4, 1e-8, 1e-12}) {
        QuadBez b{{-1, 2 - delta}, {0, -2 - delta}, {1, 2 - delta}};
        auto r = must(intersect(a, b));
        ASSERT_EQ(r.points.size(), 2u) << "delta " << delta;
        double x = std::sqrt(delta);
        for (int i = 0; i < 2; ++i) {
            double expected_t = (1.0 + (i == 0 ? -x : x)) / 2.0;
            // The crossing angle is ~2√δ, so the attainable accuracy is ~ε/√δ.
            EXPECT_NEAR(r.points[i].t_a, expected_t, 1e-15 / x + 1e-15) << "delta " << delta;
            EXPECT_NEAR(r.points[i].t_b, expected_t, 1e-15 / x + 1e-15) << "delta " << delta;
        }
    }
    // Below the resolution limit (crossings 1e-8 apart in t) they are one tangent contact.
    QuadBez b{{-1, 2 - 1e-16}, {0, -2 - 1e-16}, {1, 2 - 1e-16}};
    auto r = must(intersect(a, b));
    ASSERT_EQ(r.points.size(), 1u);
    EXPECT_EQ(r.points[0].kind, IntersectionKind::Tangent);
    EXPECT_NEAR(r.points[0].t_a, 0.5, 1e-7);
}

TEST(IntersectTangent, NearMissBeyondToleranceIsNothing) {
    QuadBez a{{-1, 1}, {0, -1}, {1, 1}};
    QuadBez b{{-1, 2 + 1e-9}, {0, -2 + 1e-9}, {1, 2 + 1e-9}};  // 1e-9 above a's apex
    EXPECT_TRUE(must(intersect(a, b)).points.empty());
}

TEST(IntersectTangent, LineThroughACuspIsOnePoint) {
    // (0,0) (1,1) (0,1) (1,0) has its cusp at t = ½, (0.5, 0.75); x(t) − ½ = 4(t − ½)³.
    CubicBez c = cubic(0, 0, 1, 1, 0, 1, 1, 0);
    auto r = must(intersect(Line{{0.5, 0}, {0.5, 1}}, c));
    ASSERT_EQ(r.points.size(), 1u);
    EXPECT_NEAR(r.points[0].t_b, 0.5, 1e-5);  // a triple root: ∛ε
    EXPECT_NEAR(r.points[0].point.y, 0.75, 1e-9);
}

// ---- Self-intersection --------------------------------------------------------------------------

TEST(SelfIntersect, SymmetricLoopHasParametersSummingToOne) {
    // Mirror-symmetric about x = ½, so the double point has s + t = 1.
    CubicBez c = cubic(0, 0, 2, 1, -1, 1, 1, 0);
    auto r = must(self_intersect(c));
    ASSERT_EQ(r.points.size(), 1u);
    EXPECT_NEAR(r.points[0].t_a + r.points[0].t_b, 1.0, 1e-14);
    EXPECT_LT(r.points[0].t_a, r.points[0].t_b);
    EXPECT_NEAR(r.points[0].point.x, 0.5, 1e-14);
    EXPECT_EQ(r.points[0].kind, IntersectionKind::Cross);
    EXPECT_LE(distance(c.eval(r.points[0].t_a), c.eval(r.points[0].t_b)), 1e-14);
}

TEST(SelfIntersect, ArchWithoutLoopAndLinesAndQuadsHaveNone) {
    EXPECT_TRUE(must(self_intersect(cubic(0, 0, 1, 1, 2, 1, 3, 0))).points.empty());
    EXPECT_TRUE(must(self_intersect(Line{{0, 0}, {1, 1}})).points.empty());
    EXPECT_TRUE(must(self_intersect(QuadBez{{0, 0}, {1, 5}, {2, 0}})).points.empty());
    // A cusp is not a loop.
    EXPECT_TRUE(must(self_intersect(cubic(0, 0, 1, 1, 0, 1, 1, 0))).points.empty());
}

TEST(SelfIntersect, CollinearCubicFoldingBackOverlapsItself) {
    // x(t) runs 0 → beyond 2 → back to 1: the stretch after the turn retraces the one before.
    CubicBez c = cubic(0, 0, 3, 0, 3, 0, 1, 0);
    auto r = must(self_intersect(c));
    ASSERT_EQ(r.overlaps.size(), 1u);
    const CurveOverlap& o = r.overlaps[0];
    EXPECT_LT(o.t_a0, o.t_a1);
    EXPECT_NEAR(o.t_a1, o.t_b1, 1e-12);  // both end at the turning point
    EXPECT_EQ(o.t_b0, 1.0);
    EXPECT_NEAR(c.eval(o.t_a0).x, 1.0, 1e-12);
}

TEST(SelfIntersect, FoldAtThePrecisionLimitIsReportedInOrderWithoutTwins) {
    // A fuzzer's cubic: out to 2^50 px and back to within 71 px of its start, flat to 1e-14 of
    // its size. Its loop and its fold both report; the result still keeps the contract's order.
    CubicBez c = cubic(1e-300, -33.5, -13, -50.5, 1125899906842624.0, -8.5, 1e-300, 37.5);
    auto r = must(self_intersect(c));
    for (std::size_t i = 1; i < r.points.size(); ++i) {
        const auto &q = r.points[i - 1], &p = r.points[i];
        EXPECT_TRUE(q.t_a < p.t_a || (q.t_a == p.t_a && q.t_b < p.t_b)) << i;
    }
    for (const auto& p : r.points) EXPECT_LT(p.t_a, p.t_b);
}

TEST(SelfIntersect, NonFiniteIsAnError) {
    auto r = self_intersect(cubic(0, 0, NAN, 1, 2, 2, 3, 3));
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("non-finite"), std::string::npos);
}

// ---- Lines ----------------------------------------------------------------------------------------

TEST(IntersectLines, CrossingIsExactForSimpleInput) {
    auto r = must(intersect(Line{{0, 0}, {4, 4}}, Line{{0, 4}, {4, 0}}));
    ASSERT_EQ(r.points.size(), 1u);
    EXPECT_EQ(r.points[0].t_a, 0.5);
    EXPECT_EQ(r.points[0].t_b, 0.5);
    EXPECT_EQ(r.points[0].point, Point(2, 2));
    EXPECT_EQ(r.points[0].kind, IntersectionKind::Cross);
}

TEST(IntersectLines, ParallelLinesDoNotMeet) {
    EXPECT_TRUE(must(intersect(Line{{0, 0}, {4, 0}}, Line{{0, 1}, {4, 1}})).points.empty());
    EXPECT_TRUE(must(intersect(Line{{0, 0}, {1, 0}}, Line{{2, 0}, {3, 0}})).points.empty());
}

TEST(IntersectLines, CollinearLinesOverlapAsIntervals) {
    auto r = must(intersect(Line{{0, 0}, {4, 0}}, Line{{6, 0}, {2, 0}}));
    EXPECT_TRUE(r.points.empty());
    ASSERT_EQ(r.overlaps.size(), 1u);
    EXPECT_EQ(r.overlaps[0].t_a0, 0.5);
    EXPECT_EQ(r.overlaps[0].t_a1, 1.0);
    EXPECT_EQ(r.overlaps[0].t_b0, 1.0);
    EXPECT_EQ(r.overlaps[0].t_b1, 0.5);
}

TEST(IntersectLines, CollinearLinesMeetingEndToEndGiveOneEndpoint) {
    auto r = must(intersect(Line{{0, 0}, {1, 1}}, Line{{1, 1}, {3, 3}}));
    EXPECT_TRUE(r.overlaps.empty());
    ASSERT_EQ(r.points.size(), 1u);
    EXPECT_EQ(r.points[0].t_a, 1.0);
    EXPECT_EQ(r.points[0].t_b, 0.0);
    EXPECT_EQ(r.points[0].kind, IntersectionKind::Endpoint);
}

TEST(IntersectLines, TJunctionIsAnExactEndpoint) {
    auto r = must(intersect(Line{{0, 0}, {10, 0}}, Line{{3.3, 5}, {3.3, 0}}));
    ASSERT_EQ(r.points.size(), 1u);
    EXPECT_EQ(r.points[0].t_b, 1.0);
    EXPECT_NEAR(r.points[0].t_a, 0.33, 1e-15);
    EXPECT_EQ(r.points[0].kind, IntersectionKind::Endpoint);
}

TEST(IntersectLines, LineTangentToQuadIsOneTangentAtTheApex) {
    // y = 4t(1 − t)·2 peaks at t = ½, y = 2: the line y = 2 touches it there.
    QuadBez q{{0, 0}, {1, 4}, {2, 0}};
    auto r = must(intersect(Line{{-1, 2}, {3, 2}}, q));
    ASSERT_EQ(r.points.size(), 1u);
    EXPECT_EQ(r.points[0].kind, IntersectionKind::Tangent);
    EXPECT_NEAR(r.points[0].t_b, 0.5, 1e-15);
    EXPECT_NEAR(r.points[0].t_a, 0.5, 1e-15);
}

TEST(IntersectLines, CubicThatIsReallyALineOverlapsThatLine) {
    CubicBez c = cubic(0, 0, 1, 0, 2, 0, 3, 0);  // x = 3t, evenly
    auto r = must(intersect(c, Line{{1, 0}, {5, 0}}));
    EXPECT_TRUE(r.points.empty());
    ASSERT_EQ(r.overlaps.size(), 1u);
    EXPECT_NEAR(r.overlaps[0].t_a0, 1.0 / 3.0, 1e-15);
    EXPECT_EQ(r.overlaps[0].t_a1, 1.0);
    EXPECT_EQ(r.overlaps[0].t_b0, 0.0);
    EXPECT_NEAR(r.overlaps[0].t_b1, 0.5, 1e-15);
}

TEST(IntersectLines, FoldedCollinearCubicOverlapsALineTwice) {
    // Runs right to x ≈ 2.2 then back to 1: both stretches cover the line [1.5, 2].
    CubicBez c = cubic(0, 0, 3, 0, 3, 0, 1, 0);
    auto r = must(intersect(c, Line{{1.5, 0}, {2, 0}}));
    ASSERT_EQ(r.overlaps.size(), 2u);
    for (const auto& o : r.overlaps) {
        EXPECT_NEAR(c.eval(o.t_a0).x, o.t_b0 == 0.0 ? 1.5 : 2.0, 1e-12);
        EXPECT_NEAR(c.eval(o.t_a1).x, o.t_b1 == 0.0 ? 1.5 : 2.0, 1e-12);
    }
    EXPECT_TRUE(r.points.empty());
}

// ---- Endpoints and degenerate input --------------------------------------------------------------

TEST(IntersectEndpoints, SharedStartIsExactAndReportedOnce) {
    CubicBez a = cubic(1, 1, 3, 5, 6, 0, 9, 2);
    CubicBez b = cubic(1, 1, 4, -3, 5, 6, 8, 8);
    auto r = must(intersect(a, b));
    ASSERT_GE(r.points.size(), 1u);
    EXPECT_EQ(r.points[0].t_a, 0.0);
    EXPECT_EQ(r.points[0].t_b, 0.0);
    EXPECT_EQ(r.points[0].kind, IntersectionKind::Endpoint);
    for (std::size_t i = 1; i < r.points.size(); ++i) EXPECT_GT(r.points[i].t_a, 1e-6);
}

TEST(IntersectEndpoints, SmoothJoinIsOneEndpointNotATangentCloud) {
    // b continues a with the same tangent (a G1 join): they meet only at the joint.
    CubicBez a = cubic(0, 0, 1, 2, 3, 2, 4, 0);
    CubicBez b = cubic(4, 0, 5, -2, 7, -1, 8, 1);
    auto r = must(intersect(a, b));
    ASSERT_EQ(r.points.size(), 1u);
    EXPECT_EQ(r.points[0].t_a, 1.0);
    EXPECT_EQ(r.points[0].t_b, 0.0);
}

TEST(IntersectEndpoints, EndOfOneCurveOnTheOtherIsExact) {
    CubicBez b = cubic(0, 0, 1, 3, 3, 3, 4, 0);
    Point on = b.eval(0.3);
    CubicBez a = cubic(on.x, on.y, on.x + 1, on.y + 2, on.x - 1, on.y + 3, on.x + 2, on.y + 5);
    auto r = must(intersect(a, b));
    ASSERT_EQ(r.points.size(), 1u);
    EXPECT_EQ(r.points[0].t_a, 0.0);
    EXPECT_NEAR(r.points[0].t_b, 0.3, 1e-14);
    EXPECT_EQ(r.points[0].kind, IntersectionKind::Endpoint);
}

TEST(IntersectDegenerate, ZeroLengthLineOnACurveMeetsItAtItsParameter) {
    CubicBez b = cubic(0, 0, 1, 3, 3, 3, 4, 0);
    Point p = b.eval(0.5);
    auto r = must(intersect(Line{p, p}, b));
    ASSERT_EQ(r.points.size(), 1u);
    EXPECT_EQ(r.points[0].t_a, 0.0);
    EXPECT_NEAR(r.points[0].t_b, 0.5, 1e-14);
    EXPECT_TRUE(must(intersect(Line{{9, 9}, {9, 9}}, b)).points.empty());
}

TEST(IntersectDegenerate, CollapsedControlPointsStillCross) {
    // p0 == p1 and p2 == p3: zero end derivatives on both curves.
    CubicBez a = cubic(0, 0, 0, 0, 4, 4, 4, 4);
    CubicBez b = cubic(0, 4, 0, 4, 4, 0, 4, 0);
    auto r = must(intersect(a, b));
    ASSERT_EQ(r.points.size(), 1u);
    EXPECT_NEAR(r.points[0].t_a, 0.5, 1e-14);
    EXPECT_NEAR(r.points[0].t_b, 0.5, 1e-14);
    EXPECT_EQ(r.points[0].kind, IntersectionKind::Cross);
}

TEST(IntersectDegenerate, NonFiniteCoordinatesAreErrors) {
    CubicBez ok = cubic(0, 0, 1, 1, 2, 1, 3, 0);
    auto r = intersect(ok, cubic(0, 0, INFINITY, 1, 2, 1, 3, 0));
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().message, "intersect: curve B has a non-finite coordinate");
    EXPECT_FALSE(intersect(Line{{NAN, 0}, {1, 1}}, ok).ok());
    EXPECT_FALSE(intersect_baseline(ok, Line{{0, NAN}, {1, 1}}).ok());
}

TEST(IntersectDegenerate, FarFromOriginAndTinyScalesGiveTheSameParameters) {
    CubicBez a = cubic(0, 0, 0, 14, 3, -9, 3, 5);
    CubicBez b = cubic(-1, 4, 13, 4, -10, 1, 4, 1);
    auto ref = must(intersect(a, b));
    ASSERT_EQ(ref.points.size(), 9u);
    // Moved near 1e6 (exactly representable: multiples of 2⁻³² there) and scaled to 1e-6·2⁰.
    for (Affine m : {Affine::translate({1048576.0, -1048576.0}), Affine::scale(std::ldexp(1.0, -20)),
                     Affine::translate({1e6, 1e6})}) {
        auto r = must(intersect(a.transformed(m), b.transformed(m)));
        ASSERT_EQ(r.points.size(), 9u);
        for (std::size_t i = 0; i < 9; ++i) {
            EXPECT_NEAR(r.points[i].t_a, ref.points[i].t_a, 1e-12);
            EXPECT_NEAR(r.points[i].t_b, ref.points[i].t_b, 1e-12);
        }
    }
}

// ---- Properties over random input ------------------------------------------------------------------

Point random_point(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    return {u(rng), u(rng)};
}

CubicBez random_cubic(std::mt19937_64& rng) {
    return {random_point(rng), random_point(rng), random_point(rng), random_point(rng)};
}

// Every reported point lies on both curves, parameters are within 1e-12 of the exact root
// (checked by a long-double Newton step) wherever the crossing is not nearly tangent, and the
// slow subdivision baseline finds the same crossings: nothing missed, nothing extra.
TEST(IntersectProperty, RandomCubicPairsAgreeWithTheBaseline) {
    std::mt19937_64 rng(20240605);
    int total = 0, pairs = 0;
    for (int iter = 0; iter < 3000; ++iter) {
        CubicBez a = random_cubic(rng), b = random_cubic(rng);
        auto r = must(intersect(a, b));
        auto base = intersect_baseline(a, b);
        ASSERT_TRUE(base.ok());
        ++pairs;
        total += static_cast<int>(r.points.size());
        bool near_tangent = false;
        for (const auto& p : r.points) {
            EXPECT_LE(distance(a.eval(p.t_a), b.eval(p.t_b)), 1e-12) << "pair " << iter;
            Vec2 da = a.deriv_at(p.t_a), db = b.deriv_at(p.t_b);
            double sine = std::fabs(da.cross(db)) / (da.length() * db.length());
            if (sine < 1e-3) {
                near_tangent = true;
                continue;
            }
            EXPECT_LE(newton_error(a, b, p.t_a, p.t_b), 1e-12) << "pair " << iter;
        }
        if (near_tangent) continue;  // the baseline cannot resolve these reliably
        ASSERT_EQ(r.points.size(), base->size()) << "pair " << iter;
        for (std::size_t i = 0; i < base->size(); ++i) {
            EXPECT_NEAR(r.points[i].t_a, (*base)[i].t_a, 1e-6) << "pair " << iter;
            EXPECT_NEAR(r.points[i].t_b, (*base)[i].t_b, 1e-6) << "pair " << iter;
        }
    }
    EXPECT_GT(total, pairs / 2);  // the sample really exercises crossings
}

// Swapping A and B swaps the parameters and changes nothing else.
TEST(IntersectProperty, SwappingCurvesSwapsParameters) {
    std::mt19937_64 rng(7);
    for (int iter = 0; iter < 1000; ++iter) {
        CubicBez a = random_cubic(rng), b = random_cubic(rng);
        auto ab = must(intersect(a, b)), ba = must(intersect(b, a));
        ASSERT_EQ(ab.points.size(), ba.points.size()) << "pair " << iter;
        for (const auto& p : ab.points) {
            bool found = false;
            for (const auto& q : ba.points)
                found |= std::fabs(p.t_a - q.t_b) <= 1e-12 && std::fabs(p.t_b - q.t_a) <= 1e-12;
            EXPECT_TRUE(found) << "pair " << iter;
        }
    }
}

// A random line against a random curve, and a random quadratic against a random cubic, also
// agree with the baseline.
TEST(IntersectProperty, LinesAndQuadsAgreeWithTheBaseline) {
    std::mt19937_64 rng(99);
    for (int iter = 0; iter < 2000; ++iter) {
        Curve a = iter % 2 ? Curve(Line{random_point(rng), random_point(rng)})
                           : Curve(QuadBez{random_point(rng), random_point(rng), random_point(rng)});
        CubicBez b = random_cubic(rng);
        auto r = must(intersect(a, b));
        auto base = intersect_baseline(a, b);
        ASSERT_TRUE(base.ok());
        bool near_tangent = false;
        for (const auto& p : r.points) {
            EXPECT_LE(distance(a.eval(p.t_a), b.eval(p.t_b)), 1e-12) << "pair " << iter;
            Vec2 da = a.deriv_at(p.t_a), db = b.deriv_at(p.t_b);
            near_tangent |= std::fabs(da.cross(db)) < 1e-3 * da.length() * db.length();
        }
        if (near_tangent) continue;
        ASSERT_EQ(r.points.size(), base->size()) << "pair " << iter;
        for (std::size_t i = 0; i < base->size(); ++i)
            EXPECT_NEAR(r.points[i].t_a, (*base)[i].t_a, 1e-6) << "pair " << iter;
    }
}

// Small-integer control points make every degeneracy common: shared and collinear control
// points, shared endpoints, collinear and overlapping curves, curves through each other's
// vertices. Whatever comes back must be consistent: points on both curves, no two results for
// one point, overlaps well formed and their ends on both curves.
TEST(IntersectProperty, DegenerateIntegerInputIsConsistent) {
    std::mt19937_64 rng(17);
    auto ip = [&] { return Point(static_cast<double>(rng() % 4), static_cast<double>(rng() % 4)); };
    auto curve = [&] {
        Curve c;
        c.degree = 1 + static_cast<int>(rng() % 3);
        for (int i = 0; i <= c.degree; ++i) c.p[i] = ip();
        return c;
    };
    for (int iter = 0; iter < 20000; ++iter) {
        Curve a = curve(), b = curve();
        auto r = intersect(a, b);
        ASSERT_TRUE(r.ok()) << r.error().message;
        for (std::size_t i = 0; i < r->points.size(); ++i) {
            const auto& p = r->points[i];
            ASSERT_TRUE(p.t_a >= 0 && p.t_a <= 1 && p.t_b >= 0 && p.t_b <= 1) << "pair " << iter;
            EXPECT_LE(distance(a.eval(p.t_a), b.eval(p.t_b)), 1e-9) << "pair " << iter;
            for (std::size_t j = 0; j < i; ++j)
                EXPECT_FALSE(std::fabs(p.t_a - r->points[j].t_a) <= 1e-9 &&
                             std::fabs(p.t_b - r->points[j].t_b) <= 1e-9)
                    << "duplicate, pair " << iter;
        }
        for (const auto& o : r->overlaps) {
            EXPECT_LT(o.t_a0, o.t_a1) << "pair " << iter;
            EXPECT_LE(distance(a.eval(o.t_a0), b.eval(o.t_b0)), 1e-9) << "pair " << iter;
            EXPECT_LE(distance(a.eval(o.t_a1), b.eval(o.t_b1)), 1e-9) << "pair " << iter;
            // The middle of A's stretch lies on B's stretch (B's parametrisation may differ from
            // A's when both are straight, so search: dense samples, then golden section).
            Point mid = a.eval(0.5 * (o.t_a0 + o.t_a1));
            double lo = std::min(o.t_b0, o.t_b1), hi = std::max(o.t_b0, o.t_b1), best_t = lo;
            for (int k = 0; k <= 256; ++k) {
                double t = lo + (hi - lo) * k / 256;
                if (distance(b.eval(t), mid) < distance(b.eval(best_t), mid)) best_t = t;
            }
            double x0 = std::max(lo, best_t - (hi - lo) / 256), x1 = std::min(hi, best_t + (hi - lo) / 256);
            for (int k = 0; k < 100; ++k) {
                double m0 = x0 + (x1 - x0) * 0.382, m1 = x0 + (x1 - x0) * 0.618;
                if (distance(b.eval(m0), mid) < distance(b.eval(m1), mid))
                    x1 = m1;
                else
                    x0 = m0;
            }
            EXPECT_LE(distance(b.eval(0.5 * (x0 + x1)), mid), 1e-9) << "pair " << iter;
        }
        auto self = self_intersect(a);
        ASSERT_TRUE(self.ok());
        for (const auto& p : self->points) EXPECT_LE(distance(a.eval(p.t_a), a.eval(p.t_b)), 1e-9);
    }
}

// A curve against a random sub-curve of itself is always exactly one overlap, no points.
TEST(IntersectProperty, RandomSubcurvesAreOverlaps) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int iter = 0; iter < 500; ++iter) {
        CubicBez a = random_cubic(rng);
        double t0 = u(rng), t1 = u(rng);
        if (std::fabs(t1 - t0) < 0.05) continue;
        auto r = must(intersect(a, a.subsegment(t0, t1)));
        ASSERT_EQ(r.overlaps.size(), 1u) << "pair " << iter;
        EXPECT_NEAR(r.overlaps[0].t_a0, std::min(t0, t1), 1e-9) << "pair " << iter;
        EXPECT_NEAR(r.overlaps[0].t_a1, std::max(t0, t1), 1e-9) << "pair " << iter;
        // Whatever else is reported must lie outside the shared stretch (a loop's double point).
        for (const auto& p : r.points)
            EXPECT_TRUE(p.t_a < std::min(t0, t1) - 1e-7 || p.t_a > std::max(t0, t1) + 1e-7)
                << "pair " << iter;
    }
}

}  // namespace
}  // namespace bezel
