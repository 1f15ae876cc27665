// bezel_path: a Path built from verbs or parsed from SVG path data, and its pixel box.
#include <cmath>
#include <string_view>

#include "bezel/limits.hpp"
#include "capi/handles.hpp"

using namespace bezel;
using namespace bezel::capi_detail;

namespace {

// Appends one verb after checking its points: finite, and the path within kMaxSvgPathPoints
// (the bound SVG data has, so a path is as bounded whichever way it was made).
template <typename Append>
bezel_status add_verb(bezel_path* path, const char* fn, std::initializer_list<double> coords,
                      Append&& append) {
    if (!path) return null_argument(nullptr, fn, "path");
    ErrorSlot* err = &path->error;
    return guarded(err, fn, [&]() -> bezel_status {
        for (double v : coords)
            if (!std::isfinite(v))
                return fail(err, BEZEL_STATUS_INVALID_ARGUMENT,
                            std::string(fn) + ": coordinate " + std::to_string(v) +
                                " is not finite");
        if (path->path.points().size() + coords.size() / 2 > kMaxSvgPathPoints)
            return fail(err, BEZEL_STATUS_OUT_OF_RANGE,
                        std::string(fn) + ": the path would have more than kMaxSvgPathPoints (" +
                            std::to_string(kMaxSvgPathPoints) + ") points");
        append(path->path);
        return BEZEL_STATUS_OK;
    });
}

}  // namespace

extern "C" {

bezel_status bezel_path_create(bezel_path** out) {
    static const char* const fn = "bezel_path_create";
    return guarded(nullptr, fn, [&]() -> bezel_status {
        if (!out) return null_argument(nullptr, fn, "out");
        *out = new bezel_path{};
        return BEZEL_STATUS_OK;
    });
}

bezel_status bezel_path_from_svg(const char* data, std::size_t length, bezel_path** out) {
    static const char* const fn = "bezel_path_from_svg";
    return guarded(nullptr, fn, [&]() -> bezel_status {
        if (!data && length > 0) return null_argument(nullptr, fn, "data");
        if (!out) return null_argument(nullptr, fn, "out");
        if (length > kMaxSvgPathLength)
            return fail(nullptr, BEZEL_STATUS_OUT_OF_RANGE,
                        std::string(fn) + ": " + std::to_string(length) +
                            " bytes of path data is more than kMaxSvgPathLength (" +
                            std::to_string(kMaxSvgPathLength) + ")");
        Expected<Path> parsed = parse_svg_path(std::string_view(data ? data : "", length));
        if (!parsed) return fail(nullptr, BEZEL_STATUS_INVALID_ARGUMENT, parsed.error().message);
        *out = new bezel_path{std::move(*parsed), {}};
        return BEZEL_STATUS_OK;
    });
}

void bezel_path_destroy(bezel_path* path) { delete path; }

const char* bezel_path_last_error(const bezel_path* path) {
    return path ? path->error.c_str() : bezel_last_error();
}

bezel_status bezel_path_move_to(bezel_path* path, double x, double y) {
    return add_verb(path, "bezel_path_move_to", {x, y}, [&](Path& p) { p.move_to({x, y}); });
}

bezel_status bezel_path_line_to(bezel_path* path, double x, double y) {
    return add_verb(path, "bezel_path_line_to", {x, y}, [&](Path& p) { p.line_to({x, y}); });
}

bezel_status bezel_path_quad_to(bezel_path* path, double cx, double cy, double x, double y) {
    return add_verb(path, "bezel_path_quad_to", {cx, cy, x, y},
                    [&](Path& p) { p.quad_to({cx, cy}, {x, y}); });
}

bezel_status bezel_path_cubic_to(bezel_path* path, double c1x, double c1y, double c2x, double c2y,
                                 double x, double y) {
    return add_verb(path, "bezel_path_cubic_to", {c1x, c1y, c2x, c2y, x, y},
                    [&](Path& p) { p.cubic_to({c1x, c1y}, {c2x, c2y}, {x, y}); });
}

bezel_status bezel_path_close(bezel_path* path) {
    return add_verb(path, "bezel_path_close", {}, [](Path& p) { p.close(); });
}

bezel_status bezel_path_pixel_bounds(bezel_path* path, const bezel_transform* transform,
                                     bezel_int_rect* out) {
    static const char* const fn = "bezel_path_pixel_bounds";
    if (!path) return null_argument(nullptr, fn, "path");
    ErrorSlot* err = &path->error;
    return guarded(err, fn, [&]() -> bezel_status {
        if (!out) return null_argument(err, fn, "out");
        const Affine m = transform ? Affine{transform->a, transform->b, transform->c,
                                            transform->d, transform->e, transform->f}
                                   : Affine{};
        if (!(std::isfinite(m.a) && std::isfinite(m.b) && std::isfinite(m.c) &&
              std::isfinite(m.d) && std::isfinite(m.e) && std::isfinite(m.f)))
            return fail(err, BEZEL_STATUS_INVALID_ARGUMENT, std::string(fn) +
                                                                ": the transform is not finite");
        const Rect r = path->path.transformed(m).bounds();
        if (r.is_empty()) {
            *out = bezel_int_rect{0, 0, 0, 0};
            return BEZEL_STATUS_OK;
        }
        // Whole pixels that fit an int, with room for x1 − x0.
        constexpr double kLimit = 1 << 30;
        const double x0 = std::floor(r.x0), y0 = std::floor(r.y0);
        const double x1 = std::ceil(r.x1), y1 = std::ceil(r.y1);
        if (!(std::fabs(x0) <= kLimit && std::fabs(y0) <= kLimit && std::fabs(x1) <= kLimit &&
              std::fabs(y1) <= kLimit))
            return fail(err, BEZEL_STATUS_OUT_OF_RANGE,
                        std::string(fn) + ": the path's box is not finite or beyond ±2^30 px");
        *out = bezel_int_rect{static_cast<int>(x0), static_cast<int>(y0), static_cast<int>(x1),
                              static_cast<int>(y1)};
        return BEZEL_STATUS_OK;
    });
}

}  // extern "C"
