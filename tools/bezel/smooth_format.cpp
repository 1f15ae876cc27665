// The text forms of `bezel smooth` (JSON, SVG path data) and `bezel continuity` (text, JSON).
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_common.hpp"
#include "smooth_output.hpp"

namespace bezel::cli {
namespace {

using nlohmann::json;

json pair(Point p) { return json::array({p.x, p.y}); }

}  // namespace

std::string format_smooth_json(const SmoothReport& r) {
    json doc = json::object();
    if (r.polyline) {
        json pts = json::array();
        for (const Point& p : r.points) pts.push_back(pair(p));
        doc["points"] = std::move(pts);
    } else {
        json segs = json::array();
        for (const PathSeg& s : r.curve.segments()) {
            CubicBez c = s.to_cubic();
            segs.push_back(json::array({pair(c.p0), pair(c.p1), pair(c.p2), pair(c.p3)}));
        }
        doc["segments"] = std::move(segs);
    }
    return doc.dump() + "\n";
}

std::string format_smooth_path(const SmoothReport& r) {
    if (!r.polyline) return to_svg_path(r.curve) + "\n";
    Path p;
    for (std::size_t i = 0; i < r.points.size(); ++i) {
        if (i == 0) p.move_to(r.points[i]);
        else p.line_to(r.points[i]);
    }
    if (r.closed) p.close();
    return to_svg_path(p) + "\n";
}

std::string format_continuity_text(const std::vector<JointReport>& joints, double tolerance) {
    std::ostringstream s;
    s << joints.size() << (joints.size() == 1 ? " joint" : " joints") << ", tolerance "
      << plain_number(tolerance) << " (relative)\n";
    for (std::size_t i = 0; i < joints.size(); ++i) {
        const JointReport& j = joints[i];
        s << "joint " << i << ": segment " << j.incoming << " -> " << j.outgoing << " (contour "
          << j.contour << ") at " << plain_number(j.point.x) << "," << plain_number(j.point.y) << ": "
          << continuity_name(j.continuity) << "  [angle " << plain_number(j.angle_rad) << " rad, d1 "
          << plain_number(j.d1_error) << ", d2 " << plain_number(j.d2_error) << "]\n";
    }
    return s.str();
}

std::string format_continuity_json(const std::vector<JointReport>& joints, double tolerance) {
    // ordered_json keeps the keys in the documented order.
    using ojson = nlohmann::ordered_json;
    ojson list = ojson::array();
    for (const JointReport& j : joints) {
        ojson o;
        o["contour"] = j.contour;
        o["incoming"] = j.incoming;
        o["outgoing"] = j.outgoing;
        o["point"] = ojson::array({j.point.x, j.point.y});
        o["class"] = continuity_name(j.continuity);
        o["gap"] = j.gap;
        o["angle_rad"] = j.angle_rad;
        o["d1_error"] = j.d1_error;
        o["d2_error"] = j.d2_error;
        list.push_back(std::move(o));
    }
    ojson doc;
    doc["tolerance"] = tolerance;
    doc["joints"] = std::move(list);
    return doc.dump() + "\n";
}

}  // namespace bezel::cli
