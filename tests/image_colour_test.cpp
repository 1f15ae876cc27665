// Colour images: hb-view colour syntax, linear-light compositing, PNG / Netpbm / ANSI encoders.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "bezel/image.hpp"
#include "image/srgb.hpp"

namespace bezel {
namespace {

const Rgba8 kWhite{255, 255, 255, 255};
const Rgba8 kBlack{0, 0, 0, 255};

std::string temp_file(const std::string& name) {
    return (std::filesystem::temp_directory_path() /
            ("bezel_image_colour_" + std::to_string(::getpid()) + "_" + name))
        .string();
}

TEST(ParseColor, AcceptsHbViewForms) {
    EXPECT_EQ(*parse_color("#FF8000"), (Rgba8{255, 128, 0, 255}));
    EXPECT_EQ(*parse_color("ff800080"), (Rgba8{255, 128, 0, 128}));
    EXPECT_EQ(*parse_color("#ff8000"), (Rgba8{255, 128, 0, 255}));
    EXPECT_EQ(*parse_color("#F80"), (Rgba8{255, 136, 0, 255}));
    EXPECT_EQ(*parse_color("#F808"), (Rgba8{255, 136, 0, 136}));
    EXPECT_EQ(*parse_color("White"), kWhite);
    EXPECT_EQ(*parse_color("green"), (Rgba8{0, 128, 0, 255}));
    EXPECT_EQ(*parse_color("transparent"), (Rgba8{0, 0, 0, 0}));
}

TEST(ParseColor, AcceptsEveryCssNamedColourCaseInsensitively) {
    // CSS Color Level 4 values, including the ones where X11's rgb.txt differs (gray, green,
    // maroon, purple) and the late additions (rebeccapurple).
    EXPECT_EQ(*parse_color("yellow"), (Rgba8{255, 255, 0, 255}));
    EXPECT_EQ(*parse_color("RebeccaPurple"), (Rgba8{0x66, 0x33, 0x99, 255}));
    EXPECT_EQ(*parse_color("gray"), (Rgba8{128, 128, 128, 255}));
    EXPECT_EQ(*parse_color("grey"), *parse_color("gray"));
    EXPECT_EQ(*parse_color("maroon"), (Rgba8{128, 0, 0, 255}));
    EXPECT_EQ(*parse_color("purple"), (Rgba8{128, 0, 128, 255}));
    EXPECT_EQ(*parse_color("aliceblue"), (Rgba8{0xF0, 0xF8, 0xFF, 255}));       // first
    EXPECT_EQ(*parse_color("YELLOWGREEN"), (Rgba8{0x9A, 0xCD, 0x32, 255}));     // last
    EXPECT_EQ(*parse_color("lightgoldenrodyellow"), (Rgba8{0xFA, 0xFA, 0xD2, 255}));
    EXPECT_EQ(*parse_color("cyan"), *parse_color("aqua"));
}

TEST(ParseColor, AnUnknownNameSaysItIsNotACssName) {
    auto c = parse_color("yelow");
    ASSERT_FALSE(c);
    EXPECT_NE(c.error().message.find("'yelow': not a CSS colour name"), std::string::npos)
        << c.error().message;
}

TEST(ParseColor, ErrorsNameTheText) {
    for (const char* bad : {"#GG0000", "#12345", "", "F80", "#", "reddish", "#FF00000"}) {
        auto c = parse_color(bad);
        ASSERT_FALSE(c) << bad;
        EXPECT_NE(c.error().message.find("'" + std::string(bad) + "'"), std::string::npos)
            << c.error().message;
    }
}

TEST(Srgb, EncodeOfDecodeIsIdentityForEveryByte) {
    const SrgbTables& t = srgb_tables();
    for (int v = 0; v < 256; ++v) EXPECT_EQ(t.enc(t.decode[static_cast<std::size_t>(v)]), v) << v;
    EXPECT_NEAR(t.decode[188], 0.5, 0.003);  // the byte that means half the light
}

TEST(BlendMask, HalfCoverageIsHalfTheLightNotHalfTheByte) {
    // 50% black on white is 0.5 linear light: sRGB byte 188 (±1 for the 8-bit coverage step),
    // where naive sRGB-space blending would give 128.
    for (std::uint8_t cov : {std::uint8_t{127}, std::uint8_t{128}}) {
        Image image(1, 1, kWhite);
        std::uint8_t m = cov;
        blend_mask(image, ConstMaskView(&m, 1, 1, 1), 0, 0, kBlack);
        EXPECT_NEAR(image.at(0, 0).r, 188, 1);
        EXPECT_EQ(image.at(0, 0).r, image.at(0, 0).b);
        EXPECT_EQ(image.at(0, 0).a, 255);
    }
    // White on black at half coverage is the same half of the light.
    Image dark(1, 1, kBlack);
    std::uint8_t m = 128;
    blend_mask(dark, ConstMaskView(&m, 1, 1, 1), 0, 0, kWhite);
    EXPECT_NEAR(dark.at(0, 0).g, 188, 1);
}

TEST(BlendMask, FullAndZeroCoverageAndColourAlpha) {
    Image image(3, 1, Rgba8{10, 200, 30, 255});
    const std::uint8_t m[3] = {0, 255, 255};
    blend_mask(image, ConstMaskView(m, 2, 1, 3), 0, 0, Rgba8{250, 5, 99, 255});
    EXPECT_EQ(image.at(0, 0), (Rgba8{10, 200, 30, 255}));   // untouched
    EXPECT_EQ(image.at(1, 0), (Rgba8{250, 5, 99, 255}));    // replaced
    EXPECT_EQ(image.at(2, 0), (Rgba8{10, 200, 30, 255}));   // outside the mask
    // A half-transparent colour at full coverage is half coverage of the opaque colour.
    Image a(1, 1, kWhite), b(1, 1, kWhite);
    std::uint8_t full = 255, half = 128;
    blend_mask(a, ConstMaskView(&full, 1, 1, 1), 0, 0, Rgba8{0, 0, 0, 128});
    blend_mask(b, ConstMaskView(&half, 1, 1, 1), 0, 0, kBlack);
    EXPECT_EQ(a.at(0, 0), b.at(0, 0));
}

TEST(BlendMask, OverTransparentKeepsTheColourAndSetsAlpha) {
    Image image(2, 1, Rgba8{0, 0, 0, 0});
    const std::uint8_t m[2] = {255, 128};
    blend_mask(image, ConstMaskView(m, 2, 1, 2), 0, 0, Rgba8{200, 100, 50, 255});
    EXPECT_EQ(image.at(0, 0), (Rgba8{200, 100, 50, 255}));
    // Straight alpha: the colour is not darkened by the empty destination.
    EXPECT_EQ(image.at(1, 0).r, 200);
    EXPECT_EQ(image.at(1, 0).b, 50);
    EXPECT_EQ(image.at(1, 0).a, 128);
}

TEST(BlendMask, ClipsAtEveryEdge) {
    // A 4×4 full mask at each of the four corners (partly outside), on a 3×3 image.
    const std::uint8_t m[16] = {255, 255, 255, 255, 255, 255, 255, 255,
                                255, 255, 255, 255, 255, 255, 255, 255};
    for (auto [x, y] : {std::pair{-3, -3}, std::pair{2, -3}, std::pair{-3, 2}, std::pair{2, 2}}) {
        Image image(3, 3, kWhite);
        blend_mask(image, ConstMaskView(m, 4, 4, 4), x, y, kBlack);
        int black = 0;
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 3; ++i) black += image.at(i, j) == kBlack;
        EXPECT_EQ(black, 1) << x << "," << y;
    }
    Image image(3, 3, kWhite);
    blend_mask(image, ConstMaskView(m, 4, 4, 4), 1 << 30, -(1 << 30), kBlack);
    blend_mask(image, ConstMaskView(m, 4, 4, 4), -2147483647, 2147483600, kBlack);
    EXPECT_EQ(image, Image(3, 3, kWhite));
}

TEST(BlendMaskGray, EqualsTheRgbaBlendOfTheSameGraysPixelForPixel) {
    // Random masks, overlapping and partly outside, onto a page that is background only where
    // nothing has been drawn yet: the background lookup and the general blend both run.
    std::uint32_t seed = 12345;
    auto next = [&seed] { return (seed = seed * 1664525u + 1013904223u) >> 24; };
    for (std::uint8_t fg : {0, 90, 255})
        for (std::uint8_t bg : {255, 200, 0}) {
            Image rgba(23, 17, Rgba8{bg, bg, bg, 255});
            Mask gray(23, 17);
            for (int y = 0; y < 17; ++y)
                for (int x = 0; x < 23; ++x) gray.at(x, y) = bg;
            for (int k = 0; k < 12; ++k) {
                Mask m(9, 7);
                for (int y = 0; y < 7; ++y)
                    for (int x = 0; x < 9; ++x) {
                        const std::uint32_t r = next();
                        m.at(x, y) = r < 60 ? 0 : r > 200 ? 255 : static_cast<std::uint8_t>(r);
                    }
                const int x = static_cast<int>(next() % 27) - 4, y = static_cast<int>(next() % 21) - 4;
                blend_mask(rgba, m.view(), x, y, Rgba8{fg, fg, fg, 255});
                blend_mask_gray(gray.view(), m.view(), x, y, fg);
            }
            int changed = 0;
            for (int y = 0; y < 17; ++y)
                for (int x = 0; x < 23; ++x) {
                    ASSERT_EQ(gray.at(x, y), rgba.at(x, y).r)
                        << +fg << " on " << +bg << " at " << x << "," << y;
                    changed += gray.at(x, y) != bg;
                }
            if (fg != bg) {
                EXPECT_GT(changed, 100);
            }
        }
}

TEST(BlendLcdMask, EachChannelTakesItsSubpixel) {
    const std::uint8_t m[3] = {255, 0, 0};  // only the first subpixel covered
    Image rgb(1, 1, kWhite), bgr(1, 1, kWhite);
    blend_lcd_mask(rgb, ConstMaskView(m, 3, 1, 3), 0, 0, kBlack, LcdOrder::Rgb);
    blend_lcd_mask(bgr, ConstMaskView(m, 3, 1, 3), 0, 0, kBlack, LcdOrder::Bgr);
    EXPECT_EQ(rgb.at(0, 0), (Rgba8{0, 255, 255, 255}));
    EXPECT_EQ(bgr.at(0, 0), (Rgba8{255, 255, 0, 255}));
    // Equal subpixels blend exactly as the gray mask does.
    const std::uint8_t even[3] = {128, 128, 128};
    std::uint8_t gray = 128;
    Image a(1, 1, kWhite), b(1, 1, kWhite);
    blend_lcd_mask(a, ConstMaskView(even, 3, 1, 3), 0, 0, kBlack, LcdOrder::Rgb);
    blend_mask(b, ConstMaskView(&gray, 1, 1, 1), 0, 0, kBlack);
    EXPECT_EQ(a, b);
}

// --- PixelView: caller-owned targets in every format ------------------------------------------

constexpr PixelFormat kAllFormats[] = {PixelFormat::Gray8, PixelFormat::Rgba8, PixelFormat::Bgra8,
                                       PixelFormat::Rgba8Premultiplied,
                                       PixelFormat::Bgra8Premultiplied};

TEST(PixelView, ByteOrderOfEveryFormat) {
    std::uint8_t p[4];
    const Rgba8 c{200, 100, 50, 255};
    store_pixel(PixelFormat::Rgba8, p, c);
    EXPECT_EQ((std::array<int, 4>{p[0], p[1], p[2], p[3]}), (std::array<int, 4>{200, 100, 50, 255}));
    store_pixel(PixelFormat::Bgra8, p, c);
    EXPECT_EQ((std::array<int, 4>{p[0], p[1], p[2], p[3]}), (std::array<int, 4>{50, 100, 200, 255}));
    // Premultiplied: P = round(C·A/255).
    store_pixel(PixelFormat::Bgra8Premultiplied, p, Rgba8{200, 100, 50, 128});
    EXPECT_EQ((std::array<int, 4>{p[0], p[1], p[2], p[3]}), (std::array<int, 4>{25, 50, 100, 128}));
    EXPECT_EQ(load_pixel(PixelFormat::Bgra8Premultiplied, p), (Rgba8{199, 100, 50, 128}));
    store_pixel(PixelFormat::Rgba8Premultiplied, p, Rgba8{200, 100, 50, 0});
    EXPECT_EQ((std::array<int, 4>{p[0], p[1], p[2], p[3]}), (std::array<int, 4>{0, 0, 0, 0}));
    // Gray8: the luma of the encoded values; a gray stays itself.
    store_pixel(PixelFormat::Gray8, p, Rgba8{77, 77, 77, 255});
    EXPECT_EQ(p[0], 77);
    EXPECT_EQ(load_pixel(PixelFormat::Gray8, p), (Rgba8{77, 77, 77, 255}));
    store_pixel(PixelFormat::Gray8, p, Rgba8{255, 0, 0, 255});
    EXPECT_EQ(p[0], 54);   // 0.2126·255, Rec. 709 in 8.8 fixed point
}

TEST(PixelView, EveryPremultipliedPixelRoundTripsThroughLoadAndStore) {
    for (int a = 0; a < 256; ++a)
        for (int c = 0; c <= a; ++c) {
            const std::uint8_t in[4] = {static_cast<std::uint8_t>(a == 0 ? 0 : c), 0,
                                        static_cast<std::uint8_t>(a), static_cast<std::uint8_t>(a)};
            std::uint8_t out[4];
            store_pixel(PixelFormat::Rgba8Premultiplied, out,
                        load_pixel(PixelFormat::Rgba8Premultiplied, in));
            ASSERT_EQ(std::memcmp(in, out, 4), 0) << c << "/" << a;
        }
}

TEST(PixelView, ImageViewIsItsRgbaMemory) {
    Image image(3, 2, Rgba8{1, 2, 3, 4});
    image.at(2, 1) = Rgba8{9, 8, 7, 6};
    const PixelView v = image.view();
    EXPECT_EQ(v.format, PixelFormat::Rgba8);
    EXPECT_EQ(v.stride, 12);
    EXPECT_EQ(load_pixel(v.format, v.pixel(2, 1)), (Rgba8{9, 8, 7, 6}));
    store_pixel(v.format, v.pixel(0, 1), Rgba8{5, 5, 5, 5});
    EXPECT_EQ(image.at(0, 1), (Rgba8{5, 5, 5, 5}));
}

// The blend formula of image.hpp, written out: D straight, S decoded, α per channel, a for alpha.
Rgba8 mixed(Rgba8 d, const float s[3], const float al[3], float a) {
    std::uint8_t* ch[3] = {&d.r, &d.g, &d.b};
    if (d.a == 255) {
        for (int k = 0; k < 3; ++k) {
            const float dl = srgb_decode(*ch[k]);
            *ch[k] = srgb_encode(dl + (s[k] - dl) * al[k]);
        }
        return d;
    }
    const float da = d.a / 255.0f, out_a = a + da * (1.0f - a);
    if (out_a <= 0.0f) return d;
    for (int k = 0; k < 3; ++k) {
        const float dl = srgb_decode(*ch[k]);
        const float num = s[k] * al[k] + dl * da * (1.0f - al[k]);
        const float norm = al[k] + da * (1.0f - al[k]);
        *ch[k] = srgb_encode(norm > 0.0f ? num / norm : 0.0f);
    }
    d.a = static_cast<std::uint8_t>(std::lround(out_a * 255.0f));
    return d;
}
std::uint8_t mixed_gray(std::uint8_t d, float s, float a) {
    const float dl = srgb_decode(d);
    return srgb_encode(dl + (s - dl) * a);
}

// Straight pixels, some opaque, some translucent, some transparent, as a random page.
struct Scene {
    int w = 13, h = 9;
    std::vector<Rgba8> px;
};
Scene random_scene(std::uint32_t& seed) {
    auto next = [&seed] { return static_cast<std::uint8_t>((seed = seed * 1664525u + 1013904223u) >> 24); };
    Scene s;
    const Rgba8 bg{next(), next(), next(), 255};
    for (int i = 0; i < s.w * s.h; ++i) {
        const std::uint8_t kind = next();
        s.px.push_back(kind < 128 ? bg : kind < 200 ? Rgba8{next(), next(), next(), 255}
                                   : kind < 240 ? Rgba8{next(), next(), next(), next()}
                                                : Rgba8{0, 0, 0, 0});
    }
    return s;
}

// A target of the scene in `format`, rows `pad` bytes apart beyond the pixels, bottom-up when
// `flip`; the padding bytes hold 0xA5, which no blend may touch.
struct Target {
    std::vector<std::uint8_t> memory;
    PixelView view;
};
Target make_target(const Scene& s, PixelFormat format, int pad, bool flip) {
    const int bpp = bytes_per_pixel(format);
    const std::ptrdiff_t row = static_cast<std::ptrdiff_t>(s.w) * bpp + pad;
    Target t;
    t.memory.assign(static_cast<std::size_t>(row * s.h), 0xA5);
    std::uint8_t* first = flip ? t.memory.data() + row * (s.h - 1) : t.memory.data();
    t.view = PixelView{first, s.w, s.h, flip ? -row : row, format};
    for (int y = 0; y < s.h; ++y)
        for (int x = 0; x < s.w; ++x) {
            Rgba8 c = s.px[static_cast<std::size_t>(y * s.w + x)];
            if (format == PixelFormat::Gray8) c = Rgba8{c.g, c.g, c.g, 255};
            store_pixel(format, t.view.pixel(x, y), c);
        }
    return t;
}

std::vector<std::uint8_t> random_mask(std::uint32_t& seed, int n) {
    std::vector<std::uint8_t> m(static_cast<std::size_t>(n));
    for (auto& v : m) {
        const std::uint32_t r = (seed = seed * 1664525u + 1013904223u) >> 24;
        v = r < 60 ? 0 : r > 200 ? 255 : static_cast<std::uint8_t>(r);
    }
    return m;
}

enum class What { Mask, Lcd, Image };

// Blends one random source in every format and checks each pixel against the formula applied to
// the pixel as load_pixel reads it, stored as store_pixel writes it.
void check_every_format(What what, std::uint32_t seed) {
    for (int round = 0; round < 40; ++round) {
        const Scene scene = random_scene(seed);
        const int mw = 6, mh = 5;
        const int x = static_cast<int>(seed % 17) - 4, y = static_cast<int>((seed >> 8) % 13) - 4;
        const std::vector<std::uint8_t> m = random_mask(seed, mw * mh * 4);
        const Rgba8 color{m[1], m[2], m[3], round % 3 == 0 ? m[4] : std::uint8_t(255)};
        const LcdOrder order = round % 2 ? LcdOrder::Bgr : LcdOrder::Rgb;
        auto curve = coverage_curve(color, {250, 250, 240, 255}, {});
        ASSERT_TRUE(curve.ok());
        // The image source: premultiplied RGBA made from the mask bytes.
        std::vector<std::uint8_t> src(m.size());
        for (std::size_t i = 0; i < m.size(); i += 4) {
            const std::uint8_t a = m[i + 3];
            for (int k = 0; k < 3; ++k)
                src[i + k] = static_cast<std::uint8_t>((m[(i + 4 * k + 5) % m.size()] * a + 127) / 255);
            src[i + 3] = a;
        }
        const ConstPixelView source(src.data(), mw, mh, 4 * mw, PixelFormat::Rgba8Premultiplied);
        for (PixelFormat format : kAllFormats)
            for (int pad : {0, 3})
                for (bool flip : {false, true}) {
                    Target t = make_target(scene, format, pad, flip);
                    const Target before = make_target(scene, format, pad, flip);
                    switch (what) {
                        case What::Mask:
                            blend_mask(t.view, ConstMaskView(m.data(), mw, mh, mw), x, y, color, *curve);
                            break;
                        case What::Lcd:
                            blend_lcd_mask(t.view, ConstMaskView(m.data(), 3 * mw, mh, 3 * mw), x, y,
                                           color, order, *curve);
                            break;
                        case What::Image: blend_image(t.view, source, x, y, 0.75f); break;
                    }
                    const std::size_t row = static_cast<std::size_t>(std::abs(t.view.stride));
                    for (std::size_t i = 0; i < t.memory.size(); ++i) {
                        if (static_cast<int>(i % row) >= scene.w * bytes_per_pixel(format)) {
                            ASSERT_EQ(t.memory[i], 0xA5) << "padding written";
                        }
                    }
                    for (int py = 0; py < scene.h; ++py)
                        for (int px = 0; px < scene.w; ++px) {
                            const Rgba8 d = load_pixel(format, before.view.pixel(px, py));
                            const int mx = px - x, my = py - y;
                            std::uint8_t want[4];
                            store_pixel(format, want, d);
                            if (mx >= 0 && my >= 0 && mx < mw && my < mh) {
                                float al[3] = {0, 0, 0}, a = 0;
                                Rgba8 s = color;
                                bool skip = false;
                                const float ca = color.a / 255.0f;
                                if (what == What::Mask) {
                                    const std::uint8_t cov = m[static_cast<std::size_t>(my * mw + mx)];
                                    a = (*curve)[cov] * ca;
                                    al[0] = al[1] = al[2] = a;
                                    skip = cov == 0;
                                } else if (what == What::Lcd) {
                                    const std::uint8_t* p = &m[static_cast<std::size_t>(my * 3 * mw + 3 * mx)];
                                    const int r_at = order == LcdOrder::Bgr ? 2 : 0;
                                    const std::uint8_t cv[3] = {p[r_at], p[1], p[2 - r_at]};
                                    for (int k = 0; k < 3; ++k) al[k] = (*curve)[cv[k]] * ca;
                                    a = std::max({al[0], al[1], al[2]});
                                    if (format == PixelFormat::Gray8)
                                        a = ((*curve)[p[0]] + (*curve)[p[1]] + (*curve)[p[2]]) *
                                            (1.0f / 3.0f) * ca;
                                    skip = (p[0] | p[1] | p[2]) == 0;
                                } else {
                                    s = load_pixel(source.format, source.pixel(mx, my));
                                    a = (s.a / 255.0f) * 0.75f;
                                    al[0] = al[1] = al[2] = a;
                                    skip = s.a == 0;
                                }
                                skip = skip || (what != What::Image && color.a == 0);
                                if (!skip) {
                                    if (format == PixelFormat::Gray8) {
                                        want[0] = mixed_gray(d.r, srgb_decode(luma(s)), a);
                                    } else {
                                        const float sl[3] = {srgb_decode(s.r), srgb_decode(s.g),
                                                             srgb_decode(s.b)};
                                        store_pixel(format, want, mixed(d, sl, al, a));
                                    }
                                }
                            }
                            const std::uint8_t* got = t.view.pixel(px, py);
                            for (int k = 0; k < bytes_per_pixel(format); ++k)
                                ASSERT_EQ(got[k], want[k])
                                    << "format " << int(format) << " what " << int(what) << " at "
                                    << px << "," << py << " byte " << k << " round " << round;
                        }
                }
    }
}

TEST(PixelViewBlend, MaskFollowsTheFormulaInEveryFormatStrideAndDirection) {
    check_every_format(What::Mask, 1);
}
TEST(PixelViewBlend, LcdMaskFollowsTheFormulaInEveryFormatStrideAndDirection) {
    check_every_format(What::Lcd, 2);
}
TEST(PixelViewBlend, ImageOverFollowsTheFormulaInEveryFormatStrideAndDirection) {
    check_every_format(What::Image, 3);
}

TEST(PixelViewBlend, BgraIsRgbaSwappedAndPremultipliedIsStraightOnOpaquePixels) {
    std::uint32_t seed = 7;
    for (int round = 0; round < 30; ++round) {
        Scene scene = random_scene(seed);
        for (Rgba8& p : scene.px) p.a = 255;   // opaque page
        const std::vector<std::uint8_t> m = random_mask(seed, 7 * 6);
        const Rgba8 color{m[0], m[1], m[2], 255};
        Target rgba = make_target(scene, PixelFormat::Rgba8, 0, false);
        Target bgra = make_target(scene, PixelFormat::Bgra8, 0, false);
        Target bgra_pm = make_target(scene, PixelFormat::Bgra8Premultiplied, 0, false);
        for (Target* t : {&rgba, &bgra, &bgra_pm})
            blend_mask(t->view, ConstMaskView(m.data(), 7, 6, 7), 3, 2, color);
        int changed = 0;
        for (std::size_t i = 0; i < rgba.memory.size(); i += 4) {
            for (int k = 0; k < 3; ++k) ASSERT_EQ(bgra.memory[i + k], rgba.memory[i + 2 - k]);
            ASSERT_EQ(bgra.memory[i + 3], rgba.memory[i + 3]);
            ASSERT_EQ(std::memcmp(&bgra.memory[i], &bgra_pm.memory[i], 4), 0);
            changed += bgra.memory[i] != 0xA5;
        }
        EXPECT_GT(changed, 0);
    }
}

TEST(PixelViewBlend, ImageOverloadsEqualTheirViewAndGrayPagesTheirGray8View) {
    std::uint32_t seed = 99;
    auto curve = coverage_curve({30, 30, 30, 255}, {230, 230, 230, 255}, {});
    ASSERT_TRUE(curve.ok());
    for (int round = 0; round < 20; ++round) {
        const Scene scene = random_scene(seed);
        Image image(scene.w, scene.h);
        for (int i = 0; i < scene.w * scene.h; ++i)
            image.at(i % scene.w, i / scene.w) = scene.px[static_cast<std::size_t>(i)];
        Target t = make_target(scene, PixelFormat::Rgba8, 5, true);
        const std::vector<std::uint8_t> m = random_mask(seed, 8 * 6);
        const Rgba8 color{m[0], m[1], m[2], m[3]};
        blend_mask(image, ConstMaskView(m.data(), 8, 6, 8), 2, 1, color, *curve);
        blend_mask(t.view, ConstMaskView(m.data(), 8, 6, 8), 2, 1, color, *curve);
        blend_lcd_mask(image, ConstMaskView(m.data(), 6, 8, 6), 5, 3, color, LcdOrder::Bgr);
        blend_lcd_mask(t.view, ConstMaskView(m.data(), 6, 8, 6), 5, 3, color, LcdOrder::Bgr);
        for (int y = 0; y < scene.h; ++y)
            for (int x = 0; x < scene.w; ++x)
                ASSERT_EQ(load_pixel(PixelFormat::Rgba8, t.view.pixel(x, y)), image.at(x, y));

        Mask page(scene.w, scene.h);
        for (int i = 0; i < scene.w * scene.h; ++i)
            page.at(i % scene.w, i / scene.w) = scene.px[static_cast<std::size_t>(i)].g;
        Mask copy = page;
        const MaskView cv = copy.view();
        blend_mask_gray(page.view(), ConstMaskView(m.data(), 8, 6, 8), 2, 1, m[4], *curve);
        blend_mask(PixelView{cv.data, cv.width, cv.height, cv.stride, PixelFormat::Gray8},
                   ConstMaskView(m.data(), 8, 6, 8), 2, 1, Rgba8{m[4], m[4], m[4], 255}, *curve);
        ASSERT_EQ(page, copy);
    }
}

TEST(PixelViewBlend, NullEmptyAndFarAwayTargetsDrawNothing) {
    const std::uint8_t m[4] = {255, 255, 255, 255};
    blend_mask(PixelView{}, ConstMaskView(m, 2, 2, 2), 0, 0, kBlack);
    blend_image(PixelView{}, ConstPixelView(m, 1, 1, 4, PixelFormat::Rgba8), 0, 0);
    std::uint8_t px[4] = {1, 2, 3, 4};
    const PixelView one{px, 1, 1, 4, PixelFormat::Bgra8Premultiplied};
    blend_mask(one, ConstMaskView(m, 2, 2, 2), -2147483647, 2147483600, kBlack);
    blend_lcd_mask(one, ConstMaskView(m, 3, 1, 3), 1, 0, kBlack, LcdOrder::Rgb);
    blend_image(one, ConstPixelView(m, 1, 1, 4, PixelFormat::Rgba8), 0, 0, std::nanf(""));
    blend_mask(one, ConstMaskView(m, 2, 2, 2), 0, 0, Rgba8{0, 0, 0, 0});
    EXPECT_EQ((std::array<int, 4>{px[0], px[1], px[2], px[3]}), (std::array<int, 4>{1, 2, 3, 4}));
}

Image test_pattern(int w, int h) {
    Image image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            image.at(x, y) = Rgba8{static_cast<std::uint8_t>(x * 37 + y),
                                   static_cast<std::uint8_t>(y * 11), static_cast<std::uint8_t>(x ^ y),
                                   static_cast<std::uint8_t>(255 - x)};
    return image;
}

TEST(EncodePng, GrayRoundTripsThroughReadPngGray) {
    Image image(5, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 5; ++x) {
            auto v = static_cast<std::uint8_t>(x * 50 + y * 3);
            image.at(x, y) = Rgba8{v, v, v, 255};
        }
    std::string file = temp_file("gray.png");
    ASSERT_TRUE(write_png(file, image, PngColor::Gray));
    auto back = read_png_gray(file);
    ASSERT_TRUE(back) << back.error().message;
    ASSERT_EQ(back->width(), 5);
    ASSERT_EQ(back->height(), 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 5; ++x) EXPECT_EQ(back->at(x, y), image.at(x, y).r);
    std::remove(file.c_str());
}

TEST(EncodePng, MaskRoundTripsExactly) {
    std::uint8_t pixels[12];
    for (int i = 0; i < 12; ++i) pixels[i] = static_cast<std::uint8_t>(i * 21);
    // A 3×3 window of a 4-wide buffer: the stride is honoured.
    auto png = encode_png_gray(ConstMaskView(pixels, 3, 3, 4));
    ASSERT_TRUE(png);
    std::string file = temp_file("mask.png");
    std::FILE* f = std::fopen(file.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    std::fwrite(png->data(), 1, png->size(), f);
    std::fclose(f);
    auto back = read_png_gray(file);
    ASSERT_TRUE(back);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 3; ++x) EXPECT_EQ(back->at(x, y), pixels[y * 4 + x]);
    std::remove(file.c_str());
}

TEST(EncodePng, GrayOnSeveralThreadsDecodesToTheSamePixels) {
    // A text-like page (long white runs, dark strokes, some noise) in a strided buffer, encoded
    // on 1–8 threads (and more than kMaxPngThreads) and decoded by libpng.
    const int W = 157, H = 701, stride = 160;
    std::vector<std::uint8_t> buf(static_cast<std::size_t>(stride) * H, 7);
    std::uint32_t seed = 99;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            seed = seed * 1664525u + 1013904223u;
            buf[y * stride + x] = (y / 9 + x / 5) % 7 == 0 ? static_cast<std::uint8_t>(seed >> 24)
                                                            : (x * y) % 13 == 0 ? 0 : 255;
        }
    const ConstMaskView view(buf.data(), W, H, stride);
    // Every compression level; Default's bands reach back into the rows of earlier bands (a
    // 32 KiB history is ~200 of these rows, three bands).
    std::vector<std::size_t> banded_size;
    for (PngCompression level :
         {PngCompression::Fast, PngCompression::Default, PngCompression::Small}) {
        const PngOptions options{level};
        auto single = encode_png_gray(view, options);
        ASSERT_TRUE(single);
        for (int threads : {1, 2, 3, 8, 64}) {
            auto png = encode_png_gray(view, threads, options);
            ASSERT_TRUE(png) << png.error().message;
            if (threads > 1 && level != PngCompression::Small) {
                EXPECT_NE(*png, *single) << threads;  // the banded writer ran
            }
            if (threads == 2) banded_size.push_back(png->size());
            const std::string file = temp_file("threads.png");
            std::FILE* f = std::fopen(file.c_str(), "wb");
            ASSERT_NE(f, nullptr);
            std::fwrite(png->data(), 1, png->size(), f);
            std::fclose(f);
            auto back = read_png_gray(file);
            std::remove(file.c_str());
            ASSERT_TRUE(back) << threads << ": " << back.error().message;
            ASSERT_EQ(back->width(), W);
            ASSERT_EQ(back->height(), H);
            int wrong = 0;
            for (int y = 0; y < H; ++y)
                for (int x = 0; x < W; ++x) wrong += back->at(x, y) != buf[y * stride + x];
            EXPECT_EQ(wrong, 0) << threads << " threads, level " << static_cast<int>(level);
        }
    }
    ASSERT_EQ(banded_size.size(), 3u);
    EXPECT_LT(banded_size[1], banded_size[0]) << "Default no smaller than Fast";
    EXPECT_LT(banded_size[2], banded_size[1]) << "Small no smaller than Default";
    // Too few rows to split, and bad masks: the one-thread writer's result and errors.
    const ConstMaskView short_view(buf.data(), W, 100, stride);
    EXPECT_EQ(*encode_png_gray(short_view, 4), *encode_png_gray(short_view));
    EXPECT_FALSE(encode_png_gray(ConstMaskView(buf.data(), 0, H, stride), 4));
}

TEST(EncodePng, StreamOnWorkerThreadsFedWhileThePageIsDrawnEqualsTheBandedFile) {
    // The page is "drawn" band by band while workers deflate what was declared final; rows
    // below the final line are still being written (overwritten from junk), as text drawing
    // does. The bytes equal the banded writer's for the finished page (any thread count).
    const int W = 301, H = 777;
    Mask finished(W, H);
    std::uint32_t seed = 5;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            seed = seed * 1664525u + 1013904223u;
            finished.at(x, y) = (x / 7 + y / 3) % 5 == 0 ? static_cast<std::uint8_t>(seed >> 24)
                                                         : 255;
        }
    auto banded = encode_png_gray(finished.view(), 3);
    ASSERT_TRUE(banded) << banded.error().message;
    EXPECT_EQ(*encode_png_gray(finished.view(), 2), *banded);
    for (int workers : {0, 1, 3}) {
        Mask page(W, H);
        std::fill(page.view().data, page.view().data + W * H, std::uint8_t{77});  // junk
        PngGrayStream stream(page.view(), workers);
        for (int y = 0; y < H; ++y) {
            std::copy(finished.view().row(y), finished.view().row(y) + W, page.view().row(y));
            if (y % 13 == 12) stream.rows_final(y + 1);
            if (y % 50 == 49) stream.rows_final(y / 2);  // going back is ignored
        }
        auto png = stream.finish();
        ASSERT_TRUE(png) << png.error().message;
        EXPECT_EQ(*png, *banded) << workers << " workers";
        auto again = stream.finish();
        EXPECT_FALSE(again);
    }
    // A stream abandoned half way (the page's drawing failed) stops its workers and frees.
    {
        Mask page(W, H);
        PngGrayStream stream(page.view(), 2);
        stream.rows_final(H / 2);
    }
    // Too few rows to band, and a bad page: the one-thread writer's result and errors.
    Mask small(W, 2 * kPngBandRows - 1);
    PngGrayStream small_stream(small.view(), 2);
    small_stream.rows_final(small.height());
    EXPECT_EQ(*small_stream.finish(), *encode_png_gray(small.view()));
    PngGrayStream bad(ConstMaskView(finished.view().data, 0, H, W), 2);
    EXPECT_FALSE(bad.finish());
}

TEST(EncodePng, HeaderNamesTheColourType) {
    Image image = test_pattern(7, 3);
    const std::pair<PngColor, int> cases[] = {
        {PngColor::Gray, 0}, {PngColor::Rgb, 2}, {PngColor::Rgba, 6}};
    for (auto [color, type] : cases) {
        auto png = encode_png(image, color);
        ASSERT_TRUE(png);
        ASSERT_GT(png->size(), 33u);
        EXPECT_EQ(std::string(png->begin() + 1, png->begin() + 4), "PNG");
        EXPECT_EQ((*png)[19], 7);         // IHDR width, low byte
        EXPECT_EQ((*png)[24], 8);         // bit depth
        EXPECT_EQ((*png)[25], type);      // colour type
    }
}

TEST(EncodePng, ErrorsNameTheFile) {
    auto empty = encode_png(Image(0, 3), PngColor::Rgb);
    ASSERT_FALSE(empty);
    EXPECT_NE(empty.error().message.find("0x3"), std::string::npos);
    std::string file = "/nonexistent-dir/bezel/out.png";
    auto st = write_png(file, test_pattern(2, 2));
    ASSERT_FALSE(st);
    EXPECT_EQ(st.error().message.rfind(file + ": ", 0), 0u) << st.error().message;
}

TEST(EncodePnm, HeadersAndBytes) {
    Image image(2, 1);
    image.at(0, 0) = Rgba8{255, 0, 0, 10};
    image.at(1, 0) = Rgba8{1, 2, 3, 255};
    auto ppm = encode_ppm(image);
    EXPECT_EQ(std::string(ppm.begin(), ppm.end()), std::string("P6\n2 1\n255\n\xff\x00\x00\x01\x02\x03", 17));
    auto pgm = encode_pgm(image);
    // Rec. 709 luma: red alone is 0.2126 → 54; (1,2,3) → 2.
    EXPECT_EQ(std::string(pgm.begin(), pgm.end()), std::string("P5\n2 1\n255\n\x36\x02", 13));
    const std::uint8_t m[4] = {9, 8, 7, 6};
    auto mask_pgm = encode_pgm(ConstMaskView(m, 1, 2, 2));
    EXPECT_EQ(std::string(mask_pgm.begin(), mask_pgm.end()), std::string("P5\n1 2\n255\n\x09\x07", 13));
}

TEST(EncodeAnsi, HalfBlocksWithTwentyFourBitColour) {
    Image image(2, 2, kWhite);
    image.at(0, 0) = Rgba8{255, 0, 0, 255};
    image.at(0, 1) = Rgba8{0, 0, 255, 255};
    std::string out = encode_ansi(image);
    EXPECT_NE(out.find("\x1b[38;2;255;0;0m"), std::string::npos);
    EXPECT_NE(out.find("\x1b[48;2;0;0;255m"), std::string::npos);
    // One text line of two cells.
    std::size_t blocks = 0;
    for (std::size_t at = out.find("\xe2\x96\x80"); at != std::string::npos;
         at = out.find("\xe2\x96\x80", at + 1))
        ++blocks;
    EXPECT_EQ(blocks, 2u);
    EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 1);
}

TEST(EncodeAnsi, BoxFilterFitsMaxColumnsInLinearLight) {
    // 8 × 2 of alternating black / white columns, shown in at most 2 columns: factor 4, so one
    // line of two cells whose colour is the linear mean, 188, not the byte mean 128.
    Image image(8, 2, kWhite);
    for (int x = 0; x < 8; x += 2) image.at(x, 0) = image.at(x, 1) = kBlack;
    std::string out = encode_ansi(image, 2);
    EXPECT_NE(out.find("\x1b[38;2;188;188;188m"), std::string::npos) << out;
    std::size_t blocks = 0;
    for (std::size_t at = out.find("\xe2\x96\x80"); at != std::string::npos;
         at = out.find("\xe2\x96\x80", at + 1))
        ++blocks;
    EXPECT_EQ(blocks, 2u);
}

}  // namespace
}  // namespace bezel
