// Colour glyphs on the command line: render (a gray page becomes RGB only when it holds colour),
// glyph -O json/png (the rgba form), atlas --format rgba, --palette / --custom-palette, and info's
// colour tables and palettes.
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
const std::string kDejaVu = kFonts + "/dejavu-sans/DejaVuSans.ttf";
const std::string kCbdt = kFonts + "/noto-color-emoji/NotoColorEmoji-subset.ttf";
const std::string kTestGlyphs = kFonts + "/colour/test_glyphs-glyf_colr_1.ttf";
// DejaVu Sans's A and B, A with an SVG document (tests/data/colour/make_svg_font.py).
const std::string kSvgFont = std::string(BEZEL_SOURCE_DIR) + "/tests/data/colour/svg-glyph.ttf";

// The PNG colour type of a file's IHDR (0 gray, 2 RGB, 6 RGBA); -1 when it is no PNG.
int png_colour_type(const std::string& bytes) {
    if (bytes.size() < 26 || bytes.compare(1, 3, "PNG") != 0) return -1;
    return static_cast<unsigned char>(bytes[25]);
}

TEST(ColorCli, RenderMakesAGrayPageRgbOnlyWhenItHoldsAnEmoji) {
    TempDir dir;
    auto plain = run_bezel({"render", "--font", kDejaVu, "--font", kCbdt, "--text", "ab",
                            "--font-size", "24", "-o", "plain.png"},
                           dir.path());
    ASSERT_EQ(plain.exit_code, 0) << plain.err;
    EXPECT_EQ(png_colour_type(slurp(dir.path() / "plain.png")), 0);
    auto emoji = run_bezel({"render", "--font", kDejaVu, "--font", kCbdt, "--text",
                            "ab \U0001F600", "--font-size", "24", "-o", "emoji.png"},
                           dir.path());
    ASSERT_EQ(emoji.exit_code, 0) << emoji.err;
    EXPECT_EQ(emoji.err, "");
    EXPECT_EQ(png_colour_type(slurp(dir.path() / "emoji.png")), 2);
    // A transparent page keeps its alpha.
    auto clear = run_bezel({"render", "--font", kDejaVu, "--font", kCbdt, "--text",
                            "\U0001F600", "--background", "transparent", "-o", "clear.png"},
                           dir.path());
    ASSERT_EQ(clear.exit_code, 0) << clear.err;
    EXPECT_EQ(png_colour_type(slurp(dir.path() / "clear.png")), 6);
}

TEST(ColorCli, GlyphJsonGivesTheLibrarysPremultipliedRgba) {
    TempDir dir;
    auto run = run_bezel({"glyph", kTestGlyphs, "--text", "\U000F0E01", "--font-size", "32",
                          "-O", "json"},
                         dir.path());
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto doc = nlohmann::json::parse(run.out);
    ASSERT_EQ(doc.size(), 1u);
    const auto& g = doc[0];
    EXPECT_EQ(g["mode"], "rgba");
    const int width = g["width"], height = g["height"];
    ASSERT_EQ(static_cast<int>(g["rows"].size()), height);

    auto font = Font::open(kTestGlyphs);
    ASSERT_TRUE(font);
    GlyphRasterizer r(*font);
    GlyphRenderOptions o;
    o.size_px = 32;
    o.box = GlyphBoxMode::FreeType;
    auto prepared = r.prepare(*font->glyph_for_char(0xF0E01), o);
    ASSERT_TRUE(prepared);
    ASSERT_EQ(prepared->box.width, width);
    ASSERT_EQ(prepared->box.left, int(g["left"]));
    ASSERT_EQ(prepared->box.top, int(g["top"]));
    std::vector<std::uint8_t> px(4 * static_cast<std::size_t>(width) * height);
    ASSERT_TRUE(r.draw_rgba(*prepared, RgbaView{px.data(), width, height, 4 * width}));
    static const char kHex[] = "0123456789abcdef";
    for (int y = 0; y < height; ++y) {
        std::string hex;
        for (int x = 0; x < 4 * width; ++x) {
            const std::uint8_t v = px[static_cast<std::size_t>(y) * 4 * width + x];
            hex += kHex[v >> 4];
            hex += kHex[v & 15];
        }
        ASSERT_EQ(g["rows"][y], hex) << "row " << y;
    }
}

TEST(ColorCli, GlyphPngOfAColourGlyphIsRgb) {
    TempDir dir;
    auto run = run_bezel({"glyph", kCbdt, "--text", "\U0001F600", "--font-size", "40", "-o",
                          "emoji.png"},
                         dir.path());
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(png_colour_type(slurp(dir.path() / "emoji.png")), 2);
    auto coverage = run_bezel({"glyph", kCbdt, "--text", "\U0001F600", "--font-size", "40",
                               "--coverage", "-o", "raw.png"},
                              dir.path());
    ASSERT_EQ(coverage.exit_code, 0) << coverage.err;
    EXPECT_EQ(png_colour_type(slurp(dir.path() / "raw.png")), 6);
}

TEST(ColorCli, AtlasRgbaHoldsColourGlyphsAndSaysWhichAreColour) {
    TempDir dir;
    auto run = run_bezel({"atlas", "--font", kDejaVu, "--font", kCbdt, "--chars",
                          "a\U0001F600", "--format", "rgba", "-o", "atlas.png", "--json",
                          "atlas.json"},
                         dir.path());
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(png_colour_type(slurp(dir.path() / "atlas.png")), 6);
    const auto doc = nlohmann::json::parse(slurp(dir.path() / "atlas.json"));
    EXPECT_EQ(doc["format"], "rgba");
    ASSERT_EQ(doc["glyphs"].size(), 2u);
    EXPECT_EQ(doc["glyphs"][0]["color"], false);
    EXPECT_EQ(doc["glyphs"][1]["color"], true);
    EXPECT_EQ(doc["glyphs"][1]["font"], 1);
    // The default gray atlas still takes the emoji, as its alpha.
    auto gray = run_bezel({"atlas", "--font", kDejaVu, "--font", kCbdt, "--chars",
                           "a\U0001F600", "-o", "gray.png", "--json", "gray.json"},
                          dir.path());
    ASSERT_EQ(gray.exit_code, 0) << gray.err;
    EXPECT_EQ(png_colour_type(slurp(dir.path() / "gray.png")), 0);
}

TEST(ColorCli, PaletteOptionsAreCheckedAgainstTheFont) {
    TempDir dir;
    auto past = run_bezel({"glyph", kTestGlyphs, "--text", "\U000F0E01", "--palette", "3"},
                          dir.path());
    EXPECT_EQ(past.exit_code, 1);
    EXPECT_NE(past.err.find("has 3 palettes (0 to 2)"), std::string::npos) << past.err;
    auto entry = run_bezel({"glyph", kTestGlyphs, "--text", "\U000F0E01", "--custom-palette",
                            "20=red"},
                           dir.path());
    EXPECT_EQ(entry.exit_code, 1);
    EXPECT_NE(entry.err.find("entry 20"), std::string::npos) << entry.err;
    auto malformed = run_bezel({"glyph", kTestGlyphs, "--text", "\U000F0E01",
                                "--custom-palette", "x=red"},
                               dir.path());
    EXPECT_EQ(malformed.exit_code, 2);
    EXPECT_NE(malformed.err.find("--custom-palette: 'x=red'"), std::string::npos)
        << malformed.err;
    auto colour = run_bezel({"glyph", kTestGlyphs, "--text", "\U000F0E01", "--custom-palette",
                             "2=nocolour"},
                            dir.path());
    EXPECT_EQ(colour.exit_code, 2);
    // Another palette draws other pixels.
    auto first = run_bezel({"glyph", kTestGlyphs, "--text", "\U000F0E01", "-O", "json"},
                           dir.path());
    auto second = run_bezel({"glyph", kTestGlyphs, "--text", "\U000F0E01", "-O", "json",
                             "--palette", "2"},
                            dir.path());
    ASSERT_EQ(first.exit_code, 0) << first.err;
    ASSERT_EQ(second.exit_code, 0) << second.err;
    EXPECT_NE(first.out, second.out);
}

TEST(ColorCli, InfoListsColourTablesAndPalettes) {
    TempDir dir;
    auto text = run_bezel({"info", kTestGlyphs}, dir.path());
    ASSERT_EQ(text.exit_code, 0) << text.err;
    EXPECT_NE(text.out.find("colour       COLRv1"), std::string::npos) << text.out;
    EXPECT_NE(text.out.find("palette      2:"), std::string::npos) << text.out;
    auto json = run_bezel({"info", kCbdt, "-O", "json"}, dir.path());
    ASSERT_EQ(json.exit_code, 0) << json.err;
    const auto doc = nlohmann::json::parse(json.out);
    EXPECT_EQ(doc["color"]["formats"], nlohmann::json::array({"CBDT"}));
    EXPECT_TRUE(doc["color"]["palettes"].empty());
}

TEST(ColorCli, SvgGlyphsAreDrawnFromTheirOutlinesWithAWarning) {
    TempDir dir;
    auto render = run_bezel({"render", kSvgFont, "--text", "ABA", "-o", "svg.png"}, dir.path());
    ASSERT_EQ(render.exit_code, 0) << render.err;
    EXPECT_EQ(render.err, "bezel: warning: 2 glyphs are SVG colour glyphs, which bezel does not "
                          "paint: drawn from the outline\n");
    EXPECT_EQ(png_colour_type(slurp(dir.path() / "svg.png")), 0);   // outlines: a gray page
    auto glyph = run_bezel({"glyph", kSvgFont, "--char", "A", "--font-size", "12"}, dir.path());
    ASSERT_EQ(glyph.exit_code, 0) << glyph.err;
    EXPECT_NE(glyph.err.find("is an SVG colour glyph"), std::string::npos) << glyph.err;
    EXPECT_NE(glyph.out.find("@"), std::string::npos);   // the outline's ink
}

}  // namespace
}  // namespace bezel
