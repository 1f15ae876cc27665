// SystemFonts: one FcConfig per object, FcFontMatch for a pattern, and per-cluster fallback
// answered from cached sorted lists (one FcFontSort per pattern and flags, then character-set
// lookups only).
#include "bezel/system_fonts.hpp"

#include <filesystem>
#include <list>
#include <system_error>
#include <utility>
#include <vector>

#include "font/fc_pattern.hpp"

namespace bezel {

using font_detail::FcCharSetPtr;
using font_detail::FcConfigPtr;
using font_detail::FcFontSetPtr;
using font_detail::FcPatternPtr;

namespace {

// One font of a sorted fallback list. `font` holds a reference to the configuration's pattern,
// so `charset` (owned by that pattern) lives as long as the entry.
struct SortedFont {
    FcPatternPtr font;
    const FcCharSet* charset = nullptr;
    // What the font opens as for this list's request, resolved when the font is first chosen
    // (a named instance reads the font's fvar table).
    std::optional<Expected<FontSource>> source;
};

struct FallbackList {
    std::string pattern;
    bool prefer_colour = false;
    bool require_outlines = false;
    FcPatternPtr request;  // the substituted pattern the list was sorted for
    std::vector<SortedFont> fonts;
};

// Every code point of the cluster that is not default-ignorable is in the charset.
bool covers(const FcCharSet* charset, std::u32string_view cluster) {
    for (char32_t c : cluster) {
        if (is_default_ignorable(c)) continue;
        if (charset == nullptr || !FcCharSetHasChar(charset, static_cast<FcChar32>(c))) return false;
    }
    return true;
}

std::size_t count_fonts(FcConfig* config) {
    std::size_t n = 0;
    for (FcSetName set : {FcSetSystem, FcSetApplication}) {
        if (FcFontSet* fonts = FcConfigGetFonts(config, set)) n += static_cast<std::size_t>(fonts->nfont);
    }
    return n;
}

}  // namespace

struct SystemFonts::Impl {
    FcConfigPtr config;
    std::string configuration;
    std::size_t font_count = 0;
    std::list<FallbackList> lists;  // most recently used first; size ≤ kMaxSystemFontLists
    SystemFontsStats stats;

    // The pattern as fontconfig matches it: parsed, `color` required when asked, the
    // configuration's substitutions and the defaults (size, weight, the locale's language) applied.
    Expected<FcPatternPtr> request(const std::string& pattern, bool prefer_colour) {
        auto parsed = font_detail::parse_pattern(pattern);
        if (!parsed) return parsed.error();
        FcPattern* p = parsed->get();
        if (prefer_colour) {
            FcPatternDel(p, FC_COLOR);
            FcPatternAddBool(p, FC_COLOR, FcTrue);
        }
        FcConfigSubstitute(config.get(), p, FcMatchPattern);
        FcDefaultSubstitute(p);
        return parsed;
    }

    std::string no_font(const std::string& pattern) const {
        std::string m = "font pattern '" + pattern + "': no font matches";
        if (font_count == 0) m += " (" + configuration + " lists no fonts)";
        return m;
    }

    // The list for the query, from the cache or sorted now.
    Expected<FallbackList*> list_for(const FallbackQuery& q) {
        for (auto it = lists.begin(); it != lists.end(); ++it) {
            if (it->pattern == q.pattern && it->prefer_colour == q.prefer_colour &&
                it->require_outlines == q.require_outlines) {
                lists.splice(lists.begin(), lists, it);
                return &lists.front();
            }
        }
        auto req = request(q.pattern, q.prefer_colour);
        if (!req) return req.error();
        FallbackList list;
        list.pattern = q.pattern;
        list.prefer_colour = q.prefer_colour;
        list.require_outlines = q.require_outlines;
        list.request = std::move(*req);

        // Untrimmed, then trimmed here as FcFontSort(trim) does — a font is kept only when it
        // covers a character no kept font before it covers — but after dropping the fonts the
        // query excludes, so an outline font hidden behind a bitmap one is not lost.
        FcResult result = FcResultMatch;
        FcFontSetPtr sorted(FcFontSort(config.get(), list.request.get(), FcFalse, nullptr, &result));
        ++stats.sorts;
        FcCharSetPtr seen(FcCharSetCreate());
        if (sorted && seen) {
            for (int i = 0; i < sorted->nfont; ++i) {
                FcPattern* font = sorted->fonts[i];
                FcBool outline = FcFalse;
                if (q.require_outlines &&
                    (FcPatternGetBool(font, FC_OUTLINE, 0, &outline) != FcResultMatch || !outline)) {
                    continue;
                }
                FcCharSet* charset = nullptr;
                if (FcPatternGetCharSet(font, FC_CHARSET, 0, &charset) != FcResultMatch ||
                    charset == nullptr || FcCharSetIsSubset(charset, seen.get())) {
                    continue;
                }
                FcCharSetMerge(seen.get(), charset, nullptr);
                FcPatternReference(font);
                list.fonts.push_back({FcPatternPtr(font), charset, std::nullopt});
            }
        }
        if (lists.size() >= kMaxSystemFontLists) {
            lists.pop_back();
            ++stats.evictions;
        }
        lists.push_front(std::move(list));
        return &lists.front();
    }

    // The FontSource of a list's font, prepared for the list's request as FcFontMatch prepares
    // its result (FcFontRenderPrepare: e.g. a variable font's coordinates for the weight asked).
    const Expected<FontSource>& source_of(FallbackList& list, SortedFont& entry) {
        if (!entry.source) {
            FcPatternPtr prepared(
                FcFontRenderPrepare(config.get(), list.request.get(), entry.font.get()));
            entry.source = font_detail::font_source(prepared ? prepared.get() : entry.font.get());
        }
        return *entry.source;
    }
};

SystemFonts::SystemFonts(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
SystemFonts::SystemFonts(SystemFonts&&) noexcept = default;
SystemFonts& SystemFonts::operator=(SystemFonts&&) noexcept = default;
SystemFonts::~SystemFonts() = default;

Expected<SystemFonts> SystemFonts::open(const SystemFontsOptions& options) {
    auto impl = std::make_unique<Impl>();
    if (options.config_file.empty()) {
        // A new configuration of the process's own (not fontconfig's shared current one), loaded
        // as every fontconfig program loads it. Without any configuration fontconfig prints a
        // warning and falls back to its built-in default; if even that fails, an empty one.
        impl->config.reset(FcInitLoadConfigAndFonts());
        if (!impl->config) impl->config.reset(FcConfigCreate());
        if (!impl->config) return Error{"fontconfig: cannot create a configuration (out of memory)"};
        impl->configuration = "the system fontconfig configuration";
    } else {
        const std::string& file = options.config_file;
        std::error_code ec;
        if (!std::filesystem::exists(file, ec)) {
            return Error{file + ": no such fontconfig configuration file"};
        }
        // fontconfig looks a relative name up in its own configuration directory.
        const std::string path = std::filesystem::absolute(file, ec).string();
        impl->config.reset(FcConfigCreate());
        if (!impl->config) return Error{file + ": fontconfig cannot create a configuration"};
        if (!FcConfigParseAndLoad(impl->config.get(), reinterpret_cast<const FcChar8*>(path.c_str()),
                                  FcTrue)) {
            return Error{file + ": fontconfig cannot load this configuration (its reason is on "
                                "stderr)"};
        }
        if (!FcConfigBuildFonts(impl->config.get())) {
            return Error{file + ": fontconfig cannot index the fonts of this configuration"};
        }
        impl->configuration = "fontconfig configuration " + file;
    }
    impl->font_count = count_fonts(impl->config.get());
    return SystemFonts(std::move(impl));
}

std::size_t SystemFonts::font_count() const { return impl_->font_count; }

const std::string& SystemFonts::configuration() const { return impl_->configuration; }

Expected<FontSource> SystemFonts::match(const std::string& pattern) {
    auto req = impl_->request(pattern, false);
    if (!req) return req.error();
    FcResult result = FcResultNoMatch;
    FcPatternPtr matched(FcFontMatch(impl_->config.get(), req->get(), &result));
    if (!matched) return Error{impl_->no_font(pattern)};
    auto source = font_detail::font_source(matched.get());
    if (!source) return Error{"font pattern '" + pattern + "': " + source.error().message};
    return source;
}

Expected<std::optional<FontSource>> SystemFonts::fallback(const FallbackQuery& query) {
    ++impl_->stats.fallback_queries;
    auto list = impl_->list_for(query);
    if (!list) return list.error();
    for (SortedFont& entry : (*list)->fonts) {
        if (!covers(entry.charset, query.cluster)) continue;
        const Expected<FontSource>& source = impl_->source_of(**list, entry);
        if (!source) {
            return Error{"font pattern '" + query.pattern + "': " + source.error().message};
        }
        return std::optional<FontSource>(*source);
    }
    return std::optional<FontSource>();
}

SystemFontsStats SystemFonts::stats() const {
    SystemFontsStats s = impl_->stats;
    s.lists = impl_->lists.size();
    return s;
}

}  // namespace bezel
