// Private to the font module (and its tests): FreeType outlines → bezel points → bezel Path.
//
// Two steps, so the second can be tested without FreeType:
//   read_ft_outline   FT_Outline (font y up, integer units) → OutlinePoints (pixels, y down)
//   path_from_points  OutlinePoints + contour ends → Path, walking the point kinds exactly as
//                     FreeType's FT_Outline_Decompose does (same segments, same start points),
//                     except that midpoints are exact in double (FreeType truncates them to its
//                     integer grid) and the line that closes a contour is left to Close.
#pragma once

#include <cstddef>
#include <vector>

#include <ft2build.h>
#include FT_FREETYPE_H  // FT_Outline; ftimage.h cannot be included on its own

#include "bezel/expected.hpp"
#include "bezel/font.hpp"
#include "bezel/path.hpp"

namespace bezel::font_detail {

// Replaces `points` and `contour_ends` with the outline's points mapped by
//   (x, y) ↦ (x·scale, −y·scale)        (font y up → bezel y down)
// and each point's kind read from its tag (FT_CURVE_TAG_ON / CONIC / CUBIC). `scale` is
// size_px / units_per_em for an unscaled outline, 1/64 for a 26.6 one.
// Errors (the message names the contour or point, not the glyph) when the outline's structure is
// inconsistent: negative counts, contour ends not strictly increasing, the last end not the last
// point, or a tag FreeType does not define.
Status read_ft_outline(const FT_Outline& outline, double scale, std::vector<OutlinePoint>& points,
                       std::vector<std::size_t>& contour_ends);

// Appends one closed contour per entry of `contour_ends` (index of each contour's last point;
// strictly increasing, the last < points.size()) to `out`. The rules, FreeType's:
//   - OnCurve after anything ends a segment: a line after an on-curve point, the end of a quad
//     after a conic point, the end of a cubic after a pair of cubic points.
//   - Two consecutive OffConic points imply an on-curve point at their midpoint.
//   - A contour that starts with an OffConic point starts at its last point when that is on
//     the curve (the contour then ends one point early), otherwise at the midpoint of its last
//     and first points; a contour with no on-curve point at all is the second case.
//   - The segment back to the start is implicit (Close) when the contour ends on-curve, and an
//     explicit quad or cubic to the start when it ends off-curve.
//   - A single on-curve point is a degenerate contour: Move + Close, no segment. A single
//     OffConic point becomes Move p, Quad (p, p), Close (FreeType's zero-length conic).
// Errors (path unchanged past the bad contour's Move) on a contour that starts with an
// OffCubic point, or cubic points not in pairs, or a cubic point right after a conic one — the
// same outlines FT_Outline_Decompose rejects.
Status path_from_points(const std::vector<OutlinePoint>& points,
                        const std::vector<std::size_t>& contour_ends, Path& out);

}  // namespace bezel::font_detail
