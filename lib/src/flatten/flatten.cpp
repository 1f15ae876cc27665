// flatten(): walks the path's verbs and points directly (no per-segment callbacks), transforms
// control points, and hands each curve to its method (methods.hpp). Contour bookkeeping, the
// input checks of flatten_checked and the limits live here; the curve mathematics does not.
#include "bezel/flatten.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "flatten/methods.hpp"

namespace bezel {

namespace {

// A number in a message: "%g" (6 significant digits), not std::to_string's "%f".
std::string number_text(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

using flatten_detail::classic_flatness;
using flatten_detail::distance_subdivision;
using flatten_detail::parabola_integral;
using flatten_detail::wang_uniform;

bool in_range(Point p) {
    // Written so NaN fails too.
    return std::fabs(p.x) <= kMaxFlattenCoordinatePx && std::fabs(p.y) <= kMaxFlattenCoordinatePx;
}

struct Settings {
    FlattenMethod method;
    double tolerance_px;
    double epsilon;
};

template <typename Curve>
bool flatten_curve(const Curve& curve, const Settings& s, std::vector<Point>& out) {
    switch (s.method) {
        case FlattenMethod::ClassicFlatness: return classic_flatness(curve, s.epsilon, out);
        case FlattenMethod::DistanceSubdivision: return distance_subdivision(curve, s.tolerance_px, out);
        case FlattenMethod::WangUniform: return wang_uniform(curve, s.tolerance_px, out);
        case FlattenMethod::ParabolaIntegral: return parabola_integral(curve, s.tolerance_px, out);
    }
    return wang_uniform(curve, s.tolerance_px, out);  // unreachable for valid enum values
}

// The walk shared by both entry points. With `error` null, problems are tolerated as documented
// for flatten(); otherwise the first one stops the walk, is described in *error, and false is
// returned (the caller restores `out`).
bool walk(const Path& path, const Affine& transform, const Settings& s, Polylines& out,
          std::string* error) {
    const std::vector<Verb>& verbs = path.verbs();
    const std::vector<Point>& pts = path.points();
    std::vector<Point>& op = out.points;

    std::size_t contour_start = op.size();
    bool open = false;  // a contour has been started by a Move
    bool bad = false;   // the open contour has a point out of range and will be dropped
    auto finish = [&] {
        if (open && !bad) {
            std::size_t count = op.size() - contour_start;
            if (count >= 2 && op.back() == op[contour_start]) {
                op.pop_back();  // closed explicitly: the filler closes it anyway
                --count;
            }
            if (count >= 2) {
                out.contour_ends.push_back(op.size());
            } else {
                op.resize(contour_start);  // a lone point covers nothing
            }
        } else {
            op.resize(contour_start);
        }
        open = false;
        bad = false;
        contour_start = op.size();
    };

    std::size_t pi = 0;  // index of the verb's first point in pts
    for (std::size_t vi = 0; vi < verbs.size(); ++vi) {
        const Verb verb = verbs[vi];
        std::size_t need = 0;
        switch (verb) {
            case Verb::Move: case Verb::Line: need = 1; break;
            case Verb::Quad: need = 2; break;
            case Verb::Cubic: need = 3; break;
            case Verb::Close: need = 0; break;
        }
        if (pts.size() - pi < need) break;  // the builder never does this; never read past the end
        if (verb == Verb::Close) {
            finish();
            continue;
        }
        if (verb == Verb::Move) finish();
        const std::size_t first = pi;
        pi += need;

        Point p[3];
        bool ok = true;
        for (std::size_t k = 0; k < need; ++k) {
            p[k] = transform * pts[first + k];
            if (!in_range(p[k])) {
                ok = false;
                if (error) {
                    *error = "path point " + std::to_string(first + k) +
                             (std::isfinite(p[k].x) && std::isfinite(p[k].y)
                                  ? " is beyond 2^50 px from the origin after the transform"
                                  : " is not finite after the transform");
                    return false;
                }
                break;
            }
        }

        if (verb == Verb::Move) {
            open = true;
            bad = !ok;
            if (ok) op.push_back(p[0]);
            continue;
        }
        if (!open) {
            // A drawing verb with no Move before it: the builder never makes one. Start the
            // contour where the curve starts, as the builder would have.
            open = true;
            Point start = first > 0 ? transform * pts[first - 1] : transform * Point{};
            bad = !in_range(start);
            if (!bad) op.push_back(start);
        }
        if (bad || !ok) {
            bad = true;
            continue;
        }

        bool met = true;
        const Point start = op.back();
        switch (verb) {
            case Verb::Line:
                if (p[0] != start) op.push_back(p[0]);
                break;
            case Verb::Quad: met = flatten_curve(QuadBez{start, p[0], p[1]}, s, op); break;
            case Verb::Cubic: met = flatten_curve(CubicBez{start, p[0], p[1], p[2]}, s, op); break;
            case Verb::Move: case Verb::Close: break;
        }
        if (!met && error) {
            *error = "path verb " + std::to_string(vi) + ": tolerance not met within " +
                     (s.method == FlattenMethod::ClassicFlatness
                          ? std::to_string(kMaxFlattenDepth) + " halvings"
                          : std::to_string(kMaxSegmentsPerCurve) + " segments per curve");
            return false;
        }
    }
    finish();
    return true;
}

}  // namespace

void flatten(const Path& path, const Affine& transform, const FlattenOptions& options,
             Polylines& out) {
    Settings s{options.method, options.tolerance_px, options.classic_flatness_epsilon};
    if (!(s.tolerance_px >= kMinFlattenTolerancePx)) s.tolerance_px = kMinFlattenTolerancePx;
    if (!(s.epsilon > 0.0 && std::isfinite(s.epsilon))) s.epsilon = kDefaultClassicFlatnessEpsilon;
    walk(path, transform, s, out, nullptr);
}

Status flatten_checked(const Path& path, const Affine& transform, const FlattenOptions& options,
                       Polylines& out) {
    const Settings s{options.method, options.tolerance_px, options.classic_flatness_epsilon};
    if (s.method == FlattenMethod::ClassicFlatness) {
        if (!(s.epsilon > 0.0 && std::isfinite(s.epsilon))) {
            return Error{"flatten: classic_flatness_epsilon " + number_text(s.epsilon) +
                         " is not a finite positive number"};
        }
    } else if (!(s.tolerance_px >= kMinFlattenTolerancePx && std::isfinite(s.tolerance_px))) {
        return Error{"flatten: tolerance_px " + number_text(s.tolerance_px) +
                     " is not a finite number ≥ 1e-9"};
    }
    if (!transform.is_finite()) return Error{"flatten: the transform is not finite"};

    const std::size_t points_before = out.points.size();
    const std::size_t contours_before = out.contour_ends.size();
    std::string message;
    if (!walk(path, transform, s, out, &message)) {
        out.points.resize(points_before);
        out.contour_ends.resize(contours_before);
        return Error{"flatten: " + message};
    }
    return ok_status();
}

}  // namespace bezel
