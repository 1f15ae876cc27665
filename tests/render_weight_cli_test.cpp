// `bezel render --rendering / --gamma / --contrast`: each gives the library's pixels for the same
// CoverageCurveOptions, the default is heavier than linear dark on light and lighter light on
// dark, outlined text (--stroke) follows the choice too, and bad values are usage errors (exit 2,
// one line naming the option and the value, no file).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "bezel/text.hpp"
#include "support/cli_run.hpp"

namespace bezel {
namespace {

using test::run_bezel;
using test::slurp;
using test::TempDir;

const std::string kDejaVu = BEZEL_FONTS_DIR "/dejavu-sans/DejaVuSans.ttf";
const std::string kText = "Hamburgefonstiv 0123";

// The library's page for `text` at 10 px, margin 2, as PGM bytes.
std::string library_pgm(bool dark, const CoverageCurveOptions& coverage) {
    auto renderer = TextRenderer::open(kDejaVu);
    EXPECT_TRUE(renderer);
    if (!renderer) return {};
    TextRenderOptions o;
    o.shape.size_px = 10;
    o.layout.margin_px = 2;
    if (!dark) std::swap(o.foreground, o.background);
    o.coverage = coverage;
    auto page = renderer->render_gray(kText, o);
    EXPECT_TRUE(page) << page.error().message;
    if (!page) return {};
    auto pgm = encode_pgm(page->view());
    return std::string(pgm.begin(), pgm.end());
}

std::vector<std::string> render_args(bool dark, const std::vector<std::string>& extra) {
    std::vector<std::string> args = {"render", kDejaVu, kText, "--font-size", "10", "--margin",
                                     "2", "-o", "page.pgm"};
    if (!dark) args.insert(args.end(), {"--foreground", "#FFFFFF", "--background", "#000000"});
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
}

long long ink(const std::string& pgm, bool dark) {
    // After the "P5\nW H\n255\n" header: one byte per pixel.
    std::size_t at = 0;
    for (int lines = 0; lines < 3; ++lines) at = pgm.find('\n', at) + 1;
    long long sum = 0;
    for (std::size_t i = at; i < pgm.size(); ++i) {
        const auto v = static_cast<unsigned char>(pgm[i]);
        sum += dark ? 255 - v : v;
    }
    return sum;
}

TEST(RenderWeightCli, EachRenderingGivesTheLibrarysPixels) {
    TempDir dir("bezel-render-weight");
    CoverageCurveOptions linear, tuned;
    linear.rendering = TextRendering::Linear;
    tuned.gamma = 1.8;
    tuned.contrast = 0.3;
    struct Case {
        std::vector<std::string> extra;
        CoverageCurveOptions coverage;
    };
    const Case cases[] = {{{}, CoverageCurveOptions()},
                          {{"--rendering", "perceptual"}, CoverageCurveOptions()},
                          {{"--rendering", "linear"}, linear},
                          {{"--gamma", "1.8", "--contrast", "0.3"}, tuned}};
    for (bool dark : {true, false})
        for (const Case& c : cases) {
            auto run = run_bezel(render_args(dark, c.extra), dir.path());
            ASSERT_EQ(run.exit_code, 0) << run.err;
            EXPECT_EQ(slurp(dir.path() / "page.pgm"), library_pgm(dark, c.coverage))
                << (c.extra.empty() ? "(default)" : c.extra[0] + " " + c.extra[1]);
        }
}

TEST(RenderWeightCli, DefaultIsHeavierDarkOnLightAndLighterLightOnDarkThanLinear) {
    TempDir dir("bezel-render-weight");
    for (bool dark : {true, false}) {
        ASSERT_EQ(run_bezel(render_args(dark, {}), dir.path()).exit_code, 0);
        const long long perceptual = ink(slurp(dir.path() / "page.pgm"), dark);
        ASSERT_EQ(run_bezel(render_args(dark, {"--rendering", "linear"}), dir.path()).exit_code, 0);
        const long long linear = ink(slurp(dir.path() / "page.pgm"), dark);
        if (dark) {
            EXPECT_GT(perceptual, linear * 5 / 4);
        } else {
            EXPECT_LT(perceptual, linear * 4 / 5);
        }
        // Contrast adds weight in either polarity.
        ASSERT_EQ(run_bezel(render_args(dark, {"--contrast", "0.5"}), dir.path()).exit_code, 0);
        EXPECT_GT(ink(slurp(dir.path() / "page.pgm"), dark), perceptual);
    }
}

TEST(RenderWeightCli, OutlinedTextFollowsTheRendering) {
    TempDir dir("bezel-render-weight");
    auto run = run_bezel({"render", kDejaVu, "O", "--font-size", "40", "--stroke", "1", "-o",
                          "p.pgm"},
                         dir.path());
    ASSERT_EQ(run.exit_code, 0) << run.err;
    run = run_bezel({"render", kDejaVu, "O", "--font-size", "40", "--stroke", "1", "--rendering",
                     "linear", "-o", "l.pgm"},
                    dir.path());
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_GT(ink(slurp(dir.path() / "p.pgm"), true), ink(slurp(dir.path() / "l.pgm"), true));
}

TEST(RenderWeightCli, BadValuesAreUsageErrorsNamingTheOption) {
    TempDir dir("bezel-render-weight");
    struct BadCase {
        std::vector<std::string> extra;
        std::string mention;
    };
    const BadCase cases[] = {
        {{"--rendering", "gamma"}, "--rendering: 'gamma': expected perceptual or linear"},
        {{"--rendering", ""}, "--rendering"},
        {{"--gamma", "0.5"}, "--gamma: '0.5': must be >= 1 and <= 3"},
        {{"--gamma", "3.5"}, "--gamma: '3.5'"},
        {{"--gamma", "nan"}, "--gamma: 'nan'"},
        {{"--gamma", "dark"}, "--gamma: 'dark': not a number"},
        {{"--contrast", "-0.1"}, "--contrast: '-0.1': must be >= 0 and <= 1"},
        {{"--contrast", "2"}, "--contrast: '2'"},
        {{"--rendering", "linear", "--gamma", "1.5"}, "--gamma: tunes --rendering perceptual"},
        {{"--rendering", "linear", "--contrast", "0.2"}, "--contrast: tunes --rendering perceptual"},
    };
    for (const BadCase& c : cases) {
        auto run = run_bezel(render_args(true, c.extra), dir.path());
        std::string joined;
        for (const std::string& a : c.extra) joined += a + " ";
        EXPECT_EQ(run.exit_code, 2) << joined << "\n" << run.err;
        const std::string first = run.err.substr(0, run.err.find('\n'));
        EXPECT_EQ(first.rfind("bezel: ", 0), 0u) << joined << "\n" << run.err;
        EXPECT_NE(first.find(c.mention), std::string::npos) << joined << "\n" << run.err;
        EXPECT_EQ(dir.entries(), std::vector<std::string>{}) << joined;
    }
}

}  // namespace
}  // namespace bezel
