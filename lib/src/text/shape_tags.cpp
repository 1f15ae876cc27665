// Script and language tags for the shaper.
#include <cctype>

#include "text/shape_tags.hpp"

namespace bezel::text_detail {

std::string tag_string(hb_tag_t tag) {
    char s[4];
    hb_tag_to_string(tag, s);
    return std::string(s, 4);
}

Expected<hb_script_t> parse_script_tag(const std::string& tag) {
    bool ok = tag.size() == 4;
    for (char c : tag) ok = ok && std::isalpha(static_cast<unsigned char>(c));
    if (!ok) return Error{"script '" + tag + "': not an ISO 15924 tag (four letters, e.g. Arab)"};
    return hb_script_from_string(tag.c_str(), 4);
}

Expected<hb_language_t> parse_language_tag(const std::string& tag) {
    bool ok = !tag.empty() && tag.size() <= 64;
    std::size_t subtag = 0, index = 0;
    for (char c : tag) {
        const auto u = static_cast<unsigned char>(c);
        if (c == '-') {
            ok = ok && subtag > 0;
            subtag = 0;
            ++index;
            continue;
        }
        ok = ok && (index == 0 ? std::isalpha(u) : std::isalnum(u)) != 0;
        ++subtag;
        ok = ok && subtag <= 8;
    }
    ok = ok && subtag > 0;
    if (!ok) return Error{"language '" + tag + "': not a BCP 47 tag (e.g. ar, hi, sr-Latn)"};
    return hb_language_from_string(tag.c_str(), static_cast<int>(tag.size()));
}

}  // namespace bezel::text_detail
