// bezel_glyph_rasterizer: GlyphRasterizer over the rasterizer's own Font instance; single glyphs
// and sets into caller masks.
#include <cmath>

#include "bezel/limits.hpp"
#include "capi/handles.hpp"

using namespace bezel;
using namespace bezel::capi_detail;

namespace {

// bezel_glyph_options → GlyphRenderOptions, every field checked (the C++ calls check them too,
// per glyph; here they are refused once, when the rasterizer is made).
bezel_status to_render_options(const char* fn, const bezel_glyph_options& in,
                               GlyphRenderOptions& out) {
    if (!(in.size_px > 0 && in.size_px <= kMaxFontSizePx))
        return fail(nullptr, BEZEL_STATUS_OUT_OF_RANGE,
                    std::string(fn) + ": size_px " + std::to_string(in.size_px) +
                        " is outside (0, " + std::to_string(static_cast<int>(kMaxFontSizePx)) +
                        "]");
    if (!(std::fabs(in.offset_x_px) <= kMaxGlyphOffsetPx &&
          std::fabs(in.offset_y_px) <= kMaxGlyphOffsetPx))
        return fail(nullptr, BEZEL_STATUS_OUT_OF_RANGE,
                    std::string(fn) + ": offset (" + std::to_string(in.offset_x_px) + ", " +
                        std::to_string(in.offset_y_px) + ") is not finite or beyond " +
                        std::to_string(static_cast<int>(kMaxGlyphOffsetPx)) + " px");
    if (!(std::fabs(in.slant) <= kMaxSyntheticSlant))
        return fail(nullptr, BEZEL_STATUS_OUT_OF_RANGE,
                    std::string(fn) + ": slant " + std::to_string(in.slant) +
                        " is outside [-1, 1] (kMaxSyntheticSlant)");
    if (!(in.bold >= 0 && in.bold <= kMaxSyntheticBold))
        return fail(nullptr, BEZEL_STATUS_OUT_OF_RANGE,
                    std::string(fn) + ": bold " + std::to_string(in.bold) +
                        " is outside [0, 0.25] (kMaxSyntheticBold)");
    GlyphRenderOptions o;
    o.size_px = in.size_px;
    if (bezel_status s = to_hinting(nullptr, fn, raw_enum(in.hinting), o.hinting)) return s;
    if (bezel_status s =
            to_coverage(nullptr, fn, raw_enum(in.coverage), o.fill.format, o.fill.lcd_order))
        return s;
    o.offset_px = {in.offset_x_px, in.offset_y_px};
    o.embedded_bitmaps = in.embedded_bitmaps != 0;
    o.slant = in.slant;
    o.bold = in.bold;
    out = o;
    return BEZEL_STATUS_OK;
}

bezel_glyph_box to_box(const PreparedGlyph& g) {
    bezel_glyph_box box{};
    box.left = g.box.left;
    box.top = g.box.top;
    box.width = g.box.width;
    box.height = g.box.height;
    box.row_bytes = g.box.width * (g.options.fill.format == CoverageFormat::Lcd ? 3 : 1);
    box.buffer_size =
        static_cast<std::size_t>(box.row_bytes) * static_cast<std::size_t>(box.height);
    box.advance_px = g.box.advance_px;
    box.color = g.box.color ? 1 : 0;
    return box;
}

std::string glyph_label(std::uint32_t gid) { return "glyph " + std::to_string(gid); }

}  // namespace

extern "C" {

void bezel_glyph_options_init(bezel_glyph_options* options) {
    if (!options) return;
    *options = bezel_glyph_options{};
    options->size_px = 16;
    options->hinting = BEZEL_HINTING_NONE;
    options->coverage = BEZEL_COVERAGE_GRAY;
}

bezel_status bezel_glyph_rasterizer_create(const bezel_font* font,
                                           const bezel_glyph_options* options,
                                           bezel_glyph_rasterizer** out) {
    static const char* const fn = "bezel_glyph_rasterizer_create";
    return guarded(nullptr, fn, [&]() -> bezel_status {
        if (!font) return null_argument(nullptr, fn, "font");
        if (!out) return null_argument(nullptr, fn, "out");
        bezel_glyph_options o;
        bezel_glyph_options_init(&o);
        if (options) o = *options;
        GlyphRenderOptions render;
        if (bezel_status s = to_render_options(fn, o, render)) return s;
        Expected<Font> instance = Font::open(font->face);
        if (!instance) return fail(nullptr, BEZEL_STATUS_FONT_ERROR, instance.error().message);
        if (!font->variations.empty()) {
            Status set = instance->set_variations(font->variations);
            if (!set) return fail(nullptr, BEZEL_STATUS_FONT_ERROR, set.error().message);
        }
        // A colour glyph is drawn as its alpha (a mask has no colour); a font with neither
        // outlines nor colour glyphs has nothing this rasterizer can draw.
        if (!instance->has_color_bitmaps()) {
            Status outlines = instance->require_outlines();
            if (!outlines) return fail(nullptr, BEZEL_STATUS_FONT_ERROR, outlines.error().message);
        }
        // The GlyphRasterizer shares the Font's face, so the Font may move into the handle after.
        GlyphRasterizer raster(*instance);
        *out = new bezel_glyph_rasterizer{std::move(*instance), std::move(raster), render, {}, {},
                                          {}};
        return BEZEL_STATUS_OK;
    });
}

void bezel_glyph_rasterizer_destroy(bezel_glyph_rasterizer* rasterizer) { delete rasterizer; }

const char* bezel_glyph_rasterizer_last_error(const bezel_glyph_rasterizer* rasterizer) {
    return rasterizer ? rasterizer->error.c_str() : bezel_last_error();
}

bezel_status bezel_glyph_measure(bezel_glyph_rasterizer* rasterizer, std::uint32_t gid,
                                 bezel_glyph_box* box) {
    static const char* const fn = "bezel_glyph_measure";
    if (!rasterizer) return null_argument(nullptr, fn, "rasterizer");
    ErrorSlot* err = &rasterizer->error;
    return guarded(err, fn, [&]() -> bezel_status {
        if (!box) return null_argument(err, fn, "box");
        Expected<PreparedGlyph> g = rasterizer->raster.prepare(gid, rasterizer->options);
        if (!g) return fail(err, BEZEL_STATUS_FONT_ERROR, g.error().message);
        *box = to_box(*g);
        return BEZEL_STATUS_OK;
    });
}

bezel_status bezel_glyph_render(bezel_glyph_rasterizer* rasterizer, std::uint32_t gid,
                                std::uint8_t* buffer, std::size_t buffer_size,
                                std::ptrdiff_t stride, bezel_glyph_box* box) {
    static const char* const fn = "bezel_glyph_render";
    if (!rasterizer) return null_argument(nullptr, fn, "rasterizer");
    ErrorSlot* err = &rasterizer->error;
    return guarded(err, fn, [&]() -> bezel_status {
        Expected<PreparedGlyph> g = rasterizer->raster.prepare(gid, rasterizer->options);
        if (!g) return fail(err, BEZEL_STATUS_FONT_ERROR, g.error().message);
        const bezel_glyph_box b = to_box(*g);
        if (box) *box = b;
        if (bezel_status s = check_buffer(err, glyph_label(gid), buffer, buffer_size, stride,
                                          static_cast<std::size_t>(b.row_bytes),
                                          static_cast<std::size_t>(b.height)))
            return s;
        if (b.buffer_size == 0) return BEZEL_STATUS_OK;
        Status drawn = rasterizer->raster.draw(*g, MaskView{buffer, b.row_bytes, b.height, stride});
        if (!drawn) return fail(err, BEZEL_STATUS_INTERNAL, drawn.error().message);
        return BEZEL_STATUS_OK;
    });
}

bezel_status bezel_glyph_measure_set(bezel_glyph_rasterizer* rasterizer, const std::uint32_t* gids,
                                     std::size_t count, bezel_glyph_box* boxes) {
    static const char* const fn = "bezel_glyph_measure_set";
    if (!rasterizer) return null_argument(nullptr, fn, "rasterizer");
    ErrorSlot* err = &rasterizer->error;
    return guarded(err, fn, [&]() -> bezel_status {
        if (count == 0) return BEZEL_STATUS_OK;
        if (!gids) return null_argument(err, fn, "gids");
        if (!boxes) return null_argument(err, fn, "boxes");
        Status prepared =
            rasterizer->raster.prepare_set(gids, count, rasterizer->options, rasterizer->set);
        if (!prepared) return fail(err, BEZEL_STATUS_FONT_ERROR, prepared.error().message);
        for (std::size_t k = 0; k < count; ++k) boxes[k] = to_box(rasterizer->set[k]);
        return BEZEL_STATUS_OK;
    });
}

bezel_status bezel_glyph_render_set(bezel_glyph_rasterizer* rasterizer, const std::uint32_t* gids,
                                    std::size_t count, const bezel_glyph_target* targets,
                                    bezel_glyph_box* boxes) {
    static const char* const fn = "bezel_glyph_render_set";
    if (!rasterizer) return null_argument(nullptr, fn, "rasterizer");
    ErrorSlot* err = &rasterizer->error;
    return guarded(err, fn, [&]() -> bezel_status {
        if (count == 0) return BEZEL_STATUS_OK;
        if (!gids) return null_argument(err, fn, "gids");
        if (!targets) return null_argument(err, fn, "targets");
        std::vector<PreparedGlyph>& set = rasterizer->set;
        Status prepared = rasterizer->raster.prepare_set(gids, count, rasterizer->options, set);
        if (!prepared) return fail(err, BEZEL_STATUS_FONT_ERROR, prepared.error().message);
        // Every target checked before anything is drawn.
        for (std::size_t k = 0; k < count; ++k) {
            const bezel_glyph_box b = to_box(set[k]);
            if (bezel_status s = check_buffer(
                    err, "glyph set index " + std::to_string(k) + " (" + glyph_label(gids[k]) + ")",
                    targets[k].buffer, targets[k].buffer_size, targets[k].stride,
                    static_cast<std::size_t>(b.row_bytes), static_cast<std::size_t>(b.height)))
                return s;
        }
        std::vector<GlyphDrawJob>& jobs = rasterizer->jobs;
        jobs.clear();
        for (std::size_t k = 0; k < count; ++k) {
            const bezel_glyph_box b = to_box(set[k]);
            if (b.buffer_size == 0) continue;
            jobs.push_back({&set[k], MaskView{targets[k].buffer, b.row_bytes, b.height,
                                              targets[k].stride}});
        }
        Status drawn = rasterizer->raster.draw_set(jobs.data(), jobs.size());
        if (!drawn) return fail(err, BEZEL_STATUS_INTERNAL, drawn.error().message);
        if (boxes)
            for (std::size_t k = 0; k < count; ++k) boxes[k] = to_box(set[k]);
        return BEZEL_STATUS_OK;
    });
}

}  // extern "C"
