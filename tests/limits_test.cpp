// Every limit of bezel/limits.hpp crossed: the input just past the wall gets an Error whose one
// line names what was too large, and nothing is allocated for it first. (Limits whose crossing
// is already tested beside their module are listed at the end, not repeated.)
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "bezel/flatten.hpp"
#include "bezel/font.hpp"
#include "bezel/image.hpp"
#include "bezel/intersect.hpp"
#include "bezel/limits.hpp"
#include "bezel/paint.hpp"
#include "bezel/path.hpp"
#include "bezel/raster.hpp"
#include "bezel/smooth.hpp"
#include "bezel/stroke.hpp"
#include "bezel/surface.hpp"
#include "bezel/text.hpp"

namespace bezel {
namespace {

const std::string kDejaVu = BEZEL_FONTS_DIR "/dejavu-sans/DejaVuSans.ttf";

// The error is one line and contains `needle`.
template <typename T>
void expect_error(const Expected<T>& r, const std::string& needle) {
    ASSERT_FALSE(r.ok());
    const std::string& m = r.error().message;
    EXPECT_NE(m.find(needle), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
}

TEST(Limits, BitmapLargerThankMaxBitmapDimIsAnError) {
    Polylines square;
    square.points = {{0, 0}, {1, 0}, {1, 1}};
    square.contour_ends = {3};
    Rasterizer raster;
    std::uint8_t pixel = 0;
    // The size is checked before the (single-pixel) memory is touched.
    expect_error(raster.fill(square, MaskView{&pixel, kMaxBitmapDim + 1, 1, kMaxBitmapDim + 1},
                             {FillRule::NonZero}),
                 std::to_string(kMaxBitmapDim + 1));
    EXPECT_EQ(pixel, 0);
    std::uint8_t row[4] = {};
    EXPECT_TRUE(raster.fill(square, MaskView{row, 4, 1, 4}, {FillRule::NonZero}));
}

TEST(Limits, FillWithMoreThankMaxEdgesIsRefusedBeforeFlattening) {
    // One cubic 2^40 px wide at 1e-9 px tolerance: Wang's bound asks for far more than kMaxEdges.
    Path path;
    path.move_to({0, 0});
    path.cubic_to({0x1p40, 0x1p40}, {-0x1p40, 0x1p40}, {1, 0});
    path.close();
    FlattenOptions fine;
    fine.tolerance_px = kMinFlattenTolerancePx;
    Rasterizer raster;
    std::uint8_t pixels[16] = {};
    auto status = raster.fill_path(path, Affine::identity(), MaskView{pixels, 4, 4, 4},
                                   {FillRule::NonZero, OverlapMode::Accumulate, fine});
    ASSERT_FALSE(status.ok());
    EXPECT_EQ(status.error().message.find('\n'), std::string::npos);
    // Nothing was allocated for it: 4 Mi edges would need far more than the band scratch.
    EXPECT_LT(raster.scratch_capacity_bytes(), std::size_t{16} << 20);
}

TEST(Limits, CurveNeedingMoreThankMaxSegmentsPerCurveIsReportedByFlattenChecked) {
    Path path;
    path.move_to({0, 0});
    path.quad_to({0x1p45, 0x1p45}, {1, 0});
    FlattenOptions fine;
    fine.tolerance_px = 1e-6;
    for (FlattenMethod method : {FlattenMethod::WangUniform, FlattenMethod::DistanceSubdivision,
                                 FlattenMethod::ParabolaIntegral}) {
        SCOPED_TRACE(static_cast<int>(method));
        fine.method = method;
        Polylines out;
        expect_error(flatten_checked(path, Affine::identity(), fine, out), "verb 1");
        EXPECT_TRUE(out.points.empty());
        flatten(path, Affine::identity(), fine, out);  // the silent version caps, never more
        EXPECT_LE(out.points.size(), kMaxSegmentsPerCurve + 1);
    }
}

TEST(Limits, CoordinateBeyondkMaxFlattenCoordinatePxIsReported) {
    Path path;
    path.move_to({0, 0});
    path.line_to({kMaxFlattenCoordinatePx * 2, 0});
    path.line_to({0, 1});
    Polylines out;
    expect_error(flatten_checked(path, Affine::identity(), {}, out), "beyond 2^50 px");
    flatten(path, Affine::identity(), {}, out);
    EXPECT_TRUE(out.points.empty());  // the contour is dropped whole
}

TEST(Limits, PathDataLongerThankMaxSvgPathLengthIsAnError) {
    std::string data = "M0 0";
    data.resize(kMaxSvgPathLength + 1, ' ');
    expect_error(parse_svg_path(data), std::to_string(kMaxSvgPathLength));
    data.resize(kMaxSvgPathLength);
    EXPECT_TRUE(parse_svg_path(data));
}

TEST(Limits, FontSizeAbovekMaxFontSizePxIsAnError) {
    auto font = Font::open(kDejaVu);
    ASSERT_TRUE(font);
    const GlyphId g = font->glyph_for_char(U'g').value();
    expect_error(font->outline(g, {kMaxFontSizePx * 2, Hinting::None}), "size");
    EXPECT_TRUE(font->outline(g, {kMaxFontSizePx, Hinting::None}));
}

TEST(Limits, GlyphOffsetBeyondkMaxGlyphOffsetPxIsAnError) {
    auto font = Font::open(kDejaVu);
    ASSERT_TRUE(font);
    GlyphRasterizer rasterizer(*font);
    const GlyphId g = font->glyph_for_char(U'g').value();
    GlyphRenderOptions o;
    o.box = GlyphBoxMode::FreeType;
    o.offset_px = {0, -2 * kMaxGlyphOffsetPx};
    expect_error(rasterizer.measure(g, o), "beyond ±16384 px");
    o.offset_px = {-kMaxGlyphOffsetPx, kMaxGlyphOffsetPx};
    EXPECT_TRUE(rasterizer.measure(g, o));
}

TEST(Limits, FaceIndexAbovekMaxFaceIndexIsAnError) {
    expect_error(Font::open(kDejaVu, kMaxFaceIndex + 1), std::to_string(kMaxFaceIndex));
    expect_error(Font::open(kDejaVu, 1), "DejaVuSans.ttf");  // in range, but no such face
}

TEST(Limits, TextLongerThankMaxTextBytesIsAnErrorFromLayoutAndRenderer) {
    auto shaper = Shaper::open(kDejaVu);
    ASSERT_TRUE(shaper);
    const std::string text(kMaxTextBytes + 1, 'a');
    auto font = Font::open(kDejaVu);
    ASSERT_TRUE(font);
    expect_error(layout_text(*shaper, font->metrics(), text, {}, {}),
                 std::to_string(kMaxTextBytes));
    auto renderer = TextRenderer::open(kDejaVu);
    ASSERT_TRUE(renderer);
    expect_error(renderer->render(text, {}), std::to_string(kMaxTextBytes));
}

TEST(Limits, SmoothingMoreThankMaxSmoothPointsIsAnError) {
    std::vector<Point> points(kMaxSmoothPoints + 1);
    for (std::size_t i = 0; i < points.size(); ++i) points[i] = {static_cast<double>(i), 0};
    expect_error(catmull_rom(points), std::to_string(kMaxSmoothPoints));
    expect_error(natural_spline(points), std::to_string(kMaxSmoothPoints));
    expect_error(bspline(points), std::to_string(kMaxSmoothPoints));
}

TEST(Limits, SmoothCoordinateBeyondkMaxSmoothCoordinateIsAnError) {
    expect_error(natural_spline({{0, 0}, {0x1p101, 0}}), "points[1]");
}

TEST(Limits, ChaikinPastItsIterationAndOutputWallsIsAnError) {
    const std::vector<Point> triangle{{0, 0}, {4, 0}, {0, 4}};
    expect_error(chaikin(triangle, kMaxChaikinIterations + 1), std::to_string(kMaxChaikinIterations));
    // 3·2^21 = 6 Mi points > kMaxChaikinOutputPoints, refused before any work.
    expect_error(chaikin(triangle, 21, {true, true}), std::to_string(kMaxChaikinOutputPoints));
}

TEST(Limits, DashesPastkMaxDashesAreAnError) {
    Path line;
    line.move_to({0, 0});
    line.line_to({1e7, 0});
    expect_error(dash(line, {1, 1}, 0), "dash");
    StrokeStyle style;
    style.dashes = {1, 1};
    expect_error(stroke(line, style), "dash");
}

TEST(Limits, SurfacePastkMaxSurfacePatchesAndTessellationWallsIsAnError) {
    std::vector<Patch> none;
    expect_error(validate_patches(none, "teapot"), "teapot");
    expect_error(bspline_grid(std::vector<Vec3>(16), kMaxBSplineGridSide + 1, 4),
                 std::to_string(kMaxBSplineGridSide));
}

TEST(Limits, PaintGraphDeeperThankMaxPaintDepthIsAnError) {
    // A chain of transforms kMaxPaintDepth nodes long (the last a fill) is allowed; one more
    // level is refused, by validate() and by the painter, before anything is painted.
    ColorGlyph g;
    for (PaintIndex i = 0; i + 1 < static_cast<PaintIndex>(kMaxPaintDepth); ++i)
        g.nodes.push_back(PaintTransform{Affine::identity(), i + 1});
    g.nodes.push_back(PaintSolid{});
    EXPECT_TRUE(validate(g));
    g.nodes.back() = PaintTransform{Affine::identity(), static_cast<PaintIndex>(g.nodes.size())};
    g.nodes.push_back(PaintSolid{});
    expect_error(validate(g), std::to_string(kMaxPaintDepth));
    std::uint8_t px[4] = {1, 2, 3, 4};
    Painter painter;
    expect_error(painter.paint(g, {}, RgbaView{px, 1, 1, 4}), std::to_string(kMaxPaintDepth));
    EXPECT_EQ(px[0], 1);
}

TEST(Limits, PaintGraphVisitingMoreThankMaxPaintNodesIsAnError) {
    // Layer lists naming the next level twice: level k is reached 2^k times. 15 levels visit
    // 2^16 − 1 nodes (allowed); 16 levels visit 2^17 − 1, refused.
    auto dag = [](PaintIndex levels) {
        ColorGlyph g;
        for (PaintIndex i = 0; i < levels; ++i) g.nodes.push_back(PaintLayers{{i + 1, i + 1}});
        g.nodes.push_back(PaintSolid{});
        return g;
    };
    static_assert(kMaxPaintNodes == (std::size_t{1} << 16), "the levels below assume 2^16");
    EXPECT_TRUE(validate(dag(15)));
    expect_error(validate(dag(16)), std::to_string(kMaxPaintNodes));
}

TEST(Limits, ImageWiderThankMaxImageDimIsAnError) {
    std::vector<std::uint8_t> row(kMaxImageDim + 1, 255);
    const ConstMaskView wide{row.data(), kMaxImageDim + 1, 1, kMaxImageDim + 1};
    expect_error(encode_png_gray(wide), "larger than the 32768 px a side images may have");
    // A text page wider than kMaxImageDim is refused, not allocated.
    auto renderer = TextRenderer::open(kDejaVu);
    ASSERT_TRUE(renderer);
    TextRenderOptions o;
    o.shape.size_px = 64;
    auto page = renderer->render(std::string(1000, 'W'), o);  // ~64 000 px wide
    ASSERT_FALSE(page.ok());
    EXPECT_EQ(page.error().message.find('\n'), std::string::npos);
}

// Crossed elsewhere (not repeated here): the glyph cache's byte bound (glyph_cache_test,
// StaysWithinItsBoundAcrossManySizes); kMaxTextCodePoints, a CLI limit (bad_inputs_cli_test);
// kMaxSyntheticBold (synthetic_bold_test, RefusesBoldOutOfRangeAndEvenOddFill);
// kMaxSystemFontLists (system_fonts_test, ListCacheStaysWithinkMaxSystemFontLists);
// kMaxCollectionFonts (text_fallback_test, BadListsAreErrorsNamingTheFile); kMaxPaintDepth,
// kMaxPaintNodes and kMaxPaintColorStops (color_glyph_test, BadColr.*); kMaxColorBitmapBytes
// (color_glyph_test, ImageLargerThankMaxColorBitmapBytesIsRefusedFromItsHeader).
// Not crossed by a test, because reaching them is seconds of work under the sanitizers (the
// fuzz targets run against them instead): kMaxSvgPathPoints and kMaxCubicsPerArc (8 Mi points
// of arcs), kMaxPathIntersections (2^20 crossings), kMaxIntersectWork, kMaxPathSegmentPairs,
// kMaxStrokeSegments and kMaxPaintOutlinePoints (2^22 points of distinct glyphs' outlines).

}  // namespace
}  // namespace bezel
