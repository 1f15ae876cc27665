// OpenType feature lists in hb-view's syntax, parsed item by item with HarfBuzz's own parser so
// that bezel accepts exactly what hb-view and hb-shape accept.
#include <cctype>
#include <climits>
#include <string>

#include <hb.h>

#include "bezel/shape.hpp"

namespace bezel {

namespace {

bool is_separator(char c) { return c == ',' || std::isspace(static_cast<unsigned char>(c)); }

// The tag of an item, after an optional +/- and an optional quote: 1 to 4 characters of
// letters, digits or spaces. hb_feature_from_string truncates longer tags silently ("kernx"
// would become "kern"), so the length is checked here.
bool tag_length_ok(std::string_view item) {
    std::size_t i = 0;
    if (i < item.size() && (item[i] == '+' || item[i] == '-')) ++i;
    char quote = 0;
    if (i < item.size() && (item[i] == '\'' || item[i] == '"')) quote = item[i++];
    std::size_t n = 0;
    while (i + n < item.size() &&
           (std::isalnum(static_cast<unsigned char>(item[i + n])) ||
            (quote != 0 && item[i + n] == ' ')))
        ++n;
    return n >= 1 && n <= 4;
}

}  // namespace

Expected<std::vector<FeatureSetting>> parse_features(std::string_view spec) {
    std::vector<FeatureSetting> out;
    std::size_t i = 0;
    while (i < spec.size()) {
        while (i < spec.size() && is_separator(spec[i])) ++i;
        std::size_t j = i;
        // A range "[3:5]" holds no separators, but "aalt = 2" is not hb syntax either: items end
        // at the first comma or blank.
        while (j < spec.size() && !is_separator(spec[j])) ++j;
        if (j == i) break;
        const std::string item(spec.substr(i, j - i));
        i = j;
        hb_feature_t f;
        if (!tag_length_ok(item) ||
            !hb_feature_from_string(item.c_str(), static_cast<int>(item.size()), &f))
            return Error{"feature '" + item + "': does not parse (expected e.g. kern, -liga, "
                         "aalt=2, liga[3:5]=0)"};
        FeatureSetting s;
        char tag[4];
        hb_tag_to_string(f.tag, tag);
        s.tag.assign(tag, 4);
        s.value = f.value;
        s.start = f.start;
        s.end = f.end == HB_FEATURE_GLOBAL_END ? SIZE_MAX : f.end;
        out.push_back(std::move(s));
    }
    return out;
}

}  // namespace bezel
