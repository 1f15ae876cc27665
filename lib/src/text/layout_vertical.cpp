// layout_text for vertical text: each paragraph a column, as hb-view lays out --direction ttb.
//
// Per paragraph: each grapheme cluster gets its font (LayoutFonts: the one font, or the first of
// a collection that draws it), the text is itemized into runs of one script and font (no bidi:
// vertical text has no left-to-right or right-to-left order, and hb-view shapes vertical lines
// unreordered) and each run is shaped once with its font in the vertical direction, which gives
// HarfBuzz's vertical advances and origins and applies the font's `vert` substitutions. Columns are filled greedily in logical
// order as lines are in layout.cpp: a column takes text up to the last break opportunity whose
// text, without trailing spaces, fits the column length; a word longer than the column is cut at
// the last cluster boundary that fits, its pieces reshaped. A column's glyphs are the slices of
// the paragraph's runs that fall in it, top to bottom: in run order for TopToBottom, in reverse
// run order for BottomToTop (HarfBuzz already reverses the glyphs inside each such run).
//
// Page: columns stack right to left (the CJK convention, and hb-view's for both directions),
// one column advance apart; the column advance and width come from the first font's vertical
// extents (Shaper::extents: vhea, or half an em each side of the centre line), as hb-view's do
// for its one font. Fallback fonts do not widen columns: a CJK column's width is the em box,
// whatever a fallback font's vhea says.
#include <algorithm>
#include <cmath>
#include <limits>

#include "text/layout_breaks.hpp"
#include "text/layout_common.hpp"
#include "text/layout_vertical.hpp"
#include "text/shape_tags.hpp"

namespace bezel::text_detail {

namespace {

struct ColumnSpan {
    std::size_t begin = 0, end = 0;   // paragraph-relative code point indices
    bool soft_end = false;            // ended by wrapping (trailing spaces hang)
    bool cut_begin = false, cut_end = false;   // cut inside a word
};

// One paragraph's columns; members are reused across paragraphs.
class VerticalParagraph {
public:
    VerticalParagraph(LayoutFonts& fonts, const ShapeOptions& shape, std::string_view text,
                      const std::vector<CodePoint>& cps)
        : fonts_(fonts), shape_(shape), text_(text), cps_(cps) {}

    // Lays out cps[begin, end) as columns appended to `out`: glyph x relative to the column's
    // centre line, y to its top; placement on the page comes once all columns are known.
    Status run(std::size_t begin, std::size_t end, double length_px, TextLayout& out);

private:
    std::uint32_t offset(std::size_t i) const {
        return i < cps_.size() ? cps_[i].offset : static_cast<std::uint32_t>(text_.size());
    }
    // The one place text is shaped: cps[a, b) of `run`, with its font, in the paragraph's
    // vertical direction.
    Status shape_range(std::size_t a, std::size_t b, const ScriptRun& run, ShapedRun& into);
    // Whether the slice [a, b) of `run` in `col` ends at a cut inside a word, where the
    // paragraph's shaping across the cut no longer applies.
    bool cut_in_word(const ColumnSpan& col, std::size_t glyph_end, std::size_t a, std::size_t b,
                     const ScriptRun& run) const {
        const std::size_t rb = run.begin - base_, re = run.end - base_;
        if (a == rb && b == re) return false;
        return (a == col.begin && a != rb && col.cut_begin) ||
               (b == glyph_end && b != re && col.cut_end);
    }
    std::size_t trimmed(std::size_t a, std::size_t b) const {
        while (b > a && is_break_space(cps_[base_ + b - 1].cp)) --b;
        return b;
    }
    bool fits(std::size_t a, std::size_t b, double length_px) const {
        return prefix_[trimmed(a, b)] - prefix_[a] <= length_px + kFitSlackPx;
    }
    Expected<double> placed_length(const ColumnSpan& col);
    Status wrap(std::size_t m, double length_px);
    Status place_column(const ColumnSpan& col, TextLayout& out);

    LayoutFonts& fonts_;
    const ShapeOptions& shape_;
    std::string_view text_;
    const std::vector<CodePoint>& cps_;
    std::size_t base_ = 0;
    UnicodeBreaks breaker_;
    std::u32string chars_;
    std::vector<std::uint8_t> levels_;   // all 0: itemize by script and font only
    std::vector<std::uint16_t> char_fonts_;
    std::vector<ScriptRun> runs_;
    std::vector<ShapedRun> shaped_;
    std::vector<std::uint8_t> breaks_, boundary_;
    std::vector<double> prefix_;   // prefix_[k]: advance of the paragraph's first k characters
    std::vector<ColumnSpan> columns_;
    std::vector<ShapedGlyph> pool_;
    std::vector<std::size_t> piece_start_;   // into pool_, one per run slice, plus the end
    std::vector<std::uint16_t> piece_font_;  // one per run slice
    ShapedRun reshaped_;
};

Status VerticalParagraph::shape_range(std::size_t a, std::size_t b, const ScriptRun& run,
                                      ShapedRun& into) {
    ShapeOptions opts = shape_;
    fonts_.variations(run.font, shape_, opts.variations);
    opts.script = tag_string(hb_script_to_iso15924_tag(run.script));
    const std::uint32_t from = offset(a), to = offset(b);
    auto shaped = fonts_.shaper(run.font).shape(text_.substr(from, to - from), opts);
    if (!shaped) return shaped.error();
    into = std::move(*shaped);
    for (ShapedGlyph& g : into.glyphs) g.cluster += from;
    return ok_status();
}

Expected<double> VerticalParagraph::placed_length(const ColumnSpan& col) {
    double length = 0;
    for (const ScriptRun& run : runs_) {
        const std::size_t a = std::max(run.begin - base_, col.begin);
        const std::size_t b = std::min(run.end - base_, col.end);
        if (a >= b) continue;
        if (cut_in_word(col, col.end, a, b, run)) {
            if (auto ok = shape_range(base_ + a, base_ + b, run, reshaped_); !ok) return ok.error();
            length += reshaped_.advance_px;
        } else {
            length += prefix_[b] - prefix_[a];
        }
    }
    return length;
}

Status VerticalParagraph::wrap(std::size_t m, double length_px) {
    columns_.clear();
    if (length_px <= 0 || m == 0) {
        columns_.push_back({0, m, false, false, false});
        return ok_status();
    }
    auto next_boundary = [&](std::size_t x) {
        ++x;
        while (x < m && boundary_[x] == 0) ++x;
        return x;
    };
    constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
    std::size_t start = 0;
    bool cut_start = false;
    while (start < m) {
        // The last opportunity (or the paragraph's end) that fits; the column's length grows
        // with its end (advances are not negative), so the first one that does not fit ends
        // the search.
        std::size_t best = kNone, k = start + 1;
        for (; k <= m; ++k) {
            if (k < m && breaks_[k] == 0) continue;
            if (!fits(start, k, length_px)) break;
            best = k;
        }
        if (best != kNone) {
            columns_.push_back({start, best, best < m, cut_start, false});
            start = best;
            cut_start = false;
            continue;
        }
        // Up to the first opportunity k nothing fits: cut between clusters at the last boundary
        // that fits by the paragraph's advances, then back while the reshaped column does not
        // (at least one cluster stays).
        const std::size_t first = next_boundary(start);
        std::size_t q = first;
        for (std::size_t q2 = next_boundary(q); q2 < k && fits(start, q2, length_px);
             q2 = next_boundary(q2))
            q = q2;
        while (q > first) {
            auto len = placed_length({start, q, false, cut_start, true});
            if (!len) return len.error();
            if (*len <= length_px + kFitSlackPx) break;
            do --q;
            while (q > first && boundary_[q] == 0);
        }
        columns_.push_back({start, q, false, cut_start, true});
        start = q;
        cut_start = true;
    }
    return ok_status();
}

Status VerticalParagraph::run(std::size_t begin, std::size_t end, double length_px,
                              TextLayout& out) {
    base_ = begin;
    const std::size_t m = end - begin;
    chars_.resize(m);
    for (std::size_t k = 0; k < m; ++k) chars_[k] = cps_[begin + k].cp;
    levels_.assign(m, 0);
    if (auto ok = fonts_.assign(chars_.data(), m, breaker_, char_fonts_); !ok) return ok;
    itemize(cps_, begin, end, levels_, char_fonts_, runs_);
    shaped_.resize(runs_.size());
    prefix_.assign(m + 1, 0.0);
    boundary_.assign(m, 0);
    for (std::size_t r = 0; r < runs_.size(); ++r) {
        if (auto ok = shape_range(runs_[r].begin, runs_[r].end, runs_[r], shaped_[r]); !ok)
            return ok;
        boundary_[runs_[r].begin - begin] = 1;
        for (const ShapedGlyph& g : shaped_[r].glyphs) {
            auto it = std::lower_bound(
                cps_.begin() + static_cast<std::ptrdiff_t>(begin),
                cps_.begin() + static_cast<std::ptrdiff_t>(end), g.cluster,
                [](const CodePoint& c, std::uint32_t off) { return c.offset < off; });
            const auto k = static_cast<std::size_t>(it - cps_.begin()) - begin;
            if (k >= m) continue;
            prefix_[k + 1] += g.y_advance_px;
            boundary_[k] = 1;
        }
    }
    for (std::size_t k = 0; k < m; ++k) prefix_[k + 1] += prefix_[k];   // now prefix sums
    if (length_px > 0) {
        if (auto ok = breaker_.line_breaks(chars_.data(), m, breaks_); !ok) return ok;
    }
    if (auto ok = wrap(m, length_px); !ok) return ok;
    for (const ColumnSpan& col : columns_)
        if (auto ok = place_column(col, out); !ok) return ok;
    return ok_status();
}

Status VerticalParagraph::place_column(const ColumnSpan& col, TextLayout& out) {
    const std::size_t glyph_end = col.soft_end ? trimmed(col.begin, col.end) : col.end;
    pool_.clear();
    piece_start_.clear();
    piece_font_.clear();
    for (std::size_t r = 0; r < runs_.size(); ++r) {
        const ScriptRun& run = runs_[r];
        const std::size_t a = std::max(run.begin - base_, col.begin);
        const std::size_t b = std::min(run.end - base_, glyph_end);
        if (a >= b) continue;
        const std::vector<ShapedGlyph>* glyphs = &shaped_[r].glyphs;
        if (cut_in_word(col, glyph_end, a, b, run)) {
            if (auto ok = shape_range(base_ + a, base_ + b, run, reshaped_); !ok) return ok;
            glyphs = &reshaped_.glyphs;
        }
        piece_start_.push_back(pool_.size());
        piece_font_.push_back(run.font);
        const std::uint32_t from = offset(base_ + a), to = offset(base_ + b);
        for (const ShapedGlyph& g : *glyphs)
            if (g.cluster >= from && g.cluster < to) pool_.push_back(g);
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
