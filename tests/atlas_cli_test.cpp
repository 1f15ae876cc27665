// `bezel atlas` end to end: no two texture rectangles overlap or touch (1 px padding), each
// rectangle holds exactly GlyphRasterizer's render of its glyph, the JSON reads back, and bad
// input is refused without leaving files.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bezel/text.hpp"
#include "support/cli_run.hpp"

namespace bezel {
namespace {

using test::run_bezel;
using test::slurp;
using test::TempDir;

const std::string kDejaVu = BEZEL_FONTS_DIR "/dejavu-sans/DejaVuSans.ttf";

// Hinted or not, as --hinting says.
void expect_padded_rectangles_holding_the_glyphs(Hinting hinting) {
    TempDir dir("bezel-atlas-cli");
    const std::string chars = "The quick brown fox, AVWQ@&g 0123456789 éß";
    auto run = run_bezel({"atlas", kDejaVu, "--chars", chars, "--font-size", "19", "-o",
                          "atlas.png", "--json", "atlas.json", "--hinting", hinting_name(hinting)},
                         dir.path());
    ASSERT_EQ(run.exit_code, 0) << run.err;
    auto texture = read_png_gray((dir.path() / "atlas.png").string());
    ASSERT_TRUE(texture) << texture.error().message;
    auto doc = nlohmann::json::parse(slurp(dir.path() / "atlas.json"));
    EXPECT_EQ(doc["hinting"], hinting_name(hinting));
    ASSERT_EQ(doc["width"].get<int>(), texture->width());
    ASSERT_EQ(doc["height"].get<int>(), texture->height());
    const int w = texture->width();
    EXPECT_EQ(w & (w - 1), 0) << "power-of-two width";

    auto font = Font::open(kDejaVu);
    ASSERT_TRUE(font);
    GlyphRasterizer rasterizer(*font);
    GlyphRenderOptions o;
    o.size_px = 19;
    o.hinting = hinting;
    // Which rectangle (grown by the padding) claims each texture pixel.
    std::vector<int> owner(static_cast<std::size_t>(w * texture->height()), -1);
    auto code_points = decode_utf8(chars);
    ASSERT_TRUE(code_points);
    std::u32string distinct;
    for (char32_t c : *code_points)
        if (distinct.find(c) == std::u32string::npos) distinct.push_back(c);
    const auto& glyphs = doc["glyphs"];
    ASSERT_EQ(glyphs.size(), distinct.size());
    for (std::size_t i = 0; i < glyphs.size(); ++i) {
        const auto& g = glyphs[i];
        auto cp = decode_utf8(g["char"].get<std::string>());
        ASSERT_TRUE(cp);
        EXPECT_EQ((*cp)[0], distinct[i]);
        GlyphId gid = g["gid"];
        EXPECT_EQ(gid, *font->glyph_for_char(distinct[i]));
        int x = g["x"], y = g["y"], gw = g["width"], gh = g["height"];
        auto box = rasterizer.measure(gid, o);
        ASSERT_TRUE(box);
        EXPECT_EQ(g["left"].get<int>(), box->left);
        EXPECT_EQ(g["top"].get<int>(), box->top);
        EXPECT_EQ(g["advance"].get<double>(), box->advance_px);
        ASSERT_EQ(gw, box->width);
        ASSERT_EQ(gh, box->height);
        if (gw == 0) continue;
        // Inside the texture with the padding ring, and the ring is claimed by no one else.
        ASSERT_GE(x, 1);
        ASSERT_GE(y, 1);
        ASSERT_LE(x + gw + 1, texture->width());
        ASSERT_LE(y + gh + 1, texture->height());
        for (int py = y - 1; py < y + gh + 1; ++py)
            for (int px = x - 1; px < x + gw + 1; ++px) {
                int& o_ = owner[static_cast<std::size_t>(py * w + px)];
                bool ring = px < x || py < y || px >= x + gw || py >= y + gh;
                if (ring) {
                    EXPECT_EQ(texture->at(px, py), 0) << "padding of " << g["char"];
                } else {
                    EXPECT_EQ(o_, -1) << g["char"] << " overlaps glyph " << o_;
                    o_ = static_cast<int>(i);
                }
            }
        Mask expected(gw, gh);
        ASSERT_TRUE(rasterizer.render(gid, o, expected.view()));
        for (int py = 0; py < gh; ++py)
            for (int px = 0; px < gw; ++px)
                ASSERT_EQ(texture->at(x + px, y + py), expected.at(px, py)) << g["char"];
    }
}

TEST(AtlasCli, RectanglesArePaddedAndHoldTheGlyphs) {
    expect_padded_rectangles_holding_the_glyphs(Hinting::None);
}

TEST(AtlasCli, HintedRectanglesHoldTheHintedGlyphs) {
    expect_padded_rectangles_holding_the_glyphs(Hinting::Full);
    expect_padded_rectangles_holding_the_glyphs(Hinting::Light);
}

TEST(AtlasCli, BadInputGivesOneErrorLineAndNoFile) {
    TempDir dir("bezel-atlas-cli");
    const std::vector<std::pair<std::vector<std::string>, int>> cases = {
        {{"atlas", "/nonexistent.ttf", "--chars", "ab", "-o", "a.png", "--json", "a.json"}, 1},
        {{"atlas", kDejaVu, "--chars", "", "-o", "a.png", "--json", "a.json"}, 2},
        {{"atlas", kDejaVu, "--chars", "a\xff", "-o", "a.png", "--json", "a.json"}, 2},
        {{"atlas", kDejaVu, "--chars", "ab", "--font-size", "0", "-o", "a.png", "--json", "a.json"}, 2},
        {{"atlas", kDejaVu, "--chars", "\xe4\xb8\xad", "--strict", "-o", "a.png", "--json", "a.json"}, 1},
        {{"atlas", kDejaVu, "--chars", "ab", "--json", "a.json"}, 2},
    };
    for (const auto& [args, code] : cases) {
        auto run = run_bezel(args, dir.path());
        EXPECT_EQ(run.exit_code, code) << args[3] << "\n" << run.err;
        EXPECT_EQ(run.err.rfind("bezel: ", 0), 0u) << run.err;
        EXPECT_TRUE(dir.entries().empty()) << args[3];
    }
}

}  // namespace
}  // namespace bezel
