// `bezel render` end to end: the default sample to PNG, formats from the file name, the same
// pixels as the library, PNG colour types, and bad input (one error line, exit 1 or 2, no file).
#include <algorithm>

#include <gtest/gtest.h>

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

TEST(RenderCli, DefaultsRenderTheSampleParagraphToPng) {
    TempDir dir("bezel-render-cli");
    auto run = run_bezel({"render", "-o", "hello.png"}, dir.path());
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.out, "");
    auto png = read_png_gray((dir.path() / "hello.png").string());
    ASSERT_TRUE(png) << png.error().message;
    // Three lines of 20 px text with 16 px margins.
    EXPECT_GT(png->width(), 300);
    EXPECT_GT(png->height(), 3 * 20);
    int dark = 0;
    for (std::uint8_t v : png->pixels()) dark += v < 64;
    EXPECT_GT(dark, 500);
    std::string bytes = slurp(dir.path() / "hello.png");
    EXPECT_EQ(bytes[25], 0) << "black on white is written as gray PNG";
}

TEST(RenderCli, PixelsEqualTheLibrarysAndFormatFollowsTheFileName) {
    TempDir dir("bezel-render-cli");
    auto run = run_bezel({"render", kDejaVu, "Kerning AV", "--font-size", "24", "--margin", "3",
                          "--foreground", "#203040", "-o", "line.ppm"},
                         dir.path());
    ASSERT_EQ(run.exit_code, 0) << run.err;
    auto renderer = TextRenderer::open(kDejaVu);
    ASSERT_TRUE(renderer);
    TextRenderOptions o;
    o.shape.size_px = 24;
    o.layout.margin_px = 3;
    o.foreground = Rgba8{0x20, 0x30, 0x40, 255};
    auto image = renderer->render("Kerning AV", o);
    ASSERT_TRUE(image);
    auto ppm = encode_ppm(*image);
    EXPECT_EQ(slurp(dir.path() / "line.ppm"), std::string(ppm.begin(), ppm.end()));

    run = run_bezel({"render", "--text", "x", "-o", "x.pgm"}, dir.path());
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(slurp(dir.path() / "x.pgm").substr(0, 3), "P5\n");
    run = run_bezel({"render", kDejaVu, "x", "-O", "ansi"}, dir.path());
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.out.find("\x1b[38;2;"), std::string::npos);
    EXPECT_NE(run.out.find("\xe2\x96\x80"), std::string::npos);
}

// --stroke W draws each glyph's outline instead of filling it: the ink of an outlined 'O' is a
// band along the filled O's boundary (every dark pixel within W/2 + 2 px of a filled edge), it
// leaves the inside of the letter's stroke white, and it is less ink than the filled letter.
TEST(RenderCli, StrokeDrawsTheGlyphOutlinesInsteadOfFillingThem) {
    test::TempDir dir("bezel-render-stroke");
    auto filled = run_bezel({"render", kDejaVu, "O", "--font-size", "96", "-o", "f.png"},
                            dir.path());
    ASSERT_EQ(filled.exit_code, 0) << filled.err;
    auto outlined = run_bezel(
        {"render", kDejaVu, "O", "--font-size", "96", "--stroke", "2", "-o", "s.png"}, dir.path());
    ASSERT_EQ(outlined.exit_code, 0) << outlined.err;
    auto f = read_png_gray((dir.path() / "f.png").string());
    auto s = read_png_gray((dir.path() / "s.png").string());
    ASSERT_TRUE(f && s);
    ASSERT_EQ(f->width(), s->width());
    ASSERT_EQ(f->height(), s->height());
    int filled_ink = 0, outlined_ink = 0, inner_white = 0;
    for (int y = 0; y < f->height(); ++y)
        for (int x = 0; x < f->width(); ++x) {
            filled_ink += f->at(x, y) < 128;
            if (s->at(x, y) >= 64) continue;
            ++outlined_ink;
            bool dark = false, light = false;   // the filled O's edge within 3 px
            for (int dy = -3; dy <= 3; ++dy)
                for (int dx = -3; dx <= 3; ++dx) {
                    const int u = std::clamp(x + dx, 0, f->width() - 1);
                    const int v = std::clamp(y + dy, 0, f->height() - 1);
                    (f->at(u, v) < 128 ? dark : light) = true;
                }
            EXPECT_TRUE(dark && light) << "ink far from the outline at " << x << "," << y;
        }
    // Pixels deep inside the filled O's ring (no light pixel within 3 px) stay white.
    for (int y = 4; y + 4 < f->height(); ++y)
        for (int x = 4; x + 4 < f->width(); ++x) {
            bool deep = true;
            for (int d = -3; d <= 3 && deep; ++d)
                deep = f->at(x + d, y) < 16 && f->at(x, y + d) < 16;
            if (!deep) continue;
            ++inner_white;
            EXPECT_GT(s->at(x, y), 200) << x << "," << y;
        }
    EXPECT_GT(inner_white, 50);
    EXPECT_GT(outlined_ink, 200);
    EXPECT_LT(outlined_ink, filled_ink);

    auto lcd = run_bezel({"render", "O", "--stroke", "2", "--lcd", "rgb", "-o", "l.png"},
                         dir.path());
    EXPECT_EQ(lcd.exit_code, 2);
    EXPECT_NE(lcd.err.find("--stroke"), std::string::npos) << lcd.err;
    auto wide = run_bezel({"render", "O", "--stroke", "5000", "-o", "w.png"}, dir.path());
    EXPECT_EQ(wide.exit_code, 2);
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"f.png", "s.png"}));
}

TEST(RenderCli, PngColourTypeFollowsTheColours) {
    TempDir dir("bezel-render-cli");
    const std::pair<std::vector<std::string>, int> cases[] = {
        {{"--foreground", "red"}, 2},
        {{"--background", "transparent"}, 6},
        {{"--lcd", "rgb"}, 2},
        {{"--foreground", "#444"}, 0},
    };
    for (const auto& [extra, type] : cases) {
        std::vector<std::string> args = {"render", "--text", "Aa", "-o", "c.png"};
        args.insert(args.end(), extra.begin(), extra.end());
        auto run = run_bezel(args, dir.path());
        ASSERT_EQ(run.exit_code, 0) << run.err;
        EXPECT_EQ(slurp(dir.path() / "c.png")[25], type) << extra[0] << " " << extra[1];
    }
}

struct BadCase {
    std::vector<std::string> args;
    int exit_code;
    std::string mention;   // the error line names this
};

TEST(RenderCli, LoneWordThatIsNoFileIsTheTextInTheDefaultFont) {
    TempDir dir("bezel-render-cli");
    auto word = run_bezel({"render", "Hello", "-o", "word.png"}, dir.path());
    ASSERT_EQ(word.exit_code, 0) << word.err;
    auto text = run_bezel({"render", "--text", "Hello", "-o", "text.png"}, dir.path());
    ASSERT_EQ(text.exit_code, 0) << text.err;
    EXPECT_EQ(slurp(dir.path() / "word.png"), slurp(dir.path() / "text.png"));
    // A file that exists stays the font, as before.
    auto font = run_bezel({"render", kDejaVu, "-o", "font.png"}, dir.path());
    ASSERT_EQ(font.exit_code, 0) << font.err;
    auto sample = run_bezel({"render", "-o", "sample.png"}, dir.path());
    ASSERT_EQ(sample.exit_code, 0) << sample.err;
    EXPECT_EQ(slurp(dir.path() / "font.png"), slurp(dir.path() / "sample.png"));
}

// Pixels an edge crosses (neither paper nor full ink): hinting moves edges onto pixel
// boundaries, so fewer pixels are partly covered than where the exact outline straddles them.
int edge_pixels(const Mask& page) {
    int n = 0;
    for (std::uint8_t v : page.pixels()) n += v > 0 && v < 255;
    return n;
}

TEST(RenderCli, EveryHintingModeDrawsAsTheLibraryAndHintedEdgesFallOnPixelBoundaries) {
    TempDir dir("bezel-render-cli");
    auto renderer = TextRenderer::open(kDejaVu);
    ASSERT_TRUE(renderer);
    int unhinted_edges = 0;
    for (Hinting mode : {Hinting::None, Hinting::Light, Hinting::Full, Hinting::Auto}) {
        const std::string name = hinting_name(mode);
        auto run = run_bezel({"render", "--hinting", name, "--text", "Hamburgefonts HELIX",
                              "--font-size", "11", "--margin", "2", "-o", name + ".pgm"},
                             dir.path());
        ASSERT_EQ(run.exit_code, 0) << name << ": " << run.err;
        TextRenderOptions o;
        o.shape.size_px = 11;
        o.layout.margin_px = 2;
        o.hinting = mode;
        auto page = renderer->render_gray("Hamburgefonts HELIX", o);
        ASSERT_TRUE(page) << page.error().message;
        auto pgm = encode_pgm(page->view());
        EXPECT_TRUE(slurp(dir.path() / (name + ".pgm")) == std::string(pgm.begin(), pgm.end()))
            << name << ": the CLI's page differs from the library's";
        if (mode == Hinting::None) {
            unhinted_edges = edge_pixels(*page);
        } else {
            EXPECT_LT(edge_pixels(*page), unhinted_edges * 9 / 10) << name;
        }
    }
}

TEST(RenderCli, FontSlantDrawsAsTheLibraryAndLeansTheText) {
    TempDir dir("bezel-render-cli");
    auto run = run_bezel({"render", "--text", "Ill", "--font-size", "30", "--margin", "2",
                          "--font-slant", "0.2", "-o", "slant.pgm"},
                         dir.path());
    ASSERT_EQ(run.exit_code, 0) << run.err;
    auto renderer = TextRenderer::open(kDejaVu);
    ASSERT_TRUE(renderer);
    TextRenderOptions o;
    o.shape.size_px = 30;
    o.layout.margin_px = 2;
    o.slant = 0.2;
    auto slanted = renderer->render_gray("Ill", o);
    o.slant = 0;
    auto upright = renderer->render_gray("Ill", o);
    ASSERT_TRUE(slanted && upright);
    auto pgm = encode_pgm(slanted->view());
    EXPECT_TRUE(slurp(dir.path() / "slant.pgm") == std::string(pgm.begin(), pgm.end()));
    // The top row of ink lies further right than upright: the stems lean.
    auto first_ink_column = [](const Mask& m, int y) {
        for (int x = 0; x < m.width(); ++x)
            if (m.at(x, y) < 128) return x;
        return -1;
    };
    int top = 0;
    while (top < upright->height() && first_ink_column(*upright, top) < 0) ++top;
    ASSERT_LT(top, upright->height());
    EXPECT_GT(first_ink_column(*slanted, top + 1), first_ink_column(*upright, top + 1) + 2);
}

TEST(RenderCli, DirectionIsTheParagraphsBaseDirection) {
    // An RTL paragraph puts its first (Latin) run at the right: the same picture as an LTR
    // paragraph that starts with the Hebrew run. Each run keeps its own direction.
    TempDir dir("bezel-render-cli");
    auto render = [&](const char* direction, const std::string& text, const std::string& file) {
        auto run = run_bezel({"render", "--direction", direction, "--text", text, "-o", file},
                             dir.path());
        EXPECT_EQ(run.exit_code, 0) << run.err;
        return slurp(dir.path() / file);
    };
    const std::string rtl = render("rtl", "abc \u05d0\u05d1\u05d2", "rtl.pgm");
    const std::string ltr_hebrew_first = render("ltr", "\u05d0\u05d1\u05d2 abc", "ltr1.pgm");
    const std::string ltr = render("ltr", "abc \u05d0\u05d1\u05d2", "ltr2.pgm");
    ASSERT_FALSE(rtl.empty());
    EXPECT_TRUE(rtl == ltr_hebrew_first);
    EXPECT_FALSE(rtl == ltr);
}

TEST(RenderCli, BadInputGivesOneErrorLineAndNoFile) {
    TempDir dir("bezel-render-cli");
    {
        std::FILE* f = std::fopen((dir.path() / "bad.txt").c_str(), "wb");
        ASSERT_NE(f, nullptr);
        std::fputs("fine\n\xc3\x28 broken", f);
        std::fclose(f);
    }
    const BadCase cases[] = {
        {{"render", "/nonexistent/font.ttf", "x", "-o", "out.png"}, 1, "/nonexistent/font.ttf"},
        {{"render", kDejaVu, "x", "--features", "kern[", "-o", "out.png"}, 2, "kern["},
        {{"render", kDejaVu, "x", "--foreground", "#12", "-o", "out.png"}, 2, "#12"},
        {{"render", kDejaVu, "x", "--background", "mauve", "-o", "out.png"}, 2, "mauve"},
        {{"render", kDejaVu, "x", "--font-size", "0", "-o", "out.png"}, 2, "--font-size"},
        {{"render", kDejaVu, "x", "--font-size", "1e9", "-o", "out.png"}, 2, "--font-size"},
        {{"render", kDejaVu, "--text-file", "bad.txt", "-o", "out.png"}, 1, "bad.txt"},
        {{"render", kDejaVu, "--text-file", "missing.txt", "-o", "out.png"}, 1, "missing.txt"},
        {{"render", kDejaVu, "x", "-o", "out.gif"}, 2, "out.gif"},
        {{"render", kDejaVu, "x", "--direction", "up", "-o", "out.png"}, 2,
         "--direction 'up': expected ltr, rtl, ttb, btt or auto"},
        {{"render", kDejaVu, "x", "--hinting", "strong", "-o", "out.png"}, 2, "--hinting"},
        {{"render", kDejaVu, "x", "--font-slant", "3", "-o", "out.png"}, 2, "--font-slant: 3 is not in -1 to 1"},
        {{"render", kDejaVu, "x", "--lcd", "rgb", "--background", "transparent", "-o", "out.png"},
         2, "--lcd needs an opaque --background"},
        {{"render", kDejaVu, "x", "--text", "y", "-o", "out.png"}, 2, "once"},
        {{"render", kDejaVu, "x", "--margin", "30000", "--font-size", "300", "-o", "out.png"}, 1,
         "too large"},
        {{"render", kDejaVu, "x", "--variations", "wght=700", "-o", "out.png"}, 1, "wght"},
        // A lone word that looks like a font path is a missing font, with a hint to --text.
        {{"render", "missing.TTF", "-o", "out.png"}, 1, "missing.TTF: no such font file"},
        {{"render", "fonts/Nothing", "-o", "out.png"}, 1, "--text"},
    };
    for (const BadCase& c : cases) {
        auto run = run_bezel(c.args, dir.path());
        std::string joined;
        for (const std::string& a : c.args) joined += a + " ";
        EXPECT_EQ(run.exit_code, c.exit_code) << joined << "\n" << run.err;
        // One error line (usage errors add a second line pointing at --help).
        std::string first = run.err.substr(0, run.err.find('\n'));
        EXPECT_EQ(first.rfind("bezel: ", 0), 0u) << joined << "\n" << run.err;
        EXPECT_NE(first.find(c.mention), std::string::npos) << joined << "\n" << run.err;
        int error_lines = 0;
        for (std::size_t at = run.err.find("bezel: "); at != std::string::npos;
             at = run.err.find("bezel: ", at + 1))
            error_lines += at == 0 || run.err[at - 1] == '\n';
        EXPECT_EQ(error_lines, 1) << joined << "\n" << run.err;
        EXPECT_EQ(run.out, "") << joined;
        EXPECT_EQ(dir.entries(), std::vector<std::string>{"bad.txt"}) << joined;
    }
}

}  // namespace
}  // namespace bezel
