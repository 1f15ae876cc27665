// Tests of layout_text: wrapping, newlines, alignment, margins, line height, bidi run order.
//
// Most cases use fonts-test/edge-cases/EdgeCases.ttf at 10 px, where every advance is a round
// number: A, B 6 px, space 3 px, period and .notdef (any other character) 5 px; ascender 8 px,
// descender −2 px, no line gap, so a line advances 10 px. Expected break positions and x
// positions are then exact.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "bezel/font.hpp"
#include "bezel/text.hpp"

namespace bezel {
namespace {

const std::string kFonts = BEZEL_FONTS_DIR;
const std::string kEdge = kFonts + "/edge-cases/EdgeCases.ttf";
const std::string kDejaVu = kFonts + "/dejavu-sans/DejaVuSans.ttf";
const std::string kHebrew = kFonts + "/noto-hebrew/NotoSansHebrew-Regular.ttf";
const std::string kArabic = kFonts + "/noto-arabic/NotoSansArabic-Regular.ttf";

struct Fixture {
    Shaper shaper;
    FontMetrics metrics;
};

Fixture open_setup(const std::string& file) {
    auto font = Font::open(file);
    auto shaper = Shaper::open(file);
    if (!font || !shaper) {
        ADD_FAILURE() << (font ? shaper.error().message : font.error().message);
        std::abort();
    }
    return Fixture{std::move(shaper).value(), font->metrics()};
}

ShapeOptions at_size(double px) {
    ShapeOptions o;
    o.size_px = px;
    return o;
}

TextLayout lay(Fixture& s, std::string_view text, const LayoutOptions& layout,
               const ShapeOptions& shape = at_size(10)) {
    auto r = layout_text(s.shaper, s.metrics, text, shape, layout);
    if (!r) {
        ADD_FAILURE() << r.error().message;
        return {};
    }
    return std::move(r).value();
}

LayoutOptions wrap_at(double width) {
    LayoutOptions o;
    o.width_px = width;
    return o;
}

// The text of each line, from its byte range.
std::vector<std::string> line_texts(const TextLayout& l, std::string_view text) {
    std::vector<std::string> out;
    for (const LaidOutLine& line : l.lines)
        out.emplace_back(text.substr(line.text_begin, line.text_end - line.text_begin));
    return out;
}

using Lines = std::vector<std::string>;

// --- Wrapping -------------------------------------------------------------------------------

TEST(Layout, NoWidthKeepsOneLinePerParagraph) {
    Fixture s = open_setup(kEdge);
    const TextLayout l = lay(s, "AA BB", LayoutOptions{});
    ASSERT_EQ(l.lines.size(), 1u);
    EXPECT_DOUBLE_EQ(l.lines[0].width_px, 27);
    EXPECT_DOUBLE_EQ(l.width_px, 27);
    EXPECT_DOUBLE_EQ(l.height_px, 10);   // ascender − descender
    EXPECT_DOUBLE_EQ(l.lines[0].baseline_y_px, 8);
    const double xs[] = {0, 6, 12, 15, 21};
    ASSERT_EQ(l.glyphs.size(), 5u);
    for (std::size_t i = 0; i < 5; ++i) {
        EXPECT_DOUBLE_EQ(l.glyphs[i].x_px, xs[i]) << i;
        EXPECT_DOUBLE_EQ(l.glyphs[i].y_px, 8) << i;
        EXPECT_EQ(l.glyphs[i].cluster, i);
    }
}

TEST(Layout, WrapsAfterSpacesAtTheExactWidth) {
    Fixture s = open_setup(kEdge);
    const std::string text = "AA BB";
    // "AA BB" is 27 px: it fits 27 exactly and not 26.99.
    EXPECT_EQ(lay(s, text, wrap_at(27)).lines.size(), 1u);
    const TextLayout l = lay(s, text, wrap_at(26.99));
    EXPECT_EQ(line_texts(l, text), (Lines{"AA ", "BB"}));
    // The trailing space hangs: not placed, not counted.
    EXPECT_EQ(l.lines[0].glyph_count, 2u);
    EXPECT_DOUBLE_EQ(l.lines[0].width_px, 12);
    EXPECT_DOUBLE_EQ(l.lines[1].baseline_y_px, 18);
    EXPECT_DOUBLE_EQ(l.glyphs[2].x_px, 0);   // B starts the second line
    EXPECT_DOUBLE_EQ(l.width_px, 26.99);
    EXPECT_DOUBLE_EQ(l.height_px, 20);
    // A line holds as many words as fit: "AA BB" + " AA" is 36, so 35 breaks after BB.
    EXPECT_EQ(line_texts(lay(s, "AA BB AA B", wrap_at(35)), "AA BB AA B"),
              (Lines{"AA BB ", "AA B"}));
}

TEST(Layout, SpacesBeyondTheWidthHang) {
    Fixture s = open_setup(kEdge);
    const std::string text = "AA    BB";
    const TextLayout l = lay(s, text, wrap_at(12));
    EXPECT_EQ(line_texts(l, text), (Lines{"AA    ", "BB"}));
    EXPECT_DOUBLE_EQ(l.lines[0].width_px, 12);
}

TEST(Layout, WordWiderThanTheLineBreaksBetweenClusters) {
    Fixture s = open_setup(kEdge);
    const std::string text = "AAAAA BB";
    const TextLayout l = lay(s, text, wrap_at(20));
    EXPECT_EQ(line_texts(l, text), (Lines{"AAA", "AA ", "BB"}));
    // Narrower than one cluster: one cluster per line, never an empty line.
    EXPECT_EQ(line_texts(lay(s, "ABA", wrap_at(1)), "ABA"), (Lines{"A", "B", "A"}));
}

TEST(Layout, BreaksAfterHyphensAndBetweenIdeographs) {
    Fixture s = open_setup(kEdge);
    // '-' is .notdef here (5 px): "AA-" is 17 px.
    EXPECT_EQ(line_texts(lay(s, "AA-BB", wrap_at(18)), "AA-BB"), (Lines{"AA-", "BB"}));
    // A leading hyphen is a sign, not a break.
    EXPECT_EQ(line_texts(lay(s, "A -BB", wrap_at(17)), "A -BB"), (Lines{"A ", "-BB"}));
    // Ideographs (5 px .notdef each) break anywhere, but not before 。.
    const std::string cjk = "中文字。字";
    EXPECT_EQ(line_texts(lay(s, cjk, wrap_at(11)), cjk), (Lines{"中文", "字。", "字"}));
    // No break at a no-break space: the word is cut only when it cannot fit.
    const std::string nbsp = "AA\u00A0BB";
    EXPECT_EQ(line_texts(lay(s, nbsp, wrap_at(100)), nbsp).size(), 1u);
}

TEST(Layout, ThaiWrapsBetweenWordsFoundByDictionary) {
    // Thai is written without spaces; ICU's dictionary finds the words. Every character is
    // .notdef here, 5 px but the marks (zero width): "สวัสดี" is 20 px, "สวัสดีครับ" 35 px.
    Fixture s = open_setup(kEdge);
    const std::string thai = "\u0e2a\u0e27\u0e31\u0e2a\u0e14\u0e35\u0e04\u0e23\u0e31\u0e1a";
    EXPECT_EQ(line_texts(lay(s, thai, wrap_at(30)), thai),
              (Lines{"\u0e2a\u0e27\u0e31\u0e2a\u0e14\u0e35", "\u0e04\u0e23\u0e31\u0e1a"}));
    // Quotation marks stay with their words (LB19) and "$5.00" is one number (LB25): 31 px,
    // then 25 px.
    EXPECT_EQ(line_texts(lay(s, "A \"BB\" $5.00", wrap_at(32)), "A \"BB\" $5.00"),
              (Lines{"A \"BB\" ", "$5.00"}));
}

TEST(Layout, NewlinesStartLinesAndEmptyLinesCount) {
    Fixture s = open_setup(kEdge);
    const std::string text = "A\nB\r\n\nAB\u2028B\rA";
    const TextLayout l = lay(s, text, LayoutOptions{});
    EXPECT_EQ(line_texts(l, text), (Lines{"A", "B", "", "AB", "B", "A"}));
    ASSERT_EQ(l.lines.size(), 6u);
    EXPECT_EQ(l.lines[2].glyph_count, 0u);
    for (std::size_t i = 0; i < l.lines.size(); ++i)
        EXPECT_DOUBLE_EQ(l.lines[i].baseline_y_px, 8 + 10.0 * i);
    EXPECT_DOUBLE_EQ(l.height_px, 10 + 5 * 10);
    // A trailing newline makes a last, empty line; an empty text is one empty line.
    EXPECT_EQ(lay(s, "A\n", LayoutOptions{}).lines.size(), 2u);
    const TextLayout empty = lay(s, "", LayoutOptions{});
    ASSERT_EQ(empty.lines.size(), 1u);
    EXPECT_TRUE(empty.glyphs.empty());
    EXPECT_DOUBLE_EQ(empty.height_px, 10);
}

// --- Alignment, margins, line height -------------------------------------------------------

TEST(Layout, AlignmentPlacesLinesInTheWidth) {
    Fixture s = open_setup(kEdge);
    LayoutOptions o = wrap_at(100);
    o.align = Align::Center;
    EXPECT_DOUBLE_EQ(lay(s, "AA", o).glyphs[0].x_px, 44);
    o.align = Align::End;
    EXPECT_DOUBLE_EQ(lay(s, "AA", o).glyphs[0].x_px, 88);
    o.align = Align::Start;
    EXPECT_DOUBLE_EQ(lay(s, "AA", o).glyphs[0].x_px, 0);
    // Without a width, lines align within the widest one.
    LayoutOptions free;
    free.align = Align::End;
    const TextLayout l = lay(s, "AAAA\nA", free);
    EXPECT_DOUBLE_EQ(l.width_px, 24);
    EXPECT_DOUBLE_EQ(l.glyphs[4].x_px, 18);
}

TEST(Layout, MarginsSurroundTheBlockAndLineHeightScales) {
    Fixture s = open_setup(kEdge);
    LayoutOptions o = wrap_at(12);
    o.margin_px = 5;
    o.line_height = 1.5;
    const TextLayout l = lay(s, "AA BB", o);
    ASSERT_EQ(l.lines.size(), 2u);
    EXPECT_DOUBLE_EQ(l.glyphs[0].x_px, 5);
    EXPECT_DOUBLE_EQ(l.lines[0].baseline_y_px, 5 + 8);
    EXPECT_DOUBLE_EQ(l.lines[1].baseline_y_px, 5 + 8 + 15);
    EXPECT_DOUBLE_EQ(l.width_px, 12 + 10);
    EXPECT_DOUBLE_EQ(l.height_px, 5 + 10 + 15 + 5);
}

TEST(Layout, LineHeightComesFromTheFontsMetrics) {
    Fixture s = open_setup(kDejaVu);
    const TextLayout l = lay(s, "a\nb", LayoutOptions{}, at_size(20));
    const double scale = 20.0 / s.metrics.units_per_em;
    ASSERT_EQ(l.lines.size(), 2u);
    EXPECT_NEAR(l.lines[0].baseline_y_px, s.metrics.ascender * scale, 1e-9);
    EXPECT_NEAR(l.lines[1].baseline_y_px - l.lines[0].baseline_y_px,
                (s.metrics.ascender - s.metrics.descender + s.metrics.line_gap) * scale, 1e-9);
}

// --- Right to left --------------------------------------------------------------------------

TEST(Layout, RtlParagraphStartsAtTheRight) {
    Fixture s = open_setup(kHebrew);
    const std::string text = "שלום";
    LayoutOptions o = wrap_at(200);
    const TextLayout l = lay(s, text, o, at_size(20));
    ASSERT_EQ(l.lines.size(), 1u);
    ASSERT_EQ(l.glyphs.size(), 4u);
    // Visual order: the last letter leftmost; the line ends at the right edge.
    EXPECT_EQ(l.glyphs.front().cluster, 6u);
    EXPECT_EQ(l.glyphs.back().cluster, 0u);
    EXPECT_NEAR(l.glyphs.front().x_px, 200 - l.lines[0].width_px, 1e-9);
    o.align = Align::End;   // End of an RTL paragraph is the left
    EXPECT_NEAR(lay(s, text, o, at_size(20)).glyphs.front().x_px, 0, 1e-9);
}

TEST(Layout, MixedDirectionsOrderRunsByLevel) {
    Fixture s = open_setup(kDejaVu);   // DejaVu Sans covers Hebrew
    // LTR paragraph: "ab " then the Hebrew run reversed, then " cd".
    const std::string ltr = "ab אבג cd";
    const TextLayout l = lay(s, ltr, LayoutOptions{}, at_size(16));
    std::vector<std::uint32_t> clusters;
    for (const PlacedGlyph& g : l.glyphs) clusters.push_back(g.cluster);
    EXPECT_EQ(clusters, (std::vector<std::uint32_t>{0, 1, 2, 7, 5, 3, 9, 10, 11}));
    for (std::size_t i = 1; i < l.glyphs.size(); ++i) EXPECT_GT(l.glyphs[i].x_px, l.glyphs[i - 1].x_px);

    // RTL paragraph: the Latin run (level 2) keeps its order, leftmost; the Hebrew run and the
    // space between (level 1) follow it, reversed.
    const std::string rtl = "אבג cd";
    const TextLayout r = lay(s, rtl, LayoutOptions{}, at_size(16));
    clusters.clear();
    for (const PlacedGlyph& g : r.glyphs) clusters.push_back(g.cluster);
    EXPECT_EQ(clusters, (std::vector<std::uint32_t>{7, 8, 6, 4, 2, 0}));

    // Numbers in an RTL paragraph read left to right.
    const std::string num = "אב 123";
    const TextLayout n = lay(s, num, LayoutOptions{}, at_size(16));
    clusters.clear();
    for (const PlacedGlyph& g : n.glyphs) clusters.push_back(g.cluster);
    EXPECT_EQ(clusters, (std::vector<std::uint32_t>{5, 6, 7, 4, 2, 0}));
}

// The visual order of `text`'s glyphs, as the byte offsets of their clusters.
std::vector<std::uint32_t> visual_clusters(Fixture& s, const std::string& text,
                                           Direction direction = Direction::Auto) {
    ShapeOptions shape = at_size(16);
    shape.direction = direction;
    std::vector<std::uint32_t> clusters;
    for (const PlacedGlyph& g : lay(s, text, LayoutOptions{}, shape).glyphs)
        clusters.push_back(g.cluster);
    return clusters;
}

// Cases the UAX #9 subset bezel had before FriBidi got wrong.
TEST(Layout, FullBidiKeepsNumbersWithSeparatorsIsolatesAndBracketPairsTogether) {
    Fixture s = open_setup(kDejaVu);
    // W4: "1,000" after Hebrew is one left-to-right number, comma included (not "000,1").
    EXPECT_EQ(visual_clusters(s, "\u05d0 1,000"),
              (std::vector<std::uint32_t>{3, 4, 5, 6, 7, 2, 0}));
    // P2 skips isolates: a paragraph that starts with an RLI...PDI of Hebrew followed by Latin
    // is left to right (isolate first, at the left).
    EXPECT_EQ(visual_clusters(s, "\u2067\u05d0\u2069 abc"),
              (std::vector<std::uint32_t>{0, 3, 5, 8, 9, 10, 11}));
    // N0: in a right-to-left paragraph, "ab(cd)" keeps its closing bracket with its pair (not
    // ")ab(cd").
    EXPECT_EQ(visual_clusters(s, "ab(cd)", Direction::RightToLeft),
              (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));
}

TEST(Layout, ExplicitDirectionOverridesTheText) {
    Fixture s = open_setup(kEdge);
    ShapeOptions shape = at_size(10);
    shape.direction = Direction::RightToLeft;
    const TextLayout l = lay(s, "AB", wrap_at(100), shape);
    // Latin letters in an RTL paragraph keep their order and the line starts at the right.
    ASSERT_EQ(l.glyphs.size(), 2u);
    EXPECT_EQ(l.glyphs[0].cluster, 0u);
    EXPECT_DOUBLE_EQ(l.glyphs[0].x_px, 88);
}

TEST(Layout, ArabicWordCutMidWordIsReshapedPerLine) {
    Fixture s = open_setup(kArabic);
    // Dual-joining letters only: every letter changes form when its neighbour moves to another line.
    const std::string word = "سبلعمنهيكسبلعمنهيك";
    const TextLayout whole = lay(s, word, LayoutOptions{}, at_size(20));
    const TextLayout cut = lay(s, word, wrap_at(whole.lines[0].width_px / 2), at_size(20));
    ASSERT_GE(cut.lines.size(), 2u);
    // Every character is on exactly one line, and lines cover the text in order.
    EXPECT_EQ(cut.lines.front().text_begin, 0u);
    EXPECT_EQ(cut.lines.back().text_end, word.size());
    for (std::size_t i = 1; i < cut.lines.size(); ++i)
        EXPECT_EQ(cut.lines[i].text_begin, cut.lines[i - 1].text_end);
    // Each line fits once reshaped.
    for (const LaidOutLine& line : cut.lines)
        EXPECT_LE(line.width_px, whole.lines[0].width_px / 2 + 1e-6);
    // The letters at a cut lose their joining to the other line: reshaped, not sliced, so the
    // glyph at the end of the first line (visually leftmost) is a final form that the whole
    // word did not have at that cluster.
    const std::uint32_t cut_cluster = cut.glyphs[cut.lines[0].first_glyph].cluster;
    GlyphId in_whole = 0;
    for (const PlacedGlyph& g : whole.glyphs)
        if (g.cluster == cut_cluster) in_whole = g.gid;
    EXPECT_NE(cut.glyphs[cut.lines[0].first_glyph].gid, in_whole);
}

// --- Bad input ------------------------------------------------------------------------------

TEST(Layout, BadOptionsAreErrorsNamingThem) {
    Fixture s = open_setup(kEdge);
    auto error_of = [&](std::string_view text, const ShapeOptions& shape,
                        const LayoutOptions& layout) {
        auto r = layout_text(s.shaper, s.metrics, text, shape, layout);
        return r.ok() ? std::string("(no error)") : r.error().message;
    };
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(error_of("A", at_size(10), wrap_at(nan)),
              "layout width_px nan: must be a finite number >= 0");
    LayoutOptions o;
    o.margin_px = -1;
    EXPECT_EQ(error_of("A", at_size(10), o), "layout margin_px -1: must be a finite number >= 0");
    o = LayoutOptions{};
    o.line_height = inf;
    EXPECT_EQ(error_of("A", at_size(10), o),
              "layout line_height inf: must be a finite number >= 0");
    EXPECT_EQ(error_of("", at_size(0), LayoutOptions{}), "font size 0 px: out of range (0, 16384]");
    EXPECT_EQ(error_of("AB\nA\xE0\x80", at_size(10), LayoutOptions{}),
              "text byte 4: invalid UTF-8");
    ShapeOptions vertical = at_size(10);
    vertical.direction = Direction::TopToBottom;
    EXPECT_EQ(error_of("A", vertical, wrap_at(-2)),
              "layout width_px -2: must be a finite number >= 0");
    o = LayoutOptions{};
    o.line_height = 1e308;   // finite, but 1e308 times a 10 px column is not
    EXPECT_EQ(error_of("A\nA", vertical, o),
              "layout: the text block would be infinitely large (line_height 1e+308, margin_px 0, "
              "width_px 0)");
    FontMetrics broken;
    auto r = layout_text(s.shaper, broken, "A", at_size(10), LayoutOptions{});
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().message, "layout: font metrics with units per em 0 (must be > 0)");
}

}  // namespace
}  // namespace bezel
