// A linear-light RGB accumulation buffer with per-pixel coverage, for the surface pictures.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "bezel/image.hpp"

namespace bezel::surface_detail {

struct LinearRgb {
    float r = 0, g = 0, b = 0;
};

// sRGB (IEC 61966-2-1) byte → linear [0, 1], and back (rounded).
float srgb_to_linear(std::uint8_t v);
std::uint8_t linear_to_srgb(float v);
LinearRgb linear(Rgba8 c);

class Framebuffer {
public:
    Framebuffer(int width, int height);
    int width() const { return width_; }
    int height() const { return height_; }
    // Saturating "under": adds min(alpha, 1 − coverage so far) of `c` at (x, y). Front-to-back
    // drawing with this is OpenGL's GL_SRC_ALPHA_SATURATE polygon antialiasing: abutting
    // triangles' partial coverages add up to 1 instead of leaving a seam.
    void add_saturating(int x, int y, float alpha, LinearRgb c) {
        std::size_t k = index(x, y);
        float take = std::min(alpha, 1.0f - cover_[k]);
        if (take <= 0.0f) return;
        rgb_[k].r += take * c.r, rgb_[k].g += take * c.g, rgb_[k].b += take * c.b;
        cover_[k] += take;
    }
    // The same with a depth test that repairs the depth sort where it got the order wrong
    // (pieces that interpenetrate, like the teapot's spout entering the body). Each pixel keeps
    // a front layer (composited by saturation, as above) over a back layer. A fragment nearer
    // than the front layer's depth by more than `margin` pushes the front layer into the back
    // (front over back) and starts a new front layer; anything else saturates into the front
    // layer. So a later, nearer surface covers what the sort drew too early, and abutting
    // triangles of that surface still add up without seams.
    void add_with_depth(int x, int y, float alpha, LinearRgb c, float depth, float margin) {
        std::size_t k = index(x, y);
        if (cover_[k] > 0.0f && depth < depth_[k] - margin) {
            float rest = 1.0f - cover_[k];
            back_[k].r = rgb_[k].r + rest * back_[k].r;
            back_[k].g = rgb_[k].g + rest * back_[k].g;
            back_[k].b = rgb_[k].b + rest * back_[k].b;
            back_cover_[k] = cover_[k] + rest * back_cover_[k];
            rgb_[k] = {};
            cover_[k] = 0.0f;
            depth_[k] = depth;
        } else {
            depth_[k] = std::min(depth_[k], depth);
        }
        add_saturating(x, y, alpha, c);
    }
    float cover(int x, int y) const { return cover_[index(x, y)]; }
    // The picture: front over back over `background`, encoded to sRGB, opaque.
    Image resolve(Rgba8 background) const;

private:
    std::size_t index(int x, int y) const {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
               static_cast<std::size_t>(x);
    }
    int width_, height_;
    std::vector<LinearRgb> rgb_;
    std::vector<float> cover_;
    std::vector<float> depth_;        // front layer's nearest depth (add_with_depth only)
    std::vector<LinearRgb> back_;     // back layer, premultiplied (add_with_depth only)
    std::vector<float> back_cover_;
};

}  // namespace bezel::surface_detail
