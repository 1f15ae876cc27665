// Tests of bezel/color_glyph.hpp: COLR paint graphs, CPAL palettes, CBDT and sbix bitmaps.
//
// Expected values come from the fonts' tables as fontTools reads them (glyph names and values of
// googlefonts/color-fonts' config/test_glyphs-glyf_colr_1.py; tests/data/colour/
// make_bad_colr_fonts.py for the small fonts), with the table's fixed-point quantization applied:
// an F2Dot14 v is stored as round(v·2¹⁴)/2¹⁴, a Fixed as round(v·2¹⁶)/2¹⁶.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <variant>

#include "bezel/color_glyph.hpp"
#include "bezel/limits.hpp"

namespace bezel {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string font_path(const std::string& name) { return std::string(BEZEL_FONTS_DIR) + "/" + name; }
std::string data_path(const std::string& name) {
    return std::string(BEZEL_SOURCE_DIR) + "/tests/data/colour/" + name;
}
Font open_font(const std::string& file) {
    auto f = Font::open(file);
    if (!f) ADD_FAILURE() << f.error().message;
    return std::move(*f);
}
Font test_glyphs() { return open_font(font_path("colour/test_glyphs-glyf_colr_1.ttf")); }

double f2dot14(double v) { return std::round(v * 16384) / 16384; }
double fixed(double v) { return std::round(v * 65536) / 65536; }

template <typename T>
const T& node(const ColorGlyph& g, PaintIndex i) {
    EXPECT_LT(i, g.nodes.size());
    EXPECT_TRUE(std::holds_alternative<T>(g.nodes.at(i))) << "node " << i << " holds variant " << g.nodes.at(i).index();
    return std::get<T>(g.nodes.at(i));
}

ColorGlyph load(Font& font, GlyphId gid, const ColorGlyphOptions& options = {}) {
    auto g = load_color_glyph(font, gid, options);
    if (!g) {
        ADD_FAILURE() << g.error().message;
        return {};
    }
    return std::move(*g);
}

// The transform of a "<op>_…" test glyph: PaintComposite(dest_over) whose source is
// PaintTransform(PaintGlyph(cross_glyph)).
Affine composite_source_transform(Font& font, GlyphId gid) {
    const ColorGlyph g = load(font, gid);
    const auto& composite = node<PaintComposite>(g, g.root);
    EXPECT_EQ(composite.mode, CompositeMode::DestOver);
    return node<PaintTransform>(g, composite.source).transform;
}

void expect_affine_near(const Affine& got, const Affine& want, double tolerance = 1e-12) {
    EXPECT_NEAR(got.a, want.a, tolerance);
    EXPECT_NEAR(got.b, want.b, tolerance);
    EXPECT_NEAR(got.c, want.c, tolerance);
    EXPECT_NEAR(got.d, want.d, tolerance);
    EXPECT_NEAR(got.e, want.e, tolerance * 1000);
    EXPECT_NEAR(got.f, want.f, tolerance * 1000);
}

ColorF rgb(int r, int g, int b) { return {r / 255.0f, g / 255.0f, b / 255.0f, 1.0f}; }

TEST(ColorTables, TestGlyphsFontHasColrBothVersionsAndCpal) {
    Font f = test_glyphs();
    const ColorTables t = color_tables(f);
    EXPECT_TRUE(t.colr_v1);
    EXPECT_TRUE(t.colr_v0);   // colored_circles_v0
    EXPECT_TRUE(t.cpal);
    EXPECT_FALSE(t.cbdt);
    EXPECT_FALSE(t.sbix);
    EXPECT_FALSE(t.svg);
}

TEST(ColorFormat, EachGlyphReportsItsTable) {
    Font f = test_glyphs();
    EXPECT_EQ(color_format(f, 9), ColorFormat::ColrV1);     // linear_repeat_0.2_0.8
    EXPECT_EQ(color_format(f, 168), ColorFormat::ColrV0);   // colored_circles_v0
    EXPECT_EQ(color_format(f, 3), ColorFormat::None);       // cross_glyph: an outline only
    EXPECT_EQ(color_format(f, 100000), ColorFormat::None);
    Font noto = open_font(font_path("noto-color-emoji/NotoColorEmoji-subset.ttf"));
    EXPECT_EQ(color_format(noto, 1), ColorFormat::Bitmap);
    EXPECT_EQ(color_format(noto, 0), ColorFormat::None);    // .notdef: an empty image
    Font sbix = open_font(font_path("colour/twemoji_smiley-sbix.ttf"));
    EXPECT_EQ(color_format(sbix, 2), ColorFormat::Bitmap);
    EXPECT_STREQ(color_format_name(ColorFormat::ColrV1), "COLRv1");
    EXPECT_STREQ(color_format_name(ColorFormat::Bitmap), "bitmap");
    EXPECT_STREQ(color_format_name(ColorFormat::Svg), "SVG");
}

TEST(ColorFormat, SvgGlyphIsReportedNotDrawn) {
    Font f = open_font(data_path("svg.ttf"));
    EXPECT_TRUE(color_tables(f).svg);
    EXPECT_FALSE(color_tables(f).colr_v1);
    EXPECT_EQ(color_format(f, 3), ColorFormat::Svg);    // "drawn", the SVG document's glyph
    EXPECT_EQ(color_format(f, 1), ColorFormat::None);   // square: not in the document index
    EXPECT_FALSE(load_color_glyph(f, 3, {}).ok());
}

TEST(Palettes, TestGlyphsPalettesHaveTheirEntriesAndTypeFlags) {
    Font f = test_glyphs();
    const std::vector<Palette> p = palettes(f);
    ASSERT_EQ(p.size(), 3u);
    for (const Palette& palette : p) EXPECT_EQ(palette.entries.size(), 14u);
    EXPECT_EQ(p[0].entries[0], (Rgba8{0xFF, 0x00, 0x00, 0xFF}));
    EXPECT_EQ(p[0].entries[13], (Rgba8{0x80, 0x80, 0x80, 0xFF}));
    EXPECT_EQ(p[1].entries[0], (Rgba8{0x2A, 0x29, 0x4A, 0xFF}));
    EXPECT_EQ(p[2].entries[0], (Rgba8{0xFC, 0x71, 0x18, 0xFF}));
    // CPAL paletteTypes 0, 2 (dark background), 1 (light background).
    EXPECT_FALSE(p[0].for_light_background || p[0].for_dark_background);
    EXPECT_TRUE(p[1].for_dark_background && !p[1].for_light_background);
    EXPECT_TRUE(p[2].for_light_background && !p[2].for_dark_background);
}

TEST(ColrV1, LinearGradientHasTheTablesPointsStopsAndClip) {
    Font f = test_glyphs();
    const ColorGlyph g = load(f, 9);   // linear_repeat_0.2_0.8
    const auto& glyph = node<PaintGlyph>(g, g.root);
    const auto& lg = node<PaintLinearGradient>(g, glyph.paint);
    EXPECT_EQ(lg.p0, (Point{100, 250}));
    EXPECT_EQ(lg.p1, (Point{900, 250}));
    EXPECT_EQ(lg.p2, (Point{100, 300}));
    EXPECT_EQ(lg.line.extend, Extend::Repeat);
    ASSERT_EQ(lg.line.stops.size(), 2u);
    EXPECT_FLOAT_EQ(lg.line.stops[0].offset, float(f2dot14(0.2)));
    EXPECT_FLOAT_EQ(lg.line.stops[1].offset, float(f2dot14(0.8)));
    EXPECT_EQ(lg.line.stops[0].color.color, rgb(0xFF, 0, 0));   // palette 0, entry 0
    EXPECT_EQ(lg.line.stops[1].color.color, rgb(0, 0, 0xFF));   // entry 4
    EXPECT_FLOAT_EQ(lg.line.stops[1].color.alpha, 1.0f);
    EXPECT_FALSE(g.uses_foreground);
    ASSERT_TRUE(g.clip.has_value());
    EXPECT_EQ(*g.clip, (Rect{100, 250, 900, 950}));
    EXPECT_EQ(g.outlines.size(), 1u);
}

TEST(ColrV1, SweepAnglesAreUnbiasedIntoDegrees) {
    Font f = test_glyphs();
    const ColorGlyph g = load(f, 13);   // sweep_60_300_pad_narrow
    const auto& sg = node<PaintSweepGradient>(g, node<PaintGlyph>(g, g.root).paint);
    // Stored as F2Dot14 (degrees / 180 − 1).
    EXPECT_DOUBLE_EQ(sg.start_deg, (f2dot14(60.0 / 180 - 1) + 1) * 180);
    EXPECT_DOUBLE_EQ(sg.end_deg, (f2dot14(300.0 / 180 - 1) + 1) * 180);
    EXPECT_EQ(sg.center, (Point{500, 600}));
    EXPECT_EQ(sg.line.extend, Extend::Pad);
    EXPECT_EQ(sg.line.stops.size(), 4u);
}

TEST(ColrV1, RadialGradientHasBothCircles) {
    Font f = test_glyphs();
    const ColorGlyph g = load(f, 95);   // radial_contained_gradient_extend_mode_reflect
    const auto& rg = node<PaintRadialGradient>(g, node<PaintGlyph>(g, g.root).paint);
    EXPECT_EQ(rg.c0, (Point{166, 768}));
    EXPECT_EQ(rg.c1, (Point{166, 768}));
    EXPECT_EQ(rg.r0, 0);
    EXPECT_EQ(rg.r1, 256);
    EXPECT_EQ(rg.line.extend, Extend::Reflect);
    EXPECT_EQ(rg.line.stops.size(), 3u);
}

TEST(ColrV1, RotateIsTheSpecsCounterClockwiseMatrix) {
    Font f = test_glyphs();
    const double t = f2dot14(10.0 / 180) * kPi;   // rotate_10_center_0_0
    expect_affine_near(composite_source_transform(f, 99), {std::cos(t), std::sin(t), -std::sin(t), std::cos(t), 0, 0});
    // rotate_25_center_500.0_500.0: T(c)·R·T(−c).
    const double u = f2dot14(25.0 / 180) * kPi, c = std::cos(u), s = std::sin(u);
    expect_affine_near(composite_source_transform(f, 101),
                       {c, s, -s, c, 500 - 500 * c + 500 * s, 500 - 500 * s - 500 * c});
}

TEST(ColrV1, SkewTurnsTheAxesCounterClockwiseAboutTheCentre) {
    Font f = test_glyphs();
    // skew_-10_20_center_500.0_500.0: x' = x + tan(−x_angle)·y, y' = tan(y_angle)·x + y.
    const double kx = std::tan(-f2dot14(-10.0 / 180) * kPi), ky = std::tan(f2dot14(20.0 / 180) * kPi);
    expect_affine_near(composite_source_transform(f, 107), {1, ky, kx, 1, -500 * kx, -500 * ky});
    // skew_25_0_center_0_0: the y axis leans left.
    const double k25 = std::tan(-f2dot14(25.0 / 180) * kPi);
    expect_affine_near(composite_source_transform(f, 103), {1, 0, k25, 1, 0, 0});
    EXPECT_LT(k25, 0);
}

TEST(ColrV1, ScaleTranslateAndMatrixBecomeOneAffineEach) {
    Font f = test_glyphs();
    // scale_0.5_1.5_center_500.0_500.0
    expect_affine_near(composite_source_transform(f, 84), {0.5, 0, 0, 1.5, 250, -250});
    // scale_1.5_1.5_center_0_0 (a uniform scale)
    expect_affine_near(composite_source_transform(f, 87), {1.5, 0, 0, 1.5, 0, 0});
    // translate_200_200
    expect_affine_near(composite_source_transform(f, 118), {1, 0, 0, 1, 200, 200});
    // transform_matrix_1.0_0.0_0.6_1.0_-300.0_0.0: Affine2x3 xx yx xy yy dx dy in 16.16.
    expect_affine_near(composite_source_transform(f, 112), {1, 0, fixed(0.6), 1, -300, 0});
}

TEST(ColrV1, EveryCompositeModeIsReadInTheSpecsOrder) {
    Font f = test_glyphs();
    // composite_CLEAR … composite_HSL_LUMINOSITY are glyphs 120 … 147: a PaintColrLayers whose
    // second layer is the PaintComposite of that mode.
    for (int mode = 0; mode < kCompositeModeCount; ++mode) {
        const ColorGlyph g = load(f, static_cast<GlyphId>(120 + mode));
        const auto& layers = node<PaintLayers>(g, g.root);
        ASSERT_EQ(layers.layers.size(), 2u);
        EXPECT_EQ(static_cast<int>(node<PaintComposite>(g, layers.layers[1]).mode), mode) << f.glyph_name(120 + mode);
    }
}

TEST(ColrV1, PaletteIndexFfffIsTheForegroundTimesAlpha) {
    Font f = test_glyphs();
    const ColorGlyph g = load(f, 155);   // foreground_color_solid_alpha_0.3
    EXPECT_TRUE(g.uses_foreground);
    const auto& solid = node<PaintSolid>(g, node<PaintGlyph>(g, g.root).paint);
    EXPECT_TRUE(solid.color.foreground);
    EXPECT_FLOAT_EQ(solid.color.alpha, float(f2dot14(0.3)));
    EXPECT_TRUE(load(f, 148).uses_foreground);   // foreground_color_linear_alpha_1: a stop
}

TEST(ColrV1, PaintColrGlyphReachedFiveTimesIsOneSharedNodeAndOneOutline) {
    Font f = test_glyphs();
    const ColorGlyph g = load(f, 180);   // no_cycle_multi_colrglyph
    std::set<PaintIndex> colr_glyphs;
    std::size_t reached = 0;
    for (const PaintNode& n : g.nodes) {
        if (const auto* t = std::get_if<PaintTransform>(&n); t && std::holds_alternative<PaintColrGlyph>(g.nodes.at(t->paint))) {
            colr_glyphs.insert(t->paint);
            ++reached;
        }
    }
    EXPECT_EQ(reached, 5u);
    EXPECT_EQ(colr_glyphs.size(), 1u);
    EXPECT_EQ(g.outlines.size(), 1u);
}

TEST(ColrV1, PaintColrGlyphCarriesThatGlyphsClipBox) {
    Font f = test_glyphs();
    const ColorGlyph g = load(f, 160);   // clip_box_center: src_over onto PaintColrGlyph(166)
    EXPECT_EQ(*g.clip, (Rect{250, 250, 750, 750}));
    const auto& composite = node<PaintComposite>(g, g.root);
    const auto& inset = node<PaintColrGlyph>(g, composite.backdrop);   // inset_clipped_radial_reflect
    ASSERT_TRUE(inset.clip.has_value());
    EXPECT_EQ(*inset.clip, (Rect{100, 100, 900, 900}));
    const auto& radial = node<PaintColrGlyph>(g, inset.paint);   // glyph 95
    EXPECT_EQ(*radial.clip, (Rect{0, 0, 1000, 1000}));
}

TEST(ColrV1, OutlinesAreFontUnitsYUp) {
    Font f = test_glyphs();
    const ColorGlyph g = load(f, 99);   // PaintGlyph(cross_glyph), glyph 3
    ASSERT_EQ(g.outlines.size(), 1u);
    // Font::outline at size = units per em is font units, y down.
    auto reference = f.outline(3, {1000.0, Hinting::None});
    ASSERT_TRUE(reference.ok());
    const Rect down = reference->path.bounds(), up = g.outlines[0].bounds();
    EXPECT_EQ(up, (Rect{down.x0, -down.y1, down.x1, -down.y0}));
    EXPECT_GT(up.y1, 500);   // the cross sits above the baseline
}

TEST(ColrV1, ChosenPaletteAndCustomEntriesColourTheStops) {
    Font f = test_glyphs();
    ColorGlyphOptions dark;
    dark.palette = 1;
    {
        const ColorGlyph g = load(f, 9, dark);
        const auto& lg = node<PaintLinearGradient>(g, node<PaintGlyph>(g, g.root).paint);
        EXPECT_EQ(lg.line.stops[0].color.color, rgb(0x2A, 0x29, 0x4A));
    }
    ColorGlyphOptions custom;
    custom.custom.push_back({4, Rgba8{0x12, 0x34, 0x56, 0x80}});
    const ColorGlyph g = load(f, 9, custom);
    const auto& lg = node<PaintLinearGradient>(g, node<PaintGlyph>(g, g.root).paint);
    EXPECT_EQ(lg.line.stops[0].color.color, rgb(0xFF, 0, 0));   // entry 0 unchanged
    EXPECT_EQ(lg.line.stops[1].color.color, (ColorF{0x12 / 255.0f, 0x34 / 255.0f, 0x56 / 255.0f, 0x80 / 255.0f}));
}

TEST(ColrV1, PaletteOrEntryOutOfRangeIsAnErrorNamingIndexAndCount) {
    Font f = test_glyphs();
    ColorGlyphOptions bad_palette;
    bad_palette.palette = 3;
    auto a = load_color_glyph(f, 9, bad_palette);
    ASSERT_FALSE(a.ok());
    EXPECT_NE(a.error().message.find("palette 3 out of range (the font has 3 palettes)"), std::string::npos)
        << a.error().message;
    ColorGlyphOptions bad_entry;
    bad_entry.custom.push_back({14, Rgba8{}});
    auto b = load_color_glyph(f, 9, bad_entry);
    ASSERT_FALSE(b.ok());
    EXPECT_NE(b.error().message.find("custom palette entry 14 out of range (the palette has 14 entries)"),
              std::string::npos)
        << b.error().message;
}

TEST(ColrV1, VariablePaintsAreReadAtTheirDefaults) {
    Font stat = test_glyphs();
    Font var = open_font(font_path("colour/test_glyphs-glyf_colr_1_variable.ttf"));
    // sweep_60_300_pad_narrow is PaintVarSweepGradient over a VarColorLine in the variable font.
    const ColorGlyph a = load(stat, 13), b = load(var, 13);
    const auto& sa = node<PaintSweepGradient>(a, node<PaintGlyph>(a, a.root).paint);
    const auto& sb = node<PaintSweepGradient>(b, node<PaintGlyph>(b, b.root).paint);
    EXPECT_EQ(sa.start_deg, sb.start_deg);
    EXPECT_EQ(sa.end_deg, sb.end_deg);
    EXPECT_EQ(sa.center, sb.center);
    ASSERT_EQ(sa.line.stops.size(), sb.line.stops.size());
    for (std::size_t i = 0; i < sa.line.stops.size(); ++i) {
        EXPECT_EQ(sa.line.stops[i].offset, sb.line.stops[i].offset);
        EXPECT_EQ(sa.line.stops[i].color.color, sb.line.stops[i].color.color);
    }
    // rotate_10_center_0_0 is PaintVarRotate there.
    expect_affine_near(composite_source_transform(var, 99), composite_source_transform(stat, 99), 0);
}

TEST(ColrV1, EveryTestGlyphBuildsExceptTheTwoThatLoop) {
    for (const char* name : {"colour/test_glyphs-glyf_colr_1.ttf", "colour/test_glyphs-glyf_colr_1_variable.ttf"}) {
        Font f = open_font(font_path(name));
        int built = 0;
        for (GlyphId gid = 0; gid < f.glyph_count(); ++gid) {
            if (color_format(f, gid) != ColorFormat::ColrV1) continue;
            auto g = load_color_glyph(f, gid, {});
            if (gid == 178 || gid == 179) {   // paintcolrglyph_cycle_first / _second
                ASSERT_FALSE(g.ok());
                continue;
            }
            ASSERT_TRUE(g.ok()) << g.error().message;
            ++built;
        }
        EXPECT_EQ(built, 198) << name;
    }
}

TEST(ColrV1, CycleThroughTwoGlyphsOfTheTestFontIsAnErrorNamingTheGlyph) {
    Font f = test_glyphs();
    auto g = load_color_glyph(f, 178, {});
    ASSERT_FALSE(g.ok());
    EXPECT_NE(g.error().message.find("glyph 178 (paintcolrglyph_cycle_first): COLR paint graph loops"),
              std::string::npos)
        << g.error().message;
}

TEST(ColrV0, LayersArePaintGlyphsOfSolidColours) {
    Font f = open_font(data_path("colr_v0.ttf"));
    const ColorTables t = color_tables(f);
    EXPECT_TRUE(t.colr_v0);
    EXPECT_FALSE(t.colr_v1);
    const std::vector<Palette> p = palettes(f);
    ASSERT_EQ(p.size(), 2u);
    EXPECT_TRUE(p[0].for_light_background);
    EXPECT_TRUE(p[1].for_dark_background);
    EXPECT_EQ(color_format(f, 3), ColorFormat::ColrV0);
    const ColorGlyph g = load(f, 3);   // stack: square (0), triangle (1), square (0xFFFF)
    const auto& layers = node<PaintLayers>(g, g.root);
    ASSERT_EQ(layers.layers.size(), 3u);
    const auto& bottom = node<PaintGlyph>(g, layers.layers[0]);
    EXPECT_EQ(node<PaintSolid>(g, bottom.paint).color.color, rgb(0xFF, 0, 0));
    const auto& middle = node<PaintGlyph>(g, layers.layers[1]);
    // buildCPAL's (0, 0, 1, 0.5) is #0000FF80.
    EXPECT_EQ(node<PaintSolid>(g, middle.paint).color.color, (ColorF{0, 0, 1, 0x80 / 255.0f}));
    const auto& top = node<PaintGlyph>(g, layers.layers[2]);
    EXPECT_TRUE(node<PaintSolid>(g, top.paint).color.foreground);
    EXPECT_TRUE(g.uses_foreground);
    // The square is loaded once and shared by the two layers that draw it.
    EXPECT_EQ(g.outlines.size(), 2u);
    EXPECT_EQ(bottom.outline, top.outline);
    EXPECT_EQ(g.outlines[bottom.outline].bounds(), (Rect{100, 0, 900, 800}));

    ColorGlyphOptions second;
    second.palette = 1;
    const ColorGlyph h = load(f, 3, second);
    EXPECT_EQ(node<PaintSolid>(h, node<PaintGlyph>(h, node<PaintLayers>(h, h.root).layers[0]).paint).color.color,
              rgb(0, 0xFF, 0));
}

TEST(ColrV0, TestFontsCirclesHaveEightLayersInPaletteOrder) {
    Font f = test_glyphs();
    const ColorGlyph g = load(f, 168);   // colored_circles_v0
    const auto& layers = node<PaintLayers>(g, g.root);
    ASSERT_EQ(layers.layers.size(), 8u);
    EXPECT_EQ(node<PaintSolid>(g, node<PaintGlyph>(g, layers.layers[0]).paint).color.color, rgb(0xFF, 0, 0));
    EXPECT_EQ(node<PaintSolid>(g, node<PaintGlyph>(g, layers.layers[1]).paint).color.color, rgb(0xFF, 0xA5, 0));
}

TEST(BadColr, PaintColrGlyphOfItselfIsAnErrorNamingTheGlyph) {
    Font f = open_font(data_path("colr_loop.ttf"));
    for (GlyphId gid : {3u, 4u, 5u}) {   // self, ping, pong
        auto g = load_color_glyph(f, gid, {});
        ASSERT_FALSE(g.ok());
        const std::string want = "glyph " + std::to_string(gid) + " (" + f.glyph_name(gid) + "): COLR paint graph loops";
        EXPECT_NE(g.error().message.find(want), std::string::npos) << g.error().message;
    }
}

TEST(BadColr, GraphNestedTenThousandDeepIsAnErrorNotAStackOverflow) {
    Font f = open_font(data_path("colr_deep.ttf"));
    auto g = load_color_glyph(f, 3, {});
    ASSERT_FALSE(g.ok());
    EXPECT_NE(g.error().message.find("glyph 3 (deep): COLR paint graph nests deeper than " +
                                     std::to_string(kMaxPaintDepth)),
              std::string::npos)
        << g.error().message;
}

TEST(BadColr, SharedSubgraphsVisitedPastTheNodeBudgetAreAnError) {
    Font f = open_font(data_path("colr_wide.ttf"));
    auto g = load_color_glyph(f, 3, {});
    ASSERT_FALSE(g.ok());
    EXPECT_NE(g.error().message.find("glyph 3 (wide): COLR paint graph visits more than " +
                                     std::to_string(kMaxPaintNodes) + " nodes"),
              std::string::npos)
        << g.error().message;
}

TEST(BadColr, GradientsHoldingMoreThankMaxPaintColorStopsAreAnError) {
    Font f = open_font(data_path("colr_stops.ttf"));
    auto g = load_color_glyph(f, 3, {});   // 32 reaches of a 2100-stop gradient
    ASSERT_FALSE(g.ok());
    EXPECT_NE(g.error().message.find("glyph 3 (stops): COLR gradients hold more than " +
                                     std::to_string(kMaxPaintColorStops) + " colour stops"),
              std::string::npos)
        << g.error().message;
}

TEST(BadColr, PaletteIndexPastCpalIsAnErrorNamingIndexAndCount) {
    Font f = open_font(data_path("colr_bad_palette.ttf"));
    auto v1 = load_color_glyph(f, 3, {});   // bad_solid: PaintSolid index 7
    ASSERT_FALSE(v1.ok());
    EXPECT_NE(v1.error().message.find("glyph 3 (bad_solid): palette index 7 out of range (the palette has 2 entries)"),
              std::string::npos)
        << v1.error().message;
    auto v0 = load_color_glyph(f, 4, {});   // bad_layer: layer 1 index 9
    ASSERT_FALSE(v0.ok());
    EXPECT_NE(v0.error().message.find("glyph 4 (bad_layer): COLR layer 1: palette index 9 out of range (the palette has 2 entries)"),
              std::string::npos)
        << v0.error().message;
}

TEST(BadColr, GlyphsWithoutColrDataAndIdsOutOfRangeAreErrors) {
    Font f = test_glyphs();
    auto none = load_color_glyph(f, 3, {});
    ASSERT_FALSE(none.ok());
    EXPECT_NE(none.error().message.find("glyph 3 (cross_glyph): no COLR data for this glyph"), std::string::npos);
    auto far = load_color_glyph(f, 5000, {});
    ASSERT_FALSE(far.ok());
    EXPECT_NE(far.error().message.find("glyph id 5000 out of range"), std::string::npos);
    Font noto = open_font(font_path("noto-color-emoji/NotoColorEmoji-subset.ttf"));
    auto cbdt = load_color_glyph(noto, 1, {});
    ASSERT_FALSE(cbdt.ok());
    EXPECT_NE(cbdt.error().message.find("no COLR data (the font has no COLR table)"), std::string::npos);
}

// Every pixel premultiplied (no colour byte above its alpha), and how many are inked.
int inked_premultiplied_pixels(const ColorBitmap& b) {
    int inked = 0;
    for (std::size_t i = 0; i + 3 < b.rgba.size(); i += 4) {
        const std::uint8_t a = b.rgba[i + 3];
        EXPECT_LE(b.rgba[i], a);
        EXPECT_LE(b.rgba[i + 1], a);
        EXPECT_LE(b.rgba[i + 2], a);
        inked += a > 0;
    }
    return inked;
}

TEST(ColorBitmap, CbdtEmojiComesAtItsStrikeWithItsMetrics) {
    Font f = open_font(font_path("noto-color-emoji/NotoColorEmoji-subset.ttf"));
    auto b = load_color_bitmap(f, 1, 64);   // U+1F600; the font's one strike is 109 ppem
    ASSERT_TRUE(b.ok()) << b.error().message;
    // CBDT format 17 small metrics: 136 × 128, bearing (0, 101), advance 136.
    EXPECT_EQ(b->width, 136);
    EXPECT_EQ(b->height, 128);
    EXPECT_EQ(b->strike_px, 109);
    EXPECT_EQ(b->left, 0);
    EXPECT_EQ(b->top, 101);
    EXPECT_EQ(b->advance_px, 136);
    ASSERT_EQ(b->rgba.size(), 136u * 128 * 4);
    EXPECT_GT(inked_premultiplied_pixels(*b), 136 * 128 / 2);
    // The face's middle is opaque yellow: R and G high, B low (RGBA order, not FreeType's BGRA).
    const std::uint8_t* mid = b->view().pixel(68, 40);
    EXPECT_EQ(mid[3], 255);
    EXPECT_GT(mid[0], 200);
    EXPECT_GT(mid[1], 150);
    EXPECT_LT(mid[2], 100);
    // Sizes above the largest strike use it too.
    auto big = load_color_bitmap(f, 1, 300);
    ASSERT_TRUE(big.ok());
    EXPECT_EQ(big->strike_px, 109);
    // .notdef has no image: an empty bitmap, not an error.
    auto notdef = load_color_bitmap(f, 0, 64);
    ASSERT_TRUE(notdef.ok()) << notdef.error().message;
    EXPECT_EQ(notdef->width, 0);
    EXPECT_TRUE(notdef->rgba.empty());
}

TEST(ColorBitmap, SbixImageIsPlacedByItsOriginOffsets) {
    Font f = open_font(font_path("colour/twemoji_smiley-sbix.ttf"));
    EXPECT_TRUE(color_tables(f).sbix);
    auto b = load_color_bitmap(f, 2, 32);   // u1F601
    ASSERT_TRUE(b.ok()) << b.error().message;
    // sbix strike 109 ppem: a 128 × 128 PNG with originOffsetX 4, originOffsetY −27; hmtx advance
    // 1275 of 1024 units per em.
    EXPECT_EQ(b->strike_px, 109);
    EXPECT_EQ(b->width, 128);
    EXPECT_EQ(b->height, 128);
    EXPECT_EQ(b->left, 4);
    EXPECT_EQ(b->top, -27 + 128);
    EXPECT_DOUBLE_EQ(b->advance_px, 1275.0 * 109 / 1024);
    EXPECT_GT(inked_premultiplied_pixels(*b), 128 * 128 / 3);
}

TEST(ColorBitmap, ImageLargerThankMaxColorBitmapBytesIsRefusedFromItsHeader) {
    // The PNG declares 5000 × 5000 and holds no pixel data: decoding it would fail after FreeType
    // allocated 100 MB; bezel refuses it from the header first.
    Font f = open_font(data_path("sbix_huge.ttf"));
    auto b = load_color_bitmap(f, 3, 100);
    ASSERT_FALSE(b.ok());
    EXPECT_NE(b.error().message.find("glyph 3 (huge): colour bitmap 5000x5000 is larger than " +
                                     std::to_string(kMaxColorBitmapBytes >> 20) + " MiB of RGBA"),
              std::string::npos)
        << b.error().message;
}

TEST(ColorBitmap, BadRequestsAreErrorsNamingTheGlyph) {
    Font f = open_font(font_path("noto-color-emoji/NotoColorEmoji-subset.ttf"));
    EXPECT_FALSE(load_color_bitmap(f, 1, 0).ok());
    EXPECT_FALSE(load_color_bitmap(f, 1, std::nan("")).ok());
    auto far = load_color_bitmap(f, 2, 32);
    ASSERT_FALSE(far.ok());
    EXPECT_NE(far.error().message.find("glyph id 2 out of range"), std::string::npos);
    Font colr = test_glyphs();
    auto none = load_color_bitmap(colr, 9, 32);
    ASSERT_FALSE(none.ok());
    EXPECT_NE(none.error().message.find("glyph 9 (linear_repeat_0.2_0.8): no colour bitmap"), std::string::npos)
        << none.error().message;
}

}  // namespace
}  // namespace bezel
