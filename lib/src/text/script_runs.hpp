// Internal: splitting a paragraph into runs of one script and one bidi level (the levels come
// from BidiParagraph, bidi.hpp), and ordering runs by level (UAX #9, L2).
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
    std::uint16_t font = 0;           // index of the font that draws the run (LayoutFonts)
};

// Itemizes cps[begin, end) of a paragraph into `runs` (cleared first), in logical order: a run
// ends where the script, the bidi level or the font changes. `levels` and `fonts` hold one entry
// per character of the paragraph (levels[k] for cps[begin + k]).
void itemize(const std::vector<CodePoint>& cps, std::size_t begin, std::size_t end,
             const std::vector<std::uint8_t>& levels, const std::vector<std::uint16_t>& fonts,
             std::vector<ScriptRun>& runs);

// L2: the visual order of items with the given levels, as indices into `levels`
// (written to `order`).
void visual_order(const std::vector<std::uint8_t>& levels, std::vector<std::size_t>& order);

// Unicode general category helpers shared by itemization and line breaking.
bool is_mark(char32_t cp);
hb_script_t script_of(char32_t cp);

}  // namespace bezel::text_detail
