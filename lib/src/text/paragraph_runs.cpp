// ParagraphRuns: shaping a paragraph once per run, greedy wrapping, slicing runs into lines.
#include "text/paragraph_runs.hpp"

#include <algorithm>
#include <limits>

#include "text/layout_common.hpp"
#include "text/shape_tags.hpp"

namespace bezel::text_detail {

void ParagraphRuns::start(std::size_t begin, std::size_t end) {
    base_ = begin;
    chars_.resize(end - begin);
    for (std::size_t k = 0; k < chars_.size(); ++k) chars_[k] = cps_[begin + k].cp;
}

Status ParagraphRuns::shape_range(std::size_t a, std::size_t b, const ScriptRun& run,
                                  ShapedRun& into) {
    ShapeOptions opts = shape_;
    fonts_.variations(run.font, shape_, opts.variations);
    if (!vertical_)
        opts.direction = (run.level & 1) != 0 ? Direction::RightToLeft : Direction::LeftToRight;
    opts.script = tag_string(hb_script_to_iso15924_tag(run.script));
    const std::uint32_t from = offset(a), to = offset(b);
    auto shaped = fonts_.shaper(run.font).shape(text_.substr(from, to - from), opts);
    if (!shaped) return shaped.error();
    into = std::move(*shaped);
    for (ShapedGlyph& g : into.glyphs) g.cluster += from;
    return ok_status();
}

Status ParagraphRuns::shape_and_wrap(const std::vector<std::uint8_t>& levels, double length_px) {
    const std::size_t m = chars_.size(), begin = base_, end = base_ + m;
    if (auto ok = fonts_.assign(chars_.data(), m, breaker_, char_fonts_); !ok) return ok;
    itemize(cps_, begin, end, levels, char_fonts_, runs_);
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
            prefix_[k + 1] += advance(g);
            boundary_[k] = 1;
        }
    }
    for (std::size_t k = 0; k < m; ++k) prefix_[k + 1] += prefix_[k];   // now prefix sums
    // Without a length no line is wrapped: the opportunities are not needed.
    if (length_px > 0) {
        if (auto ok = breaker_.line_breaks(chars_.data(), m, breaks_); !ok) return ok;
    }
    return wrap(m, length_px);
}

bool ParagraphRuns::fits(std::size_t a, std::size_t b, double length_px) const {
    return prefix_[trimmed(a, b)] - prefix_[a] <= length_px + kFitSlackPx;
}

Expected<double> ParagraphRuns::placed_length(const LineSpan& span) {
    double length = 0;
    for (const ScriptRun& run : runs_) {
        const std::size_t a = std::max(run.begin - base_, span.begin);
        const std::size_t b = std::min(run.end - base_, span.end);
        if (a >= b) continue;
        if (cut_in_word(span, span.end, a, b, run)) {
            if (auto ok = shape_range(base_ + a, base_ + b, run, reshaped_); !ok) return ok.error();
            length += reshaped_.advance_px;
        } else {
            length += prefix_[b] - prefix_[a];
        }
    }
    return length;
}

// Greedy, in logical order: a line takes text up to the last break opportunity whose text,
// without trailing spaces, fits; a word with no opportunity that is longer than the line is cut
// at the last cluster boundary that fits, then back while the reshaped line does not (at least
// one cluster per line).
Status ParagraphRuns::wrap(std::size_t m, double length_px) {
    spans_.clear();
    if (length_px <= 0 || m == 0) {
        spans_.push_back({0, m, false, false, false});
        return ok_status();
    }
    auto next_boundary = [&](std::size_t x) {
        ++x;
        while (x < m && boundary_[x] == 0) ++x;
        return x;
    };
    constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
    std::size_t start = 0, candidate = kNone;
    bool start_cut = false;
    for (std::size_t k = 1; k <= m;) {
        if (k < m && breaks_[k] == 0) {
            ++k;
            continue;
        }
        if (k <= start || fits(start, k, length_px)) {
            if (k > start) candidate = k;
            ++k;
            continue;
        }
        if (candidate != kNone) {
            spans_.push_back({start, candidate, true, start_cut, false});
            start = candidate;
            start_cut = false;
            candidate = kNone;
            continue;   // the same k again, from the new start
        }
        const std::size_t first = next_boundary(start);
        std::size_t q = first;
        for (std::size_t q2 = next_boundary(q); q2 < k && fits(start, q2, length_px);
             q2 = next_boundary(q2))
            q = q2;
        while (q > first) {
            auto length = placed_length({start, q, false, start_cut, true});
            if (!length) return length.error();
            if (*length <= length_px + kFitSlackPx) break;
            do --q;
            while (q > first && boundary_[q] == 0);
        }
        spans_.push_back({start, q, false, start_cut, true});
        start = q;
        start_cut = true;
    }
    if (start < m || spans_.empty()) spans_.push_back({start, m, false, start_cut, false});
    return ok_status();
}

Expected<const std::vector<ShapedGlyph>*> ParagraphRuns::slice_glyphs(const LineSpan& span,
                                                                      std::size_t glyph_end,
                                                                      std::size_t r,
                                                                      std::size_t a,
                                                                      std::size_t b) {
    if (!cut_in_word(span, glyph_end, a, b, runs_[r])) return &shaped_[r].glyphs;
    if (auto ok = shape_range(base_ + a, base_ + b, runs_[r], reshaped_); !ok) return ok.error();
    return &reshaped_.glyphs;
}

void ParagraphRuns::append_clusters(const std::vector<ShapedGlyph>& glyphs, std::size_t r,
                                    std::size_t p, std::size_t q,
                                    std::vector<ShapedGlyph>& pool) const {
    // HarfBuzz keeps a run's clusters monotonic (ascending, or descending for a right-to-left
    // or bottom-to-top run), so the glyphs of [from, to) are one stretch, found by two binary
    // searches instead of a scan of the whole run per line.
    const std::uint32_t from = offset(base_ + p), to = offset(base_ + q);
    const bool down = descending(runs_[r]);
    auto before = [down](std::uint32_t bound) {
        return [bound, down](const ShapedGlyph& g) {
            return down ? g.cluster >= bound : g.cluster < bound;
        };
    };
    auto first = std::partition_point(glyphs.begin(), glyphs.end(), before(down ? to : from));
    auto last = std::partition_point(first, glyphs.end(), before(down ? from : to));
    pool.insert(pool.end(), first, last);
}

}  // namespace bezel::text_detail
