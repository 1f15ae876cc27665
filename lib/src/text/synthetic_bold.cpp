// Synthetic bold as a Minkowski sum: the glyph's ink G dilated by a disk D of radius r,
//   G ⊕ D = G ∪ (∂G ⊕ D),
// every point of G ⊕ D not in G being within r of G's boundary. ∂G ⊕ D is exactly the stroke of
// the outline with width 2r and ROUND joins (every boundary point swept by the disk: the offset
// curves at ±r, and at each corner the arc a round join draws), so the construction is
// bezel's own stroker, whose offsets stay within the tolerance of the exact ones (stroke.hpp).
//
// Why round joins and not miter-limited ones: the round join makes the result the exact dilation
// (one rule, one error bound, area A + P·r + π·r² for a convex glyph), while a miter at the
// sharp inner angles of serifs and ink traps reaches up to r / sin(θ/2) out and needs a limit
// that switches the shape discontinuously between miter and bevel. The visible difference at an
// outer right angle is the corner's r·(√2 − 1) ≈ 0.41·r: at text sizes a fraction of a pixel.
//
// Why the union fills correctly with non-zero: every piece of the stroke winds the same way
// (negative Path::signed_area, stroke.hpp), so a point of the band has a winding number of that
// sign. The glyph's contours are turned, as a whole, to the same sense (reversed when their total
// signed area is positive): in a well-formed glyph the outer contours wind one way and the holes
// the other (TrueType and CFF each have a convention; the sign of the total area tells which),
// so inside the ink the winding number has the band's sign too and nothing cancels; a hole, wound
// zero, is covered only where the band reaches into it, which is the hole shrinking by r. This
// is the orientation rule FreeType's FT_Outline_EmboldenXY uses (FT_Outline_Get_Orientation, by
// area). A malformed glyph whose contours wind against each other over the same ink can lose the
// inner half of the band there, as it does in FreeType.
#include "text/synthetic_bold.hpp"

#include "bezel/stroke.hpp"

namespace bezel::text_detail {
namespace {

// Appends every contour of `src` to `dst`, verbs and points as they are.
void append_contours(Path& dst, const Path& src) {
    const std::vector<Point>& pts = src.points();
    std::size_t k = 0;
    for (Verb v : src.verbs()) {
        switch (v) {
            case Verb::Move: dst.move_to(pts[k]); k += 1; break;
            case Verb::Line: dst.line_to(pts[k]); k += 1; break;
            case Verb::Quad: dst.quad_to(pts[k], pts[k + 1]); k += 2; break;
            case Verb::Cubic: dst.cubic_to(pts[k], pts[k + 1], pts[k + 2]); k += 3; break;
            case Verb::Close: dst.close(); break;
        }
    }
}

}  // namespace

Expected<Path> dilate_outline(const Path& glyph, double radius_px, double tolerance_px) {
    if (glyph.empty()) return Path{};
    StrokeStyle band;
    band.width = 2 * radius_px;
    band.join = LineJoin::Round;
    band.cap = LineCap::Round;   // glyph contours are closed; an open one would end in a half disk
    band.tolerance = tolerance_px;
    auto stroked = stroke(glyph, band);
    if (!stroked) return stroked.error();
    Path out = glyph.signed_area() > 0 ? glyph.reversed() : glyph;
    append_contours(out, *stroked);
    return out;
}

}  // namespace bezel::text_detail
