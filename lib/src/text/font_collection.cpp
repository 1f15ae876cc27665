// FontCollection: fonts opened once per face, in list order, plus the ones a fallback source
// adds.
#include "bezel/font_collection.hpp"

#include <utility>

#include "text/layout_breaks.hpp"

namespace bezel {

namespace {

struct Entry {
    FontSource source;
    FontOrigin origin;
    Font font;
    Shaper shaper;
    FontMetrics metrics;
    bool colour;
};

}  // namespace

struct FontCollection::Impl {
    // unique_ptr: a Font keeps its address while the list grows.
    std::vector<std::unique_ptr<Entry>> entries;
    std::shared_ptr<FallbackSource> fallback;
    std::vector<std::string> warnings;
    bool outlines_only = false;
};

FontCollection::FontCollection(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
FontCollection::FontCollection(FontCollection&&) noexcept = default;
FontCollection& FontCollection::operator=(FontCollection&&) noexcept = default;
FontCollection::~FontCollection() = default;

Expected<FontCollection> FontCollection::open(const std::vector<FontSource>& sources) {
    if (sources.empty()) return Error{"font list: empty (give at least one font)"};
    FontCollection fonts(std::make_unique<Impl>());
    for (const FontSource& source : sources)
        if (auto added = fonts.add(source); !added) return added.error();
    return fonts;
}

Expected<std::size_t> FontCollection::add(const FontSource& source, FontOrigin origin) {
    if (impl_->entries.size() >= kMaxCollectionFonts)
        return Error{source.file + ": a font list holds at most " +
                     std::to_string(kMaxCollectionFonts) + " fonts"};
    auto font = Font::open(source.file, source.face_index);
    if (!font) return font.error();
    if (!source.variations.empty()) {
        if (auto set = font->set_variations(source.variations); !set) {
            const std::string& m = set.error().message;
            return m.find(source.file) == std::string::npos ? Error{source.file + ": " + m}
                                                            : set.error();
        }
    }
    if (origin == FontOrigin::System && impl_->outlines_only) {
        if (Status s = font->require_outlines(); !s) return s.error();
    }
    auto shaper = Shaper::open(source.file, source.face_index);
    if (!shaper) return shaper.error();
    const FontMetrics metrics = font->metrics();
    const bool colour = font->has_color_bitmaps();
    impl_->entries.push_back(std::make_unique<Entry>(
        Entry{source, origin, std::move(*font), std::move(*shaper), metrics, colour}));
    return impl_->entries.size() - 1;
}

std::size_t FontCollection::size() const { return impl_->entries.size(); }
Font& FontCollection::font(std::size_t i) { return impl_->entries.at(i)->font; }
Shaper& FontCollection::shaper(std::size_t i) { return impl_->entries.at(i)->shaper; }
const FontSource& FontCollection::source(std::size_t i) const { return impl_->entries.at(i)->source; }
FontOrigin FontCollection::origin(std::size_t i) const { return impl_->entries.at(i)->origin; }
const FontMetrics& FontCollection::metrics(std::size_t i) const {
    return impl_->entries.at(i)->metrics;
}
bool FontCollection::is_colour(std::size_t i) const { return impl_->entries.at(i)->colour; }

Expected<bool> FontCollection::covers(std::size_t i, const char32_t* cluster,
                                      std::size_t n) const {
    const Font& font = impl_->entries.at(i)->font;
    for (std::size_t k = 0; k < n; ++k) {
        if (font.glyph_for_char(cluster[k])) continue;
        // Asked only for characters the font lacks, so ICU is not loaded for covered text.
        auto ignorable =
            text_detail::has_unicode_property(cluster[k], text_detail::UnicodeProperty::DefaultIgnorable);
        if (!ignorable) return ignorable.error();
        if (!*ignorable) return false;
    }
    return true;
}

Expected<std::optional<std::size_t>> FontCollection::font_for(const std::u32string& cluster) {
    for (std::size_t i = 0; i < size(); ++i) {
        auto ok = covers(i, cluster.data(), cluster.size());
        if (!ok) return ok.error();
        if (*ok) return std::optional<std::size_t>(i);
    }
    if (!impl_->fallback) return std::optional<std::size_t>{};
    FallbackRequest request;
    for (char32_t c : cluster) {
        auto ignorable =
            text_detail::has_unicode_property(c, text_detail::UnicodeProperty::DefaultIgnorable);
        if (!ignorable) return ignorable.error();
        if (!*ignorable) request.cluster.push_back(c);
    }
    request.outlines_only = impl_->outlines_only;
    auto source = impl_->fallback->font_for(request);
    if (!source) {
        add_warning(source.error().message);
        return std::optional<std::size_t>{};
    }
    if (!*source) return std::optional<std::size_t>{};
    for (std::size_t i = 0; i < size(); ++i)
        if (this->source(i).file == (*source)->file &&
            this->source(i).face_index == (*source)->face_index)
            return std::optional<std::size_t>{};   // listed, and it did not cover the cluster
    auto added = add(**source, FontOrigin::System);
    if (!added) {
        add_warning(added.error().message);
        return std::optional<std::size_t>{};
    }
    auto ok = covers(*added, cluster.data(), cluster.size());
    if (!ok) return ok.error();
    return *ok ? std::optional<std::size_t>(*added) : std::optional<std::size_t>{};
}

void FontCollection::set_fallback(std::shared_ptr<FallbackSource> fallback) {
    impl_->fallback = std::move(fallback);
}
FallbackSource* FontCollection::fallback() const { return impl_->fallback.get(); }
void FontCollection::set_outlines_only(bool outlines_only) {
    impl_->outlines_only = outlines_only;
}
bool FontCollection::outlines_only() const { return impl_->outlines_only; }
const std::vector<std::string>& FontCollection::warnings() const { return impl_->warnings; }
void FontCollection::add_warning(std::string message) {
    impl_->warnings.push_back(std::move(message));
}

}  // namespace bezel
