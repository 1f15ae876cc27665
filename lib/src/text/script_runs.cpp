// Script runs of one bidi level, and L2 reordering.
#include "text/script_runs.hpp"

#include <algorithm>

namespace bezel::text_detail {

namespace {

hb_unicode_funcs_t* ufuncs() {
    static hb_unicode_funcs_t* const funcs = hb_unicode_funcs_get_default();
    return funcs;
}

}  // namespace

bool is_mark(char32_t cp) {
    const hb_unicode_general_category_t gc = hb_unicode_general_category(ufuncs(), cp);
    return gc == HB_UNICODE_GENERAL_CATEGORY_NON_SPACING_MARK ||
           gc == HB_UNICODE_GENERAL_CATEGORY_SPACING_MARK ||
           gc == HB_UNICODE_GENERAL_CATEGORY_ENCLOSING_MARK;
}

hb_script_t script_of(char32_t cp) { return hb_unicode_script(ufuncs(), cp); }

void itemize(const std::vector<CodePoint>& cps, std::size_t begin, std::size_t end,
             const std::vector<std::uint8_t>& levels, const std::vector<std::uint16_t>& fonts,
             std::vector<ScriptRun>& runs) {
    runs.clear();
    const std::size_t n = end - begin;
    // Common and inherited characters take the script before them (the one after, at the
    // start).
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
        const std::uint8_t level = levels[k];
        const std::uint16_t font = fonts[k];
        if (!runs.empty() && runs.back().level == level && runs.back().script == current &&
            runs.back().font == font) {
            runs.back().end = begin + k + 1;
        } else {
            runs.push_back({begin + k, begin + k + 1, current, level, font});
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
