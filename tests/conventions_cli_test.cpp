// One convention across the CLI's commands (issue 33, item 4): pictures are ink on paper (black
// on white unless --foreground / --background say otherwise) and raw coverage is asked for by
// name (--coverage); a character the font has no glyph for is drawn as .notdef with one warning
// naming it, or with --strict is an error; colours are hex or any CSS colour name; a
// bitmap-only font is reported as such, naming the file, with the units per em of its head.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "bezel/image.hpp"
#include "support/cli_run.hpp"

namespace bezel {
namespace {

using test::CliRun;
using test::run_bezel;
using test::slurp;
using test::TempDir;

const std::string kDejaVu = BEZEL_FONTS_DIR "/dejavu-sans/DejaVuSans.ttf";
const std::string kEmoji = BEZEL_FONTS_DIR "/noto-color-emoji/NotoColorEmoji-subset.ttf";
const std::string kSaddle = BEZEL_SOURCE_DIR "/tests/data/surfaces/saddle.json";

class ConventionsCli : public ::testing::Test {
protected:
    CliRun run(const std::vector<std::string>& args) { return run_bezel(args, dir_.path()); }
    std::string file(const std::string& name) const { return (dir_.path() / name).string(); }
    TempDir dir_{"bezel-conventions-cli"};
};

// PNG's colour type (IHDR byte 9, at file offset 25): 0 gray, 2 RGB, 6 RGBA.
int png_colour_type(const std::string& bytes) {
    return bytes.size() > 25 ? static_cast<unsigned char>(bytes[25]) : -1;
}

// Every command that writes a picture, asked for a PNG into `out` with `extra` options.
std::vector<std::vector<std::string>> picture_commands(const std::string& out,
                                                       const std::vector<std::string>& extra) {
    std::vector<std::vector<std::string>> commands = {
        {"fill", "M2,2 L30,4 L16,28 Z", "--width", "32", "--height", "32"},
        {"glyph", kDejaVu, "--text", ".H", "--font-size", "24"},  // above the period: paper
        {"stroke", "M4,4 L28,28", "--width", "4"},
        {"smooth", "--method", "natural", "--points", "0,0 10,20 30,10"},
        {"intersect", "M0,0 L10,10", "M0,10 L10,0"},
        {"render", kDejaVu, "--text", "Hg", "--font-size", "24"},
    };
    for (auto& c : commands) {
        c.insert(c.end(), extra.begin(), extra.end());
        c.insert(c.end(), {"-o", out});
    }
    return commands;
}

TEST_F(ConventionsCli, EveryPictureIsBlackInkOnWhitePaperByDefault) {
    for (const auto& args : picture_commands(file("p.png"), {})) {
        CliRun r = run(args);
        ASSERT_EQ(r.exit_code, 0) << args[0] << ": " << r.err;
        EXPECT_EQ(png_colour_type(slurp(file("p.png"))), 0) << args[0];  // gray
        auto picture = read_png_gray(file("p.png"));
        ASSERT_TRUE(picture) << args[0];
        int darkest = 255;
        for (int y = 0; y < picture->height(); ++y)
            for (int x = 0; x < picture->width(); ++x) darkest = std::min<int>(darkest, picture->at(x, y));
        EXPECT_EQ(picture->at(0, 0), 255) << args[0] << ": the corner is paper";
        EXPECT_LT(darkest, 64) << args[0] << ": some ink is (nearly) black";
    }
}

TEST_F(ConventionsCli, ForegroundAndBackgroundColourEveryPicture) {
    // White on black: still gray, the paper now black.
    for (const auto& args : picture_commands(file("p.png"), {"--foreground", "white", "--background", "Black"})) {
        CliRun r = run(args);
        ASSERT_EQ(r.exit_code, 0) << args[0] << ": " << r.err;
        EXPECT_EQ(png_colour_type(slurp(file("p.png"))), 0) << args[0];
        auto picture = read_png_gray(file("p.png"));
        ASSERT_TRUE(picture) << args[0];
        EXPECT_EQ(picture->at(0, 0), 0) << args[0];
    }
    // CSS names beyond the old six, and colour: RGB; a translucent colour: RGBA.
    for (const auto& args : picture_commands(file("p.png"), {"--foreground", "yellow", "--background", "RebeccaPurple"})) {
        CliRun r = run(args);
        ASSERT_EQ(r.exit_code, 0) << args[0] << ": " << r.err;
        EXPECT_EQ(png_colour_type(slurp(file("p.png"))), 2) << args[0];
    }
    for (const auto& args : picture_commands(file("p.png"), {"--background", "#FFFFFF00"})) {
        CliRun r = run(args);
        ASSERT_EQ(r.exit_code, 0) << args[0] << ": " << r.err;
        EXPECT_EQ(png_colour_type(slurp(file("p.png"))), 6) << args[0];
    }
    // surface draws shaded pictures in its own colours, named the same way.
    CliRun surface = run({"surface", "--patch", kSaddle, "--size", "32x32", "--background", "lightyellow",
                          "--foreground", "teal", "-o", file("p.png")});
    EXPECT_EQ(surface.exit_code, 0) << surface.err;
    // A misspelt name is a usage error naming it, for every command.
    for (const auto& args : picture_commands(file("never.png"), {"--foreground", "yelow"})) {
        CliRun r = run(args);
        EXPECT_EQ(r.exit_code, 2) << args[0];
        EXPECT_NE(r.err.find("'yelow': not a CSS colour name"), std::string::npos) << args[0] << ": " << r.err;
    }
    EXPECT_TRUE(dir_.entries() == std::vector<std::string>{"p.png"});
}

TEST_F(ConventionsCli, GlyphPictureColoursArePaintedExactly) {
    // Colours that are not gray make a PPM: full coverage is exactly the ink, none exactly the
    // paper (the column between the two glyphs).
    CliRun r = run({"glyph", kDejaVu, "--text", "ll", "--font-size", "40", "--foreground", "navy",
                    "--background", "yellow", "-O", "pgm"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    ASSERT_EQ(r.out.rfind("P6\n", 0), 0u);
    int w = 0, h = 0;
    ASSERT_EQ(std::sscanf(r.out.c_str() + 3, "%d %d", &w, &h), 2);
    const std::size_t first = r.out.size() - std::size_t(w) * std::size_t(h) * 3;
    bool paper = false, ink = false;
    for (std::size_t i = first; i + 2 < r.out.size(); i += 3) {
        const std::string px = r.out.substr(i, 3);
        paper |= px == std::string("\xff\xff\x00", 3);  // yellow
        ink |= px == std::string("\x00\x00\x80", 3);     // navy
    }
    EXPECT_TRUE(ink);
    EXPECT_TRUE(paper);
}

// A binary PGM's width, height and pixels.
struct Pgm {
    int w = 0, h = 0;
    std::string px;
};
Pgm parse_pgm(const std::string& bytes) {
    Pgm p;
    int maxval = 0, consumed = 0;
    if (std::sscanf(bytes.c_str(), "P5 %d %d %d%n", &p.w, &p.h, &maxval, &consumed) != 3) return p;
    p.px = bytes.substr(static_cast<std::size_t>(consumed) + 1);
    return p;
}

TEST_F(ConventionsCli, GlyphMarginSurroundsTheSamePictureWithPaper) {
    CliRun plain = run({"glyph", kDejaVu, "--text", "Ag", "--font-size", "20", "-O", "pgm"});
    CliRun framed = run({"glyph", kDejaVu, "--text", "Ag", "--font-size", "20", "--margin", "3",
                         "-O", "pgm"});
    ASSERT_EQ(plain.exit_code, 0) << plain.err;
    ASSERT_EQ(framed.exit_code, 0) << framed.err;
    const Pgm a = parse_pgm(plain.out), b = parse_pgm(framed.out);
    ASSERT_EQ(b.w, a.w + 6);
    ASSERT_EQ(b.h, a.h + 6);
    ASSERT_EQ(b.px.size(), std::size_t(b.w) * std::size_t(b.h));
    for (int y = 0; y < b.h; ++y)
        for (int x = 0; x < b.w; ++x) {
            const char v = b.px[std::size_t(y) * b.w + x];
            const bool inside = x >= 3 && x < 3 + a.w && y >= 3 && y < 3 + a.h;
            const char want = inside ? a.px[std::size_t(y - 3) * a.w + (x - 3)] : '\xff';
            ASSERT_EQ(v, want) << x << "," << y;
        }
    CliRun bad = run({"glyph", "g", "--margin", "5000", "-o", file("g.png")});
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.err.find("--margin: 5000 is not in 0 to 4096"), std::string::npos) << bad.err;
}

TEST_F(ConventionsCli, CoverageIsAskedForByName) {
    // fill and glyph: --coverage is the coverage itself, 0 = empty, 255 = covered.
    CliRun fill = run({"fill", "M0,0 h4 v4 h-4 z", "--width", "8", "--height", "8", "--coverage", "-o", file("c.png")});
    ASSERT_EQ(fill.exit_code, 0) << fill.err;
    auto coverage = read_png_gray(file("c.png"));
    ASSERT_TRUE(coverage);
    EXPECT_EQ(coverage->at(1, 1), 255);
    EXPECT_EQ(coverage->at(6, 6), 0);
    CliRun glyph = run({"glyph", kDejaVu, "--char", "l", "--font-size", "40", "--coverage", "-o", file("g.png")});
    ASSERT_EQ(glyph.exit_code, 0) << glyph.err;
    auto g = read_png_gray(file("g.png"));
    ASSERT_TRUE(g);
    EXPECT_EQ(g->at(g->width() / 2, g->height() / 2), 255);
    // Coverage has no colours.
    for (const char* command : {"fill", "glyph"}) {
        std::vector<std::string> args = {command};
        if (args[0] == "fill") args.insert(args.end(), {"M0,0 h4 v4 h-4 z", "--width", "8", "--height", "8"});
        else args.insert(args.end(), {kDejaVu, "--char", "l"});
        args.insert(args.end(), {"--coverage", "--foreground", "red", "-o", file("never.png")});
        CliRun r = run(args);
        EXPECT_EQ(r.exit_code, 2) << command;
        EXPECT_NE(r.err.find("--coverage"), std::string::npos) << r.err;
    }
    // The atlas texture is coverage by nature, and says so.
    CliRun help = run({"atlas", "--help"});
    EXPECT_NE(help.out.find("coverage"), std::string::npos) << help.out;
}

TEST_F(ConventionsCli, MissingGlyphsWarnOnceNamingTheFirstAndDrawNotdef) {
    // 中 and 文 are not in DejaVu Sans.
    struct Case {
        std::vector<std::string> args;
        std::string output;
    };
    const Case cases[] = {
        {{"render", kDejaVu, "--text", "a\xe4\xb8\xad" "b\xe6\x96\x87", "-o", "out.png"}, "out.png"},
        {{"glyph", kDejaVu, "--text", "a\xe4\xb8\xad" "b\xe6\x96\x87", "-o", "out.png"}, "out.png"},
        {{"outline", kDejaVu, "--text", "a\xe4\xb8\xad" "b\xe6\x96\x87", "-o", "out.svg"}, "out.svg"},
        {{"atlas", kDejaVu, "--chars", "a\xe4\xb8\xad" "b\xe6\x96\x87", "-o", "out.png", "--json", "out.json"}, "out.json"},
    };
    for (const Case& c : cases) {
        CliRun r = run(c.args);
        EXPECT_EQ(r.exit_code, 0) << c.args[0] << ": " << r.err;
        EXPECT_EQ(r.err, "bezel: warning: " + kDejaVu +
                             ": no glyph for U+4E2D '\xe4\xb8\xad' (and 1 more character); drawn as .notdef\n")
            << c.args[0];
        EXPECT_TRUE(std::filesystem::exists(dir_.path() / c.output)) << c.args[0];
        std::filesystem::remove_all(dir_.path());
        std::filesystem::create_directories(dir_.path());

        std::vector<std::string> strict = c.args;
        strict.push_back("--strict");
        r = run(strict);
        EXPECT_EQ(r.exit_code, 1) << c.args[0];
        EXPECT_EQ(r.err, "bezel: " + kDejaVu +
                             ": no glyph for U+4E2D '\xe4\xb8\xad' (and 1 more character) (--strict)\n")
            << c.args[0];
        EXPECT_TRUE(dir_.entries().empty()) << c.args[0] << ": --strict writes nothing";
    }
    // --char follows the same policy: .notdef (gid 0) with the warning.
    CliRun one = run({"outline", kDejaVu, "--char", "U+4E2D", "-O", "json"});
    EXPECT_EQ(one.exit_code, 0) << one.err;
    EXPECT_EQ(nlohmann::json::parse(one.out)["glyphs"][0]["gid"], 0);
    EXPECT_NE(one.err.find("no glyph for U+4E2D"), std::string::npos) << one.err;
    // Text the font covers: not a word on stderr.
    CliRun covered = run({"render", kDejaVu, "--text", "Hello", "-o", "ok.png"});
    EXPECT_EQ(covered.exit_code, 0);
    EXPECT_EQ(covered.err, "");
}

TEST_F(ConventionsCli, BitmapOnlyFontIsNamedAndItsHeadUnitsPerEmReported) {
    // FreeType reports units per em 0 for a face without outlines; the head table says 2048.
    CliRun info = run({"info", kEmoji});
    ASSERT_EQ(info.exit_code, 0) << info.err;
    EXPECT_NE(info.out.find("units/em     2048\n"), std::string::npos) << info.out;
    EXPECT_NE(info.out.find("outlines     bitmap\n"), std::string::npos) << info.out;
    CliRun json = run({"info", kEmoji, "-O", "json"});
    ASSERT_EQ(json.exit_code, 0) << json.err;
    const auto doc = nlohmann::json::parse(json.out);
    EXPECT_EQ(doc["units_per_em"], 2048);
    EXPECT_GT(doc["ascender"].get<double>(), 0);
    EXPECT_LT(doc["descender"].get<double>(), 0);

    // Its glyphs are drawn as colour glyphs; its outlines, which it has not, are an error.
    const std::vector<std::vector<std::string>> drawn = {
        {"render", kEmoji, "--text", "\xf0\x9f\x98\x80", "-o", "out.png"},
        {"glyph", kEmoji, "--char", "U+1F600", "-o", "out.png"},
        {"atlas", kEmoji, "--chars", "\xf0\x9f\x98\x80", "-o", "out.png", "--json", "out.json"},
    };
    for (const auto& args : drawn) {
        CliRun r = run(args);
        EXPECT_EQ(r.exit_code, 0) << args[0] << ": " << r.err;
        EXPECT_EQ(r.err, "") << args[0];
        EXPECT_FALSE(dir_.entries().empty()) << args[0];
        for (const std::string& f : dir_.entries()) std::filesystem::remove(dir_.path() / f);
    }
    CliRun outline = run({"outline", kEmoji, "--char", "U+1F600", "-o", "out.svg"});
    EXPECT_EQ(outline.exit_code, 1);
    EXPECT_EQ(outline.err, "bezel: " + kEmoji +
                               ": a bitmap-only font (no outlines): its glyphs are colour "
                               "bitmaps, drawn only as colour glyphs\n");
    EXPECT_TRUE(dir_.entries().empty());
}

}  // namespace
}  // namespace bezel
