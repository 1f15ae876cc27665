// Internal: what horizontal (layout.cpp) and vertical (layout_vertical.cpp) layout do alike to
// one paragraph: a font per grapheme cluster, runs of one script, level and font, each run
// shaped once (which gives every cluster its advance along the line), greedy wrapping at break
// opportunities, and each line's (or column's) slice of a run, reshaped where the line cuts the
// run inside a word.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "bezel/shape.hpp"
#include "text/layout_breaks.hpp"
#include "text/layout_fonts.hpp"
#include "text/script_runs.hpp"

namespace bezel::text_detail {

// A line (or column) of a paragraph: paragraph-relative code point indices [begin, end).
struct LineSpan {
    std::size_t begin = 0, end = 0;
    bool soft_end = false;                    // ended by wrapping (trailing spaces hang)
    bool cut_begin = false, cut_end = false;  // cut inside a word
};

// Members are reused from paragraph to paragraph.
class ParagraphRuns {
public:
    // `vertical`: runs are shaped in shape.direction (TopToBottom or BottomToTop) and advance
    // along y; otherwise each run in the direction of its bidi level, advancing along x.
    ParagraphRuns(LayoutFonts& fonts, const ShapeOptions& shape, std::string_view text,
                  const std::vector<CodePoint>& cps, bool vertical)
        : fonts_(fonts), shape_(shape), text_(text), cps_(cps), vertical_(vertical) {}

protected:
    // cps[begin, end) becomes the paragraph: chars_ holds its code points.
    void start(std::size_t begin, std::size_t end);
    // With chars_ and one bidi level per character: fonts, runs, their shaping, the advances'
    // prefix sums and cluster boundaries; with length_px > 0 the break opportunities and the
    // lines (spans_) too, else one line.
    Status shape_and_wrap(const std::vector<std::uint8_t>& levels, double length_px);
    // The glyphs to take the slice [a, b) of run r in `span` from: the run's own, or the slice
    // reshaped where the span cuts the run inside a word (valid until the next call).
    // `glyph_end` is the span's end without hanging spaces.
    Expected<const std::vector<ShapedGlyph>*> slice_glyphs(const LineSpan& span,
                                                           std::size_t glyph_end, std::size_t r,
                                                           std::size_t a, std::size_t b);
    // Appends those of `glyphs` (of run r) whose clusters lie in characters [p, q) to `pool`, in
    // the run's glyph order.
    void append_clusters(const std::vector<ShapedGlyph>& glyphs, std::size_t r, std::size_t p,
                         std::size_t q, std::vector<ShapedGlyph>& pool) const;
    std::uint32_t offset(std::size_t i) const {
        return i < cps_.size() ? cps_[i].offset : static_cast<std::uint32_t>(text_.size());
    }
    // The span's end without the spaces that hang at a wrapped line's end.
    std::size_t glyph_end(const LineSpan& span) const {
        return span.soft_end ? trimmed(span.begin, span.end) : span.end;
    }
    double advance(const ShapedGlyph& g) const { return vertical_ ? g.y_advance_px : g.x_advance_px; }

    LayoutFonts& fonts_;
    const ShapeOptions& shape_;
    std::string_view text_;
    const std::vector<CodePoint>& cps_;
    std::size_t base_ = 0;                     // the paragraph's first code point in cps_
    std::u32string chars_;
    std::vector<ScriptRun> runs_;
    std::vector<LineSpan> spans_;

private:
    // The one place text is shaped: cps[a, b) of `run`, with its font and direction.
    Status shape_range(std::size_t a, std::size_t b, const ScriptRun& run, ShapedRun& into);
    Status wrap(std::size_t m, double length_px);
    // The length `span` will have once placed: its runs' advances, reshaped where it cuts a run
    // inside a word (a joining or kerning change there changes the length).
    Expected<double> placed_length(const LineSpan& span);
    // Whether the slice [a, b) of `run` in `span` ends at a cut inside a word, where the
    // paragraph's shaping across the cut no longer applies.
    bool cut_in_word(const LineSpan& span, std::size_t end, std::size_t a, std::size_t b,
                     const ScriptRun& run) const {
        const std::size_t rb = run.begin - base_, re = run.end - base_;
        if (a == rb && b == re) return false;
        return (a == span.begin && a != rb && span.cut_begin) ||
               (b == end && b != re && span.cut_end);
    }
    std::size_t trimmed(std::size_t a, std::size_t b) const {
        while (b > a && is_break_space(cps_[base_ + b - 1].cp)) --b;
        return b;
    }
    bool fits(std::size_t a, std::size_t b, double length_px) const;
    // Whether the run's glyphs come in descending cluster order (right to left, bottom to top).
    bool descending(const ScriptRun& run) const {
        return vertical_ ? shape_.direction == Direction::BottomToTop : (run.level & 1) != 0;
    }

    bool vertical_;
    UnicodeBreaks breaker_;
    std::vector<std::uint16_t> char_fonts_;
    std::vector<ShapedRun> shaped_;
    std::vector<std::uint8_t> breaks_, boundary_;
    std::vector<double> prefix_;   // prefix_[k]: advance of the paragraph's first k characters
    ShapedRun reshaped_;
};

}  // namespace bezel::text_detail
