// Bidi conformance: every case of Unicode's BidiCharacterTest.txt (Debian's unicode-data) run
// through BidiParagraph (FriBidi) and bezel's own L1 end-of-line rule and L2 reordering, as layout
// uses them: paragraph level, resolved levels and visual order. A case may fail only where one of
// its characters has a different bidi class in the Unicode version of the test file than in
// FriBidi's data (the test says how many and which); every other case must pass.
#include <gtest/gtest.h>

#include <fribidi.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "text/bidi.hpp"
#include "text/script_runs.hpp"

namespace bezel::text_detail {
namespace {

const std::string kUnicodeDir = "/usr/share/unicode";

// Bidi_Class of every code point UnicodeData.txt lists (ranges given as First/Last pairs).
std::map<char32_t, std::string> unicode_bidi_classes() {
    std::map<char32_t, std::string> classes;
    std::ifstream in(kUnicodeDir + "/UnicodeData.txt");
    std::string line;
    char32_t range_first = 0;
    while (std::getline(in, line)) {
        std::vector<std::string> f;
        std::stringstream ss(line);
        for (std::string field; std::getline(ss, field, ';');) f.push_back(field);
        if (f.size() < 5) continue;
        const char32_t cp = static_cast<char32_t>(std::stoul(f[0], nullptr, 16));
        if (f[1].find(", First>") != std::string::npos) {
            range_first = cp;
            continue;
        }
        const char32_t first = f[1].find(", Last>") != std::string::npos ? range_first : cp;
        for (char32_t c = first; c <= cp; ++c) classes[c] = f[4];
    }
    return classes;
}

struct Case {
    std::u32string text;
    Direction direction = Direction::Auto;
    int paragraph_level = 0;
    std::vector<int> levels;          // −1: x (removed by X9)
    std::vector<std::size_t> order;   // visual order of the characters that are not x
};

bool parse_case(const std::string& line, Case& c) {
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string field; std::getline(ss, field, ';');) f.push_back(field);
    if (f.size() != 5) return false;
    std::stringstream cps(f[0]), levels(f[3]), order(f[4]);
    for (std::string hex; cps >> hex;) c.text.push_back(static_cast<char32_t>(std::stoul(hex, nullptr, 16)));
    c.direction = f[1] == "0" ? Direction::LeftToRight
                  : f[1] == "1" ? Direction::RightToLeft
                                : Direction::Auto;
    c.paragraph_level = std::stoi(f[2]);
    for (std::string l; levels >> l;) c.levels.push_back(l == "x" ? -1 : std::stoi(l));
    for (std::string i; order >> i;) c.order.push_back(std::stoul(i));
    return c.levels.size() == c.text.size();
}

// What bezel makes of the case: the whole paragraph as one line.
bool passes(BidiParagraph& bidi, const Case& c) {
    if (!bidi.resolve(c.text.data(), c.text.size(), c.direction)) return false;
    if (bidi.paragraph_level() != c.paragraph_level) return false;
    std::vector<std::uint8_t> line;
    bidi.line_levels(0, c.text.size(), line);
    std::vector<std::uint8_t> kept_levels;
    std::vector<std::size_t> kept;
    for (std::size_t i = 0; i < c.text.size(); ++i) {
        const bool removed = bidi.removed_by_x9(i);
        if (removed != (c.levels[i] < 0)) return false;
        if (removed) continue;
        if (line[i] != c.levels[i]) return false;
        kept.push_back(i);
        kept_levels.push_back(line[i]);
    }
    std::vector<std::size_t> order;
    visual_order(kept_levels, order);
    for (std::size_t k = 0; k < order.size(); ++k)
        if (k >= c.order.size() || kept[order[k]] != c.order[k]) return false;
    return order.size() == c.order.size();
}

TEST(BidiConformance, BidiCharacterTestPassesWhereFriBidisDataAgrees) {
    std::ifstream in(kUnicodeDir + "/BidiCharacterTest.txt");
    ASSERT_TRUE(in) << kUnicodeDir << "/BidiCharacterTest.txt (Debian's unicode-data)";
    const std::map<char32_t, std::string> classes = unicode_bidi_classes();
    ASSERT_GT(classes.size(), 100000u) << "UnicodeData.txt";
    BidiParagraph bidi;
    int total = 0, passed = 0, data_version = 0, unexplained = 0;
    std::string first_unexplained;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        Case c;
        ASSERT_TRUE(parse_case(line, c)) << line;
        ++total;
        if (passes(bidi, c)) {
            ++passed;
            continue;
        }
        bool newer = false;
        for (char32_t cp : c.text) {
            auto it = classes.find(cp);
            newer = newer || it == classes.end() ||
                    it->second != fribidi_get_bidi_type_name(fribidi_get_bidi_type(cp));
        }
        if (newer) {
            ++data_version;
        } else if (unexplained++ == 0) {
            first_unexplained = line;
        }
    }
    std::printf("BidiCharacterTest: %d of %d pass; %d fail on characters whose bidi class in "
                "FriBidi's data (Unicode %s) differs from UnicodeData.txt's\n",
                passed, total, data_version, fribidi_unicode_version);
    EXPECT_GT(total, 90000);
    EXPECT_EQ(unexplained, 0) << "first: " << first_unexplained;
    EXPECT_GE(passed, total * 99 / 100);
}

TEST(Bidi, TrailingWhitespaceOfALineTakesTheParagraphLevel) {
    // "abc def אב" in an RTL paragraph: the space between the Latin words is at their level, 2.
    // (Each case of BidiCharacterTest is one line ending with its paragraph, where FriBidi
    // applies L1 itself; this is a line that ends inside a paragraph.)
    const std::u32string text = U"abc def \u05d0\u05d1";
    BidiParagraph bidi;
    ASSERT_TRUE(bidi.resolve(text.data(), text.size(), Direction::RightToLeft));
    EXPECT_EQ(bidi.paragraph_level(), 1);
    std::vector<std::uint8_t> line;
    bidi.line_levels(0, text.size(), line);
    EXPECT_EQ(line, (std::vector<std::uint8_t>{2, 2, 2, 2, 2, 2, 2, 1, 1, 1}));
    // Wrapped after "abc ": that space ends a line and takes the paragraph level.
    bidi.line_levels(0, 4, line);
    EXPECT_EQ(line, (std::vector<std::uint8_t>{2, 2, 2, 1}));
    bidi.line_levels(4, text.size(), line);
    EXPECT_EQ(line, (std::vector<std::uint8_t>{2, 2, 2, 1, 1, 1}));
}

TEST(Bidi, AutoDirectionSkipsIsolates) {
    // P2 skips the isolate: the first strong character outside it is the Hebrew letter.
    const std::u32string text = U"\u2066abc\u2069 \u05d0";
    BidiParagraph bidi;
    ASSERT_TRUE(bidi.resolve(text.data(), text.size(), Direction::Auto));
    EXPECT_EQ(bidi.paragraph_level(), 1);
    ASSERT_TRUE(bidi.resolve(U"123", 3, Direction::Auto));
    EXPECT_EQ(bidi.paragraph_level(), 0) << "no strong character: left to right";
}

}  // namespace
}  // namespace bezel::text_detail
