// CoverageCombine::Over and Add: the fill drawn (Replace) into scratch covering its box, then
// combined into the target pixel by pixel (raster.hpp states the rules).
//
// The box. A fill inks nothing outside the box of its points (polylines) or control points
// (a path: a Bézier lies in the hull of its control points, and an affine map keeps that), so
// combining only that box, clipped to the target, is combining everywhere with b = 0 outside.
// Edges left of the box do not exist, and the sub-fill clips at the target's sides as the
// whole fill would. An LCD fill spreads two subpixels past its outline (the filter's reach):
// its box grows by one display pixel on each side. A box that is not finite (a NaN or infinite
// point) becomes the whole target, so the sub-fill meets the point and reports it as a Replace
// fill would; the target is written only after the sub-fill succeeded.
#include <algorithm>
#include <cmath>
#include <string>

#include "bezel/raster.hpp"
#include "raster/fill_common.hpp"
#include "raster/overlap.hpp"

namespace bezel {

namespace {

// Plain form of Over in bytes: out = a + b − round(a·b/255). a·b/255 is never k + ½ (255 is
// odd), so +127 then floor rounds it; the result stays ≤ 255 since a + b − a·b/255 =
// 255 − (255 − a)(255 − b)/255.
inline std::uint8_t over(std::uint8_t a, std::uint8_t b) {
    return static_cast<std::uint8_t>(a + b - (a * b + 127) / 255);
}
// a + b − a·b written as 1 − (1 − a)(1 − b): equal in real numbers, and in floats it stays in
// [0, 1] for a, b in [0, 1] (each factor and their product do), where a + b − a·b can round
// past 1.
inline float over(float a, float b) { return 1.0f - (1.0f - a) * (1.0f - b); }
inline std::uint8_t add(std::uint8_t a, std::uint8_t b) {
    return static_cast<std::uint8_t>(std::min(a + b, 255));
}
inline float add(float a, float b) { return std::min(a + b, 1.0f); }

template <typename T>
void combine_row(T* target, const T* fill, int n, CoverageCombine rule) {
    if (rule == CoverageCombine::Over)
        for (int i = 0; i < n; ++i) target[i] = over(target[i], fill[i]);
    else
        for (int i = 0; i < n; ++i) target[i] = add(target[i], fill[i]);
}

// The pixel box [x0, x1) × [y0, y1) of `box` in a w × h target (whole target if not finite).
struct PixelBox {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};
PixelBox pixel_box(const Rect& box, int w, int h) {
    PixelBox b{0, 0, w, h};
    if (!(std::isfinite(box.x0) && std::isfinite(box.x1) && std::isfinite(box.y0) &&
          std::isfinite(box.y1)))
        return b;
    if (box.x0 > box.x1 || box.y0 > box.y1) return {0, 0, 0, 0};   // no point: nothing inked
    raster_detail::pixel_range(box.x0, box.x1, 0.0, w, b.x0, b.x1);
    raster_detail::pixel_range(box.y0, box.y1, 0.0, h, b.y0, b.y1);
    if (b.x0 >= b.x1 || b.y0 >= b.y1) b = {0, 0, 0, 0};
    return b;
}

// `fill(sub, dx, dy)` draws the fill, moved by (dx, dy) px, into `sub` (Replace); then `sub` is
// combined into `target` at the box. `cells` is how many elements one display pixel takes.
template <typename View, typename T, typename Fill>
Status combine_into(const View& target, const PixelBox& b, int cells, std::vector<T>& scratch,
                    CoverageCombine rule, Fill&& fill) {
    const int w = b.x1 - b.x0, h = b.y1 - b.y0;
    const std::size_t need =
        static_cast<std::size_t>(w) * static_cast<std::size_t>(cells) * static_cast<std::size_t>(h);
    if (scratch.size() < need) scratch.resize(need);
    const View sub{scratch.data(), w * cells, h, static_cast<std::ptrdiff_t>(w) * cells};
    if (Status st = fill(sub, -static_cast<double>(b.x0), -static_cast<double>(b.y0)); !st)
        return st;
    for (int y = 0; y < h; ++y)
        combine_row(target.row(b.y0 + y) + static_cast<std::ptrdiff_t>(b.x0) * cells, sub.row(y),
                    w * cells, rule);
    return ok_status();
}

Rect control_box(const Path& path, const Affine& m) {
    Rect box = Rect::empty();
    for (const Point& p : path.points()) box = box.union_with(m * p);
    return box;
}

Rect points_box(const Polylines& lines, Vec2 origin) {
    Rect box = Rect::empty();
    for (const Point& p : lines.points) box = box.union_with(Point{p.x + origin.x, p.y + origin.y});
    return box;
}

Affine moved(Affine m, double dx, double dy) {
    m.e += dx;
    m.f += dy;
    return m;
}

}  // namespace

Status Rasterizer::fill_combined(const Polylines& lines, const MaskView& target,
                                 const FillOptions& options) {
    if (Status st = raster_detail::check_target(target); !st) return st;
    if (!options.origin.is_finite()) return Error{"raster origin is not finite (NaN or infinity)"};
    const PixelBox b = pixel_box(points_box(lines, options.origin), target.width, target.height);
    return combine_into(target, b, 1, features().combine_bytes, options.combine,
                        [&](const MaskView& sub, double dx, double dy) {
                            return fill_impl(lines, options.rule, sub,
                                             options.origin + Vec2{dx, dy});
                        });
}

Status Rasterizer::fill_combined(const Polylines& lines, const FloatMaskView& target,
                                 const FillOptions& options) {
    if (Status st = raster_detail::check_target(target); !st) return st;
    if (!options.origin.is_finite()) return Error{"raster origin is not finite (NaN or infinity)"};
    const PixelBox b = pixel_box(points_box(lines, options.origin), target.width, target.height);
    return combine_into(target, b, 1, features().combine_floats, options.combine,
                        [&](const FloatMaskView& sub, double dx, double dy) {
                            return fill_impl(lines, options.rule, sub,
                                             options.origin + Vec2{dx, dy});
                        });
}

Status Rasterizer::fill_path_combined(const Path& path, const Affine& transform,
                                      const MaskView& target, const FillOptions& options) {
    if (Status st = raster_detail::check_target(target); !st) return st;
    const bool lcd = options.format == CoverageFormat::Lcd;
    if (lcd && target.width % 3 != 0)
        return Error{"LCD target width " + std::to_string(target.width) +
                     " is not a multiple of 3 (3 bytes per display pixel)"};
    Rect box = control_box(path, transform);
    if (lcd) box = box.inflated(kLcdPaddingPx);
    const PixelBox b = pixel_box(box, lcd ? target.width / 3 : target.width, target.height);
    return combine_into(target, b, lcd ? 3 : 1, features().combine_bytes, options.combine,
                        [&](const MaskView& sub, double dx, double dy) {
                            const Affine m = moved(transform, dx, dy);
                            return lcd ? fill_path_lcd(path, m, sub, options)
                                       : fill_path_gray(path, m, sub, options);
                        });
}

Status Rasterizer::fill_path_combined(const Path& path, const Affine& transform,
                                      const FloatMaskView& target, const FillOptions& options) {
    if (Status st = raster_detail::check_target(target); !st) return st;
    const PixelBox b = pixel_box(control_box(path, transform), target.width, target.height);
    return combine_into(target, b, 1, features().combine_floats, options.combine,
                        [&](const FloatMaskView& sub, double dx, double dy) {
                            return fill_path_gray(path, moved(transform, dx, dy), sub, options);
                        });
}

}  // namespace bezel
