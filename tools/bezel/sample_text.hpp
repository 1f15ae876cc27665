// tools/bezel/sample_text.hpp — what `bezel render` draws when given no text: a short paragraph
// (our own words) that exercises kerning (AV, Wa, To), a ligature (fi) and punctuation, short
// enough that its terminal preview fits on one screen.
#pragma once

namespace bezel::cli {

inline constexpr const char* kSampleText =
    "Hello from bezel! Text shaped by HarfBuzz,\n"
    "drawn with exact-area coverage and blended\n"
    "in linear light. AV Wa To: fine kerning.";

}  // namespace bezel::cli
