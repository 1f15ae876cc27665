// Stroking: exact shapes for lines, the annulus of a circle, joins and caps, miter limits,
// dashes, degenerate input and errors. (Rendering against a distance reference, the golden glyph
// and the offset-accuracy sweep are in stroke_render_test.cpp and stroke_offset_test.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "bezel/stroke.hpp"

namespace bezel {
namespace {

constexpr double kPi = 3.14159265358979323846;

Path svg(const char* d) {
    SvgParseOptions o;
    o.arc_tolerance = 1e-9;
    auto p = parse_svg_path(d, o);
    EXPECT_TRUE(p.ok()) << d;
    return p.ok() ? *p : Path{};
}

Path stroked(const Path& p, const StrokeStyle& s) {
    auto r = stroke(p, s);
    EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().message);
    return r.ok() ? *r : Path{};
}

// Distance from q to the segment ab.
double seg_distance(Point q, Point a, Point b) {
    Vec2 ab = b - a;
    double l2 = ab.length_squared();
    double t = l2 > 0 ? std::clamp((q - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
    return distance(q, a + ab * t);
}

double polyline_distance(Point q, const std::vector<Point>& pts) {
    double best = HUGE_VAL;
    for (std::size_t i = 0; i + 1 < pts.size(); ++i)
        best = std::min(best, seg_distance(q, pts[i], pts[i + 1]));
    return best;
}

// Points along every segment of `p` (20 per segment, ends included).
std::vector<Point> sample_outline(const Path& p) {
    std::vector<Point> out;
    for (const PathSeg& s : p.segments())
        for (int k = 0; k <= 20; ++k) out.push_back(s.eval(k / 20.0));
    return out;
}

TEST(Stroke, StraightSegmentIsExactRectangle) {
    Path line = svg("M10 10 L40 50");  // length 50, direction (0.6, 0.8)
    StrokeStyle s;
    s.width = 6;
    Path out = stroked(line, s);
    ASSERT_EQ(out.contour_count(), 1u);
    EXPECT_NEAR(std::fabs(out.signed_area()), 50.0 * 6.0, 1e-9);
    // The corners are the ends moved ±3 along the normal (−0.8, 0.6), nothing else.
    Vec2 n{-0.8 * 3, 0.6 * 3};
    std::vector<Point> want{Point{10, 10} + n, Point{40, 50} + n, Point{40, 50} - n,
                            Point{10, 10} - n};
    for (const Point& p : out.points()) {
        double best = HUGE_VAL;
        for (const Point& w : want) best = std::min(best, distance(p, w));
        EXPECT_LT(best, 1e-12) << p.x << "," << p.y;
    }
    for (const Point& w : want) {
        double best = HUGE_VAL;
        for (const Point& p : out.points()) best = std::min(best, distance(p, w));
        EXPECT_LT(best, 1e-12);
    }
}

TEST(Stroke, CapsAddTheirExactArea) {
    Path line = svg("M0 0 L30 0");
    StrokeStyle s;
    s.width = 4;
    s.cap = LineCap::Square;
    EXPECT_NEAR(std::fabs(stroked(line, s).signed_area()), 34.0 * 4.0, 1e-9);
    s.cap = LineCap::Round;
    s.tolerance = 1e-4;
    EXPECT_NEAR(std::fabs(stroked(line, s).signed_area()), 30.0 * 4.0 + kPi * 4.0, 2e-3);
}

TEST(Stroke, CircleStrokeIsAnnulusOfArea2PiRW) {
    for (double r : {10.0, 50.0}) {
        for (double w : {1.0, 4.0, 12.0}) {
            Path circle = svg(r == 10.0 ? "M10 0 A10 10 0 0 1 -10 0 A10 10 0 0 1 10 0 Z"
                                        : "M50 0 A50 50 0 0 1 -50 0 A50 50 0 0 1 50 0 Z");
            StrokeStyle s;
            s.width = w;
            s.tolerance = 1e-3;
            Path out = stroked(circle, s);
            // Two contours, outer and inner, wound alike relative to the ring, no overlap: the
            // signed area is the ring's. Each offset is within tol of its circle, so the area is
            // within tol × (both perimeters) = 4πr·tol.
            EXPECT_NEAR(std::fabs(out.signed_area()), 2 * kPi * r * w, 4 * kPi * r * s.tolerance)
                << "r=" << r << " w=" << w;
            for (const Point& q : sample_outline(out)) {
                double d = std::fabs(std::hypot(q.x, q.y) - r);
                EXPECT_NEAR(d, w / 2, s.tolerance) << "r=" << r << " w=" << w;
            }
        }
    }
}

TEST(Stroke, OutlineIsOneSignOfWinding) {
    // Every region the stroker emits winds the same way (negative signed area), so non-zero
    // never cancels pieces. A closed square clockwise on screen: its right offset runs back
    // round the outside (−22², miter corners); its left offset (+perp, here inside) runs with
    // the path round the hole (+18²), less a 1×1 loop at each corner where the inner side goes
    // through the corner point — loops inside the ring, wound like it.
    Path sq = svg("M0 0 H20 V20 H0 Z");
    StrokeStyle s;
    s.width = 2;
    Path out = stroked(sq, s);
    auto areas = out.contour_areas();
    ASSERT_EQ(areas.size(), 2u);
    EXPECT_NEAR(areas[0], 18.0 * 18.0 - 4.0, 1e-9);
    EXPECT_NEAR(areas[1], -22.0 * 22.0, 1e-9);
    // The same square drawn the other way round strokes to the same ring, same sign.
    Path back = stroked(sq.reversed(), s);
    EXPECT_NEAR(back.signed_area(), out.signed_area(), 1e-9);
    EXPECT_LT(out.signed_area(), 0);
}

TEST(Stroke, RoundJoinsStayWithinHalfWidthOfPath) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> coord(0, 100), width(0.5, 20);
    for (int trial = 0; trial < 50; ++trial) {
        std::vector<Point> pts;
        Path p;
        for (int i = 0; i < 8; ++i) {
            Point q{coord(rng), coord(rng)};
            pts.push_back(q);
            if (i == 0) p.move_to(q); else p.line_to(q);
        }
        StrokeStyle s;
        s.width = width(rng);
        s.join = LineJoin::Round;
        s.cap = LineCap::Round;
        s.tolerance = 0.01;
        Path out = stroked(p, s);
        double worst = 0;
        for (const Point& q : sample_outline(out)) worst = std::max(worst, polyline_distance(q, pts));
        EXPECT_LE(worst, s.width / 2 + s.tolerance) << "trial " << trial;
    }
}

// The farthest outline point from the joint of two length-100 segments turning by `turn`,
// among points within 50 of it (the far ends excluded).
double farthest_from_joint(double turn, double limit) {
    Path p;
    p.move_to({-100, 0});
    p.line_to({0, 0});
    p.line_to({100 * std::cos(turn), 100 * std::sin(turn)});
    StrokeStyle s;
    s.width = 2;
    s.join = LineJoin::Miter;
    s.miter_limit = limit;
    Path out = stroked(p, s);
    double best = 0;
    for (const Point& q : out.points())
        if (q.length() < 50) best = std::max(best, q.length());
    return best;
}

TEST(Stroke, MiterLimitSwitchesToBevelAtTheSvgAngle) {
    // SVG: miter length / width = 1/sin(φ/2), φ the angle between the segments = π − turn. For
    // limit L the switch is at turn τ = 2·acos(1/L): below it a miter tip at h/cos(τ/2).
    for (double limit : {1.5, 2.0, 4.0, 10.0}) {
        double critical = 2 * std::acos(1 / limit);
        double below = critical - 1e-3, above = critical + 1e-3;
        EXPECT_NEAR(farthest_from_joint(below, limit), 1.0 / std::cos(below / 2), 1e-9);
        EXPECT_NEAR(farthest_from_joint(above, limit), 1.0, 1e-9);  // bevel: corners at h
    }
    EXPECT_NEAR(farthest_from_joint(kPi / 2, 4), std::sqrt(2.0), 1e-9);  // square corner
}

TEST(Stroke, BevelAndRoundJoinAreasOfRightAngle) {
    // An L of two length-10 segments, width 2: strips 2·(10·2) minus the shared 1×1 inner
    // square counted twice... measured instead as the bevel/round wedge beyond the miter-free
    // union: bevel adds the triangle ½h², round the quarter disc πh²/4. Areas are compared
    // through the difference of the two (the strips and inner overlap cancel).
    Path p = svg("M-10 0 L0 0 L0 10");
    StrokeStyle s;
    s.width = 2;
    s.join = LineJoin::Bevel;
    double bevel = std::fabs(stroked(p, s).signed_area());
    s.join = LineJoin::Round;
    s.tolerance = 1e-5;
    double round = std::fabs(stroked(p, s).signed_area());
    s.join = LineJoin::Miter;
    double miter = std::fabs(stroked(p, s).signed_area());
    EXPECT_NEAR(miter - bevel, 0.5, 1e-9);
    EXPECT_NEAR(round - bevel, kPi / 4 - 0.5, 1e-4);
}

TEST(Stroke, ZeroLengthContoursBecomeDotsWithRoundOrSquareCaps) {
    StrokeStyle s;
    s.width = 4;
    s.tolerance = 1e-5;
    s.cap = LineCap::Round;
    EXPECT_NEAR(std::fabs(stroked(svg("M5 5 Z"), s).signed_area()), kPi * 4, 1e-3);
    EXPECT_NEAR(std::fabs(stroked(svg("M5 5 L5 5"), s).signed_area()), kPi * 4, 1e-3);
    s.cap = LineCap::Square;
    EXPECT_NEAR(std::fabs(stroked(svg("M5 5 L5 5 L5 5"), s).signed_area()), 16.0, 1e-12);
    s.cap = LineCap::Butt;
    EXPECT_TRUE(stroked(svg("M5 5 L5 5"), s).empty());
    s.cap = LineCap::Round;
    EXPECT_TRUE(stroked(svg("M5 5"), s).empty());  // a lone moveto is not stroked (SVG)
}

TEST(Stroke, DegenerateInputGivesFiniteOutline) {
    const char* cases[] = {
        "M0 0 L0 0 L10 0 L10 0 L10 0 L20 5",     // repeated points
        "M0 0 C0 0 0 0 0 0",                     // a cubic collapsed to a point
        "M0 0 C10 0 -5 0 5 0",                   // collinear, doubling back twice (cusps)
        "M0 0 C0 0 10 10 10 10",                 // coincident handles
        "M0 0 C100 100 0 100 100 0",             // a cusp inside
        "M0 0 Q10 0 5 0",                        // a quad folding back on its line
        "M0 0 C30 0 30 0 30 30 Z",               // closed, coincident inner handles
        "M0 0 L10 0 L0 0",                       // a 180° turn
        "M1e6 1e6 L1e6 1e6 C1e6 1e6 1000001 1e6 1e6 1000001",
    };
    for (const char* d : cases) {
        for (LineJoin j : {LineJoin::Miter, LineJoin::Round, LineJoin::Bevel}) {
            StrokeStyle s;
            s.width = 3;
            s.join = j;
            s.cap = LineCap::Round;
            auto out = stroke(svg(d), s);
            ASSERT_TRUE(out.ok()) << d;
            EXPECT_TRUE(out->is_finite()) << d;
            EXPECT_FALSE(out->empty()) << d;
        }
    }
}

double total_length(const Path& p) {
    double sum = 0;
    for (const PathSeg& s : p.segments()) sum += s.to_cubic().arclen(1e-9);
    return sum;
}

TEST(Stroke, DashesCoverTheOnLengthOfThePattern) {
    Path line = svg("M0 0 L100 0");
    auto d = dash(line, {10, 5}, 0);
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(d->contour_count(), 7u);  // on at 0,15,...,90
    EXPECT_NEAR(total_length(*d), 70.0, 1e-9);

    // Offset 12: starts 2 into the gap, so the first dash starts at 3.
    d = dash(line, {10, 5}, 12);
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(d->points().front().x, 3.0);
    // A negative offset is the same phase shifted backwards: −3 ≡ 12 for period 15.
    auto e = dash(line, {10, 5}, -3);
    ASSERT_TRUE(e.ok());
    EXPECT_EQ(d->contour_count(), e->contour_count());
    EXPECT_NEAR(total_length(*d), total_length(*e), 1e-9);

    // An odd list repeats: "3" is "3,3".
    d = dash(line, {3}, 0);
    ASSERT_TRUE(d.ok());
    EXPECT_NEAR(total_length(*d), 51.0, 1e-9);  // 17 dashes of 3 (the last 96..99)

    // On a circle of circumference 2π·20 the on-length is the pattern's share, to arc-length
    // accuracy. With offset 1 the last dash runs over the closing point into the first: SVG
    // makes them one dash, so one contour fewer than the pattern's on-intervals.
    Path circle = svg("M20 0 A20 20 0 0 1 -20 0 A20 20 0 0 1 20 0 Z");
    double len = total_length(circle);
    for (double offset : {1.0, 4.0}) {
        d = dash(circle, {7, 3}, offset);
        ASSERT_TRUE(d.ok());
        double want = 0, pos = -offset;
        int pieces = 0;
        bool through_start = false;
        for (; pos < len; pos += 10) {
            want += std::max(0.0, std::min(pos + 7, len) - std::max(pos, 0.0));
            ++pieces;
            through_start = pos + 7 > len;
        }
        EXPECT_NEAR(total_length(*d), want, 1e-6) << offset;
        EXPECT_EQ(d->contour_count(), static_cast<std::size_t>(pieces - (through_start ? 1 : 0)))
            << offset;
        EXPECT_EQ(through_start, offset == 1.0);
    }
}

TEST(Stroke, DashedStrokeEqualsStrokeOfDashes) {
    Path p = svg("M0 0 C30 -20 60 40 90 0 L120 30");
    StrokeStyle s;
    s.width = 3;
    s.join = LineJoin::Round;
    s.dashes = {12, 4, 2, 4};
    s.dash_offset = 5;
    Path a = stroked(p, s);
    auto d = dash(p, s.dashes, s.dash_offset);
    ASSERT_TRUE(d.ok());
    s.dashes.clear();
    EXPECT_EQ(a, stroked(*d, s));
}

TEST(Stroke, BadInputsAreErrors) {
    Path p = svg("M0 0 L10 0");
    auto fails = [&](StrokeStyle s, const char* what) {
        auto r = stroke(p, s);
        ASSERT_FALSE(r.ok()) << what;
        EXPECT_NE(r.error().message.find(what), std::string::npos) << r.error().message;
    };
    const double nan = std::numeric_limits<double>::quiet_NaN();
    StrokeStyle s;
    s.width = 0; fails(s, "width");
    s.width = -1; fails(s, "width");
    s.width = nan; fails(s, "width");
    s.width = HUGE_VAL; fails(s, "width");
    s = {}; s.miter_limit = 0.5; fails(s, "miter");
    s = {}; s.miter_limit = nan; fails(s, "miter");
    s = {}; s.tolerance = 0; fails(s, "tolerance");
    s = {}; s.tolerance = nan; fails(s, "tolerance");
    s = {}; s.dashes = {1, -1}; fails(s, "dash pattern entry 1");
    s = {}; s.dashes = {0, 0}; fails(s, "dash pattern");
    s = {}; s.dashes = {1, nan}; fails(s, "dash pattern entry 1");
    s = {}; s.dashes = {1, 1}; s.dash_offset = HUGE_VAL; fails(s, "dash offset");
    // A tiny dash over a long path meets kMaxDashes before anything is allocated for it.
    s = {}; s.dashes = {1e-6, 1e-6};
    Path long_line = svg("M0 0 L1e6 0");
    auto r = stroke(long_line, s);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("more than the " + std::to_string(kMaxDashes) + " allowed"),
              std::string::npos)
        << r.error().message;
    // 39 995 dashes are within kMaxDashes, and dash() makes them. Stroked with round caps
    // (eight verbs each at least: Move, two sides, two arcs per cap, Close) they would pass
    // kMaxStrokeSegments, which stroke() says before making any ("dashes of at least").
    s = {}; s.dashes = {1, 1}; s.cap = LineCap::Round;
    Path line = svg("M0 0 L79990 0");
    auto round = stroke(line, s);
    ASSERT_FALSE(round.ok());
    EXPECT_NE(round.error().message.find("dashes of at least 8 verbs"), std::string::npos)
        << round.error().message;
    EXPECT_NE(round.error().message.find(std::to_string(kMaxStrokeSegments) + " segments"),
              std::string::npos)
        << round.error().message;
    auto pieces = dash(line, s.dashes, 0);
    ASSERT_TRUE(pieces.ok()) << pieces.error().message;
    // A Move and a Line per dash; the last one is empty, where the line ends.
    EXPECT_EQ(pieces->verbs().size(), 2u * 39996);
    // The bound is a lower one: 24 995 butt-capped dashes (six verbs each) are stroked.
    s.cap = LineCap::Butt;
    auto butt = stroke(svg("M0 0 L49990 0"), s);
    ASSERT_TRUE(butt.ok()) << butt.error().message;
    EXPECT_EQ(butt->verbs().size(), 6u * 24995);
    EXPECT_LE(butt->verbs().size(), kMaxStrokeSegments);

    Path bad;
    bad.move_to({0, 0});
    bad.line_to({nan, 1});
    auto rb = stroke(bad, StrokeStyle{});
    ASSERT_FALSE(rb.ok());
    EXPECT_NE(rb.error().message.find("non-finite"), std::string::npos);
}

}  // namespace
}  // namespace bezel
