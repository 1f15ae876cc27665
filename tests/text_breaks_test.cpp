// Line break and grapheme cluster conformance: every case of Unicode's LineBreakTest.txt and
// GraphemeBreakTest.txt (Debian's unicode-data, auxiliary/) through UnicodeBreaks (ICU), as
// layout uses it. Every grapheme case must pass; a line break case may fail only where ICU's
// tailoring of numbers that start with a hyphen or a separator differs from UAX #14's default, or
// where a character is unassigned in ICU's Unicode version. The counts are printed.
#include <gtest/gtest.h>

#include <unicode/uchar.h>
#include <unicode/uversion.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "text/layout_breaks.hpp"

namespace bezel::text_detail {
namespace {

const std::string kAuxiliary = "/usr/share/unicode/auxiliary/";

// "× 0023 × 0020 ÷ 0023 ÷\t# ...": the code points, and whether a boundary comes before each
// (expected[k] for text[k]; the leading and trailing marks are the text's ends).
struct Case {
    std::u32string text;
    std::vector<std::uint8_t> expected;
};

bool parse_case(const std::string& line, Case& c) {
    std::stringstream ss(line.substr(0, line.find('#')));
    bool boundary = false;
    for (std::string word; ss >> word;) {
        if (word == "\xc3\xb7") {   // ÷
            boundary = true;
        } else if (word == "\xc3\x97") {   // ×
            boundary = false;
        } else {
            c.text.push_back(static_cast<char32_t>(std::stoul(word, nullptr, 16)));
            c.expected.push_back(boundary ? 1 : 0);
        }
    }
    return !c.text.empty();
}

bool assigned_in_icu(char32_t c) { return u_charType(static_cast<UChar32>(c)) != U_UNASSIGNED; }

int line_break_class(char32_t c) {
    return u_getIntPropertyValue(static_cast<UChar32>(c), UCHAR_LINE_BREAK);
}

// ICU's line rules treat a hyphen-minus or an infix separator (HY, IS: "-", ",", ".") before a
// digit as the start of a number: "-5" and ".35" are kept together with what follows and may
// be broken before, after spaces (UAX #14 with its Example 7 number tailoring breaks after them
// before a letter or, after IS, a digit, and never before an IS). A case fails for that reason
// alone when every boundary ICU leaves out comes after HY or IS (marks between count as the
// character, LB9) and every boundary ICU adds is before an IS that a digit follows.
bool only_icu_number_start_tailoring(const Case& c, const std::vector<std::uint8_t>& got) {
    const std::size_t n = c.text.size();
    for (std::size_t k = 0; k < n; ++k) {
        if (got[k] == c.expected[k]) continue;
        if (got[k] != 0) {
            if (line_break_class(c.text[k]) != U_LB_INFIX_NUMERIC || k + 1 >= n ||
                line_break_class(c.text[k + 1]) != U_LB_NUMERIC)
                return false;
            continue;
        }
        std::size_t j = k;
        while (j > 0 && line_break_class(c.text[j - 1]) == U_LB_COMBINING_MARK) --j;
        if (j == 0) return false;
        const int lb = line_break_class(c.text[j - 1]);
        if (lb != U_LB_HYPHEN && lb != U_LB_INFIX_NUMERIC) return false;
    }
    return true;
}

struct Tally {
    int total = 0, passed = 0, unassigned = 0, tailored = 0, other = 0;
    std::string first_other;
};

template <typename Breaks>
Tally run_file(const std::string& file, Breaks&& breaks) {
    Tally t;
    std::ifstream in(kAuxiliary + file);
    EXPECT_TRUE(in) << kAuxiliary << file << " (Debian's unicode-data)";
    std::vector<std::uint8_t> got;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        Case c;
        if (!parse_case(line, c)) continue;
        ++t.total;
        EXPECT_TRUE(breaks(c.text, got)) << line;
        if (got == c.expected) {
            ++t.passed;
            continue;
        }
        bool unassigned = false;
        for (char32_t cp : c.text) unassigned = unassigned || !assigned_in_icu(cp);
        if (got.size() == c.expected.size() && only_icu_number_start_tailoring(c, got)) {
            ++t.tailored;
        } else if (unassigned) {
            ++t.unassigned;
        } else if (t.other++ == 0) {
            t.first_other = line;
        }

    }
    return t;
}

std::string icu_unicode_version() {
    UVersionInfo v;
    u_getUnicodeVersion(v);
    char text[U_MAX_VERSION_STRING_LENGTH];
    u_versionToString(v, text);
    return text;
}

TEST(BreakConformance, LineBreakTestPasses) {
    UnicodeBreaks breaks;
    const Tally t = run_file("LineBreakTest.txt", [&](const std::u32string& s, auto& out) {
        return breaks.line_breaks(s.data(), s.size(), out).ok();
    });
    std::printf("LineBreakTest: %d of %d pass (ICU %s, Unicode %s); %d differ only by ICU's "
                "tailoring of numbers that start with - , or .; %d fail with characters ICU's data does not assign\n",
                t.passed, t.total, U_ICU_VERSION, icu_unicode_version().c_str(), t.tailored,
                t.unassigned);
    EXPECT_GT(t.total, 7000);
    EXPECT_EQ(t.other, 0) << "first: " << t.first_other;
    EXPECT_LE(t.tailored, 30) << "ICU's tailoring explains a few cases, not a class of them";
}

TEST(BreakConformance, GraphemeBreakTestPasses) {
    UnicodeBreaks breaks;
    const Tally t = run_file("GraphemeBreakTest.txt", [&](const std::u32string& s, auto& out) {
        return breaks.grapheme_starts(s.data(), s.size(), out).ok();
    });
    std::printf("GraphemeBreakTest: %d of %d pass (ICU %s, Unicode %s); %d fail with characters "
                "ICU's data does not assign\n",
                t.passed, t.total, U_ICU_VERSION, icu_unicode_version().c_str(), t.unassigned);
    EXPECT_GT(t.total, 600);
    EXPECT_EQ(t.tailored + t.unassigned + t.other, 0) << "first: " << t.first_other;
}

TEST(Breaks, ThaiIsBrokenBetweenWordsByDictionary) {
    // "สวัสดีครับ" (hello, polite): two words, no space; ICU's dictionary breaks between them.
    const std::u32string thai = U"\u0e2a\u0e27\u0e31\u0e2a\u0e14\u0e35\u0e04\u0e23\u0e31\u0e1a";
    UnicodeBreaks breaks;
    std::vector<std::uint8_t> out;
    ASSERT_TRUE(breaks.line_breaks(thai.data(), thai.size(), out));
    EXPECT_EQ(out, (std::vector<std::uint8_t>{0, 0, 0, 0, 0, 0, 1, 0, 0, 0}));
}

TEST(Breaks, AClusterOfABaseAndItsMarksOrAnEmojiSequenceIsOne) {
    UnicodeBreaks breaks;
    std::vector<std::uint8_t> out;
    // e + combining acute, then a family emoji (ZWJ sequence), then a flag (two regional
    // indicators).
    const std::u32string text = U"e\u0301\U0001F468\u200D\U0001F469\u200D\U0001F467\U0001F1EB\U0001F1F7";
    ASSERT_TRUE(breaks.grapheme_starts(text.data(), text.size(), out));
    EXPECT_EQ(out, (std::vector<std::uint8_t>{1, 0, 1, 0, 0, 0, 0, 1, 0}));
}

}  // namespace
}  // namespace bezel::text_detail
