// Script runs and simplified bidi levels; see script_runs.hpp for what of UAX #9 is left out.
#include "text/script_runs.hpp"

#include <algorithm>

namespace bezel::text_detail {

namespace {

// Resolved classes, before and after W1/W2/W7 and N1/N2.
enum Cls : std::uint8_t { kL, kR, kNumL, kNumR, kNeutral, kNumber, kMark };

hb_unicode_funcs_t* ufuncs() {
    static hb_unicode_funcs_t* const funcs = hb_unicode_funcs_get_default();
    return funcs;
}

Cls raw_class(char32_t cp) {
    const hb_unicode_general_category_t gc = hb_unicode_general_category(ufuncs(), cp);
    if (gc == HB_UNICODE_GENERAL_CATEGORY_NON_SPACING_MARK ||
        gc == HB_UNICODE_GENERAL_CATEGORY_ENCLOSING_MARK)
        return kMark;
    if (gc == HB_UNICODE_GENERAL_CATEGORY_DECIMAL_NUMBER) {
        const hb_script_t s = script_of(cp);
        // Digits of a right-to-left script's own (Arabic-Indic, N'Ko) are numbers too.
        if (s == HB_SCRIPT_COMMON || s == HB_SCRIPT_INHERITED ||
            hb_script_get_horizontal_direction(s) == HB_DIRECTION_RTL)
            return kNumber;
    }
    const hb_script_t s = script_of(cp);
    if (s == HB_SCRIPT_COMMON || s == HB_SCRIPT_INHERITED || s == HB_SCRIPT_UNKNOWN) {
        // Letters of no script (e.g. U+00AA ª) are still strong L.
        const bool letter = gc == HB_UNICODE_GENERAL_CATEGORY_LOWERCASE_LETTER ||
                            gc == HB_UNICODE_GENERAL_CATEGORY_UPPERCASE_LETTER ||
                            gc == HB_UNICODE_GENERAL_CATEGORY_OTHER_LETTER;
        return letter ? kL : kNeutral;
    }
    if (gc == HB_UNICODE_GENERAL_CATEGORY_SPACING_MARK) return kMark;
    return hb_script_get_horizontal_direction(s) == HB_DIRECTION_RTL ? kR : kL;
}

bool is_strong_rtl_like(Cls c) { return c == kR || c == kNumR; }

}  // namespace

bool is_mark(char32_t cp) {
    const hb_unicode_general_category_t gc = hb_unicode_general_category(ufuncs(), cp);
    return gc == HB_UNICODE_GENERAL_CATEGORY_NON_SPACING_MARK ||
           gc == HB_UNICODE_GENERAL_CATEGORY_SPACING_MARK ||
           gc == HB_UNICODE_GENERAL_CATEGORY_ENCLOSING_MARK;
}

hb_script_t script_of(char32_t cp) { return hb_unicode_script(ufuncs(), cp); }

int first_strong_direction(const std::vector<CodePoint>& cps, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
        const Cls c = raw_class(cps[i].cp);
        if (c == kL) return 1;
        if (c == kR) return -1;
    }
    return 0;
}

void itemize(const std::vector<CodePoint>& cps, std::size_t begin, std::size_t end,
             int paragraph_level, std::vector<ScriptRun>& runs, std::vector<std::uint8_t>& cls) {
    runs.clear();
    const std::size_t n = end - begin;
    cls.resize(n);
    const Cls sos = paragraph_level == 1 ? kR : kL;
    // W1 (marks take the class before them), W2/W7 (numbers after L are L).
    Cls prev = sos, prev_strong = sos;
    for (std::size_t k = 0; k < n; ++k) {
        Cls c = raw_class(cps[begin + k].cp);
        if (c == kMark) c = prev == kNumber ? kNumber : prev;
        prev = c;
        if (c == kNumber) c = prev_strong == kL ? kNumL : kNumR;
        if (c == kL || c == kR) prev_strong = c;
        cls[k] = c;
    }
    // N1/N2: neutrals between equal directions take it; numbers count as R.
    for (std::size_t k = 0; k < n;) {
        if (cls[k] != kNeutral) {
            ++k;
            continue;
        }
        std::size_t j = k;
        while (j < n && cls[j] == kNeutral) ++j;
        const Cls before = k == 0 ? sos : static_cast<Cls>(cls[k - 1]);
        const Cls after = j == n ? sos : static_cast<Cls>(cls[j]);
        const bool before_r = is_strong_rtl_like(before), after_r = is_strong_rtl_like(after);
        const Cls resolved = before_r == after_r ? (before_r ? kR : kL) : sos;
        std::fill(cls.begin() + static_cast<std::ptrdiff_t>(k),
                  cls.begin() + static_cast<std::ptrdiff_t>(j), resolved);
        k = j;
    }
    // I1/I2: levels; then runs of one level and one script. Common and inherited characters
    // take the script before them (the one after, at the start).
    hb_script_t current = HB_SCRIPT_COMMON;
    for (std::size_t k = 0; k < n; ++k) {
        const hb_script_t s = script_of(cps[begin + k].cp);
        if (s != HB_SCRIPT_COMMON && s != HB_SCRIPT_INHERITED && s != HB_SCRIPT_UNKNOWN) {
            current = s;
            break;
        }
    }
    for (std::size_t k = 0; k < n; ++k) {
        const hb_script_t s = script_of(cps[begin + k].cp);
        if (s != HB_SCRIPT_COMMON && s != HB_SCRIPT_INHERITED && s != HB_SCRIPT_UNKNOWN)
            current = s;
        std::uint8_t level;
        if (paragraph_level == 0)
            level = cls[k] == kL || cls[k] == kNumL ? 0 : cls[k] == kR ? 1 : 2;
        else
            level = cls[k] == kR ? 1 : 2;
        if (!runs.empty() && runs.back().level == level && runs.back().script == current) {
            runs.back().end = begin + k + 1;
        } else {
            runs.push_back({begin + k, begin + k + 1, current, level});
        }
    }
}

void visual_order(const std::vector<std::uint8_t>& levels, std::vector<std::size_t>& order) {
    order.resize(levels.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    if (levels.empty()) return;
    const std::uint8_t highest = *std::max_element(levels.begin(), levels.end());
    std::uint8_t lowest_odd = 255;
    for (std::uint8_t l : levels)
        if ((l & 1) != 0) lowest_odd = std::min(lowest_odd, l);
    if (lowest_odd == 255) lowest_odd = static_cast<std::uint8_t>(highest + 1);
    // L2: from the highest level down to the lowest odd one, reverse every maximal sequence of
    // items at that level or higher.
    for (int level = highest; level >= lowest_odd; --level) {
        for (std::size_t i = 0; i < order.size();) {
            if (levels[order[i]] < level) {
                ++i;
                continue;
            }
            std::size_t j = i;
            while (j < order.size() && levels[order[j]] >= level) ++j;
            std::reverse(order.begin() + static_cast<std::ptrdiff_t>(i),
                         order.begin() + static_cast<std::ptrdiff_t>(j));
            i = j;
        }
    }
}

}  // namespace bezel::text_detail
