// Internal: the fonts a layout draws from, and which of them draws each character: one Shaper
// (layout_text's single-font form) or a FontCollection (font fallback).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_set>
#include <vector>

#include "bezel/font_collection.hpp"
#include "bezel/shape.hpp"
#include "text/layout_breaks.hpp"

namespace bezel::text_detail {

class LayoutFonts {
public:
    virtual ~LayoutFonts() = default;
    virtual std::size_t size() const = 0;
    virtual Shaper& shaper(std::size_t font) = 0;
    virtual const FontMetrics& metrics(std::size_t font) const = 0;
    // The design coordinates font `font` is shaped at: its own, and for the first font
    // ShapeOptions::variations after them (a later setting of an axis wins).
    virtual void variations(std::size_t font, const ShapeOptions& shape,
                            std::vector<VariationSetting>& out) const = 0;
    // out[k] = the font that draws text[k], for a paragraph of n code points. Every code point
    // of a grapheme cluster gets the same font.
    virtual Status assign(const char32_t* text, std::size_t n, UnicodeBreaks& breaks,
                          std::vector<std::uint16_t>& out) = 0;
};

// One Shaper: every character from it.
class SingleFont final : public LayoutFonts {
public:
    SingleFont(Shaper& shaper, const FontMetrics& metrics) : shaper_(shaper), metrics_(metrics) {}
    std::size_t size() const override { return 1; }
    Shaper& shaper(std::size_t) override { return shaper_; }
    const FontMetrics& metrics(std::size_t) const override { return metrics_; }
    void variations(std::size_t, const ShapeOptions& shape,
                    std::vector<VariationSetting>& out) const override {
        out = shape.variations;
    }
    Status assign(const char32_t*, std::size_t n, UnicodeBreaks&,
                  std::vector<std::uint16_t>& out) override {
        out.assign(n, 0);
        return ok_status();
    }

private:
    Shaper& shaper_;
    FontMetrics metrics_;
};

// A FontCollection, font by grapheme cluster (font_choice.cpp has the rule).
class CollectionFonts final : public LayoutFonts {
public:
    explicit CollectionFonts(FontCollection& fonts) : fonts_(fonts) {}
    std::size_t size() const override { return fonts_.size(); }
    Shaper& shaper(std::size_t font) override { return fonts_.shaper(font); }
    const FontMetrics& metrics(std::size_t font) const override { return fonts_.metrics(font); }
    void variations(std::size_t font, const ShapeOptions& shape,
                    std::vector<VariationSetting>& out) const override;
    Status assign(const char32_t* text, std::size_t n, UnicodeBreaks& breaks,
                  std::vector<std::uint16_t>& out) override;

private:
    // The font for one cluster (code points needing a glyph in needed_), given the previous
    // cluster's font (kNoFont at the start of a paragraph).
    std::uint16_t choose(std::uint16_t previous, bool prefer_colour, bool prefer_text);
    // Bit i set: font i maps `cp` (remembered per code point, extended as fonts are added).
    std::uint64_t fonts_with(char32_t cp);
    // The fonts that map every code point of needed_.
    std::uint64_t fonts_with_needed();
    std::optional<std::uint16_t> from_fallback(bool prefer_colour);

    // A direct-mapped memo of fonts_with: a page uses a few hundred distinct characters, each
    // looked up in every font once instead of once per occurrence.
    struct Coverage {
        char32_t cp = 0xFFFFFFFF;
        std::uint16_t fonts_checked = 0;
        std::uint64_t mask = 0;
    };
    static constexpr std::size_t kCoverageSlots = 4096;
    static_assert(kMaxCollectionFonts <= 64, "a coverage mask holds one bit per font");

    FontCollection& fonts_;
    std::vector<Coverage> coverage_;
    std::vector<std::uint8_t> starts_;
    std::u32string needed_;
    FallbackRequest request_;
    // Single characters the fallback had no font for: not asked again (bounded; cleared when
    // full).
    std::unordered_set<char32_t> unfound_;
};

}  // namespace bezel::text_detail
