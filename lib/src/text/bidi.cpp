// BidiParagraph (bidi.hpp): FriBidi's resolution of one paragraph, and L1 per line.
#include "text/bidi.hpp"

#include <fribidi.h>

#include <type_traits>

namespace bezel::text_detail {

static_assert(std::is_same_v<FriBidiCharType, std::uint32_t> &&
                  std::is_same_v<FriBidiBracketType, std::uint32_t> &&
                  std::is_same_v<FriBidiChar, std::uint32_t> && sizeof(FriBidiLevel) == 1,
              "FriBidi's types are stored as fixed-width integers here");

Status BidiParagraph::resolve(const char32_t* text, std::size_t n, Direction direction) {
    // FriBidiStrIndex is an int: a paragraph is at most kMaxTextBytes characters, well within.
    const auto len = static_cast<FriBidiStrIndex>(n);
    types_.resize(n);
    brackets_.resize(n);
    levels_.resize(n);
    const auto* chars = reinterpret_cast<const FriBidiChar*>(text);
    fribidi_get_bidi_types(chars, len, types_.data());
    fribidi_get_bracket_types(chars, len, types_.data(), brackets_.data());
    FriBidiParType base = direction == Direction::RightToLeft   ? FRIBIDI_PAR_RTL
                          : direction == Direction::LeftToRight ? FRIBIDI_PAR_LTR
                                                                : FRIBIDI_PAR_ON;
    if (n == 0) {
        paragraph_level_ = base == FRIBIDI_PAR_RTL ? 1 : 0;
        return ok_status();
    }
    const FriBidiLevel max_plus_one = fribidi_get_par_embedding_levels_ex(
        types_.data(), brackets_.data(), len, &base,
        reinterpret_cast<FriBidiLevel*>(levels_.data()));
    if (max_plus_one == 0) return Error{"bidi: FriBidi could not resolve a paragraph"};
    paragraph_level_ = FRIBIDI_DIR_TO_LEVEL(base);
    return ok_status();
}

void BidiParagraph::line_levels(std::size_t begin, std::size_t end,
                                std::vector<std::uint8_t>& out) const {
    out.assign(levels_.begin() + static_cast<std::ptrdiff_t>(begin),
               levels_.begin() + static_cast<std::ptrdiff_t>(end));
    // L1, part 4: whitespace and isolate formatting characters at the end of the line (and the
    // controls X9 removes among them) take the paragraph level.
    for (std::size_t i = end; i-- > begin;) {
        const FriBidiCharType t = types_[i];
        if (!(FRIBIDI_IS_EXPLICIT_OR_BN_OR_WS(t) || FRIBIDI_IS_ISOLATE(t))) break;
        out[i - begin] = paragraph_level_;
    }
}

bool BidiParagraph::removed_by_x9(std::size_t i) const {
    return FRIBIDI_IS_EXPLICIT_OR_BN(types_[i]) && !FRIBIDI_IS_ISOLATE(types_[i]);
}

}  // namespace bezel::text_detail
