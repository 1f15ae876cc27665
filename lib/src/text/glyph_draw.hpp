// Private: how GlyphRasterizer::draw places a prepared glyph into a target, shared by draw() and
// draw_set() so that a set's bytes are draw()'s by construction.
#pragma once

#include <string>

#include "bezel/glyph.hpp"

namespace bezel::text_detail {

// Bytes a pixel of the glyph's coverage takes: 3 in LCD modes (subpixels), else 1.
inline int glyph_bytes_per_px(const PreparedGlyph& glyph) {
    return glyph.options.fill.format == CoverageFormat::Lcd ? 3 : 1;
}

// Whether `target` holds the glyph's box (with memory): draw()'s test. The message does not
// name the glyph; callers prefix it.
inline Status check_glyph_target(const PreparedGlyph& glyph, const MaskView& target) {
    const GlyphBox& box = glyph.box;
    const int bytes_per_px = glyph_bytes_per_px(glyph);
    if (target.width < box.width * bytes_per_px || target.height < box.height || !target.data)
        return Error{"target " + std::to_string(target.width) + "x" +
                     std::to_string(target.height) + " is smaller than the glyph's " +
                     std::to_string(box.width * bytes_per_px) + "x" + std::to_string(box.height) +
                     " bytes"};
    return ok_status();
}

// The fill options of an outline glyph: its own, with the overlap mode its box chose, and the
// origin left to the job (outline_job).
inline FillOptions outline_fill(const PreparedGlyph& glyph) {
    FillOptions fill = glyph.options.fill;
    fill.overlap = glyph.box.overlap;
    fill.origin = Vec2{};
    return fill;
}

// An outline glyph's fill: its path moved by the pen offset so the box's corner is the
// target's top-left pixel (y down), into that corner of `target`, at the options' origin.
inline FillJob outline_job(const PreparedGlyph& glyph, const MaskView& target) {
    const GlyphBox& box = glyph.box;
    const GlyphRenderOptions& o = glyph.options;
    FillJob job;
    job.path = &glyph.path;
    job.transform = Affine::translate({o.offset_px.x - box.left, o.offset_px.y + box.top});
    job.target = target.sub(0, 0, box.width * glyph_bytes_per_px(glyph), box.height);
    job.origin = o.fill.origin;
    return job;
}

}  // namespace bezel::text_detail
