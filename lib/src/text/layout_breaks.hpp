// Internal: line break opportunities, a small subset of UAX #14.
//
// A line may break before code point i when
//   - i follows a run of spaces (U+0020, tab, U+1680, U+2000–U+200A but not U+2007, U+205F,
//     U+3000) or a zero width space U+200B;
//   - i follows a hyphen (U+002D, U+2010, U+2012, U+2013) that follows a non-space;
//   - i or the code point before it is an ideograph (Han, Hiragana, Katakana, Bopomofo, CJK
//     symbols and fullwidth forms);
// never before a space, a combining mark or closing punctuation (".,:;!?)]}" and their CJK and
// fullwidth forms), never after opening punctuation ("([{" and CJK brackets), and never around
// a no-break space (U+00A0, U+202F, U+2060, U+FEFF).
// Left out: the rest of UAX #14's classes (quotation marks, numeric prefixes and postfixes,
// Thai/Lao/Khmer dictionary breaking, Hangul syllable rules, emoji sequences).
#pragma once

#include <cstddef>
#include <vector>

#include "text/script_runs.hpp"

namespace bezel::text_detail {

bool is_break_space(char32_t cp);

// Sets out[k] = 1 when a line may break before cps[begin + k] (k in 1..n−1; out[0] = 0).
void break_opportunities(const std::vector<CodePoint>& cps, std::size_t begin, std::size_t end,
                         std::vector<std::uint8_t>& out);

}  // namespace bezel::text_detail
