// GlyphCache: hits and misses for repeated text, LRU eviction, the memory bound under many sizes,
// oversized glyphs, bitmaps equal to direct renders, and no allocation once warm.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "bezel/text.hpp"

#include "support/allocation_counter.hpp"

using bezel::test::g_allocations;

namespace bezel {
namespace {

const std::string kDejaVu = BEZEL_FONTS_DIR "/dejavu-sans/DejaVuSans.ttf";

struct Fixture {
    Font font = std::move(Font::open(kDejaVu).value());
    GlyphRasterizer rasterizer{font};

    GlyphId gid(char32_t c) const { return font.glyph_for_char(c).value(); }
};

// The bytes one cache entry of `c` takes (0 when it cannot be rendered).
std::size_t entry_bytes(Fixture& f, char32_t c, const GlyphRenderOptions& o) {
    GlyphCache probe;
    return probe.get(f.rasterizer, f.gid(c), o) ? probe.stats().bytes : 0;
}

TEST(GlyphCache, RepeatedStringMissesOncePerGlyphAndBin) {
    Fixture f;
    GlyphCache cache;
    const std::u32string text = U"hello, hello world";
    GlyphRenderOptions o;
    o.size_px = 16;
    std::set<std::pair<GlyphId, int>> distinct;
    for (int pass = 0; pass < 3; ++pass) {
        double pen = 0;
        for (char32_t c : text) {
            double frac = pen - static_cast<int>(pen);
            o.offset_px.x = frac;
            distinct.insert({f.gid(c), static_cast<int>(frac * kSubpixelBins)});
            ASSERT_TRUE(cache.get(f.rasterizer, f.gid(c), o));
            pen += 7.3;
        }
    }
    GlyphCacheStats s = cache.stats();
    EXPECT_EQ(s.misses, distinct.size());
    EXPECT_EQ(s.hits, 3 * text.size() - distinct.size());
    EXPECT_EQ(s.entries, distinct.size());
    EXPECT_EQ(s.evictions, 0u);
    // The font instance, size and mode are part of the key: another Font of the same file is
    // another instance (its own instance_id).
    o.offset_px.x = 0;
    Font other = std::move(Font::open(kDejaVu).value());
    GlyphRasterizer other_rasterizer(other);
    ASSERT_TRUE(cache.get(other_rasterizer, f.gid(U'h'), o));
    o.size_px = 17;
    ASSERT_TRUE(cache.get(f.rasterizer, f.gid(U'h'), o));
    o.fill.format = CoverageFormat::Lcd;
    ASSERT_TRUE(cache.get(f.rasterizer, f.gid(U'h'), o));
    EXPECT_EQ(cache.stats().misses, distinct.size() + 3);
}

TEST(GlyphCache, HintingSlantBoxModeFlatteningAndLcdSettingsAreInTheKey) {
    // Each option that changes the pixels misses once, and what the cache returns equals a
    // direct render with the same options.
    Fixture f;
    GlyphCache cache;
    GlyphRenderOptions o;
    o.size_px = 13;
    const GlyphId g = f.gid(U'g');
    std::vector<GlyphRenderOptions> variants(8, o);
    variants[1].hinting = Hinting::Full;
    variants[2].box = GlyphBoxMode::FreeType;
    variants[3].fill.flatten.method = FlattenMethod::ParabolaIntegral;
    variants[4].fill.format = CoverageFormat::Lcd;
    variants[5].fill.format = CoverageFormat::Lcd;
    variants[5].fill.lcd_order = LcdOrder::Bgr;
    variants[6].fill.format = CoverageFormat::Lcd;
    variants[6].fill.lcd_filter = {{0, 0, 0xFF, 0, 0}};   // no filtering (sum 255)
    variants[7].slant = 0.2;
    for (std::size_t i = 0; i < variants.size(); ++i) {
        auto cached = cache.get(f.rasterizer, g, variants[i]);
        ASSERT_TRUE(cached) << cached.error().message;
        EXPECT_EQ(cache.stats().misses, i + 1);
        auto box = f.rasterizer.measure(g, variants[i]);
        ASSERT_TRUE(box);
        const int bpp = variants[i].fill.format == CoverageFormat::Lcd ? 3 : 1;
        Mask direct(box->width * bpp, box->height);
        ASSERT_TRUE(f.rasterizer.render(g, variants[i], direct.view()));
        EXPECT_EQ((**cached).box.left, box->left) << i;
        EXPECT_EQ((**cached).box.top, box->top) << i;
        EXPECT_EQ(to_mask((**cached).mask), direct) << i;
    }
    for (const GlyphRenderOptions& v : variants) ASSERT_TRUE(cache.get(f.rasterizer, g, v));
    EXPECT_EQ(cache.stats().misses, variants.size());
}

TEST(GlyphCache, SubpixelOffsetsShareFourBins) {
    Fixture f;
    GlyphCache cache;
    GlyphRenderOptions o;
    for (double sx : {0.0, 0.1, 0.24, 0.25, 0.49, 0.5, 0.74, 0.75, 0.99}) {
        o.offset_px.x = sx;
        ASSERT_TRUE(cache.get(f.rasterizer, f.gid(U'x'), o));
    }
    EXPECT_EQ(cache.stats().misses, 4u);
    EXPECT_EQ(cache.stats().hits, 5u);
}

TEST(GlyphCache, BitmapEqualsADirectRenderAtTheBinOffset) {
    Fixture f;
    GlyphCache cache;
    for (CoverageFormat format : {CoverageFormat::Gray, CoverageFormat::Lcd}) {
        GlyphRenderOptions o;
        o.size_px = 21;
        o.fill.format = format;
        o.fill.lcd_order = LcdOrder::Bgr;
        o.offset_px.x = 0.6;   // bin 2: rendered at +0.5
        auto cached = cache.get(f.rasterizer, f.gid(U'&'), o);
        ASSERT_TRUE(cached) << cached.error().message;
        o.offset_px.x = 0.5;
        auto box = f.rasterizer.measure(f.gid(U'&'), o);
        ASSERT_TRUE(box);
        int bpp = format == CoverageFormat::Gray ? 1 : 3;
        Mask direct(box->width * bpp, box->height);
        ASSERT_TRUE(f.rasterizer.render(f.gid(U'&'), o, direct.view()));
        const CachedGlyph& g = **cached;
        EXPECT_EQ(g.box.left, box->left);
        EXPECT_EQ(g.box.top, box->top);
        EXPECT_EQ(g.box.advance_px, box->advance_px);
        EXPECT_EQ(to_mask(g.mask), direct);
    }
}

TEST(GlyphCache, EvictsTheLeastRecentlyUsed) {
    Fixture f;
    GlyphRenderOptions o;
    o.size_px = 30;
    // 'o', 'n' and 'c' are of similar size: room for two and a half of 'o' holds any two of
    // them, not three.
    const std::size_t one = entry_bytes(f, U'o', o);
    ASSERT_GT(one, 0u);
    GlyphCache cache(2 * one + one / 2);
    auto get = [&](char32_t c) { ASSERT_TRUE(cache.get(f.rasterizer, f.gid(c), o)); };
    get(U'o');
    get(U'n');
    get(U'o');   // 'o' is now the most recent
    get(U'c');   // evicts 'n'
    std::size_t misses = cache.stats().misses;
    get(U'o');
    EXPECT_EQ(cache.stats().misses, misses) << "'o' was recently used and must still be cached";
    get(U'n');
    EXPECT_EQ(cache.stats().misses, misses + 1) << "'n' was the least recently used";
    EXPECT_LE(cache.stats().bytes, cache.max_bytes());
    EXPECT_GE(cache.stats().evictions, 1u);
}

TEST(GlyphCache, StaysWithinItsBoundAcrossManySizes) {
    Fixture f;
    GlyphCache cache(64 * 1024);
    GlyphRenderOptions o;
    std::size_t peak = 0;
    for (double size = 6; size <= 120; size += 3) {
        o.size_px = size;
        for (char32_t c = U'a'; c <= U'z'; ++c) {
            auto g = cache.get(f.rasterizer, f.gid(c), o);
            ASSERT_TRUE(g) << g.error().message;
            ASSERT_GT((*g)->box.width, 0);
            peak = std::max(peak, cache.stats().bytes);
        }
    }
    EXPECT_LE(peak, cache.max_bytes());
    EXPECT_GT(peak, cache.max_bytes() / 2);
    EXPECT_GT(cache.stats().evictions, 100u);
    cache.clear();
    EXPECT_EQ(cache.stats().bytes, 0u);
    EXPECT_EQ(cache.stats().entries, 0u);
}

TEST(GlyphCache, GlyphLargerThanTheBoundIsRenderedButNotKept) {
    Fixture f;
    GlyphCache cache(1000);
    GlyphRenderOptions o;
    o.size_px = 100;
    auto g = cache.get(f.rasterizer, f.gid(U'W'), o);
    ASSERT_TRUE(g);
    EXPECT_GT(static_cast<std::size_t>((*g)->mask.width * (*g)->mask.height), cache.max_bytes());
    EXPECT_EQ(cache.stats().entries, 0u);
    EXPECT_LE(cache.stats().bytes, cache.max_bytes());
}

TEST(GlyphCache, ErrorsPassThroughAndCacheNothing) {
    Fixture f;
    GlyphCache cache;
    GlyphRenderOptions o;
    auto g = cache.get(f.rasterizer, static_cast<GlyphId>(f.font.glyph_count() + 5), o);
    ASSERT_FALSE(g);
    EXPECT_NE(g.error().message.find(std::to_string(f.font.glyph_count() + 5)), std::string::npos);
    EXPECT_EQ(cache.stats().entries, 0u);
}

// A direct render of `gid` (the reference a cached bitmap must equal).
Mask direct_render(GlyphRasterizer& r, GlyphId gid, const GlyphRenderOptions& o) {
    auto box = r.measure(gid, o);
    EXPECT_TRUE(box);
    Mask m(box->width, box->height);
    EXPECT_TRUE(r.render(gid, o, m.view()));
    return m;
}

// Issue 38: the cache trusted a caller's font id, so two fonts (or two instances of a variable
// font) given one id shared entries. It keys on the face the rasterizer draws.
TEST(GlyphCache, KeyedOnTheFaceAndVariationsTheRasterizerDraws) {
    auto dejavu = Font::open(kDejaVu);
    auto cantarell = Font::open(BEZEL_FONTS_DIR "/cantarell/Cantarell-Regular.otf");
    ASSERT_TRUE(dejavu && cantarell);
    GlyphRasterizer rd(*dejavu), rc(*cantarell);
    GlyphCache cache;
    GlyphRenderOptions o;
    o.size_px = 24;
    const GlyphId gid = 40;   // a glyph both fonts have, drawn differently
    auto a = cache.get(rd, gid, o);
    auto b = cache.get(rc, gid, o);
    ASSERT_TRUE(a && b);
    EXPECT_EQ(cache.stats().misses, 2u);
    EXPECT_EQ(to_mask((*a)->mask), direct_render(rd, gid, o));
    EXPECT_EQ(to_mask((*b)->mask), direct_render(rc, gid, o));
    EXPECT_NE(to_mask((*a)->mask), to_mask((*b)->mask));

    // A variable font: each instance its own entry, and a return to an instance hits again.
    auto variable = Font::open(BEZEL_FONTS_DIR "/edge-cases/EdgeCasesVariable.ttf");
    ASSERT_TRUE(variable);
    GlyphRasterizer rv(*variable);
    const GlyphId i = variable->glyph_for_char(U'I').value();
    o.size_px = 40;
    ASSERT_TRUE(variable->set_variations({{"wght", 100}}));
    auto light = cache.get(rv, i, o);
    ASSERT_TRUE(light);
    const Mask light_pixels = to_mask((*light)->mask);
    ASSERT_TRUE(variable->set_variations({{"wght", 900}}));
    auto heavy = cache.get(rv, i, o);
    ASSERT_TRUE(heavy);
    EXPECT_EQ(cache.stats().misses, 4u);
    EXPECT_EQ(to_mask((*heavy)->mask), direct_render(rv, i, o));
    EXPECT_NE(to_mask((*heavy)->mask), light_pixels);
    ASSERT_TRUE(variable->set_variations({{"wght", 100}}));
    auto light_again = cache.get(rv, i, o);
    ASSERT_TRUE(light_again);
    EXPECT_EQ(cache.stats().misses, 4u) << "the wght 100 instance is cached already";
    EXPECT_EQ(to_mask((*light_again)->mask), light_pixels);
}

// Issue 38: an offset outside the cache's bins silently became bin 0, where the rasterizer
// itself reports an error. The cache says what is wrong.
TEST(GlyphCache, OffsetOutsideOnePixelIsAnErrorNamingIt) {
    Fixture f;
    GlyphCache cache;
    GlyphRenderOptions o;
    const GlyphId x = f.gid(U'x');
    o.offset_px = {1.0, 0};
    auto one = cache.get(f.rasterizer, x, o);
    ASSERT_FALSE(one);
    EXPECT_EQ(one.error().message,
              "glyph " + std::to_string(x) + ": pen offset (1, 0) is outside [0, 1): the glyph "
              "cache takes the pen's fractional part (the caller adds the whole pixels)");
    o.offset_px = {0.5, -0.25};
    auto negative = cache.get(f.rasterizer, x, o);
    ASSERT_FALSE(negative);
    EXPECT_NE(negative.error().message.find("(0.5, -0.25)"), std::string::npos);
    o.offset_px = {std::nan(""), 0};
    EXPECT_FALSE(cache.get(f.rasterizer, x, o));
    EXPECT_EQ(cache.stats().entries, 0u);
    o.offset_px = {0.999, 0.75};   // the last bin of each axis
    EXPECT_TRUE(cache.get(f.rasterizer, x, o));
}

// Issue 38: a get() pointer died at the next get(). A handle now lives until its entry is
// evicted, so many lookups later (the cache's slots grown many times) it still shows its glyph.
TEST(GlyphCache, HandlesStayValidUntilEviction) {
    Fixture f;
    GlyphCache cache;
    GlyphRenderOptions o;
    o.size_px = 18;
    auto first = cache.get(f.rasterizer, f.gid(U'&'), o);
    ASSERT_TRUE(first);
    const CachedGlyph* handle = *first;
    const Mask expected = direct_render(f.rasterizer, f.gid(U'&'), o);
    for (double size = 8; size < 40; size += 0.5) {
        GlyphRenderOptions other = o;
        other.size_px = size;
        for (char32_t c = U'a'; c <= U'z'; ++c) ASSERT_TRUE(cache.get(f.rasterizer, f.gid(c), other));
    }
    ASSERT_EQ(cache.stats().evictions, 0u);
    EXPECT_EQ(to_mask(handle->mask), expected);
    auto again = cache.get(f.rasterizer, f.gid(U'&'), o);
    ASSERT_TRUE(again);
    EXPECT_EQ(*again, handle);
}

// A frame holds all its glyphs at once: inside a batch nothing it returned is evicted or
// overwritten, even in a cache with room for two glyphs, and a glyph too large to keep gets its
// own buffer.
TEST(GlyphCache, BatchKeepsEveryGlyphOfTheFrameValidTogether) {
    Fixture f;
    GlyphRenderOptions o;
    o.size_px = 30;
    const std::size_t one = entry_bytes(f, U'o', o);
    ASSERT_GT(one, 0u);
    GlyphCache cache(2 * one + one / 2);
    const std::u32string frame = U"Hamburgefonstiv";
    ASSERT_TRUE(cache.begin_batch());
    EXPECT_TRUE(cache.in_batch());
    EXPECT_FALSE(cache.begin_batch());   // batches do not nest
    std::vector<const CachedGlyph*> held;
    for (char32_t c : frame) {
        auto g = cache.get(f.rasterizer, f.gid(c), o);
        ASSERT_TRUE(g) << g.error().message;
        held.push_back(*g);
    }
    GlyphRenderOptions huge = o;
    huge.size_px = 200;   // larger than the whole cache: not kept, but held for the batch
    auto big = cache.get(f.rasterizer, f.gid(U'W'), huge);
    auto big2 = cache.get(f.rasterizer, f.gid(U'M'), huge);
    ASSERT_TRUE(big && big2);
    EXPECT_NE(*big, *big2);
    EXPECT_EQ(cache.stats().evictions, 0u);
    EXPECT_GT(cache.stats().bytes, cache.max_bytes());   // the frame's glyphs must all exist
    for (std::size_t i = 0; i < frame.size(); ++i)
        EXPECT_EQ(to_mask(held[i]->mask), direct_render(f.rasterizer, f.gid(frame[i]), o)) << i;
    EXPECT_EQ(to_mask((*big)->mask), direct_render(f.rasterizer, f.gid(U'W'), huge));
    EXPECT_EQ(to_mask((*big2)->mask), direct_render(f.rasterizer, f.gid(U'M'), huge));
    cache.end_batch();
    EXPECT_FALSE(cache.in_batch());
    // After the batch the next miss evicts back under the bound.
    o.size_px = 31;
    ASSERT_TRUE(cache.get(f.rasterizer, f.gid(U'o'), o));
    EXPECT_LE(cache.stats().bytes, cache.max_bytes());
}

TEST(GlyphCache, WarmBatchAllocatesNothing) {
    Fixture f;
    GlyphCache cache;
    GlyphRenderOptions o;
    const std::u32string text = U"The quick brown fox";
    std::vector<GlyphId> gids;
    for (char32_t c : text) gids.push_back(f.gid(c));
    for (GlyphId g : gids) ASSERT_TRUE(cache.get(f.rasterizer, g, o));
    const long before = g_allocations.load();
    std::size_t found = 0;
    for (int frame = 0; frame < 3; ++frame) {
        if (!cache.begin_batch()) break;
        for (GlyphId g : gids) found += cache.get(f.rasterizer, g, o).ok();
        cache.end_batch();
    }
    EXPECT_EQ(g_allocations.load() - before, 0);
    EXPECT_EQ(found, 3 * gids.size());
}

TEST(GlyphCache, HitsAllocateNothing) {
    Fixture f;
    GlyphCache cache;
    GlyphRenderOptions o;
    const std::u32string text = U"The quick brown fox jumps over the lazy dog";
    for (char32_t c : text) ASSERT_TRUE(cache.get(f.rasterizer, f.gid(c), o));
    std::vector<GlyphId> gids;
    for (char32_t c : text) gids.push_back(f.gid(c));
    long before = g_allocations.load();
    std::size_t found = 0;
    for (int pass = 0; pass < 5; ++pass)
        for (GlyphId gid : gids) found += cache.get(f.rasterizer, gid, o).ok();
    EXPECT_EQ(g_allocations.load() - before, 0);
    EXPECT_EQ(found, 5 * gids.size());
}


TEST(GlyphCache, ColourGlyphHitsAllocateNothing) {
    auto font = Font::open(std::string(BEZEL_FONTS_DIR) + "/colour/twemoji_smiley-glyf_colr_1.ttf");
    ASSERT_TRUE(font) << font.error().message;
    GlyphRasterizer rasterizer(*font);
    GlyphCache cache;
    GlyphRenderOptions o;
    o.size_px = 32;
    std::vector<GlyphId> gids;
    for (char32_t c : {U'\u263A', U'\U0001F601', U'\U0001F603', U'\U0001F604'}) {
        auto gid = font->glyph_for_char(c);
        ASSERT_TRUE(gid);
        gids.push_back(*gid);
        auto got = cache.get(rasterizer, *gid, o);
        ASSERT_TRUE(got) << got.error().message;
        ASSERT_TRUE((*got)->box.color);
        ASSERT_NE((*got)->rgba.data, nullptr);
    }
    long before = g_allocations.load();
    std::size_t found = 0;
    for (int pass = 0; pass < 5; ++pass)
        for (GlyphId gid : gids) found += cache.get(rasterizer, gid, o).ok();
    EXPECT_EQ(g_allocations.load() - before, 0);
    EXPECT_EQ(found, 5 * gids.size());
    EXPECT_EQ(cache.stats().misses, gids.size());
}

}  // namespace
}  // namespace bezel
