// The lone-word rule of the font commands (render, glyph, outline, atlas, info): one positional
// word that is no file is the text in the default font, exactly as if given with the command's
// text option; one that looks like a font path but is not there is a missing font (exit 1) with a
// hint to that option; a file that exists stays the font.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/cli_run.hpp"

namespace bezel {
namespace {

using test::CliRun;
using test::run_bezel;
using test::slurp;
using test::TempDir;

const std::string kDejaVu = BEZEL_FONTS_DIR "/dejavu-sans/DejaVuSans.ttf";

struct Equivalence {
    std::vector<std::string> lone_word;   // the word alone
    std::vector<std::string> with_font;   // the bundled font named, then the word
    std::vector<std::string> explicit_;   // the word through the text option
    std::string text_option;
};

const Equivalence kCommands[] = {
    {{"render", "Hello", "-o", "out.pgm"},
     {"render", kDejaVu, "Hello", "-o", "out.pgm"},
     {"render", "--text", "Hello", "-o", "out.pgm"},
     "--text"},
    {{"glyph", "Ab", "--font-size", "12"},
     {"glyph", kDejaVu, "Ab", "--font-size", "12"},
     {"glyph", "--text", "Ab", "--font-size", "12"},
     "--text"},
    {{"outline", "g", "-O", "json"},
     {"outline", kDejaVu, "g", "-O", "json"},
     {"outline", "--text", "g", "-O", "json"},
     "--text"},
    {{"atlas", "0123", "-o", "out.png", "--json", "-"},
     {"atlas", kDejaVu, "0123", "-o", "out.png", "--json", "-"},
     {"atlas", "--chars", "0123", "-o", "out.png", "--json", "-"},
     "--chars"},
    {{"info", "Hello"},
     {"info", kDejaVu, "Hello"},
     {"info", "--coverage", "Hello"},
     "--coverage"},
};

// stdout and the output file, if any, of a run that must succeed.
std::string outputs(const std::vector<std::string>& args, const TempDir& dir) {
    CliRun run = run_bezel(args, dir.path());
    EXPECT_EQ(run.exit_code, 0) << args[0] << ": " << run.err;
    return run.out + "\n--\n" + slurp(dir.path() / "out.pgm") + slurp(dir.path() / "out.png");
}

TEST(LoneWord, IsTheTextInTheDefaultFontForEveryFontCommand) {
    for (const Equivalence& c : kCommands) {
        TempDir dir("bezel-lone-word");
        const std::string alone = outputs(c.lone_word, dir);
        EXPECT_TRUE(alone == outputs(c.explicit_, dir)) << c.lone_word[0] << " vs " << c.text_option;
        EXPECT_TRUE(alone == outputs(c.with_font, dir)) << c.lone_word[0] << " with FONT";
        EXPECT_GT(alone.size(), 10u) << c.lone_word[0];
    }
}

TEST(LoneWord, ThatLooksLikeAFontPathIsAMissingFontWithAHint) {
    for (const Equivalence& c : kCommands) {
        TempDir dir("bezel-lone-word");
        for (const std::string& word : {std::string("Missing.TTF"), std::string("fonts/Nothing")}) {
            std::vector<std::string> args = c.lone_word;
            args[1] = word;
            CliRun run = run_bezel(args, dir.path());
            EXPECT_EQ(run.exit_code, 1) << args[0] << " " << word;
            EXPECT_EQ(run.err, "bezel: " + word +
                                   ": no such font file (to use these words as text, give them "
                                   "with " + c.text_option + ")\n")
                << args[0];
            EXPECT_TRUE(dir.entries().empty()) << args[0] << ": no output file";
        }
    }
}

TEST(LoneWord, GlyphCommandsNeedExactlyOneWayOfChoosingGlyphs) {
    TempDir dir("bezel-lone-word");
    for (const char* command : {"glyph", "outline"}) {
        CliRun none = run_bezel({command}, dir.path());
        EXPECT_EQ(none.exit_code, 2) << command;
        EXPECT_EQ(none.err.rfind("bezel: no glyph given: give exactly one of --char, --gid, "
                                 "--text or TEXT\n", 0), 0u)
            << none.err;
        CliRun two = run_bezel({command, kDejaVu, "ab", "--char", "a"}, dir.path());
        EXPECT_EQ(two.exit_code, 2) << command;
        EXPECT_NE(two.err.find("more than one way"), std::string::npos) << two.err;
    }
    CliRun atlas = run_bezel({"atlas", "-o", "out.png"}, dir.path());
    EXPECT_EQ(atlas.exit_code, 2);
    EXPECT_NE(atlas.err.find("no characters given"), std::string::npos) << atlas.err;
    EXPECT_TRUE(dir.entries().empty());
}

TEST(InfoCoverage, ListsEachCharacterOnceWithItsGlyphOrMissing) {
    TempDir dir("bezel-lone-word");
    // DejaVu Sans maps Latin and Greek but no Han.
    CliRun run = run_bezel({"info", "--coverage", "a\u03b1a\u6f22", "-O", "json"}, dir.path());
    ASSERT_EQ(run.exit_code, 0) << run.err;
    auto doc = nlohmann::json::parse(run.out);
    EXPECT_EQ(doc["file"], kDejaVu);
    EXPECT_EQ(doc["characters"], 3);
    EXPECT_EQ(doc["missing"], 1);
    ASSERT_EQ(doc["coverage"].size(), 3u);
    EXPECT_EQ(doc["coverage"][0]["code_point"], "U+0061");
    EXPECT_EQ(doc["coverage"][0]["gid"], 68);
    EXPECT_EQ(doc["coverage"][1]["code_point"], "U+03B1");
    EXPECT_TRUE(doc["coverage"][1]["gid"].is_number());
    EXPECT_EQ(doc["coverage"][2]["code_point"], "U+6F22");
    EXPECT_TRUE(doc["coverage"][2]["gid"].is_null());

    run = run_bezel({"info", "--coverage", "a\u6f22"}, dir.path());
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.out.find("covered  1 of 2 characters\n"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("  U+6F22   \u6f22  missing\n"), std::string::npos) << run.out;

    run = run_bezel({"info", kDejaVu, "ab", "--coverage", "c"}, dir.path());
    EXPECT_EQ(run.exit_code, 2) << run.err;
    run = run_bezel({"info", "--coverage", "\xc3\x28"}, dir.path());
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_NE(run.err.find("--coverage"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace bezel
