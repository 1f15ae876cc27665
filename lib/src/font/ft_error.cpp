// FreeType error text. fterrors.h is written to be included again with FT_ERRORDEF defined, to
// expand its list of (code, message) into whatever the includer wants; here, a table. This file
// includes no other FreeType header after that, so the redefinitions stay local.
#include "font/ft_error.hpp"

#include <cstdio>

namespace bezel::font_detail {
namespace {

struct FtErrorName {
    int code;
    const char* text;
};

#undef FTERRORS_H_
#define FT_ERRORDEF(e, v, s) {v, s},
#define FT_ERROR_START_LIST constexpr FtErrorName kFtErrorNames[] = {
#define FT_ERROR_END_LIST {0, nullptr}};
#include FT_ERRORS_H

const char* table_lookup(FT_Error error) {
    for (const FtErrorName& e : kFtErrorNames) {
        if (e.text != nullptr && e.code == error) return e.text;
    }
    return "unknown error";
}

}  // namespace

std::string ft_error_text(FT_Error error) {
    const char* text = nullptr;
#if FREETYPE_MAJOR > 2 || (FREETYPE_MAJOR == 2 && FREETYPE_MINOR >= 10)
    text = FT_Error_String(error);  // null unless FreeType was built with error strings
#endif
    if (text == nullptr) text = table_lookup(error);
    char code[32];
    std::snprintf(code, sizeof code, "0x%02x", static_cast<unsigned>(error));
    return std::string("FreeType error ") + code + " (" + text + ")";
}

}  // namespace bezel::font_detail
