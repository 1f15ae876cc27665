// Internal: what the horizontal (layout.cpp) and the vertical (layout_vertical.cpp) layouts share.
#pragma once

#include <cstdio>
#include <string>

namespace bezel::text_detail {

// Slack when comparing a line's length with the wrapping length: sums of advances in a different
// order must not flip a fit that is exact on paper.
constexpr double kFitSlackPx = 1e-6;

// Paragraph separators: each ends a paragraph (a line, or a column in vertical text). CR LF is
// one separator; the caller skips the LF.
inline bool is_newline(char32_t c) {
    return c == '\n' || c == '\r' || c == 0x0B || c == 0x0C || c == 0x85 || c == 0x2028 ||
           c == 0x2029;
}

// A number in a message: "%g" (6 significant digits), not std::to_string's "%f".
inline std::string format_num(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

}  // namespace bezel::text_detail
