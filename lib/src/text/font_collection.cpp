// FontCollection: fonts opened once per face (one FontFace for each font's Font and Shaper), in
// list order, plus the ones a fallback source adds.
#include "bezel/font_collection.hpp"
#include "text/layout_fonts.hpp"

#include <utility>


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

class SystemFallback final : public FallbackSource {
public:
    SystemFallback(std::string pattern, SystemFontsOptions options)
        : pattern_(std::move(pattern)), options_(std::move(options)) {}

    Expected<std::optional<FontSource>> font_for(const FallbackRequest& request) override {
        if (!fonts_) {
            if (!failure_.empty()) return Error{failure_};
            auto opened = SystemFonts::open(options_);
            if (!opened) {
                failure_ = "system fonts: " + opened.error().message;
                return Error{failure_};
            }
            fonts_ = std::move(*opened);
        }
        FallbackQuery query;
        query.pattern = pattern_;
        query.cluster = request.cluster;
        query.prefer_colour = request.prefer_colour;
        query.require_outlines = request.outlines_only;
        return fonts_->fallback(query);
    }

private:
    std::string pattern_;
    SystemFontsOptions options_;
    std::optional<SystemFonts> fonts_;
    std::string failure_;   // why the configuration could not be loaded (asked once)
};

}  // namespace

std::shared_ptr<FallbackSource> system_fallback(std::string pattern, SystemFontsOptions options) {
    return std::make_shared<SystemFallback>(std::move(pattern), std::move(options));
}

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

Expected<FontCollection> FontCollection::from_face(const FontFace& face,
                                                   const std::vector<VariationSetting>& variations) {
    FontCollection fonts(std::make_unique<Impl>());
    if (auto added = fonts.add(face, variations); !added) return added.error();
    return fonts;
}

Expected<std::size_t> FontCollection::add(const FontSource& source, FontOrigin origin) {
    if (impl_->entries.size() >= kMaxCollectionFonts)
        return Error{source.file + ": a font list holds at most " +
                     std::to_string(kMaxCollectionFonts) + " fonts"};
    auto face = FontFace::open(source.file, source.face_index);
    if (!face) return face.error();
    return add_face(*face, source, origin);
}

Expected<std::size_t> FontCollection::add(const FontFace& face,
                                          const std::vector<VariationSetting>& variations) {
    const FontSource source{face.name(), face.face_index(), variations};
    if (impl_->entries.size() >= kMaxCollectionFonts)
        return Error{source.file + ": a font list holds at most " +
                     std::to_string(kMaxCollectionFonts) + " fonts"};
    return add_face(face, source, FontOrigin::Listed);
}

// One face for both the Font and the Shaper: the bytes are read once, and both see the same.
Expected<std::size_t> FontCollection::add_face(const FontFace& face, const FontSource& source,
                                               FontOrigin origin) {
    auto font = Font::open(face);
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
    auto shaper = Shaper::open(face);
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
const FontSource& FontCollection::source(std::size_t i) const {
    return impl_->entries.at(i)->source;
}
FontOrigin FontCollection::origin(std::size_t i) const { return impl_->entries.at(i)->origin; }
const FontMetrics& FontCollection::metrics(std::size_t i) const {
    return impl_->entries.at(i)->metrics;
}
void FontCollection::variations_for(std::size_t i,
                                    const std::vector<VariationSetting>& shape_variations,
                                    std::vector<VariationSetting>& out) const {
    out = source(i).variations;
    if (i == 0) out.insert(out.end(), shape_variations.begin(), shape_variations.end());
}
bool FontCollection::is_colour(std::size_t i) const { return impl_->entries.at(i)->colour; }

bool FontCollection::covers(std::size_t i, const char32_t* cluster, std::size_t n) const {
    const Font& font = impl_->entries.at(i)->font;
    for (std::size_t k = 0; k < n; ++k) {
        if (!font.glyph_for_char(cluster[k]) && !is_default_ignorable(cluster[k])) return false;
    }
    return true;
}

std::optional<std::size_t> FontCollection::font_for(const std::u32string& cluster) {
    // Layout's own choice, so a glyph or an atlas entry comes from the font a page would draw it
    // with (an emoji from the colour font); it gives the first font when nothing covers it.
    text_detail::CollectionFonts fonts(*this);
    text_detail::UnicodeBreaks breaks;
    std::vector<std::uint16_t> chosen;
    if (fonts.assign(cluster.data(), cluster.size(), breaks, chosen) && !chosen.empty() &&
        covers(chosen[0], cluster.data(), cluster.size()))
        return chosen[0];
    // ICU could not find the clusters: the first font that covers it, then the fallback's.
    for (std::size_t i = 0; i < size(); ++i)
        if (covers(i, cluster.data(), cluster.size())) return i;
    FallbackRequest request;
    for (char32_t c : cluster)
        if (!is_default_ignorable(c)) request.cluster.push_back(c);
    request.outlines_only = impl_->outlines_only;
    return fallback_font(request);
}

std::optional<std::size_t> FontCollection::fallback_font(const FallbackRequest& request) {
    if (!impl_->fallback) return std::nullopt;
    auto source = impl_->fallback->font_for(request);
    if (!source) {
        add_warning(source.error().message);
        return std::nullopt;
    }
    if (!*source) return std::nullopt;
    for (std::size_t i = 0; i < size(); ++i)
        if (this->source(i).file == (*source)->file &&
            this->source(i).face_index == (*source)->face_index)
            return std::nullopt;   // listed already, and no listed font covers the cluster
    auto added = add(**source, FontOrigin::System);
    if (!added) {
        add_warning(added.error().message);
        return std::nullopt;
    }
    if (covers(*added, request.cluster.data(), request.cluster.size())) return *added;
    return std::nullopt;
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
    // A source that fails fails for every cluster: one line each.
    for (const std::string& w : impl_->warnings)
        if (w == message) return;
    impl_->warnings.push_back(std::move(message));
}

}  // namespace bezel
