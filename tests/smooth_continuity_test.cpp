// Continuity analysis of path joints: the C0 / G1 / C1 / C2 chain on hand-built joints, which
// joints exist (contours, closing segments), the tolerance, and errors.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "bezel/smooth.hpp"

using namespace bezel;

namespace {

std::vector<Continuity> classes(const Path& path, double tol = kDefaultContinuityTolerance) {
    auto joints = analyze_continuity(path, tol);
    EXPECT_TRUE(joints.ok());
    std::vector<Continuity> out;
    if (joints)
        for (const JointReport& j : *joints) out.push_back(j.continuity);
    return out;
}

using C = Continuity;

}  // namespace

TEST(Continuity, NamesAreTheIssueSpelling) {
    EXPECT_STREQ(continuity_name(C::Broken), "broken");
    EXPECT_STREQ(continuity_name(C::C0), "C0");
    EXPECT_STREQ(continuity_name(C::G1), "G1");
    EXPECT_STREQ(continuity_name(C::C1), "C1");
    EXPECT_STREQ(continuity_name(C::C2), "C2");
}

// Lines as cubics have zero second derivative, so equal collinear lines are C2; a longer second
// line is G1 (same direction, different speed); a turn is C0; a reversal is C0.
TEST(Continuity, LineJointsCoverTheChain) {
    Path same;
    same.move_to({0, 0});
    same.line_to({1, 0});
    same.line_to({2, 0});
    EXPECT_EQ(classes(same), std::vector<C>{C::C2});

    Path longer;
    longer.move_to({0, 0});
    longer.line_to({1, 0});
    longer.line_to({3, 0});
    EXPECT_EQ(classes(longer), std::vector<C>{C::G1});

    Path corner;
    corner.move_to({0, 0});
    corner.line_to({1, 0});
    corner.line_to({1, 1});
    EXPECT_EQ(classes(corner), std::vector<C>{C::C0});

    Path back;
    back.move_to({0, 0});
    back.line_to({1, 0});
    back.line_to({0, 0});
    EXPECT_EQ(classes(back), std::vector<C>{C::C0});
}

// A parabola split at t = ½ is C2 (its second derivative is constant); two quadratics sharing a
// tangent but bending opposite ways (an S) are C1 only.
TEST(Continuity, QuadraticJoints) {
    QuadBez q{{0, 0}, {1, 2}, {2, 0}};
    auto [a, b] = q.split(0.5);
    Path split;
    split.move_to(a.p0);
    split.quad_to(a.p1, a.p2);
    split.quad_to(b.p1, b.p2);
    // Both halves run at half speed: derivatives halved (quartered) on both sides, equal.
    EXPECT_EQ(classes(split), std::vector<C>{C::C2});

    Path s_curve;  // up then down: the tangent is shared, the bend flips
    s_curve.move_to({0, 0});
    s_curve.quad_to({1, 1}, {2, 1});
    s_curve.quad_to({3, 1}, {4, 2});
    EXPECT_EQ(classes(s_curve), std::vector<C>{C::C1});
}

// A cubic split at t = ½ is C2 at the split: each half runs at half speed, so A′(1) = B′(0) =
// ½C′(½) and A″(1) = B″(0) = ¼C″(½). Split at 0.3 the speeds differ (0.3 vs 0.7): G1.
TEST(Continuity, SplitCubicIsC2AtTheMiddleAndG1Elsewhere) {
    std::mt19937_64 rng(80);
    std::uniform_real_distribution<double> c(-100, 100);
    for (int trial = 0; trial < 1000; ++trial) {
        CubicBez cb{{c(rng), c(rng)}, {c(rng), c(rng)}, {c(rng), c(rng)}, {c(rng), c(rng)}};
        auto [a, b] = cb.split(0.5);
        Path p;
        p.move_to(a.p0);
        p.cubic_to(a.p1, a.p2, a.p3);
        p.cubic_to(b.p1, b.p2, b.p3);
        EXPECT_EQ(classes(p), std::vector<C>{C::C2}) << "trial " << trial;

        auto [a3, b3] = cb.split(0.3);  // A′(1) = 0.3·C′(0.3), B′(0) = 0.7·C′(0.3)
        Path q;
        q.move_to(a3.p0);
        q.cubic_to(a3.p1, a3.p2, a3.p3);
        q.cubic_to(b3.p1, b3.p2, b3.p3);
        EXPECT_EQ(classes(q), std::vector<C>{C::G1}) << "trial " << trial;
    }
}

// A joint that is C2 except for a second-derivative change of 1e-6 (relative) is C1 at the
// default tolerance and C2 at 1e-5: the relative tolerance is what decides.
TEST(Continuity, ToleranceDecidesNearMisses) {
    // A = (0,0) (1,1) (2,1) (3,0): A′(1) = 3(P₃ − P₂) = (3, −3), A″(1) = 6(P₁ − 2P₂ + P₃) = (0, −6).
    // B starts at (3,0) with P₁ = P₀ + A′(1)/3 = (4, −1) and P₂ from 6(P₀ − 2P₁ + P₂) = (0, −6):
    // P₂ = (5, −3). Moving P₂ by δ changes B″(0) by 6δ.
    const double size = std::hypot(4.0, 5.0);  // B's control box [3,7]×[−5,0], the larger one
    const double delta = 1e-6 * size / 6.0;
    Path p;
    p.move_to({0, 0});
    p.cubic_to({1, 1}, {2, 1}, {3, 0});
    p.cubic_to({4, -1}, {5, -3 + delta}, {7, -5});
    auto strict = analyze_continuity(p);
    ASSERT_TRUE(strict.ok());
    ASSERT_EQ(strict->size(), 1u);
    EXPECT_EQ((*strict)[0].continuity, C::C1);
    EXPECT_NEAR((*strict)[0].d2_error, 1e-6, 1e-12);
    EXPECT_EQ((*strict)[0].d1_error, 0.0);
    EXPECT_EQ((*strict)[0].angle_rad, 0.0);
    EXPECT_EQ(classes(p, 1e-5), std::vector<C>{C::C2});
}

// Joints stay within contours; a closed contour adds its closing joint (through the implicit
// closing line when the contour does not end at its start); an open contour that happens to end
// at its start gets none.
TEST(Continuity, JointsFollowContoursAndClosingSegments) {
    Path p;
    p.move_to({0, 0});  // contour 0: closed triangle with an implicit closing line, 3 joints
    p.line_to({4, 0});
    p.line_to({0, 4});
    p.close();
    p.move_to({10, 0});  // contour 1: open, ends at its start, 1 joint
    p.line_to({12, 0});
    p.line_to({10, 0});
    p.move_to({20, 0});  // contour 2: a single closed cubic loop, 1 joint (with itself)
    p.cubic_to({30, 10}, {10, 10}, {20, 0});
    p.close();
    auto joints = analyze_continuity(p);
    ASSERT_TRUE(joints.ok());
    ASSERT_EQ(joints->size(), 5u);
    const std::size_t expect[5][3] = {{0, 0, 1}, {0, 1, 2}, {0, 2, 0}, {1, 3, 4}, {2, 5, 5}};
    for (std::size_t i = 0; i < 5; ++i) {
        EXPECT_EQ((*joints)[i].contour, expect[i][0]) << i;
        EXPECT_EQ((*joints)[i].incoming, expect[i][1]) << i;
        EXPECT_EQ((*joints)[i].outgoing, expect[i][2]) << i;
    }
    EXPECT_EQ((*joints)[2].point, (Point{0, 0}));
    for (const JointReport& j : *joints) EXPECT_EQ(j.continuity, C::C0);
}

// A piece collapsed to a point has no direction, so the joints around it are C0 even though
// the derivatives on both sides vanish and are "equal".
TEST(Continuity, ZeroLengthSegmentBreaksTangentContinuity) {
    Path p;
    p.move_to({0, 0});
    p.line_to({1, 0});
    p.line_to({1, 0});
    p.line_to({2, 0});
    EXPECT_EQ(classes(p), (std::vector<C>{C::C0, C::C0}));
}

// A cubic whose end derivative vanishes (P₂ = P₃) still has a direction (CubicBez::tangent's
// limit), so a joint with it can be G1 — but not C1.
TEST(Continuity, VanishingDerivativeUsesTheLimitDirection) {
    Path p;
    p.move_to({0, 0});
    p.cubic_to({1, 0}, {2, 0}, {2, 0});
    p.line_to({3, 0});
    EXPECT_EQ(classes(p), std::vector<C>{C::G1});
}

TEST(Continuity, LoosePiecesThatDoNotMeetAreBroken) {
    std::vector<CubicBez> pieces{{{0, 0}, {1, 0}, {2, 0}, {3, 0}}, {{3, 1}, {4, 1}, {5, 1}, {6, 1}}};
    auto open = analyze_joints(pieces, false);
    ASSERT_TRUE(open.ok());
    ASSERT_EQ(open->size(), 1u);
    EXPECT_EQ((*open)[0].continuity, C::Broken);
    auto closed = analyze_joints(pieces, true);
    ASSERT_TRUE(closed.ok());
    EXPECT_EQ(closed->size(), 2u);
    auto none = analyze_joints({}, true);
    ASSERT_TRUE(none.ok());
    EXPECT_TRUE(none->empty());
}

TEST(Continuity, BadToleranceOrNonFinitePathIsAnError) {
    Path p;
    p.move_to({0, 0});
    p.line_to({1, 0});
    for (double tol : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), HUGE_VAL}) {
        auto r = analyze_continuity(p, tol);
        ASSERT_FALSE(r.ok());
        EXPECT_NE(r.error().message.find("continuity: tolerance"), std::string::npos);
    }
    p.line_to({std::numeric_limits<double>::quiet_NaN(), 0});
    auto r = analyze_continuity(p);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().message, "continuity: the path has a point that is not finite");
}
