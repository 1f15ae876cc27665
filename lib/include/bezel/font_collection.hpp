// bezel/font_collection.hpp — an ordered list of fonts that text draws from: each grapheme
// cluster comes from the first font of the list that covers it (font fallback).
//
// Threading: a FontCollection holds Fonts and Shapers; one collection must not be used from two
// threads at once. Open one per thread (faces are opened once per collection).
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bezel/expected.hpp"
#include "bezel/font.hpp"
#include "bezel/limits.hpp"
#include "bezel/shape.hpp"
#include "bezel/system_fonts.hpp"

#pragma GCC visibility push(default)  // the public API of libbezel.so (docs/architecture.md)
namespace bezel {

// Where a font of the collection came from.
enum class FontOrigin : std::uint8_t {
    Listed,   // the list it was opened with, or add()
    System,   // found by the system fallback for characters no listed font covers
};

// What a fallback source is asked for: a font for one grapheme cluster.
struct FallbackRequest {
    std::u32string cluster;       // the code points that need glyphs (default-ignorables removed)
    bool prefer_colour = false;   // emoji presentation: a colour font first
    bool outlines_only = false;   // the collection takes only fonts with outlines
};

// Asked for a font when no font of the collection covers a cluster (for example fontconfig's
// sorted fallback: system_fallback below). nullopt: no font has it. An Error (a source that
// cannot work, such as a malformed pattern) becomes a warning of the collection, and the cluster
// is drawn as missing.
class FallbackSource {
public:
    virtual ~FallbackSource() = default;
    virtual Expected<std::optional<FontSource>> font_for(const FallbackRequest& request) = 0;
};

// A fallback source over the system's fonts (SystemFonts::fallback, fontconfig's sorted list
// for `pattern`: the primary font's family or pattern, which orders the list). The fontconfig
// configuration is loaded on the first request (about 9 ms with a warm fontconfig cache), so a
// text every listed font covers never pays for it. A configuration that cannot be loaded, or a
// pattern fontconfig rejects, is an Error of each request (a warning of the collection).
std::shared_ptr<FallbackSource> system_fallback(std::string pattern,
                                                SystemFontsOptions options = {});

class FontCollection {
public:
    // Opens each source's face once (FontFace::open: the file read once), makes a Font
    // (outlines, metrics) and a Shaper (HarfBuzz) of that one face, and sets its variations. Errors name the file and the reason: missing, not a font, face index
    // out of range, an unknown variation axis; an empty list; more than kMaxCollectionFonts.
    static Expected<FontCollection> open(const std::vector<FontSource>& sources);
    // A list of one face read already (a font from memory; font_face.hpp), at `variations`: what
    // add(face, variations) appends to a list. Errors as add().
    static Expected<FontCollection> from_face(const FontFace& face,
                                              const std::vector<VariationSetting>& variations = {});
    FontCollection(FontCollection&&) noexcept;
    FontCollection& operator=(FontCollection&&) noexcept;
    FontCollection(const FontCollection&) = delete;
    FontCollection& operator=(const FontCollection&) = delete;
    ~FontCollection();

    // Appends a font (its index is size() − 1). Errors as open().
    Expected<std::size_t> add(const FontSource& source, FontOrigin origin = FontOrigin::Listed);
    // Appends a face read already (a font from memory, or one shared with other collections and
    // threads: its Font and Shaper are new instances of it), at `variations`. Its source(i) is
    // {face.name(), face.face_index(), variations}. Errors as open().
    Expected<std::size_t> add(const FontFace& face,
                              const std::vector<VariationSetting>& variations = {});

    std::size_t size() const;
    // Fonts keep their index and their address for the life of the collection. A
    // GlyphRasterizer made from font(i) shares its face (glyph.hpp) and follows its variations.
    Font& font(std::size_t i);
    Shaper& shaper(std::size_t i);
    const FontSource& source(std::size_t i) const;
    FontOrigin origin(std::size_t i) const;
    const FontMetrics& metrics(std::size_t i) const;
    // The design coordinates font i is shaped and drawn at (layout.hpp): its FontSource's, and
    // for the first font `shape_variations` (ShapeOptions::variations) after them, a later
    // setting of an axis winning. Written to `out`.
    void variations_for(std::size_t i, const std::vector<VariationSetting>& shape_variations,
                        std::vector<VariationSetting>& out) const;
    // A colour font (COLR, CBDT, sbix): preferred for emoji presentation.
    bool is_colour(std::size_t i) const;

    // The font for one character or cluster outside text layout (a glyph, an atlas entry): the one
    // layout would draw it with (its rule, text.md's "Font fallback": an emoji takes the first
    // colour font that covers it, otherwise the first font that covers it, else the fallback
    // source's, appended), or nullopt when none covers it.
    std::optional<std::size_t> font_for(const std::u32string& cluster);

    // The fallback source's font for a cluster no font of the list covers: asks the source,
    // appends the font it names (FontOrigin::System) and returns its index when it covers
    // request.cluster. nullopt: no source, no font, a font already listed, or one that cannot be
    // opened or fails request.outlines_only (those two, and the source's errors, are warnings).
    std::optional<std::size_t> fallback_font(const FallbackRequest& request);

    // Whether font i maps every code point of `cluster` except default-ignorable ones
    // (is_default_ignorable, system_fonts.hpp: ZWJ, variation selectors, tags; HarfBuzz draws
    // them as nothing when the font lacks them).
    bool covers(std::size_t i, const char32_t* cluster, std::size_t n) const;

    // Where no font of the list covers a cluster, `fallback` is asked for one; a font it
    // names is opened and appended with FontOrigin::System (once per file and face). A font it
    // names that fails to open is skipped, and its error kept in warnings(): a system font is not
    // the caller's mistake. nullptr (the default): no fallback beyond the list.
    void set_fallback(std::shared_ptr<FallbackSource> fallback);
    FallbackSource* fallback() const;
    // Whether fonts from the fallback must have outlines (a renderer that cannot draw colour
    // bitmaps sets it): a bitmap-only one is then skipped with a warning. Off by default.
    void set_outlines_only(bool outlines_only);
    bool outlines_only() const;
    // Fonts the fallback named that could not be opened and the fallback's own errors, each
    // message once.
    const std::vector<std::string>& warnings() const;
    // Records a fallback font that could not be opened (the layout calls it).
    void add_warning(std::string message);

private:
    struct Impl;
    explicit FontCollection(std::unique_ptr<Impl> impl);
    Expected<std::size_t> add_face(const FontFace& face, const FontSource& source,
                                   FontOrigin origin);
    std::unique_ptr<Impl> impl_;
};

}  // namespace bezel
#pragma GCC visibility pop
