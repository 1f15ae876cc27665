// Whole-path intersection: segment indices (the closing line counts), the joint rule, self-
// intersection, overlaps between neighbours, errors, and a brute-force property on polygons.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "bezel/intersect.hpp"

namespace bezel {
namespace {

Path svg(const char* d) {
    auto p = parse_svg_path(d);
    EXPECT_TRUE(p.ok()) << d;
    return p.ok() ? *p : Path{};
}

PathIntersections must(const Expected<PathIntersections>& r) {
    EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().message);
    return r.ok() ? r.value() : PathIntersections{};
}

TEST(IntersectPaths, OverlappingSquaresCrossTwiceWithClosingLineIndexed) {
    auto r = must(intersect_paths(svg("M0,0 H10 V10 H0 Z"), svg("M5,5 H15 V15 H5 Z")));
    ASSERT_EQ(r.intersections.size(), 2u);
    EXPECT_TRUE(r.overlaps.empty());
    const PathIntersection &p = r.intersections[0], &q = r.intersections[1];
    // (10, 5): A's right side (seg 1) at its middle, B's top (seg 0) at its middle.
    EXPECT_EQ(p.seg_a, 1u);
    EXPECT_EQ(p.seg_b, 0u);
    EXPECT_EQ(p.t_a, 0.5);
    EXPECT_EQ(p.t_b, 0.5);
    EXPECT_EQ(p.point, Point(10, 5));
    // (5, 10): A's bottom (seg 2) and B's implicit closing line (seg 3, from (5,15) up to (5,5)).
    EXPECT_EQ(q.seg_a, 2u);
    EXPECT_EQ(q.seg_b, 3u);
    EXPECT_EQ(q.point, Point(5, 10));
    EXPECT_EQ(q.kind, IntersectionKind::Cross);
}

TEST(IntersectPaths, CrossingThroughAJointIsReportedOnceOnTheLaterSegment) {
    auto r = must(intersect_paths(svg("M0,0 L10,10 L20,0"), svg("M10,0 L10,20")));
    ASSERT_EQ(r.intersections.size(), 1u);
    const PathIntersection& p = r.intersections[0];
    EXPECT_EQ(p.seg_a, 1u);
    EXPECT_EQ(p.t_a, 0.0);
    EXPECT_EQ(p.seg_b, 0u);
    EXPECT_EQ(p.t_b, 0.5);
    EXPECT_EQ(p.kind, IntersectionKind::Endpoint);
}

TEST(IntersectPaths, ClosedContoursFirstSegmentStartIsItsOwnJoint) {
    // B passes through A's start corner (0, 0), where the closing line (seg 3) joins seg 0.
    auto r = must(intersect_paths(svg("M0,0 H10 V10 H0 Z"), svg("M-5,-5 L5,5")));
    ASSERT_EQ(r.intersections.size(), 1u);
    EXPECT_EQ(r.intersections[0].seg_a, 0u);
    EXPECT_EQ(r.intersections[0].t_a, 0.0);
    EXPECT_EQ(r.intersections[0].t_b, 0.5);
}

TEST(SelfIntersectPath, FigureEightCrossesOnceAndJointsAreNotIntersections) {
    auto r = must(self_intersect_path(svg("M0,0 L10,10 L10,0 L0,10 Z")));
    ASSERT_EQ(r.intersections.size(), 1u);
    const PathIntersection& p = r.intersections[0];
    EXPECT_EQ(p.seg_a, 0u);
    EXPECT_EQ(p.seg_b, 2u);
    EXPECT_EQ(p.t_a, 0.5);
    EXPECT_EQ(p.t_b, 0.5);
    EXPECT_EQ(p.point, Point(5, 5));
}

TEST(SelfIntersectPath, SimpleClosedShapesHaveNone) {
    EXPECT_TRUE(must(self_intersect_path(svg("M0,0 H10 V10 H0 Z"))).intersections.empty());
    EXPECT_TRUE(must(self_intersect_path(svg("M0,0 C5,-5 10,5 15,0 S20,10 10,10 Z"))).intersections.empty());
    // An open contour ending where it began touches itself there: that is reported.
    auto open = must(self_intersect_path(svg("M0,0 H10 V10 L0,0")));
    ASSERT_EQ(open.intersections.size(), 1u);
    EXPECT_EQ(open.intersections[0].seg_a, 0u);
    EXPECT_EQ(open.intersections[0].seg_b, 2u);
    EXPECT_EQ(open.intersections[0].t_b, 1.0);
}

TEST(SelfIntersectPath, CubicLoopIsReportedOnItsOwnSegment) {
    auto r = must(self_intersect_path(svg("M0,0 C2,1 -1,1 1,0")));
    ASSERT_EQ(r.intersections.size(), 1u);
    EXPECT_EQ(r.intersections[0].seg_a, 0u);
    EXPECT_EQ(r.intersections[0].seg_b, 0u);
    EXPECT_LT(r.intersections[0].t_a, r.intersections[0].t_b);
}

TEST(SelfIntersectPath, LineDoublingBackOverlapsThePreviousSegment) {
    auto r = must(self_intersect_path(svg("M0,0 L10,0 L5,0")));
    EXPECT_TRUE(r.intersections.empty());
    ASSERT_EQ(r.overlaps.size(), 1u);
    const PathOverlap& o = r.overlaps[0];
    EXPECT_EQ(o.seg_a, 0u);
    EXPECT_EQ(o.seg_b, 1u);
    EXPECT_EQ(o.t_a0, 0.5);
    EXPECT_EQ(o.t_a1, 1.0);
    EXPECT_EQ(o.t_b0, 1.0);
    EXPECT_EQ(o.t_b1, 0.0);
}

TEST(IntersectPaths, NonFinitePathIsAnError) {
    Path bad;
    bad.move_to({0, 0});
    bad.line_to({NAN, 1});
    auto r = intersect_paths(bad, svg("M0,0 L1,1"));
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("non-finite"), std::string::npos);
    EXPECT_FALSE(self_intersect_path(bad).ok());
}

TEST(IntersectPaths, EmptyPathsMeetNothing) {
    EXPECT_TRUE(must(intersect_paths(Path{}, svg("M0,0 L1,1"))).intersections.empty());
    EXPECT_TRUE(must(self_intersect_path(Path{})).intersections.empty());
}

// Random closed polygons in general position: self_intersect_path finds exactly the crossings
// of non-adjacent edges that the exact orientation test (brute force) finds.
TEST(SelfIntersectPathProperty, RandomPolygonsMatchBruteForce) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0.0, 100.0);
    auto orient = [](Point a, Point b, Point c) { return (b - a).cross(c - a); };
    for (int iter = 0; iter < 300; ++iter) {
        int n = 3 + static_cast<int>(rng() % 10);
        std::vector<Point> pts;
        for (int i = 0; i < n; ++i) pts.push_back({u(rng), u(rng)});
        Path p;
        p.move_to(pts[0]);
        for (int i = 1; i < n; ++i) p.line_to(pts[i]);
        p.close();
        std::size_t expected = 0;
        for (int i = 0; i < n; ++i)
            for (int j = i + 1; j < n; ++j) {
                if (j == i + 1 || (i == 0 && j == n - 1)) continue;  // neighbours share a joint
                Point a = pts[i], b = pts[(i + 1) % n], c = pts[j], d = pts[(j + 1) % n];
                if (orient(a, b, c) * orient(a, b, d) < 0 && orient(c, d, a) * orient(c, d, b) < 0) ++expected;
            }
        auto r = must(self_intersect_path(p));
        EXPECT_EQ(r.intersections.size(), expected) << "polygon " << iter;
        for (const auto& x : r.intersections) {
            EXPECT_LT(x.seg_a, x.seg_b);
            EXPECT_LE(distance(p.segment(x.seg_a).eval(x.t_a), p.segment(x.seg_b).eval(x.t_b)), 1e-12);
        }
    }
}

// Two random curve paths: the path result is the union of the segment-pair results (no joints
// are hit in general position, so nothing is merged).
TEST(IntersectPathsProperty, RandomCurvePathsAreTheUnionOfSegmentPairs) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(0.0, 10.0);
    auto pt = [&] { return Point{u(rng), u(rng)}; };
    for (int iter = 0; iter < 200; ++iter) {
        Path a, b;
        a.move_to(pt());
        a.cubic_to(pt(), pt(), pt());
        a.quad_to(pt(), pt());
        b.move_to(pt());
        b.cubic_to(pt(), pt(), pt());
        b.line_to(pt());
        std::size_t expected = 0;
        for (const PathSeg& sa : a.segments())
            for (const PathSeg& sb : b.segments()) expected += intersect(Curve(sa), Curve(sb))->points.size();
        auto r = must(intersect_paths(a, b));
        EXPECT_EQ(r.intersections.size(), expected) << "paths " << iter;
    }
}

}  // namespace
}  // namespace bezel
