// layout_text for vertical text: each paragraph a column, as hb-view lays out --direction ttb.
//
// Per paragraph, ParagraphRuns (paragraph_runs.hpp) gives each grapheme cluster its font,
// itemizes runs of one script and font (no bidi: vertical text has no left-to-right or
// right-to-left order, and hb-view shapes vertical lines unreordered), shapes each run once in
// the vertical direction (HarfBuzz's vertical advances and origins, the font's `vert`
// substitutions) and wraps the paragraph into columns as lines are wrapped, the column length
// standing for the line width. A column's glyphs are the slices of the paragraph's runs that
// fall in it, top to bottom: in run order for TopToBottom, in reverse run order for BottomToTop
// (HarfBuzz already reverses the glyphs inside each such run).
//
// Page: columns stack right to left (the CJK convention, and hb-view's for both directions),
// one column advance apart; the column advance and width come from the first font's vertical
// extents (Shaper::extents: vhea, or half an em each side of the centre line), as hb-view's do
// for its one font. Fallback fonts do not widen columns: a CJK column's width is the em box,
// whatever a fallback font's vhea says.
#include <algorithm>
#include <cmath>

#include "text/layout_common.hpp"
#include "text/layout_vertical.hpp"
#include "text/paragraph_runs.hpp"

namespace bezel::text_detail {

namespace {

// One paragraph's columns; members are reused across paragraphs.
class VerticalParagraph : private ParagraphRuns {
public:
    VerticalParagraph(LayoutFonts& fonts, const ShapeOptions& shape, std::string_view text,
                      const std::vector<CodePoint>& cps)
        : ParagraphRuns(fonts, shape, text, cps, true) {}

    // Lays out cps[begin, end) as columns appended to `out`: glyph x relative to the column's
    // centre line, y to its top; placement on the page comes once all columns are known.
    Status run(std::size_t begin, std::size_t end, double length_px, TextLayout& out);

private:
    Status place_column(const LineSpan& col, TextLayout& out);

    std::vector<std::uint8_t> levels_;   // all 0: itemize by script and font only
    std::vector<ShapedGlyph> pool_;
    std::vector<std::size_t> piece_start_;   // into pool_, one per run slice, plus the end
    std::vector<std::uint16_t> piece_font_;  // one per run slice
};

Status VerticalParagraph::run(std::size_t begin, std::size_t end, double length_px,
                              TextLayout& out) {
    start(begin, end);
    levels_.assign(chars_.size(), 0);
    if (auto ok = shape_and_wrap(levels_, length_px); !ok) return ok;
    for (const LineSpan& col : spans_)
        if (auto ok = place_column(col, out); !ok) return ok;
    return ok_status();
}

Status VerticalParagraph::place_column(const LineSpan& col, TextLayout& out) {
    const std::size_t end = glyph_end(col);
    pool_.clear();
    piece_start_.clear();
    piece_font_.clear();
    for (std::size_t r = 0; r < runs_.size(); ++r) {
        const ScriptRun& run = runs_[r];
        const std::size_t a = std::max(run.begin - base_, col.begin);
        const std::size_t b = std::min(run.end - base_, end);
        if (a >= b) continue;
        auto glyphs = slice_glyphs(col, end, r, a, b);
        if (!glyphs) return glyphs.error();
        piece_start_.push_back(pool_.size());
        piece_font_.push_back(run.font);
        append_clusters(**glyphs, r, a, b, pool_);
    }
    piece_start_.push_back(pool_.size());

    LaidOutLine laid;
    laid.first_glyph = out.glyphs.size();
    laid.text_begin = offset(base_ + col.begin);
    laid.text_end = offset(base_ + col.end);
    const std::size_t pieces = piece_start_.size() - 1;
    const bool reversed = shape_.direction == Direction::BottomToTop;
    double pen = 0;
    for (std::size_t i = 0; i < pieces; ++i) {
        const std::size_t p = reversed ? pieces - 1 - i : i;
        for (std::size_t j = piece_start_[p]; j < piece_start_[p + 1]; ++j) {
            const ShapedGlyph& g = pool_[j];
            out.glyphs.push_back(
                {g.gid, g.x_offset_px, pen + g.y_offset_px, g.cluster, piece_font_[p]});
            pen += g.y_advance_px;
        }
    }
    laid.glyph_count = out.glyphs.size() - laid.first_glyph;
    laid.width_px = pen;
    out.lines.push_back(laid);
    return ok_status();
}

}  // namespace

Expected<TextLayout> layout_vertical(LayoutFonts& fonts, std::string_view utf8,
                                     const std::vector<CodePoint>& cps, const ShapeOptions& shape,
                                     const LayoutOptions& layout) {
    ShapeOptions first = shape;
    fonts.variations(0, shape, first.variations);
    auto extents = fonts.shaper(0).extents(first);
    if (!extents) return extents.error();
    double right = extents->ascender_px, left = -extents->descender_px;
    double gap = extents->line_gap_px;
    // A vhea whose ascender is not beyond its descender (a broken font) would stack columns on
    // top of each other or outside the page: it is taken as absent, as HarfBuzz takes no vhea.
    if (!(right + left > 0)) {
        right = left = shape.size_px / 2;
        gap = 0;
    }

    TextLayout out;
    out.glyphs.reserve(cps.size());
    VerticalParagraph paragraph(fonts, shape, utf8, cps);
    for (std::size_t p = 0;;) {
        std::size_t q = p;
        while (q < cps.size() && !is_newline(cps[q].cp)) ++q;
        if (auto ok = paragraph.run(p, q, layout.width_px, out); !ok) return ok.error();
        if (q == cps.size()) break;
        p = q + 1;
        if (cps[q].cp == '\r' && p < cps.size() && cps[p].cp == '\n') ++p;
    }

    const double factor = layout.line_height > 0 ? layout.line_height : 1.0;
    const double column_advance = (right + left + gap) * factor;
    double longest = 0;
    for (const LaidOutLine& l : out.lines) longest = std::max(longest, l.width_px);
    const double avail = layout.width_px > 0 ? layout.width_px : longest;
    const double margin = layout.margin_px;
    out.width_px = 2 * margin + right + left +
                   static_cast<double>(out.lines.size() - 1) * column_advance;
    out.height_px = avail + 2 * margin;
    // As in layout_text: finite options whose products are not (a line_height of 1e300).
    if (!std::isfinite(out.width_px) || !std::isfinite(out.height_px))
        return Error{"layout: the text block would be infinitely large (line_height " +
                     format_num(layout.line_height) + ", margin_px " +
                     format_num(layout.margin_px) + ", width_px " +
                     format_num(layout.width_px) + ")"};
    const bool btt = shape.direction == Direction::BottomToTop;
    const double first_centre = out.width_px - margin - right;
    for (std::size_t i = 0; i < out.lines.size(); ++i) {
        LaidOutLine& col = out.lines[i];
        const double slack = std::max(0.0, avail - col.width_px);
        // Start is where the text begins: the top for TopToBottom, the bottom for BottomToTop.
        double y0 = 0;
        switch (layout.align) {
            case Align::Start: y0 = btt ? slack : 0; break;
            case Align::Center: y0 = slack / 2; break;
            case Align::End: y0 = btt ? 0 : slack; break;
        }
        col.baseline_x_px = first_centre - static_cast<double>(i) * column_advance;
        col.baseline_y_px = margin + y0;
        col.ascent_px = right;
        col.descent_px = left;
        for (std::size_t g = col.first_glyph; g < col.first_glyph + col.glyph_count; ++g) {
            out.glyphs[g].x_px += col.baseline_x_px;
            out.glyphs[g].y_px += col.baseline_y_px;
        }
    }
    return out;
}

}  // namespace bezel::text_detail
