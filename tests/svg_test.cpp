// SVG path data: the parser (every command, the number and flag grammar, errors and limits), arcs
// against the true ellipse, and the writer's exact round trip.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <ostream>
#include <random>
#include <string>
#include <vector>

#include "bezel/path.hpp"

// gtest prints points readably instead of as bytes.
namespace bezel {
inline void PrintTo(const Vec2& v, std::ostream* os) { *os << "(" << v.x << ", " << v.y << ")"; }
}  // namespace bezel

using namespace bezel;

namespace {

constexpr double kPi = 3.14159265358979323846;

Path parse_ok(std::string_view data, const SvgParseOptions& options = {}) {
    Expected<Path> r = parse_svg_path(data, options);
    EXPECT_TRUE(r.ok()) << data << " → " << (r.ok() ? "" : r.error().message);
    return r.ok() ? *r : Path{};
}

std::string parse_error(std::string_view data, const SvgParseOptions& options = {}) {
    Expected<Path> r = parse_svg_path(data, options);
    EXPECT_FALSE(r.ok()) << data;
    return r.ok() ? std::string() : r.error().message;
}

bool bitwise_equal(const Path& a, const Path& b) {
    return a.verbs() == b.verbs() && a.points().size() == b.points().size() &&
           (a.points().empty() ||
            std::memcmp(a.points().data(), b.points().data(), a.points().size() * sizeof(Point)) == 0);
}

using V = Verb;

}  // namespace

// --- Commands ----------------------------------------------------------------------------------

TEST(SvgParse, AbsoluteCommands) {
    Path p = parse_ok("M1 2 L3 4 H5 V6 C7 8 9 10 11 12 Q13 14 15 16 Z");
    EXPECT_EQ(p.verbs(), (std::vector<Verb>{V::Move, V::Line, V::Line, V::Line, V::Cubic,
                                            V::Quad, V::Close}));
    EXPECT_EQ(p.points(), (std::vector<Point>{{1, 2}, {3, 4}, {5, 4}, {5, 6}, {7, 8}, {9, 10},
                                              {11, 12}, {13, 14}, {15, 16}}));
}

TEST(SvgParse, RelativeCommandsAreRelativeToTheCurrentPoint) {
    Path p = parse_ok("m1 2 l3 4 h5 v6 c1 1 2 2 3 3 q1 0 2 0 z");
    EXPECT_EQ(p.verbs(), (std::vector<Verb>{V::Move, V::Line, V::Line, V::Line, V::Cubic,
                                            V::Quad, V::Close}));
    EXPECT_EQ(p.points(), (std::vector<Point>{{1, 2}, {4, 6}, {9, 6}, {9, 12}, {10, 13}, {11, 14},
                                              {12, 15}, {13, 15}, {14, 15}}));
}

TEST(SvgParse, AfterCloseTheCurrentPointIsTheSubpathStart) {
    Path p = parse_ok("M10 10 l5 0 l0 5 z l0 5 m1 1 l1 0");
    EXPECT_EQ(p.verbs(), (std::vector<Verb>{V::Move, V::Line, V::Line, V::Close, V::Move, V::Line,
                                            V::Move, V::Line}));
    EXPECT_EQ(p.points(), (std::vector<Point>{{10, 10}, {15, 10}, {15, 15}, {10, 10}, {10, 15},
                                              {11, 16}, {12, 16}}));
}

TEST(SvgParse, SmoothCubicReflectsOnlyAfterACubic) {
    // After C: the first control point is C's second one reflected about the current point.
    Path p = parse_ok("M0 0 C1 2 3 4 5 5 S9 9 10 10 s1 1 2 0");
    ASSERT_EQ(p.points().size(), 10u);
    EXPECT_EQ(p.points()[4], (Point{7, 6}));     // (5,5)·2 − (3,4)
    EXPECT_EQ(p.points()[7], (Point{11, 11}));   // after S: (10,10)·2 − (9,9)
    EXPECT_EQ(p.points()[8], (Point{11, 11}));   // relative control point
    EXPECT_EQ(p.points()[9], (Point{12, 10}));
    // After a line (or a quadratic): the first control point is the current point.
    Path q = parse_ok("M0 0 L4 0 S8 4 8 8");
    EXPECT_EQ(q.points()[2], (Point{4, 0}));
    Path r = parse_ok("M0 0 Q1 1 4 0 S8 4 8 8");
    EXPECT_EQ(r.points()[3], (Point{4, 0}));
}

TEST(SvgParse, SmoothQuadReflectsAfterQuadOrSmoothQuad) {
    Path p = parse_ok("M0 0 Q2 4 4 0 T8 0 t4 0");
    ASSERT_EQ(p.points().size(), 7u);
    EXPECT_EQ(p.points()[3], (Point{6, -4}));   // (4,0)·2 − (2,4)
    EXPECT_EQ(p.points()[5], (Point{10, 4}));   // (8,0)·2 − (6,−4)
    EXPECT_EQ(p.points()[6], (Point{12, 0}));
    // T with no quadratic before it: control point = current point; a T after that T reflects
    // that control point.
    Path q = parse_ok("M1 1 T5 1 T9 1");
    EXPECT_EQ(q.points(), (std::vector<Point>{{1, 1}, {1, 1}, {5, 1}, {9, 1}, {9, 1}}));
    Path r = parse_ok("M0 0 C1 1 2 2 3 3 T5 5");  // a cubic is not a quadratic
    EXPECT_EQ(r.points()[4], (Point{3, 3}));
}

TEST(SvgParse, ImplicitRepeatsAfterMoveAreLines) {
    Path p = parse_ok("M1 2 3 4 5 6");
    EXPECT_EQ(p.verbs(), (std::vector<Verb>{V::Move, V::Line, V::Line}));
    EXPECT_EQ(p.points(), (std::vector<Point>{{1, 2}, {3, 4}, {5, 6}}));
    Path q = parse_ok("m1 2 3 4 5 6");  // relative repeats are relative lines
    EXPECT_EQ(q.points(), (std::vector<Point>{{1, 2}, {4, 6}, {9, 12}}));
    Path r = parse_ok("M0 0 h1 2 3 v1, 1 L1 1, 2 2 Q0 0 1 1 2 2 3 3");
    EXPECT_EQ(r.verbs(), (std::vector<Verb>{V::Move, V::Line, V::Line, V::Line, V::Line, V::Line,
                                            V::Line, V::Line, V::Quad, V::Quad}));
    EXPECT_EQ(r.points()[3], (Point{6, 0}));
    EXPECT_EQ(r.points()[5], (Point{6, 2}));
}

TEST(SvgParse, NumbersWithoutSeparators) {
    EXPECT_EQ(parse_ok("M1.5.5").points()[0], (Point{1.5, 0.5}));
    EXPECT_EQ(parse_ok("M.5-.5").points()[0], (Point{0.5, -0.5}));
    EXPECT_EQ(parse_ok("M1-2").points()[0], (Point{1, -2}));
    EXPECT_EQ(parse_ok("M1e-3 2E+2").points()[0], (Point{1e-3, 200}));
    EXPECT_EQ(parse_ok("M1e2.5").points()[0], (Point{100, 0.5}));  // an exponent has no fraction
    EXPECT_EQ(parse_ok("M+3.,-4.").points()[0], (Point{3, -4}));
    EXPECT_EQ(parse_ok("M0,0L1,1").verbs().size(), 2u);
    EXPECT_EQ(parse_ok("\t\r\n\fM 1 2 \n").points()[0], (Point{1, 2}));
    // Too small for a double: zero, keeping the sign.
    Point tiny = parse_ok("M1e-400 -1e-400").points()[0];
    EXPECT_EQ(tiny.x, 0.0);
    EXPECT_TRUE(std::signbit(tiny.y));
    EXPECT_EQ(parse_ok("M0.000001e-320 0").points()[0].x, 0.0);
    EXPECT_EQ(parse_ok("M4.9e-324 0").points()[0].x, 4.9e-324);  // subnormals are kept
}

TEST(SvgParse, ArcFlagsNeedNoSeparators) {
    // a rx ry rotation large sweep x y: both spellings say rx=1 ry=1 rot=0 large=0 sweep=0/1.
    Path a = parse_ok("M0 0 a1 1 0 00 1 1");
    Path b = parse_ok("M0 0 a1,1,0,0,0,1,1");
    EXPECT_TRUE(bitwise_equal(a, b));
    Path c = parse_ok("M0 0 a1,1,0,0,1,1,1");
    Path d = parse_ok("M0 0 a1 1 0 011 1");
    EXPECT_TRUE(bitwise_equal(c, d));
    EXPECT_FALSE(bitwise_equal(a, c));  // the sweep flag picks the other quarter circle
    EXPECT_EQ(a.points().back(), (Point{1, 1}));
    EXPECT_EQ(c.points().back(), (Point{1, 1}));
    // A unit quarter circle from (0,0) to (1,1). Sweep 1 (angle increasing) goes from −90° to
    // 0° about (0,1); sweep 0 from 180° down to 90° about (1,0). The cubic's midpoint lies on
    // the circle (the standard arc cubic is exact at t = ½).
    Point mid_a = a.segment(0).eval(0.5), mid_c = c.segment(0).eval(0.5);
    EXPECT_NEAR(distance(mid_a, {1, 0}), 1.0, 1e-12);
    EXPECT_NEAR(distance(mid_c, {0, 1}), 1.0, 1e-12);
    EXPECT_LT(distance(mid_a, {1, 0}), 0.5 + distance(mid_a, {0, 1}));
}

TEST(SvgParse, EmptyDataIsAnEmptyPath) {
    EXPECT_TRUE(parse_ok("").empty());
    EXPECT_TRUE(parse_ok(" \n\t ").empty());
}

// --- Errors -----------------------------------------------------------------------------------

TEST(SvgParseErrors, NameTheOffsetAndWhatWasExpected) {
    EXPECT_EQ(parse_error("M 1"), "path data offset 3: expected a number, found end of data");
    EXPECT_EQ(parse_error("M 1 x"), "path data offset 4: expected a number, found 'x'");
    EXPECT_EQ(parse_error("L 1 2"), "path data offset 0: expected a moveto (M or m), found 'L'");
    EXPECT_EQ(parse_error("  10 20"), "path data offset 2: expected a moveto (M or m), found '1'");
    EXPECT_EQ(parse_error("M1 2 X3 4"), "path data offset 5: expected a command letter, found 'X'");
    EXPECT_EQ(parse_error("M1 2,L3 4"), "path data offset 5: expected a number, found 'L'");
    EXPECT_EQ(parse_error("M,1 2"), "path data offset 1: expected a number, found ','");
    EXPECT_EQ(parse_error("M1e 2"),
              "path data offset 3: expected digits of the exponent, found ' '");
    EXPECT_EQ(parse_error("M0 0 A1 1 0 2 0 1 1"),
              "path data offset 12: expected a flag (0 or 1), found '2'");
    EXPECT_EQ(parse_error("M0 0 Z 5 5"), "path data offset 7: expected a command letter, found '5'");
    EXPECT_EQ(parse_error("M1 2 \x01"),
              "path data offset 5: expected a command letter, found byte 0x01");
    EXPECT_EQ(parse_error("M. 1"), "path data offset 1: expected a number, found '.'");
    EXPECT_EQ(parse_error("M- 1"), "path data offset 1: expected a number, found '-'");
}

TEST(SvgParseErrors, RejectNonFiniteAndOverflowingNumbers) {
    EXPECT_EQ(parse_error("M1e400 0"), "path data offset 1: number out of range (overflows double)");
    EXPECT_EQ(parse_error("M0 -1.8e308"),
              "path data offset 3: number out of range (overflows double)");
    EXPECT_EQ(parse_error("M0.1e310 0"),
              "path data offset 1: number out of range (overflows double)");
    EXPECT_EQ(parse_error("Mnan 0"), "path data offset 1: expected a number, found 'n'");
    EXPECT_EQ(parse_error("M0 inf"), "path data offset 3: expected a number, found 'i'");
    // Each number fits, but the absolute coordinate does not.
    EXPECT_EQ(parse_error("M1e308 0 l1e308 0"), "path data offset 10: coordinates overflow double");
    EXPECT_EQ(parse_error("M0 0 1.7e308 0 h1.7e308"),
              "path data offset 16: coordinates overflow double");
}

TEST(SvgParseErrors, RejectBadArcTolerance) {
    for (double t : {0.0, -1.0, std::nan(""), HUGE_VAL}) {
        SvgParseOptions o;
        o.arc_tolerance = t;
        std::string e = parse_error("M0 0", o);
        EXPECT_EQ(e.rfind("SvgParseOptions::arc_tolerance: must be finite and > 0", 0), 0u) << e;
    }
}

TEST(SvgParseErrors, InputLongerThanTheLimitIsRefused) {
    std::string big(kMaxSvgPathLength + 1, ' ');
    big[0] = 'M';
    EXPECT_EQ(parse_error(big), "path data: 16777217 bytes exceeds the limit of 16777216 bytes");
    big.pop_back();
    big.replace(0, 4, "M1 1");
    EXPECT_EQ(parse_ok(big).points().size(), 1u);  // exactly at the limit is fine
}

TEST(SvgParseErrors, ArcsCannotExpandPastThePointLimit) {
    // With a tolerance far below rounding, every arc takes kMaxCubicsPerArc cubics; alternating
    // large arcs would need ~1536 points each, so a 100 kB input would ask for > 8 Mi points.
    SvgParseOptions o;
    o.arc_tolerance = 1e-300;
    std::string data = "M0 0";
    for (int i = 0; i < 6000; ++i) data += i % 2 ? "A1 1 0 1 1 0 0" : "A1 1 0 1 1 1 0";
    std::string e = parse_error(data, o);
    EXPECT_NE(e.find("path has more than " + std::to_string(kMaxSvgPathPoints) + " points"),
              std::string::npos)
        << e;
}

TEST(SvgParseErrors, RandomBytesNeverCrashAndAlwaysExplain) {
    // Strings over the path-data alphabet (plus a few strangers): each parse either succeeds
    // with a finite path or fails with a message naming an offset inside the data.
    std::mt19937_64 rng(43);
    const std::string alphabet = "MmLlHhVvCcSsQqTtAaZz0123456789+-.eE ,\t\n#x\x7f";
    int ok = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        std::string d = rng() % 2 ? "M" : "";
        std::size_t n = rng() % 40;
        for (std::size_t i = 0; i < n; ++i) d += alphabet[rng() % alphabet.size()];
        Expected<Path> r = parse_svg_path(d);
        if (r.ok()) {
            ++ok;
            ASSERT_TRUE(r->is_finite()) << d;
            // What parses also survives the round trip.
            Expected<Path> back = parse_svg_path(to_svg_path(*r));
            ASSERT_TRUE(back.ok()) << d;
            ASSERT_TRUE(bitwise_equal(*back, *r)) << d;
        } else {
            const std::string& m = r.error().message;
            ASSERT_EQ(m.rfind("path data offset ", 0), 0u) << m;
            std::size_t offset = std::stoul(m.substr(17));
            ASSERT_LE(offset, d.size()) << m;
        }
    }
    EXPECT_GT(ok, 100);  // the generator does reach valid data
}

// --- Arcs -------------------------------------------------------------------------------------

TEST(SvgArc, NegativeRadiiCountByTheirMagnitude) {
    EXPECT_TRUE(bitwise_equal(parse_ok("M0 0 A-5 -3 20 0 1 4 5"), parse_ok("M0 0 A5 3 20 0 1 4 5")));
}

TEST(SvgArc, ZeroRadiusIsALineAndAnArcToTheCurrentPointIsOmitted) {
    Path p = parse_ok("M1 1 A0 5 0 0 1 4 5 A3 0 0 0 1 1 1");
    EXPECT_EQ(p.verbs(), (std::vector<Verb>{V::Move, V::Line, V::Line}));
    Path q = parse_ok("M1 1 A5 5 0 0 1 1 1 L2 2");
    EXPECT_EQ(q.verbs(), (std::vector<Verb>{V::Move, V::Line}));
    EXPECT_EQ(q.points()[1], (Point{2, 2}));
}

namespace {

// A true elliptical arc chosen by its centre form, for checking the parser against.
struct TrueArc {
    Point c;
    double rx, ry, phi_rad, t0, dt;
    Point at(double t) const {
        double x = rx * std::cos(t), y = ry * std::sin(t);
        return c + Vec2{std::cos(phi_rad) * x - std::sin(phi_rad) * y,
                        std::sin(phi_rad) * x + std::cos(phi_rad) * y};
    }
    // The point in the ellipse's unit-circle frame.
    Vec2 unit(Point p) const {
        Vec2 d = p - c;
        double x = std::cos(phi_rad) * d.x + std::sin(phi_rad) * d.y;
        double y = -std::sin(phi_rad) * d.x + std::cos(phi_rad) * d.y;
        return {x / rx, y / ry};
    }
    // An upper bound on the distance from p to the ellipse: the distance to the ellipse point
    // on the same ray from the centre (in the unit frame).
    double distance_bound(Point p) const {
        Vec2 u = unit(p);
        double len = u.length();
        Vec2 on = u / len;
        Vec2 back{rx * on.x, ry * on.y};
        Point q = c + Vec2{std::cos(phi_rad) * back.x - std::sin(phi_rad) * back.y,
                           std::sin(phi_rad) * back.x + std::cos(phi_rad) * back.y};
        return distance(p, q);
    }
};

std::string num(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

// Checks that the path (M then cubics) follows `arc` within `tol`: every sampled point is within
// tol of the ellipse (bound above), and the sampled angles advance monotonically from t0 to
// t0 + dt, so the cubics cover the arc without leaving it. Returns the largest bound seen.
double check_arc(const Path& p, const TrueArc& arc, double tol, double slack) {
    double worst = 0.0;
    double sign = arc.dt > 0 ? 1.0 : -1.0;
    double prev_angle = arc.t0;  // unwrapped, relative progression along the sweep
    for (const PathSeg& s : p.segments()) {
        EXPECT_EQ(s.kind, SegKind::Cubic);
        for (int i = 0; i <= 64; ++i) {
            Point q = s.eval(i / 64.0);
            double d = arc.distance_bound(q);
            worst = std::max(worst, d);
            Vec2 u = arc.unit(q);
            double a = std::atan2(u.y, u.x);
            // Unwrap next to the previous angle.
            while (a - prev_angle > kPi) a -= 2 * kPi;
            while (a - prev_angle < -kPi) a += 2 * kPi;
            EXPECT_GE(sign * (a - prev_angle), -1e-9) << "angle went backwards";
            prev_angle = a;
        }
    }
    EXPECT_LE(worst, tol + slack);
    EXPECT_NEAR(prev_angle, arc.t0 + arc.dt, 1e-9);
    return worst;
}

}  // namespace

TEST(SvgArc, CubicsStayWithinToleranceOfRandomEllipses) {
    std::mt19937_64 rng(29);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    double worst_ratio = 0.0;
    int trials = 0;
    for (double tol : {1e-1, 1e-3, 1e-6}) {
        for (int trial = 0; trial < 700; ++trial) {
            TrueArc arc;
            arc.c = {200 * u01(rng) - 100, 200 * u01(rng) - 100};
            // Radii across four decades, rotations of any angle, sweeps from tiny to ~2π.
            arc.rx = std::pow(10.0, 4 * u01(rng) - 1);
            arc.ry = std::pow(10.0, 4 * u01(rng) - 1);
            double phi_deg = 720 * u01(rng) - 360;
            arc.phi_rad = phi_deg * kPi / 180;
            arc.t0 = 2 * kPi * u01(rng);
            double mag = (0.001 + 0.998 * u01(rng)) * 2 * kPi;
            // Near a half turn the end points barely determine the centre (it moves like
            // 1/√(1 − s²) with the half-chord s → 1), so rounding the end points to text would
            // move the ellipse itself; exact half turns are tested below through F.6.6.
            if (std::fabs(mag - kPi) < 0.05) mag += 0.1;
            bool sweep = u01(rng) < 0.5;
            arc.dt = sweep ? mag : -mag;
            Point a = arc.at(arc.t0), b = arc.at(arc.t0 + arc.dt);
            std::string data = "M" + num(a.x) + " " + num(a.y) + "A" + num(arc.rx) + " " +
                               num(arc.ry) + " " + num(phi_deg) + " " + (mag > kPi ? "1" : "0") +
                               " " + (sweep ? "1" : "0") + " " + num(b.x) + " " + num(b.y);
            SvgParseOptions o;
            o.arc_tolerance = tol;
            Path p = parse_ok(data, o);
            ASSERT_EQ(p.points().back(), b) << data;  // ends exactly at the given end point
            // Slack: the endpoints were rounded to text and the centre form re-derived from
            // them, which moves the ellipse by ~1e-13 relative to its size.
            double slack = 1e-12 * std::max({arc.rx, arc.ry, 100.0});
            SCOPED_TRACE(data);
            double worst = check_arc(p, arc, tol, slack);
            worst_ratio = std::max(worst_ratio, worst / tol);
            ++trials;
        }
    }
    // The bound is not wildly loose: some arc gets within a factor 2 of it.
    EXPECT_GT(worst_ratio, 0.5);
    std::printf("arcs checked: %d, largest error / tolerance = %.3f\n", trials, worst_ratio);
}

TEST(SvgArc, RadiiTooSmallAreScaledUpToAHalfEllipse) {
    // SVG 1.1 F.6.6: with radii too small to span the chord, the radii are scaled uniformly
    // until they just do — the arc becomes exactly half the ellipse, centred on the chord.
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    for (int trial = 0; trial < 500; ++trial) {
        TrueArc arc;
        arc.c = {100 * u01(rng), 100 * u01(rng)};
        arc.rx = 1 + 50 * u01(rng);
        arc.ry = 1 + 50 * u01(rng);
        double phi_deg = 360 * u01(rng);
        arc.phi_rad = phi_deg * kPi / 180;
        arc.t0 = 2 * kPi * u01(rng);
        bool sweep = trial % 2 == 0;
        arc.dt = sweep ? kPi : -kPi;
        Point a = arc.at(arc.t0), b = arc.at(arc.t0 + arc.dt);
        double shrink = trial % 3 == 0 ? 1e-3 : 0.5;  // either flag: both halves are π
        std::string data = "M" + num(a.x) + " " + num(a.y) + "A" + num(arc.rx * shrink) + " " +
                           num(arc.ry * shrink) + " " + num(phi_deg) + " " +
                           (trial % 4 < 2 ? "1" : "0") + " " + (sweep ? "1" : "0") + " " +
                           num(b.x) + " " + num(b.y);
        SCOPED_TRACE(data);
        check_arc(parse_ok(data), arc, 1e-3, 1e-10);
    }
}

TEST(SvgArc, CircleAreaIsWithinPerimeterTimesTolerance) {
    // Two half-circle arcs. The cubic error is outward only, so the area exceeds πr² by at most
    // perimeter × tolerance.
    auto circle = [](double r, const char* sweep) {
        return "M" + num(r) + " 0A" + num(r) + " " + num(r) + " 0 0 " + sweep + " " + num(-r) +
               " 0A" + num(r) + " " + num(r) + " 0 0 " + sweep + " " + num(r) + " 0Z";
    };
    for (double r : {0.5, 1.0, 37.0, 1000.0}) {
        for (double tol : {1e-2, 1e-3, 1e-6}) {
            SvgParseOptions o;
            o.arc_tolerance = tol;
            Path p = parse_ok(circle(r, "1"), o);
            double exact = kPi * r * r;
            double area = p.signed_area();
            EXPECT_GE(area, exact - 1e-12 * exact) << r << " " << tol;
            EXPECT_LE(area, exact + 2 * kPi * r * tol) << r << " " << tol;
            EXPECT_EQ(p.contour_windings(), std::vector<Winding>{Winding::Clockwise});
            // sweep-flag 0 runs the other way round.
            EXPECT_NEAR(parse_ok(circle(r, "0"), o).signed_area(), -area, 1e-12 * exact);
        }
    }
}

TEST(SvgArc, HugeRadiusAgainstAShortChordStaysAccurate) {
    // Radius 1e15 on a chord of 2: the true arc is within 5e-16 of the chord. Computing points as
    // centre + r·(cos t, sin t) would cancel catastrophically (the centre is 1e15 away and
    // doubles carry ~16 digits: errors ~0.1); placing them relative to the start point must not.
    for (const char* data : {"M-1 0A1e15 1e15 0 0 1 1 0", "M-1 0A1e15 1e15 30 0 0 1 0",
                             "M-1 0A1e15 2e14 -70 0 1 1 0"}) {
        Path p = parse_ok(data);
        ASSERT_GT(p.segment_count(), 0u);
        for (const PathSeg& s : p.segments())
            for (int i = 0; i <= 16; ++i) {
                Point q = s.eval(i / 16.0);
                EXPECT_NEAR(q.y, 0.0, 1e-9) << data;
                EXPECT_GE(q.x, -1.0 - 1e-9) << data;
                EXPECT_LE(q.x, 1.0 + 1e-9) << data;
            }
    }
}

// --- Writing and the round trip ---------------------------------------------------------------

TEST(SvgWrite, OneAbsoluteCommandPerVerbInShortestForm) {
    Path p;
    p.move_to({0.5, -0.5});
    p.line_to({1e21, 1e-7});
    p.quad_to({1.5, 0.25}, {-0.0, 3});
    p.cubic_to({1, 2}, {3, 4}, {5, 6});
    p.close();
    EXPECT_EQ(to_svg_path(p), "M.5-.5L1e21 1e-7Q1.5.25-0 3C1 2 3 4 5 6Z");
    EXPECT_EQ(to_svg_path(Path{}), "");
    Path q;
    q.move_to({1.0 / 3.0, 2});
    EXPECT_EQ(to_svg_path(q), "M.3333333333333333 2");
    EXPECT_EQ(to_svg_path(q, 3), "M.333 2");
}

namespace {

// Doubles from every corner: uniform bit patterns (all exponents, subnormals, −0), integers and
// short decimals (which exercise the separator-dropping rules).
double random_double(std::mt19937_64& rng) {
    switch (rng() % 4) {
        case 0: {
            for (;;) {
                std::uint64_t bits = rng();
                double d;
                std::memcpy(&d, &bits, sizeof d);
                if (std::isfinite(d)) return d;
            }
        }
        case 1: return static_cast<double>(static_cast<int>(rng() % 2001) - 1000);
        case 2: return static_cast<double>(static_cast<int>(rng() % 20001) - 10000) / 100.0;
        default: return (rng() % 2 ? -1.0 : 1.0) * static_cast<double>(rng() % 1000) * 1e-3;
    }
}

Path random_svg_path(std::mt19937_64& rng) {
    Path p;
    auto pt = [&] { return Point{random_double(rng), random_double(rng)}; };
    int n = 1 + static_cast<int>(rng() % 12);
    for (int i = 0; i < n; ++i) {
        switch (rng() % 6) {
            case 0: p.move_to(pt()); break;
            case 1: p.line_to(pt()); break;
            case 2: p.quad_to(pt(), pt()); break;
            case 3: p.cubic_to(pt(), pt(), pt()); break;
            case 4: p.close(); break;
            default: p.line_to(pt()); p.close(); break;
        }
    }
    return p;
}

}  // namespace

TEST(SvgRoundTrip, WriteThenParseGivesTheSamePathBitForBit) {
    std::mt19937_64 rng(37);
    for (int trial = 0; trial < 5000; ++trial) {
        Path p = random_svg_path(rng);
        std::string text = to_svg_path(p);
        Expected<Path> back = parse_svg_path(text);
        ASSERT_TRUE(back.ok()) << text << " → " << back.error().message;
        ASSERT_TRUE(bitwise_equal(*back, p)) << text;
        ASSERT_EQ(to_svg_path(*back), text);
    }
}

TEST(SvgRoundTrip, ParsedArcsWriteAndReadBackExactly) {
    Path p = parse_ok("M10 80 A45 45 0 0 0 125 125 a25 60 -30 1 1 -50 -50 T 200 80 s 10 10 20 0 z");
    Path back = parse_ok(to_svg_path(p));
    EXPECT_TRUE(bitwise_equal(back, p));
}
