#include "path/svg_lexer.hpp"

#include <charconv>
#include <cstdio>
#include <system_error>

namespace bezel::svg_detail {

namespace {

bool is_wsp(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\f' || c == '\r'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

void Lexer::skip_wsp() {
    while (!at_end() && is_wsp(s_[pos_])) ++pos_;
}

bool Lexer::skip_comma_wsp() {
    skip_wsp();
    if (peek() != ',') return false;
    ++pos_;
    skip_wsp();
    return true;
}

bool Lexer::at_number_start() const {
    char c = peek();
    return is_digit(c) || c == '+' || c == '-' || c == '.';
}

Error Lexer::error_at(std::size_t offset, const std::string& message) {
    return Error{"path data offset " + std::to_string(offset) + ": " + message};
}

Error Lexer::expected_at(std::size_t offset, const char* what) const {
    std::string found;
    if (offset >= s_.size()) {
        found = "end of data";
    } else {
        unsigned char c = static_cast<unsigned char>(s_[offset]);
        char buf[16];
        if (c >= 0x20 && c < 0x7f)
            std::snprintf(buf, sizeof buf, "'%c'", c);
        else
            std::snprintf(buf, sizeof buf, "byte 0x%02X", c);
        found = buf;
    }
    return error_at(offset, std::string("expected ") + what + ", found " + found);
}

Expected<double> Lexer::number() {
    const std::size_t begin = pos_;
    std::size_t i = pos_;
    bool negative = false;
    if (i < s_.size() && (s_[i] == '+' || s_[i] == '-')) negative = s_[i++] == '-';
    const std::size_t int_begin = i;
    while (i < s_.size() && is_digit(s_[i])) ++i;
    const std::size_t int_end = i;
    std::size_t frac_begin = i, frac_end = i;
    if (i < s_.size() && s_[i] == '.') {
        frac_begin = ++i;
        while (i < s_.size() && is_digit(s_[i])) ++i;
        frac_end = i;
    }
    if (int_end == int_begin && frac_end == frac_begin) return expected_at(begin, "a number");

    // The exponent, clamped: only its order of magnitude matters for telling overflow from
    // underflow below, and from_chars reads the digits themselves.
    long long exponent = 0;
    if (i < s_.size() && (s_[i] == 'e' || s_[i] == 'E')) {
        ++i;
        bool exp_negative = false;
        if (i < s_.size() && (s_[i] == '+' || s_[i] == '-')) exp_negative = s_[i++] == '-';
        const std::size_t exp_begin = i;
        while (i < s_.size() && is_digit(s_[i])) {
            if (exponent < 1000000000) exponent = exponent * 10 + (s_[i] - '0');
            ++i;
        }
        if (i == exp_begin) return expected_at(i, "digits of the exponent");
        if (exp_negative) exponent = -exponent;
    }

    // from_chars takes no '+'; it reads exactly the span we scanned (it follows the same
    // grammar, so it stops at i) and rounds correctly.
    const char* first = s_.data() + begin + (s_[begin] == '+' ? 1 : 0);
    const char* last = s_.data() + i;
    double value = 0.0;
    std::from_chars_result r = std::from_chars(first, last, value);
    pos_ = i;
    if (r.ec == std::errc::result_out_of_range) {
        // Overflow or underflow? The value is about 10^order, with order the position of the
        // leading non-zero digit relative to the decimal point, plus the exponent.
        long long order = 0;
        std::size_t k = int_begin;
        while (k < int_end && s_[k] == '0') ++k;
        if (k < int_end) {
            order = static_cast<long long>(int_end - k) - 1;
        } else {
            k = frac_begin;
            while (k < frac_end && s_[k] == '0') ++k;
            order = -static_cast<long long>(k - frac_begin + 1);
        }
        if (order + exponent > 0)
            return error_at(begin, "number out of range (overflows double)");
        return negative ? -0.0 : 0.0;
    }
    if (r.ec != std::errc() || r.ptr != last) return expected_at(begin, "a number");
    return value;
}

Expected<double> Lexer::flag() {
    char c = peek();
    if (c != '0' && c != '1') return expected_here("a flag (0 or 1)");
    ++pos_;
    return c == '1' ? 1.0 : 0.0;
}

}  // namespace bezel::svg_detail
