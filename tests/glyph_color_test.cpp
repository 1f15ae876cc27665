// Tests of colour glyphs through the one glyph path: GlyphRasterizer boxes and draws COLR paints
// and bitmap strikes into premultiplied RGBA, draw() gives their alpha, outline glyphs drawn into
// RGBA are coverage times the foreground, and GlyphCache keys on the colour options.
//
// Fonts: test_glyphs-glyf_colr_1.ttf (googlefonts/color-fonts: one COLRv1 feature per glyph,
// 1000 units per em, 3 palettes), twemoji_smiley (COLRv1 and sbix forms of one emoji), the Noto
// Color Emoji subset (CBDT, U+1F600) and DejaVu Sans (outlines).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "bezel/text.hpp"

namespace bezel {
namespace {

const std::string kFonts = BEZEL_FONTS_DIR;
const std::string kTestGlyphs = kFonts + "/colour/test_glyphs-glyf_colr_1.ttf";
const std::string kSmileyColr = kFonts + "/colour/twemoji_smiley-glyf_colr_1.ttf";
const std::string kSmileySbix = kFonts + "/colour/twemoji_smiley-sbix.ttf";
const std::string kCbdt = kFonts + "/noto-color-emoji/NotoColorEmoji-subset.ttf";
const std::string kDejaVu = kFonts + "/dejavu-sans/DejaVuSans.ttf";

Font open(const std::string& file) {
    auto font = Font::open(file);
    if (!font) {
        ADD_FAILURE() << font.error().message;
        std::abort();
    }
    return std::move(font).value();
}

GlyphId gid_of(Font& font, char32_t c) {
    auto gid = font.glyph_for_char(c);
    EXPECT_TRUE(gid) << "U+" << std::hex << static_cast<unsigned>(c);
    return gid.value_or(0);
}

// A drawn glyph's premultiplied pixels.
struct Rgba {
    int width = 0, height = 0;
    std::vector<std::uint8_t> px;
    RgbaView view() { return {px.data(), width, height, 4 * std::ptrdiff_t{width}}; }
    const std::uint8_t* at(int x, int y) const {
        return px.data() + 4 * (static_cast<std::size_t>(y) * width + x);
    }
};

Rgba draw_rgba(GlyphRasterizer& r, const PreparedGlyph& g) {
    Rgba out{g.box.width, g.box.height,
             std::vector<std::uint8_t>(4 * static_cast<std::size_t>(g.box.width) * g.box.height, 7)};
    Status drawn = r.draw_rgba(g, out.view());
    EXPECT_TRUE(drawn) << drawn.error().message;
    return out;
}

// Pixels whose colour is not a gray (r, g, b not all equal) with some alpha.
int coloured(const Rgba& img) {
    int n = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const std::uint8_t* p = img.at(x, y);
            if (p[3] > 0 && (p[0] != p[1] || p[1] != p[2])) ++n;
        }
    return n;
}

bool premultiplied(const Rgba& img) {
    for (std::size_t i = 0; i < img.px.size(); i += 4)
        if (img.px[i] > img.px[i + 3] || img.px[i + 1] > img.px[i + 3] ||
            img.px[i + 2] > img.px[i + 3])
            return false;
    return true;
}

TEST(GlyphColor, AColrGlyphIsBoxedAroundItsPaintAndDrawnInColour) {
    Font font = open(kTestGlyphs);
    GlyphRasterizer r(font);
    const GlyphId gid = gid_of(font, 0xF0E01);   // colored_circles_v1
    GlyphRenderOptions o;
    o.size_px = 64;
    EXPECT_TRUE(r.is_color(gid, o.color));
    auto g = r.prepare(gid, o);
    ASSERT_TRUE(g) << g.error().message;
    ASSERT_TRUE(g->box.color);
    ASSERT_TRUE(g->paint);
    EXPECT_GT(g->box.width, 8);
    EXPECT_GT(g->box.height, 8);
    // Its box holds what its paint can ink, mapped to pixels at 64 px per 1000 units, y down.
    const Rect bounds = paint_bounds(*g->paint);
    const double s = 64.0 / 1000;
    EXPECT_EQ(g->box.left, static_cast<int>(std::floor(bounds.x0 * s)));
    EXPECT_EQ(g->box.top, static_cast<int>(std::ceil(bounds.y1 * s)));
    const Rgba img = draw_rgba(r, *g);
    EXPECT_TRUE(premultiplied(img));
    EXPECT_GT(coloured(img), g->box.width * g->box.height / 8);
    // draw() gives the same glyph's alpha as coverage.
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(g->box.width) * g->box.height);
    ASSERT_TRUE(r.draw(*g, MaskView{mask.data(), g->box.width, g->box.height, g->box.width}));
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            ASSERT_EQ(mask[static_cast<std::size_t>(y) * img.width + x], img.at(x, y)[3]);
}

TEST(GlyphColor, WithColourOffAColrGlyphIsItsOwnOutlineMask) {
    Font font = open(kTestGlyphs);
    GlyphRasterizer r(font);
    const GlyphId gid = gid_of(font, 0xF0E01);
    GlyphRenderOptions o;
    o.size_px = 64;
    o.color.enabled = false;
    EXPECT_FALSE(r.is_color(gid, o.color));
    auto g = r.prepare(gid, o);
    ASSERT_TRUE(g) << g.error().message;
    EXPECT_FALSE(g->box.color);
    EXPECT_FALSE(g->paint);
}

TEST(GlyphColor, AnOutlineGlyphInRgbaIsCoverageTimesTheForeground) {
    Font font = open(kDejaVu);
    GlyphRasterizer r(font);
    GlyphRenderOptions o;
    o.size_px = 20;
    o.offset_px = {0.25, 0};
    o.color.foreground = {200, 100, 50, 255};
    const GlyphId gid = gid_of(font, U'a');
    EXPECT_FALSE(r.is_color(gid, o.color));
    auto g = r.prepare(gid, o);
    ASSERT_TRUE(g);
    ASSERT_FALSE(g->box.color);
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(g->box.width) * g->box.height);
    ASSERT_TRUE(r.draw(*g, MaskView{mask.data(), g->box.width, g->box.height, g->box.width}));
    const Rgba img = draw_rgba(r, *g);
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const unsigned cov = mask[static_cast<std::size_t>(y) * img.width + x];
            const std::uint8_t* p = img.at(x, y);
            ASSERT_EQ(p[3], cov);
            ASSERT_EQ(p[0], (200 * cov + 127) / 255);
            ASSERT_EQ(p[1], (100 * cov + 127) / 255);
            ASSERT_EQ(p[2], (50 * cov + 127) / 255);
        }
}

TEST(GlyphColor, APaletteAndCustomEntriesChangeTheColours) {
    Font font = open(kTestGlyphs);
    GlyphRasterizer r(font);
    const GlyphId gid = gid_of(font, 0xF0E01);
    GlyphRenderOptions o;
    o.size_px = 48;
    auto first = r.prepare(gid, o);
    o.color.palette.palette = 1;
    auto second = r.prepare(gid, o);
    ASSERT_TRUE(first && second);
    EXPECT_NE(draw_rgba(r, *first).px, draw_rgba(r, *second).px);
    o.color.palette.palette = 0;
    o.color.palette.custom = {{0, {0, 0, 255, 255}}, {1, {0, 0, 255, 255}}, {2, {0, 0, 255, 255}},
                              {3, {0, 0, 255, 255}}, {4, {0, 0, 255, 255}}, {5, {0, 0, 255, 255}},
                              {6, {0, 0, 255, 255}}, {7, {0, 0, 255, 255}}, {8, {0, 0, 255, 255}},
                              {9, {0, 0, 255, 255}}, {10, {0, 0, 255, 255}},
                              {11, {0, 0, 255, 255}}, {12, {0, 0, 255, 255}},
                              {13, {0, 0, 255, 255}}};
    auto blue = r.prepare(gid, o);
    ASSERT_TRUE(blue) << blue.error().message;
    const Rgba img = draw_rgba(r, *blue);
    // Every entry is opaque blue: whatever is inked is blue (red and green stay 0).
    int inked = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const std::uint8_t* p = img.at(x, y);
            if (p[3] == 0) continue;
            ++inked;
            ASSERT_EQ(p[0], 0);
            ASSERT_EQ(p[1], 0);
            ASSERT_EQ(p[2], p[3]);
        }
    EXPECT_GT(inked, 100);
    o.color.palette.custom = {{14, {0, 0, 255, 255}}};
    auto past = r.prepare(gid, o);
    ASSERT_FALSE(past);
    EXPECT_NE(past.error().message.find("14"), std::string::npos);
}

TEST(GlyphColor, TheForegroundEntryTakesTheTextColour) {
    Font font = open(kTestGlyphs);
    GlyphRasterizer r(font);
    const GlyphId gid = gid_of(font, 0xF0B06);   // foreground_color_solid_alpha_1
    GlyphRenderOptions o;
    o.size_px = 32;
    o.color.foreground = {255, 0, 0, 255};
    auto red = r.prepare(gid, o);
    ASSERT_TRUE(red) << red.error().message;
    ASSERT_TRUE(red->paint && red->paint->uses_foreground);
    const Rgba img = draw_rgba(r, *red);
    int opaque_red = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const std::uint8_t* p = img.at(x, y);
            if (p[3] == 255 && p[0] == 255 && p[1] == 0 && p[2] == 0) ++opaque_red;
        }
    EXPECT_GT(opaque_red, 50);
}

TEST(GlyphColor, TheCacheKeysOnPaletteAndOnTheForegroundOnlyWhereItIsUsed) {
    Font font = open(kTestGlyphs);
    GlyphRasterizer r(font);
    GlyphCache cache;
    GlyphRenderOptions o;
    o.size_px = 32;
    const GlyphId circles = gid_of(font, 0xF0E01), fg_glyph = gid_of(font, 0xF0B06);
    ASSERT_TRUE(cache.get(r, circles, o));
    o.color.palette.palette = 1;
    ASSERT_TRUE(cache.get(r, circles, o));
    EXPECT_EQ(cache.stats().misses, 2u);
    o.color.palette.palette = 0;
    ASSERT_TRUE(cache.get(r, circles, o));
    EXPECT_EQ(cache.stats().hits, 1u);
    // Another text colour: the palette-only glyph is a hit, the foreground glyph is repainted.
    o.color.foreground = {0, 0, 255, 255};
    ASSERT_TRUE(cache.get(r, circles, o));
    EXPECT_EQ(cache.stats().hits, 2u);
    auto blue = cache.get(r, fg_glyph, o);
    ASSERT_TRUE(blue);
    const std::vector<std::uint8_t> blue_px((*blue)->rgba.data,
                                            (*blue)->rgba.data + 4 * (*blue)->box.width *
                                                                     (*blue)->box.height);
    o.color.foreground = {255, 0, 0, 255};
    auto red = cache.get(r, fg_glyph, o);
    ASSERT_TRUE(red);
    const std::vector<std::uint8_t> red_px((*red)->rgba.data,
                                           (*red)->rgba.data + 4 * (*red)->box.width *
                                                                   (*red)->box.height);
    EXPECT_NE(blue_px, red_px);
    EXPECT_EQ(cache.stats().misses, 4u);
}

// A bitmap strike scaled to the size: its box is the strike's scaled, and it is coloured.
void expect_bitmap_glyph(const std::string& file, char32_t c, double size_px) {
    Font font = open(file);
    GlyphRasterizer r(font);
    const GlyphId gid = gid_of(font, c);
    GlyphRenderOptions o;
    o.size_px = size_px;
    auto g = r.prepare(gid, o);
    ASSERT_TRUE(g) << g.error().message;
    ASSERT_TRUE(g->box.color);
    ASSERT_TRUE(g->bitmap);
    const double k = size_px / g->bitmap->strike_px;
    EXPECT_NEAR(g->box.width, g->bitmap->width * k, 1.0);
    EXPECT_NEAR(g->box.height, g->bitmap->height * k, 1.0);
    EXPECT_NEAR(g->box.left, g->bitmap->left * k, 1.0);
    EXPECT_NEAR(g->box.top, g->bitmap->top * k, 1.0);
    EXPECT_NEAR(g->box.advance_px, g->bitmap->advance_px * k, 1e-9);
    const Rgba img = draw_rgba(r, *g);
    EXPECT_TRUE(premultiplied(img));
    EXPECT_GT(coloured(img), g->box.width * g->box.height / 3);
}

TEST(GlyphColor, CbdtBitmapsAreScaledToTheSize) {
    expect_bitmap_glyph(kCbdt, 0x1F600, 32);
    expect_bitmap_glyph(kCbdt, 0x1F600, 16);
}

TEST(GlyphColor, SbixBitmapsAreScaledToTheSize) {
    expect_bitmap_glyph(kSmileySbix, 0x1F601, 40);
}

TEST(GlyphColor, TheColrAndSbixFormsOfOneEmojiAgree) {
    // The same Twitter emoji in two formats: drawn at one size, their boxes nearly coincide and
    // their mean colours are close (a yellow face).
    Font colr = open(kSmileyColr), sbix = open(kSmileySbix);
    GlyphRasterizer rc(colr), rs(sbix);
    GlyphRenderOptions o;
    o.size_px = 64;
    auto a = rc.prepare(gid_of(colr, 0x1F601), o);
    auto b = rs.prepare(gid_of(sbix, 0x1F601), o);
    ASSERT_TRUE(a && b);
    EXPECT_NEAR(a->box.width, b->box.width, 4);
    EXPECT_NEAR(a->box.height, b->box.height, 4);
    EXPECT_NEAR(a->box.left, b->box.left, 3);
    EXPECT_NEAR(a->box.top, b->box.top, 3);
    auto mean = [](const Rgba& img, int channel) {
        double sum = 0, alpha = 0;
        for (std::size_t i = 0; i < img.px.size(); i += 4) {
            sum += img.px[i + channel];
            alpha += img.px[i + 3];
        }
        return alpha > 0 ? sum / alpha : 0.0;   // un-premultiplied mean
    };
    const Rgba ia = draw_rgba(rc, *a), ib = draw_rgba(rs, *b);
    for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(mean(ia, ch), mean(ib, ch), 0.08) << ch;
}

}  // namespace
}  // namespace bezel
