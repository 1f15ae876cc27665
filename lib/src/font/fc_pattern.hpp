// Private to the font module: fontconfig patterns for bezel/system_fonts.hpp — owning pointers,
// parsing a pattern string with errors that name what is wrong, and turning a font's pattern
// into the FontSource that opens what fontconfig meant.
#pragma once

#include <memory>
#include <string>

#include <fontconfig/fontconfig.h>

#include "bezel/expected.hpp"
#include "bezel/font.hpp"

namespace bezel::font_detail {

struct FcPatternDeleter {
    void operator()(FcPattern* p) const { FcPatternDestroy(p); }
};
struct FcFontSetDeleter {
    void operator()(FcFontSet* s) const { FcFontSetDestroy(s); }
};
struct FcCharSetDeleter {
    void operator()(FcCharSet* c) const { FcCharSetDestroy(c); }
};
struct FcConfigDeleter {
    void operator()(FcConfig* c) const { FcConfigDestroy(c); }
};
using FcPatternPtr = std::unique_ptr<FcPattern, FcPatternDeleter>;
using FcFontSetPtr = std::unique_ptr<FcFontSet, FcFontSetDeleter>;
using FcCharSetPtr = std::unique_ptr<FcCharSet, FcCharSetDeleter>;
using FcConfigPtr = std::unique_ptr<FcConfig, FcConfigDeleter>;

// FcNameParse with the checks it leaves out: it silently drops an element naming an unknown
// property ("colour=1") or an unknown style word ("blod"), so such a pattern is an Error here,
// as is one FcNameParse rejects (a value of the wrong type: "size=abc"). The error names the
// pattern and the element.
Expected<FcPatternPtr> parse_pattern(const std::string& pattern);

// The FontSource of a font pattern (one of the configuration's fonts, or FcFontMatch's /
// FcFontRenderPrepare's result): FC_FILE; the face from FC_INDEX's low 16 bits; a named
// instance (FC_INDEX's high 16 bits, 1-based) as that instance's design coordinates, read from
// the font; then FC_FONT_VARIATIONS ("wght=563,wdth=100", what fontconfig computes for a
// variable font and a requested weight), which override the instance's value of the same axis.
// Errors name the pattern's file: none, an unreadable instance, malformed variations.
Expected<FontSource> font_source(FcPattern* font);

}  // namespace bezel::font_detail
