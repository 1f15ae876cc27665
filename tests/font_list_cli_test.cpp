// Font lists on the command line: --font (repeatable) and --fallback on render, glyph, atlas and
// info --coverage; each page equals the library's over the same FontCollection.
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

const std::string kFonts = BEZEL_FONTS_DIR;
const std::string kCantarell = kFonts + "/cantarell/Cantarell-Regular.otf";
const std::string kDejaVu = kFonts + "/dejavu-sans/DejaVuSans.ttf";
const std::string kArabic = kFonts + "/noto-arabic/NotoSansArabic-Regular.ttf";
const std::string kHebrew = kFonts + "/noto-hebrew/NotoSansHebrew-Regular.ttf";
const std::string kDevanagari = kFonts + "/noto-devanagari/NotoSansDevanagari-Regular.ttf";
const std::string kEdgeTtc = kFonts + "/edge-cases/EdgeCases.ttc";

const std::string kMixed = "Hi \u0645\u0631\u062D\u0628\u0627 \u05E9\u05DC\u05D5\u05DD \u0928\u092E\u0938\u094D\u0924\u0947";

TEST(FontListCli, RenderWithAFontListEqualsTheLibrarysPage) {
    TempDir dir;
    auto run = run_bezel({"render", "--font", kCantarell, "--fallback",
                          kArabic + "," + kHebrew + "," + kDevanagari, "--text", kMixed,
                          "--font-size", "24", "--margin", "2", "-o", "mixed.pgm"},
                         dir.path());
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.err, "");   // every character has a font: no warning

    auto fonts = FontCollection::open(
        {{kCantarell, 0, {}}, {kArabic, 0, {}}, {kHebrew, 0, {}}, {kDevanagari, 0, {}}});
    ASSERT_TRUE(fonts);
    auto renderer = TextRenderer::open(std::move(*fonts));
    ASSERT_TRUE(renderer);
    TextRenderOptions o;
    o.shape.size_px = 24;
    o.layout.margin_px = 2;
    auto page = renderer->render_gray(kMixed, o);
    ASSERT_TRUE(page);
    auto pgm = encode_pgm(page->view());
    EXPECT_TRUE(slurp(dir.path() / "mixed.pgm") == std::string(pgm.begin(), pgm.end()));
}

TEST(FontListCli, FontComesFirstThenEachFontOptionThenTheFallbacks) {
    // FONT Cantarell, --font DejaVu, --fallback Noto Arabic: Arabic from DejaVu (listed first).
    TempDir dir;
    auto run = run_bezel({"info", kCantarell, "--font", kDejaVu, "--fallback", kArabic,
                          "--coverage", "a\u0628\u05E9\u0928", "-O", "json"},
                         dir.path());
    ASSERT_EQ(run.exit_code, 0) << run.err;
    auto j = nlohmann::json::parse(run.out);
    ASSERT_EQ(j["fonts"].size(), 3u);
    EXPECT_EQ(j["fonts"][0], kCantarell);
    EXPECT_EQ(j["fonts"][1], kDejaVu);
    EXPECT_EQ(j["fonts"][2], kArabic);
    EXPECT_EQ(j["coverage"][0]["font"], 0);   // a
    EXPECT_EQ(j["coverage"][1]["font"], 1);   // ب from DejaVu
    EXPECT_EQ(j["coverage"][2]["font"], 1);   // ש from DejaVu
    EXPECT_TRUE(j["coverage"][3]["font"].is_null());   // न: no font of the list
    EXPECT_TRUE(j["coverage"][3]["gid"].is_null());
    EXPECT_EQ(j["missing"], 1);
}

TEST(FontListCli, AMissingCharacterNamesTheWholeListAndStrictFails) {
    TempDir dir;
    auto run = run_bezel({"render", "--font", kCantarell, "--font", kArabic, "--text",
                          "a\u0928", "-o", "out.png"},
                         dir.path());
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.err.find(kCantarell + ", " + kArabic + ": no glyph for U+0928"),
              std::string::npos)
        << run.err;
    auto strict = run_bezel({"render", "--font", kCantarell, "--font", kArabic, "--text",
                             "a\u0928", "--strict", "-o", "strict.png"},
                            dir.path());
    EXPECT_EQ(strict.exit_code, 1);
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "strict.png"));
}

TEST(FontListCli, GlyphAndAtlasTakeEachCharacterFromTheFirstFontThatHasIt) {
    TempDir dir;
    auto glyph = run_bezel({"glyph", "--font", kCantarell, "--font", kArabic, "--text",
                            "a\u0628", "--font-size", "8", "-O", "json"},
                           dir.path());
    ASSERT_EQ(glyph.exit_code, 0) << glyph.err;
    auto g = nlohmann::json::parse(glyph.out);
    ASSERT_EQ(g.size(), 2u);
    EXPECT_EQ(g[0]["font"], kCantarell);
    EXPECT_EQ(g[1]["font"], kArabic);
    auto arabic = Font::open(kArabic);
    ASSERT_TRUE(arabic);
    EXPECT_EQ(g[1]["gid"], *arabic->glyph_for_char(U'\u0628'));

    auto atlas = run_bezel({"atlas", "--font", kCantarell, "--fallback", kArabic, "--chars",
                            "a\u0628", "-o", "atlas.png", "--json", "atlas.json"},
                           dir.path());
    ASSERT_EQ(atlas.exit_code, 0) << atlas.err;
    auto a = nlohmann::json::parse(slurp(dir.path() / "atlas.json"));
    EXPECT_EQ(a["font"], kCantarell);
    ASSERT_EQ(a["fonts"].size(), 2u);
    EXPECT_EQ(a["glyphs"][0]["font"], 0);
    EXPECT_EQ(a["glyphs"][1]["font"], 1);
    EXPECT_EQ(a["glyphs"][1]["gid"], *arabic->glyph_for_char(U'\u0628'));
}

TEST(FontListCli, AFaceOfACollectionIsFileHashIndex) {
    TempDir dir;
    auto run = run_bezel({"info", "--font", kCantarell, "--fallback", kEdgeTtc + "#1",
                          "--coverage", "A", "-O", "json"},
                         dir.path());
    ASSERT_EQ(run.exit_code, 0) << run.err;
    auto j = nlohmann::json::parse(run.out);
    EXPECT_EQ(j["fonts"][1], kEdgeTtc);
}

TEST(FontListCli, BadListsAreClearErrors) {
    TempDir dir;
    struct Case {
        std::vector<std::string> args;
        int code;
        std::string message;
    };
    const std::vector<Case> cases = {
        {{"render", "--font", kCantarell, "--fallback", kFonts + "/nope.ttf", "--text", "a", "-o",
          "out.png"},
         1,
         "nope.ttf"},
        {{"render", "--font", kCantarell, "--fallback", kArabic + ",", "--text", "a", "-o",
          "out.png"},
         2,
         "an empty font name"},
        {{"glyph", "--font", kCantarell, "--font", kFonts + "/noto-color-emoji/NotoColorEmoji-subset.ttf",
          "--char", "a"},
         1,
         "bitmap-only"},
        {{"info", "--font", kCantarell, "--fallback", kArabic}, 2, "go with --coverage"},
    };
    for (const Case& c : cases) {
        auto run = run_bezel(c.args, dir.path());
        EXPECT_EQ(run.exit_code, c.code) << c.args[0] << " " << run.err;
        EXPECT_NE(run.err.find(c.message), std::string::npos) << run.err;
    }
    EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace bezel
