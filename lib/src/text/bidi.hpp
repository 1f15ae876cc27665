// Internal: the Unicode Bidirectional Algorithm (UAX #9) for one paragraph, by GNU FriBidi.
//
// FriBidi resolves the paragraph level (P2, P3, or the caller's), explicit embeddings, overrides
// and isolates (X1–X10), weak and neutral types including paired brackets (W1–W7, N0–N2),
// implicit levels (I1, I2) and the parts of L1 that do not depend on where lines end. Per line,
// line_levels() applies the rest of L1 (whitespace and isolate formatting characters at the end
// of the line take the paragraph level); L2 (reordering) is visual_order() of script_runs.hpp.
// FriBidi's character data is of the Unicode version it was built with (fribidi_unicode_version).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "bezel/expected.hpp"
#include "bezel/shape.hpp"

namespace bezel::text_detail {

class BidiParagraph {
public:
    // Resolves the levels of text[0, n). `direction`: LeftToRight or RightToLeft sets the
    // paragraph level (0 or 1); Auto takes it from the first strong character outside isolates
    // (P2, P3; 0 when there is none). Errors only if FriBidi fails (it allocates).
    Status resolve(const char32_t* text, std::size_t n, Direction direction);

    std::uint8_t paragraph_level() const { return paragraph_level_; }
    // One embedding level per character of the last resolve(); odd: right to left.
    const std::vector<std::uint8_t>& levels() const { return levels_; }
    // The levels of the line [begin, end) of the paragraph, with L1's end-of-line rule applied,
    // into `out` (resized to end − begin).
    void line_levels(std::size_t begin, std::size_t end, std::vector<std::uint8_t>& out) const;
    // Whether character i is one X9 removes (embedding and override controls, boundary
    // neutrals): it has a level, but no place of its own in the visual order.
    bool removed_by_x9(std::size_t i) const;

private:
    std::vector<std::uint32_t> types_, brackets_;   // FriBidiCharType, FriBidiBracketType
    std::vector<std::uint8_t> levels_;
    std::uint8_t paragraph_level_ = 0;
};

}  // namespace bezel::text_detail
