// Internal: line break opportunities (UAX #14) and grapheme cluster boundaries (UAX #29), by
// ICU's break iterators, and the few character properties font fallback asks ICU for.
//
// ICU's root line rules are UAX #14's default algorithm, with its number tailoring (Example 7 of
// UAX #14, which Unicode's LineBreakTest.txt assumes too), and dictionaries for the scripts
// written without spaces (Thai, Lao, Khmer, Myanmar; CJK by dictionary where the rules allow).
// ICU's data is of the Unicode version it was built with (u_getUnicodeVersion).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "bezel/expected.hpp"

namespace bezel::text_detail {

// Spaces that hang at the end of a wrapped line (not placed, not counted in its width): the
// UAX #14 class SP and the other breaking spaces of Zs (U+1680, U+2000–U+200A but not U+2007,
// U+205F, U+3000), and tab.
bool is_break_space(char32_t cp);

// Binary character properties of ICU's Unicode data, for choosing a font per cluster.
enum class UnicodeProperty : std::uint8_t {
    EmojiPresentation,   // drawn as emoji (colour) by default (UTS #51 Emoji_Presentation)
};
// Errors only when ICU cannot be loaded.
Expected<bool> has_unicode_property(char32_t cp, UnicodeProperty property);

// One ICU break iterator of each kind, reused from text to text. Not thread-safe: one per thread
// (each ParagraphLayout has its own).
class UnicodeBreaks {
public:
    UnicodeBreaks();
    ~UnicodeBreaks();
    UnicodeBreaks(const UnicodeBreaks&) = delete;
    UnicodeBreaks& operator=(const UnicodeBreaks&) = delete;

    // out[k] = 1 when a line may break before text[k] (k in 1..n−1; out[0] = 0). Errors only
    // when ICU fails (its data missing, no memory).
    Status line_breaks(const char32_t* text, std::size_t n, std::vector<std::uint8_t>& out);
    // out[k] = 1 when a grapheme cluster starts at text[k] (out[0] = 1 for n > 0).
    Status grapheme_starts(const char32_t* text, std::size_t n, std::vector<std::uint8_t>& out);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace bezel::text_detail
