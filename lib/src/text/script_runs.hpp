// Internal: splitting a paragraph into runs of one script and one direction, with a simplified
// Unicode Bidirectional Algorithm (UAX #9) for the embedding levels.
//
// What of UAX #9 is implemented:
//   - P2/P3: the paragraph direction is that of its first strong character (L, or R/AL), LTR
//     when it has none — unless the caller gives one;
//   - character classes come from the Unicode script (HarfBuzz's tables): letters of a
//     right-to-left script (Hebrew, Arabic, Syriac, Thaana, N'Ko, ...) are R, letters of any other
//     script L; nonspacing marks take the class of the character before them (W1); European
//     and other decimal digits are numbers: L after an L (or at the start of an LTR paragraph,
//     W7), otherwise a left-to-right number one level up (W2/I1/I2);
//   - N1/N2: a run of neutrals (spaces, punctuation, symbols) between two strongs of the same
//     direction takes it (numbers count as R), otherwise the paragraph's direction;
//   - I1/I2 levels (0/1/2) and L2 reordering of runs by level, per line.
// Left out: explicit embeddings, overrides and isolates (LRE/RLE/LRO/RLO/PDF, LRI/RLI/FSI/PDI are
// treated as neutrals), the distinction of European/Arabic number separators and terminators
// (W3–W6: "1,000" or "5%" after Arabic may split), paired brackets (N0), and L1 (trailing
// whitespace is not reset to the paragraph level; bezel drops it from wrapped lines instead).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <hb.h>

namespace bezel::text_detail {

struct CodePoint {
    std::uint32_t offset = 0;   // byte offset in the whole text
    char32_t cp = 0;
};

struct ScriptRun {
    std::size_t begin = 0, end = 0;   // code point indices [begin, end)
    hb_script_t script = HB_SCRIPT_COMMON;
    std::uint8_t level = 0;           // odd: right to left
};

// The direction of the first strong character of cps[begin, end): +1 LTR, −1 RTL, 0 none.
int first_strong_direction(const std::vector<CodePoint>& cps, std::size_t begin, std::size_t end);

// Itemizes cps[begin, end) of a paragraph whose level is `paragraph_level` (0 LTR, 1 RTL) into
// `runs` (cleared first), in logical order. `scratch` is reused between calls.
void itemize(const std::vector<CodePoint>& cps, std::size_t begin, std::size_t end,
             int paragraph_level, std::vector<ScriptRun>& runs, std::vector<std::uint8_t>& scratch);

// L2: the visual order of items with the given levels, as indices into `levels`
// (written to `order`).
void visual_order(const std::vector<std::uint8_t>& levels, std::vector<std::size_t>& order);

// Unicode general category helpers shared by itemization and line breaking.
bool is_mark(char32_t cp);
hb_script_t script_of(char32_t cp);

}  // namespace bezel::text_detail
