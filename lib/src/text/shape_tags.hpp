// Internal: OpenType/ISO tags between bezel's strings and HarfBuzz's types.
#pragma once

#include <cstdint>
#include <string>

#include <hb.h>

#include "bezel/expected.hpp"

namespace bezel::text_detail {

// A 4-byte tag as its four characters ("wght", "Arab").
std::string tag_string(hb_tag_t tag);

// An ISO 15924 script tag: four ASCII letters, case-insensitive ("Arab", "deva"), of a script
// HarfBuzz's Unicode data has (or one of the aliases HarfBuzz maps to one: "Hans", "Latf"). Error
// names the tag: malformed ("Ar") or a script HarfBuzz does not know ("Xyzw"; hb-shape would
// accept it silently and shape as for no script).
Expected<hb_script_t> parse_script_tag(const std::string& tag);

// A BCP 47 language tag, loosely: subtags of 1 to 8 ASCII letters or digits joined by '-', the
// first of letters only ("ar", "hi", "sr-Latn", "zh-Hant-TW"). Error names the tag.
Expected<hb_language_t> parse_language_tag(const std::string& tag);

}  // namespace bezel::text_detail
