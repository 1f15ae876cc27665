// Whole-process work of the CLI (issue 33, item 7). --compression fast|default|small on the
// commands that write PNG: every level writes a valid PNG of the same pixels, the levels order
// the file sizes on a page of text (small <= default <= fast), and a value that is not a level is
// a usage error (exit 2) that writes nothing. And the command registry that builds only the
// command named on the command line knows each command by the name it gives itself.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "bezel/image.hpp"
#include "support/cli_run.hpp"

namespace bezel {
namespace {

using test::run_bezel;
using test::TempDir;

const std::string kDejaVu = BEZEL_FONTS_DIR "/dejavu-sans/DejaVuSans.ttf";
const std::string kPage = BEZEL_FONTS_DIR "/../tools/bench/render_page.txt";
const std::vector<std::string> kLevels = {"fast", "default", "small"};

// The page is tall enough (> 2 bands of 64 rows) for the banded gray writer, whose levels differ
// most; the colour page goes through libpng (RGB).
TEST(PngCompressionCli, EveryLevelWritesTheSamePixelsAndSmallIsSmallest) {
    TempDir dir("bezel-compression-cli");
    for (const std::string& colour : {std::string("#000000"), std::string("#800000")}) {
        std::vector<std::uintmax_t> sizes;
        std::vector<std::string> files;
        for (const std::string& level : kLevels) {
            const std::string file = level + ".png";
            auto run = run_bezel({"render", kDejaVu, "--text-file", kPage, "--font-size", "12",
                                  "--foreground", colour, "--compression", level, "-o", file},
                                 dir.path());
            ASSERT_EQ(run.exit_code, 0) << level << ": " << run.err;
            EXPECT_EQ(run.err, "");
            sizes.push_back(std::filesystem::file_size(dir.path() / file));
            files.push_back((dir.path() / file).string());
        }
        // read_png_gray converts RGB to gray: equal gray values of three files whose colour pixels
        // came from one renderer; the gray page's values are its pixels.
        auto fast = read_png_gray(files[0]);
        ASSERT_TRUE(fast) << fast.error().message;
        EXPECT_GT(fast->height(), 2 * kPngBandRows);
        for (std::size_t i = 1; i < files.size(); ++i) {
            auto other = read_png_gray(files[i]);
            ASSERT_TRUE(other) << kLevels[i] << ": " << other.error().message;
            EXPECT_TRUE(*other == *fast) << kLevels[i] << " has other pixels than fast";
        }
        EXPECT_LE(sizes[2], sizes[1]) << colour << ": small larger than default";
        EXPECT_LE(sizes[1], sizes[0]) << colour << ": default larger than fast";
        EXPECT_LT(sizes[2], sizes[0]) << colour << ": small no smaller than fast";
    }
}

// The other PNG writers take the option too and draw the same picture at every level.
TEST(PngCompressionCli, OtherCommandsAcceptEveryLevel) {
    TempDir dir("bezel-compression-cli");
    const std::vector<std::vector<std::string>> commands = {
        {"glyph", kDejaVu, "--char", "g", "--font-size", "40"},
        {"atlas", kDejaVu, "--chars", "abc", "--font-size", "20"},
        {"fill", "M 1 1 L 30 4 L 12 28 Z", "--width", "32", "--height", "32"},
    };
    for (const auto& base : commands) {
        std::vector<Mask> pictures;
        for (const std::string& level : kLevels) {
            auto args = base;
            const std::string file = base[0] + "-" + level + ".png";
            args.insert(args.end(), {"--compression", level, "-o", file});
            auto run = run_bezel(args, dir.path());
            ASSERT_EQ(run.exit_code, 0) << base[0] << " " << level << ": " << run.err;
            auto png = read_png_gray((dir.path() / file).string());
            ASSERT_TRUE(png) << png.error().message;
            pictures.push_back(std::move(*png));
        }
        EXPECT_TRUE(pictures[1] == pictures[0]) << base[0];
        EXPECT_TRUE(pictures[2] == pictures[0]) << base[0];
    }
}

TEST(PngCompressionCli, UnknownLevelIsAUsageError) {
    TempDir dir("bezel-compression-cli");
    for (const char* bad : {"9", "best", "", "FAST"}) {
        auto run = run_bezel({"render", "--text", "x", "--compression", bad, "-o", "x.png"},
                             dir.path());
        EXPECT_EQ(run.exit_code, 2) << bad;
        EXPECT_NE(run.err.find("--compression"), std::string::npos) << run.err;
        EXPECT_NE(run.err.find("fast,default,small"), std::string::npos) << run.err;
        EXPECT_TRUE(dir.entries().empty()) << bad;
    }
}

// `bezel NAME ...` builds only NAME's options; were the registry's name not the one the command
// gives itself, `bezel NAME --help` would fail or show another command.
TEST(CommandRegistry, EveryListedCommandRunsAloneUnderItsOwnName) {
    TempDir dir("bezel-registry-cli");
    auto all = run_bezel({"--help"}, dir.path());
    ASSERT_EQ(all.exit_code, 0) << all.err;
    const std::size_t at = all.out.find("Subcommands:");
    ASSERT_NE(at, std::string::npos) << all.out;
    std::istringstream lines(all.out.substr(at));
    std::string line;
    std::getline(lines, line);
    int listed = 0;
    while (std::getline(lines, line) && line.rfind("  ", 0) == 0) {
        std::istringstream words(line);
        std::string name;
        words >> name;
        auto help = run_bezel({name, "--help"}, dir.path());
        EXPECT_EQ(help.exit_code, 0) << name << ": " << help.err;
        EXPECT_NE(help.out.find("Usage: bezel " + name + " "), std::string::npos)
            << name << ": " << help.out.substr(0, 200);
        ++listed;
    }
    EXPECT_GE(listed, 12);
    // A misspelt command still names every command.
    auto typo = run_bezel({"rendr"}, dir.path());
    EXPECT_EQ(typo.exit_code, 2);
    EXPECT_NE(typo.err.find("atlas"), std::string::npos) << typo.err;
    EXPECT_NE(typo.err.find("outline"), std::string::npos) << typo.err;
}

}  // namespace
}  // namespace bezel
