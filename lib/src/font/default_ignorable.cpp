// Unicode's Default_Ignorable_Code_Point property, the coverage rule of font fallback
// (bezel/system_fonts.hpp). The ranges are DerivedCoreProperties.txt's for Unicode 15.0;
// tests/system_fonts_test.cpp compares every code point with the file Debian's unicode-data ships.
#include <algorithm>
#include <iterator>

#include "bezel/system_fonts.hpp"

namespace bezel {

namespace {

struct Range {
    char32_t first, last;  // inclusive
};

// Sorted and disjoint, so a binary search finds the only candidate range.
constexpr Range kDefaultIgnorable[] = {
    {0x00AD, 0x00AD},    // soft hyphen
    {0x034F, 0x034F},    // combining grapheme joiner
    {0x061C, 0x061C},    // Arabic letter mark
    {0x115F, 0x1160},    // Hangul choseong and jungseong fillers
    {0x17B4, 0x17B5},    // Khmer inherent vowels
    {0x180B, 0x180F},    // Mongolian free variation selectors, vowel separator
    {0x200B, 0x200F},    // ZWSP, ZWNJ, ZWJ, LRM, RLM
    {0x202A, 0x202E},    // bidi embeddings and overrides
    {0x2060, 0x206F},    // word joiner, invisible operators, isolates, deprecated format chars
    {0x3164, 0x3164},    // Hangul filler
    {0xFE00, 0xFE0F},    // variation selectors 1–16
    {0xFEFF, 0xFEFF},    // zero width no-break space
    {0xFFA0, 0xFFA0},    // halfwidth Hangul filler
    {0xFFF0, 0xFFF8},    // reserved
    {0x1BCA0, 0x1BCA3},  // shorthand format controls
    {0x1D173, 0x1D17A},  // musical symbol format controls
    {0xE0000, 0xE0FFF},  // tags, variation selectors 17–256, reserved
};

}  // namespace

bool is_default_ignorable(char32_t code_point) {
    // The first range whose end is at or past the code point is the only one that can hold it.
    const Range* r = std::lower_bound(std::begin(kDefaultIgnorable), std::end(kDefaultIgnorable),
                                      code_point,
                                      [](const Range& range, char32_t c) { return range.last < c; });
    return r != std::end(kDefaultIgnorable) && r->first <= code_point;
}

}  // namespace bezel
