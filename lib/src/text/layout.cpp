// layout_text: paragraphs, script/direction runs, greedy line wrapping, alignment.
//
// Per paragraph (text between newlines): the bidi levels are resolved (bidi.hpp: FriBidi, UAX #9)
// and the text itemized into runs of one script and one level (script_runs.hpp); each run is
// shaped once, which
// gives every cluster its advance. Lines are then filled greedily in logical order: a line
// takes text up to the last break opportunity (layout_breaks.hpp) whose text, without trailing
// spaces, fits width_px; a word with no opportunity that is wider than the line is cut at the
// last cluster boundary that fits (at least one cluster per line). Each line's glyphs are the
// slices of the paragraph's shaped runs that fall on it — reshaped only where a line cuts a run
// inside a word, where shaping across the cut (joining, kerning) no longer applies — split where
// L1 gives the line's trailing whitespace the paragraph level, ordered by level (L2) and placed
// along the baseline.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "bezel/layout.hpp"
#include "text/bidi.hpp"
#include "text/layout_breaks.hpp"
#include "text/layout_common.hpp"
#include "text/layout_fonts.hpp"
#include "text/layout_vertical.hpp"
#include "text/script_runs.hpp"
#include "text/shape_tags.hpp"
#include "text/utf8_decode.hpp"

namespace bezel {

using namespace text_detail;

namespace {

Status check_length(const char* name, double v) {
    if (std::isfinite(v) && v >= 0) return ok_status();
    return Error{std::string("layout ") + name + " " + format_num(v) + ": must be a finite number >= 0"};
}

struct LineSpan {
    std::size_t begin = 0, end = 0;   // paragraph-relative code point indices
    bool soft_end = false;            // ended by wrapping (trailing spaces hang)
    bool forced_begin = false, forced_end = false;   // cut inside a word
};

struct Piece {
    std::size_t first = 0, count = 0;   // in the line's glyph pool
    std::uint16_t font = 0;
};

// A line's vertical extent in pixels from the fonts it uses (the first font always counts).
struct LineExtent {
    double ascent = 0, descent = 0, gap = 0;   // descent > 0 below the baseline
    bool operator==(const LineExtent& o) const {
        return ascent == o.ascent && descent == o.descent && gap == o.gap;
    }
};

// Everything one paragraph needs; members are reused across paragraphs.
class ParagraphLayout {
public:
    ParagraphLayout(LayoutFonts& fonts, const ShapeOptions& shape, std::string_view text,
                    const std::vector<CodePoint>& cps)
        : fonts_(fonts), shape_(shape), text_(text), cps_(cps) {}

    // Lays out cps[begin, end) as lines appended to `out`: glyph x relative to the line's start,
    // y relative to its baseline; placement on the page comes after all lines are known.
    Status run(std::size_t begin, std::size_t end, double width_px, TextLayout& out,
               std::vector<LineExtent>& extents);
    // The level of the paragraph last run: 1 right to left, 0 left to right.
    std::uint8_t paragraph_level() const { return bidi_.paragraph_level(); }

private:
    std::uint32_t offset(std::size_t i) const {
        return i < cps_.size() ? cps_[i].offset : static_cast<std::uint32_t>(text_.size());
    }
    Status shape_range(std::size_t a, std::size_t b, const ScriptRun& run, ShapedRun& into);
    Status wrap(std::size_t m, double width_px);
    // The width `line` will have once placed: its runs' advances, reshaped where it cuts a run
    // inside a word (a joining or kerning change there changes the width).
    Expected<double> placed_width(const LineSpan& line);
    bool cut_in_word(const LineSpan& line, std::size_t glyph_end, std::size_t a, std::size_t b,
                     const ScriptRun& run) const {
        const std::size_t rb = run.begin - base_, re = run.end - base_;
        if (a == rb && b == re) return false;
        return (a == line.begin && a != rb && line.forced_begin) ||
               (b == glyph_end && b != re && line.forced_end);
    }
    std::size_t trimmed(std::size_t a, std::size_t b) const {
        while (b > a && is_break_space(cps_[base_ + b - 1].cp)) --b;
        return b;
    }
    bool fits(std::size_t a, std::size_t b, double width_px) const {
        return prefix_[trimmed(a, b)] - prefix_[a] <= width_px + kFitSlackPx;
    }
    Status place_line(const LineSpan& line, TextLayout& out, std::vector<LineExtent>& extents);
    void add_extent(std::uint16_t font, LineExtent& extent) const;

    LayoutFonts& fonts_;
    const ShapeOptions& shape_;
    std::string_view text_;
    const std::vector<CodePoint>& cps_;
    std::size_t base_ = 0;
    BidiParagraph bidi_;
    UnicodeBreaks breaker_;
    std::u32string chars_;
    std::vector<ScriptRun> runs_;
    std::vector<ShapedRun> shaped_;
    std::vector<std::uint8_t> breaks_, boundary_, line_levels_;
    std::vector<std::uint16_t> char_fonts_;
    std::vector<double> prefix_;
    std::vector<LineSpan> lines_;
    std::vector<ShapedGlyph> pool_;
    std::vector<Piece> pieces_;
    std::vector<std::uint8_t> levels_;
    std::vector<std::size_t> order_;
    ShapedRun reshaped_;
};

Status ParagraphLayout::shape_range(std::size_t a, std::size_t b, const ScriptRun& run,
                                    ShapedRun& into) {
    ShapeOptions opts = shape_;
    fonts_.variations(run.font, shape_, opts.variations);
    opts.direction = (run.level & 1) != 0 ? Direction::RightToLeft : Direction::LeftToRight;
    opts.script = tag_string(hb_script_to_iso15924_tag(run.script));
    const std::uint32_t from = offset(a), to = offset(b);
    auto shaped = fonts_.shaper(run.font).shape(text_.substr(from, to - from), opts);
    if (!shaped) return shaped.error();
    into = std::move(*shaped);
    for (ShapedGlyph& g : into.glyphs) g.cluster += from;
    return ok_status();
}

Expected<double> ParagraphLayout::placed_width(const LineSpan& line) {
    double width = 0;
    for (const ScriptRun& run : runs_) {
        const std::size_t a = std::max(run.begin - base_, line.begin);
        const std::size_t b = std::min(run.end - base_, line.end);
        if (a >= b) continue;
        if (cut_in_word(line, line.end, a, b, run)) {
            if (auto ok = shape_range(base_ + a, base_ + b, run, reshaped_); !ok) return ok.error();
            width += reshaped_.advance_px;
        } else {
            width += prefix_[b] - prefix_[a];
        }
    }
    return width;
}

Status ParagraphLayout::wrap(std::size_t m, double width_px) {
    lines_.clear();
    if (width_px <= 0 || m == 0) {
        lines_.push_back({0, m, false, false, false});
        return ok_status();
    }
    auto next_boundary = [&](std::size_t x) {
        ++x;
        while (x < m && boundary_[x] == 0) ++x;
        return x;
    };
    constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
    std::size_t start = 0, candidate = kNone;
    bool start_forced = false;
    for (std::size_t k = 1; k <= m;) {
        if (k < m && breaks_[k] == 0) {
            ++k;
            continue;
        }
        if (k <= start || fits(start, k, width_px)) {
            if (k > start) candidate = k;
            ++k;
            continue;
        }
        if (candidate != kNone) {
            lines_.push_back({start, candidate, true, start_forced, false});
            start = candidate;
            start_forced = false;
            candidate = kNone;
            continue;   // the same k again, from the new start
        }
        // No opportunity in [start, k) and it does not fit: cut between clusters, at the last
        // boundary that fits by the paragraph's advances, then back while the reshaped line
        // does not (at least one cluster stays).
        const std::size_t first = next_boundary(start);
        std::size_t q = first;
        for (std::size_t q2 = next_boundary(q); q2 < k && fits(start, q2, width_px);
             q2 = next_boundary(q2))
            q = q2;
        while (q > first) {
            auto w = placed_width({start, q, false, start_forced, true});
            if (!w) return w.error();
            if (*w <= width_px + kFitSlackPx) break;
            do --q;
            while (q > first && boundary_[q] == 0);
        }
        lines_.push_back({start, q, false, start_forced, true});
        start = q;
        start_forced = true;
    }
    if (start < m || lines_.empty()) lines_.push_back({start, m, false, start_forced, false});
    return ok_status();
}

Status ParagraphLayout::run(std::size_t begin, std::size_t end, double width_px,
                            TextLayout& out, std::vector<LineExtent>& extents) {
    base_ = begin;
    const std::size_t m = end - begin;
    chars_.resize(m);
    for (std::size_t k = 0; k < m; ++k) chars_[k] = cps_[begin + k].cp;
    if (auto ok = bidi_.resolve(chars_.data(), m, shape_.direction); !ok) return ok;
    if (auto ok = fonts_.assign(chars_.data(), m, breaker_, char_fonts_); !ok) return ok;
    itemize(cps_, begin, end, bidi_.levels(), char_fonts_, runs_);
    shaped_.resize(runs_.size());
    std::vector<double>& adv = prefix_;
    adv.assign(m + 1, 0.0);
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
            adv[k + 1] += g.x_advance_px;
            boundary_[k] = 1;
        }
    }
    for (std::size_t k = 0; k < m; ++k) prefix_[k + 1] += prefix_[k];   // now prefix sums
    // Without a width no line is wrapped: the opportunities are not needed.
    if (width_px > 0) {
        if (auto ok = breaker_.line_breaks(chars_.data(), m, breaks_); !ok) return ok;
    }
    if (auto ok = wrap(m, width_px); !ok) return ok;
    for (const LineSpan& line : lines_)
        if (auto ok = place_line(line, out, extents); !ok) return ok;
    return ok_status();
}

void ParagraphLayout::add_extent(std::uint16_t font, LineExtent& extent) const {
    const FontMetrics& m = fonts_.metrics(font);
    if (m.units_per_em <= 0) return;
    const double scale = shape_.size_px / m.units_per_em;
    extent.ascent = std::max(extent.ascent, m.ascender * scale);
    extent.descent = std::max(extent.descent, -m.descender * scale);
    extent.gap = std::max(extent.gap, m.line_gap * scale);
}

Status ParagraphLayout::place_line(const LineSpan& line, TextLayout& out,
                                   std::vector<LineExtent>& extents) {
    const std::size_t glyph_end = line.soft_end ? trimmed(line.begin, line.end) : line.end;
    pool_.clear();
    pieces_.clear();
    levels_.clear();
    bidi_.line_levels(line.begin, line.end, line_levels_);
    for (std::size_t r = 0; r < runs_.size(); ++r) {
        const ScriptRun& run = runs_[r];
        const std::size_t rb = run.begin - base_, re = run.end - base_;
        const std::size_t a = std::max(rb, line.begin), b = std::min(re, glyph_end);
        if (a >= b) continue;
        const std::vector<ShapedGlyph>* glyphs = &shaped_[r].glyphs;
        if (cut_in_word(line, glyph_end, a, b, run)) {
            if (auto ok = shape_range(base_ + a, base_ + b, run, reshaped_); !ok) return ok;
            glyphs = &reshaped_.glyphs;
        }
        // One piece per stretch of the slice at one line level: within a run the levels differ
        // only where L1 reset the line's trailing whitespace.
        for (std::size_t p = a; p < b;) {
            const std::uint8_t level = line_levels_[p - line.begin];
            std::size_t q = p + 1;
            while (q < b && line_levels_[q - line.begin] == level) ++q;
            const std::uint32_t from = offset(base_ + p), to = offset(base_ + q);
            Piece piece{pool_.size(), 0, run.font};
            // HarfBuzz keeps a run's clusters monotonic (ascending left to right, descending
            // for a right-to-left run), so the glyphs of [from, to) are one stretch, found by
            // two binary searches instead of a scan of the whole run per line.
            const bool rtl = (run.level & 1) != 0;
            auto before = [&](std::uint32_t bound) {
                return [bound, rtl](const ShapedGlyph& g) {
                    return rtl ? g.cluster >= bound : g.cluster < bound;
                };
            };
            auto first = std::partition_point(glyphs->begin(), glyphs->end(),
                                              before(rtl ? to : from));
            auto last = std::partition_point(first, glyphs->end(), before(rtl ? from : to));
            pool_.insert(pool_.end(), first, last);
            piece.count = pool_.size() - piece.first;
            pieces_.push_back(piece);
            levels_.push_back(level);
            p = q;
        }
    }
    visual_order(levels_, order_);

    LaidOutLine laid;
    laid.first_glyph = out.glyphs.size();
    laid.text_begin = offset(base_ + line.begin);
    laid.text_end = offset(base_ + line.end);
    double pen = 0;
    LineExtent extent;
    add_extent(0, extent);
    for (std::size_t p : order_) {
        const Piece& piece = pieces_[p];
        if (piece.font != 0 && piece.count > 0) add_extent(piece.font, extent);
        for (std::size_t i = piece.first; i < piece.first + piece.count; ++i) {
            const ShapedGlyph& g = pool_[i];
            out.glyphs.push_back({g.gid, pen + g.x_offset_px, g.y_offset_px, g.cluster, piece.font});
            pen += g.x_advance_px;
        }
    }
    extents.push_back(extent);
    laid.glyph_count = out.glyphs.size() - laid.first_glyph;
    laid.width_px = pen;
    out.lines.push_back(laid);
    return ok_status();
}

}  // namespace

namespace {

Expected<TextLayout> layout_with(LayoutFonts& fonts, std::string_view utf8,
                                 const ShapeOptions& shape, const LayoutOptions& layout) {
    if (auto ok = check_length("width_px", layout.width_px); !ok) return ok.error();
    if (auto ok = check_length("margin_px", layout.margin_px); !ok) return ok.error();
    if (auto ok = check_length("line_height", layout.line_height); !ok) return ok.error();
    const FontMetrics& metrics = fonts.metrics(0);
    if (metrics.units_per_em <= 0)
        return Error{"layout: font metrics with units per em " +
                     std::to_string(metrics.units_per_em) + " (must be > 0)"};
    if (utf8.size() > kMaxTextBytes)
        return Error{"text of " + std::to_string(utf8.size()) + " bytes: longer than the " +
                     std::to_string(kMaxTextBytes) + " allowed"};
    // Shaping nothing checks the size, features, variations, script and language once, also
    // for a text with no characters.
    {
        ShapeOptions probe = shape;
        fonts.variations(0, shape, probe.variations);
        if (auto shaped = fonts.shaper(0).shape({}, probe); !shaped) return shaped.error();
    }

    std::vector<CodePoint> cps;
    cps.reserve(utf8.size());
    for (std::size_t i = 0; i < utf8.size();) {
        char32_t cp = 0;
        const std::size_t n = decode_one(utf8, i, cp);
        if (n == 0) return invalid_utf8(i);
        cps.push_back({static_cast<std::uint32_t>(i), cp});
        i += n;
    }

    if (shape.direction == Direction::TopToBottom || shape.direction == Direction::BottomToTop)
        return layout_vertical(fonts, utf8, cps, shape, layout);

    TextLayout out;
    // Most scripts give about one glyph per code point: one allocation for a page instead of a
    // doubling series (whose copies each fault in fresh memory).
    out.glyphs.reserve(cps.size());
    std::vector<bool> rtl_line;
    std::vector<LineExtent> extents;
    ParagraphLayout paragraph(fonts, shape, utf8, cps);
    for (std::size_t p = 0;;) {
        std::size_t q = p;
        while (q < cps.size() && !is_newline(cps[q].cp)) ++q;
        if (auto ok = paragraph.run(p, q, layout.width_px, out, extents); !ok) return ok.error();
        rtl_line.resize(out.lines.size(), paragraph.paragraph_level() == 1);
        if (q == cps.size()) break;
        p = q + 1;
        if (cps[q].cp == '\r' && p < cps.size() && cps[p].cp == '\n') ++p;
    }

    // Baselines (layout.hpp): the first at margin + its line's ascent; from one baseline to the
    // next, (descent + gap of the line above + ascent of the line below) × the factor. Runs of
    // lines with equal extents are placed by multiplication, so a single-font page has exactly
    // the spacing margin + ascender + i · line advance.
    const double factor = layout.line_height > 0 ? layout.line_height : 1.0;
    double widest = 0;
    for (const LaidOutLine& l : out.lines) widest = std::max(widest, l.width_px);
    const double avail = layout.width_px > 0 ? layout.width_px : widest;
    const double margin = layout.margin_px;
    // The first font's extent, and its line advance computed in font units as it always was.
    const double scale = shape.size_px / metrics.units_per_em;
    const LineExtent base{metrics.ascender * scale, -metrics.descender * scale,
                          std::max(0.0, metrics.line_gap * scale)};
    const double base_step =
        (metrics.ascender - metrics.descender + metrics.line_gap) * scale * factor;
    double anchor = margin + extents[0].ascent;   // baseline of line `anchor_line`
    std::size_t anchor_line = 0;
    for (std::size_t i = 0; i < out.lines.size(); ++i) {
        LaidOutLine& line = out.lines[i];
        if (i > 0 && !(extents[i] == extents[i - 1])) {
            anchor = out.lines[i - 1].baseline_y_px +
                     (extents[i - 1].descent + extents[i - 1].gap + extents[i].ascent) * factor;
            anchor_line = i;
        }
        const double step = extents[i] == base
                                ? base_step
                                : (extents[i].descent + extents[i].gap + extents[i].ascent) * factor;
        line.baseline_y_px = anchor + static_cast<double>(i - anchor_line) * step;
        line.ascent_px = extents[i].ascent;
        line.descent_px = extents[i].descent;
        const double slack = std::max(0.0, avail - line.width_px);
        double x0 = 0;
        switch (layout.align) {
            case Align::Start: x0 = rtl_line[i] ? slack : 0; break;
            case Align::Center: x0 = slack / 2; break;
            case Align::End: x0 = rtl_line[i] ? 0 : slack; break;
        }
        for (std::size_t g = line.first_glyph; g < line.first_glyph + line.glyph_count; ++g) {
            out.glyphs[g].x_px += margin + x0;
            out.glyphs[g].y_px += line.baseline_y_px;
        }
    }
    out.width_px = avail + 2 * margin;
    const bool uniform = std::all_of(extents.begin(), extents.end(),
                                     [&](const LineExtent& e) { return e == base; });
    out.height_px = uniform ? 2 * margin + base.ascent + base.descent +
                                  static_cast<double>(out.lines.size() - 1) * base_step
                            : out.lines.back().baseline_y_px + extents.back().descent + margin;
    // Each option is finite, but their products need not be: a line_height of 1e300 puts the
    // second line at infinity (a fuzz_text finding). The block's size bounds every position.
    if (!std::isfinite(out.width_px) || !std::isfinite(out.height_px))
        return Error{"layout: the text block would be infinitely large (line_height " +
                     format_num(layout.line_height) + ", margin_px " +
                     format_num(layout.margin_px) + ", width_px " +
                     format_num(layout.width_px) + ")"};
    return out;
}

}  // namespace

Expected<TextLayout> layout_text(Shaper& shaper, const FontMetrics& metrics,
                                 std::string_view utf8, const ShapeOptions& shape,
                                 const LayoutOptions& layout) {
    SingleFont fonts(shaper, metrics);
    return layout_with(fonts, utf8, shape, layout);
}

Expected<TextLayout> layout_text(FontCollection& fonts, std::string_view utf8,
                                 const ShapeOptions& shape, const LayoutOptions& layout) {
    CollectionFonts collection(fonts);
    return layout_with(collection, utf8, shape, layout);
}

MissingGlyphs find_missing_glyphs(const TextLayout& layout, std::string_view utf8) {
    MissingGlyphs missing;
    for (const PlacedGlyph& g : layout.glyphs) {
        if (g.gid != 0) continue;
        // Glyphs are in visual order: the first in the text is the smallest cluster.
        if (missing.count == 0 || g.cluster < missing.first_cluster) missing.first_cluster = g.cluster;
        ++missing.count;
    }
    if (missing.count > 0 && missing.first_cluster < utf8.size())
        text_detail::decode_one(utf8, missing.first_cluster, missing.first_code_point);
    return missing;
}

}  // namespace bezel
