// The COLR table's header, its glyph lookups and clip boxes, and version 0 layers
// (OpenType 1.9 'COLR'). The version 1 paint graph is colr_paint.cpp.
#include "font/colr_table.hpp"

#include <string>
#include <unordered_map>

#include "bezel/limits.hpp"

namespace bezel::font_detail {

namespace {

// Record sizes in bytes, from the table layouts in the OpenType specification.
constexpr std::size_t kHeaderV0 = 14, kHeaderV1 = 34;
constexpr std::size_t kBaseGlyphRecord = 6;        // glyphID, firstLayerIndex, numLayers
constexpr std::size_t kLayerRecord = 4;            // glyphID, paletteIndex
constexpr std::size_t kBaseGlyphPaintRecord = 6;   // glyphID, Offset32 paint
constexpr std::size_t kLayerListEntry = 4;         // Offset32 paint
constexpr std::size_t kClipRecord = 7;             // startGlyphID, endGlyphID, Offset24 clipBox
constexpr std::size_t kClipBox = 9;                // format, xMin, yMin, xMax, yMax

std::string past_end(const char* what) {
    return std::string("COLR ") + what + " past the end of the table";
}

}  // namespace

Expected<ColrTable> ColrTable::parse(std::vector<std::uint8_t> bytes) {
    ColrTable t;
    t.bytes_ = std::move(bytes);
    const auto& b = t.bytes_;
    if (!fits(b, 0, kHeaderV0))
        return Error{"COLR table too short (" + std::to_string(b.size()) + " bytes)"};
    t.version_ = static_cast<int>(read_u16(b, 0));
    if (t.version_ > 1) return Error{"COLR version " + std::to_string(t.version_) + " not supported"};
    t.num_base_v0_ = read_u16(b, 2);
    t.base_v0_ = read_u32(b, 4);
    t.layers_v0_ = read_u32(b, 8);
    t.num_layers_v0_ = read_u16(b, 12);
    if (t.num_base_v0_ > 0 && !fits(b, t.base_v0_, kBaseGlyphRecord * t.num_base_v0_))
        return Error{past_end("base glyph records")};
    if (t.num_layers_v0_ > 0 && !fits(b, t.layers_v0_, kLayerRecord * t.num_layers_v0_))
        return Error{past_end("layer records")};
    if (t.version_ == 0) return t;

    if (!fits(b, 0, kHeaderV1)) return Error{"COLR version 1 header too short"};
    const std::uint32_t base_list = read_u32(b, 14), layer_list = read_u32(b, 18);
    const std::uint32_t clip_list = read_u32(b, 22);
    if (base_list != 0) {
        if (!fits(b, base_list, 4)) return Error{past_end("BaseGlyphList")};
        t.base_v1_ = base_list;
        t.num_base_v1_ = read_u32(b, base_list);
        if (!fits(b, std::uint64_t{base_list} + 4,
                  std::uint64_t{kBaseGlyphPaintRecord} * t.num_base_v1_))
            return Error{past_end("BaseGlyphList")};
    }
    if (layer_list != 0) {
        if (!fits(b, layer_list, 4)) return Error{past_end("LayerList")};
        t.layer_list_ = layer_list;
        t.num_layers_v1_ = read_u32(b, layer_list);
        if (!fits(b, std::uint64_t{layer_list} + 4, std::uint64_t{kLayerListEntry} * t.num_layers_v1_))
            return Error{past_end("LayerList")};
    }
    if (clip_list != 0) {
        if (!fits(b, clip_list, 5)) return Error{past_end("ClipList")};
        // ClipList format 1 is the only one defined; another is ignored (no clip boxes).
        if (read_u8(b, clip_list) == 1) {
            t.clip_list_ = clip_list;
            t.num_clips_ = read_u32(b, clip_list + 1);
            if (!fits(b, std::uint64_t{clip_list} + 5, std::uint64_t{kClipRecord} * t.num_clips_))
                return Error{past_end("ClipList")};
        }
    }
    return t;
}

namespace {

// The byte offset of the record for `gid` among `count` records of `stride` bytes from `first`,
// each starting with its glyph id (u16): the spec keeps both base-glyph lists sorted by glyph id,
// so a binary search. nullopt when the glyph has no record.
std::optional<std::size_t> find_base_record(const std::vector<std::uint8_t>& bytes,
                                            std::size_t first, std::uint32_t count,
                                            std::size_t stride, GlyphId gid) {
    std::uint32_t lo = 0, hi = count;
    while (lo < hi) {
        const std::uint32_t mid = lo + (hi - lo) / 2;
        const std::size_t rec = first + std::size_t{mid} * stride;
        const GlyphId g = read_u16(bytes, rec);
        if (g < gid) {
            lo = mid + 1;
        } else if (g > gid) {
            hi = mid;
        } else {
            return rec;
        }
    }
    return std::nullopt;
}

}  // namespace

std::optional<std::uint32_t> ColrTable::v1_root(GlyphId gid) const {
    const auto rec = find_base_record(bytes_, base_v1_ + 4, num_base_v1_, kBaseGlyphPaintRecord, gid);
    if (!rec) return std::nullopt;
    const std::uint64_t offset = std::uint64_t{base_v1_} + read_u32(bytes_, *rec + 2);
    if (offset >= bytes_.size()) return std::nullopt;
    return static_cast<std::uint32_t>(offset);
}

std::optional<ColrTable::V0Layers> ColrTable::v0_layers(GlyphId gid) const {
    const auto rec = find_base_record(bytes_, base_v0_, num_base_v0_, kBaseGlyphRecord, gid);
    if (!rec) return std::nullopt;
    return V0Layers{read_u16(bytes_, *rec + 2), read_u16(bytes_, *rec + 4)};
}

std::optional<ColrTable::V0Layer> ColrTable::v0_layer(std::uint32_t index) const {
    if (index >= num_layers_v0_) return std::nullopt;
    const std::size_t rec = layers_v0_ + std::size_t{index} * kLayerRecord;
    return V0Layer{read_u16(bytes_, rec), static_cast<std::uint16_t>(read_u16(bytes_, rec + 2))};
}

Expected<std::optional<Rect>> ColrTable::clip_box(GlyphId gid) const {
    // Clip records are sorted by glyph range and do not overlap: binary search on the start.
    std::uint32_t lo = 0, hi = num_clips_;
    while (lo < hi) {
        const std::uint32_t mid = lo + (hi - lo) / 2;
        const std::size_t rec = clip_list_ + 5 + std::size_t{mid} * kClipRecord;
        const GlyphId start = read_u16(bytes_, rec), end = read_u16(bytes_, rec + 2);
        if (end < gid) {
            lo = mid + 1;
        } else if (start > gid) {
            hi = mid;
        } else {
            const std::uint64_t box = std::uint64_t{clip_list_} + read_u24(bytes_, rec + 4);
            if (!fits(bytes_, box, kClipBox)) return Error{past_end("ClipBox")};
            // Format 1, and format 2 at its default (its varIndexBase follows the box).
            const std::uint32_t format = read_u8(bytes_, box);
            if (format != 1 && format != 2) return std::optional<Rect>{};
            const std::size_t p = static_cast<std::size_t>(box);
            return std::optional<Rect>{
                Rect{double(read_s16(bytes_, p + 1)), double(read_s16(bytes_, p + 3)),
                     double(read_s16(bytes_, p + 5)), double(read_s16(bytes_, p + 7))}};
        }
    }
    return std::optional<Rect>{};
}

Expected<ColorGlyph> build_colr_v0(const ColrTable& table, GlyphId gid, const ColrContext& context) {
    const std::optional<ColrTable::V0Layers> layers = table.v0_layers(gid);
    if (!layers) return Error{context.file + ": " + context.glyph_label(gid) + ": no COLR layers"};
    // Two nodes per layer and the root: bounded like a version 1 graph.
    if (2 * std::size_t{layers->count} + 1 > kMaxPaintNodes)
        return Error{context.file + ": " + context.glyph_label(gid) +
                     ": COLR paint graph visits more than " + std::to_string(kMaxPaintNodes) + " nodes"};
    ColorGlyph out;
    PaintLayers root;
    std::unordered_map<GlyphId, std::uint32_t> outline_of;   // glyph → index in out.outlines
    std::size_t points = 0;                                  // against kMaxPaintOutlinePoints
    for (std::uint32_t i = 0; i < layers->count; ++i) {
        const std::uint32_t index = layers->first + i;
        const std::optional<ColrTable::V0Layer> layer = table.v0_layer(index);
        if (!layer)
            return Error{context.file + ": " + context.glyph_label(gid) + ": COLR layer record " +
                         std::to_string(index) + " past the end of the table"};
        if (layer->glyph >= context.glyph_count)
            return Error{context.file + ": " + context.glyph_label(gid) + ": COLR layer " +
                         std::to_string(i) + " names glyph " + std::to_string(layer->glyph) +
                         ", out of range (the font has " + std::to_string(context.glyph_count) +
                         " glyphs)"};
        PaintColor color;
        if (layer->palette_index == 0xFFFF) {
            color.foreground = true;
            out.uses_foreground = true;
        } else if (layer->palette_index >= context.palette.size()) {
            return Error{context.file + ": " + context.glyph_label(gid) + ": COLR layer " +
                         std::to_string(i) + ": palette index " + std::to_string(layer->palette_index) +
                         " out of range (the palette has " + std::to_string(context.palette.size()) +
                         " entries)"};
        } else {
            color.color = context.palette[layer->palette_index];
        }
        std::uint32_t outline = 0;
        if (auto known = outline_of.find(layer->glyph); known != outline_of.end()) {
            outline = known->second;
        } else {
            Expected<Path> path = context.load_outline(layer->glyph);
            if (!path)
                return Error{context.file + ": " + context.glyph_label(gid) + ": outline of " +
                             context.glyph_label(layer->glyph) + ": " + path.error().message};
            points += path->points().size();
            if (points > kMaxPaintOutlinePoints)
                return Error{context.file + ": " + context.glyph_label(gid) +
                             ": COLR outlines hold more than " + std::to_string(kMaxPaintOutlinePoints) +
                             " points"};
            outline = static_cast<std::uint32_t>(out.outlines.size());
            out.outlines.push_back(std::move(*path));
            outline_of.emplace(layer->glyph, outline);
        }
        const auto solid = static_cast<PaintIndex>(out.nodes.size());
        out.nodes.emplace_back(PaintSolid{color});
        root.layers.push_back(static_cast<PaintIndex>(out.nodes.size()));
        out.nodes.emplace_back(PaintGlyph{outline, solid});
    }
    out.root = static_cast<PaintIndex>(out.nodes.size());
    out.nodes.emplace_back(std::move(root));
    return out;
}

}  // namespace bezel::font_detail
