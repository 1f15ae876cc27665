// GlyphCache: rendered glyph bitmaps in slots, found through an open-addressing hash table and
// ordered by an intrusive least-recently-used list.
//
// Memory. `bytes` counts each entry's pixel capacity plus kEntryOverheadBytes (so blank glyphs,
// which have no pixels, still count and the number of entries is bounded too); inserting evicts
// from the LRU end until the new entry fits under max_bytes. A glyph larger than max_bytes on its
// own is not cached: it is rendered into an "unkept" scratch bitmap that the next get() reuses
// (outside a batch) or that lives until end_batch() (inside one).
//
// Handles. Slots live in a deque, which never moves an element when it grows, so a CachedGlyph*
// (and its slot's pixels) stays put until the slot is evicted or dropped. A batch pins what it
// returns: each pinned slot carries the batch's number, and since every hit and insert moves its
// slot to the head of the LRU list, the pinned slots are a prefix of the list from the head. So
// the tail is unpinned unless every slot is pinned, and eviction from the tail stops at the
// first pinned slot: then the cache grows past max_bytes for the rest of the batch.
//
// No allocation once warm: hits touch only the table and the list; a miss that evicts reuses the
// last evicted slot's pixel buffer (glyphs of one size are of similar sizes), slots are recycled
// through a free list, and the table is rehashed only while the number of entries grows.
#include <array>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <deque>
#include <string>
#include <vector>

#include "bezel/glyph.hpp"

namespace bezel {

namespace {

constexpr std::size_t kEntryOverheadBytes = 64;
constexpr std::int32_t kNone = -1;

struct Key {
    std::uint64_t instance_id;   // the rasterizer's Font::instance_id(): face and variations
    std::uint64_t size_bits;       // the double's bit pattern: sizes compare exactly
    std::uint64_t tolerance_bits;
    std::uint64_t flatness_bits;   // ClassicFlatness's ε (the tolerance's counterpart there)
    std::uint64_t slant_bits;
    std::uint64_t bold_bits;
    GlyphId gid;
    std::uint8_t bin_x, bin_y, coverage, rule_overlap;   // coverage: format and LCD order
    std::uint8_t outline_box;   // hinting (2 bits), box mode (1) and flattening method (2)
    std::array<std::uint8_t, 5> lcd_filter;
    std::uint8_t color_mode;    // colour enabled (1 bit) and bitmap filter (1)
    std::int32_t palette;
    std::uint64_t custom_palette;   // a hash of the custom entries (0: none)

    bool operator==(const Key& o) const {
        return instance_id == o.instance_id && size_bits == o.size_bits &&
               tolerance_bits == o.tolerance_bits && flatness_bits == o.flatness_bits &&
               slant_bits == o.slant_bits && bold_bits == o.bold_bits &&
               gid == o.gid && bin_x == o.bin_x && bin_y == o.bin_y && coverage == o.coverage &&
               rule_overlap == o.rule_overlap && outline_box == o.outline_box &&
               lcd_filter == o.lcd_filter && color_mode == o.color_mode &&
               palette == o.palette && custom_palette == o.custom_palette;
    }
};

std::uint64_t bits(double v) {
    std::uint64_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
}

// splitmix64's finalizer: a cheap mix whose low bits depend on every input bit.
std::uint64_t mix(std::uint64_t x) {
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ULL;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

std::uint64_t hash_key(const Key& k) {
    std::uint64_t h = mix(k.instance_id ^ 0x9e3779b97f4a7c15ULL);
    h = mix(h ^ k.size_bits);
    h = mix(h ^ k.tolerance_bits);
    h = mix(h ^ k.flatness_bits);
    h = mix(h ^ k.slant_bits);
    h = mix(h ^ k.bold_bits);
    std::uint64_t filter = k.outline_box;
    for (std::uint8_t tap : k.lcd_filter) filter = filter << 8 | tap;
    h = mix(h ^ filter);
    h = mix(h ^ (std::uint64_t{k.color_mode} << 32 | static_cast<std::uint32_t>(k.palette)));
    h = mix(h ^ k.custom_palette);
    return mix(h ^ (std::uint64_t{k.gid} << 32 | std::uint64_t{k.bin_x} << 24 |
                    std::uint64_t{k.bin_y} << 16 | std::uint64_t{k.coverage} << 8 | k.rule_overlap));
}

// The custom palette entries as one number for the key: FNV-1a over index and colour, so two
// lists of the same entries hash alike only when they are the same list (order counts, as the
// later of two entries for one index wins).
std::uint64_t custom_palette_hash(const std::vector<ColorGlyphOptions::Entry>& entries) {
    if (entries.empty()) return 0;
    std::uint64_t h = 0xcbf29ce484222325ULL;
    for (const ColorGlyphOptions::Entry& e : entries) {
        const std::uint64_t v = std::uint64_t{static_cast<std::uint32_t>(e.index)} << 32 |
                                std::uint64_t{e.color.r} << 24 | std::uint64_t{e.color.g} << 16 |
                                std::uint64_t{e.color.b} << 8 | e.color.a;
        for (int i = 0; i < 8; ++i) h = (h ^ ((v >> (8 * i)) & 0xff)) * 0x100000001b3ULL;
    }
    return h | 1;   // never 0, the key of no custom entries
}

std::uint32_t rgba_bits(Rgba8 c) {
    return std::uint32_t{c.r} << 24 | std::uint32_t{c.g} << 16 | std::uint32_t{c.b} << 8 | c.a;
}

// floor(v · bins) for v in [0, 1) (the caller checked the range). The min guards the one float
// case where v · bins rounds up to bins (v just below 1).
std::uint8_t bin_of(double v) {
    return static_cast<std::uint8_t>(std::min(kSubpixelBins - 1, static_cast<int>(v * kSubpixelBins)));
}

bool in_unit_interval(double v) { return v >= 0.0 && v < 1.0; }   // NaN fails

std::string format_number(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

// Draws a prepared glyph into `pixels` (rows packed, `row_bytes` each): RGBA for a colour glyph,
// coverage otherwise.
Expected<CachedGlyph> draw_into(GlyphRasterizer& rasterizer, const PreparedGlyph& glyph,
                                std::uint8_t* pixels, int row_bytes) {
    const GlyphBox& box = glyph.box;
    CachedGlyph out;
    out.box = box;
    if (box.color) {
        const RgbaView view{pixels, box.width, box.height, row_bytes};
        if (Status drawn = rasterizer.draw_rgba(glyph, view); !drawn) return drawn.error();
        out.rgba = view;
        out.mask = {nullptr, 0, 0, 0};
    } else {
        const MaskView view{pixels, row_bytes, box.height, row_bytes};
        if (Status drawn = rasterizer.draw(glyph, view); !drawn) return drawn.error();
        out.mask = view;
    }
    return out;
}

}  // namespace

struct GlyphCache::Impl {
    struct Slot {
        Key key{};
        CachedGlyph glyph;
        // A colour glyph painted with the text colour (palette index 0xFFFF): the foreground it
        // was painted with, checked on every hit (the key leaves the foreground out, so mask
        // glyphs and other colour glyphs are shared by every text colour).
        bool uses_foreground = false;
        std::uint32_t foreground = 0;
        std::uint64_t pinned_batch = 0;   // the batch that returned it last (0: none)
        std::vector<std::uint8_t> pixels;
        std::int32_t prev = kNone, next = kNone;   // LRU list (head = most recent) or free list
    };

    // A glyph drawn but not kept in a slot (larger than max_bytes, or a pinned colour glyph
    // asked for in a second text colour).
    struct Unkept {
        std::vector<std::uint8_t> pixels;
        CachedGlyph glyph;
    };

    std::size_t max_bytes;
    std::deque<Slot> slots;   // a deque: slots never move (handles stay valid)
    std::int32_t head = kNone, tail = kNone, free_list = kNone;
    std::vector<std::int32_t> table;   // slot index or kNone; size a power of two, load ≤ 1/2
    GlyphCacheStats stats;
    // Unkept glyphs: [0, unkept_used) are live (the last get's outside a batch, the batch's in
    // one); the rest are buffers kept for reuse.
    std::vector<std::unique_ptr<Unkept>> unkept;
    std::size_t unkept_used = 0;
    bool in_batch = false;
    std::uint64_t batch = 0;   // the current (or last) batch's number, from 1

    explicit Impl(std::size_t max) : max_bytes(max) {}

    bool pinned(std::int32_t s) { return in_batch && at(s).pinned_batch == batch; }
    void pin(std::int32_t s) {
        if (in_batch) at(s).pinned_batch = batch;
    }
    Unkept& next_unkept() {
        if (unkept_used == unkept.size()) unkept.push_back(std::make_unique<Unkept>());
        return *unkept[unkept_used++];
    }

    std::size_t slot_bytes(const Slot& s) const { return s.pixels.capacity() + kEntryOverheadBytes; }

    // --- the table: linear probing, backward-shift deletion (no tombstones) ---
    std::size_t mask() const { return table.size() - 1; }
    std::size_t find_pos(const Key& k) const {
        if (table.empty()) return SIZE_MAX;
        for (std::size_t i = hash_key(k) & mask();; i = (i + 1) & mask()) {
            if (table[i] == kNone) return SIZE_MAX;
            if (slots[static_cast<std::size_t>(table[i])].key == k) return i;
        }
    }
    void table_insert(std::int32_t slot) {
        if ((stats.entries + 1) * 2 > table.size()) rehash(std::max<std::size_t>(64, table.size() * 2));
        std::size_t i = hash_key(slots[static_cast<std::size_t>(slot)].key) & mask();
        while (table[i] != kNone) i = (i + 1) & mask();
        table[i] = slot;
    }
    void table_erase(std::size_t pos) {
        // Shift later members of the probe run back so that no lookup meets a false hole.
        std::size_t hole = pos;
        for (std::size_t i = (pos + 1) & mask(); table[i] != kNone; i = (i + 1) & mask()) {
            std::size_t home = hash_key(slots[static_cast<std::size_t>(table[i])].key) & mask();
            // Movable iff its home is not cyclically within (hole, i].
            bool in_between = hole <= i ? (home > hole && home <= i) : (home > hole || home <= i);
            if (!in_between) {
                table[hole] = table[i];
                hole = i;
            }
        }
        table[hole] = kNone;
    }
    void rehash(std::size_t size) {
        std::vector<std::int32_t> old = std::move(table);
        table.assign(size, kNone);
        for (std::int32_t s : old) {
            if (s == kNone) continue;
            std::size_t i = hash_key(slots[static_cast<std::size_t>(s)].key) & mask();
            while (table[i] != kNone) i = (i + 1) & mask();
            table[i] = s;
        }
    }

    // --- the LRU list ---
    Slot& at(std::int32_t s) { return slots[static_cast<std::size_t>(s)]; }
    void unlink(std::int32_t s) {
        Slot& e = at(s);
        (e.prev == kNone ? head : at(e.prev).next) = e.next;
        (e.next == kNone ? tail : at(e.next).prev) = e.prev;
        e.prev = e.next = kNone;
    }
    void push_front(std::int32_t s) {
        Slot& e = at(s);
        e.prev = kNone;
        e.next = head;
        (head == kNone ? tail : at(head).prev) = s;
        head = s;
    }

    // Removes the least recently used entry; returns its slot (pixels kept, not on any list).
    std::int32_t evict_tail() {
        std::int32_t s = tail;
        unlink(s);
        table_erase(find_pos(at(s).key));
        stats.bytes -= slot_bytes(at(s));
        --stats.entries;
        ++stats.evictions;
        return s;
    }
    void release(std::int32_t s) {
        std::vector<std::uint8_t>().swap(at(s).pixels);
        at(s).next = free_list;
        free_list = s;
    }
};

GlyphCache::GlyphCache(std::size_t max_bytes) : impl_(std::make_unique<Impl>(max_bytes)) {}
GlyphCache::GlyphCache(GlyphCache&&) noexcept = default;
GlyphCache& GlyphCache::operator=(GlyphCache&&) noexcept = default;
GlyphCache::~GlyphCache() = default;

std::size_t GlyphCache::max_bytes() const { return impl_->max_bytes; }
GlyphCacheStats GlyphCache::stats() const { return impl_->stats; }

void GlyphCache::clear() {
    std::size_t max = impl_->max_bytes;
    GlyphCacheStats kept = impl_->stats;
    impl_ = std::make_unique<Impl>(max);
    impl_->stats.hits = kept.hits;
    impl_->stats.misses = kept.misses;
    impl_->stats.evictions = kept.evictions;
}

Status GlyphCache::begin_batch() {
    Impl& c = *impl_;
    if (c.in_batch) return Error{"glyph cache: begin_batch() inside a batch (batches do not nest)"};
    c.in_batch = true;
    ++c.batch;
    c.unkept_used = 0;
    return ok_status();
}

void GlyphCache::end_batch() {
    Impl& c = *impl_;
    c.in_batch = false;
    c.unkept_used = 0;
    // Unkept glyphs are outside the bound: keep one buffer for reuse, free the batch's others.
    if (c.unkept.size() > 1) c.unkept.resize(1);
}

bool GlyphCache::in_batch() const { return impl_->in_batch; }

Expected<const CachedGlyph*> GlyphCache::get(GlyphRasterizer& rasterizer, GlyphId gid,
                                             const GlyphRenderOptions& options) {
    Impl& c = *impl_;
    if (!in_unit_interval(options.offset_px.x) || !in_unit_interval(options.offset_px.y))
        return Error{"glyph " + std::to_string(gid) + ": pen offset (" +
                     format_number(options.offset_px.x) + ", " +
                     format_number(options.offset_px.y) + ") is outside [0, 1): the glyph cache "
                     "takes the pen's fractional part (the caller adds the whole pixels)"};
    // Outside a batch, the last get's unkept glyph is free again.
    if (!c.in_batch) c.unkept_used = 0;
    GlyphRenderOptions o = options;
    const std::uint8_t bx = bin_of(options.offset_px.x), by = bin_of(options.offset_px.y);
    o.offset_px = {static_cast<double>(bx) / kSubpixelBins, static_cast<double>(by) / kSubpixelBins};
    const FillOptions& f = o.fill;
    const Key key{rasterizer.instance_id(),
                  bits(o.size_px),
                  bits(f.flatten.tolerance_px),
                  bits(f.flatten.classic_flatness_epsilon),
                  bits(o.slant),
                  bits(o.bold),
                  gid,
                  bx,
                  by,
                  static_cast<std::uint8_t>(static_cast<int>(f.format) |
                                            static_cast<int>(f.lcd_order) << 1),
                  static_cast<std::uint8_t>(static_cast<int>(f.rule) << 4 | static_cast<int>(f.overlap)),
                  static_cast<std::uint8_t>(static_cast<int>(o.hinting) |
                                            static_cast<int>(o.box) << 2 |
                                            static_cast<int>(f.flatten.method) << 3),
                  f.lcd_filter.taps,
                  static_cast<std::uint8_t>(static_cast<int>(o.color.enabled) |
                                            static_cast<int>(o.color.bitmap_filter) << 1),
                  o.color.palette.palette,
                  custom_palette_hash(o.color.palette.custom)};
    const std::uint32_t foreground = rgba_bits(o.color.foreground);

    bool keep = true;   // false: draw into an unkept buffer, leave the slots alone
    if (std::size_t pos = c.find_pos(key); pos != SIZE_MAX) {
        std::int32_t s = c.table[pos];
        if (!c.at(s).uses_foreground || c.at(s).foreground == foreground) {
            if (s != c.head) {
                c.unlink(s);
                c.push_front(s);
            }
            c.pin(s);
            ++c.stats.hits;
            return &c.at(s).glyph;
        }
        if (c.pinned(s)) {
            // This batch holds it in another text colour: that handle must stay as it is.
            keep = false;
        } else {
            // Painted in another text colour: dropped, and painted again below.
            c.unlink(s);
            c.table_erase(pos);
            c.stats.bytes -= c.slot_bytes(c.at(s));
            --c.stats.entries;
            c.release(s);
        }
    }
    ++c.stats.misses;

    // The one outline load of a miss: prepare() measures, draw() fills the buffer sized here.
    auto glyph = rasterizer.prepare(gid, o);
    if (!glyph) return glyph.error();
    const GlyphBox& box = glyph->box;
    const int row_bytes = box.width * (box.color ? 4 : f.format == CoverageFormat::Lcd ? 3 : 1);
    const std::size_t need = static_cast<std::size_t>(row_bytes) * static_cast<std::size_t>(box.height);

    if (!keep || need + kEntryOverheadBytes > c.max_bytes) {
        Impl::Unkept& unkept = c.next_unkept();
        unkept.pixels.resize(need);
        auto drawn = draw_into(rasterizer, *glyph, unkept.pixels.data(), row_bytes);
        if (!drawn) {
            --c.unkept_used;
            return drawn.error();
        }
        unkept.glyph = *drawn;
        return &unkept.glyph;
    }

    // Make room (never evicting a slot this batch pinned); keep the last evicted slot (and its
    // buffer) for the new glyph.
    std::int32_t s = kNone;
    while (c.stats.entries > 0 && c.stats.bytes + need + kEntryOverheadBytes > c.max_bytes &&
           !c.pinned(c.tail)) {
        if (s != kNone) c.release(s);
        s = c.evict_tail();
    }
    if (s == kNone) {
        if (c.free_list != kNone) {
            s = c.free_list;
            c.free_list = c.at(s).next;
        } else {
            s = static_cast<std::int32_t>(c.slots.size());
            c.slots.emplace_back();
        }
    }
    Impl::Slot& slot = c.at(s);
    slot.pixels.resize(need);
    if (slot.pixels.capacity() + kEntryOverheadBytes + c.stats.bytes > c.max_bytes)
        slot.pixels.shrink_to_fit();   // a reused buffer much larger than needed
    auto drawn = draw_into(rasterizer, *glyph, slot.pixels.data(), row_bytes);
    if (!drawn) {
        c.release(s);
        return drawn.error();
    }
    slot.key = key;
    slot.glyph = *drawn;
    slot.uses_foreground = glyph->paint && glyph->paint->uses_foreground;
    slot.foreground = foreground;
    slot.pinned_batch = 0;
    c.pin(s);
    c.table_insert(s);
    c.push_front(s);
    c.stats.bytes += c.slot_bytes(slot);
    ++c.stats.entries;
    return &slot.glyph;
}

}  // namespace bezel
