// COLR version 1 paint graphs → bezel/paint.hpp's ColorGlyph (OpenType 1.9 'COLR', "Paint
// tables"). Coordinates stay in font units, y up, as the table states them; the fixed-point
// fields become doubles exactly (FWORD integers, F2Dot14 = n / 2¹⁴, Fixed = n / 2¹⁶).
#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>

#include "bezel/limits.hpp"
#include "font/colr_table.hpp"

namespace bezel::font_detail {

namespace {

constexpr double kPi = 3.14159265358979323846;

double f2dot14(std::int32_t v) { return v / 16384.0; }
double fixed(std::int32_t v) { return v / 65536.0; }

// The transforms of the Translate, Scale, Rotate and Skew paints, in glyph space (y up), as
// matrices that map the child's coordinates into the parent's (x' = a·x + c·y + e, …).
// Angles are F2Dot14 multiples of 180°, counter-clockwise.
Affine rotation(double half_turns) {
    const double t = half_turns * kPi;
    return {std::cos(t), std::sin(t), -std::sin(t), std::cos(t), 0, 0};
}
// xSkewAngle turns the y axis counter-clockwise, so (0, 1) ↦ (−tan x, 1); ySkewAngle turns the x
// axis counter-clockwise, so (1, 0) ↦ (1, tan y).
Affine skew(double x_half_turns, double y_half_turns) {
    return {1, std::tan(y_half_turns * kPi), std::tan(-x_half_turns * kPi), 1, 0, 0};
}
// M about the centre c: T(c) · M · T(−c).
Affine around(const Affine& m, Point c) {
    return Affine::translate({c.x, c.y}) * m * Affine::translate({-c.x, -c.y});
}

// Bytes each paint format occupies (format byte included), by format number; 0: not a format.
// Var* formats (odd numbers from 3) are their static form plus a 4-byte varIndexBase.
constexpr std::size_t kPaintSize[33] = {
    0,  6,  5, 9,   // 1 ColrLayers, 2 Solid, 3 VarSolid
    16, 20,         // 4 LinearGradient, 5 Var
    16, 20,         // 6 RadialGradient, 7 Var
    12, 16,         // 8 SweepGradient, 9 Var
    6,  3,          // 10 Glyph, 11 ColrGlyph
    7,  7,          // 12 Transform, 13 VarTransform (the varIndexBase is in its VarAffine2x3)
    8,  12,         // 14 Translate, 15 Var
    8,  12,         // 16 Scale, 17 Var
    12, 16,         // 18 ScaleAroundCenter, 19 Var
    6,  10,         // 20 ScaleUniform, 21 Var
    10, 14,         // 22 ScaleUniformAroundCenter, 23 Var
    6,  10,         // 24 Rotate, 25 Var
    10, 14,         // 26 RotateAroundCenter, 27 Var
    8,  12,         // 28 Skew, 29 Var
    12, 16,         // 30 SkewAroundCenter, 31 Var
    8,              // 32 Composite
};

class GraphBuilder {
public:
    GraphBuilder(const ColrTable& table, const ColrContext& context, GlyphId root)
        : t_(table), b_(table.bytes()), ctx_(context), root_(root) {}

    Expected<ColorGlyph> build(std::uint32_t root_offset) {
        Expected<std::optional<Rect>> clip = t_.clip_box(root_);
        if (!clip) return fail(clip.error().message);
        out_.clip = *clip;
        active_.push_back(root_);
        Expected<PaintIndex> root = paint(root_offset, 1);
        if (!root) return root.error();
        out_.root = *root;
        return std::move(out_);
    }

private:
    const ColrTable& t_;
    const std::vector<std::uint8_t>& b_;
    const ColrContext& ctx_;
    GlyphId root_;
    ColorGlyph out_;
    // Per node: the visits painting it costs (itself and everything below, a shared node once per
    // reach) and its height (1 for a leaf): what a reused PaintColrGlyph adds to the budget.
    std::vector<std::uint64_t> cost_;
    std::vector<int> height_;
    std::uint64_t visits_ = 0;
    std::size_t stops_ = 0, outline_points_ = 0;   // against kMaxPaintColorStops, kMaxPaintOutlinePoints
    std::unordered_map<GlyphId, PaintIndex> colr_glyph_;   // PaintColrGlyph nodes built, by glyph
    std::vector<GlyphId> active_;                          // PaintColrGlyphs being built (a stack)
    std::unordered_map<GlyphId, std::uint32_t> outline_;   // outlines loaded, by glyph

    Error fail(const std::string& what) const {
        return Error{ctx_.file + ": " + ctx_.glyph_label(root_) + ": " + what};
    }
    Error damaged(const std::string& what, std::size_t offset) const {
        return fail("damaged COLR table: " + what + " at offset " + std::to_string(offset));
    }

    PaintIndex add(PaintNode node, std::uint64_t cost, int height) {
        out_.nodes.push_back(std::move(node));
        cost_.push_back(cost);
        height_.push_back(height);
        return static_cast<PaintIndex>(out_.nodes.size() - 1);
    }

    Expected<PaintColor> color(std::uint32_t palette_index, std::int32_t alpha) {
        PaintColor c;
        c.alpha = static_cast<float>(std::clamp(f2dot14(alpha), 0.0, 1.0));
        if (palette_index == 0xFFFF) {
            c.foreground = true;
            out_.uses_foreground = true;
            return c;
        }
        if (palette_index >= ctx_.palette.size())
            return fail("palette index " + std::to_string(palette_index) + " out of range (the palette has " +
                        std::to_string(ctx_.palette.size()) + " entries)");
        c.color = ctx_.palette[palette_index];
        return c;
    }

    // The ColorLine (or VarColorLine, `var`) at `offset`, stops sorted by offset (stable).
    Expected<ColorLine> color_line(std::uint64_t offset, bool var) {
        if (!fits(b_, offset, 3)) return damaged("colour line past the end", offset);
        const auto o = static_cast<std::size_t>(offset);
        ColorLine line;
        // An extend value the spec does not define is read as pad (the spec's rule).
        const std::uint32_t extend = read_u8(b_, o);
        line.extend = extend == 1 ? Extend::Repeat : extend == 2 ? Extend::Reflect : Extend::Pad;
        const std::uint32_t count = read_u16(b_, o + 1);
        const std::size_t stride = var ? 10 : 6;   // ColorStop, VarColorStop (+ varIndexBase)
        if (!fits(b_, o + 3, std::uint64_t{stride} * count)) return damaged("colour stops past the end", offset);
        stops_ += count;
        if (stops_ > kMaxPaintColorStops)
            return fail("COLR gradients hold more than " + std::to_string(kMaxPaintColorStops) + " colour stops");
        line.stops.reserve(count);
        for (std::uint32_t i = 0; i < count; ++i) {
            const std::size_t s = o + 3 + i * stride;
            Expected<PaintColor> c = color(read_u16(b_, s + 2), read_s16(b_, s + 4));
            if (!c) return c.error();
            line.stops.push_back({static_cast<float>(f2dot14(read_s16(b_, s))), *c});
        }
        std::stable_sort(line.stops.begin(), line.stops.end(),
                         [](const ColorStop& x, const ColorStop& y) { return x.offset < y.offset; });
        return line;
    }

    Expected<std::uint32_t> outline(GlyphId gid) {
        if (gid >= ctx_.glyph_count)
            return fail("PaintGlyph names glyph " + std::to_string(gid) + ", out of range (the font has " +
                        std::to_string(ctx_.glyph_count) + " glyphs)");
        if (auto it = outline_.find(gid); it != outline_.end()) return it->second;
        Expected<Path> path = ctx_.load_outline(gid);
        if (!path) return fail("outline of " + ctx_.glyph_label(gid) + ": " + path.error().message);
        outline_points_ += path->points().size();
        if (outline_points_ > kMaxPaintOutlinePoints)
            return fail("COLR outlines hold more than " + std::to_string(kMaxPaintOutlinePoints) + " points");
        const auto index = static_cast<std::uint32_t>(out_.outlines.size());
        out_.outlines.push_back(std::move(*path));
        outline_.emplace(gid, index);
        return index;
    }

    // The paint at table offset `parent` + the Offset24 stored at `field`.
    Expected<PaintIndex> child(std::size_t parent, std::size_t field, int depth) {
        const std::uint32_t rel = read_u24(b_, field);
        if (rel == 0) return damaged("null paint offset", parent);
        return paint(std::uint64_t{parent} + rel, depth + 1);
    }

    // A transform node over the child paint at `field`.
    Expected<PaintIndex> transform(const Affine& m, std::size_t o, int depth) {
        Expected<PaintIndex> c = child(o, o + 1, depth);
        if (!c) return c;
        return add(PaintTransform{m, *c}, 1 + cost_[*c], 1 + height_[*c]);
    }

    Expected<PaintIndex> colr_glyph(GlyphId gid, int depth) {
        if (auto it = colr_glyph_.find(gid); it != colr_glyph_.end()) {
            const PaintIndex node = it->second;
            if (depth - 1 + height_[node] > kMaxPaintDepth)
                return fail("COLR paint graph nests deeper than " + std::to_string(kMaxPaintDepth));
            visits_ += cost_[node] - 1;   // paint() counted this node already
            if (visits_ > kMaxPaintNodes)
                return fail("COLR paint graph visits more than " + std::to_string(kMaxPaintNodes) + " nodes");
            return node;
        }
        if (std::find(active_.begin(), active_.end(), gid) != active_.end())
            return fail("COLR paint graph loops: PaintColrGlyph of " + ctx_.glyph_label(gid) + " inside itself");
        const std::optional<std::uint32_t> root = t_.v1_root(gid);
        // A glyph the BaseGlyphList does not have paints nothing (the spec's rule).
        if (!root) return add(PaintLayers{}, 1, 1);
        Expected<std::optional<Rect>> clip = t_.clip_box(gid);
        if (!clip) return fail(clip.error().message);
        active_.push_back(gid);
        Expected<PaintIndex> c = paint(*root, depth + 1);
        active_.pop_back();
        if (!c) return c;
        const PaintIndex node = add(PaintColrGlyph{*c, *clip}, 1 + cost_[*c], 1 + height_[*c]);
        colr_glyph_.emplace(gid, node);
        return node;
    }

    Expected<PaintIndex> paint(std::uint64_t offset, int depth) {
        if (depth > kMaxPaintDepth)
            return fail("COLR paint graph nests deeper than " + std::to_string(kMaxPaintDepth));
        if (++visits_ > kMaxPaintNodes)
            return fail("COLR paint graph visits more than " + std::to_string(kMaxPaintNodes) + " nodes");
        if (!fits(b_, offset, 1)) return damaged("paint past the end", offset);
        const auto o = static_cast<std::size_t>(offset);
        const std::uint32_t format = read_u8(b_, o);
        if (format == 0 || format > 32) return damaged("unknown paint format " + std::to_string(format), o);
        if (!fits(b_, o, kPaintSize[format])) return damaged("paint past the end", o);
        const bool var = format % 2 == 1 && format >= 3 && format <= 31;

        switch (format) {
            case 1: {   // PaintColrLayers: numLayers (uint8), firstLayerIndex (uint32) into the LayerList
                const std::uint32_t count = read_u8(b_, o + 1), first = read_u32(b_, o + 2);
                if (std::uint64_t{first} + count > t_.num_layers_v1())
                    return damaged("PaintColrLayers past the LayerList", o);
                PaintLayers layers;
                std::uint64_t cost = 1;
                int height = 1;
                for (std::uint32_t i = 0; i < count; ++i) {
                    const std::size_t entry = t_.layer_list() + 4 + std::size_t{first + i} * 4;
                    Expected<PaintIndex> c = paint(std::uint64_t{t_.layer_list()} + read_u32(b_, entry), depth + 1);
                    if (!c) return c;
                    layers.layers.push_back(*c);
                    cost += cost_[*c];
                    height = std::max(height, 1 + height_[*c]);
                }
                return add(std::move(layers), cost, height);
            }
            case 2:
            case 3: {   // PaintSolid: paletteIndex, alpha
                Expected<PaintColor> c = color(read_u16(b_, o + 1), read_s16(b_, o + 3));
                if (!c) return c.error();
                return add(PaintSolid{*c}, 1, 1);
            }
            case 4:
            case 5:
            case 6:
            case 7:
            case 8:
            case 9: {   // gradients: Offset24 colour line, then the geometry
                Expected<ColorLine> line = color_line(std::uint64_t{o} + read_u24(b_, o + 1), var);
                if (!line) return line.error();
                // Without a stop a gradient paints nothing.
                if (line->stops.empty()) return add(PaintLayers{}, 1, 1);
                auto s = [&](std::size_t at) { return double(read_s16(b_, o + at)); };
                if (format <= 5) {
                    return add(PaintLinearGradient{std::move(*line), {s(4), s(6)}, {s(8), s(10)}, {s(12), s(14)}}, 1, 1);
                }
                if (format <= 7) {
                    PaintRadialGradient g{std::move(*line), {s(4), s(6)}, {s(10), s(12)},
                                          double(read_u16(b_, o + 8)), double(read_u16(b_, o + 14))};
                    return add(std::move(g), 1, 1);
                }
                // Sweep angles are stored biased: degrees = (F2Dot14 + 1) · 180, so that 360° fits.
                const double start = (f2dot14(read_s16(b_, o + 8)) + 1.0) * 180.0;
                const double end = (f2dot14(read_s16(b_, o + 10)) + 1.0) * 180.0;
                return add(PaintSweepGradient{std::move(*line), {s(4), s(6)}, start, end}, 1, 1);
            }
            case 10: {   // PaintGlyph: Offset24 paint, glyphID
                Expected<std::uint32_t> shape = outline(read_u16(b_, o + 4));
                if (!shape) return shape.error();
                Expected<PaintIndex> c = child(o, o + 1, depth);
                if (!c) return c;
                return add(PaintGlyph{*shape, *c}, 1 + cost_[*c], 1 + height_[*c]);
            }
            case 11:   // PaintColrGlyph: glyphID
                return colr_glyph(read_u16(b_, o + 1), depth);
            case 12:
            case 13: {   // PaintTransform: Offset24 paint, Offset24 (Var)Affine2x3 of Fixed xx yx xy yy dx dy
                const std::uint64_t m = std::uint64_t{o} + read_u24(b_, o + 4);
                if (!fits(b_, m, var ? 28 : 24)) return damaged("Affine2x3 past the end", o);
                const auto a = static_cast<std::size_t>(m);
                auto f = [&](std::size_t i) { return fixed(read_s32(b_, a + 4 * i)); };
                return transform(Affine{f(0), f(1), f(2), f(3), f(4), f(5)}, o, depth);
            }
            case 14:
            case 15:   // PaintTranslate: dx, dy (FWORD)
                return transform(Affine::translate({double(read_s16(b_, o + 4)), double(read_s16(b_, o + 6))}), o,
                                 depth);
            case 16:
            case 17:
            case 18:
            case 19: {   // PaintScale[AroundCenter]: scaleX, scaleY (F2Dot14)[, centerX, centerY]
                const Affine m = Affine::scale(f2dot14(read_s16(b_, o + 4)), f2dot14(read_s16(b_, o + 6)));
                if (format <= 17) return transform(m, o, depth);
                return transform(around(m, {double(read_s16(b_, o + 8)), double(read_s16(b_, o + 10))}), o, depth);
            }
            case 20:
            case 21:
            case 22:
            case 23: {   // PaintScaleUniform[AroundCenter]: scale[, centerX, centerY]
                const Affine m = Affine::scale(f2dot14(read_s16(b_, o + 4)));
                if (format <= 21) return transform(m, o, depth);
                return transform(around(m, {double(read_s16(b_, o + 6)), double(read_s16(b_, o + 8))}), o, depth);
            }
            case 24:
            case 25:
            case 26:
            case 27: {   // PaintRotate[AroundCenter]: angle[, centerX, centerY]
                const Affine m = rotation(f2dot14(read_s16(b_, o + 4)));
                if (format <= 25) return transform(m, o, depth);
                return transform(around(m, {double(read_s16(b_, o + 6)), double(read_s16(b_, o + 8))}), o, depth);
            }
            case 28:
            case 29:
            case 30:
            case 31: {   // PaintSkew[AroundCenter]: xSkewAngle, ySkewAngle[, centerX, centerY]
                const Affine m = skew(f2dot14(read_s16(b_, o + 4)), f2dot14(read_s16(b_, o + 6)));
                if (format <= 29) return transform(m, o, depth);
                return transform(around(m, {double(read_s16(b_, o + 8)), double(read_s16(b_, o + 10))}), o, depth);
            }
            case 32: {   // PaintComposite: Offset24 source, compositeMode (uint8), Offset24 backdrop
                const std::uint32_t mode = read_u8(b_, o + 4);
                if (mode >= static_cast<std::uint32_t>(kCompositeModeCount))
                    return damaged("unknown composite mode " + std::to_string(mode), o);
                Expected<PaintIndex> source = child(o, o + 1, depth);
                if (!source) return source;
                Expected<PaintIndex> backdrop = child(o, o + 5, depth);
                if (!backdrop) return backdrop;
                return add(PaintComposite{*source, *backdrop, static_cast<CompositeMode>(mode)},
                           1 + cost_[*source] + cost_[*backdrop],
                           1 + std::max(height_[*source], height_[*backdrop]));
            }
            default:
                return damaged("unknown paint format " + std::to_string(format), o);
        }
    }
};

}  // namespace

Expected<ColorGlyph> build_colr_v1(const ColrTable& table, GlyphId gid, const ColrContext& context) {
    const std::optional<std::uint32_t> root = table.v1_root(gid);
    if (!root) return Error{context.file + ": " + context.glyph_label(gid) + ": no COLR version 1 paint"};
    return GraphBuilder(table, context, gid).build(*root);
}

}  // namespace bezel::font_detail
