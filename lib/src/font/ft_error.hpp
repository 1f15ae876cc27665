// Private to the font module: FreeType error codes as text for error messages.
#pragma once

#include <string>

#include <ft2build.h>
#include FT_FREETYPE_H

namespace bezel::font_detail {

// "FreeType error 0x02 (cannot open resource)". Uses FT_Error_String when FreeType was built
// with error strings (Debian's is not), otherwise FreeType's own table from fterrors.h.
std::string ft_error_text(FT_Error error);

}  // namespace bezel::font_detail
