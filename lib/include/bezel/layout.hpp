// bezel/layout.hpp — a paragraph shaped and laid out into lines: explicit breaks, wrapping at a
// width, bidi runs ordered per line, alignment and margins; or, for a vertical direction, into
// columns.
//
// Units: pixels, y DOWN; a glyph's pen position is on its baseline (horizontal text) or on its
// column's centre line (vertical text).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "bezel/expected.hpp"
#include "bezel/font.hpp"
#include "bezel/shape.hpp"

namespace bezel {

enum class Align : std::uint8_t { Start, Center, End };

// For vertical text (ShapeOptions::direction TopToBottom or BottomToTop) every field is along
// the line's own axis: width_px is the column LENGTH (a height), line_height spaces columns, and
// align places the text along its column.
struct LayoutOptions {
    double width_px = 0;       // wrap lines at break opportunities to fit this width; 0 = no wrap
                               // (vertical text: columns wrap at this height)
    double line_height = 0;    // baseline-to-baseline distance as a multiple of the font's own
                               // (ascender − descender + line gap); 0 means 1.0. Vertical text:
                               // centre line to centre line, a multiple of the vertical extents
                               // (Shaper::extents)
    double margin_px = 0;      // around the text block on all four sides
    Align align = Align::Start;  // Start is left for LTR paragraphs and right for RTL ones; top
                                 // for TopToBottom columns and bottom for BottomToTop ones
};

// A glyph placed on the page, y down: its origin (where its outline's (0, 0) goes), which is the
// pen position plus HarfBuzz's offset. Horizontal text: on the baseline. Vertical text: the
// glyph's horizontal origin, placed by HarfBuzz's vertical origin (half its advance left of the
// column's centre line; VORG or vmtx below the pen).
struct PlacedGlyph {
    GlyphId gid = 0;
    double x_px = 0, y_px = 0;    // origin: pen position + offset
    std::uint32_t cluster = 0;   // byte offset in the whole input text
};

// A line, or a column of vertical text (then "width" is its length down the page).
struct LaidOutLine {
    std::size_t first_glyph = 0, glyph_count = 0;   // into TextLayout::glyphs, in visual order
                                                    // (left to right; vertical: top to bottom)
    std::uint32_t text_begin = 0, text_end = 0;     // byte range of the text on this line
    double baseline_y_px = 0;                       // vertical text: the pen y of the column's top
    double baseline_x_px = 0;                       // vertical text: the column's centre line
                                                    // (its pens' x); 0 for horizontal text
    double width_px = 0;                            // advance width of the line's glyphs
                                                    // (vertical text: their advance height)
};

struct TextLayout {
    std::vector<PlacedGlyph> glyphs;
    std::vector<LaidOutLine> lines;
    double width_px = 0, height_px = 0;   // page size including margins (width_px + margins if wrapping)
};

// Shapes and lays out a paragraph: explicit newlines (\n, \r\n, U+2028) start lines; with
// width_px > 0 lines wrap at break opportunities (after spaces, after hyphens, between ideographs;
// a word wider than the line is broken between clusters); each line is shaped per run of one
// script and direction, runs ordered right to left within an RTL paragraph. `metrics` gives line
// height. Errors as Shaper::shape, plus a negative or non-finite width/margin/line height,
// metrics with units_per_em ≤ 0.
//
// Vertical text (shape.direction TopToBottom or BottomToTop), as hb-view lays out --direction
// ttb: each paragraph is one column, or several when width_px > 0 (the column length), wrapped
// as lines are. Columns stack right to left, the first one's centre line at `right` from the
// page's right margin, the next one column advance further left; the column advance is
// (right + left + line gap) · line_height, where right, left and the gap are the vertical
// extents (Shaper::extents: vhea's ascender and −descender; half an em each when the font has
// no vhea, or one whose ascender is not beyond its descender); `metrics` is not used. The page
// is right + left + (columns − 1) · column advance wide and the longest column (or width_px)
// high, plus the margins. Each run of one script is shaped in the vertical direction: vertical
// advances (vmtx, else ascender − descender), origins (VORG, else vmtx's side bearing, else
// HarfBuzz's fallback from the glyph's extents) and the font's `vert` substitutions (brackets,
// 、。, ー, small kana). Latin and other horizontal scripts stand upright, one glyph under the
// next, as hb-view draws them (not turned sideways as CSS's text-orientation: mixed would). No
// bidi: runs keep their logical order down the column (up it for BottomToTop, whose glyphs
// HarfBuzz reverses).
//
// Lines: N line separators make N + 1 lines (an empty text is one empty line); the first
// baseline is at margin + ascender; spaces at the end of a wrapped line hang (not placed, not
// counted in its width, but inside its text range). Where a line cuts a word between clusters,
// both pieces are reshaped (Arabic letters at the cut take their final/initial forms).
//
// Bidi is a simplified Unicode Bidirectional Algorithm (UAX #9), without fribidi. Implemented:
// the paragraph direction from its first strong character (P2/P3) unless shape.direction gives
// it; strong classes from the Unicode script (letters of Hebrew, Arabic, Syriac, Thaana, N'Ko, …
// are R, other letters L); marks take the class before them (W1); digits are left-to-right
// numbers, one level up unless they follow L text (W2, W7, I1, I2); neutrals between equal
// directions take it, others the paragraph's (N1, N2); runs reordered by level per line (L2).
// Left out: explicit embeddings, overrides and isolates (LRE…PDI are neutrals), the number
// separator/terminator rules W3–W6 ("1,000" or "5%" beside Arabic may split), paired brackets
// (N0), and L1 (trailing whitespace keeps its level; wrapped lines drop it instead). Line
// breaking is a subset of UAX #14: no dictionary breaking (Thai, Lao, Khmer), no quotation or
// numeric prefix/postfix classes.
Expected<TextLayout> layout_text(Shaper& shaper, const FontMetrics& metrics,
                                 std::string_view utf8, const ShapeOptions& shape,
                                 const LayoutOptions& layout);

// The glyphs of a layout that are .notdef (gid 0): characters the font maps to nothing, drawn as
// its "missing glyph" box, as hb-view draws them.
struct MissingGlyphs {
    std::size_t count = 0;             // .notdef glyphs placed
    std::uint32_t first_cluster = 0;   // byte offset of the first of them in text order
    char32_t first_code_point = 0;     // the character there (valid when count > 0)
};
// `layout` must be layout_text's result for `utf8`.
MissingGlyphs find_missing_glyphs(const TextLayout& layout, std::string_view utf8);

}  // namespace bezel
