// `bezel glyph` end to end: the JSON contract, boxes against FreeType's own FT_Render_Glyph,
// pixels against FreeType's within its flattening error, the accurate overlap mode chosen for
// marked glyphs, LCD layout, ASCII, the picture formats (goldens) and errors.
//
// Goldens live in tests/golden/glyph/; regenerate with BEZEL_UPDATE_GOLDEN=1 after a deliberate
// change (and say why in the commit).
#include <gtest/gtest.h>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <cmath>
#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "bezel/freetype_reference.hpp"
#include "bezel/font.hpp"
#include "bezel/image.hpp"
#include "support/cli_run.hpp"
#include "support/golden.hpp"

namespace {

using bezel::test::CliRun;
using nlohmann::json;

const std::string kDejaVu = std::string(BEZEL_FONTS_DIR) + "/dejavu-sans/DejaVuSans.ttf";
const std::string kCantarell = std::string(BEZEL_FONTS_DIR) + "/cantarell/Cantarell-Regular.otf";
const std::string kEdge = std::string(BEZEL_FONTS_DIR) + "/edge-cases/EdgeCases.ttf";
const std::string kAscii =
    "!\"#$%&()*+,-./0123456789:;<=>?@ABCDEFGHIJKLMNOPQRSTUVWXYZ[\\]^_`abcdefghijklmnopqrstuvwxyz{|}~";

bezel::test::TempDir& scratch() {
    static bezel::test::TempDir dir("bezel-glyph-cli");
    return dir;
}
CliRun run(const std::vector<std::string>& args) {
    std::vector<std::string> a{"glyph"};
    a.insert(a.end(), args.begin(), args.end());
    return bezel::test::run_bezel(a, scratch().path());
}
json run_json(const std::vector<std::string>& args) {
    std::vector<std::string> a = args;
    a.push_back("-O");
    a.push_back("json");
    CliRun r = run(a);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return r.exit_code == 0 ? json::parse(r.out) : json::array();
}

int hex_byte(const std::string& row, std::size_t i) {
    return std::stoi(row.substr(2 * i, 2), nullptr, 16);
}

// FreeType's own render of a glyph: unhinted at `size`, pen at (dx, dy) (y down), gray or LCD.
struct FtBitmap {
    int left = 0, top = 0, width = 0, rows = 0, pitch = 0;
    std::vector<unsigned char> px;
};
class FreeType {
public:
    explicit FreeType(const std::string& file) {
        EXPECT_EQ(FT_Init_FreeType(&lib_), 0);
        EXPECT_EQ(FT_New_Face(lib_, file.c_str(), 0, &face_), 0);
    }
    ~FreeType() {
        FT_Done_Face(face_);
        FT_Done_FreeType(lib_);
    }
    FtBitmap render(unsigned gid, double size, double dx, double dy) {
        FtBitmap b;
        EXPECT_EQ(FT_Set_Char_Size(face_, 0, std::lround(size * 64), 72, 72), 0);
        EXPECT_EQ(FT_Load_Glyph(face_, gid, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP), 0);
        FT_Outline_Translate(&face_->glyph->outline, std::lround(dx * 64), std::lround(-dy * 64));
        EXPECT_EQ(FT_Render_Glyph(face_->glyph, FT_RENDER_MODE_NORMAL), 0);
        const FT_Bitmap& bm = face_->glyph->bitmap;
        b.left = face_->glyph->bitmap_left;
        b.top = face_->glyph->bitmap_top;
        b.width = static_cast<int>(bm.width);
        b.rows = static_cast<int>(bm.rows);
        b.pitch = bm.pitch;
        if (bm.buffer) b.px.assign(bm.buffer, bm.buffer + std::size_t(bm.rows) * std::abs(bm.pitch));
        return b;
    }

private:
    FT_Library lib_ = nullptr;
    FT_Face face_ = nullptr;
};

class GlyphCli : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(std::filesystem::exists(bezel::test::cli_path())) << bezel::test::cli_path();
    }
};

}  // namespace

TEST_F(GlyphCli, JsonIsTheContract) {
    json doc = run_json({kDejaVu, "--text", "Ag ", "--font-size", "24"});
    ASSERT_TRUE(doc.is_array());
    ASSERT_EQ(doc.size(), 3u);
    const json& a = doc[0];
    for (const char* key : {"gid", "char", "size", "left", "top", "width", "height", "advance",
                            "rows", "mode"})
        EXPECT_TRUE(a.contains(key)) << key;
    EXPECT_EQ(a["char"], "A");
    EXPECT_EQ(a["code_point"], "U+0041");
    EXPECT_EQ(a["size"], 24.0);
    EXPECT_EQ(a["mode"], "gray");
    EXPECT_EQ(a["rows"].size(), a["height"].get<std::size_t>());
    for (const json& row : a["rows"]) {
        const std::string s = row.get<std::string>();
        ASSERT_EQ(s.size(), 2 * a["width"].get<std::size_t>());
        EXPECT_EQ(s.find_first_not_of("0123456789abcdef"), std::string::npos);
    }
    // DejaVu Sans 'A' advance: 1401 units of 2048 at 24 px.
    EXPECT_NEAR(a["advance"].get<double>(), 1401.0 * 24 / 2048, 1e-9);
    // 'g' descends: its box reaches below the baseline.
    EXPECT_LT(doc[1]["top"].get<int>() - doc[1]["height"].get<int>(), 0);
    // The space is an empty bitmap.
    EXPECT_EQ(doc[2]["width"], 0);
    EXPECT_EQ(doc[2]["rows"].size(), 0u);
}

// fonts-test/bitmap-strike: 'A' has a 16 ppem 1-bit strike, an 8x10 checkerboard (pixel (x, y)
// inked when x + y is odd), while its outline is a solid rectangle.
TEST_F(GlyphCli, EmbeddedBitmapsDrawTheStrikeOfTheExactSize) {
    const std::string font = std::string(BEZEL_FONTS_DIR) + "/bitmap-strike/BitmapStrike.ttf";
    json strike = run_json({font, "--char", "A", "--font-size", "16", "--embedded-bitmaps"});
    ASSERT_EQ(strike.size(), 1u);
    const json& a = strike[0];
    EXPECT_EQ(a["left"], 1);
    EXPECT_EQ(a["top"], 10);
    EXPECT_EQ(a["advance"], 11.0);
    ASSERT_EQ(a["rows"].size(), 10u);
    for (int y = 0; y < 10; ++y) {
        const std::string row = a["rows"][y].get<std::string>();
        ASSERT_EQ(row.size(), 16u);
        for (int x = 0; x < 8; ++x)
            EXPECT_EQ(hex_byte(row, x), (x + y) % 2 ? 255 : 0) << x << "," << y;
    }
    // Without the flag, and at a size with no strike: the outline, solid inside.
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{font, "--char", "A", "--font-size", "16"},
          std::vector<std::string>{font, "--char", "A", "--font-size", "17", "--embedded-bitmaps"}}) {
        json outline = run_json(args);
        ASSERT_EQ(outline.size(), 1u);
        const std::string middle = outline[0]["rows"][5].get<std::string>();
        EXPECT_EQ(hex_byte(middle, 3), 255);
        EXPECT_EQ(hex_byte(middle, 4), 255);
    }
}

TEST_F(GlyphCli, BoxesAreFreeTypesBitmapBoxes) {
    // left/top/width/height equal FT_Render_Glyph's bitmap_left/bitmap_top/width/rows, for all
    // of printable ASCII in a TrueType and a CFF font, at several sizes and pen offsets.
    int compared = 0;
    for (const std::string& file : {kDejaVu, kCantarell}) {
        FreeType ft(file);
        for (double size : {9.0, 17.0, 100.0})
            for (auto [dx, dy] : {std::pair{0.0, 0.0}, std::pair{-2.7, 1.125}}) {
                char offset[64];
                std::snprintf(offset, sizeof offset, "%g,%g", dx, dy);
                json doc = run_json({file, "--text", kAscii, "--font-size", std::to_string(size),
                                     "--offset", offset});
                ASSERT_EQ(doc.size(), kAscii.size());
                for (const json& g : doc) {
                    const FtBitmap b = ft.render(g["gid"].get<unsigned>(), size, dx, dy);
                    const std::string where = file + " " + g["char"].get<std::string>() + " at " +
                                              std::to_string(size) + " offset " + offset;
                    EXPECT_EQ(g["left"].get<int>(), b.left) << where;
                    EXPECT_EQ(g["top"].get<int>(), b.top) << where;
                    EXPECT_EQ(g["width"].get<int>(), b.width) << where;
                    EXPECT_EQ(g["height"].get<int>(), b.rows) << where;
                    ++compared;
                }
            }
    }
    EXPECT_EQ(compared, 2 * 3 * 2 * int(kAscii.size()));
}

TEST_F(GlyphCli, PixelsAgreeWithFreeTypeWithinItsFlatteningError) {
    // FreeType flattens coarser (up to ~0.1 px on conics) and rounds points to 1/64 px; bezel is
    // exact to 0.01 px. Against the 16x16 reference FreeType's own error is ~1.7/255 mean and up
    // to ~55/255 in its worst pixel (docs/rasterizer.md), so that is the agreement to expect; a glyph off by
    // a pixel would differ by tens of levels on average.
    FreeType ft(kDejaVu);
    json doc = run_json({kDejaVu, "--text", "Rg@&8", "--font-size", "20", "--offset", "0.4,0.2"});
    double sum = 0;
    int n = 0, worst = 0;
    for (const json& g : doc) {
        const FtBitmap b = ft.render(g["gid"].get<unsigned>(), 20, 0.4, 0.2);
        ASSERT_EQ(g["width"].get<int>(), b.width);
        for (int y = 0; y < b.rows; ++y) {
            const std::string row = g["rows"][y].get<std::string>();
            for (int x = 0; x < b.width; ++x) {
                const int d = std::abs(hex_byte(row, x) - b.px[std::size_t(y) * b.pitch + x]);
                sum += d;
                worst = std::max(worst, d);
                ++n;
            }
        }
    }
    ASSERT_GT(n, 500);
    EXPECT_LT(sum / n, 3.0);
    EXPECT_LT(worst, 64);
}

TEST_F(GlyphCli, OverlappingGlyphUsesTheAccurateMode) {
    // EdgeCases 'O': squares (100,100)–(500,500) and (300,300)–(700,700) in 1000 units/em. At
    // 25 px with the pen at (0.3, 0.3) the crossing pixels are partial in both squares; each
    // pixel must be the exact area of the union.
    json doc = run_json({kEdge, "--char", "O", "--font-size", "25", "--offset", "0.3,0.3"});
    ASSERT_EQ(doc.size(), 1u);
    const json& g = doc[0];
    EXPECT_EQ(g["overlap"], "accurate");
    const double k = 0.025;
    auto cov = [&](double ax0, double ay0, double ax1, double ay1, int x, int y) {
        // Pixel (x, y) of the bitmap is [left + x, +1] × [−top + y, +1] in pen coordinates.
        const double px = g["left"].get<int>() + x, py = -g["top"].get<int>() + y;
        const double w = std::max(0.0, std::min(ax1, px + 1) - std::max(ax0, px));
        const double h = std::max(0.0, std::min(ay1, py + 1) - std::max(ay0, py));
        return w * h;
    };
    for (int y = 0; y < g["height"].get<int>(); ++y) {
        const std::string row = g["rows"][y].get<std::string>();
        for (int x = 0; x < g["width"].get<int>(); ++x) {
            // Squares in pen coordinates, y down, moved by the offset.
            const double a = cov(100 * k + .3, -500 * k + .3, 500 * k + .3, -100 * k + .3, x, y);
            const double b = cov(300 * k + .3, -700 * k + .3, 700 * k + .3, -300 * k + .3, x, y);
            const double ab = cov(300 * k + .3, -500 * k + .3, 500 * k + .3, -300 * k + .3, x, y);
            EXPECT_NEAR(hex_byte(row, x), 255 * (a + b - ab), 0.5 + 1e-6) << x << "," << y;
        }
    }
}

TEST_F(GlyphCli, OverlapAccurateResolvesUnmarkedOverlappingComponents) {
    // DejaVu Sans marks no glyph as overlapping, yet U+1EC7 (e with circumflex and dot below) has
    // components whose edges overlap: plain accumulation over-darkens them, --overlap accurate
    // does not. Elsewhere the two modes agree within rounding.
    json plain = run_json({kDejaVu, "--text", "\u1EC7e", "--font-size", "12", "--offset", "0.3,0.3"});
    json acc = run_json({kDejaVu, "--text", "\u1EC7e", "--font-size", "12", "--offset", "0.3,0.3",
                         "--overlap", "accurate"});
    ASSERT_EQ(plain.size(), 2u);
    EXPECT_EQ(plain[0]["overlap"], "accumulate");
    EXPECT_EQ(acc[0]["overlap"], "accurate");
    int darker[2] = {0, 0}, worst[2] = {0, 0};
    for (int i = 0; i < 2; ++i)
        for (std::size_t y = 0; y < plain[i]["rows"].size(); ++y) {
            const std::string p = plain[i]["rows"][y], a = acc[i]["rows"][y];
            for (std::size_t x = 0; x < p.size() / 2; ++x) {
                const int d = hex_byte(p, x) - hex_byte(a, x);
                darker[i] += d > 1;
                worst[i] = std::max(worst[i], std::abs(d));
            }
        }
    EXPECT_GT(worst[0], 60);   // the overlap, over-darkened by plain accumulation
    EXPECT_GT(darker[0], 0);
    EXPECT_LE(worst[1], 1);    // plain 'e': no overlap
}

TEST_F(GlyphCli, LcdRowsHoldTheSubpixelsLeftToRightInThePanelsOrder) {
    // The bytes are positions on the screen, the same for either panel; the mode names their
    // colours, and the PPM shows each in its colour: bgr's picture is rgb's with R and B swapped.
    json gray = run_json({kDejaVu, "--char", "e", "--font-size", "16"});
    json rgb = run_json({kDejaVu, "--char", "e", "--font-size", "16", "--lcd", "rgb"});
    json bgr = run_json({kDejaVu, "--char", "e", "--font-size", "16", "--lcd", "bgr"});
    ASSERT_EQ(rgb.size(), 1u);
    EXPECT_EQ(rgb[0]["mode"], "lcd-rgb");
    EXPECT_EQ(bgr[0]["mode"], "lcd-bgr");
    EXPECT_EQ(rgb[0]["width"].get<int>(), gray[0]["width"].get<int>() + 2);
    EXPECT_EQ(rgb[0]["left"].get<int>(), gray[0]["left"].get<int>() - 1);
    EXPECT_EQ(rgb[0]["top"], gray[0]["top"]);
    const int w = rgb[0]["width"].get<int>(), h = rgb[0]["height"].get<int>();
    int colourful = 0;
    for (int y = 0; y < h; ++y) {
        const std::string r = rgb[0]["rows"][y];
        ASSERT_EQ(r.size(), std::size_t(6 * w));
        EXPECT_EQ(bgr[0]["rows"][y], r);
        for (int x = 0; x < w; ++x) colourful += hex_byte(r, 3 * x) != hex_byte(r, 3 * x + 2);
    }
    EXPECT_GT(colourful, 4);   // so a swap would show
    const std::string rgb_ppm = (scratch().path() / "e-rgb.ppm").string();
    const std::string bgr_ppm = (scratch().path() / "e-bgr.ppm").string();
    for (const auto& [order, file] : {std::pair{"rgb", rgb_ppm}, std::pair{"bgr", bgr_ppm}}) {
        CliRun r = run({kDejaVu, "--char", "e", "--font-size", "16", "--lcd", order, "--coverage",
                        "-o", file});
        ASSERT_EQ(r.exit_code, 0) << r.err;
    }
    const std::string a = bezel::test::slurp(rgb_ppm), b = bezel::test::slurp(bgr_ppm);
    const std::string header = "P6\n" + std::to_string(w) + " " + std::to_string(h) + "\n255\n";
    ASSERT_EQ(a.substr(0, header.size()), header);
    ASSERT_EQ(a.size(), header.size() + std::size_t(3 * w * h));
    ASSERT_EQ(b.size(), a.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t at = header.size() + std::size_t(3 * (y * w + x));
            for (int c = 0; c < 3; ++c) {
                EXPECT_EQ(static_cast<unsigned char>(a[at + c]),
                          hex_byte(rgb[0]["rows"][y], 3 * x + c));
                EXPECT_EQ(b[at + c], a[at + 2 - c]);
            }
        }
}

TEST_F(GlyphCli, AsciiArtHasAHeaderAndOneCharacterPerPixel) {
    CliRun r = run({kDejaVu, "--char", "o", "--font-size", "14"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    json doc = run_json({kDejaVu, "--char", "o", "--font-size", "14"});
    const int w = doc[0]["width"], h = doc[0]["height"];
    std::istringstream in(r.out);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line.rfind("glyph " + std::to_string(doc[0]["gid"].get<int>()) + " o 'o' U+006F", 0), 0u)
        << line;
    EXPECT_NE(line.find(std::to_string(w) + "x" + std::to_string(h)), std::string::npos) << line;
    int rows = 0;
    while (std::getline(in, line)) {
        ASSERT_EQ(line[0], '|');
        EXPECT_LE(int(line.size()) - 1, w);
        EXPECT_EQ(line.find_first_not_of("| .:-=+*#%@"), std::string::npos);
        ++rows;
    }
    EXPECT_EQ(rows, h);
    EXPECT_NE(r.out.find('@'), std::string::npos);  // the interior of the stroke is fully covered
}

TEST_F(GlyphCli, PicturesMatchGoldens) {
    // Tolerance: 1/255 per pixel (rounding differences between sweep kernels).
    const std::string dir = std::string(BEZEL_GOLDEN_DIR) + "/glyph/";
    const bool update = bezel::test::update_golden();
    struct Case {
        std::string name;
        std::vector<std::string> args;
    };
    const Case cases[] = {
        {"hamburg_24.png", {kDejaVu, "--text", "Hamburg", "--font-size", "24"}},
        {"cantarell_ag_40.png", {kCantarell, "--text", "&Qg", "--font-size", "40", "--offset", "0.5,0.25"}},
        {"hamburg_lcd_16.png", {kDejaVu, "--text", "Hamburg", "--font-size", "16", "--lcd", "rgb"}},
    };
    for (const Case& c : cases) {
        const std::string out = (scratch().path() / c.name).string();
        std::vector<std::string> args = c.args;
        args.push_back("-o");
        args.push_back(out);
        CliRun r = run(args);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        if (update) {
            bezel::test::replace_golden(out, dir + c.name);
            continue;
        }
        auto got = bezel::read_png_gray(out);
        auto want = bezel::read_png_gray(dir + c.name);
        ASSERT_TRUE(got.ok()) << got.error().message;
        ASSERT_TRUE(want.ok()) << want.error().message;
        ASSERT_EQ(got->width(), want->width()) << c.name;
        ASSERT_EQ(got->height(), want->height()) << c.name;
        int worst = 0;
        for (int y = 0; y < got->height(); ++y)
            for (int x = 0; x < got->width(); ++x)
                worst = std::max(worst, std::abs(got->at(x, y) - want->at(x, y)));
        EXPECT_LE(worst, 1) << c.name;
    }
}

TEST_F(GlyphCli, PgmHoldsTheSamePixelsAsJson) {
    // --coverage: the JSON's bytes; the picture (default): black ink on white paper, the same
    // coverage inverted byte for byte.
    const std::string pgm = (scratch().path() / "k.pgm").string();
    const std::string picture = (scratch().path() / "k-picture.pgm").string();
    CliRun r = run({kDejaVu, "--char", "k", "--font-size", "13", "--coverage", "-o", pgm});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    r = run({kDejaVu, "--char", "k", "--font-size", "13", "-o", picture});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    json doc = run_json({kDejaVu, "--char", "k", "--font-size", "13"});
    const std::string bytes = bezel::test::slurp(pgm), ink = bezel::test::slurp(picture);
    const int w = doc[0]["width"], h = doc[0]["height"];
    const std::string header = "P5\n" + std::to_string(w) + " " + std::to_string(h) + "\n255\n";
    ASSERT_EQ(bytes.substr(0, header.size()), header);
    ASSERT_EQ(bytes.size(), header.size() + std::size_t(w * h));
    ASSERT_EQ(ink.size(), bytes.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t at = header.size() + std::size_t(y * w + x);
            EXPECT_EQ(static_cast<unsigned char>(bytes[at]), hex_byte(doc[0]["rows"][y], x));
            EXPECT_EQ(static_cast<unsigned char>(ink[at]), 255 - hex_byte(doc[0]["rows"][y], x));
        }
}

TEST_F(GlyphCli, ErrorsNameTheirInput) {
    struct Case {
        std::vector<std::string> args;
        int code;
        std::string says;
    };
    const Case cases[] = {
        {{kDejaVu, "--font-size", "12"}, 2, ""},                                 // no glyph chosen
        {{kDejaVu, "--char", "a", "--gid", "3"}, 2, ""},                          // two chosen
        {{kDejaVu, "--char", "a", "--offset", "1"}, 2, "--offset"},
        {{kDejaVu, "--char", "a", "--offset", "nan,0"}, 2, "--offset"},
        {{kDejaVu, "--char", "a", "--offset", "1e9,0"}, 2, "beyond ±16384 px"},
        {{kDejaVu, "--char", "a", "--tolerance", "0"}, 2, "--tolerance"},
        {{kDejaVu, "--char", "a", "--lcd", "rbg"}, 2, "--lcd"},
        {{kDejaVu, "--char", "a", "-o", "a.bmp"}, 2, "a.bmp"},
        {{kDejaVu, "--gid", "999999"}, 1, "--gid 999999"},
        {{kDejaVu, "--char", "U+10FFFF", "--strict"}, 1, "U+10FFFF"},
        {{"no-such-font.ttf", "--char", "a"}, 1, "no-such-font.ttf"},
        {{kDejaVu, "--char", "a", "--font-size", "0"}, 2, "--font-size: '0'"},
        {{kDejaVu, "--text", std::string(600, 'W'), "--font-size", "300"}, 1,
         "more than 16777216 pixels, the most one call renders"},
        {{kDejaVu, "--char", " ", "-O", "png"}, 1, "empty"},
        {{kDejaVu, "--char", "a", "-o", "no/such/dir/a.png"}, 1, "no/such/dir/a.png"},
    };
    for (const Case& c : cases) {
        CliRun r = run(c.args);
        EXPECT_EQ(r.exit_code, c.code) << c.args.back() << ": " << r.err;
        EXPECT_EQ(r.err.rfind("bezel: ", 0), 0u) << r.err;
        EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
        EXPECT_TRUE(r.out.empty());
    }
    EXPECT_FALSE(std::filesystem::exists(scratch().path() / "a.bmp"));
}

// render_with_freetype (bezel/freetype_reference.hpp: what `bezel bench` times for FreeType) is
// FreeType's own render: the same pixels as FT_Render_Glyph in FreeType's box, for any stride.
TEST(RenderWithFreeType, EqualsFtRenderGlyphForAnyStride) {
    auto font = bezel::Font::open(kDejaVu);
    ASSERT_TRUE(font.ok());
    FreeType ft(kDejaVu);
    for (char32_t ch : std::u32string(U"Ag@\u00e9")) {
        const bezel::GlyphId gid = *font->glyph_for_char(ch);
        for (double size : {11.0, 30.0}) {
            const FtBitmap b = ft.render(gid, size, 0.25, 0);
            ASSERT_GT(b.width * b.rows, 0);
            // Pen at (0.25 − left, top) from the bitmap's top-left corner, y down.
            const bezel::Vec2 pen{0.25 - b.left, double(b.top)};
            const int stride = b.width + 5;
            std::vector<std::uint8_t> down(std::size_t(stride) * b.rows, 77);
            ASSERT_TRUE(render_with_freetype(*font, gid, {size},
                                                   bezel::MaskView{down.data(), b.width, b.rows, stride},
                                                   pen)
                            .ok());
            // Bottom-up memory: row 0 at the end, negative stride.
            std::vector<std::uint8_t> up(std::size_t(b.width) * b.rows, 77);
            const bezel::MaskView up_view{up.data() + std::size_t(b.rows - 1) * b.width, b.width,
                                          b.rows, -b.width};
            ASSERT_TRUE(render_with_freetype(*font, gid, {size}, up_view, pen).ok());
            for (int y = 0; y < b.rows; ++y) {
                for (int x = 0; x < b.width; ++x) {
                    const int want = b.px[std::size_t(y) * b.pitch + x];
                    ASSERT_EQ(down[std::size_t(y) * stride + x], want) << x << "," << y;
                    ASSERT_EQ(up_view.at(x, y), want) << x << "," << y;
                }
                EXPECT_EQ(down[std::size_t(y) * stride + b.width], 77);  // past the width: untouched
            }
        }
    }
}

TEST(RenderWithFreeType, FollowsVariationsAndRejectsBadInput) {
    // EdgeCasesVariable 'I': a bar whose right edge moves with wght, so the cached outline must
    // not survive set_variations.
    auto font = bezel::Font::open(std::string(BEZEL_FONTS_DIR) + "/edge-cases/EdgeCasesVariable.ttf");
    ASSERT_TRUE(font.ok());
    const bezel::GlyphId gid = *font->glyph_for_char('I');
    bezel::Mask regular(40, 40), black(40, 40);
    ASSERT_TRUE(render_with_freetype(*font, gid, {40}, regular.view(), {0, 35}).ok());
    ASSERT_TRUE(font->set_variations({{"wght", 900}}).ok());
    ASSERT_TRUE(render_with_freetype(*font, gid, {40}, black.view(), {0, 35}).ok());
    // The bar spans x 4..12 px at wght 400 and 4..20 at 900.
    EXPECT_EQ(regular.at(15, 20), 0);
    EXPECT_EQ(black.at(15, 20), 255);
    bezel::Mask m(8, 8);
    EXPECT_FALSE(render_with_freetype(*font, 99, {12}, m.view(), {0, 0}).ok());
    EXPECT_FALSE(render_with_freetype(*font, gid, {0}, m.view(), {0, 0}).ok());
    EXPECT_FALSE(render_with_freetype(*font, gid, {12}, m.view(), {NAN, 0}).ok());
    EXPECT_FALSE(render_with_freetype(*font, gid, {12}, bezel::MaskView{nullptr, 8, 8, 8},
                                            {0, 0})
                     .ok());
    EXPECT_FALSE(render_with_freetype(*font, gid, {12}, bezel::MaskView{m.view().data, 8, 8, 4},
                                            {0, 0})
                     .ok());
}
