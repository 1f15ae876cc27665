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

// A segment with its cumulative arc length at kTableSteps equal parameter steps, so a distance
// is inverted on one short sub-curve instead of from the start of a long one (dashing a long
// curve is then linear in the number of dashes, not quadratic).
constexpr int kTableSteps = 16;

struct Measured {
    PathSeg seg;
    double cum[kTableSteps + 1] = {};  // arc length of [0, i/kTableSteps]; lines use cum[K] only

    double length() const { return cum[kTableSteps]; }

    explicit Measured(const PathSeg& s) : seg(s) {
        if (s.kind == SegKind::Line) {
            cum[kTableSteps] = s.as_line().length();
            return;
        }
        CubicBez c = s.to_cubic();
        Rect b = c.control_box();
        double acc = kArcAccuracy * std::max({b.width(), b.height(), 1e-300}) / kTableSteps;
        for (int i = 0; i < kTableSteps; ++i)
            cum[i + 1] = cum[i] + c.subsegment(double(i) / kTableSteps, double(i + 1) / kTableSteps)
                                      .arclen(acc);
    }

    // The parameter at arc length d (clamped to [0, length]).
    double param(double d) const {
        double len = length();
        if (d <= 0 || !(len > 0)) return 0.0;
        if (d >= len) return 1.0;
        if (seg.kind == SegKind::Line) return d / len;
        int i = static_cast<int>(std::upper_bound(cum, cum + kTableSteps + 1, d) - cum) - 1;
        i = std::clamp(i, 0, kTableSteps - 1);
        double t0 = double(i) / kTableSteps, t1 = double(i + 1) / kTableSteps;
        double piece = cum[i + 1] - cum[i];
        if (!(piece > 0)) return t0;
        CubicBez sub = seg.to_cubic().subsegment(t0, t1);
        double local = sub.inv_arclen(d - cum[i], kArcAccuracy * piece);
        return t0 + (t1 - t0) * local;
    }

    // The part between arc lengths a and b (0 ≤ a ≤ b ≤ length), same kind as the segment.
    PathSeg part(double a, double b) const {
        PathSeg out;
        out.kind = seg.kind;
        double ta = param(a), tb = b >= length() ? 1.0 : param(b);
        switch (seg.kind) {
            case SegKind::Line:
                out.p[0] = seg.eval(ta);
                out.p[1] = tb >= 1.0 ? seg.p[1] : seg.eval(tb);
                break;
            case SegKind::Quad: {
                QuadBez q = seg.as_quad().subsegment(ta, tb);
                out.p[0] = q.p0, out.p[1] = q.p1, out.p[2] = q.p2;
                break;
            }
            case SegKind::Cubic: {
                CubicBez c = seg.as_cubic().subsegment(ta, tb);
                out.p[0] = c.p0, out.p[1] = c.p1, out.p[2] = c.p2, out.p[3] = c.p3;
                break;
            }
        }
        return out;
    }
};

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
    return stroke_detail::dash_limited(path, dashes, dash_offset, {});
}

Expected<Path> stroke_detail::dash_limited(const Path& path, const std::vector<double>& dashes,
                                           double dash_offset, const DashLimit& limit) {
    if (auto ok = stroke_detail::check_dashes(dashes, dash_offset); !ok) return ok.error();
    if (!path.is_finite()) return Error{"dash: the path has a non-finite coordinate"};
    if (dashes.empty()) return path;
    std::vector<double> pattern = dashes;
    if (pattern.size() % 2 == 1) pattern.insert(pattern.end(), dashes.begin(), dashes.end());
    double period = 0;
    for (double d : pattern) period += d;
    const std::size_t n = pattern.size();

    std::vector<ContourInput> contours = stroke_detail::contours_of(path);
    std::vector<std::vector<Measured>> measured(contours.size());
    // Each period holds n/2 dashes; a contour starts at most one extra. Checked before any
    // dash is made, so an input far past the limit costs only the measuring.
    double estimate = 0, counted = 0;
    for (std::size_t i = 0; i < n; i += 2) counted += pattern[i] > 0 || limit.count_empty;
    for (std::size_t c = 0; c < contours.size(); ++c) {
        double total = 0;
        for (const PathSeg& s : contours[c].segs) total += measured[c].emplace_back(s).length();
        estimate += (total / period + 2.0) * static_cast<double>(n / 2);
    }
    if (!(estimate <= static_cast<double>(kMaxDashes)))
        return Error{"dash pattern: about " + stroke_detail::num(estimate) +
                     " dashes over this path, more than the " + std::to_string(kMaxDashes) +
                     " allowed"};
    // The dashes the caller will turn into output (a zero-length one may make none), at the
    // fewest segments each: past the caller's bound the result could only fail later, slowly.
    const double made = estimate * counted / static_cast<double>(n / 2);
    if (limit.segments_per_dash > 0 &&
        !(made * static_cast<double>(limit.segments_per_dash) <=
          static_cast<double>(limit.max_segments)))
        return Error{"dash pattern: about " + stroke_detail::num(made) + " dashes of at least " +
                     std::to_string(limit.segments_per_dash) +
                     " verbs each: the outline would exceed " +
                     std::to_string(limit.max_segments) +
                     " segments (the stroker's limit); lengthen the dashes or shorten the path"};

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
            const Measured& m = measured[c][i];
            double len = m.length(), pos = 0;
            while (true) {
                if (rem <= 0) {  // the interval ends here: switch
                    Point here = pos >= len ? m.seg.end() : m.seg.eval(m.param(pos));
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
                if (on) current.segs.push_back(m.part(pos, pos + step));
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
