// What the CLI says to a person (issue 33, item 5): numbers as people write them (no
// "0.000000", no "1e+01"), limits in words and numbers rather than constant names, malformed
// option values as usage errors (exit 2), and "did you mean" for a mistyped option or command.
#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <vector>

#include "support/cli_run.hpp"

namespace bezel {
namespace {

using test::CliRun;
using test::run_bezel;
using test::split_args;
using test::TempDir;

class MessagesCli : public ::testing::Test {
protected:
    CliRun run(const std::string& line) { return run_bezel(split_args(line), dir_.path()); }
    TempDir dir_{"bezel-messages-cli"};
};

// The first line of stderr, without "bezel: ".
std::string first_error(const CliRun& r) {
    const std::string line = r.err.substr(0, r.err.find('\n'));
    return line.rfind("bezel: ", 0) == 0 ? line.substr(7) : line;
}

// No message shows a constant's name (kMaxFillDim) or std::to_string's six decimals.
void expect_plain(const CliRun& r) {
    EXPECT_FALSE(std::regex_search(r.err, std::regex("\\bk[A-Z][A-Za-z]+"))) << r.err;
    EXPECT_FALSE(std::regex_search(r.err, std::regex("[0-9]\\.[0-9]{6}\\b"))) << r.err;
}

TEST_F(MessagesCli, RangeChecksPrintTheValueAndBoundsPlainly) {
    CliRun margin = run("render --margin -5 -o x.png");
    EXPECT_EQ(margin.exit_code, 2);
    EXPECT_EQ(first_error(margin), "--margin: -5 is not in 0 to 32768");
    CliRun height = run("render --line-height 101 -o x.png");
    EXPECT_EQ(first_error(height), "--line-height: 101 is not in 0 to 100");
    CliRun not_number = run("render --width wide -o x.png");
    EXPECT_EQ(not_number.exit_code, 2);
    EXPECT_EQ(first_error(not_number), "--width: 'wide' is not a number");
    CliRun tolerance = run("continuity 'M0 0 L1 1' --tolerance 0");
    EXPECT_EQ(tolerance.exit_code, 2);
    EXPECT_EQ(first_error(tolerance), "--tolerance: 0 is not a positive number");
    CliRun face = run("info --face-index -1");
    EXPECT_EQ(face.exit_code, 2);
    EXPECT_EQ(first_error(face), "--face-index: -1 is negative (expected 0 or more)");
    CliRun steps = run("surface --patch p.json --steps 0");
    EXPECT_EQ(first_error(steps), "--steps: 0 is not in 1 to 512");
    CliRun line_width = run("surface --patch p.json --line-width 100");
    EXPECT_EQ(first_error(line_width), "--line-width: 100 is not in 0.01 to 64");
    for (const CliRun* r : {&margin, &height, &tolerance, &face, &steps, &line_width}) expect_plain(*r);
}

TEST_F(MessagesCli, LimitsAreSaidInWordsAndNumbers) {
    // Each once leaked a constant's name or std::to_string's "%f" form.
    CliRun fill = run("fill 'M0,0 h1 v1 z' --width 8 --height 100000");
    EXPECT_EQ(fill.exit_code, 2);
    EXPECT_EQ(first_error(fill), "--height 100000: expected 1 to 8192 pixels");
    CliRun offset = run("glyph --char a --offset 1e9,0");
    EXPECT_EQ(first_error(offset), "--offset '1e9,0': beyond ±16384 px");
    CliRun pixels = run("glyph --text " + std::string(600, 'W') + " --font-size 300");
    EXPECT_EQ(pixels.exit_code, 1);
    EXPECT_NE(first_error(pixels).find("more than 16777216 pixels, the most one call renders"),
              std::string::npos)
        << pixels.err;
    // A page far past the limits: its size in whole pixels, and the limits.
    CliRun page = run("render --text 'xx' --font-size 10000 --width 32768 --margin 32768 -o p.png");
    EXPECT_EQ(page.exit_code, 1);
    EXPECT_TRUE(std::regex_search(first_error(page),
                                  std::regex("^text page of [0-9]+x[0-9]+ px is too large \\(at most "
                                             "32768 px a side, [0-9]+ px in all\\)$")))
        << page.err;
    CliRun outlined = run("render --text 'xx' --font-size 10000 --margin 32768 --stroke 1 -o p.png");
    EXPECT_EQ(outlined.exit_code, 1);
    EXPECT_TRUE(std::regex_search(first_error(outlined),
                                  std::regex("^outlined text page of [0-9]+x[0-9]+ px is too large")))
        << outlined.err;
    CliRun dashes = run("stroke 'M0,0 L1e6,0' --width 1 --dash 1e-6 -o never.path");
    EXPECT_EQ(dashes.exit_code, 1);
    for (const CliRun* r : {&fill, &offset, &pixels, &page, &outlined, &dashes}) expect_plain(*r);
}

TEST_F(MessagesCli, ContinuityPrintsPointsAsPlainNumbers) {
    // 10 once printed as "1e+01" (the shortest %g that reads back, at one digit).
    CliRun r = run("continuity 'M0 0 L10 0 L10 10 L100.5 10 L1e20 10'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find(" at 10,0: "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(" at 10,10: "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(" at 100.5,10: "), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("e+01"), std::string::npos) << r.out;
    // The angle of a right turn: every digit that reads back as the double.
    EXPECT_NE(r.out.find("[angle 1.5707963267948966 rad"), std::string::npos) << r.out;
    CliRun path = run("smooth --method natural --points '0,0 10,20 30,10' -O path");
    ASSERT_EQ(path.exit_code, 0) << path.err;
    EXPECT_EQ(path.out.find("e+"), std::string::npos) << path.out;
    EXPECT_EQ(path.out.rfind("M0 0C", 0), 0u) << path.out;
}

TEST_F(MessagesCli, MalformedScriptLanguageAndFeaturesAreUsageErrors) {
    struct Case {
        std::string args, says;
    };
    const Case cases[] = {
        {"--script Ar", "--script: script 'Ar': not an ISO 15924 tag (four letters, e.g. Arab)"},
        {"--script Xyzw", "--script: script 'Xyzw': not a script HarfBuzz knows"},
        {"--script Ar4b", "--script: script 'Ar4b': not an ISO 15924 tag"},
        {"--language 'en us'", "--language: language 'en us': not a BCP 47 tag"},
        {"--language -en", "--language: language '-en': not a BCP 47 tag"},
        {"--features kern=zz", "--features: feature 'kern=zz'"},
    };
    for (const Case& c : cases) {
        CliRun r = run("render --text x -o out.png " + c.args);
        EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
        EXPECT_EQ(first_error(r).rfind(c.says, 0), 0u) << c.args << "\n" << r.err;
        EXPECT_TRUE(dir_.entries().empty()) << c.args;
    }
    // Well-formed tags of known scripts, any case, and HarfBuzz's aliases (Hant is Han).
    for (const char* script : {"Latn", "latn", "ARAB", "Hant", "Zyyy"}) {
        CliRun r = run(std::string("render --text x -o out.png --script ") + script);
        EXPECT_EQ(r.exit_code, 0) << script << "\n" << r.err;
    }
    EXPECT_EQ(run("render --text x -o out.png --language sr-Latn").exit_code, 0);
}

TEST_F(MessagesCli, AMistypedOptionOrCommandGetsASuggestion) {
    CliRun option = run("render --font-sise 12");
    EXPECT_EQ(option.exit_code, 2);
    EXPECT_EQ(first_error(option), "unknown option --font-sise; did you mean --font-size?");
    EXPECT_NE(option.err.find("Run 'bezel render --help'"), std::string::npos) << option.err;
    // The value attached with '=' is not part of the name.
    EXPECT_EQ(first_error(run("render --forground=red")),
              "unknown option --forground; did you mean --foreground?");
    // A unique beginning of an option.
    EXPECT_EQ(first_error(run("render --backg red")),
              "unknown option --backg; did you mean --background?");
    // In an option group (glyph's --char/--gid/--text), and though the group then lacks its
    // required option, the misspelling is what is reported.
    EXPECT_EQ(first_error(run("glyph --chr a")), "unknown option --chr; did you mean --char?");
    // Nothing close: no guess.
    EXPECT_EQ(first_error(run("render --zzzzzz")), "unknown option --zzzzzz");
    EXPECT_EQ(first_error(run("render -x")), "unknown option -x");
    // Top-level options and commands.
    EXPECT_EQ(first_error(run("--verison")), "unknown option --verison; did you mean --version?");
    CliRun command = run("rendr 'Hello'");
    EXPECT_EQ(command.exit_code, 2);
    EXPECT_EQ(first_error(command).rfind("rendr: not a bezel command; did you mean render? (commands: ", 0),
              0u)
        << command.err;
    EXPECT_EQ(first_error(run("outlien --char a")).rfind("outlien: not a bezel command; did you mean outline?", 0),
              0u);
    EXPECT_EQ(first_error(run("paint")).rfind("paint: not a bezel command (commands: ", 0), 0u);
}

}  // namespace
}  // namespace bezel
