// Tests of bezel/image.hpp: views with strides, the owning mask, gray PNG round trips and the
// errors that name the file.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "bezel/image.hpp"

namespace bezel {
namespace {

std::string temp_path(const std::string& name) {
    return ::testing::TempDir() + "bezel_image_test_" + name;
}

TEST(MaskView, SubViewAddressesParentPixelsThroughStride) {
    Mask m(10, 8);
    MaskView v = m.view();
    MaskView s = v.sub(3, 2, 4, 5);
    s.at(0, 0) = 7;
    s.at(3, 4) = 9;
    EXPECT_EQ(m.at(3, 2), 7);
    EXPECT_EQ(m.at(6, 6), 9);
    EXPECT_EQ(s.stride, 10);
}

TEST(Mask, CopiesAreIndependentValues) {
    Mask a(3, 3);
    a.at(1, 1) = 200;
    Mask b = a;
    b.at(1, 1) = 5;
    EXPECT_EQ(a.at(1, 1), 200);
    EXPECT_NE(a, b);
    b.at(1, 1) = 200;
    EXPECT_EQ(a, b);
}

TEST(Png, RoundTripPreservesEveryByteOfRandomMasks) {
    std::mt19937 rng(1234);
    for (int trial = 0; trial < 20; ++trial) {
        int w = 1 + static_cast<int>(rng() % 70), h = 1 + static_cast<int>(rng() % 50);
        Mask m(w, h);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) m.at(x, y) = static_cast<std::uint8_t>(rng());
        std::string file = temp_path("roundtrip.png");
        ASSERT_TRUE(write_png_gray(file, m.view()).ok());
        Expected<Mask> back = read_png_gray(file);
        ASSERT_TRUE(back.ok()) << back.error().message;
        EXPECT_EQ(*back, m) << "trial " << trial;
        std::remove(file.c_str());
    }
}

TEST(Png, WritesAStridedSubViewAsItsOwnImage) {
    Mask big(20, 20);
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 20; ++x) big.at(x, y) = static_cast<std::uint8_t>(x * 10 + y);
    MaskView sub = big.view().sub(5, 6, 7, 3);
    std::string file = temp_path("sub.png");
    ASSERT_TRUE(write_png_gray(file, sub).ok());
    Expected<Mask> back = read_png_gray(file);
    ASSERT_TRUE(back.ok());
    ASSERT_EQ(back->width(), 7);
    ASSERT_EQ(back->height(), 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 7; ++x) EXPECT_EQ(back->at(x, y), big.at(x + 5, y + 6));
    std::remove(file.c_str());
}

// The one-stream igzip writer (Fast, Default) and libpng (Small) on images too short for the
// banded writer, 1-row ones included: every byte comes back through libpng's reader, gray
// masks and opaque RGBA images whose colour channels are equal (the reader's gray is then
// their value; tests/python/test_render.py checks RGBA with varied alpha through Pillow).
TEST(Png, SmallAndOneRowImagesRoundTripAtEveryCompression) {
    std::mt19937 rng(37);
    const int sizes[][2] = {{1, 1}, {739, 1}, {1, 28}, {739, 28}, {57, 127}};
    for (PngCompression level :
         {PngCompression::Fast, PngCompression::Default, PngCompression::Small}) {
        for (auto [w, h] : sizes) {
            Mask m(w, h);
            Image image(w, h);
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) {
                    // Text-like: mostly one value, some runs of noise.
                    const auto v = (x / 9 + y) % 4 == 0 ? static_cast<std::uint8_t>(rng())
                                                        : std::uint8_t{230};
                    m.at(x, y) = v;
                    image.at(x, y) = Rgba8{v, v, v, 255};
                }
            const std::string what = std::to_string(w) + "x" + std::to_string(h) + " level " +
                                     std::to_string(static_cast<int>(level));
            auto gray = encode_png_gray(m.view(), PngOptions{level});
            auto rgba = encode_png(image, PngColor::Rgba, PngOptions{level});
            ASSERT_TRUE(gray) << what;
            ASSERT_TRUE(rgba) << what;
            EXPECT_EQ((*rgba)[25], 6) << what;  // IHDR colour type: RGBA
            for (const auto* png : {&*gray, &*rgba}) {
                const std::string file = temp_path("small.png");
                { std::ofstream(file, std::ios::binary)
                      .write(reinterpret_cast<const char*>(png->data()),
                             static_cast<std::streamsize>(png->size())); }
                Expected<Mask> back = read_png_gray(file);
                std::remove(file.c_str());
                ASSERT_TRUE(back.ok()) << what << ": " << back.error().message;
                EXPECT_EQ(*back, m) << what << (png == &*gray ? " gray" : " rgba");
            }
        }
    }
}

TEST(Png, MissingFileErrorNamesTheFile) {
    Expected<Mask> r = read_png_gray("/nonexistent/dir/x.png");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("/nonexistent/dir/x.png"), std::string::npos);
}

TEST(Png, NonPngFileIsAnErrorNamingTheFile) {
    std::string file = temp_path("notpng.png");
    { std::ofstream(file) << "this is not a png file at all"; }
    Expected<Mask> r = read_png_gray(file);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find(file), std::string::npos);
    std::remove(file.c_str());
}

TEST(Png, TruncatedPngIsAnErrorNotACrash) {
    Mask m(30, 30);
    for (int i = 0; i < 30; ++i) m.at(i, i) = 255;
    std::string file = temp_path("trunc.png");
    ASSERT_TRUE(write_png_gray(file, m.view()).ok());
    std::ifstream in(file, std::ios::binary);
    std::vector<char> bytes((std::istreambuf_iterator<char>(in)), {});
    in.close();
    ASSERT_GT(bytes.size(), 60u);
    { std::ofstream(file, std::ios::binary).write(bytes.data(), 60); }
    Expected<Mask> r = read_png_gray(file);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find(file), std::string::npos);
    std::remove(file.c_str());
}

TEST(Png, EmptyImageAndUnwritablePathAreErrors) {
    Mask empty;
    EXPECT_FALSE(write_png_gray(temp_path("empty.png"), empty.view()).ok());
    Mask m(2, 2);
    Status s = write_png_gray("/nonexistent/dir/y.png", m.view());
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message.find("/nonexistent/dir/y.png"), std::string::npos);
}

}  // namespace
}  // namespace bezel
