// Glyph-level tests of the rasterizer (links the whole library: fonts come through bezel::Font).
//
//  - Accuracy: against the reference — the same outline scaled by 16, rendered with
//    float coverage and box-filtered 16×16 back to size S — on a sample of glyphs of both test
//    fonts at 12, 24, 48 and 96 px (the full sweep, with FreeType's own error beside it, is
//    `bench_raster_bench --accuracy`).
//  - Goldens: a few glyph renders kept as PNG in tests/golden/raster/. Regenerate them with
//    BEZEL_UPDATE_GOLDEN=1 after a deliberate change (and say why in the commit).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "bezel/font.hpp"
#include "bezel/image.hpp"
#include "bezel/raster.hpp"
#include "support/golden.hpp"

namespace bezel {
namespace {

const std::string kDejaVu = std::string(BEZEL_FONTS_DIR) + "/dejavu-sans/DejaVuSans.ttf";
const std::string kCantarell = std::string(BEZEL_FONTS_DIR) + "/cantarell/Cantarell-Regular.otf";

struct Rendered {
    Path path;      // pixels, y down, pen at the origin
    int x0 = 0, y0 = 0, width = 0, height = 0;  // integer box of the control box
};

Rendered load(Font& font, char32_t ch, double size_px) {
    Rendered r;
    auto gid = font.glyph_for_char(ch);
    if (!gid) return r;
    Expected<GlyphOutline> o = font.outline(*gid, OutlineOptions{size_px, Hinting::None});
    if (!o.ok() || o->metrics.bounds_px.is_empty()) return r;
    const Rect& b = o->metrics.bounds_px;
    r.path = o->path;
    r.x0 = static_cast<int>(std::floor(b.x0));
    r.y0 = static_cast<int>(std::floor(b.y0));
    r.width = static_cast<int>(std::ceil(b.x1)) - r.x0;
    r.height = static_cast<int>(std::ceil(b.y1)) - r.y0;
    return r;
}

struct ErrorStats {
    double sum = 0, max = 0;
    std::size_t n = 0;
};

// |bezel 8-bit − reference| in 1/255 units, added to `stats`.
void measure(Rasterizer& rast, const Rendered& g, ErrorStats& stats) {
    const int W = g.width * 16, H = g.height * 16;
    std::vector<float> big(static_cast<std::size_t>(W) * H);
    Affine to_box = Affine::translate({-double(g.x0), -double(g.y0)});
    FlattenOptions fine;  // 1/16 px at 16× = 1/256 px at the glyph's size
    fine.tolerance_px = 1.0 / 16.0;
    ASSERT_TRUE(rast.fill_path(g.path, Affine::scale(16.0) * to_box,
                               FloatMaskView{big.data(), W, H, W},
                               {FillRule::NonZero, OverlapMode::Accumulate, fine}).ok());
    Mask mine(g.width, g.height);
    ASSERT_TRUE(rast.fill_path(g.path, to_box, mine.view(), {FillRule::NonZero}).ok());
    for (int y = 0; y < g.height; ++y) {
        for (int x = 0; x < g.width; ++x) {
            double ref = 0.0;
            for (int sy = 0; sy < 16; ++sy)
                for (int sx = 0; sx < 16; ++sx)
                    ref += big[static_cast<std::size_t>(y * 16 + sy) * W + x * 16 + sx];
            double e = std::fabs(mine.at(x, y) - ref / 256.0 * 255.0);
            stats.sum += e;
            stats.max = std::max(stats.max, e);
            ++stats.n;
        }
    }
}

TEST(RasterGlyphs, MeanErrorAgainstSupersampledReferenceIsUnderHalfALevel) {
    // Bounds: mean ≤ 0.5/255 (the target); max ≤ 3/255. The max is what 8-bit rounding
    // (0.5) plus the 0.01 px default flattening tolerance allow in the worst pixel (measured:
    // ≤ 1.7/255 over all ASCII glyphs of both fonts; FreeType's own render of the same outlines
    // errs up to 16–54/255 against the same reference).
    const char32_t sample[] = U"agQ&@8sRWe%?ß";
    Rasterizer rast;
    for (const std::string& file : {kDejaVu, kCantarell}) {
        Expected<Font> font = Font::open(file);
        ASSERT_TRUE(font.ok()) << font.error().message;
        for (double size : {12.0, 24.0, 48.0, 96.0}) {
            ErrorStats stats;
            for (char32_t ch : sample) {
                if (ch == 0) break;
                Rendered g = load(*font, ch, size);
                if (g.width == 0) continue;
                measure(rast, g, stats);
            }
            ASSERT_GT(stats.n, 0u);
            const double mean = stats.sum / static_cast<double>(stats.n);
            EXPECT_LE(mean, 0.5) << file << " at " << size << " px";
            EXPECT_LE(stats.max, 3.0) << file << " at " << size << " px";
        }
    }
}

// Compares with a golden PNG, within ±2 levels per pixel: the goldens pin the rasterizer, but
// the outline and the flattening come from other modules whose last-bit rounding may change.
void check_golden(const Mask& m, const std::string& name) {
    const std::string file = std::string(BEZEL_GOLDEN_DIR) + "/raster/" + name + ".png";
    if (test::update_golden()) {
        ASSERT_TRUE(write_png_gray(file, m.view()).ok());
        return;
    }
    Expected<Mask> golden = read_png_gray(file);
    ASSERT_TRUE(golden.ok()) << golden.error().message
                             << " (run with BEZEL_UPDATE_GOLDEN=1 to create it)";
    ASSERT_EQ(golden->width(), m.width()) << name;
    ASSERT_EQ(golden->height(), m.height()) << name;
    int worst = 0;
    for (int y = 0; y < m.height(); ++y)
        for (int x = 0; x < m.width(); ++x)
            worst = std::max(worst, std::abs(int(golden->at(x, y)) - int(m.at(x, y))));
    EXPECT_LE(worst, 2) << name;
}

TEST(RasterGlyphs, GoldenDejaVuGAt24Px) {
    Expected<Font> font = Font::open(kDejaVu);
    ASSERT_TRUE(font.ok());
    Rendered g = load(*font, U'g', 24.0);
    ASSERT_GT(g.width, 0);
    Mask m(g.width, g.height);
    Rasterizer r;
    ASSERT_TRUE(r.fill_path(g.path, Affine::translate({-double(g.x0), -double(g.y0)}), m.view(),
                            {FillRule::NonZero}).ok());
    check_golden(m, "dejavu_g_24");
}

TEST(RasterGlyphs, GoldenCantarellAmpersandAt48PxSubpixelOrigin) {
    Expected<Font> font = Font::open(kCantarell);
    ASSERT_TRUE(font.ok());
    Rendered g = load(*font, U'&', 48.0);
    ASSERT_GT(g.width, 0);
    Mask m(g.width + 1, g.height + 1);
    Rasterizer r;
    ASSERT_TRUE(r.fill_path(g.path, Affine::translate({0.25 - g.x0, 0.5 - g.y0}), m.view(),
                            {FillRule::NonZero}).ok());
    check_golden(m, "cantarell_ampersand_48_subpixel");
}

TEST(RasterGlyphs, GoldenDejaVuAtSignEvenOddRotated) {
    Expected<Font> font = Font::open(kDejaVu);
    ASSERT_TRUE(font.ok());
    Rendered g = load(*font, U'@', 32.0);
    ASSERT_GT(g.width, 0);
    Mask m(48, 48);
    Rasterizer r;
    Affine t = Affine::translate({24, 24}) * Affine::rotate(0.5) *
               Affine::translate({-(g.x0 + g.width / 2.0), -(g.y0 + g.height / 2.0)});
    ASSERT_TRUE(r.fill_path(g.path, t, m.view(), {FillRule::EvenOdd}).ok());
    check_golden(m, "dejavu_at_32_rotated_evenodd");
}

}  // namespace
}  // namespace bezel
