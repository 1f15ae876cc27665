// Internal: decoding one UTF-8 sequence at a time, for callers that need the byte offset of
// every code point (layout keeps clusters as byte offsets).
#pragma once

#include <cstddef>
#include <string_view>

#include "bezel/expected.hpp"

namespace bezel::text_detail {

// Decodes the sequence starting at text[i] (i < text.size()) into `cp`; returns its length in
// bytes, or 0 when it is not valid UTF-8 (see decode_utf8 for what is rejected).
std::size_t decode_one(std::string_view text, std::size_t i, char32_t& cp);

// "text byte N: invalid UTF-8".
Error invalid_utf8(std::size_t offset);

}  // namespace bezel::text_detail
