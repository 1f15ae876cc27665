// docs/cli.md reproduces each command's --help: every "## bezel <command>" section's first code
// block must be exactly what `bezel <command> --help` prints, with the bundled font's path shown
// as <bundled DejaVu Sans>, so the reference cannot drift from the tool.
// BEZEL_UPDATE_DOCS=1 rewrites the blocks from the binary instead of comparing.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <string>

#include "support/cli_run.hpp"

namespace bezel {
namespace {

using test::run_bezel;
using test::slurp;
using test::TempDir;

const std::string kDoc = BEZEL_SOURCE_DIR "/docs/cli.md";
const std::string kFontPlaceholder = "<bundled DejaVu Sans>";

std::string help_as_documented(const std::string& command, const TempDir& dir) {
    auto run = run_bezel({command, "--help"}, dir.path());
    EXPECT_EQ(run.exit_code, 0) << command << ": " << run.err;
    std::string text = run.out;
    const std::string font = BEZEL_FONTS_DIR "/dejavu-sans/DejaVuSans.ttf";   // the CLI's default
    for (std::size_t at = text.find(font); at != std::string::npos; at = text.find(font, at))
        text.replace(at, font.size(), kFontPlaceholder);
    return text;
}

// The first line where `documented` and `actual` part, both ways, for a readable failure.
std::string first_difference(const std::string& documented, const std::string& actual) {
    std::size_t a = 0, b = 0;
    while (a < documented.size() && b < actual.size()) {
        const std::size_t ea = documented.find('\n', a), eb = actual.find('\n', b);
        const std::string la = documented.substr(a, ea - a), lb = actual.substr(b, eb - b);
        if (la != lb) return "  docs: " + la + "\n  help: " + lb + "\n";
        if (ea == std::string::npos || eb == std::string::npos) break;
        a = ea + 1;
        b = eb + 1;
    }
    return "  (one ends before the other)\n";
}

TEST(HelpDocs, EveryCommandSectionShowsItsHelpVerbatim) {
    TempDir dir("bezel-help-docs");
    std::string doc = slurp(kDoc);
    ASSERT_FALSE(doc.empty()) << kDoc;
    const bool update = std::getenv("BEZEL_UPDATE_DOCS") != nullptr &&
                        std::string(std::getenv("BEZEL_UPDATE_DOCS")) == "1";
    const std::string heading = "\n## bezel ";
    int sections = 0;
    for (std::size_t at = doc.find(heading); at != std::string::npos;
         at = doc.find(heading, at + 1)) {
        const std::size_t name_start = at + heading.size();
        const std::string command = doc.substr(name_start, doc.find('\n', name_start) - name_start);
        const std::size_t next = doc.find(heading, name_start);
        const std::size_t open = doc.find("\n```\n", name_start);
        ASSERT_NE(open, std::string::npos) << command;
        ASSERT_TRUE(next == std::string::npos || open < next) << command << ": no help block";
        const std::size_t body = open + 5;
        const std::size_t close = doc.find("```\n", body);
        ASSERT_NE(close, std::string::npos) << command;
        const std::string expected = help_as_documented(command, dir);
        if (update) {
            doc.replace(body, close - body, expected);
        } else {
            const std::string documented = doc.substr(body, close - body);
            if (documented != expected)
                ADD_FAILURE() << "docs/cli.md, bezel " << command
                              << ": the help block differs from --help at\n"
                              << first_difference(documented, expected)
                              << "(BEZEL_UPDATE_DOCS=1 rewrites it)";
        }
        ++sections;
    }
    EXPECT_GE(sections, 12) << "one section per command";
    if (update) std::ofstream(kDoc, std::ios::binary) << doc;
}

}  // namespace
}  // namespace bezel
