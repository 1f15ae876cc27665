// fontconfig patterns: parsing with errors that name the element, and a font pattern's FontSource.
#include "font/fc_pattern.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "font/font_impl.hpp"

namespace bezel::font_detail {

namespace {

// One element of the pattern after the family part, split as FcNameParse splits it: up to the
// next unescaped ':' (a backslash takes the next character literally), and within it a property
// name ends at the first unescaped '=' or '_' (fontconfig's older "weight_bold" form).
struct Element {
    std::string name;     // the property, or the whole element when it is a bare style word
    bool has_value = false;
    std::string text;     // the element as written, for the message
};

std::vector<Element> elements_after_family(const std::string& pattern) {
    std::vector<Element> out;
    std::size_t i = 0;
    const std::size_t n = pattern.size();
    // The family part (and an optional "-size" list) ends at the first unescaped ':'.
    for (; i < n && pattern[i] != ':'; ++i)
        if (pattern[i] == '\\') ++i;
    while (i < n) {
        ++i;  // past ':'
        Element e;
        bool in_value = false;
        const std::size_t start = i;
        for (; i < n && pattern[i] != ':'; ++i) {
            char c = pattern[i];
            if (c == '\\' && i + 1 < n) c = pattern[++i];
            else if (!in_value && (c == '=' || c == '_')) {
                in_value = e.has_value = true;
                continue;
            }
            if (!in_value) e.name += c;
        }
        e.text = pattern.substr(start, i - start);
        if (!e.name.empty()) out.push_back(std::move(e));
    }
    return out;
}

std::string quoted(const std::string& s) { return "'" + s + "'"; }

// The properties of fontconfig.h (2.14's FC_* names). fontconfig adds every name it is asked
// about (FcNameGetObjectType, FcNameParse) to a process-wide table it never shrinks, so a name
// outside this list is refused before fontconfig sees it: garbage patterns cannot grow memory.
constexpr const char* kProperties[] = {
    "family",     "style",          "slant",          "weight",       "size",
    "aspect",     "pixelsize",      "spacing",        "foundry",      "antialias",
    "hinting",    "hintstyle",      "verticallayout", "autohint",     "globaladvance",
    "width",      "file",           "index",          "ftface",       "rasterizer",
    "outline",    "scalable",       "color",          "variable",     "scale",
    "symbol",     "dpi",            "rgba",           "minspace",     "source",
    "charset",    "lang",           "fontversion",    "fullname",     "familylang",
    "stylelang",  "fullnamelang",   "capability",     "fontformat",   "embolden",
    "embeddedbitmap", "decorative", "lcdfilter",      "fontfeatures", "fontvariations",
    "namelang",   "prgname",        "hash",           "postscriptname", "fonthashint",
    "order",      "charwidth",      "charheight",     "matrix",
};

// A property this fontconfig knows (one of the list that its own table types).
bool known_property(const std::string& name) {
    for (const char* p : kProperties) {
        if (name == p) {
            const FcObjectType* type = FcNameGetObjectType(p);
            return type != nullptr && type->type != FcTypeUnknown;
        }
    }
    return false;
}

// "wght=563,wdth=100" (fontconfig writes FC_FONT_VARIATIONS so; users may write it with spaces
// around the parts): settings in order. A part that is not tag=number is an Error.
Expected<std::vector<VariationSetting>> parse_variations(const std::string& text,
                                                         const std::string& file) {
    std::vector<VariationSetting> out;
    std::size_t pos = 0;
    while (pos <= text.size()) {
        std::size_t comma = text.find(',', pos);
        if (comma == std::string::npos) comma = text.size();
        std::string part = text.substr(pos, comma - pos);
        pos = comma + 1;
        part.erase(0, part.find_first_not_of(' '));
        part.erase(part.find_last_not_of(' ') + 1);
        if (part.empty()) continue;
        const std::size_t eq = part.find('=');
        const std::string tag = part.substr(0, std::min(eq, part.size()));
        const std::string value = eq == std::string::npos ? "" : part.substr(eq + 1);
        char* end = nullptr;
        errno = 0;
        const double v = value.empty() ? 0 : std::strtod(value.c_str(), &end);
        if (tag.empty() || tag.size() > 4 || value.empty() || end == nullptr || *end != '\0' ||
            errno != 0 || !std::isfinite(v)) {
            return Error{file + ": fontconfig variations " + quoted(text) + ": " + quoted(part) +
                         " is not tag=number"};
        }
        // OpenType tags are four characters, shorter ones padded with spaces.
        out.push_back({tag + std::string(4 - tag.size(), ' '), v});
    }
    return out;
}

}  // namespace

Expected<FcPatternPtr> parse_pattern(const std::string& pattern) {
    const std::string what = "font pattern " + quoted(pattern);
    if (pattern.find('\0') != std::string::npos) return Error{what + ": contains a NUL byte"};
    for (const Element& e : elements_after_family(pattern)) {
        if (e.has_value && !known_property(e.name)) {
            return Error{what + ": unknown property " + quoted(e.name) +
                         " (fontconfig's are family, style, weight, slant, width, size, lang, "
                         "spacing, color, variable, ...)"};
        }
        if (!e.has_value &&
            FcNameGetConstant(reinterpret_cast<const FcChar8*>(e.name.c_str())) == nullptr) {
            return Error{what + ": unknown style word " + quoted(e.name) +
                         " (fontconfig's are bold, light, italic, oblique, condensed, mono, ...)"};
        }
    }
    FcPattern* parsed = FcNameParse(reinterpret_cast<const FcChar8*>(pattern.c_str()));
    if (parsed != nullptr) return FcPatternPtr(parsed);
    // FcNameParse fails on a value its property cannot take; name the first such element.
    for (const Element& e : elements_after_family(pattern)) {
        const std::string alone = ":" + e.text;
        FcPattern* p = FcNameParse(reinterpret_cast<const FcChar8*>(alone.c_str()));
        if (p == nullptr) {
            return Error{what + ": " + quoted(e.text) + " is not a value " + quoted(e.name) +
                         " can take"};
        }
        FcPatternDestroy(p);
    }
    return Error{what + ": fontconfig cannot parse it"};
}

Expected<FontSource> font_source(FcPattern* font) {
    FcChar8* file = nullptr;
    if (FcPatternGetString(font, FC_FILE, 0, &file) != FcResultMatch || file == nullptr) {
        FcChar8* name = FcNameUnparse(font);
        const std::string text = name != nullptr ? reinterpret_cast<char*>(name) : "?";
        std::free(name);
        return Error{"fontconfig font " + quoted(text) + " has no file"};
    }
    FontSource source;
    source.file = reinterpret_cast<const char*>(file);
    int index = 0;
    if (FcPatternGetInteger(font, FC_INDEX, 0, &index) != FcResultMatch) index = 0;
    // fontconfig follows FreeType's face index: the face in bits 0–15, the named instance
    // (1-based, 0 for none) in bits 16–30.
    source.face_index = index & 0xFFFF;
    const int instance = (index >> 16) & 0x7FFF;
    if (instance > 0) {
        auto coords = named_instance_coordinates(source.file, source.face_index, instance);
        if (!coords) return coords.error();
        source.variations = std::move(*coords);
    }
    // A pattern may hold several values ("fontvariations=wght=300,wdth=80" parses as two).
    FcChar8* variations = nullptr;
    for (int id = 0;
         FcPatternGetString(font, FC_FONT_VARIATIONS, id, &variations) == FcResultMatch; ++id) {
        if (variations == nullptr) continue;
        auto settings = parse_variations(reinterpret_cast<const char*>(variations), source.file);
        if (!settings) return settings.error();
        // A later setting of an axis replaces the earlier one, so each axis appears once.
        for (VariationSetting& s : *settings) {
            bool replaced = false;
            for (VariationSetting& have : source.variations) {
                if (have.tag == s.tag) {
                    have.value = s.value;
                    replaced = true;
                }
            }
            if (!replaced) source.variations.push_back(std::move(s));
        }
    }
    return source;
}

}  // namespace bezel::font_detail
