// bezel/path.hpp — paths made of contours of line, quadratic and cubic pieces, and SVG path data.
//
// Coordinates are y DOWN (SVG's and bitmaps' convention). A path is stored as a verb list and a
// point list (one point per Line/Move, two per Quad, three per Cubic, none per Close), so it is a
// cheap value type: copying copies two vectors, and nothing else is hidden inside.
//
// Invariants the builder keeps (every Path is built through it, so every Path has them):
//   - every drawing verb (Line, Quad, Cubic) follows, within its contour, a Move;
//   - there are never two Moves in a row, and never two Closes in a row;
//   - a contour is a Move and the verbs up to the next Move; it is closed when it ends in Close.
//
// Segments and their stable indices. Iterating a path (`segments()`) yields one PathSeg per Line,
// Quad and Cubic verb, in order, plus — for a CLOSED contour whose last point differs (by ==)
// from its start point — one closing Line from the last point back to the start, flagged
// `closing`. A closed contour already back at its start gets no closing segment; an open contour
// never gets one. `PathSeg::index` counts these segments from 0 over the whole path, so an index
// names the same piece of geometry for every consumer (flattening, intersection, smoothing).
// Contours are numbered from 0 in order of their Move verbs, including contours with no segment
// (a lone Move, or a Move followed by Close).
#pragma once

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

#include "bezel/bezier.hpp"
#include "bezel/expected.hpp"
#include "bezel/geometry.hpp"
#include "bezel/limits.hpp"

#pragma GCC visibility push(default)  // the public API of libbezel.so (docs/architecture.md)
namespace bezel {

enum class Verb : std::uint8_t { Move, Line, Quad, Cubic, Close };

enum class SegKind : std::uint8_t { Line, Quad, Cubic };

// One segment of a path, by value. `p[0]` is the start point; a Line uses p[0..1], a Quad
// p[0..2], a Cubic p[0..3]; unused entries are (0, 0).
struct PathSeg {
    SegKind kind = SegKind::Line;
    Point p[4] = {};
    std::size_t index = 0;    // position among all segments of the path (see the rule above)
    std::size_t contour = 0;  // which contour, counted from 0 over the Move verbs
    bool closing = false;     // the implicit closing Line of a closed contour

    Point start() const { return p[0]; }
    Point end() const;
    // The point at parameter t in [0, 1] (exact at 0 and 1).
    Point eval(double t) const;
    // The same curve as a cubic, by exact degree elevation (a Line's control points sit at 1/3
    // and 2/3 of the chord, a Quad's at Pᵢ + ⅔(P₁ − Pᵢ)); parameterization is preserved.
    CubicBez to_cubic() const;
    // Preconditions: kind is Line / Quad / Cubic respectively (checked by assert).
    Line as_line() const;
    QuadBez as_quad() const;
    CubicBez as_cubic() const;
};

// Iterates the segments of a path's verb/point arrays without allocating. Valid while the Path
// it came from is alive and unmodified.
class SegmentIterator {
public:
    using value_type = PathSeg;
    using difference_type = std::ptrdiff_t;
    using reference = const PathSeg&;
    using pointer = const PathSeg*;
    using iterator_category = std::input_iterator_tag;

    SegmentIterator() = default;  // the end iterator
    SegmentIterator(const Verb* verbs, std::size_t verb_count, const Point* points);

    const PathSeg& operator*() const { return seg_; }
    const PathSeg* operator->() const { return &seg_; }
    SegmentIterator& operator++() { advance(); return *this; }
    SegmentIterator operator++(int) { SegmentIterator old = *this; advance(); return old; }
    // Two iterators are equal when both are at the end or both stand on the same segment index.
    bool operator==(const SegmentIterator& o) const {
        return done_ == o.done_ && (done_ || seg_.index == o.seg_.index);
    }
    bool operator!=(const SegmentIterator& o) const { return !(*this == o); }

private:
    void advance();

    const Verb* verbs_ = nullptr;
    const Point* points_ = nullptr;
    std::size_t verb_count_ = 0;
    std::size_t vi_ = 0;           // next verb to read
    std::size_t pi_ = 0;           // next point to read
    std::size_t next_index_ = 0;   // index the next yielded segment gets
    std::size_t moves_seen_ = 0;
    Point start_{}, last_{};       // current contour's start and the current point
    PathSeg seg_{};
    bool done_ = true;
};

struct SegmentRange {
    const Verb* verbs = nullptr;
    std::size_t verb_count = 0;
    const Point* points = nullptr;
    SegmentIterator begin() const { return {verbs, verb_count, points}; }
    SegmentIterator end() const { return {}; }
};

// Direction of a contour as seen on screen, y down.
enum class Winding : std::uint8_t { Clockwise, CounterClockwise, None };

// The winding of a contour with this signed area (see Path::signed_area): > 0 → Clockwise,
// < 0 → CounterClockwise, exactly 0 (or NaN) → None.
Winding winding_of_area(double signed_area);

class Path {
public:
    // Builder. A drawing call with no current contour starts one at the last point (or at (0,0)),
    // as SVG does. close() ends the contour; the next drawing call starts a new one at the same
    // start point. Consecutive move_to calls keep only the last; close() with no open contour
    // does nothing.
    void move_to(Point p);
    void line_to(Point p);
    void quad_to(Point c, Point p);
    void cubic_to(Point c1, Point c2, Point p);
    void close();

    const std::vector<Verb>& verbs() const { return verbs_; }
    const std::vector<Point>& points() const { return points_; }
    bool empty() const { return verbs_.empty(); }
    void clear() { verbs_.clear(); points_.clear(); }

    // Segments in order, with the stable indices of the rule at the top of this file:
    //   for (const PathSeg& seg : path.segments()) ...
    // No allocation. Not callable on a temporary Path (the range would dangle).
    SegmentRange segments() const& { return {verbs_.data(), verbs_.size(), points_.data()}; }
    SegmentRange segments() const&& = delete;
    std::size_t segment_count() const;
    std::size_t contour_count() const;  // the number of Move verbs
    // The segment with index i. O(number of verbs): iterate segments() to visit them all.
    // Precondition: i < segment_count() (assert; a default PathSeg is returned otherwise).
    PathSeg segment(std::size_t i) const;

    // Applies `m` to every point. Exact for lines and Béziers: affine maps commute with the
    // Bernstein combination, so mapping control points maps the curve.
    void transform(const Affine& m);
    Path transformed(const Affine& m) const;

    // Union of all segments' points, control points included; Rect::empty() when there is no
    // segment. A Move that starts no segment does not count.
    Rect control_box() const;
    // The tight box of the drawn geometry: segment end points and the curves' axis extrema.
    // Rect::empty() when there is no segment. bounds() ⊆ control_box().
    Rect bounds() const;

    // Each contour traversed backwards; contour order and closedness kept. For a closed contour
    // M P₀ … Pₙ Z the result is M Pₙ … P₀ Z, whose implicit closing line is the original one
    // reversed, so the segment count is unchanged. reversed().reversed() == *this exactly.
    Path reversed() const;

    // Signed area enclosed, every contour implicitly closed by a line back to its start (as a
    // filler closes it), summed over contours. Sign convention: ½∮(x dy − y dx), positive for a
    // contour that runs CLOCKWISE ON SCREEN (y down) — the orientation that is counter-clockwise
    // in a y-up frame. Exact (up to rounding) for lines, quadratics and cubics: each piece adds
    // its closed-form Green's-theorem integral. Overlaps count with their winding multiplicity.
    double signed_area() const;
    // One signed area per contour, in contour order (0 for a contour without segments).
    std::vector<double> contour_areas() const;
    // winding_of_area() of each contour's area.
    std::vector<Winding> contour_windings() const;

    // True when every point is finite (no NaN, no infinity).
    bool is_finite() const;

    // Verb lists equal and points equal by == on doubles (so −0 == 0, and NaN != NaN).
    bool operator==(const Path& o) const { return verbs_ == o.verbs_ && points_ == o.points_; }
    bool operator!=(const Path& o) const { return !(*this == o); }

private:
    std::vector<Verb> verbs_;
    std::vector<Point> points_;
};

// ---------------------------------------------------------------------------------------------
// SVG path data (SVG 1.1 §8.3 / SVG 2 §9.3 grammar), in and out.

struct SvgParseOptions {
    // Bound on the distance between each true elliptical arc and the cubics that replace it, in
    // path units (both ways: every point of the cubics is within it of the arc, and every point
    // of the arc within it of the cubics). Must be finite and > 0. The bound holds up to double
    // rounding, i.e. to ~1e-15 × the ellipse's larger radius. For paths drawn in pixels, 1e-3
    // is far below what anti-aliasing can show.
    double arc_tolerance = 1e-3;
};

// Parses SVG path data: every command (M m L l H h V v C c S s Q q T t A a Z z), implicit
// repeats (extra coordinate pairs after M become lines), numbers with exponents and without
// separators ("M1.5.5" is M 1.5 0.5, "1-2" is 1 −2), flags without separators ("a1 1 0 00 1 1").
// S/T reflect the previous C/S (Q/T) control point; after any other command the control point
// is the current point. Arcs follow SVG 1.1 F.6: radii are made absolute and scaled up when too
// small to reach the end point (F.6.6), a zero radius gives a line, an arc to the current point
// is omitted; otherwise they become cubics within options.arc_tolerance. H/V/S/T become L/C/Q.
// Empty or all-whitespace data gives an empty path. Numbers too small for a double become 0.
//
// Errors (one line, naming the byte offset and what was expected):
//   "path data offset 7: expected a number, found 'x'"
//   "path data offset 0: expected a moveto (M or m), found 'L'"
//   "path data offset 3: number out of range (overflows double)"
// also for a bad flag, an unknown command, a coordinate that overflows once made absolute, data
// longer than kMaxSvgPathLength, a result with more than kMaxSvgPathPoints points, and an
// arc_tolerance that is not finite and > 0. The parsed path is always is_finite().
Expected<Path> parse_svg_path(std::string_view data, const SvgParseOptions& options = {});

// Writes `path` as SVG path data, one absolute command letter per verb (M L Q C Z), numbers in
// their shortest form that reads back to the same double ("0.5" → ".5", separators dropped before
// '-'). With precision ≥ 17 (the default), parse_svg_path(to_svg_path(p)) == p exactly, verbs and
// points bit for bit, for every finite p. A smaller precision (1..16) rounds to that many
// significant digits instead. Non-finite coordinates are written as "nan"/"inf", which the parser
// rejects.
std::string to_svg_path(const Path& path, int precision = 17);

// One elliptical arc as SVG's A command gives it.
struct SvgArc {
    Vec2 radii;                   // rx, ry (signs ignored)
    double x_rotation_deg = 0.0;  // rotation of the ellipse's x axis, degrees, as in SVG
    bool large_arc = false;
    bool sweep = false;           // true: angle increasing, i.e. clockwise on screen (y down)
    Point to;
};

// Appends the arc from `from` (which should be the path's current point) to arc.to, following
// SVG 1.1 F.6 as parse_svg_path does: nothing when from == arc.to, a line_to when a radius is 0,
// otherwise cubic_to calls within `tolerance` (path units, > 0) of the true arc, the last ending
// exactly at arc.to (also a line_to when the chord is below double resolution against the radii,
// chord/radius < ~1e-308). Non-finite input, or radii so extreme that the ellipse overflows,
// yields non-finite points (check Path::is_finite(); parse_svg_path reports them as errors).
void append_svg_arc(Path& path, Point from, const SvgArc& arc, double tolerance);

}  // namespace bezel
#pragma GCC visibility pop
