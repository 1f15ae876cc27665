// `--font-bold X` end to end (render, glyph, atlas): a bold page is the library's bold page,
// heavier and wider than the regular one; glyph and atlas JSON report the widened advance; bad
// values and combinations that cannot be drawn are usage errors (exit 2) that leave no file.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
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

// Ink on a white page: Σ (255 − v) / 255.
double ink(const Mask& page) {
    double sum = 0;
    for (std::uint8_t v : page.pixels()) sum += (255 - v) / 255.0;
    return sum;
}

TEST(FontBoldCli, RenderDrawsTheLibrarysBoldPageHeavierAndWider) {
    TempDir dir("bezel-bold-cli");
    const std::string text = "Hamburgefonts";
    auto run = run_bezel({"render", "--text", text, "--font-size", "30", "--margin", "2",
                          "--font-bold", "0.05", "-o", "bold.pgm"},
                         dir.path());
    ASSERT_EQ(run.exit_code, 0) << run.err;
    auto renderer = TextRenderer::open(kDejaVu);
    ASSERT_TRUE(renderer);
    TextRenderOptions o;
    o.shape.size_px = 30;
    o.layout.margin_px = 2;
    o.shape.bold = 0.05;
    auto bold = renderer->render_gray(text, o);
    o.shape.bold = 0;
    auto regular = renderer->render_gray(text, o);
    ASSERT_TRUE(bold && regular);
    auto pgm = encode_pgm(bold->view());
    EXPECT_TRUE(slurp(dir.path() / "bold.pgm") == std::string(pgm.begin(), pgm.end()));
    // Every advance grows by 0.05 × 30 = 1.5 px: the page is 13 × 1.5 = 19.5 px wider (its width
    // is the laid-out width rounded up), and the ink heavier by far more than rounding.
    EXPECT_GE(bold->width(), regular->width() + 19);
    EXPECT_LE(bold->width(), regular->width() + 20);
    EXPECT_EQ(bold->height(), regular->height());
    EXPECT_GT(ink(*bold), ink(*regular) * 1.25);
}

TEST(FontBoldCli, GlyphJsonReportsTheWidenedAdvanceAndTheGrownBox) {
    TempDir dir("bezel-bold-cli");
    auto glyph = [&](const std::vector<std::string>& extra) {
        std::vector<std::string> args = {"glyph", "--char", "H", "--font-size", "40", "-O", "json"};
        args.insert(args.end(), extra.begin(), extra.end());
        auto run = run_bezel(args, dir.path());
        EXPECT_EQ(run.exit_code, 0) << run.err;
        return nlohmann::json::parse(run.out).at(0);
    };
    const auto regular = glyph({});
    const auto bold = glyph({"--font-bold", "0.05"});
    EXPECT_DOUBLE_EQ(bold["advance"].get<double>(), regular["advance"].get<double>() + 2.0);
    // d = 0.05 × 40 / 2 = 1 px more on each side, then moved right and up by 1 px: the left
    // edge and the bottom stay, the right edge and the top move out by 2 px, a whole number of
    // pixels, so the box grows by exactly 2 on those sides.
    EXPECT_EQ(bold["left"].get<int>(), regular["left"].get<int>());
    EXPECT_EQ(bold["top"].get<int>(), regular["top"].get<int>() + 2);
    EXPECT_EQ(bold["height"].get<int>(), regular["height"].get<int>() + 2);
    EXPECT_EQ(bold["width"].get<int>(), regular["width"].get<int>() + 2);
    EXPECT_EQ(bold["overlap"], "accurate");
}

TEST(FontBoldCli, AtlasJsonReportsTheWidenedAdvance) {
    TempDir dir("bezel-bold-cli");
    auto atlas = [&](const std::vector<std::string>& extra, const std::string& name) {
        std::vector<std::string> args = {"atlas", kDejaVu, "--chars", "ao", "--font-size", "20",
                                         "-o", name + ".png", "--json", name + ".json"};
        args.insert(args.end(), extra.begin(), extra.end());
        auto run = run_bezel(args, dir.path());
        EXPECT_EQ(run.exit_code, 0) << run.err;
        return nlohmann::json::parse(slurp(dir.path() / (name + ".json")));
    };
    const auto regular = atlas({}, "regular");
    const auto bold = atlas({"--font-bold", "0.1"}, "bold");
    ASSERT_EQ(regular["glyphs"].size(), 2u);
    ASSERT_EQ(bold["glyphs"].size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_DOUBLE_EQ(bold["glyphs"][i]["advance"].get<double>(),
                         regular["glyphs"][i]["advance"].get<double>() + 2.0);
        EXPECT_GT(bold["glyphs"][i]["width"].get<int>(), regular["glyphs"][i]["width"].get<int>());
    }
}

TEST(FontBoldCli, BadValuesAreUsageErrorsAndLeaveNoFile) {
    TempDir dir("bezel-bold-cli");
    struct Case {
        std::vector<std::string> args;
        std::string mention;
    };
    const Case cases[] = {
        {{"render", kDejaVu, "x", "--font-bold", "-0.1", "-o", "out.png"},
         "--font-bold: -0.1 is not in 0 to 0.25"},
        {{"render", kDejaVu, "x", "--font-bold", "0.3", "-o", "out.png"},
         "--font-bold: 0.3 is not in 0 to 0.25"},
        {{"render", kDejaVu, "x", "--font-bold", "nan", "-o", "out.png"}, "--font-bold"},
        {{"render", kDejaVu, "x", "--font-bold", "bold", "-o", "out.png"},
         "--font-bold: 'bold' is not a number"},
        {{"render", kDejaVu, "x", "--font-bold", "0.05", "--stroke", "1", "-o", "out.png"},
         "--font-bold does not combine with --stroke"},
        {{"glyph", kDejaVu, "--char", "a", "--font-bold", "0.05", "--fill", "evenodd", "-o",
          "out.png"},
         "--font-bold needs --fill nonzero"},
        {{"glyph", kDejaVu, "--char", "a", "--font-bold", "1", "-o", "out.png"}, "--font-bold"},
        {{"atlas", kDejaVu, "--chars", "a", "--font-bold", "-1", "-o", "out.png"}, "--font-bold"},
    };
    for (const Case& c : cases) {
        auto run = run_bezel(c.args, dir.path());
        std::string joined;
        for (const std::string& a : c.args) joined += a + " ";
        EXPECT_EQ(run.exit_code, 2) << joined << "\n" << run.err;
        const std::string first = run.err.substr(0, run.err.find('\n'));
        EXPECT_NE(first.find(c.mention), std::string::npos) << joined << "\n" << run.err;
        EXPECT_EQ(run.out, "") << joined;
        EXPECT_TRUE(dir.entries().empty()) << joined;
    }
}

}  // namespace
}  // namespace bezel
