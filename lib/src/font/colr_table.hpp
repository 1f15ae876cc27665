// Private to the font module (and its tests): the COLR table read by bezel itself, and its paint
// graphs built into bezel/paint.hpp's ColorGlyph. No FreeType here: the caller hands over the
// table's bytes, the palette and a way to load a glyph's outline.
//
// Why bezel parses COLR rather than walking FreeType's FT_Get_Paint: Debian 12's FreeType 2.12.1
// (2.12.1+dfsg-5+deb12u3 on) is built with its COLRv1 API compiled out (debian/patches
// disable_COLRv1.patch: FT_Get_Color_Glyph_Paint, FT_Get_Paint, FT_Get_Paint_Layers,
// FT_Get_Colorline_Stops and FT_Get_Color_Glyph_ClipBox always return 0), and FreeType's COLRv0
// iterator ends a glyph's layers silently at a bad glyph or palette index. Reading the table
// (OpenType 1.9 'COLR', versions 0 and 1) gives the same graph on every FreeType, with errors that
// say what is wrong.
//
// Every read is bounds-checked against the table; offsets are followed only inside it. Variable
// paints (the Var* formats, ClipBox format 2, VarColorLine) are read at their default values: the
// variation deltas of the ItemVariationStore are not applied.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "bezel/expected.hpp"
#include "bezel/font.hpp"
#include "bezel/paint.hpp"

namespace bezel::font_detail {

// A COLR table whose header has been checked: version 0 or 1, and every list it names (base glyph
// records, layer records, BaseGlyphList, LayerList, ClipList) inside the table with its count.
class ColrTable {
public:
    // Errors (no glyph named: the caller adds the file): "COLR table too short", "COLR version N
    // not supported", "COLR <list> past the end of the table".
    static Expected<ColrTable> parse(std::vector<std::uint8_t> bytes);

    int version() const { return version_; }
    bool has_v0_glyphs() const { return num_base_v0_ > 0; }
    bool has_v1_glyphs() const { return num_base_v1_ > 0; }

    // The table offset of `gid`'s version 1 root paint, when the BaseGlyphList has it.
    std::optional<std::uint32_t> v1_root(GlyphId gid) const;
    // The first layer record and layer count of `gid`'s version 0 BaseGlyphRecord, when it has one.
    struct V0Layers {
        std::uint32_t first = 0, count = 0;
    };
    std::optional<V0Layers> v0_layers(GlyphId gid) const;
    struct V0Layer {
        GlyphId glyph = 0;
        std::uint16_t palette_index = 0;
    };
    // Layer record `index`; none past the table's layer records.
    std::optional<V0Layer> v0_layer(std::uint32_t index) const;

    // `gid`'s ClipBox in font units (y up), when the ClipList has one. ClipBox format 2 is read at
    // its default; an unknown format is no clip (the spec's rule for formats it does not define).
    // Error: a clip record or box past the end of the table.
    Expected<std::optional<Rect>> clip_box(GlyphId gid) const;

    // The raw reader the graph builder uses.
    const std::vector<std::uint8_t>& bytes() const { return bytes_; }
    std::uint32_t layer_list() const { return layer_list_; }
    std::uint32_t num_layers_v1() const { return num_layers_v1_; }

private:
    std::vector<std::uint8_t> bytes_;
    int version_ = 0;
    std::uint32_t base_v0_ = 0, num_base_v0_ = 0, layers_v0_ = 0, num_layers_v0_ = 0;
    std::uint32_t base_v1_ = 0, num_base_v1_ = 0;
    std::uint32_t layer_list_ = 0, num_layers_v1_ = 0;
    std::uint32_t clip_list_ = 0, num_clips_ = 0;
};

// What the graph builder needs from the font.
struct ColrContext {
    // The chosen palette's entries (straight sRGB), custom entries applied.
    std::vector<ColorF> palette;
    // The glyph count of the font (PaintGlyph and PaintColrGlyph ids are checked against it).
    std::size_t glyph_count = 0;
    // Loads `gid`'s outline in font units, y up (called once per glyph id per build); an error
    // says only why (the builder names the glyphs).
    std::function<Expected<Path>(GlyphId)> load_outline;
    // Error messages start "<file>: glyph 12 (name): ".
    std::string file;
    std::function<std::string(GlyphId)> glyph_label;   // "glyph 12 (name)"
};

// The version 1 paint graph of `gid` (precondition: table.v1_root(gid)), walked depth first with
// kMaxPaintDepth and kMaxPaintNodes (a node reached twice counts twice, as the painter visits it).
// PaintColrGlyph of one glyph id is built once and shared; each PaintGlyph outline is loaded once
// per glyph id. Errors start with the file and glyph_label(gid) and say what: the graph loops (a PaintColrGlyph
// inside itself), nests deeper than kMaxPaintDepth, visits more than kMaxPaintNodes, holds more
// than kMaxPaintColorStops colour stops or kMaxPaintOutlinePoints outline points, a palette
// index out of range (index and count), a glyph id out of range, an unknown paint format or
// composite mode, an offset past the end of the table, an outline that does not load.
Expected<ColorGlyph> build_colr_v1(const ColrTable& table, GlyphId gid, const ColrContext& context);

// Version 0: PaintLayers of PaintGlyph(PaintSolid), bottom layer first, each layer glyph's outline
// loaded once (precondition: table.v0_layers(gid)). Errors as build_colr_v1's for palette and
// glyph indices, outlines and the node and point budgets, and a layer record past the table.
Expected<ColorGlyph> build_colr_v0(const ColrTable& table, GlyphId gid, const ColrContext& context);

// Big-endian reads at a byte offset. Preconditions: the bytes are inside `b` (callers check
// with fits() first).
inline bool fits(const std::vector<std::uint8_t>& b, std::uint64_t offset, std::uint64_t length) {
    return offset <= b.size() && length <= b.size() - offset;
}
inline std::uint32_t read_u8(const std::vector<std::uint8_t>& b, std::size_t o) { return b[o]; }
inline std::uint32_t read_u16(const std::vector<std::uint8_t>& b, std::size_t o) {
    return std::uint32_t{b[o]} << 8 | b[o + 1];
}
inline std::int32_t read_s16(const std::vector<std::uint8_t>& b, std::size_t o) {
    return static_cast<std::int16_t>(read_u16(b, o));
}
inline std::uint32_t read_u24(const std::vector<std::uint8_t>& b, std::size_t o) {
    return read_u16(b, o) << 8 | b[o + 2];
}
inline std::uint32_t read_u32(const std::vector<std::uint8_t>& b, std::size_t o) {
    return read_u16(b, o) << 16 | read_u16(b, o + 2);
}
inline std::int32_t read_s32(const std::vector<std::uint8_t>& b, std::size_t o) {
    return static_cast<std::int32_t>(read_u32(b, o));
}

}  // namespace bezel::font_detail
