// `bezel render --direction ttb|btt` end to end: vertical pages against hb-view's pictures of
// the same text (tests/golden/vertical/hbview_*.png, made by generate.sh there), columns right
// to left, --width as the column length, and the direction's errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "bezel/image.hpp"
#include "support/cli_run.hpp"

namespace bezel {
namespace {

using test::run_bezel;
using test::TempDir;

const std::string kCjk = BEZEL_FONTS_DIR "/noto-cjk/NotoSansCJKjp-Subset.otf";
const std::string kGolden = BEZEL_GOLDEN_DIR "/vertical/";

// How close bezel's page must be to hb-view's. The two rasterize differently (bezel's exact
// area coverage through its perceptual curve, cairo's own; cairo rounds glyph positions to
// whole pixels, bezel keeps a quarter pixel for the Latin letters' half-advance offsets), so
// single pixels on glyph edges differ by up to half the range; measured: mean 0.55 and 0.28
// levels, ink within 0.1 %, ink centroid within 0.16 px. The bounds leave room for that and
// catch any glyph misplaced by a pixel or more, missing or substituted.
constexpr double kMeanLevels = 1.5;
constexpr double kInkRatio = 0.01;
constexpr double kCentroidPx = 0.3;

struct Ink {
    double total = 0, x = 0, y = 0;   // sum of (255 − v), and its centroid
};

Ink ink_of(const Mask& m, int x0 = 0, int x1 = -1) {
    if (x1 < 0) x1 = m.width();
    Ink ink;
    for (int y = 0; y < m.height(); ++y)
        for (int x = x0; x < x1; ++x) {
            const double w = 255 - m.at(x, y);
            ink.total += w;
            ink.x += w * x;
            ink.y += w * y;
        }
    if (ink.total > 0) {
        ink.x /= ink.total;
        ink.y /= ink.total;
    }
    return ink;
}

Mask render_ok(const std::vector<std::string>& args, const TempDir& dir) {
    std::vector<std::string> argv = {"render", kCjk};
    argv.insert(argv.end(), args.begin(), args.end());
    argv.insert(argv.end(), {"-o", "page.png"});
    auto run = run_bezel(argv, dir.path());
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.err, "");
    auto png = read_png_gray((dir.path() / "page.png").string());
    if (!png) {
        ADD_FAILURE() << png.error().message;
        return Mask();
    }
    return std::move(*png);
}

void expect_like_hb_view(const Mask& got, const std::string& golden) {
    auto want = read_png_gray(kGolden + golden);
    ASSERT_TRUE(want) << want.error().message;
    ASSERT_EQ(got.width(), want->width());
    ASSERT_EQ(got.height(), want->height());
    double diff = 0;
    for (int y = 0; y < got.height(); ++y)
        for (int x = 0; x < got.width(); ++x) diff += std::abs(got.at(x, y) - want->at(x, y));
    EXPECT_LE(diff / (got.width() * got.height()), kMeanLevels);
    const Ink a = ink_of(got), b = ink_of(*want);
    EXPECT_NEAR(a.total / b.total, 1.0, kInkRatio);
    EXPECT_NEAR(a.x, b.x, kCentroidPx);
    EXPECT_NEAR(a.y, b.y, kCentroidPx);
}

TEST(RenderVerticalCli, TopToBottomPageMatchesHbView) {
    TempDir dir("bezel-vertical-cli");
    const Mask page = render_ok({"--text", "縦書き、「日本語」。\nあいう（ー）Ab", "--direction", "ttb",
                                 "--font-size", "50"},
                                dir);
    // Two columns one em apart plus 16 px margins; the longer column is 10 em.
    EXPECT_EQ(page.width(), 2 * 50 + 32);
    EXPECT_EQ(page.height(), 10 * 50 + 32);
    expect_like_hb_view(page, "hbview_ttb_50.png");
}

TEST(RenderVerticalCli, BottomToTopPageMatchesHbView) {
    TempDir dir("bezel-vertical-cli");
    // Columns of equal length: hb-view starts every btt column at the top, bezel's Start puts
    // the first character at the bottom; they agree when no column is shorter.
    const Mask page =
        render_ok({"--text", "日本語、\nあいうえ", "--direction", "btt", "--font-size", "50"}, dir);
    expect_like_hb_view(page, "hbview_btt_50.png");
}

TEST(RenderVerticalCli, OneColumnIsTallerThanWideWithInkDownItsMiddle) {
    TempDir dir("bezel-vertical-cli");
    const Mask page =
        render_ok({"--text", "日本語の縦書き", "--direction", "ttb", "--font-size", "20", "--margin",
                   "4"},
                  dir);
    EXPECT_EQ(page.width(), 28);
    EXPECT_EQ(page.height(), 7 * 20 + 8);
    const Ink ink = ink_of(page);
    EXPECT_GT(ink.total, 255.0 * 300);
    EXPECT_NEAR(ink.x, 14, 1.5);        // about the centre line
    EXPECT_NEAR(ink.y, 74, 10);         // spread down the whole column
}

TEST(RenderVerticalCli, WidthWrapsColumnsAndTheFirstIsRightmost) {
    TempDir dir("bezel-vertical-cli");
    // 100 px columns of 20 px text: five characters each, three columns.
    const Mask page = render_ok({"--text", "日本語の縦書きあいうえおか", "--direction", "ttb",
                                 "--font-size", "20", "--margin", "0", "--width", "100"},
                                dir);
    EXPECT_EQ(page.width(), 60);
    EXPECT_EQ(page.height(), 100);
    const Ink right = ink_of(page, 40, 60), middle = ink_of(page, 20, 40), left = ink_of(page, 0, 20);
    EXPECT_GT(right.total, 0);
    EXPECT_GT(middle.total, 0);
    EXPECT_GT(left.total, 0);
    // The last column holds three characters: its ink stays in the top 60 px.
    EXPECT_LT(left.y, right.y);
    for (int y = 62; y < 100; ++y)
        for (int x = 0; x < 20; ++x) ASSERT_EQ(page.at(x, y), 255) << x << "," << y;
}

TEST(RenderVerticalCli, UnknownDirectionNamesTheChoices) {
    TempDir dir("bezel-vertical-cli");
    auto run = run_bezel({"render", kCjk, "--text", "日", "--direction", "up", "-o", "page.png"},
                         dir.path());
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_NE(run.err.find("--direction 'up': expected ltr, rtl, ttb, btt or auto"),
              std::string::npos)
        << run.err;
    EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace bezel
