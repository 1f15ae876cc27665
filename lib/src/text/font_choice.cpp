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

bool is_common(char32_t cp) {
    const hb_script_t s = script_of(cp);
    return s == HB_SCRIPT_COMMON || s == HB_SCRIPT_INHERITED || s == HB_SCRIPT_UNKNOWN;
}

}  // namespace

void CollectionFonts::variations(std::size_t font, const ShapeOptions& shape,
                                 std::vector<VariationSetting>& out) const {
    out = fonts_.source(font).variations;
    if (font == 0) out.insert(out.end(), shape.variations.begin(), shape.variations.end());
}

Expected<std::optional<std::uint16_t>> CollectionFonts::from_fallback(bool prefer_colour) {
    FallbackSource* fallback = fonts_.fallback();
    if (fallback == nullptr) return std::optional<std::uint16_t>{};
    const bool single = needed_.size() == 1;
    if (single && unfound_.count(needed_[0]) != 0) return std::optional<std::uint16_t>{};
    const std::optional<FontSource> source = fallback->font_for(needed_, prefer_colour);
    std::optional<std::uint16_t> found;
    if (source) {
        std::size_t index = fonts_.size();
        for (std::size_t i = 0; i < fonts_.size(); ++i) {
            const FontSource& s = fonts_.source(i);
            if (s.file == source->file && s.face_index == source->face_index) index = i;
        }
        if (index == fonts_.size()) {
            auto added = fonts_.add(*source, FontOrigin::System);
            if (!added) {
                fonts_.add_warning(added.error().message);
                index = fonts_.size();
            }
        }
        if (index < fonts_.size()) {
            auto ok = covers(index);
            if (!ok) return ok.error();
            if (*ok) found = static_cast<std::uint16_t>(index);
        }
    }
    if (!found && single) {
        if (unfound_.size() >= kMaxUnfoundRemembered) unfound_.clear();
        unfound_.insert(needed_[0]);
    }
    return found;
}

Expected<std::uint16_t> CollectionFonts::choose(std::uint16_t previous, bool prefer_colour,
                                                bool prefer_text) {
    const std::size_t n = fonts_.size();
    if (prefer_colour) {
        for (std::size_t i = 0; i < n; ++i) {
            if (!fonts_.is_colour(i)) continue;
            auto ok = covers(i);
            if (!ok) return ok.error();
            if (*ok) return static_cast<std::uint16_t>(i);
        }
    }
    if (previous != kNoFont &&
        std::all_of(needed_.begin(), needed_.end(), [](char32_t c) { return is_common(c); })) {
        auto ok = covers(previous);
        if (!ok) return ok.error();
        if (*ok) return previous;
    }
    for (int pass = 0; pass < 2; ++pass) {
        for (std::size_t i = 0; i < n; ++i) {
            // With VS15, colour fonts only in a second pass.
            if (prefer_text && fonts_.is_colour(i) == (pass == 0)) continue;
            auto ok = covers(i);
            if (!ok) return ok.error();
            if (*ok) return static_cast<std::uint16_t>(i);
        }
        if (!prefer_text) break;
    }
    auto found = from_fallback(prefer_colour);
    if (!found) return found.error();
    return found->value_or(0);
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
        const Font& first = fonts_.font(0);
        bool all = true;
        for (std::size_t k = 0; k < n && all; ++k) {
            // U+231A is the first character with Emoji_Presentation.
            if (colour_in_list && text[k] >= 0x231A) all = false;
            else all = first.glyph_for_char(text[k]).has_value();
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
            auto ignorable = has_unicode_property(c, UnicodeProperty::DefaultIgnorable);
            if (!ignorable) return ignorable.error();
            if (!*ignorable) needed_.push_back(c);
        }
        std::uint16_t font = previous == kNoFont ? 0 : previous;
        if (!needed_.empty()) {
            bool emoji = vs16;
            if (!vs15 && !vs16) {
                auto presentation =
                    has_unicode_property(needed_[0], UnicodeProperty::EmojiPresentation);
                if (!presentation) return presentation.error();
                emoji = *presentation;
            }
            auto chosen = choose(previous, emoji, vs15);
            if (!chosen) return chosen.error();
            font = *chosen;
        }
        std::fill(out.begin() + static_cast<std::ptrdiff_t>(s),
                  out.begin() + static_cast<std::ptrdiff_t>(e), font);
        previous = font;
        s = e;
    }
    return ok_status();
}

}  // namespace bezel::text_detail
