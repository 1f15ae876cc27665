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
#include "bezel/font_face.hpp"
#include "bezel/glyph.hpp"
#include "bezel/raster.hpp"
#include "bezel/shape.hpp"

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

// What one thread draws from its own instances of a shared face: the shaped run's glyph ids and
// advances (its Shaper), then each glyph's bitmap (its Font, through a GlyphRasterizer), all in
// one byte list; empty on any failure.
std::vector<std::uint8_t> shape_and_render(const FontFace& face) {
    auto font = Font::open(face);
    auto shaper = Shaper::open(face);
    if (!font || !shaper) return {};
    ShapeOptions so;
    so.size_px = 19;
    auto run = shaper->shape("Hamburgefonstiv &@g AVATAR", so);
    if (!run) return {};
    GlyphRasterizer rasterizer(*font);
    GlyphRenderOptions o;
    o.size_px = 19;
    o.hinting = Hinting::Light;
    std::vector<std::uint8_t> all;
    for (const ShapedGlyph& g : run->glyphs) {
        const auto advance = static_cast<std::uint32_t>(std::lround(g.x_advance_px * 1024));
        for (int k = 0; k < 4; ++k) all.push_back(static_cast<std::uint8_t>(advance >> (8 * k)));
        auto glyph = rasterizer.prepare(g.gid, o);
        if (!glyph) return {};
        std::vector<std::uint8_t> pixels(
            static_cast<std::size_t>(glyph->box.width) * static_cast<std::size_t>(glyph->box.height));
        if (!rasterizer.draw(*glyph, {pixels.data(), glyph->box.width, glyph->box.height,
                                      glyph->box.width}))
            return {};
        all.insert(all.end(), pixels.begin(), pixels.end());
    }
    return all;
}

// font_face.hpp's promise: one FontFace (bytes read once, HarfBuzz face parsed once) shared by
// threads, each with its own Font, Shaper and GlyphRasterizer of it, all starting together.
TEST(Threads, InstancesOfOneSharedFaceShapeAndRenderIdenticallyOnThreads) {
    for (const std::string& file : {kDejaVu, kCantarell}) {
        auto face = FontFace::open(file);
        ASSERT_TRUE(face) << face.error().message;
        // No thread has touched the face before: they race to parse it (the HarfBuzz face is
        // made once, by whichever thread asks first).
        std::vector<std::vector<std::uint8_t>> results(kThreads);
        std::vector<std::thread> threads;
        for (int i = 0; i < kThreads; ++i)
            threads.emplace_back([&, i] { results[i] = shape_and_render(*face); });
        for (std::thread& t : threads) t.join();
        const std::vector<std::uint8_t> reference = shape_and_render(*face);
        ASSERT_FALSE(reference.empty()) << file;
        for (int i = 0; i < kThreads; ++i) EXPECT_EQ(results[i], reference) << file << " thread " << i;
    }
}

}  // namespace
}  // namespace bezel
