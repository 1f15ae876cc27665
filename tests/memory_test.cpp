// Rendering the same text 10,000 times keeps memory flat: after a warm-up the glyph cache neither
// renders nor grows, and the live heap (bytes allocated and not yet freed) does not grow either.
// The heap is measured with the allocator's own count, not RSS: ASan's quarantine holds freed
// blocks in RSS, and RSS also moves with the allocator's caching of pages, so it would measure
// the allocator rather than bezel. The cache's own bound across sizes is glyph_cache_test's.
#include <gtest/gtest.h>

#include <malloc.h>

#include <cstddef>
#include <string>

#include "bezel/text.hpp"

#if defined(__SANITIZE_ADDRESS__)
#define BEZEL_HEAP_FROM_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define BEZEL_HEAP_FROM_ASAN 1
#endif
#endif
#ifdef BEZEL_HEAP_FROM_ASAN
// ASan's public allocator interface, declared here because g++'s packages do not always ship
// <sanitizer/allocator_interface.h> (Debian's g++ 12 does not).
extern "C" std::size_t __sanitizer_get_current_allocated_bytes();
#endif

namespace bezel {
namespace {

const std::string kDejaVu = BEZEL_FONTS_DIR "/dejavu-sans/DejaVuSans.ttf";

std::size_t live_heap_bytes() {
#ifdef BEZEL_HEAP_FROM_ASAN
    return __sanitizer_get_current_allocated_bytes();
#else
    return mallinfo2().uordblks;
#endif
}

TEST(Memory, RenderingTheSameText10000TimesKeepsMemoryFlat) {
    auto renderer = TextRenderer::open(kDejaVu);
    ASSERT_TRUE(renderer) << renderer.error().message;
    TextRenderOptions options;
    options.shape.size_px = 11;
    options.layout.margin_px = 1;
    const std::string text = "Flat 10k";

    // Warm-up: every glyph and subpixel bin of the text is cached, every scratch buffer grown.
    for (int i = 0; i < 20; ++i) ASSERT_TRUE(renderer->render(text, options));
    const GlyphCacheStats warm = renderer->cache().stats();
    const std::size_t heap_warm = live_heap_bytes();
    ASSERT_GT(warm.entries, 0u);

    std::size_t width = 0;
    for (int i = 0; i < 10000; ++i) {
        auto image = renderer->render(text, options);
        ASSERT_TRUE(image) << image.error().message;
        width += static_cast<std::size_t>(image->width());
    }
    const GlyphCacheStats after = renderer->cache().stats();
    const std::size_t heap_after = live_heap_bytes();

    EXPECT_GT(width, 0u);
    EXPECT_EQ(after.misses, warm.misses);        // nothing rendered twice
    EXPECT_EQ(after.entries, warm.entries);
    EXPECT_EQ(after.bytes, warm.bytes);
    EXPECT_EQ(after.evictions, warm.evictions);
    EXPECT_GE(after.hits, warm.hits + 10000u);   // every glyph of every render came from the cache
    // 10,000 renders leaking even 8 bytes each would add 80 kB; allow 16 kB of allocator noise.
    EXPECT_LE(heap_after, heap_warm + 16 * 1024)
        << "live heap " << heap_warm << " → " << heap_after << " bytes";
}

}  // namespace
}  // namespace bezel
