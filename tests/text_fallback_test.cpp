// Tests of font fallback: FontCollection, layout_text over a collection, TextRenderer over one.
//
// Coverage of the fonts used (from their cmaps): Cantarell has Latin but no Arabic, Hebrew or
// Devanagari; DejaVu Sans has Latin, Arabic, Hebrew, U+20D7 (a combining arrow) and a text
// (monochrome) U+1F600; the Noto fonts have their script, spaces, digits and ZWJ; the Noto Color
// Emoji subset has U+1F600 only (colour bitmaps).
#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "bezel/text.hpp"

namespace bezel {
namespace {

const std::string kFonts = BEZEL_FONTS_DIR;
const std::string kCantarell = kFonts + "/cantarell/Cantarell-Regular.otf";
const std::string kDejaVu = kFonts + "/dejavu-sans/DejaVuSans.ttf";
const std::string kArabic = kFonts + "/noto-arabic/NotoSansArabic-Regular.ttf";
const std::string kHebrew = kFonts + "/noto-hebrew/NotoSansHebrew-Regular.ttf";
const std::string kDevanagari = kFonts + "/noto-devanagari/NotoSansDevanagari-Regular.ttf";
const std::string kEmoji = kFonts + "/noto-color-emoji/NotoColorEmoji-subset.ttf";

FontCollection open_fonts(const std::vector<std::string>& files) {
    std::vector<FontSource> sources;
    for (const std::string& f : files) sources.push_back({f, 0, {}});
    auto fonts = FontCollection::open(sources);
    if (!fonts) {
        ADD_FAILURE() << fonts.error().message;
        std::abort();
    }
    return std::move(fonts).value();
}

TextLayout lay(FontCollection& fonts, std::string_view text, double size_px = 20) {
    ShapeOptions shape;
    shape.size_px = size_px;
    auto r = layout_text(fonts, text, shape, LayoutOptions{});
    if (!r) {
        ADD_FAILURE() << r.error().message;
        return {};
    }
    return std::move(r).value();
}

// The set of fonts whose glyphs carry each cluster (byte offset).
std::map<std::uint32_t, std::set<int>> fonts_by_cluster(const TextLayout& l) {
    std::map<std::uint32_t, std::set<int>> out;
    for (const PlacedGlyph& g : l.glyphs) out[g.cluster].insert(g.font);
    return out;
}

// The one font drawing the text at byte `offset` (the cluster starting there).
int font_at(const TextLayout& l, std::uint32_t offset) {
    auto by = fonts_by_cluster(l);
    auto it = by.find(offset);
    if (it == by.end() || it->second.size() != 1) {
        ADD_FAILURE() << "no single font at byte " << offset;
        return -1;
    }
    return *it->second.begin();
}

TEST(FontFallback, EachScriptComesFromTheFirstFontThatCoversIt) {
    FontCollection fonts = open_fonts({kCantarell, kArabic, kHebrew, kDevanagari});
    const std::string text = "Hi \u0645\u0631\u062D\u0628\u0627 \u05E9\u05DC\u05D5\u05DD \u0928\u092E\u0938\u094D\u0924\u0947";
    TextLayout l = lay(fonts, text);
    EXPECT_EQ(font_at(l, 0), 0);                                   // H
    EXPECT_EQ(font_at(l, text.find("\u0645")), 1);                 // Arabic
    EXPECT_EQ(font_at(l, text.find("\u05E9")), 2);                 // Hebrew
    EXPECT_EQ(font_at(l, text.find("\u0928")), 3);                 // Devanagari
    for (const PlacedGlyph& g : l.glyphs) EXPECT_NE(g.gid, 0u) << "cluster " << g.cluster;
    EXPECT_EQ(find_missing_glyphs(l, text).count, 0u);
}

TEST(FontFallback, ListOrderDecidesBetweenFontsThatBothCover) {
    const std::string text = "A\u0627\u0644\u0639\u0631\u0628\u064A\u0629";
    FontCollection dejavu_first = open_fonts({kCantarell, kDejaVu, kArabic});
    FontCollection noto_first = open_fonts({kCantarell, kArabic, kDejaVu});
    EXPECT_EQ(font_at(lay(dejavu_first, text), 1), 1);
    EXPECT_EQ(font_at(lay(noto_first, text), 1), 1);
    // The Arabic glyphs are the listed font's: their ids differ between the two fonts.
    const TextLayout a = lay(dejavu_first, text), b = lay(noto_first, text);
    ASSERT_EQ(a.glyphs.size(), b.glyphs.size());
    EXPECT_EQ(dejavu_first.source(1).file, kDejaVu);
    EXPECT_EQ(noto_first.source(1).file, kArabic);
    bool differ = false;
    for (std::size_t i = 0; i < a.glyphs.size(); ++i) differ |= a.glyphs[i].gid != b.glyphs[i].gid;
    EXPECT_TRUE(differ);
}

TEST(FontFallback, ABaseAndItsMarkAreNeverSplitAcrossFonts) {
    // Cantarell has "a" but not U+20D7; DejaVu has both: the whole cluster moves to DejaVu.
    FontCollection fonts = open_fonts({kCantarell, kDejaVu});
    const std::string text = "xa\u20D7y";
    TextLayout l = lay(fonts, text);
    EXPECT_EQ(font_at(l, 0), 0);
    EXPECT_EQ(font_at(l, 1), 1);   // a + U+20D7, one cluster, one font
    EXPECT_EQ(font_at(l, static_cast<std::uint32_t>(text.size() - 1)), 0);

    // No font has "a" + U+0952 together: the cluster stays whole in the first font, whose
    // .notdef draws the mark, rather than splitting it.
    FontCollection none = open_fonts({kCantarell, kDevanagari});
    const std::string marked = "a\u0952";
    TextLayout m = lay(none, marked);
    EXPECT_EQ(font_at(m, 0), 0);
    // One .notdef, in the cluster that starts at the "a" (HarfBuzz merges a mark's cluster).
    EXPECT_EQ(find_missing_glyphs(m, marked).count, 1u);
    EXPECT_EQ(find_missing_glyphs(m, marked).first_cluster, 0u);
}

TEST(FontFallback, SpacesAndDigitsStayInThePreviousFontWhenItHasThem) {
    FontCollection fonts = open_fonts({kCantarell, kArabic});
    const std::string text = "\u0645\u0631\u062D\u0628\u0627 \u0628\u0643, 12";
    TextLayout l = lay(fonts, text);
    // Every glyph, the space, comma and digits included, from the Arabic font: one font run.
    for (const PlacedGlyph& g : l.glyphs) EXPECT_EQ(g.font, 1) << "cluster " << g.cluster;
    // After Latin the same characters stay Latin.
    const std::string latin = "ab, 12";
    for (const PlacedGlyph& g : lay(fonts, latin).glyphs) EXPECT_EQ(g.font, 0);
}

TEST(FontFallback, EmojiPresentationPrefersAColourFontAndVs15AskesForText) {
    // Layout only: the colour font has no outlines to render yet, but HarfBuzz shapes it.
    FontCollection fonts = open_fonts({kDejaVu, kEmoji});
    EXPECT_TRUE(fonts.is_colour(1));
    EXPECT_FALSE(fonts.is_colour(0));
    // U+1F600 has Emoji_Presentation: the colour font, though DejaVu (first) has it too.
    EXPECT_EQ(font_at(lay(fonts, "a\U0001F600"), 1), 1);
    // With VS16 likewise; with VS15 (text presentation) DejaVu's monochrome glyph.
    EXPECT_EQ(font_at(lay(fonts, "a\U0001F600\uFE0F"), 1), 1);
    EXPECT_EQ(font_at(lay(fonts, "a\U0001F600\uFE0E"), 1), 0);
    // Without a colour font in the list, the emoji is simply the first font's.
    FontCollection plain = open_fonts({kCantarell, kDejaVu});
    EXPECT_EQ(font_at(lay(plain, "a\U0001F600"), 1), 1);
}

TEST(FontFallback, MissingEverywhereIsTheFirstFontsNotdefAndCounted) {
    FontCollection fonts = open_fonts({kCantarell, kArabic});
    const std::string text = "a\u4E00b\u4E8C";
    TextLayout l = lay(fonts, text);
    const MissingGlyphs missing = find_missing_glyphs(l, text);
    EXPECT_EQ(missing.count, 2u);
    EXPECT_EQ(missing.first_code_point, U'\u4E00');
    EXPECT_EQ(font_at(l, 1), 0);
}

TEST(FontFallback, ALineUsingATallerFontGrowsAndOtherLinesKeepTheFirstFontsSpacing) {
    // EdgeCases.ttf: ascender 0.8 em, descender -0.2 em, no gap; Noto Devanagari is taller.
    FontCollection fonts = open_fonts({kFonts + "/edge-cases/EdgeCases.ttf", kDevanagari});
    const FontMetrics latin = fonts.metrics(0), deva = fonts.metrics(1);
    const double size = 20;
    const double latin_ascent = latin.ascender * size / latin.units_per_em;
    const double deva_ascent = deva.ascender * size / deva.units_per_em;
    const double deva_descent = -deva.descender * size / deva.units_per_em;
    const double latin_descent = -latin.descender * size / latin.units_per_em;
    ASSERT_GT(deva_ascent, latin_ascent);   // the test needs a taller fallback font
    TextLayout l = lay(fonts, "AB\n\u0928\u092E\nBA\nAA", size);
    ASSERT_EQ(l.lines.size(), 4u);
    EXPECT_NEAR(l.lines[0].ascent_px, latin_ascent, 1e-9);
    EXPECT_NEAR(l.lines[1].ascent_px, deva_ascent, 1e-9);
    EXPECT_NEAR(l.lines[1].descent_px, std::max(deva_descent, latin_descent), 1e-9);
    EXPECT_NEAR(l.lines[0].baseline_y_px, latin_ascent, 1e-9);
    const double latin_gap = std::max(0.0, latin.line_gap * size / latin.units_per_em);
    const double deva_gap = std::max(0.0, deva.line_gap * size / deva.units_per_em);
    EXPECT_NEAR(l.lines[1].baseline_y_px - l.lines[0].baseline_y_px,
                latin_descent + latin_gap + deva_ascent, 1e-9);
    EXPECT_NEAR(l.lines[2].baseline_y_px - l.lines[1].baseline_y_px,
                std::max(deva_descent, latin_descent) + std::max(deva_gap, latin_gap) +
                    latin_ascent,
                1e-9);
    const double latin_step = (latin.ascender - latin.descender + latin.line_gap) * size /
                              latin.units_per_em;
    EXPECT_NEAR(l.lines[3].baseline_y_px - l.lines[2].baseline_y_px, latin_step, 1e-9);
    EXPECT_NEAR(l.height_px, l.lines[3].baseline_y_px + latin_descent, 1e-9);
}

TEST(FontFallback, AOneFontCollectionLaysOutExactlyAsTheSingleFontForm) {
    FontCollection fonts = open_fonts({kDejaVu});
    auto font = Font::open(kDejaVu);
    auto shaper = Shaper::open(kDejaVu);
    ASSERT_TRUE(font && shaper);
    const std::string text = "Hello, \u05E9\u05DC\u05D5\u05DD 123\nsecond line \u4E00";
    ShapeOptions shape;
    shape.size_px = 17;
    LayoutOptions layout;
    layout.width_px = 90;
    layout.margin_px = 3;
    auto a = layout_text(fonts, text, shape, layout);
    auto b = layout_text(*shaper, font->metrics(), text, shape, layout);
    ASSERT_TRUE(a && b);
    ASSERT_EQ(a->glyphs.size(), b->glyphs.size());
    for (std::size_t i = 0; i < a->glyphs.size(); ++i) {
        EXPECT_EQ(a->glyphs[i].gid, b->glyphs[i].gid);
        EXPECT_EQ(a->glyphs[i].x_px, b->glyphs[i].x_px);
        EXPECT_EQ(a->glyphs[i].y_px, b->glyphs[i].y_px);
    }
    EXPECT_EQ(a->width_px, b->width_px);
    EXPECT_EQ(a->height_px, b->height_px);
}

// A fallback source that answers from a fixed table, counting its calls.
class TableFallback : public FallbackSource {
public:
    std::map<char32_t, FontSource> table;
    int calls = 0;
    Expected<std::optional<FontSource>> font_for(const FallbackRequest& request) override {
        ++calls;
        auto it = table.find(request.cluster.at(0));
        if (it == table.end()) return std::optional<FontSource>{};
        return std::optional<FontSource>(it->second);
    }
};

TEST(FontFallback, TheFallbackSourceAddsFontsWhereTheListRunsOut) {
    FontCollection fonts = open_fonts({kCantarell});
    auto source = std::make_shared<TableFallback>();
    source->table[U'\u05E9'] = {kHebrew, 0, {}};
    source->table[U'\u05DC'] = {kHebrew, 0, {}};
    source->table[U'\u4E00'] = {kFonts + "/no-such-font.ttf", 0, {}};
    fonts.set_fallback(source);
    const std::string text = "a\u05E9\u05DC\u4E00\u4E00";
    TextLayout l = lay(fonts, text);
    ASSERT_EQ(fonts.size(), 2u);   // the Hebrew font, once
    EXPECT_EQ(fonts.origin(1), FontOrigin::System);
    EXPECT_EQ(fonts.source(1).file, kHebrew);
    EXPECT_EQ(font_at(l, 1), 1);
    EXPECT_EQ(font_at(l, 3), 1);
    // A font the source names that cannot be opened: a warning naming it, the character missing.
    ASSERT_EQ(fonts.warnings().size(), 1u);
    EXPECT_NE(fonts.warnings()[0].find("no-such-font.ttf"), std::string::npos);
    EXPECT_EQ(find_missing_glyphs(l, text).count, 2u);
    // Asked for ש, ל (then the Hebrew font covers ל itself) and once for 一: the second 一 is
    // remembered as unfound.
    EXPECT_EQ(source->calls, 2);
}

// The number of pixels of `page` whose channels differ (colour, not gray).
int colour_pixels(const Image& page) {
    int n = 0;
    for (int y = 0; y < page.height(); ++y)
        for (int x = 0; x < page.width(); ++x) {
            const Rgba8 p = page.at(x, y);
            if (p.r != p.g || p.g != p.b) ++n;
        }
    return n;
}

TEST(FontFallback, AnEmojiInALineIsDrawnFromTheColourFontOfTheList) {
    auto listed = FontCollection::open({{kDejaVu, 0, {}}, {kEmoji, 0, {}}});
    ASSERT_TRUE(listed);
    auto renderer = TextRenderer::open(std::move(*listed));
    ASSERT_TRUE(renderer) << renderer.error().message;
    TextRenderOptions options;
    options.shape.size_px = 32;
    // DejaVu has a monochrome U+1F600 of its own: emoji presentation takes the colour font.
    auto page = renderer->render("ab \U0001F600", options);
    ASSERT_TRUE(page) << page.error().message;
    EXPECT_TRUE(renderer->last_text_has_color());
    EXPECT_EQ(renderer->missing_glyphs().count, 0u);
    EXPECT_GT(colour_pixels(*page), 100);   // a 32-px yellow face
    // A gray page cannot hold it: refused before drawing, and said so.
    auto gray = renderer->render_gray("ab \U0001F600", options);
    ASSERT_FALSE(gray);
    EXPECT_TRUE(renderer->last_text_has_color());
    EXPECT_NE(gray.error().message.find("colour"), std::string::npos);
    // Text without the emoji stays gray.
    auto plain = renderer->render_gray("ab", options);
    ASSERT_TRUE(plain) << plain.error().message;
    EXPECT_FALSE(renderer->last_text_has_color());
}

TEST(FontFallback, WithoutColourGlyphsARendererTakesNoBitmapOnlyFontFromTheFallback) {
    FontCollection fonts = open_fonts({kCantarell});
    auto source = std::make_shared<TableFallback>();
    source->table[U'\U0001F600'] = {kEmoji, 0, {}};
    fonts.set_fallback(source);
    auto renderer = TextRenderer::open(std::move(fonts));
    ASSERT_TRUE(renderer) << renderer.error().message;
    TextRenderOptions options;
    options.color.enabled = false;
    auto page = renderer->render_gray("a\U0001F600", options);
    ASSERT_TRUE(page) << page.error().message;
    EXPECT_EQ(renderer->fonts().size(), 1u);
    ASSERT_EQ(renderer->fonts().warnings().size(), 1u);
    EXPECT_NE(renderer->fonts().warnings()[0].find("bitmap-only"), std::string::npos);
    EXPECT_EQ(renderer->missing_glyphs().count, 1u);
}

TEST(FontFallback, WithColourGlyphsTheFallbackSuppliesTheColourFont) {
    FontCollection fonts = open_fonts({kCantarell});
    auto source = std::make_shared<TableFallback>();
    source->table[U'\U0001F600'] = {kEmoji, 0, {}};
    fonts.set_fallback(source);
    auto renderer = TextRenderer::open(std::move(fonts));
    ASSERT_TRUE(renderer) << renderer.error().message;
    TextRenderOptions options;
    options.shape.size_px = 24;
    auto page = renderer->render("a\U0001F600", options);
    ASSERT_TRUE(page) << page.error().message;
    EXPECT_EQ(renderer->fonts().size(), 2u);
    EXPECT_EQ(renderer->missing_glyphs().count, 0u);
    EXPECT_GT(colour_pixels(*page), 50);
}

TEST(FontFallback, RendererDrawsEachFontsGlyphsAsThatFontAlone) {
    // The Arabic word of a mixed line is drawn with the Arabic font's pixels: rendering the
    // word alone in that font and the line through the collection give the same ink there.
    FontCollection fonts = open_fonts({kCantarell, kArabic});
    auto renderer = TextRenderer::open(std::move(fonts));
    auto alone = TextRenderer::open(kArabic);
    ASSERT_TRUE(renderer && alone);
    TextRenderOptions options;
    options.shape.size_px = 24;
    const std::string word = "\u0645\u0631\u062D\u0628\u0627";
    auto mixed = renderer->render_gray(word, options);
    auto single = alone->render_gray(word, options);
    ASSERT_TRUE(mixed && single);
    // Same width (the same glyphs and advances); the height may differ (line metrics of both).
    ASSERT_EQ(mixed->width(), single->width());
    long ink_mixed = 0, ink_single = 0;
    for (int y = 0; y < mixed->height(); ++y)
        for (int x = 0; x < mixed->width(); ++x) ink_mixed += 255 - mixed->at(x, y);
    for (int y = 0; y < single->height(); ++y)
        for (int x = 0; x < single->width(); ++x) ink_single += 255 - single->at(x, y);
    EXPECT_EQ(ink_mixed, ink_single);
    EXPECT_GT(ink_mixed, 0);
}

TEST(FontFallback, CoversIgnoresDefaultIgnorableCharacters) {
    FontCollection fonts = open_fonts({kCantarell, kArabic});
    const std::u32string lam_alef = U"\u0644\u0627";
    EXPECT_FALSE(fonts.covers(0, lam_alef.data(), lam_alef.size()));
    EXPECT_TRUE(fonts.covers(1, lam_alef.data(), lam_alef.size()));
    // ZWJ and VS16 need no glyph: Cantarell lacks them and still covers "a" + ZWJ + VS16.
    const std::u32string joined = U"a\u200D\uFE0F";
    EXPECT_TRUE(fonts.covers(0, joined.data(), joined.size()));
    const std::u32string unmapped = U"a\u4E00";
    EXPECT_FALSE(fonts.covers(0, unmapped.data(), unmapped.size()));
}

TEST(FontFallback, BadListsAreErrorsNamingTheFile) {
    auto empty = FontCollection::open({});
    ASSERT_FALSE(empty);
    EXPECT_NE(empty.error().message.find("empty"), std::string::npos);
    auto missing = FontCollection::open({{kDejaVu, 0, {}}, {kFonts + "/nope.ttf", 0, {}}});
    ASSERT_FALSE(missing);
    EXPECT_NE(missing.error().message.find("nope.ttf"), std::string::npos);
    auto axis = FontCollection::open({{kDejaVu, 0, {{"wght", 500}}}});
    ASSERT_FALSE(axis);
    EXPECT_NE(axis.error().message.find("DejaVuSans.ttf"), std::string::npos);
    std::vector<FontSource> many(kMaxCollectionFonts + 1, FontSource{kDejaVu, 0, {}});
    auto too_many = FontCollection::open(many);
    ASSERT_FALSE(too_many);
    EXPECT_NE(too_many.error().message.find(std::to_string(kMaxCollectionFonts)), std::string::npos);
}

}  // namespace
}  // namespace bezel
