// layout_text: paragraphs, bidi, lines, alignment and line spacing.
//
// Per paragraph (text between newlines): the bidi levels are resolved (bidi.hpp: FriBidi,
// UAX #9), then ParagraphRuns (paragraph_runs.hpp) gives each grapheme cluster its font, shapes
// runs of one script, level and font once and wraps the paragraph greedily into lines. Each
// line's glyphs are the slices of those runs that fall on it, split where L1 gives the line's
// trailing whitespace the paragraph level, ordered by level (L2) and placed along the baseline.
#include <algorithm>
#include <cmath>

#include "bezel/layout.hpp"
#include "text/bidi.hpp"
#include "text/layout_common.hpp"
#include "text/layout_fonts.hpp"
#include "text/layout_vertical.hpp"
#include "text/paragraph_runs.hpp"
#include "text/script_runs.hpp"
#include "text/utf8_decode.hpp"

namespace bezel {

using namespace text_detail;

namespace {

Status check_length(const char* name, double v) {
    if (std::isfinite(v) && v >= 0) return ok_status();
    return Error{std::string("layout ") + name + " " + format_num(v) + ": must be a finite number >= 0"};
}

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

// One paragraph's lines; members are reused across paragraphs.
class ParagraphLayout : private ParagraphRuns {
public:
    ParagraphLayout(LayoutFonts& fonts, const ShapeOptions& shape, std::string_view text,
                    const std::vector<CodePoint>& cps)
        : ParagraphRuns(fonts, shape, text, cps, false) {}

    // Lays out cps[begin, end) as lines appended to `out`: glyph x relative to the line's start,
    // y relative to its baseline; placement on the page comes after all lines are known.
    Status run(std::size_t begin, std::size_t end, double width_px, TextLayout& out,
               std::vector<LineExtent>& extents);
    // The level of the paragraph last run: 1 right to left, 0 left to right.
    std::uint8_t paragraph_level() const { return bidi_.paragraph_level(); }

private:
    Status place_line(const LineSpan& line, TextLayout& out, std::vector<LineExtent>& extents);
    void add_extent(std::uint16_t font, LineExtent& extent) const;

    BidiParagraph bidi_;
    std::vector<std::uint8_t> line_levels_;
    std::vector<ShapedGlyph> pool_;
    std::vector<Piece> pieces_;
    std::vector<std::uint8_t> levels_;
    std::vector<std::size_t> order_;
};

Status ParagraphLayout::run(std::size_t begin, std::size_t end, double width_px,
                            TextLayout& out, std::vector<LineExtent>& extents) {
    start(begin, end);
    if (auto ok = bidi_.resolve(chars_.data(), chars_.size(), shape_.direction); !ok) return ok;
    if (auto ok = shape_and_wrap(bidi_.levels(), width_px); !ok) return ok;
    for (const LineSpan& line : spans_)
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
    const std::size_t end = glyph_end(line);
    pool_.clear();
    pieces_.clear();
    levels_.clear();
    bidi_.line_levels(line.begin, line.end, line_levels_);
    for (std::size_t r = 0; r < runs_.size(); ++r) {
        const ScriptRun& run = runs_[r];
        const std::size_t a = std::max(run.begin - base_, line.begin);
        const std::size_t b = std::min(run.end - base_, end);
        if (a >= b) continue;
        auto glyphs = slice_glyphs(line, end, r, a, b);
        if (!glyphs) return glyphs.error();
        // One piece per stretch of the slice at one line level: within a run the levels differ
        // only where L1 reset the line's trailing whitespace.
        for (std::size_t p = a; p < b;) {
            const std::uint8_t level = line_levels_[p - line.begin];
            std::size_t q = p + 1;
            while (q < b && line_levels_[q - line.begin] == level) ++q;
            Piece piece{pool_.size(), 0, run.font};
            append_clusters(**glyphs, r, p, q, pool_);
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
