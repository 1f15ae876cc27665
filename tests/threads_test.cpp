// Separate Font and Rasterizer objects on separate threads (font.hpp and raster.hpp promise they
// are independent): several threads render the same glyphs of the same file and must get exactly
// the single-threaded pixels. `./dev tsan` runs these under ThreadSanitizer (their names contain
// "Thread"), which also catches shared state that happens to give the same pixels.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <thread>
#include <vector>

#include "bezel/font.hpp"
#include "bezel/raster.hpp"

namespace bezel {
namespace {

const std::string kDejaVu = std::string(BEZEL_FONTS_DIR) + "/dejavu-sans/DejaVuSans.ttf";
const std::string kCantarell = std::string(BEZEL_FONTS_DIR) + "/cantarell/Cantarell-Regular.otf";
constexpr char32_t kText[] = U"Hamburgefonstiv&@g";
constexpr int kThreads = 4;

// Every glyph of kText at `size_px`, each in its own mask, concatenated; empty on any failure.
std::vector<std::uint8_t> render_all(const std::string& file, double size_px, Hinting hinting) {
    auto font = Font::open(file);
    if (!font) return {};
    Rasterizer raster;
    std::vector<std::uint8_t> all;
    for (const char32_t* c = kText; *c; ++c) {
        auto gid = font->glyph_for_char(*c);
        if (!gid) return {};
        auto outline = font->outline(*gid, {size_px, hinting});
        if (!outline) return {};
        const Rect box = outline->path.bounds();
        if (box.is_empty()) continue;
        const int w = static_cast<int>(std::ceil(box.x1) - std::floor(box.x0));
        const int h = static_cast<int>(std::ceil(box.y1) - std::floor(box.y0));
        Mask mask(w, h);
        const Affine at = Affine::translate({-std::floor(box.x0), -std::floor(box.y0)});
        if (!raster.fill_path(outline->path, at, mask.view(), {FillRule::NonZero})) return {};
        all.insert(all.end(), mask.pixels().begin(), mask.pixels().end());
    }
    return all;
}

void expect_threads_match(const std::string& file, double size_px, Hinting hinting) {
    const std::vector<std::uint8_t> reference = render_all(file, size_px, hinting);
    ASSERT_FALSE(reference.empty()) << file;
    std::vector<std::vector<std::uint8_t>> results(kThreads);
    std::vector<std::thread> threads;
    for (int i = 0; i < kThreads; ++i)
        threads.emplace_back([&, i] { results[i] = render_all(file, size_px, hinting); });
    for (std::thread& t : threads) t.join();
    for (int i = 0; i < kThreads; ++i) EXPECT_EQ(results[i], reference) << "thread " << i;
}

TEST(Threads, SeparateFontsAndRasterizersOnThreadsMatchOneThreadTrueType) {
    expect_threads_match(kDejaVu, 24.0, Hinting::None);
}

TEST(Threads, SeparateFontsAndRasterizersOnThreadsMatchOneThreadCffHinted) {
    expect_threads_match(kCantarell, 17.0, Hinting::Full);
}

}  // namespace
}  // namespace bezel
