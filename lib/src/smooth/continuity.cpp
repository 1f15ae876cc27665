// Continuity of a path's joints: C0 / G1 / C1 / C2 from the derivative conditions at t = 1 of
// the incoming piece and t = 0 of the outgoing one (smooth.hpp states the tests and the scale).
//
// For a cubic C with control points P₀..P₃ (bezier.hpp):
//     C′(0) = 3(P₁ − P₀),  C′(1) = 3(P₃ − P₂),
//     C″(0) = 6(P₀ − 2P₁ + P₂),  C″(1) = 6(P₁ − 2P₂ + P₃).
// Lines and quadratics are compared as their exact cubic elevations (same parametrisation, so
// the same derivatives).
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "bezel/smooth.hpp"
#include "smooth/input.hpp"

namespace bezel {

namespace {

constexpr double kPi = 3.14159265358979323846;

double diagonal(const CubicBez& c) {
    Rect r = c.control_box();
    return std::hypot(r.width(), r.height());
}

// |a − b| / max(|a|, |b|, size); 0 when all three are 0 (two vanishing vectors are equal).
double relative_difference(Vec2 a, Vec2 b, double size) {
    double scale = std::max({a.length(), b.length(), size});
    return scale > 0.0 ? (a - b).length() / scale : 0.0;
}

JointReport classify(const CubicBez& a, const CubicBez& b, double tolerance) {
    JointReport r;
    r.point = b.p0;
    const double size = std::max(diagonal(a), diagonal(b));
    r.gap = size > 0.0 ? distance(a.p3, b.p0) / size : 0.0;

    const Vec2 ta = a.tangent(1.0), tb = b.tangent(0.0);
    // atan2(|sin|, cos) is accurate at every angle, unlike acos(dot) near 0.
    // A piece collapsed to a point has no direction: no tangent continuity through it.
    r.angle_rad = (ta == Vec2{} || tb == Vec2{})
                      ? kPi
                      : std::atan2(std::fabs(ta.cross(tb)), ta.dot(tb));

    r.d1_error = relative_difference(a.deriv_at(1.0), b.deriv_at(0.0), size);
    r.d2_error = relative_difference(a.deriv2_at(1.0), b.deriv2_at(0.0), size);

    // Each class needs its own test and every lower one (a chain, see smooth.hpp).
    if (!(r.gap <= tolerance)) r.continuity = Continuity::Broken;
    else if (!(r.angle_rad <= tolerance)) r.continuity = Continuity::C0;
    else if (!(r.d1_error <= tolerance)) r.continuity = Continuity::G1;
    else if (!(r.d2_error <= tolerance)) r.continuity = Continuity::C1;
    else r.continuity = Continuity::C2;
    return r;
}

Status check_tolerance(double tolerance) {
    if (std::isfinite(tolerance) && tolerance > 0.0) return ok_status();
    return Error{"continuity: tolerance " + std::to_string(tolerance) +
                 " is not a finite number > 0"};
}

}  // namespace

const char* continuity_name(Continuity c) {
    switch (c) {
        case Continuity::Broken: return "broken";
        case Continuity::C0: return "C0";
        case Continuity::G1: return "G1";
        case Continuity::C1: return "C1";
        case Continuity::C2: return "C2";
    }
    return "broken";
}

Expected<std::vector<JointReport>> analyze_joints(const std::vector<CubicBez>& pieces,
                                                  bool closed, double tolerance) {
    if (auto ok = check_tolerance(tolerance); !ok) return ok.error();
    for (std::size_t i = 0; i < pieces.size(); ++i)
        if (!pieces[i].is_finite())
            return Error{"continuity: piece " + std::to_string(i) + " has a point that is not finite"};
    std::vector<JointReport> out;
    const std::size_t n = pieces.size();
    const std::size_t joints = n == 0 ? 0 : (closed ? n : n - 1);
    for (std::size_t i = 0; i < joints; ++i) {
        JointReport r = classify(pieces[i], pieces[(i + 1) % n], tolerance);
        r.incoming = i;
        r.outgoing = (i + 1) % n;
        out.push_back(r);
    }
    return out;
}

Expected<std::vector<JointReport>> analyze_continuity(const Path& path, double tolerance) {
    if (auto ok = check_tolerance(tolerance); !ok) return ok.error();
    if (!path.is_finite()) return Error{"continuity: the path has a point that is not finite"};

    // Which contours end in Close (contours are numbered by their Move verbs).
    std::vector<bool> contour_closed;
    for (Verb v : path.verbs()) {
        if (v == Verb::Move) contour_closed.push_back(false);
        else if (v == Verb::Close && !contour_closed.empty()) contour_closed.back() = true;
    }

    std::vector<JointReport> out;
    std::vector<CubicBez> pieces;
    std::vector<std::size_t> indices;
    auto flush = [&](std::size_t contour) {
        const bool closed = contour < contour_closed.size() && contour_closed[contour];
        const std::size_t n = pieces.size();
        const std::size_t joints = n == 0 ? 0 : (closed ? n : n - 1);
        for (std::size_t i = 0; i < joints; ++i) {
            JointReport r = classify(pieces[i], pieces[(i + 1) % n], tolerance);
            r.contour = contour;
            r.incoming = indices[i];
            r.outgoing = indices[(i + 1) % n];
            out.push_back(r);
        }
        pieces.clear();
        indices.clear();
    };
    std::size_t contour = 0;
    for (const PathSeg& seg : path.segments()) {
        if (!pieces.empty() && seg.contour != contour) flush(contour);
        contour = seg.contour;
        pieces.push_back(seg.to_cubic());
        indices.push_back(seg.index);
    }
    if (!pieces.empty()) flush(contour);
    return out;
}

}  // namespace bezel
