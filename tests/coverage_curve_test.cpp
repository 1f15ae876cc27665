// CoverageCurve (image.hpp): the identity is today's linear blend bit for bit, perceptual curves
// are monotone with fixed ends for every colour pair and setting, gamma 1 mixes the encoded
// values as cairo does, the blend functions' per-thread tables follow a change of curve, and
// settings out of range are errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "bezel/image.hpp"

namespace bezel {
namespace {

const Rgba8 kWhite{255, 255, 255, 255};
const Rgba8 kBlack{0, 0, 0, 255};

CoverageCurve perceptual(Rgba8 fg, Rgba8 bg, double gamma = kDefaultTextGamma,
                         double contrast = kDefaultTextContrast) {
    CoverageCurveOptions o;
    o.gamma = gamma;
    o.contrast = contrast;
    auto curve = coverage_curve(fg, bg, o);
    EXPECT_TRUE(curve) << curve.error().message;
    return curve ? *curve : CoverageCurve();
}

// One pixel of `bg` with `fg` blended at coverage `cov` through `curve`, on a gray page.
std::uint8_t gray_blend(std::uint8_t fg, std::uint8_t bg, std::uint8_t cov,
                        const CoverageCurve& curve) {
    std::uint8_t page = bg;
    blend_mask_gray(MaskView{&page, 1, 1, 1}, ConstMaskView(&cov, 1, 1, 1), 0, 0, fg, curve);
    return page;
}

TEST(CoverageCurve, LinearIsCoverageOver255AndTheDefaultIsPerceptual) {
    const CoverageCurve identity;
    EXPECT_TRUE(identity.linear());
    for (int i = 0; i < 256; ++i)
        EXPECT_EQ(identity[static_cast<std::uint8_t>(i)], static_cast<float>(i) / 255.0f) << i;
    CoverageCurveOptions linear;
    linear.rendering = TextRendering::Linear;
    linear.gamma = 99.0;   // ignored by Linear
    auto made = coverage_curve(kBlack, kWhite, linear);
    ASSERT_TRUE(made) << made.error().message;
    EXPECT_TRUE(made->linear());
    EXPECT_EQ(made->alphas(), identity.alphas());
    EXPECT_EQ(CoverageCurveOptions().rendering, TextRendering::Perceptual);
    EXPECT_FALSE(perceptual(kBlack, kWhite).linear());
}

TEST(CoverageCurve, MonotoneFromZeroToOneForEveryPairAndSetting) {
    const std::vector<Rgba8> colours = {kBlack,
                                        kWhite,
                                        {128, 128, 128, 255},
                                        {200, 30, 10, 255},
                                        {0, 0, 255, 255},
                                        {240, 240, 200, 255},
                                        {0, 0, 0, 0},
                                        {255, 255, 255, 100},
                                        {60, 60, 60, 255},
                                        {61, 60, 60, 255}};
    for (const Rgba8& fg : colours)
        for (const Rgba8& bg : colours)
            for (double gamma : {1.0, 1.2, 1.8, 2.2, 3.0})
                for (double contrast : {0.0, 0.2, 0.5, 1.0}) {
                    const CoverageCurve c = perceptual(fg, bg, gamma, contrast);
                    const std::string where = std::to_string(gamma) + " " +
                                              std::to_string(contrast) + " fg " +
                                              std::to_string(fg.r) + " bg " + std::to_string(bg.r);
                    ASSERT_EQ(c[0], 0.0f) << where;
                    ASSERT_EQ(c[255], 1.0f) << where;
                    for (int i = 1; i < 256; ++i)
                        ASSERT_GE(c[static_cast<std::uint8_t>(i)],
                                  c[static_cast<std::uint8_t>(i - 1)])
                            << where << " at " << i;
                }
}

TEST(CoverageCurve, GammaOneMixesTheEncodedValuesAsCairoDoes) {
    // At gamma 1, contrast 0 the pixel is lerp(bg, fg, c) of the sRGB bytes themselves (to one
    // level: the linear-light blend quantizes through 8-bit coverage and the encode table).
    for (auto [fg, bg] : {std::pair<int, int>{0, 255}, {255, 0}, {90, 200}, {230, 40}}) {
        const CoverageCurve curve = perceptual(Rgba8{std::uint8_t(fg), std::uint8_t(fg),
                                                     std::uint8_t(fg), 255},
                                               Rgba8{std::uint8_t(bg), std::uint8_t(bg),
                                                     std::uint8_t(bg), 255},
                                               1.0, 0.0);
        for (int cov = 0; cov < 256; ++cov) {
            const double naive = bg + (fg - bg) * cov / 255.0;
            EXPECT_NEAR(gray_blend(std::uint8_t(fg), std::uint8_t(bg), std::uint8_t(cov), curve),
                        naive, 1.0)
                << fg << " on " << bg << " at " << cov;
        }
    }
    // Half-covered black on white: 128 (cairo's value), where linear light gives 188.
    EXPECT_NEAR(gray_blend(0, 255, 128, perceptual(kBlack, kWhite, 1.0, 0.0)), 127, 1);
    EXPECT_NEAR(gray_blend(0, 255, 128, CoverageCurve()), 188, 1);
}

TEST(CoverageCurve, DarkTextGainsWeightLightTextLosesItAndContrastAddsToBoth) {
    const CoverageCurve dark = perceptual(kBlack, kWhite), light = perceptual(kWhite, kBlack);
    const CoverageCurve dark_k = perceptual(kBlack, kWhite, kDefaultTextGamma, 0.5);
    const CoverageCurve light_k = perceptual(kWhite, kBlack, kDefaultTextGamma, 0.5);
    const CoverageCurve linear;
    for (int i = 1; i < 255; ++i) {
        const auto c = static_cast<std::uint8_t>(i);
        EXPECT_GT(dark[c], linear[c]) << i;
        EXPECT_LT(light[c], linear[c]) << i;
        EXPECT_GT(dark_k[c], dark[c]) << i;
        EXPECT_GT(light_k[c], light[c]) << i;
    }
    // Gamma towards sRGB's own ~2.2 brings the curve back towards linear light.
    const CoverageCurve near_linear = perceptual(kBlack, kWhite, 2.2, 0.0);
    EXPECT_NEAR(near_linear[128], linear[128], 0.03);
}

TEST(CoverageCurve, TranslucentBackgroundAssumesTheBackdropTextIsReadOn) {
    // Dark text on a clear page is shaped as dark text on white, light text as on black.
    const Rgba8 clear{0, 0, 0, 0};
    EXPECT_EQ(perceptual(kBlack, clear).alphas(), perceptual(kBlack, kWhite).alphas());
    EXPECT_EQ(perceptual(kWhite, clear).alphas(), perceptual(kWhite, kBlack).alphas());
    // Text the colour of its page: nothing to shape, the contrast lift alone.
    const CoverageCurve same = perceptual(kWhite, kWhite, 1.0, 0.0);
    EXPECT_EQ(same.alphas(), CoverageCurve().alphas());
}

TEST(CoverageCurve, OutOfRangeSettingsAreErrorsNamingThem) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (double gamma : {0.5, 0.999, 3.01, nan, -1.0}) {
        CoverageCurveOptions o;
        o.gamma = gamma;
        auto c = coverage_curve(kBlack, kWhite, o);
        ASSERT_FALSE(c) << gamma;
        EXPECT_NE(c.error().message.find("gamma"), std::string::npos) << c.error().message;
        EXPECT_NE(c.error().message.find("(1 to 3)"), std::string::npos) << c.error().message;
    }
    for (double contrast : {-0.01, 1.01, nan}) {
        CoverageCurveOptions o;
        o.contrast = contrast;
        auto c = coverage_curve(kBlack, kWhite, o);
        ASSERT_FALSE(c) << contrast;
        EXPECT_NE(c.error().message.find("contrast"), std::string::npos) << c.error().message;
    }
    for (double gamma : {kMinTextGamma, kMaxTextGamma}) {
        CoverageCurveOptions o;
        o.gamma = gamma;
        o.contrast = kMaxTextContrast;
        EXPECT_TRUE(coverage_curve(kBlack, kWhite, o));
    }
}

// The blend functions keep a per-thread table for the colour pair; a new curve on the same pair
// must rebuild it, and a copy of a curve may reuse it.
TEST(CoverageCurve, BlendTablesFollowTheCurve) {
    const std::uint8_t cov = 128;
    const CoverageCurve dark = perceptual(kBlack, kWhite);
    const CoverageCurve copy = dark;
    EXPECT_TRUE(copy.same_as(dark));
    const std::uint8_t linear_px = gray_blend(0, 255, cov, CoverageCurve());
    const std::uint8_t perceptual_px = gray_blend(0, 255, cov, dark);
    EXPECT_NE(linear_px, perceptual_px);
    EXPECT_EQ(gray_blend(0, 255, cov, CoverageCurve()), linear_px);
    EXPECT_EQ(gray_blend(0, 255, cov, copy), perceptual_px);

    Image a(1, 1, kWhite), b(1, 1, kWhite), c(1, 1, kWhite);
    blend_mask(a, ConstMaskView(&cov, 1, 1, 1), 0, 0, kBlack);
    blend_mask(b, ConstMaskView(&cov, 1, 1, 1), 0, 0, kBlack, dark);
    blend_mask(c, ConstMaskView(&cov, 1, 1, 1), 0, 0, kBlack);
    EXPECT_EQ(a.at(0, 0).r, linear_px);
    EXPECT_EQ(b.at(0, 0).r, perceptual_px);
    EXPECT_EQ(c, a);
}

// Random masks, overlapping (so both the background table and the per-pixel blend run), through
// one curve: the identity curve gives the curve-less functions' pixels exactly, and a perceptual
// curve gives the same pixels on a gray page as on an RGBA page, and the same on an LCD mask of
// equal subpixels as on the gray mask.
TEST(CoverageCurve, EveryBlendAppliesTheSameCurve) {
    std::uint32_t seed = 777;
    auto next = [&seed] { return (seed = seed * 1664525u + 1013904223u) >> 24; };
    for (std::uint8_t fg : {0, 90, 255})
        for (std::uint8_t bg : {255, 200, 0}) {
            const Rgba8 fg_rgba{fg, fg, fg, 255}, bg_rgba{bg, bg, bg, 255};
            const CoverageCurve curve = perceptual(fg_rgba, bg_rgba, 1.3, 0.2);
            Image plain(23, 17, bg_rgba), identity(23, 17, bg_rgba), rgba(23, 17, bg_rgba),
                lcd(23, 17, bg_rgba);
            Mask gray(23, 17);
            for (int y = 0; y < 17; ++y)
                for (int x = 0; x < 23; ++x) gray.at(x, y) = bg;
            for (int k = 0; k < 12; ++k) {
                Mask m(9, 7), m3(27, 7);
                for (int y = 0; y < 7; ++y)
                    for (int x = 0; x < 9; ++x) {
                        const std::uint32_t r = next();
                        const auto v = r < 60 ? 0 : r > 200 ? 255 : static_cast<std::uint8_t>(r);
                        m.at(x, y) = v;
                        for (int s = 0; s < 3; ++s) m3.at(3 * x + s, y) = v;
                    }
                const int x = static_cast<int>(next() % 27) - 4,
                          y = static_cast<int>(next() % 21) - 4;
                blend_mask(plain, m.view(), x, y, fg_rgba);
                blend_mask(identity, m.view(), x, y, fg_rgba, CoverageCurve());
                blend_mask(rgba, m.view(), x, y, fg_rgba, curve);
                blend_lcd_mask(lcd, m3.view(), x, y, fg_rgba, LcdOrder::Rgb, curve);
                blend_mask_gray(gray.view(), m.view(), x, y, fg, curve);
            }
            EXPECT_EQ(identity, plain) << +fg << " on " << +bg;
            EXPECT_EQ(lcd, rgba) << +fg << " on " << +bg;
            for (int y = 0; y < 17; ++y)
                for (int x = 0; x < 23; ++x)
                    ASSERT_EQ(gray.at(x, y), rgba.at(x, y).r)
                        << +fg << " on " << +bg << " at " << x << "," << y;
            if (fg != bg) {
                EXPECT_NE(rgba, plain) << +fg << " on " << +bg;
            }
        }
}

}  // namespace
}  // namespace bezel
