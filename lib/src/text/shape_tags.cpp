// Script and language tags for the shaper.
#include <cctype>
#include <mutex>
#include <utility>
#include <vector>

#include "text/shape_tags.hpp"

namespace bezel::text_detail {

std::string tag_string(hb_tag_t tag) {
    char s[4];
    hb_tag_to_string(tag, s);
    return std::string(s, 4);
}

namespace {

// Whether HarfBuzz's Unicode data gives `script` to some character. hb_script_from_string turns
// any four letters into a script value ("Xyzw" included), so this is what tells a real script
// from a typo. The scan stops at the script's first character: U+0041 for Latn, U+1E900 for
// Adlm; only a tag that names no script goes through all 0x110000 code points, on the way to
// an error.
// The answers are remembered (layout shapes every run with its script named, up to thousands of
// runs a page, and a scan to U+0900 for Devanagari is 2,300 lookups). Well-formed tags that
// name no script are remembered too, up to kMaxRememberedScripts (past that, scanned again).
bool unicode_has_script(hb_script_t script) {
    constexpr std::size_t kMaxRememberedScripts = 1024;
    static std::mutex mutex;
    static std::vector<std::pair<hb_script_t, bool>> known;
    {
        std::lock_guard<std::mutex> lock(mutex);
        for (const auto& k : known)
            if (k.first == script) return k.second;
    }
    hb_unicode_funcs_t* ucd = hb_unicode_funcs_get_default();
    bool found = false;
    for (hb_codepoint_t cp = 0; cp <= 0x10FFFF && !found; ++cp)
        found = hb_unicode_script(ucd, cp) == script;
    std::lock_guard<std::mutex> lock(mutex);
    if (known.size() < kMaxRememberedScripts) known.emplace_back(script, found);
    return found;
}

}  // namespace

Expected<hb_script_t> parse_script_tag(const std::string& tag) {
    bool ok = tag.size() == 4;
    for (char c : tag) ok = ok && std::isalpha(static_cast<unsigned char>(c));
    if (!ok) return Error{"script '" + tag + "': not an ISO 15924 tag (four letters, e.g. Arab)"};
    // Aliases map to their script here (Hans and Hant to Hani, Latf to Latn, Qaai to Zinh).
    const hb_script_t script = hb_script_from_string(tag.c_str(), 4);
    // Zmth (mathematical notation) is a script HarfBuzz shapes with but no character has.
    if (script != HB_SCRIPT_MATH && !unicode_has_script(script))
        return Error{"script '" + tag + "': not a script HarfBuzz knows (ISO 15924, e.g. Latn, Arab, Deva)"};
    return script;
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
