// Dashing with SVG's semantics (SVG 2 §13.5.5, stroke-dasharray / stroke-dashoffset): the
// pattern restarts at every subpath, an odd-length list is repeated to make it even, the offset
// shifts where the pattern starts (negative allowed), and a closed subpath whose pattern is "on"
// both where it starts and where it ends gets one dash running through its start point. Distances
// are arc lengths, computed to 1e-9 of each segment's size.
#include <algorithm>
#include <cmath>

#include "bezel/stroke.hpp"
#include "stroke/stroke_internal.hpp"

namespace bezel {
namespace {

using stroke_detail::ContourInput;

constexpr double kArcAccuracy = 1e-9;

double seg_length(const PathSeg& s) {
    Rect b = s.kind == SegKind::Line ? s.as_line().control_box() : s.to_cubic().control_box();
    double acc = kArcAccuracy * std::max({b.width(), b.height(), 1e-300});
    switch (s.kind) {
        case SegKind::Line: return s.as_line().length();
        case SegKind::Quad: return s.as_quad().arclen(acc);
        case SegKind::Cubic: return s.as_cubic().arclen(acc);
    }
    return 0.0;
}

// The part of `s` between arc lengths a and b (0 ≤ a ≤ b ≤ len).
PathSeg sub_seg(const PathSeg& s, double len, double a, double b) {
    PathSeg out;
    out.kind = s.kind;
    if (s.kind == SegKind::Line) {
        double ta = len > 0 ? a / len : 0.0, tb = len > 0 ? b / len : 0.0;
        out.p[0] = s.eval(ta);
        out.p[1] = b >= len ? s.p[1] : s.eval(tb);
        return out;
    }
    double acc = kArcAccuracy * std::max(len, 1e-300);
    auto param = [&](double d) {
        if (d <= 0) return 0.0;
        if (d >= len) return 1.0;
        return s.kind == SegKind::Quad ? s.as_quad().inv_arclen(d, acc)
                                       : s.as_cubic().inv_arclen(d, acc);
    };
    double ta = param(a), tb = param(b);
    if (s.kind == SegKind::Quad) {
        QuadBez q = s.as_quad().subsegment(ta, tb);
        out.p[0] = q.p0, out.p[1] = q.p1, out.p[2] = q.p2;
    } else {
        CubicBez c = s.as_cubic().subsegment(ta, tb);
        out.p[0] = c.p0, out.p[1] = c.p1, out.p[2] = c.p2, out.p[3] = c.p3;
    }
    return out;
}

struct Dash {
    Point start;
    std::vector<PathSeg> segs;
};

void emit(Path& out, const Dash& d, bool close) {
    out.move_to(d.start);
    if (d.segs.empty()) out.line_to(d.start);  // a zero-length dash: a dot for round/square caps
    for (const PathSeg& s : d.segs) {
        switch (s.kind) {
            case SegKind::Line: out.line_to(s.p[1]); break;
            case SegKind::Quad: out.quad_to(s.p[1], s.p[2]); break;
            case SegKind::Cubic: out.cubic_to(s.p[1], s.p[2], s.p[3]); break;
        }
    }
    if (close) out.close();
}

}  // namespace

Expected<Path> dash(const Path& path, const std::vector<double>& dashes, double dash_offset) {
    if (auto ok = stroke_detail::check_dashes(dashes, dash_offset); !ok) return ok.error();
    if (!path.is_finite()) return Error{"dash: the path has a non-finite coordinate"};
    if (dashes.empty()) return path;
    std::vector<double> pattern = dashes;
    if (pattern.size() % 2 == 1) pattern.insert(pattern.end(), dashes.begin(), dashes.end());
    double period = 0;
    for (double d : pattern) period += d;
    const std::size_t n = pattern.size();

    std::vector<ContourInput> contours = stroke_detail::contours_of(path);
    std::vector<std::vector<double>> lengths(contours.size());
    // Each period holds n/2 dashes; a contour starts at most one extra.
    double estimate = 0;
    for (std::size_t c = 0; c < contours.size(); ++c) {
        double total = 0;
        for (const PathSeg& s : contours[c].segs) total += lengths[c].emplace_back(seg_length(s));
        estimate += (total / period + 2.0) * static_cast<double>(n / 2);
    }
    if (!(estimate <= static_cast<double>(kMaxDashes)))
        return Error{"dash pattern: about " + stroke_detail::num(estimate) +
                     " dashes over this path, more than kMaxDashes (" +
                     std::to_string(kMaxDashes) + ")"};

    // Where the pattern stands at the start of every contour.
    double phase = std::fmod(dash_offset, period);
    if (phase < 0) phase += period;
    std::size_t idx0 = 0;
    for (std::size_t guard = 0; guard < 2 * n; ++guard) {
        if (phase < pattern[idx0] || (phase == 0 && pattern[idx0] == 0)) break;
        phase -= pattern[idx0];
        idx0 = (idx0 + 1) % n;
    }
    double rem0 = std::max(0.0, pattern[idx0] - phase);

    Path out;
    for (std::size_t c = 0; c < contours.size(); ++c) {
        const ContourInput& contour = contours[c];
        if (contour.segs.empty()) continue;
        std::size_t idx = idx0;
        double rem = rem0;
        bool on = idx % 2 == 0;
        bool ever_off = !on;
        std::vector<Dash> found;
        Dash current;
        bool open = on;
        if (on) current.start = contour.start;
        for (std::size_t i = 0; i < contour.segs.size(); ++i) {
            const PathSeg& s = contour.segs[i];
            double len = lengths[c][i], pos = 0;
            while (true) {
                if (rem <= 0) {  // the interval ends here: switch
                    Point here = pos >= len ? s.end() : sub_seg(s, len, 0, pos).end();
                    if (on) {
                        found.push_back(std::move(current));
                        current = Dash{};
                        open = false;
                    }
                    idx = (idx + 1) % n;
                    rem = pattern[idx];
                    on = idx % 2 == 0;
                    if (!on) ever_off = true;
                    if (on) {
                        current.start = here;
                        open = true;
                    }
                    continue;
                }
                if (pos >= len) break;
                double step = std::min(rem, len - pos);
                if (on) current.segs.push_back(sub_seg(s, len, pos, pos + step));
                pos += step;
                rem -= step;
            }
        }
        if (!ever_off && contour.closed) {  // never switched off: the whole contour, still closed
            emit(out, current, true);
            continue;
        }
        bool starts_on = idx0 % 2 == 0;
        if (open && contour.closed && starts_on && !found.empty()) {
            // The last dash runs through the start point into the first one.
            for (const PathSeg& s : found.front().segs) current.segs.push_back(s);
            found.front() = std::move(current);
        } else if (open) {
            found.push_back(std::move(current));
        }
        for (const Dash& d : found) emit(out, d, false);
    }
    return out;
}

}  // namespace bezel
