// Line break opportunities; see layout_breaks.hpp for the rules and what is left out.
#include "text/layout_breaks.hpp"

namespace bezel::text_detail {

namespace {

bool is_hyphen(char32_t c) { return c == 0x2D || c == 0x2010 || c == 0x2012 || c == 0x2013; }

bool is_glue(char32_t c) { return c == 0xA0 || c == 0x202F || c == 0x2060 || c == 0xFEFF; }

bool is_closing(char32_t c) {
    switch (c) {
        case '.': case ',': case ':': case ';': case '!': case '?': case ')': case ']': case '}':
        case 0x3001: case 0x3002: case 0x3009: case 0x300B: case 0x300D: case 0x300F:
        case 0x3011: case 0x3015: case 0x3017: case 0x3019: case 0x301B: case 0x30FC:
        case 0xFF01: case 0xFF09: case 0xFF0C: case 0xFF0E: case 0xFF1A: case 0xFF1B:
        case 0xFF1F: case 0xFF3D: case 0xFF5D:
            return true;
        default:
            return false;
    }
}

bool is_opening(char32_t c) {
    switch (c) {
        case '(': case '[': case '{':
        case 0x3008: case 0x300A: case 0x300C: case 0x300E: case 0x3010: case 0x3014:
        case 0x3016: case 0x3018: case 0x301A: case 0xFF08: case 0xFF3B: case 0xFF5B:
            return true;
        default:
            return false;
    }
}

bool is_ideographic(char32_t c) {
    if ((c >= 0x3000 && c <= 0x303F) || (c >= 0xFF00 && c <= 0xFFEF)) return true;
    const hb_script_t s = script_of(c);
    return s == HB_SCRIPT_HAN || s == HB_SCRIPT_HIRAGANA || s == HB_SCRIPT_KATAKANA ||
           s == HB_SCRIPT_BOPOMOFO;
}

}  // namespace

bool is_break_space(char32_t c) {
    return c == 0x20 || c == 0x09 || c == 0x1680 || (c >= 0x2000 && c <= 0x200A && c != 0x2007) ||
           c == 0x205F || c == 0x3000;
}

void break_opportunities(const std::vector<CodePoint>& cps, std::size_t begin, std::size_t end,
                         std::vector<std::uint8_t>& out) {
    const std::size_t n = end - begin;
    out.assign(n, 0);
    for (std::size_t k = 1; k < n; ++k) {
        const char32_t before = cps[begin + k - 1].cp, cur = cps[begin + k].cp;
        if (is_break_space(cur) || is_mark(cur) || is_closing(cur) || is_glue(cur) ||
            is_glue(before) || is_opening(before))
            continue;
        bool ok = is_break_space(before) || before == 0x200B;
        if (!ok && is_hyphen(before) && k >= 2 && !is_break_space(cps[begin + k - 2].cp)) ok = true;
        if (!ok && (is_ideographic(before) || is_ideographic(cur))) ok = true;
        out[k] = ok ? 1 : 0;
    }
}

}  // namespace bezel::text_detail
