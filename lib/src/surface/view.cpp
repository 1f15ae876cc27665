// Cameras: world → view space → pixels, for orthographic and perspective projection.
#include <algorithm>
#include <cmath>

#include "bezel/surface.hpp"

namespace bezel {
namespace {

constexpr double kPi = 3.14159265358979323846;

Status check_size(int width, int height) {
    if (width < 1 || height < 1 || width > kMaxSurfaceImageDim || height > kMaxSurfaceImageDim)
        return Error{"picture size " + std::to_string(width) + "x" + std::to_string(height) +
                     ": each side must be 1 to " + std::to_string(kMaxSurfaceImageDim)};
    return ok_status();
}

}  // namespace

Camera orbit_camera(Vec3 target, double azimuth_deg, double elevation_deg, double distance,
                    Projection projection) {
    const double az = azimuth_deg * kPi / 180.0, el = elevation_deg * kPi / 180.0;
    const Vec3 dir{std::sin(az) * std::cos(el), -std::cos(az) * std::cos(el), std::sin(el)};
    Camera c;
    c.target = target;
    c.eye = target + dir * distance;
    // Looking straight up or down, z cannot be "up": use the horizontal heading instead.
    c.up = std::fabs(std::cos(el)) < 1e-6 ? Vec3{-std::sin(az), std::cos(az), 0} : Vec3{0, 0, 1};
    c.projection = projection;
    c.ortho_height = distance;
    return c;
}

Expected<View> View::look_at(const Camera& camera, int width, int height) {
    if (auto ok = check_size(width, height); !ok) return ok.error();
    if (!camera.eye.is_finite() || !camera.target.is_finite() || !camera.up.is_finite())
        return Error{"camera: eye, target and up must be finite"};
    const Vec3 d = camera.target - camera.eye;
    const double dist = d.length();
    if (!(dist > 0.0) || !std::isfinite(dist)) return Error{"camera: eye and target coincide"};
    View v;
    v.forward_ = d / dist;
    v.right_ = v.forward_.cross(camera.up);
    if (!(v.right_.length() > 1e-9 * camera.up.length()))
        return Error{"camera: up is parallel to the view direction"};
    v.right_ = v.right_.normalized();
    v.up_ = v.right_.cross(v.forward_);
    v.eye_ = camera.eye;
    v.projection_ = camera.projection;
    v.width_ = width;
    v.height_ = height;
    v.cx_ = width * 0.5;
    v.cy_ = height * 0.5;
    v.near_ = camera.projection == Projection::Perspective ? kNearPlaneFraction * dist : -HUGE_VAL;
    if (camera.projection == Projection::Perspective) {
        if (!(camera.fov_y_deg > 0.0 && camera.fov_y_deg < 180.0))
            return Error{"camera: field of view must be in (0, 180) degrees"};
        v.k_ = height * 0.5 / std::tan(camera.fov_y_deg * kPi / 360.0);
    } else {
        if (!(camera.ortho_height > 0.0) || !std::isfinite(camera.ortho_height))
            return Error{"camera: orthographic height must be positive"};
        v.k_ = height / camera.ortho_height;
    }
    return v;
}

Expected<View> View::fit(const Camera& camera, int width, int height,
                         const std::vector<Patch>& patches, double margin_px) {
    auto base = look_at(camera, width, height);
    if (!base) return base;
    View v = *base;
    if (auto ok = validate_patches(patches, "camera fit"); !ok) return ok.error();
    double x0 = HUGE_VAL, y0 = HUGE_VAL, x1 = -HUGE_VAL, y1 = -HUGE_VAL;
    bool behind = false;
    for (const Patch& p : patches) {
        const Patch b = p.to_bezier();
        for (const auto& row : b.g)
            for (const Vec3& q : row) {
                if (!v.in_front(q)) {
                    behind = true;
                    continue;
                }
                Vec3 w = v.to_view(q);
                double X = w.x, Y = w.y;
                if (v.projection_ == Projection::Perspective) X /= w.z, Y /= w.z;
                x0 = std::min(x0, X), x1 = std::max(x1, X);
                y0 = std::min(y0, Y), y1 = std::max(y1, Y);
            }
    }
    if (!(x0 <= x1)) return Error{"camera: the whole surface is behind the camera"};
    if (behind) return base;
    const double room_x = std::max(1.0, width - 2.0 * margin_px);
    const double room_y = std::max(1.0, height - 2.0 * margin_px);
    const double span = std::max(x1 - x0, (y1 - y0) * room_x / room_y);
    if (span > 0.0) v.k_ = room_x / span;
    v.cx_ = width * 0.5 - v.k_ * (x0 + x1) * 0.5;
    v.cy_ = height * 0.5 + v.k_ * (y0 + y1) * 0.5;
    return v;
}

Vec3 View::to_view(Vec3 world) const {
    Vec3 d = world - eye_;
    return {d.dot(right_), d.dot(up_), d.dot(forward_)};
}

Vec3 View::project(Vec3 world) const {
    Vec3 w = to_view(world);
    double X = w.x, Y = w.y;
    if (projection_ == Projection::Perspective) X /= w.z, Y /= w.z;
    return {cx_ + k_ * X, cy_ - k_ * Y, w.z};
}

double View::depth(Vec3 world) const { return (world - eye_).dot(forward_); }

bool View::in_front(Vec3 world) const { return depth(world) >= near_; }

double View::near_depth() const { return near_; }

Vec3 View::to_viewer(Vec3 world) const {
    if (projection_ == Projection::Orthographic) return -forward_;
    return (eye_ - world).normalized();
}

}  // namespace bezel
