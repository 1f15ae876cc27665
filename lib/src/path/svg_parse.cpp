// SVG path data → Path: the command level (SVG 1.1 §8.3, SVG 2 §9.3). Tokens come from
// svg_lexer; arcs go through append_svg_arc.
//
// State, as the spec defines it: the current point, the start of the current subpath (where Z
// returns and what a command after Z is relative to), and the last control point of the previous
// command when it was a cubic (C/S) or a quadratic (Q/T), which S and T reflect.
#include <cmath>
#include <cstdio>
#include <string>

#include "bezel/path.hpp"
#include "path/svg_lexer.hpp"

namespace bezel {

using svg_detail::Lexer;

namespace {

bool is_command(char c) {
    switch (c) {
        case 'M': case 'm': case 'L': case 'l': case 'H': case 'h': case 'V': case 'v':
        case 'C': case 'c': case 'S': case 's': case 'Q': case 'q': case 'T': case 't':
        case 'A': case 'a': case 'Z': case 'z':
            return true;
        default:
            return false;
    }
}

int arg_count(char upper) {
    switch (upper) {
        case 'M': case 'L': case 'T': return 2;
        case 'H': case 'V': return 1;
        case 'S': case 'Q': return 4;
        case 'C': return 6;
        case 'A': return 7;
        default: return 0;
    }
}

// Which kind of curve the previous command drew, for S/T reflection.
enum class Prev { Other, Cubic, Quad };

class Parser {
public:
    Parser(std::string_view data, double arc_tolerance) : lx_(data), tol_(arc_tolerance) {}

    Expected<Path> run() {
        lx_.skip_wsp();
        if (lx_.at_end()) return std::move(path_);
        char c = lx_.peek();
        if (c != 'M' && c != 'm') return lx_.expected_here("a moveto (M or m)");
        while (!lx_.at_end()) {
            c = lx_.peek();
            if (!is_command(c)) return lx_.expected_here("a command letter");
            lx_.bump();
            Status st = command(c);
            if (!st) return st.error();
            lx_.skip_wsp();
        }
        return std::move(path_);
    }

private:
    // One command letter with all its (implicitly repeated) argument sets.
    Status command(char c) {
        if (c == 'Z' || c == 'z') {
            path_.close();
            cur_ = start_;
            prev_ = Prev::Other;
            return ok_status();
        }
        const bool rel = c >= 'a';
        char upper = rel ? static_cast<char>(c - 'a' + 'A') : c;
        const int n = arg_count(upper);
        lx_.skip_wsp();
        for (;;) {
            const std::size_t set_offset = lx_.offset();
            double a[7];
            for (int i = 0; i < n; ++i) {
                if (i > 0) lx_.skip_comma_wsp();
                // The arc's 4th and 5th arguments are flags: one character, no sign.
                Expected<double> x = (upper == 'A' && (i == 3 || i == 4)) ? lx_.flag() : lx_.number();
                if (!x) return x.error();
                a[i] = *x;
            }
            apply(upper, rel, a);
            Status st = check_new_points(set_offset);
            if (!st) return st;
            // SVG's implicit repeat: more numbers continue the command; after a moveto they
            // are lineto arguments.
            bool comma = lx_.skip_comma_wsp();
            if (!lx_.at_number_start()) {
                if (comma) return lx_.expected_here("a number");
                return ok_status();
            }
            if (upper == 'M') upper = 'L';
        }
    }

    void apply(char upper, bool rel, const double* a) {
        // Absolute coordinates are taken as they are, not added to (0, 0): that would turn −0
        // into +0 and break the bit-exact round trip.
        const Point base = cur_;
        auto pt = [&](int i) { return rel ? base + Vec2{a[i], a[i + 1]} : Vec2{a[i], a[i + 1]}; };
        Prev prev = Prev::Other;
        switch (upper) {
            case 'M':
                cur_ = start_ = pt(0);
                path_.move_to(cur_);
                break;
            case 'L':
                cur_ = pt(0);
                path_.line_to(cur_);
                break;
            case 'H':
                cur_.x = rel ? base.x + a[0] : a[0];
                path_.line_to(cur_);
                break;
            case 'V':
                cur_.y = rel ? base.y + a[0] : a[0];
                path_.line_to(cur_);
                break;
            case 'C':
                ctrl_ = pt(2);
                cur_ = pt(4);
                path_.cubic_to(pt(0), ctrl_, cur_);
                prev = Prev::Cubic;
                break;
            case 'S': {
                // First control point: the previous cubic's second one reflected about the
                // current point, or the current point itself after anything else.
                Point c1 = prev_ == Prev::Cubic ? cur_ * 2.0 - ctrl_ : cur_;
                ctrl_ = pt(0);
                cur_ = pt(2);
                path_.cubic_to(c1, ctrl_, cur_);
                prev = Prev::Cubic;
                break;
            }
            case 'Q':
                ctrl_ = pt(0);
                cur_ = pt(2);
                path_.quad_to(ctrl_, cur_);
                prev = Prev::Quad;
                break;
            case 'T':
                ctrl_ = prev_ == Prev::Quad ? cur_ * 2.0 - ctrl_ : cur_;
                cur_ = pt(0);
                path_.quad_to(ctrl_, cur_);
                prev = Prev::Quad;
                break;
            case 'A': {
                SvgArc arc{{a[0], a[1]}, a[2], a[3] != 0.0, a[4] != 0.0, pt(5)};
                append_svg_arc(path_, cur_, arc, tol_);
                cur_ = arc.to;
                break;
            }
            default:
                break;
        }
        prev_ = prev;
    }

    // Every point a command adds must be finite (relative coordinates can overflow once made
    // absolute, and so can an arc with extreme radii), and the total stays under the limit.
    Status check_new_points(std::size_t set_offset) {
        const std::vector<Point>& pts = path_.points();
        if (pts.size() > kMaxSvgPathPoints)
            return Lexer::error_at(set_offset, "path has more than " +
                                                   std::to_string(kMaxSvgPathPoints) +
                                                   " points");
        for (std::size_t i = checked_; i < pts.size(); ++i)
            if (!pts[i].is_finite())
                return Lexer::error_at(set_offset, "coordinates overflow double");
        checked_ = pts.size();
        if (!cur_.is_finite()) return Lexer::error_at(set_offset, "coordinates overflow double");
        return ok_status();
    }

    Lexer lx_;
    double tol_;
    Path path_;
    Point cur_{}, start_{}, ctrl_{};
    Prev prev_ = Prev::Other;
    std::size_t checked_ = 0;
};

}  // namespace

Expected<Path> parse_svg_path(std::string_view data, const SvgParseOptions& options) {
    if (data.size() > kMaxSvgPathLength)
        return Error{"path data: " + std::to_string(data.size()) + " bytes exceeds the limit of " +
                     std::to_string(kMaxSvgPathLength) + " bytes"};
    if (!(std::isfinite(options.arc_tolerance) && options.arc_tolerance > 0.0)) {
        char got[32];
        std::snprintf(got, sizeof got, "%g", options.arc_tolerance);
        return Error{std::string("SvgParseOptions::arc_tolerance: must be finite and > 0, got ") +
                     got};
    }
    return Parser(data, options.arc_tolerance).run();
}

}  // namespace bezel
