// Font lists on the command line: --font (repeatable) and --fallback on render, glyph, atlas and
// info --coverage; each page equals the library's over the same FontCollection.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
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

// A fontconfig configuration of some fonts-test folders, with its cache in `dir`: system fonts
// that are the same on every machine.
std::string write_fontconfig(const TempDir& dir, const std::vector<std::string>& folders) {
    std::string conf = "<?xml version=\"1.0\"?>\n<!DOCTYPE fontconfig SYSTEM \"fonts.dtd\">\n<fontconfig>\n";
    for (const std::string& f : folders) conf += "  <dir>" + kFonts + "/" + f + "</dir>\n";
    conf += "  <cachedir>" + (dir.path() / "fc-cache").string() + "</cachedir>\n</fontconfig>\n";
    const std::string file = (dir.path() / "fonts.conf").string();
    std::ofstream(file) << conf;
    return "FONTCONFIG_FILE=" + file;
}

TEST(FontListCli, SystemFontsDrawWhatTheListLacksUnlessTurnedOff) {
    TempDir dir;
    const std::string env = write_fontconfig(dir, {"noto-arabic", "noto-devanagari"});
    // Cantarell alone has no Devanagari: the system's Noto Sans Devanagari draws it.
    auto run = run_bezel({"info", "--font", kCantarell, "--coverage",
                          "a\u0928\u092E", "-O", "json"},
                         dir.path(), {env});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    auto j = nlohmann::json::parse(run.out);
    ASSERT_EQ(j["fonts"].size(), 2u);
    EXPECT_EQ(j["fonts"][1], kDevanagari);
    EXPECT_EQ(j["coverage"][1]["font"], 1);
    EXPECT_EQ(j["missing"], 0);
    // The render draws it (no warning); with --no-system-fonts it is missing.
    auto drawn = run_bezel({"render", kCantarell, "--text", "a\u0928\u092E", "-o", "a.png"},
                           dir.path(), {env});
    ASSERT_EQ(drawn.exit_code, 0) << drawn.err;
    EXPECT_EQ(drawn.err, "");
    auto off = run_bezel({"render", kCantarell, "--text", "a\u0928\u092E", "--no-system-fonts",
                          "-o", "b.png"},
                         dir.path(), {env});
    ASSERT_EQ(off.exit_code, 0) << off.err;
    EXPECT_NE(off.err.find("no glyph for U+0928"), std::string::npos) << off.err;
    // glyph takes the character from the system font too.
    auto glyph = run_bezel({"glyph", kCantarell, "--char", "\u0928", "-O", "json", "--font-size", "8"},
                           dir.path(), {env});
    ASSERT_EQ(glyph.exit_code, 0) << glyph.err;
    EXPECT_EQ(nlohmann::json::parse(glyph.out)[0]["font"], kDevanagari);
}

TEST(FontListCli, FontFamilyPicksAnInstalledFont) {
    TempDir dir;
    const std::string env = write_fontconfig(dir, {"cantarell", "dejavu-sans", "noto-hebrew"});
    auto run = run_bezel({"info", "--font-family", "Cantarell", "--coverage", "a", "-O", "json"},
                         dir.path(), {env});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    auto j = nlohmann::json::parse(run.out);
    EXPECT_EQ(j["file"], kCantarell);
    // The page equals one drawn from the file itself.
    auto by_family = run_bezel({"render", "--font-family", "Cantarell", "--text", "Hamburg",
                                "-o", "family.pgm"},
                               dir.path(), {env});
    auto by_file = run_bezel({"render", kCantarell, "--text", "Hamburg", "-o", "file.pgm"},
                             dir.path(), {env});
    ASSERT_EQ(by_family.exit_code, 0) << by_family.err;
    ASSERT_EQ(by_file.exit_code, 0) << by_file.err;
    EXPECT_TRUE(slurp(dir.path() / "family.pgm") == slurp(dir.path() / "file.pgm"));
    // A pattern fontconfig rejects is an error naming it.
    auto bad = run_bezel({"render", "--font-family", "Cantarell:blod", "--text", "a", "-o", "x.png"},
                         dir.path(), {env});
    EXPECT_EQ(bad.exit_code, 1);
    EXPECT_NE(bad.err.find("Cantarell:blod"), std::string::npos) << bad.err;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "x.png"));
}

TEST(FontListCli, ABareEnvironmentStillDrawsWithTheBundledFonts) {
    // The tests' default: a fontconfig configuration with no fonts at all.
    TempDir dir;
    auto run = run_bezel({"render", "--text", "Hi \u0928", "-o", "bare.png"}, dir.path());
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.err.find("no glyph for U+0928"), std::string::npos) << run.err;
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "bare.png"));
    auto family = run_bezel({"render", "--font-family", "Noto Sans", "--text", "a", "-o", "f.png"},
                            dir.path());
    EXPECT_EQ(family.exit_code, 1);
    EXPECT_NE(family.err.find("--font-family"), std::string::npos) << family.err;
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
