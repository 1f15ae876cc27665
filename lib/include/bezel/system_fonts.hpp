// bezel/system_fonts.hpp — the system's fonts through fontconfig: a family or pattern selects a
// font, and a grapheme cluster no font of the caller's list covers gets fontconfig's fallback.
//
// Results are FontSource values (bezel/font.hpp): the file, the face in it, and the design
// coordinates that select what fontconfig meant — a variable font's named instance ("Black") or
// the coordinates fontconfig computed for a requested weight or width. Open one with
// Font::open(source.file, source.face_index) and Font::set_variations(source.variations).
//
// Patterns are fontconfig's (fc-match's): "DejaVu Sans", "Noto Serif:bold",
// "DejaVu Sans:style=Oblique", "monospace", "Noto Sans:lang=hi". The empty pattern is
// fontconfig's default font (sans-serif in the locale's language).
//
// Threading: a SystemFonts owns its own fontconfig configuration (FcConfig) and caches. One object
// must not be used from two threads at once; separate objects may be used on separate threads.
// Moving is cheap; a moved-from SystemFonts may only be destroyed or assigned to.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "bezel/expected.hpp"
#include "bezel/font.hpp"
#include "bezel/limits.hpp"

#pragma GCC visibility push(default)  // the public API of libbezel.so (docs/architecture.md)
namespace bezel {

// Unicode's Default_Ignorable_Code_Point property (DerivedCoreProperties.txt, Unicode 15): soft
// hyphen, CGJ, ZWSP/ZWNJ/ZWJ, bidi marks, embeddings and isolates, word joiner and invisible
// operators, variation selectors (180B–180F, FE00–FE0F, E0100–E01EF), ZWNBSP, Hangul fillers,
// tag characters and the reserved ranges the property includes. Shapers draw these as nothing
// when a font lacks them, so a font need not map them to cover a cluster.
bool is_default_ignorable(char32_t code_point);

struct SystemFontsOptions {
    // A fontconfig configuration file (fonts.conf syntax) to load instead of the system's: only
    // the fonts its <dir> elements name, its cache in its <cachedir>. Tests and applications
    // shipping their own fonts use it for results that do not depend on the machine. A relative
    // name is taken relative to the working directory.
    // Empty: the system configuration, as every fontconfig program loads it (FONTCONFIG_FILE
    // when set, else fontconfig's fonts.conf).
    std::string config_file;
};

struct FallbackQuery {
    // The primary font's pattern: it orders the fallback list (its family, style, language
    // first). Empty: fontconfig's default font.
    std::string pattern;
    // The code points of one grapheme cluster (a base and its marks, an emoji sequence).
    std::u32string_view cluster;
    // Emoji presentation: colour fonts (fontconfig's `color`, COLR/CBDT/sbix/SVG fonts) first.
    bool prefer_colour = false;
    // Only fonts with outlines (fontconfig's `outline`), for a caller that cannot draw
    // bitmap-only fonts.
    bool require_outlines = false;
};

struct SystemFontsStats {
    std::size_t sorts = 0;          // fontconfig sorts run (FcFontSort): one per uncached list
    std::size_t lists = 0;          // sorted fallback lists held now (≤ kMaxSystemFontLists)
    std::size_t evictions = 0;      // lists dropped, least recently used, to stay within it
    std::size_t fallback_queries = 0;
};

class SystemFonts {
public:
    // Loads the configuration and indexes its fonts (fontconfig's caches make this fast after
    // the first time). An explicit config_file that does not exist or that fontconfig cannot
    // load is an Error naming it (fontconfig prints its own reason on stderr). The system
    // configuration never fails: with no configuration or no fonts (a bare container) the set
    // is empty, match() reports that no font is installed and fallback() finds nothing.
    static Expected<SystemFonts> open(const SystemFontsOptions& options = {});

    SystemFonts(SystemFonts&&) noexcept;
    SystemFonts& operator=(SystemFonts&&) noexcept;
    SystemFonts(const SystemFonts&) = delete;
    SystemFonts& operator=(const SystemFonts&) = delete;
    ~SystemFonts();

    // Fonts (faces and named instances) the configuration knows; 0 for a bare environment.
    std::size_t font_count() const;
    // The configuration loaded: the file, or "the system fontconfig configuration".
    const std::string& configuration() const;

    // The font fontconfig's FcFontMatch picks for `pattern` after its configuration's
    // substitutions (FcConfigSubstitute) and the defaults (FcDefaultSubstitute) — as fc-match
    // does, so a family that is not installed gives the configuration's closest font, not an
    // error (open the result and compare its family_name() to tell). Errors name the pattern:
    // one fontconfig cannot parse ("Foo:size=abc"), an unknown property ("Foo:colour=1") or
    // style word ("Foo:blod"), no font at all, a named instance whose coordinates FreeType
    // cannot read. Each call asks fontconfig; keep the result.
    Expected<FontSource> match(const std::string& pattern);

    // The first font of fontconfig's sorted fallback list for query.pattern whose character set
    // covers every code point of query.cluster that is not default-ignorable (is_default_ignorable;
    // a cluster of ignorables only is covered by every font), or std::nullopt when none does.
    // The list is FcFontSort's order for the substituted pattern (with `color` set when
    // prefer_colour), restricted to outline fonts when require_outlines, and trimmed as
    // fontconfig trims: a font that covers nothing the fonts before it do not is left out.
    // Cost: the first query of a (pattern, prefer_colour, require_outlines) sorts once; later
    // queries are character-set lookups only. At most kMaxSystemFontLists lists are kept (least
    // recently used dropped). Errors: the pattern, as match(); a named instance as match().
    Expected<std::optional<FontSource>> fallback(const FallbackQuery& query);

    SystemFontsStats stats() const;

private:
    struct Impl;
    explicit SystemFonts(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace bezel
#pragma GCC visibility pop
