// Text weight against hb-view: the ink of a line rendered by TextRenderer, dark on light and
// light on dark, against hb-view's ink for the same text, font, size and margins, stored with
// its provenance in tests/data/text_weight/hb_view_ink.tsv (tools/bench/text_weight.py
// --reference made it; hb-view need not be installed here).
//
// Ink: the sum of (255 − value) dark on light, of value light on dark. The default rendering
// must stay within kInkTolerance of hb-view's in both polarities; TextRendering::Linear, the
// exact mix, is thin dark on light and heavy light on dark at small sizes, as it always was.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "bezel/text.hpp"

namespace bezel {
namespace {

// The bound: text weight within about 10 % of hb-view's at 8-24 px.
constexpr double kInkTolerance = 0.10;
constexpr double kMarginPx = 16;   // hb-view's margin, as the reference was made

struct Reference {
    std::string font;   // under fonts-test/
    int px = 0;
    bool dark = true;   // dark on light
    long long ink = 0;
};

struct References {
    std::string text;
    std::vector<Reference> rows;
};

References read_references() {
    References refs;
    std::ifstream in(BEZEL_SOURCE_DIR "/tests/data/text_weight/hb_view_ink.tsv");
    EXPECT_TRUE(in) << "tests/data/text_weight/hb_view_ink.tsv is missing";
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream fields(line);
        std::string first;
        std::getline(fields, first, '\t');
        if (first == "text") {
            std::getline(fields, refs.text);
            continue;
        }
        Reference r;
        r.font = first;
        std::string polarity;
        long long peak = 0;
        fields >> r.px >> polarity >> r.ink >> peak;
        EXPECT_TRUE(fields && (polarity == "dark" || polarity == "light")) << line;
        r.dark = polarity == "dark";
        refs.rows.push_back(r);
    }
    EXPECT_FALSE(refs.text.empty());
    return refs;
}

// The ink of `text` rendered as `bezel render FONT --text TEXT --font-size PX --margin 16`
// with the colours of the polarity.
long long ink_of(TextRenderer& renderer, const std::string& text, int px, bool dark,
                 TextRendering rendering) {
    TextRenderOptions o;
    o.shape.size_px = px;
    o.layout.margin_px = kMarginPx;
    o.foreground = dark ? Rgba8{0, 0, 0, 255} : Rgba8{255, 255, 255, 255};
    o.background = dark ? Rgba8{255, 255, 255, 255} : Rgba8{0, 0, 0, 255};
    o.coverage.rendering = rendering;
    auto page = renderer.render_gray(text, o);
    EXPECT_TRUE(page) << page.error().message;
    if (!page) return 0;
    long long ink = 0;
    for (std::uint8_t v : page->pixels()) ink += dark ? 255 - v : v;
    return ink;
}

TEST(TextWeight, DefaultRenderingIsWithinTenPercentOfHbViewInBothPolarities) {
    const References refs = read_references();
    std::map<std::string, TextRenderer> renderers;
    int checked = 0;
    for (const Reference& r : refs.rows) {
        if (r.px != 8 && r.px != 12 && r.px != 16 && r.px != 24) continue;
        if (renderers.count(r.font) == 0) {
            auto opened = TextRenderer::open(std::string(BEZEL_FONTS_DIR) + "/" + r.font);
            ASSERT_TRUE(opened) << opened.error().message;
            renderers.emplace(r.font, std::move(*opened));
        }
        const long long ink = ink_of(renderers.at(r.font), refs.text, r.px, r.dark,
                                     CoverageCurveOptions().rendering);
        const double ratio = static_cast<double>(ink) / static_cast<double>(r.ink);
        EXPECT_NEAR(ratio, 1.0, kInkTolerance)
            << r.font << " " << r.px << " px " << (r.dark ? "dark" : "light") << " on "
            << (r.dark ? "light" : "dark") << ": ink " << ink << ", hb-view " << r.ink;
        ++checked;
    }
    EXPECT_EQ(checked, 16);   // two fonts, four sizes, two polarities
}

TEST(TextWeight, LinearRenderingIsThinDarkOnLightAndHeavyLightOnDarkAtSmallSizes) {
    const References refs = read_references();
    auto renderer = TextRenderer::open(BEZEL_FONTS_DIR "/dejavu-sans/DejaVuSans.ttf");
    ASSERT_TRUE(renderer) << renderer.error().message;
    for (const Reference& r : refs.rows) {
        if (r.font != "dejavu-sans/DejaVuSans.ttf" || r.px != 8) continue;
        const double ratio =
            static_cast<double>(ink_of(*renderer, refs.text, r.px, r.dark, TextRendering::Linear)) /
            static_cast<double>(r.ink);
        // The measurement: 54-57 % of hb-view's ink dark on light, 138-154 % light on dark.
        if (r.dark) {
            EXPECT_LT(ratio, 0.65);
        } else {
            EXPECT_GT(ratio, 1.35);
        }
    }
}

}  // namespace
}  // namespace bezel
