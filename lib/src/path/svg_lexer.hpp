// The token level of SVG path data: whitespace, comma separators, numbers and arc flags.
//
// Grammar (SVG 1.1 §8.3.9, SVG 2 §9.3.9):
//   wsp        ::= #x20 | #x9 | #xA | #xC | #xD
//   comma-wsp  ::= wsp+ ","? wsp* | "," wsp*
//   number     ::= sign? (digits "."? digits? | "." digits) (("e" | "E") sign? digits)?
//   flag       ::= "0" | "1"
// A number ends at the first character that cannot continue it, so "1.5.5" is 1.5 then .5,
// "1-2" is 1 then −2, and "1e5.5" is 1e5 then .5.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "bezel/expected.hpp"

namespace bezel::svg_detail {

class Lexer {
public:
    explicit Lexer(std::string_view data) : s_(data) {}

    std::size_t offset() const { return pos_; }
    bool at_end() const { return pos_ >= s_.size(); }
    // The current byte; '\0' at the end.
    char peek() const { return at_end() ? '\0' : s_[pos_]; }
    void bump() { ++pos_; }

    void skip_wsp();
    // Skips a comma-wsp if there is one; returns whether a comma was among it.
    bool skip_comma_wsp();
    // Whether a number can start here (a sign, a digit or '.').
    bool at_number_start() const;

    // Reads a number here. Errors: no number here, an exponent without digits, a value that
    // overflows double. Values too small for a double underflow to ±0.
    Expected<double> number();
    // Reads a flag ('0' or '1') here.
    Expected<double> flag();

    // "path data offset N: <what>, found <the byte at N>".
    Error expected_here(const char* what) const { return expected_at(pos_, what); }
    Error expected_at(std::size_t offset, const char* what) const;
    // "path data offset N: <message>".
    static Error error_at(std::size_t offset, const std::string& message);

private:
    std::string_view s_;
    std::size_t pos_ = 0;
};

}  // namespace bezel::svg_detail
