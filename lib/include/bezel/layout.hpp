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
#include "bezel/font_collection.hpp"
#include "bezel/shape.hpp"

#pragma GCC visibility push(default)  // the public API of libbezel.so (docs/architecture.md)
namespace bezel {

enum class Align : std::uint8_t { Start, Center, End };

// For vertical text (ShapeOptions::direction TopToBottom or BottomToTop) every field is along
// the line's own axis: width_px is the column LENGTH (a height), line_height spaces columns, and
// align places the text along its column.
struct LayoutOptions {
    double width_px = 0;       // wrap lines at break opportunities to fit this width; 0 = no wrap
                               // (vertical text: columns wrap at this height)
    double line_height = 0;    // baseline-to-baseline distance as a multiple of the fonts' own
                               // (ascender − descender + line gap); 0 means 1.0. Vertical text:
                               // centre line to centre line, a multiple of the first font's
                               // vertical extents (Shaper::extents)
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
    std::uint16_t font = 0;      // index in the FontCollection (0 for the single-font layout)
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
    // The line's extent above and below its baseline: the largest ascender and descender
    // (descent > 0) of the fonts it uses, the first font always among them. Vertical text: the
    // first font's vertical extents right (ascent) and left (descent) of the centre line.
    double ascent_px = 0, descent_px = 0;
};

struct TextLayout {
    std::vector<PlacedGlyph> glyphs;
    std::vector<LaidOutLine> lines;
    double width_px = 0, height_px = 0;   // page size including margins (width_px + margins if wrapping)
};

// Shapes and lays out a paragraph: explicit newlines (\n, \r\n, U+2028) start lines; with
// width_px > 0 lines wrap at break opportunities (UAX #14 by ICU, dictionaries for Thai, Lao,
// Khmer and Myanmar; a word wider than the line is broken between grapheme clusters); each line
// is shaped per run of one script, direction and font, runs ordered by their bidi levels. `metrics`
// gives line height. Errors as Shaper::shape, plus a negative or non-finite
// width/margin/line height, metrics with units_per_em ≤ 0.
//
// Vertical text (shape.direction TopToBottom or BottomToTop), as hb-view lays out --direction
// ttb: each paragraph is one column, or several when width_px > 0 (the column length), wrapped
// as lines are. Columns stack right to left, the first one's centre line at `right` from the
// page's right margin, the next one column advance further left; the column advance is
// (right + left + line gap) · line_height, where right, left and the gap are the first font's
// vertical extents (Shaper::extents: vhea's ascender and −descender; half an em each when the
// font has no vhea, or one whose ascender is not beyond its descender); `metrics` is not used.
// The page is right + left + (columns − 1) · column advance wide and the longest column (or
// width_px) high, plus the margins. Each run of one script and font is shaped in the vertical
// direction: vertical advances (vmtx, else ascender − descender), origins (VORG, else vmtx's
// side bearing, else HarfBuzz's fallback from the glyph's extents) and the font's `vert`
// substitutions (brackets, 、。, ー, small kana). Latin and other horizontal scripts stand
// upright, one glyph under the next, as hb-view draws them (not turned sideways as CSS's
// text-orientation: mixed would). No bidi: runs keep their logical order down the column (up it
// for BottomToTop, whose glyphs HarfBuzz reverses).
//
// Lines: N line separators make N + 1 lines (an empty text is one empty line); the first
// baseline is at margin + ascender; spaces at the end of a wrapped line hang (not placed, not
// counted in its width, but inside its text range). Where a line cuts a word between clusters,
// both pieces are reshaped (Arabic letters at the cut take their final/initial forms).
//
// Bidi is the full Unicode Bidirectional Algorithm (UAX #9) by GNU FriBidi, per paragraph:
// explicit embeddings, overrides and isolates, W1–W7, N0–N2, I1–I2, then per line after
// wrapping L1 (trailing whitespace at the paragraph level) and L2 (runs reordered by level).
// The paragraph direction is shape.direction, or from the first strong character (P2/P3).
Expected<TextLayout> layout_text(Shaper& shaper, const FontMetrics& metrics,
                                 std::string_view utf8, const ShapeOptions& shape,
                                 const LayoutOptions& layout);

// The same over a list of fonts (font fallback): each grapheme cluster is drawn by the font the
// rule of font_choice.cpp picks (in short: emoji presentation takes the first colour font that
// covers it; a cluster of spaces, punctuation or digits stays in the font before it if that font
// covers it; otherwise the first font of the list that covers it; then the collection's
// fallback source, whose font is appended; else the first font's .notdef). Runs are shaped per
// font. shape.variations apply to the first font (after its FontSource's own); the others are
// shaped at their FontSource's coordinates.
//
// Line spacing: a line's ascent and descent are the largest of the fonts it uses, the first
// font always among them; the first baseline is at margin + its line's ascent, and each next
// baseline (descent + line gap of the line above + ascent of the line below) × line_height
// further down, so a line that needs a taller font grows and a page of one font is spaced as
// layout_text above. Errors as above, plus a font the fallback names that cannot be opened does
// not fail (FontCollection::warnings) and ICU missing where clusters must be found.
Expected<TextLayout> layout_text(FontCollection& fonts, std::string_view utf8,
                                 const ShapeOptions& shape, const LayoutOptions& layout);

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
#pragma GCC visibility pop
