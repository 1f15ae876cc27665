// Synthetic bold: a glyph outline dilated by a disk (GlyphRenderOptions::bold, glyph.hpp).
#pragma once

#include "bezel/expected.hpp"
#include "bezel/path.hpp"

namespace bezel::text_detail {

// The outline whose non-zero fill is every point within `radius_px` (> 0) of the non-zero fill
// of `glyph` (pixels, y down), within `tolerance_px`, NOT yet moved by the placement rule of
// GlyphRenderOptions::bold. The result overlaps itself by construction: fill it with
// FillRule::NonZero and OverlapMode::Accurate. Errors: the stroker's (a non-finite coordinate,
// more than kMaxStrokeSegments pieces).
Expected<Path> dilate_outline(const Path& glyph, double radius_px, double tolerance_px);

}  // namespace bezel::text_detail
