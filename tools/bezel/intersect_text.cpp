// The text and JSON forms of `bezel intersect` (the JSON shape is documented in
// intersect_output.hpp and is a stable contract: keys in that order, 17 significant digits).
#include <cstdio>
#include <string>

#include "intersect_output.hpp"

namespace bezel::cli {
namespace {

// 17 significant digits: every double reads back to itself.
std::string exact_number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

std::string idx(std::size_t i) { return std::to_string(i); }

}  // namespace

std::string format_intersect_text(const IntersectReport& r) {
    const auto& xs = r.result.intersections;
    const auto& os = r.result.overlaps;
    std::string out = r.self ? "self-intersections of one path\n" : "intersections of two paths\n";
    out += std::to_string(xs.size()) + (xs.size() == 1 ? " intersection" : " intersections");
    out += ", " + std::to_string(os.size()) + (os.size() == 1 ? " overlap" : " overlaps") + "\n";
    for (const PathIntersection& p : xs) {
        out += "  " + std::string(intersection_kind_name(p.kind)) + " at (" + exact_number(p.point.x) + ", " +
               exact_number(p.point.y) + "): A seg " + idx(p.seg_a) + " t=" + exact_number(p.t_a) + ", " +
               (r.self ? "A" : "B") + " seg " + idx(p.seg_b) + " t=" + exact_number(p.t_b) + "\n";
    }
    for (const PathOverlap& o : os) {
        out += "  overlap: A seg " + idx(o.seg_a) + " t=[" + exact_number(o.t_a0) + ", " + exact_number(o.t_a1) + "], " +
               (r.self ? "A" : "B") + " seg " + idx(o.seg_b) + " t=[" + exact_number(o.t_b0) + ", " +
               exact_number(o.t_b1) + "]\n";
    }
    return out;
}

std::string format_intersect_json(const IntersectReport& r) {
    std::string out = "{\"intersections\": [";
    const char* sep = "\n  ";
    for (const PathIntersection& p : r.result.intersections) {
        out += sep;
        sep = ",\n  ";
        out += "{\"seg_a\": " + idx(p.seg_a) + ", \"t_a\": " + exact_number(p.t_a) + ", \"seg_b\": " +
               idx(p.seg_b) + ", \"t_b\": " + exact_number(p.t_b) + ", \"x\": " + exact_number(p.point.x) +
               ", \"y\": " + exact_number(p.point.y) + ", \"kind\": \"" + intersection_kind_name(p.kind) +
               "\"}";
    }
    out += r.result.intersections.empty() ? "]" : "\n]";
    out += ", \"overlaps\": [";
    sep = "\n  ";
    for (const PathOverlap& o : r.result.overlaps) {
        out += sep;
        sep = ",\n  ";
        out += "{\"seg_a\": " + idx(o.seg_a) + ", \"t_a\": [" + exact_number(o.t_a0) + ", " + exact_number(o.t_a1) +
               "], \"seg_b\": " + idx(o.seg_b) + ", \"t_b\": [" + exact_number(o.t_b0) + ", " + exact_number(o.t_b1) +
               "]}";
    }
    out += r.result.overlaps.empty() ? "]" : "\n]";
    out += "}\n";
    return out;
}

}  // namespace bezel::cli
