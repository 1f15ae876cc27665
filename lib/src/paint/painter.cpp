// Painter: the paint graph walked into float premultiplied layers, then rounded to RGBA8.
//
// The walk carries a current transform (CTM: the node's space → target pixels, y down) and a
// current clip: a coverage mask in [0, 1] and the pixel box outside which it is 0. Fills (solid
// and gradients) are composited SrcOver onto the current layer through the clip:
//   dst = src·cov + dst·(1 − src.a·cov)
// PaintGlyph and clip boxes narrow the clip by multiplying its coverage by theirs (nested clips
// intersect), so an anti-aliased edge is drawn once, with the rasterizer's exact area coverage.
// PaintColrLayers needs no layer of its own: painting its children one after another onto the
// same layer is SrcOver of each, SrcOver being associative. PaintComposite paints its backdrop
// and its source into two fresh layers (cleared inside the clip's box, which bounds everything
// its children can touch), composites them per pixel, and SrcOvers the result onto the layer
// below.
//
// Gradients are evaluated at each pixel centre mapped back through the inverse CTM into the
// gradient's own space, so they follow every transform exactly (y up there, y down here).
//
// Scratch: one float RGBA layer per composite level (two per PaintComposite) and one mask per
// clip level, each of the target's size, kept between calls: a repeat paint of the same or a
// smaller target allocates nothing.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "bezel/limits.hpp"
#include "bezel/paint.hpp"
#include "paint/composite.hpp"
#include "paint/gradient.hpp"
#include "paint/graph.hpp"
#include "paint/pixel.hpp"

namespace bezel {

using paint_detail::Pixel;

namespace {

// The current clip: coverage `mask` (target-sized rows of `stride` floats; null means 1
// everywhere) inside the pixel box [x0, x1) × [y0, y1), 0 outside it.
struct Clip {
    const float* mask = nullptr;
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x0 >= x1 || y0 >= y1; }
};

}  // namespace

struct Painter::Impl {
    Rasterizer raster;
    std::vector<std::uint8_t> on_path;
    std::vector<std::vector<Pixel>> layers;   // [0] is the glyph; then two per composite level
    std::vector<std::vector<float>> masks;    // one per clip level
    Polylines box_polygon;                    // a clip box's four corners, reused
    const ColorGlyph* glyph = nullptr;
    Rgba8 foreground;
    FlattenOptions flatten;
    int w = 0, h = 0;
    std::string error;

    Pixel* layer(std::size_t i) {
        if (layers.size() <= i) layers.resize(i + 1);
        const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
        if (layers[i].size() < n) layers[i].resize(n);
        return layers[i].data();
    }
    float* mask(std::size_t i) {
        if (masks.size() <= i) masks.resize(i + 1);
        const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
        if (masks[i].size() < n) masks[i].resize(n);
        return masks[i].data();
    }
    std::size_t at(int x, int y) const {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(w) +
               static_cast<std::size_t>(x);
    }

    // The pixel box of a target-space rectangle, within `within`.
    static Clip box_within(const Rect& r, const Clip& within) {
        Clip c;
        // is_empty() is also true for a NaN side: such a box covers nothing.
        if (r.is_empty()) return c;
        auto lo = [](double v, int min, int max) {
            return static_cast<int>(std::clamp(std::floor(v), double(min), double(max)));
        };
        auto hi = [](double v, int min, int max) {
            return static_cast<int>(std::clamp(std::ceil(v), double(min), double(max)));
        };
        c.x0 = lo(r.x0, within.x0, within.x1);
        c.x1 = hi(r.x1, within.x0, within.x1);
        c.y0 = lo(r.y0, within.y0, within.y1);
        c.y1 = hi(r.y1, within.y0, within.y1);
        return c;
    }

    // The new clip's mask (already holding this clip level's own coverage in its box) multiplied
    // by the enclosing clip's.
    void intersect_with(float* m, const Clip& box, const Clip& outer) const {
        if (!outer.mask) return;
        for (int y = box.y0; y < box.y1; ++y) {
            float* row = m + at(0, y);
            const float* o = outer.mask + at(0, y);
            for (int x = box.x0; x < box.x1; ++x) row[x] *= o[x];
        }
    }

    bool fail(const Error& e) {
        error = e.message;
        return false;
    }

    // SrcOver of a fill through the clip: `color_at(x, y, px)` yields the fill's premultiplied
    // colour at pixel (x, y), false where it paints nothing.
    template <typename ColorAt>
    void fill(const Clip& clip, Pixel* dst, ColorAt color_at) {
        for (int y = clip.y0; y < clip.y1; ++y) {
            Pixel* d = dst + at(0, y);
            const float* m = clip.mask ? clip.mask + at(0, y) : nullptr;
            for (int x = clip.x0; x < clip.x1; ++x) {
                const float cov = m ? m[x] : 1.0f;
                if (cov <= 0.0f) continue;
                Pixel s;
                if (!color_at(x, y, s)) continue;
                s = {s.r * cov, s.g * cov, s.b * cov, s.a * cov};
                paint_detail::src_over(d[x], s);
            }
        }
    }

    template <typename G>
    void paint_gradient(const G& node, const Affine& ctm, const Clip& clip, Pixel* dst) {
        const paint_detail::Gradient g(node);
        if (!g.paints()) return;
        const double det = ctm.determinant();
        if (!(det != 0.0) || !std::isfinite(det)) return;  // collapsed: no area to paint
        const Affine inv = ctm.inverse();
        if (!inv.is_finite()) return;
        fill(clip, dst, [&](int x, int y, Pixel& out) {
            double t;
            if (!g.t_at(inv * Point{x + 0.5, y + 0.5}, t)) return false;
            out = paint_detail::color_line_at(g.line(), t, foreground);
            return true;
        });
    }

    bool paint(PaintIndex i, const Affine& ctm, const Clip& clip, Pixel* dst, std::size_t mask_level,
               std::size_t layer_level) {
        if (clip.empty()) return true;
        const PaintNode& node = glyph->nodes[i];
        if (const auto* n = std::get_if<PaintLayers>(&node)) {
            for (PaintIndex c : n->layers)
                if (!paint(c, ctm, clip, dst, mask_level, layer_level)) return false;
            return true;
        }
        if (const auto* n = std::get_if<PaintSolid>(&node)) {
            const Pixel c = paint_detail::premultiplied(paint_detail::resolve(n->color, foreground));
            if (c.a <= 0.0f) return true;
            fill(clip, dst, [&](int, int, Pixel& out) {
                out = c;
                return true;
            });
            return true;
        }
        if (const auto* n = std::get_if<PaintLinearGradient>(&node)) {
            paint_gradient(*n, ctm, clip, dst);
            return true;
        }
        if (const auto* n = std::get_if<PaintRadialGradient>(&node)) {
            paint_gradient(*n, ctm, clip, dst);
            return true;
        }
        if (const auto* n = std::get_if<PaintSweepGradient>(&node)) {
            paint_gradient(*n, ctm, clip, dst);
            return true;
        }
        if (const auto* n = std::get_if<PaintTransform>(&node))
            return paint(n->paint, ctm * n->transform, clip, dst, mask_level, layer_level);
        if (const auto* n = std::get_if<PaintGlyph>(&node)) {
            const Path& outline = glyph->outlines[n->outline];
            // The control points' hull holds the outline: their box bounds its pixels.
            Rect r = Rect::empty();
            for (Point p : outline.points()) r = r.union_with(ctm * p);
            if (!(std::isfinite(r.x0) && std::isfinite(r.y0) && std::isfinite(r.x1) &&
                  std::isfinite(r.y1)) && !outline.empty())
                return fail(Error{"outline " + std::to_string(n->outline) +
                                  " is not finite in target pixels"});
            const Clip box = box_within(r, clip);
            if (box.empty()) return true;
            float* m = mask(mask_level);
            FillOptions fo;
            fo.flatten = flatten;
            // The union of the contours, whatever their winding: colour glyphs build shapes from
            // pieces that abut with opposite windings, where plain accumulation leaves a seam.
            // One contour has no other to meet (accumulation is exact for it but where it crosses
            // itself), and the accurate fill costs several times as much, so only outlines of two
            // or more contours take it.
            fo.overlap = outline.contour_count() > 1 ? OverlapMode::Accurate : OverlapMode::Accumulate;
            fo.origin = {-static_cast<double>(box.x0), -static_cast<double>(box.y0)};
            const FloatMaskView view{m + at(box.x0, box.y0), box.x1 - box.x0, box.y1 - box.y0, w};
            Status s = raster.fill_path(outline, ctm, view, fo);
            if (!s) return fail(s.error());
            intersect_with(m, box, clip);
            Clip inner = box;
            inner.mask = m;
            return paint(n->paint, ctm, inner, dst, mask_level + 1, layer_level);
        }
        if (const auto* n = std::get_if<PaintColrGlyph>(&node)) {
            if (!n->clip) return paint(n->paint, ctm, clip, dst, mask_level, layer_level);
            Clip inner;
            if (!clip_to_box(*n->clip, ctm, clip, mask_level, inner)) return false;
            return paint(n->paint, ctm, inner, dst, mask_level + 1, layer_level);
        }
        const auto& n = std::get<PaintComposite>(node);
        Pixel* backdrop = layer(layer_level);
        Pixel* source = layer(layer_level + 1);
        for (int y = clip.y0; y < clip.y1; ++y) {
            std::fill(backdrop + at(clip.x0, y), backdrop + at(clip.x1, y), Pixel{});
            std::fill(source + at(clip.x0, y), source + at(clip.x1, y), Pixel{});
        }
        if (!paint(n.backdrop, ctm, clip, backdrop, mask_level, layer_level + 2)) return false;
        if (!paint(n.source, ctm, clip, source, mask_level, layer_level + 2)) return false;
        for (int y = clip.y0; y < clip.y1; ++y) {
            for (int x = clip.x0; x < clip.x1; ++x) {
                const std::size_t k = at(x, y);
                paint_detail::src_over(dst[k], paint_detail::composite(n.mode, source[k], backdrop[k]));
            }
        }
        return true;
    }

    // A clip box (glyph space, mapped by the CTM: a rotated box is a parallelogram) rasterized
    // into the mask of `level` and intersected with `outer`.
    bool clip_to_box(const Rect& r, const Affine& ctm, const Clip& outer, std::size_t level,
                     Clip& inner) {
        box_polygon.clear();
        Rect device = Rect::empty();
        for (Point p : {Point{r.x0, r.y0}, Point{r.x1, r.y0}, Point{r.x1, r.y1}, Point{r.x0, r.y1}}) {
            box_polygon.points.push_back(ctm * p);
            device = device.union_with(box_polygon.points.back());
        }
        box_polygon.contour_ends.push_back(4);
        if (!(std::isfinite(device.x0) && std::isfinite(device.y0) && std::isfinite(device.x1) &&
              std::isfinite(device.y1)))
            return fail(Error{"clip box is not finite in target pixels"});
        inner = box_within(r.is_empty() ? Rect::empty() : device, outer);
        if (inner.empty()) return true;
        float* m = mask(level);
        FillOptions fo;
        fo.origin = {-static_cast<double>(inner.x0), -static_cast<double>(inner.y0)};
        const FloatMaskView view{m + at(inner.x0, inner.y0), inner.x1 - inner.x0,
                                 inner.y1 - inner.y0, w};
        Status s = raster.fill(box_polygon, view, fo);
        if (!s) return fail(s.error());
        intersect_with(m, inner, outer);
        inner.mask = m;
        return true;
    }
};

Painter::Painter() : impl_(std::make_unique<Impl>()) {}
Painter::~Painter() = default;
Painter::Painter(Painter&&) noexcept = default;
Painter& Painter::operator=(Painter&&) noexcept = default;

Status Painter::paint(const ColorGlyph& glyph, const PaintOptions& options, const RgbaView& target) {
    if (target.width < 0 || target.height < 0 || target.width > kMaxBitmapDim ||
        target.height > kMaxBitmapDim)
        return Error{"paint target " + std::to_string(target.width) + "x" +
                     std::to_string(target.height) + " is outside 0.." +
                     std::to_string(kMaxBitmapDim) + " pixels"};
    if (target.data == nullptr && target.width > 0 && target.height > 0)
        return Error{"paint target has no memory"};
    if (!options.transform.is_finite() || !(options.transform.determinant() != 0.0) ||
        !options.transform.inverse().is_finite())
        return Error{"paint transform is not finite or not invertible"};
    Impl& im = *impl_;
    if (Status s = paint_detail::validate(glyph, im.on_path); !s) return s;
    if (target.width == 0 || target.height == 0) return ok_status();

    im.glyph = &glyph;
    im.foreground = options.foreground;
    im.flatten = options.flatten;
    im.w = target.width;
    im.h = target.height;
    Pixel* out = im.layer(0);
    std::fill(out, out + static_cast<std::size_t>(im.w) * static_cast<std::size_t>(im.h), Pixel{});
    Clip all{nullptr, 0, 0, im.w, im.h};
    bool ok;
    if (glyph.clip) {
        Clip inner;
        ok = im.clip_to_box(*glyph.clip, options.transform, all, 0, inner) &&
             im.paint(glyph.root, options.transform, inner, out, 1, 1);
    } else {
        ok = im.paint(glyph.root, options.transform, all, out, 0, 1);
    }
    im.glyph = nullptr;
    if (!ok) return Error{"colour glyph: " + im.error};

    for (int y = 0; y < im.h; ++y) {
        std::uint8_t* d = target.row(y);
        const Pixel* p = out + im.at(0, y);
        for (int x = 0; x < im.w; ++x, d += 4, ++p) {
            const std::uint8_t a = paint_detail::to_byte(p->a);
            d[0] = std::min(paint_detail::to_byte(p->r), a);
            d[1] = std::min(paint_detail::to_byte(p->g), a);
            d[2] = std::min(paint_detail::to_byte(p->b), a);
            d[3] = a;
        }
    }
    return ok_status();
}

}  // namespace bezel
