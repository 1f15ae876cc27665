// Which font of a FontCollection draws each grapheme cluster.
//
// The rule, per cluster in logical order (its code points that need a glyph: all but the
// default-ignorable ones, ZWJ and variation selectors among them):
//   1. Emoji presentation (a VS16, or a first character with Emoji_Presentation and no VS15):
//      the first colour font that covers the cluster.
//   2. A cluster of Common or Inherited script only (spaces, punctuation, digits, symbols) stays
//      in the previous cluster's font when that font covers it, so a space between two Arabic
//      words does not split the Arabic run into three runs of two fonts (shaping, kerning and
//      speed all prefer long runs).
//   3. The first font of the list that covers the cluster (with a VS15, text presentation, a
//      colour font only when no other covers it).
//   4. The fallback source (system fonts), whose font is appended to the collection.
//   5. Nothing covers it: the first font, whose .notdef then marks it as missing.
// A cluster of default-ignorable characters only takes the previous cluster's font.
#include <algorithm>

#include "text/layout_fonts.hpp"
#include "text/script_runs.hpp"

namespace bezel::text_detail {

namespace {

constexpr std::uint16_t kNoFont = 0xFFFF;
// How many characters without any font are remembered (a page of unknown script asks the
// fallback source once per distinct character, not once per occurrence).
constexpr std::size_t kMaxUnfoundRemembered = 4096;

constexpr char32_t kVs15 = 0xFE0E, kVs16 = 0xFE0F;
// The first character with Emoji_Presentation.
constexpr char32_t kFirstEmojiPresentation = 0x231A;

bool is_common(char32_t cp) {
    const hb_script_t s = script_of(cp);
    return s == HB_SCRIPT_COMMON || s == HB_SCRIPT_INHERITED || s == HB_SCRIPT_UNKNOWN;
}

}  // namespace

void CollectionFonts::variations(std::size_t font, const ShapeOptions& shape,
                                 std::vector<VariationSetting>& out) const {
    fonts_.variations_for(font, shape.variations, out);
}

std::uint64_t CollectionFonts::fonts_with(char32_t cp) {
    if (coverage_.empty()) coverage_.resize(kCoverageSlots);
    Coverage& c = coverage_[(cp ^ (cp >> 12)) % kCoverageSlots];
    if (c.cp != cp) c = Coverage{cp, 0, 0};
    for (std::size_t i = c.fonts_checked; i < fonts_.size(); ++i)
        if (fonts_.font(i).glyph_for_char(cp)) c.mask |= std::uint64_t{1} << i;
    c.fonts_checked = static_cast<std::uint16_t>(fonts_.size());
    return c.mask;
}

std::uint64_t CollectionFonts::fonts_with_needed() {
    std::uint64_t mask = ~std::uint64_t{0};
    for (char32_t c : needed_) mask &= fonts_with(c);
    return mask;
}

std::optional<std::uint16_t> CollectionFonts::from_fallback(bool prefer_colour) {
    if (fonts_.fallback() == nullptr) return std::nullopt;
    const bool single = needed_.size() == 1;
    if (single && unfound_.count(needed_[0]) != 0) return std::nullopt;
    request_.cluster = needed_;
    request_.prefer_colour = prefer_colour;
    request_.outlines_only = fonts_.outlines_only();
    const std::optional<std::size_t> found = fonts_.fallback_font(request_);
    if (!found && single) {
        if (unfound_.size() >= kMaxUnfoundRemembered) unfound_.clear();
        unfound_.insert(needed_[0]);
    }
    if (!found) return std::nullopt;
    return static_cast<std::uint16_t>(*found);
}

std::uint16_t CollectionFonts::choose(std::uint16_t previous, bool prefer_colour,
                                      bool prefer_text) {
    const std::size_t n = fonts_.size();
    const std::uint64_t covering = fonts_with_needed();
    auto has = [&](std::size_t i) { return ((covering >> i) & 1) != 0; };
    if (prefer_colour)
        for (std::size_t i = 0; i < n; ++i)
            if (fonts_.is_colour(i) && has(i)) return static_cast<std::uint16_t>(i);
    if (previous != kNoFont && has(previous) &&
        std::all_of(needed_.begin(), needed_.end(), [](char32_t c) { return is_common(c); }))
        return previous;
    // With VS15 a colour font only when no other covers the cluster.
    for (int pass = prefer_text ? 0 : 1; pass < 2; ++pass)
        for (std::size_t i = 0; i < n; ++i)
            if (has(i) && (pass == 1 || !fonts_.is_colour(i))) return static_cast<std::uint16_t>(i);
    return from_fallback(prefer_colour).value_or(0);
}

Status CollectionFonts::assign(const char32_t* text, std::size_t n, UnicodeBreaks& breaks,
                               std::vector<std::uint16_t>& out) {
    out.assign(n, 0);
    if (n == 0 || (fonts_.size() == 1 && fonts_.fallback() == nullptr)) return ok_status();
    // The common case first: the first font maps every character, and no emoji wants a colour
    // font of the list. Then no cluster needs to be found (nor ICU loaded).
    {
        bool colour_in_list = false;
        for (std::size_t i = 1; i < fonts_.size(); ++i) colour_in_list |= fonts_.is_colour(i);
        bool all = true;
        for (std::size_t k = 0; k < n && all; ++k) {
            if (colour_in_list && text[k] >= kFirstEmojiPresentation) all = false;
            else all = (fonts_with(text[k]) & 1) != 0;
        }
        if (all) return ok_status();
    }
    if (auto ok = breaks.grapheme_starts(text, n, starts_); !ok) return ok;
    std::uint16_t previous = kNoFont;
    for (std::size_t s = 0; s < n;) {
        std::size_t e = s + 1;
        while (e < n && starts_[e] == 0) ++e;
        needed_.clear();
        bool vs15 = false, vs16 = false;
        for (std::size_t k = s; k < e; ++k) {
            const char32_t c = text[k];
            vs15 |= c == kVs15;
            vs16 |= c == kVs16;
            if (!is_default_ignorable(c)) needed_.push_back(c);
        }
        std::uint16_t font = previous == kNoFont ? 0 : previous;
        if (!needed_.empty()) {
            bool emoji = vs16;
            if (!vs15 && !vs16 && needed_[0] >= kFirstEmojiPresentation) {
                auto presentation =
                    has_unicode_property(needed_[0], UnicodeProperty::EmojiPresentation);
                if (!presentation) return presentation.error();
                emoji = *presentation;
            }
            font = choose(previous, emoji, vs15);
        }
        std::fill(out.begin() + static_cast<std::ptrdiff_t>(s),
                  out.begin() + static_cast<std::ptrdiff_t>(e), font);
        previous = font;
        s = e;
    }
    return ok_status();
}

}  // namespace bezel::text_detail
