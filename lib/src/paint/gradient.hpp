// Private: colour lines and the three gradients, evaluated at a point of glyph space.
#pragma once

#include "bezel/paint.hpp"
#include "paint/pixel.hpp"

namespace bezel::paint_detail {

// The colour line at `t` (any finite t; the extend mode folds it onto the stops' span),
// premultiplied. Interpolation between two stops is of STRAIGHT colour and alpha, premultiplied
// afterwards (gradient.cpp says why).
Pixel color_line_at(const ColorLine& line, double t, const Rgba8& foreground);

// One gradient node made ready for per-pixel evaluation: the colour at a glyph-space point.
class Gradient {
public:
    explicit Gradient(const PaintLinearGradient& g);
    explicit Gradient(const PaintRadialGradient& g);
    explicit Gradient(const PaintSweepGradient& g);

    // False when the gradient paints nothing anywhere (degenerate geometry).
    bool paints() const { return paints_; }
    // The colour line position of glyph-space point p; false where the gradient paints nothing.
    bool t_at(Point p, double& t) const;
    const ColorLine& line() const { return *line_; }

private:
    enum class Kind { Linear, Radial, Sweep } kind_;
    const ColorLine* line_;
    bool paints_ = true;
    // Linear: t = (p − p0)·axis, axis = (p1' − p0) / |p1' − p0|².
    Point p0_;
    Vec2 axis_;
    // Radial: c0, cd = c1 − c0, r0, dr = r1 − r0, a = cd·cd − dr².
    Vec2 cd_;
    double r0_ = 0, dr_ = 0, a_ = 0;
    bool linear_equation_ = false;
    // Sweep: centre p0_, angles in degrees.
    double start_deg_ = 0, end_deg_ = 0;
};

}  // namespace bezel::paint_detail
