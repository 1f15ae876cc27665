// Tests of vertical layout (layout_text with Direction::TopToBottom / BottomToTop): columns,
// their order and spacing, wrapping at a column length, `vert` glyph variants, and pen positions
// against hb-shape's (tests/golden/vertical/expected.tsv, made by generate.sh beside it).
//
// The CJK font is fonts-test/noto-cjk/NotoSansCJKjp-Subset.otf: 1000 units/em, vhea ascender
// 500, descender −500, line gap 0, so a column is one em wide and the next column one em to its
// left; ideographs, kana and fullwidth forms advance one em down (vmtx) and have their vertical
// origin 880 units above their baseline (VORG) and 500 units right of their horizontal origin.
// At 40 px: every such glyph advances 40 px, its origin is 20 px left of the column's centre
// line and 35.2 px below the pen.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "bezel/font.hpp"
#include "bezel/font_collection.hpp"
#include "bezel/text.hpp"

namespace bezel {
namespace {

const std::string kFonts = BEZEL_FONTS_DIR;
const std::string kCjk = kFonts + "/noto-cjk/NotoSansCJKjp-Subset.otf";
const std::string kDejaVu = kFonts + "/dejavu-sans/DejaVuSans.ttf";

// Pen positions are compared with hb-shape's to this, pixels: HarfBuzz's positions are whole
// units of 1/1024 px in bezel (shape.cpp) and each glyph's rounding adds at most 1/2048 px, far
// inside 1/64 px for the dozen glyphs of a case.
constexpr double kPenTolerancePx = 1.0 / 64;

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

ShapeOptions vertical(double px, Direction d = Direction::TopToBottom) {
    ShapeOptions o;
    o.size_px = px;
    o.direction = d;
    return o;
}

TextLayout lay(Fixture& s, std::string_view text, const ShapeOptions& shape,
               const LayoutOptions& layout = LayoutOptions{}) {
    auto r = layout_text(s.shaper, s.metrics, text, shape, layout);
    if (!r) {
        ADD_FAILURE() << r.error().message;
        return {};
    }
    return std::move(r).value();
}

std::vector<std::string> column_texts(const TextLayout& l, std::string_view text) {
    std::vector<std::string> out;
    for (const LaidOutLine& line : l.lines)
        out.emplace_back(text.substr(line.text_begin, line.text_end - line.text_begin));
    return out;
}

GlyphId horizontal_gid(Shaper& shaper, std::string_view text, bool vert_feature) {
    ShapeOptions o;
    o.size_px = 40;
    o.direction = Direction::LeftToRight;
    if (vert_feature) o.features = {FeatureSetting{"vert", 1}};
    auto run = shaper.shape(text, o);
    if (!run || run->glyphs.size() != 1) {
        ADD_FAILURE() << "shaping '" << text << "' horizontally";
        return 0;
    }
    return run->glyphs[0].gid;
}

// --- One column -----------------------------------------------------------------------------

TEST(VerticalLayout, ColumnGlyphsShareTheCentreLineAndDescendByTheirAdvance) {
    Fixture s = open_setup(kCjk);
    const TextLayout l = lay(s, "縦書きの日本語", vertical(40));
    ASSERT_EQ(l.lines.size(), 1u);
    ASSERT_EQ(l.glyphs.size(), 7u);
    const LaidOutLine& col = l.lines[0];
    EXPECT_DOUBLE_EQ(col.baseline_x_px, 20);   // right of it: vhea's 500 units
    EXPECT_DOUBLE_EQ(col.baseline_y_px, 0);
    EXPECT_NEAR(col.width_px, 7 * 40, 1e-9);   // the column's length
    for (std::size_t i = 0; i < l.glyphs.size(); ++i) {
        EXPECT_NEAR(l.glyphs[i].x_px, 0, 1e-3) << i;                    // centre − 20 px
        EXPECT_NEAR(l.glyphs[i].y_px, 35.2 + 40.0 * i, 1e-3) << i;      // pen + VORG
        if (i > 0) {
            EXPECT_GT(l.glyphs[i].y_px, l.glyphs[i - 1].y_px);
        }
    }
    EXPECT_DOUBLE_EQ(l.width_px, 40);
    EXPECT_NEAR(l.height_px, 280, 1e-9);
}

TEST(VerticalLayout, PageIsOneColumnWidePlusMargins) {
    Fixture s = open_setup(kCjk);
    LayoutOptions o;
    o.margin_px = 16;
    const TextLayout l = lay(s, "日本", vertical(40), o);
    EXPECT_DOUBLE_EQ(l.width_px, 40 + 32);
    EXPECT_NEAR(l.height_px, 80 + 32, 1e-9);
    EXPECT_DOUBLE_EQ(l.lines[0].baseline_x_px, 16 + 20);
    EXPECT_NEAR(l.glyphs[0].y_px, 16 + 35.2, 1e-3);
}

TEST(VerticalLayout, EmptyTextIsOneEmptyColumn) {
    Fixture s = open_setup(kCjk);
    const TextLayout l = lay(s, "", vertical(40));
    ASSERT_EQ(l.lines.size(), 1u);
    EXPECT_EQ(l.glyphs.size(), 0u);
    EXPECT_DOUBLE_EQ(l.width_px, 40);
    EXPECT_DOUBLE_EQ(l.height_px, 0);
}

// --- Columns --------------------------------------------------------------------------------

TEST(VerticalLayout, ParagraphsStackRightToLeftOneColumnAdvanceApart) {
    Fixture s = open_setup(kCjk);
    const std::string text = "日本語\nあいうえ\n漢字";
    const TextLayout l = lay(s, text, vertical(40));
    ASSERT_EQ(l.lines.size(), 3u);
    EXPECT_EQ(column_texts(l, text), (std::vector<std::string>{"日本語", "あいうえ", "漢字"}));
    EXPECT_DOUBLE_EQ(l.width_px, 120);
    EXPECT_NEAR(l.height_px, 160, 1e-9);   // the longest column
    EXPECT_DOUBLE_EQ(l.lines[0].baseline_x_px, 100);
    EXPECT_DOUBLE_EQ(l.lines[1].baseline_x_px, 60);
    EXPECT_DOUBLE_EQ(l.lines[2].baseline_x_px, 20);
    // Every glyph of the second column is left of every glyph of the first.
    const PlacedGlyph& first_of_second = l.glyphs[l.lines[1].first_glyph];
    for (std::size_t g = 0; g < l.lines[0].glyph_count; ++g)
        EXPECT_LT(first_of_second.x_px, l.glyphs[g].x_px);
    // Each column starts at the top.
    for (const LaidOutLine& col : l.lines) EXPECT_NEAR(l.glyphs[col.first_glyph].y_px, 35.2, 1e-3);
}

TEST(VerticalLayout, LineHeightScalesTheColumnAdvance) {
    Fixture s = open_setup(kCjk);
    LayoutOptions o;
    o.line_height = 1.5;
    const TextLayout l = lay(s, "日\n本", vertical(40), o);
    ASSERT_EQ(l.lines.size(), 2u);
    EXPECT_DOUBLE_EQ(l.lines[0].baseline_x_px - l.lines[1].baseline_x_px, 60);
    EXPECT_DOUBLE_EQ(l.width_px, 40 + 60);
}

TEST(VerticalLayout, AlignPlacesShortColumnsAlongTheLongest) {
    Fixture s = open_setup(kCjk);
    const std::string text = "日本語あい\n漢字";
    LayoutOptions o;
    o.align = Align::End;
    TextLayout l = lay(s, text, vertical(40), o);
    ASSERT_EQ(l.lines.size(), 2u);
    EXPECT_NEAR(l.lines[1].baseline_y_px, 120, 1e-9);   // 200 − 80: ends at the bottom
    o.align = Align::Center;
    l = lay(s, text, vertical(40), o);
    EXPECT_NEAR(l.lines[1].baseline_y_px, 60, 1e-9);
}

// --- Wrapping -------------------------------------------------------------------------------

TEST(VerticalLayout, ColumnsWrapAtTheColumnLength) {
    Fixture s = open_setup(kCjk);
    // Five ems a column. No column may start with 、 or 」。 nor end with 「 (UAX #14's
    // CL, OP classes): the first column ends after 、, the second holds the bracketed word.
    const std::string text = "日本語、「漢字」。あいうえおかき";
    LayoutOptions o;
    o.width_px = 200;
    const TextLayout l = lay(s, text, vertical(40), o);
    EXPECT_EQ(column_texts(l, text),
              (std::vector<std::string>{"日本語、", "「漢字」。", "あいうえお", "かき"}));
    for (const LaidOutLine& col : l.lines) EXPECT_LE(col.width_px, 200 + 1e-9);
    EXPECT_DOUBLE_EQ(l.height_px, 200);
    EXPECT_DOUBLE_EQ(l.width_px, 4 * 40);
    EXPECT_DOUBLE_EQ(l.lines[3].baseline_x_px, 20);
}

TEST(VerticalLayout, ALatinWordLongerThanTheColumnIsCutBetweenClusters) {
    Fixture s = open_setup(kCjk);
    // Upright Latin in Noto CJK advances one em per letter: three letters a column.
    const std::string text = "Vertical";
    LayoutOptions o;
    o.width_px = 120;
    const TextLayout l = lay(s, text, vertical(40), o);
    EXPECT_EQ(column_texts(l, text), (std::vector<std::string>{"Ver", "tic", "al"}));
}

TEST(VerticalLayout, TrailingSpacesHangAtAWrappedColumnEnd) {
    Fixture s = open_setup(kDejaVu);
    // DejaVu Sans has no vmtx: every glyph advances ascender − descender (HarfBuzz's fallback).
    const std::string text = "ab cd";
    const TextLayout one = lay(s, "a", vertical(20));
    const double adv = one.lines[0].width_px;
    ASSERT_GT(adv, 20);
    LayoutOptions o;
    o.width_px = 2.5 * adv;
    const TextLayout l = lay(s, text, vertical(20), o);
    ASSERT_EQ(column_texts(l, text), (std::vector<std::string>{"ab ", "cd"}));
    EXPECT_EQ(l.lines[0].glyph_count, 2u);   // the space is not placed
    EXPECT_NEAR(l.lines[0].width_px, 2 * adv, 1e-9);
}

// --- Glyph variants -------------------------------------------------------------------------

TEST(VerticalLayout, PunctuationTakesTheFontsVertVariant) {
    Fixture s = open_setup(kCjk);
    for (const char* c : {"、", "（", "ー", "「"}) {
        SCOPED_TRACE(c);
        const TextLayout l = lay(s, c, vertical(40));
        ASSERT_EQ(l.glyphs.size(), 1u);
        const GlyphId upright = horizontal_gid(s.shaper, c, false);
        const GlyphId vert = horizontal_gid(s.shaper, c, true);
        EXPECT_NE(upright, vert);
        EXPECT_EQ(l.glyphs[0].gid, vert);
    }
    // An ideograph has no vertical form: the same glyph both ways.
    EXPECT_EQ(lay(s, "日", vertical(40)).glyphs[0].gid, horizontal_gid(s.shaper, "日", false));
}

// --- Bottom to top --------------------------------------------------------------------------

TEST(VerticalLayout, BottomToTopReadsUpAndStartsAtTheBottom) {
    Fixture s = open_setup(kCjk);
    const std::string text = "日本語\nあい";
    const TextLayout l = lay(s, text, vertical(40, Direction::BottomToTop));
    ASSERT_EQ(l.lines.size(), 2u);
    // Column 1: 語 at the top, 日 (the text's first character) at the bottom.
    ASSERT_EQ(l.lines[0].glyph_count, 3u);
    EXPECT_EQ(l.glyphs[0].cluster, 6u);
    EXPECT_EQ(l.glyphs[2].cluster, 0u);
    EXPECT_LT(l.glyphs[0].y_px, l.glyphs[2].y_px);
    // Column 2 is shorter: Start puts its first character (あ) at the bottom, as column 1's.
    EXPECT_NEAR(l.lines[1].baseline_y_px, 40, 1e-9);
    const PlacedGlyph& a = l.glyphs[l.lines[1].first_glyph + 1];
    EXPECT_EQ(a.cluster, std::string("日本語\n").size());
    EXPECT_NEAR(a.y_px, l.glyphs[2].y_px, 1e-9);
    EXPECT_LT(a.x_px, l.glyphs[2].x_px);   // still right to left
}

// --- Font fallback --------------------------------------------------------------------------

TEST(VerticalLayout, FallbackFontDrawsWhatTheFirstLacksAndColumnsKeepTheFirstFontsWidth) {
    auto fonts = FontCollection::open({FontSource{kDejaVu, 0, {}}, FontSource{kCjk, 0, {}}});
    ASSERT_TRUE(fonts) << fonts.error().message;
    const std::string text = "Ab日本\n語";
    auto l = layout_text(*fonts, text, vertical(40), LayoutOptions{});
    ASSERT_TRUE(l) << l.error().message;
    ASSERT_EQ(l->lines.size(), 2u);
    ASSERT_EQ(l->glyphs.size(), 5u);
    const std::uint16_t want[] = {0, 0, 1, 1, 1};   // A b from DejaVu Sans, the ideographs from Noto
    for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(l->glyphs[i].font, want[i]) << i;
    // Each run advances by its own font's vertical advances: DejaVu has no vmtx (ascender −
    // descender, 1.164 em), Noto's ideographs one em.
    Fixture dejavu = open_setup(kDejaVu);
    const double latin = lay(dejavu, "Ab", vertical(40)).lines[0].width_px;
    EXPECT_NEAR(l->lines[0].width_px, latin + 80, 1e-3);
    // Columns one em apart: DejaVu, the first font, has no vhea (half an em each side).
    EXPECT_DOUBLE_EQ(l->lines[0].baseline_x_px - l->lines[1].baseline_x_px, 40);
    EXPECT_DOUBLE_EQ(l->width_px, 80);
}

// --- Against hb-shape -----------------------------------------------------------------------

struct HbGlyph {
    GlyphId gid = 0;
    std::uint32_t cluster = 0;
    double x_offset = 0, y_offset = 0, x_advance = 0, y_advance = 0;   // 1/64000 em, y up
};

// "[gid=cluster@dx,dy+ax,ay|…]" as hb-shape --no-glyph-names prints it.
std::vector<HbGlyph> parse_hb_shape(const std::string& s) {
    std::vector<HbGlyph> out;
    std::stringstream items(s.substr(1, s.size() - 2));
    std::string item;
    while (std::getline(items, item, '|')) {
        HbGlyph e;
        const char* p = item.c_str();
        char* end = nullptr;
        e.gid = static_cast<GlyphId>(std::strtoul(p, &end, 10));
        e.cluster = static_cast<std::uint32_t>(std::strtoul(end + 1, &end, 10));
        if (*end == '@') {
            e.x_offset = std::strtod(end + 1, &end);
            e.y_offset = std::strtod(end + 1, &end);
        }
        if (*end == '+') {
            e.x_advance = std::strtod(end + 1, &end);
            if (*end == ',') e.y_advance = std::strtod(end + 1, &end);
        }
        out.push_back(e);
    }
    return out;
}

TEST(VerticalLayout, OriginsEqualHbShapePenPlusOffset) {
    std::ifstream in(std::string(BEZEL_GOLDEN_DIR) + "/vertical/expected.tsv");
    ASSERT_TRUE(in) << "tests/golden/vertical/expected.tsv missing";
    std::string line;
    int cases = 0;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::vector<std::string> f;
        std::stringstream ss(line);
        std::string field;
        while (std::getline(ss, field, '\t')) f.push_back(field);
        ASSERT_EQ(f.size(), 4u) << line;
        SCOPED_TRACE(f[0] + " " + f[1] + " '" + f[2] + "'");
        Fixture s = open_setup(kFonts + "/" + f[0]);
        // 37 px: no position is a whole number of pixels.
        const double size = 37;
        const double scale = size / 64000;   // generate.sh's --font-size
        LayoutOptions o;
        o.margin_px = 5;
        const TextLayout l = lay(
            s, f[2], vertical(size, f[1] == "btt" ? Direction::BottomToTop : Direction::TopToBottom),
            o);
        const std::vector<HbGlyph> hb = parse_hb_shape(f[3]);
        ASSERT_EQ(l.lines.size(), 1u);
        ASSERT_EQ(l.glyphs.size(), hb.size());
        // hb-view's column: its centre line half an em from the left margin for both fonts
        // (Noto's vhea, DejaVu's HarfBuzz fallback), its top at the top margin.
        const double centre = o.margin_px + size / 2;
        EXPECT_NEAR(l.lines[0].baseline_x_px, centre, 1e-9);
        double pen_y = o.margin_px;
        for (std::size_t i = 0; i < hb.size(); ++i) {
            const PlacedGlyph& g = l.glyphs[i];
            EXPECT_EQ(g.gid, hb[i].gid) << "glyph " << i;
            EXPECT_EQ(g.cluster, hb[i].cluster) << "glyph " << i;
            EXPECT_NEAR(g.x_px, centre + hb[i].x_offset * scale, kPenTolerancePx) << "glyph " << i;
            EXPECT_NEAR(g.y_px, pen_y - hb[i].y_offset * scale, kPenTolerancePx) << "glyph " << i;
            pen_y -= hb[i].y_advance * scale;
        }
        EXPECT_NEAR(l.lines[0].width_px, pen_y - o.margin_px, kPenTolerancePx);
        ++cases;
    }
    EXPECT_GE(cases, 6);
}

// --- Extents and errors ---------------------------------------------------------------------

TEST(VerticalLayout, ShaperExtentsAreVheaOrHalfAnEm) {
    Fixture cjk = open_setup(kCjk);
    auto v = cjk.shaper.extents(vertical(40));
    ASSERT_TRUE(v) << v.error().message;
    EXPECT_NEAR(v->ascender_px, 20, 1e-9);
    EXPECT_NEAR(v->descender_px, -20, 1e-9);
    EXPECT_NEAR(v->line_gap_px, 0, 1e-9);
    ShapeOptions h = vertical(40, Direction::LeftToRight);
    auto hx = cjk.shaper.extents(h);
    ASSERT_TRUE(hx) << hx.error().message;
    // hhea, to HarfBuzz's precision in bezel (1/1024 px, shape.cpp).
    EXPECT_NEAR(hx->ascender_px, 1160 * 0.04, 1.0 / 1024);
    EXPECT_NEAR(hx->descender_px, -288 * 0.04, 1.0 / 1024);

    Fixture dejavu = open_setup(kDejaVu);   // no vhea
    auto dv = dejavu.shaper.extents(vertical(30, Direction::BottomToTop));
    ASSERT_TRUE(dv) << dv.error().message;
    EXPECT_NEAR(dv->ascender_px, 15, 1e-9);
    EXPECT_NEAR(dv->descender_px, -15, 1e-9);
    auto bad = dejavu.shaper.extents(vertical(0));
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().message, "font size 0 px: out of range (0, 16384]");
}

TEST(VerticalLayout, CharactersTheFontLacksAreCounted) {
    Fixture s = open_setup(kCjk);
    const std::string text = "日\xE0\xB8\x81本";   // U+0E01 THAI CHARACTER KO KAI: not in the subset
    const TextLayout l = lay(s, text, vertical(40));
    const MissingGlyphs missing = find_missing_glyphs(l, text);
    EXPECT_EQ(missing.count, 1u);
    EXPECT_EQ(missing.first_code_point, U'\u0E01');
}

}  // namespace
}  // namespace bezel
