// TextRenderer: rendered lines against golden images, the cache across renders, LCD output,
// colours, determinism across threads, and errors; drawing into a caller's pixels (every format,
// offsets, clipping, no background) equal to render()'s page.
//
// Goldens: tests/golden/text/<name>.png, 8-bit gray (black text on white, so gray loses
// nothing). Tolerance: max |difference| <= 2 levels per pixel — room for a rasterizer or
// flattening change of a rounding step, far below any change of placement or shaping (a glyph
// moved by a quarter pixel changes its edge pixels by ~64). BEZEL_UPDATE_GOLDEN=1 rewrites them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "bezel/text.hpp"
#include "support/golden.hpp"

namespace bezel {
namespace {

const std::string kDejaVu = BEZEL_FONTS_DIR "/dejavu-sans/DejaVuSans.ttf";
const std::string kCantarell = BEZEL_FONTS_DIR "/cantarell/Cantarell-Regular.otf";
const std::string kEmoji = BEZEL_FONTS_DIR "/noto-color-emoji/NotoColorEmoji-subset.ttf";

// A PageRowsSink that hands each call to `f`.
template <typename F>
struct SinkOf final : PageRowsSink {
    explicit SinkOf(F g) : f(std::move(g)) {}
    void rows_final(int rows) override { f(rows); }
    F f;
};
template <typename F>
SinkOf<F> sink_of(F f) {
    return SinkOf<F>(std::move(f));
}
constexpr int kGoldenTolerance = 2;

Mask luma_of(const Image& image) {
    Mask m(image.width(), image.height());
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const Rgba8& p = image.at(x, y);
            EXPECT_TRUE(p.r == p.g && p.g == p.b) << "not gray at " << x << "," << y;
            m.at(x, y) = p.r;
        }
    return m;
}

void expect_matches_golden(const Image& image, const std::string& name) {
    const std::string file = std::string(BEZEL_GOLDEN_DIR) + "/text/" + name + ".png";
    Mask got = luma_of(image);
    if (bezel::test::update_golden()) {
        ASSERT_TRUE(write_png_gray(file, got.view()));
        return;
    }
    auto golden = read_png_gray(file);
    ASSERT_TRUE(golden) << golden.error().message << " (BEZEL_UPDATE_GOLDEN=1 creates it)";
    ASSERT_EQ(golden->width(), got.width()) << name;
    ASSERT_EQ(golden->height(), got.height()) << name;
    int worst = 0;
    for (int y = 0; y < got.height(); ++y)
        for (int x = 0; x < got.width(); ++x)
            worst = std::max(worst, std::abs(golden->at(x, y) - got.at(x, y)));
    EXPECT_LE(worst, kGoldenTolerance) << name;
}

// The goldens hold the exact linear-light mix (TextRendering::Linear), unchanged by the default
// rendering; the default's own golden is perceptual_line_12.
TextRenderOptions line_options(double size) {
    TextRenderOptions o;
    o.shape.size_px = size;
    o.layout.margin_px = 4;
    o.coverage.rendering = TextRendering::Linear;
    return o;
}

TEST(TextRenderer, LinesMatchGoldenImages) {
    auto dejavu = TextRenderer::open(kDejaVu);
    ASSERT_TRUE(dejavu) << dejavu.error().message;
    auto image = dejavu->render("Hamburgefonstiv AV Wa To office", line_options(24));
    ASSERT_TRUE(image) << image.error().message;
    expect_matches_golden(*image, "dejavu_line_24");

    TextRenderOptions wrapped = line_options(13);
    wrapped.layout.width_px = 160;
    wrapped.layout.align = Align::Center;
    image = dejavu->render("Small text wraps at spaces and centres each line of the paragraph.",
                           wrapped);
    ASSERT_TRUE(image) << image.error().message;
    expect_matches_golden(*image, "dejavu_wrapped_13_center");

    auto cantarell = TextRenderer::open(kCantarell);
    ASSERT_TRUE(cantarell) << cantarell.error().message;
    image = cantarell->render("Cubic outlines: &@Qg 0123", line_options(20));
    ASSERT_TRUE(image) << image.error().message;
    expect_matches_golden(*image, "cantarell_line_20");
}

TEST(TextRenderer, MixedScriptsFromAFontListMatchGoldenImages) {
    // Latin, Arabic, Hebrew, Devanagari, CJK and symbols, each from its own font, wrapped into
    // lines of different heights; the bidi order and the fallback are both in the picture.
    const std::string fonts = BEZEL_FONTS_DIR;
    auto list = FontCollection::open({{kCantarell, 0, {}},
                                      {fonts + "/noto-arabic/NotoSansArabic-Regular.ttf", 0, {}},
                                      {fonts + "/noto-hebrew/NotoSansHebrew-Regular.ttf", 0, {}},
                                      {fonts + "/noto-devanagari/NotoSansDevanagari-Regular.ttf", 0, {}},
                                      {fonts + "/noto-cjk/NotoSansCJKjp-Subset.otf", 0, {}},
                                      {kDejaVu, 0, {}}});
    ASSERT_TRUE(list) << list.error().message;
    auto renderer = TextRenderer::open(std::move(*list));
    ASSERT_TRUE(renderer) << renderer.error().message;
    TextRenderOptions o = line_options(18);
    auto image = renderer->render(
        "Hi \u0645\u0631\u062D\u0628\u0627 \u05E9\u05DC\u05D5\u05DD \u0928\u092E\u0938\u094D\u0924\u0947 "
        "\u65E5\u672C\u8A9E \u2192 \u2211 \u221E",
        o);
    ASSERT_TRUE(image) << image.error().message;
    expect_matches_golden(*image, "mixed_line_18");
    EXPECT_EQ(renderer->missing_glyphs().count, 0u);

    o.layout.width_px = 150;
    image = renderer->render(
        "Text \u05E9\u05DC\u05D5\u05DD 123 \u0627\u0644\u0639\u0631\u0628\u064A\u0629 "
        "\u0939\u093F\u0928\u094D\u0926\u0940 \u4E2D\u6587\u3068\u65E5\u672C\u8A9E "
        "\u2264 \u2713 end",
        o);
    ASSERT_TRUE(image) << image.error().message;
    expect_matches_golden(*image, "mixed_wrapped_18");
    EXPECT_EQ(renderer->missing_glyphs().count, 0u);
}

TEST(TextRenderer, DefaultRenderingMatchesItsGolden) {
    auto dejavu = TextRenderer::open(kDejaVu);
    ASSERT_TRUE(dejavu) << dejavu.error().message;
    TextRenderOptions o = line_options(12);
    o.coverage = CoverageCurveOptions();
    auto image = dejavu->render("Hamburgefonstiv AV Wa To office", o);
    ASSERT_TRUE(image) << image.error().message;
    expect_matches_golden(*image, "perceptual_line_12");
    // The same line in the exact mix is lighter: less ink.
    auto linear = dejavu->render("Hamburgefonstiv AV Wa To office", line_options(12));
    ASSERT_TRUE(linear) << linear.error().message;
    long long ink = 0, linear_ink = 0;
    for (int y = 0; y < image->height(); ++y)
        for (int x = 0; x < image->width(); ++x) {
            ink += 255 - image->at(x, y).r;
            linear_ink += 255 - linear->at(x, y).r;
        }
    EXPECT_GT(ink, linear_ink * 5 / 4);
}

TEST(TextRenderer, SecondRenderOfTheSameTextOnlyHitsTheCache) {
    auto r = TextRenderer::open(kDejaVu);
    ASSERT_TRUE(r);
    const std::string text = "abracadabra abracadabra";
    auto first = r->render(text, line_options(16));
    ASSERT_TRUE(first);
    GlyphCacheStats s1 = r->cache().stats();
    EXPECT_GT(s1.misses, 0u);
    EXPECT_GT(s1.hits, 0u);   // repeated letters at repeated bins
    EXPECT_LT(s1.misses, text.size());
    auto second = r->render(text, line_options(16));
    ASSERT_TRUE(second);
    GlyphCacheStats s2 = r->cache().stats();
    EXPECT_EQ(s2.misses, s1.misses);
    EXPECT_EQ(s2.hits, s1.hits + text.size());   // one glyph per character here (no ligature)
    EXPECT_EQ(*first, *second);
}

TEST(TextRenderer, ColoursBackgroundAndTransparency) {
    auto r = TextRenderer::open(kDejaVu);
    ASSERT_TRUE(r);
    TextRenderOptions o = line_options(20);
    o.foreground = Rgba8{200, 30, 10, 255};
    o.background = Rgba8{0, 0, 0, 0};
    auto image = r->render("I", o);
    ASSERT_TRUE(image);
    EXPECT_EQ(image->at(0, 0), (Rgba8{0, 0, 0, 0}));   // the margin is background
    // The stem of the I is fully covered somewhere: the exact foreground colour.
    bool solid = false;
    for (int y = 0; y < image->height(); ++y)
        for (int x = 0; x < image->width(); ++x) solid |= image->at(x, y) == o.foreground;
    EXPECT_TRUE(solid);
}

TEST(TextRenderer, LcdModeHasColourFringesAndTheSameInk) {
    auto r = TextRenderer::open(kDejaVu);
    ASSERT_TRUE(r);
    TextRenderOptions o = line_options(16);
    auto gray = r->render("olive", o);
    o.format = CoverageFormat::Lcd;
    auto lcd = r->render("olive", o);
    ASSERT_TRUE(gray && lcd) << (lcd ? "" : lcd.error().message);
    ASSERT_EQ(gray->width(), lcd->width());
    int fringes = 0;
    double ink_gray = 0, ink_lcd = 0;
    for (int y = 0; y < lcd->height(); ++y)
        for (int x = 0; x < lcd->width(); ++x) {
            const Rgba8& p = lcd->at(x, y);
            fringes += p.r != p.b;
            ink_lcd += 3 * 255 - p.r - p.g - p.b;
            const Rgba8& q = gray->at(x, y);
            ink_gray += 3 * 255 - q.r - q.g - q.b;
        }
    EXPECT_GT(fringes, 10);
    EXPECT_NEAR(ink_lcd / ink_gray, 1.0, 0.15);

    // Onto a page that is not opaque, three subpixel coverages have no alpha to go to.
    o.background = Rgba8{255, 255, 255, 254};
    auto translucent = r->render("olive", o);
    ASSERT_FALSE(translucent);
    EXPECT_NE(translucent.error().message.find("opaque background"), std::string::npos);
}

TEST(TextRenderer, SeparateRenderersOnFourThreadsAgree) {
    const std::string text = "Threads share nothing: each has its own Font, Shaper and cache.\n"
                             "Second line, with kerning AV and ligatures fi.";
    TextRenderOptions o = line_options(15);
    o.layout.width_px = 300;
    std::vector<Image> images(4);
    std::vector<std::string> errors(4);
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
        threads.emplace_back([&, t] {
            auto r = TextRenderer::open(kDejaVu);
            if (!r) { errors[t] = r.error().message; return; }
            for (int rep = 0; rep < 3; ++rep) {
                auto image = r->render(text, o);
                if (!image) { errors[t] = image.error().message; return; }
                images[static_cast<std::size_t>(t)] = std::move(*image);
            }
        });
    for (std::thread& t : threads) t.join();
    for (int t = 0; t < 4; ++t) {
        EXPECT_EQ(errors[static_cast<std::size_t>(t)], "");
        EXPECT_EQ(images[static_cast<std::size_t>(t)], images[0]) << "thread " << t;
    }
    EXPECT_GT(images[0].width(), 0);
}

TEST(TextRenderer, GrayPageIsTheRgbaPagesChannelByteForByte) {
    auto r = TextRenderer::open(kDejaVu);
    ASSERT_TRUE(r) << r.error().message;
    const std::string text = "Wafer office, AVA.\nJumpy quartz vex.";
    for (auto [fg, bg] : {std::pair<std::uint8_t, std::uint8_t>{0, 255}, {255, 0}, {60, 210}}) {
        TextRenderOptions o = line_options(17.5);
        o.foreground = {fg, fg, fg, 255};
        o.background = {bg, bg, bg, 255};
        auto rgba = r->render(text, o);
        auto gray = r->render_gray(text, o);
        ASSERT_TRUE(rgba && gray);
        EXPECT_EQ(*gray, luma_of(*rgba)) << +fg << " on " << +bg;
        int ink = 0;
        for (std::uint8_t v : gray->pixels()) ink += v != bg;
        EXPECT_GT(ink, 500);
    }
    TextRenderOptions o = line_options(12);
    o.foreground = {255, 0, 0, 255};
    auto red = r->render_gray(text, o);
    ASSERT_FALSE(red);
    EXPECT_NE(red.error().message.find("gray"), std::string::npos);
    o = line_options(12);
    o.background = {255, 255, 255, 128};
    EXPECT_FALSE(r->render_gray(text, o));
    o = line_options(12);
    o.format = CoverageFormat::Lcd;
    auto lcd = r->render_gray(text, o);
    ASSERT_FALSE(lcd);
    EXPECT_NE(lcd.error().message.find("CoverageFormat::Gray"), std::string::npos);
}

TEST(TextRenderer, RowsDeclaredFinalAreNeverWrittenAgain) {
    // Lines whose ink overlaps (a line height below the font's extent: descenders of one line
    // reach into the next) and a long page: every row the callback calls final must hold its
    // finished pixels at that moment, the calls must only grow, and the last is the height.
    auto r = TextRenderer::open(kDejaVu);
    ASSERT_TRUE(r) << r.error().message;
    std::string text;
    for (int i = 0; i < 40; ++i) text += "Ågypsy jQ|, AVA (" + std::to_string(i) + ")\n";
    TextRenderOptions o = line_options(15);
    o.layout.line_height = 0.8;
    auto whole = r->render_gray(text, o);
    ASSERT_TRUE(whole) << whole.error().message;
    Mask page;
    std::vector<int> calls;
    std::vector<std::uint8_t> at_call(whole->pixels().size());  // each row as it was when final
    auto record = sink_of([&](int rows) {
        const int from = calls.empty() ? 0 : calls.back();
        calls.push_back(rows);
        for (int y = std::max(0, from); y < rows; ++y)
            std::copy(page.view().row(y), page.view().row(y) + page.width(),
                      at_call.begin() + static_cast<std::ptrdiff_t>(y) * page.width());
    });
    auto drawn = r->render_gray_streaming(text, o, page, record);
    ASSERT_TRUE(drawn) << drawn.error().message;
    EXPECT_EQ(page, *whole);
    ASSERT_GT(calls.size(), 20u);  // one per line or so: the rows are handed on early
    EXPECT_TRUE(std::is_sorted(calls.begin(), calls.end()));
    EXPECT_GT(calls.front(), 0);
    EXPECT_LT(calls.front(), page.height() / 4);
    EXPECT_EQ(calls.back(), page.height());
    EXPECT_EQ(at_call, whole->pixels());
    // A refused size fails before any row is drawn: no call.
    calls.clear();
    o.shape.size_px = -1;
    auto count = sink_of([&](int rows) { calls.push_back(rows); });
    EXPECT_FALSE(r->render_gray_streaming(text, o, page, count));
    EXPECT_TRUE(calls.empty());
}

TEST(TextRenderer, PageDeflatedOnWorkerThreadsWhileDrawnDecodesToThePage) {
    // bezel render's gray PNG route: workers read the final rows while this thread blends the
    // rows below them (ThreadSanitizer runs this test).
    auto r = TextRenderer::open(kDejaVu);
    ASSERT_TRUE(r) << r.error().message;
    std::string text;
    for (int i = 0; i < 30; ++i) text += "Wafer office, jumpy quartz vex (" + std::to_string(i) + ")\n";
    const TextRenderOptions o = line_options(16);
    Mask page;
    std::optional<PngGrayStream> png;
    auto deflate = sink_of([&](int rows) {
        if (!png) png.emplace(page.view(), 2);
        png->rows_final(rows);
    });
    auto drawn = r->render_gray_streaming(text, o, page, deflate);
    ASSERT_TRUE(drawn) << drawn.error().message;
    ASSERT_TRUE(png.has_value());
    auto bytes = png->finish();
    ASSERT_TRUE(bytes) << bytes.error().message;
    EXPECT_EQ(*bytes, *encode_png_gray(page.view(), 2));
    const std::string file = ::testing::TempDir() + "bezel_text_stream.png";
    std::FILE* f = std::fopen(file.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    std::fwrite(bytes->data(), 1, bytes->size(), f);
    std::fclose(f);
    auto back = read_png_gray(file);
    std::remove(file.c_str());
    ASSERT_TRUE(back) << back.error().message;
    EXPECT_EQ(*back, page);
    EXPECT_GT(page.height(), 4 * kPngBandRows);  // several bands went to the workers
}

TEST(TextRenderer, ErrorsNameTheInput) {
    auto missing = TextRenderer::open("/nonexistent/font.ttf");
    ASSERT_FALSE(missing);
    EXPECT_NE(missing.error().message.find("/nonexistent/font.ttf"), std::string::npos);

    auto r = TextRenderer::open(kDejaVu);
    ASSERT_TRUE(r);
    auto bad_utf8 = r->render("ok \xff", line_options(16));
    ASSERT_FALSE(bad_utf8);
    EXPECT_NE(bad_utf8.error().message.find("byte 3"), std::string::npos) << bad_utf8.error().message;
    auto zero = r->render("x", line_options(0));
    EXPECT_FALSE(zero);
    // A page past the pixel bound is refused before any pixel is allocated.
    TextRenderOptions huge = line_options(16);
    huge.layout.margin_px = 20000;
    auto too_big = r->render("x", huge);
    ASSERT_FALSE(too_big);
    EXPECT_NE(too_big.error().message.find("too large"), std::string::npos);
    TextRenderOptions axes = line_options(16);
    axes.shape.variations = {{"wght", 700}};
    EXPECT_FALSE(r->render("x", axes));   // DejaVu Sans has no axes
}

// --- Drawing into the caller's pixels -----------------------------------------------------------

// A target of `w` × `h` pixels of `fill` in `format`, rows padded by 8 bytes.
struct Surface {
    std::vector<std::uint8_t> memory;
    PixelView view;
    Surface(int w, int h, PixelFormat format, Rgba8 fill) {
        const std::ptrdiff_t stride = static_cast<std::ptrdiff_t>(w) * bytes_per_pixel(format) + 8;
        memory.assign(static_cast<std::size_t>(stride * h), 0);
        view = PixelView{memory.data(), w, h, stride, format};
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) store_pixel(format, view.pixel(x, y), fill);
    }
    Rgba8 at(int x, int y) const { return load_pixel(view.format, view.pixel(x, y)); }
};

TEST(TextRendererDraw, OntoAnImageOfTheBackgroundIsRenderPixelForPixel) {
    auto fonts = FontCollection::open({{kDejaVu, 0, {}}, {kEmoji, 0, {}}});
    ASSERT_TRUE(fonts) << fonts.error().message;
    auto r = TextRenderer::open(std::move(*fonts));
    ASSERT_TRUE(r);
    for (CoverageFormat format : {CoverageFormat::Gray, CoverageFormat::Lcd})
        for (LcdOrder order : {LcdOrder::Rgb, LcdOrder::Bgr}) {
            TextRenderOptions o;
            o.shape.size_px = 17;
            o.layout.margin_px = 3;
            o.format = format;
            o.lcd_order = order;
            o.foreground = {20, 60, 140, 255};
            o.background = {250, 245, 230, 255};
            const std::string text = "Wave \xF0\x9F\x98\x80 fj";   // with a colour emoji
            auto page = r->render(text, o);
            ASSERT_TRUE(page) << page.error().message;
            auto laid_out = r->layout(text, o);
            ASSERT_TRUE(laid_out);
            EXPECT_EQ(std::ceil(laid_out->width_px), page->width());
            EXPECT_EQ(std::ceil(laid_out->height_px), page->height());
            EXPECT_TRUE(r->last_text_has_color());
            Image drawn(page->width(), page->height(), o.background);
            ASSERT_TRUE(r->draw(text, o, drawn.view(), {0, 0}).ok());
            EXPECT_TRUE(drawn == *page);
            Image again(page->width(), page->height(), o.background);
            ASSERT_TRUE(r->draw(*laid_out, o, again.view(), {0, 0}).ok());
            EXPECT_TRUE(again == *page);
        }
}

TEST(TextRendererDraw, IntoBgraPremultipliedAtAnOffsetIsThePageMovedAndClipped) {
    auto r = TextRenderer::open(kDejaVu);
    ASSERT_TRUE(r);
    TextRenderOptions o;
    o.shape.size_px = 15;
    o.layout.margin_px = 4;   // all ink inside the page (draw() does not clip to the page)
    o.foreground = {200, 30, 30, 255};
    o.background = {240, 240, 255, 255};
    const std::string text = "Toolkit text";
    auto page = r->render(text, o);
    ASSERT_TRUE(page);
    // Whole-pixel offsets, one of them pushing the text past the target's left and top sides.
    for (const auto& [dx, dy] : {std::pair{9, 4}, std::pair{-13, -6}}) {
        Surface s(page->width() + 5, page->height() + 2, PixelFormat::Bgra8Premultiplied,
                  o.background);
        ASSERT_TRUE(r->draw(text, o, s.view, {double(dx), double(dy)}).ok());
        int inked = 0;
        for (int y = 0; y < s.view.height; ++y)
            for (int x = 0; x < s.view.width; ++x) {
                const int px = x - dx, py = y - dy;
                const bool on_page = px >= 0 && py >= 0 && px < page->width() && py < page->height();
                const Rgba8 want = on_page ? page->at(px, py) : o.background;
                ASSERT_EQ(s.at(x, y), want) << dx << "," << dy << " at " << x << "," << y;
                inked += want != o.background;
            }
        EXPECT_GT(inked, 50);
        // The padding after each row is untouched.
        for (int y = 0; y < s.view.height; ++y)
            for (int k = 0; k < 8; ++k) ASSERT_EQ(s.view.row(y)[4 * s.view.width + k], 0);
    }
}

TEST(TextRendererDraw, WritesOnlyThePixelsUnderGlyphs) {
    // No background is filled: over transparent pixels the text is "over" nothing, and every
    // pixel render() leaves as background stays transparent.
    auto r = TextRenderer::open(kDejaVu);
    ASSERT_TRUE(r);
    TextRenderOptions o;
    o.shape.size_px = 14;
    o.coverage.rendering = TextRendering::Linear;
    auto page = r->render("Hi there", o);
    ASSERT_TRUE(page);
    Surface s(page->width(), page->height(), PixelFormat::Rgba8, Rgba8{0, 0, 0, 0});
    ASSERT_TRUE(r->draw("Hi there", o, s.view, {0, 0}).ok());
    int opaque = 0;
    for (int y = 0; y < page->height(); ++y)
        for (int x = 0; x < page->width(); ++x) {
            const Rgba8 got = s.at(x, y);
            if (page->at(x, y) == o.background) {
                ASSERT_EQ(got.a, 0) << x << "," << y;
            } else {
                ASSERT_GT(got.a, 0) << x << "," << y;
                ASSERT_EQ(got.r, 0);   // the ink is black, whatever its alpha
            }
            opaque += got.a == 255;
        }
    EXPECT_GT(opaque, 20);
}

TEST(TextRendererDraw, GrayTargetIsRenderGray) {
    auto r = TextRenderer::open(kCantarell);
    ASSERT_TRUE(r);
    TextRenderOptions o;
    o.shape.size_px = 13;
    o.foreground = {30, 30, 30, 255};
    o.background = {220, 220, 220, 255};
    auto page = r->render_gray("Gray page", o);
    ASSERT_TRUE(page);
    Surface s(page->width(), page->height(), PixelFormat::Gray8, o.background);
    ASSERT_TRUE(r->draw("Gray page", o, s.view, {0, 0}).ok());
    for (int y = 0; y < page->height(); ++y)
        for (int x = 0; x < page->width(); ++x) ASSERT_EQ(s.view.pixel(x, y)[0], page->at(x, y));
}

TEST(TextRendererDraw, ErrorsNameTheProblemAndWriteNothing) {
    auto r = TextRenderer::open(kDejaVu);
    ASSERT_TRUE(r);
    TextRenderOptions o;
    Surface gray(40, 20, PixelFormat::Gray8, Rgba8{255, 255, 255, 255});
    Surface rgba(40, 20, PixelFormat::Rgba8, Rgba8{255, 255, 255, 255});
    const std::vector<std::uint8_t> gray_before = gray.memory, rgba_before = rgba.memory;
    auto says = [](const Status& s, const std::string& what) {
        return !s.ok() && s.error().message.find(what) != std::string::npos;
    };
    TextRenderOptions lcd = o;
    lcd.format = CoverageFormat::Lcd;
    EXPECT_TRUE(says(r->draw("a", lcd, gray.view, {0, 0}), "RGBA or BGRA target"));
    lcd.background.a = 128;
    EXPECT_TRUE(says(r->draw("a", lcd, rgba.view, {0, 0}), "opaque background"));
    EXPECT_TRUE(says(r->draw("a", o, PixelView{nullptr, 4, 4, 16, PixelFormat::Rgba8}, {0, 0}),
                     "null data"));
    EXPECT_TRUE(says(r->draw("a", o, PixelView{rgba.memory.data(), -1, 4, 16, PixelFormat::Rgba8},
                             {0, 0}),
                     "outside 0.."));
    EXPECT_TRUE(says(r->draw("a", o, rgba.view, {std::nan(""), 0}), "origin is not finite"));
    TextLayout foreign;
    foreign.glyphs.push_back(PlacedGlyph{3, 1, 10, 0, 7});
    EXPECT_TRUE(says(r->draw(foreign, o, rgba.view, {0, 0}), "font 7"));
    EXPECT_EQ(gray.memory, gray_before);
    EXPECT_EQ(rgba.memory, rgba_before);
    // Text wholly outside the target draws nothing and is no error.
    ASSERT_TRUE(r->draw("far away", o, rgba.view, {-5000, 3e6}).ok());
    EXPECT_EQ(rgba.memory, rgba_before);
}

TEST(TextRenderer, EmptyTextIsABackgroundPage) {
    auto r = TextRenderer::open(kDejaVu);
    ASSERT_TRUE(r);
    auto image = r->render("", line_options(16));
    ASSERT_TRUE(image) << image.error().message;
    EXPECT_GE(image->width(), 1);
    for (int y = 0; y < image->height(); ++y)
        for (int x = 0; x < image->width(); ++x) ASSERT_EQ(image->at(x, y), (Rgba8{255, 255, 255, 255}));
}

}  // namespace
}  // namespace bezel
