// Colour glyphs drawn by bezel against the same glyphs drawn by Chromium (Skia, a real COLRv1
// renderer): every COLRv1 glyph of test_glyphs-glyf_colr_1.ttf at 64 and 128 px, and the CBDT and
// sbix bitmap glyphs of the test fonts at 32 and 128 px. The references and their cell geometry
// are tests/golden/colour/ (manifest.tsv; made once by make_goldens.sh, README.md there says how
// and records where the two renderers differ and which follows the specification).
//
// bezel's rendering goes through the public API only: load_color_glyph (default palette) and
// Painter::paint into an RgbaView of the cell, or load_color_bitmap scaled with scale_rgba. The
// premultiplied result is composited over white in sRGB-encoded values, as Chromium's canvas
// composites text onto its white background: out = c + (255 − a) for each colour byte c.
//
// BEZEL_COLOUR_GOLDEN_OUT=<dir> also writes bezel's composited cells there as PNG, under the
// golden's file name (for side_by_side.py and for looking at a difference).
#include <gtest/gtest.h>
#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "bezel/color_glyph.hpp"
#include "bezel/font.hpp"
#include "bezel/image.hpp"
#include "bezel/paint.hpp"

namespace bezel {
namespace {

const std::filesystem::path kGoldenDir = std::filesystem::path(BEZEL_GOLDEN_DIR) / "colour";

// One manifest row: what Chromium drew into one cell.
struct Cell {
    std::string format;   // "COLRv1", "CBDT", "sbix"
    std::string font;     // relative to the source tree
    std::string glyph;    // PostScript name
    GlyphId gid = 0;
    std::vector<char32_t> text;   // the code points the page drew (a ligature's spelling)
    int size_px = 0;
    int width = 0, height = 0;
    int pen_x = 0, pen_y = 0;     // cell pixels, y down
    std::string file;             // relative to kGoldenDir
    std::string label() const { return glyph + "@" + std::to_string(size_px); }
};

std::vector<Cell> read_manifest() {
    std::vector<Cell> cells;
    std::ifstream in(kGoldenDir / "manifest.tsv");
    std::string line;
    bool header = true;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        if (header) {   // the column names
            header = false;
            continue;
        }
        std::vector<std::string> f;
        std::stringstream ss(line);
        for (std::string field; std::getline(ss, field, '\t');) f.push_back(field);
        if (f.size() != 11) {
            ADD_FAILURE() << "manifest.tsv: a row of " << f.size() << " fields, not 11: " << line;
            continue;
        }
        Cell c;
        c.format = f[0];
        c.font = f[1];
        c.glyph = f[2];
        c.gid = static_cast<GlyphId>(std::stoul(f[3]));
        std::stringstream cps(f[4]);
        for (std::string cp; cps >> cp;) {
            c.text.push_back(static_cast<char32_t>(std::stoul(cp.substr(2), nullptr, 16)));
        }
        c.size_px = std::stoi(f[5]);
        c.width = std::stoi(f[6]);
        c.height = std::stoi(f[7]);
        c.pen_x = std::stoi(f[8]);
        c.pen_y = std::stoi(f[9]);
        c.file = f[10];
        cells.push_back(c);
    }
    return cells;
}

// An opaque RGB picture, rows packed.
struct Rgb {
    int width = 0, height = 0;
    std::vector<std::uint8_t> pixels;   // R, G, B
};

// The golden, through libpng's simplified API (bezel's own reader is gray only).
Rgb read_golden(const std::string& file) {
    Rgb rgb;
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    const std::string path = (kGoldenDir / file).string();
    if (!png_image_begin_read_from_file(&image, path.c_str())) {
        ADD_FAILURE() << path << ": " << image.message;
        return rgb;
    }
    image.format = PNG_FORMAT_RGB;
    rgb.width = static_cast<int>(image.width);
    rgb.height = static_cast<int>(image.height);
    rgb.pixels.resize(PNG_IMAGE_SIZE(image));
    if (!png_image_finish_read(&image, nullptr, rgb.pixels.data(), 0, nullptr)) {
        ADD_FAILURE() << path << ": " << image.message;
        return {};
    }
    return rgb;
}

// Premultiplied RGBA composited over opaque white in sRGB-encoded values.
Rgb over_white(ConstRgbaView v) {
    Rgb rgb{v.width, v.height, {}};
    rgb.pixels.reserve(static_cast<std::size_t>(3 * v.width * v.height));
    for (int y = 0; y < v.height; ++y) {
        for (int x = 0; x < v.width; ++x) {
            const std::uint8_t* p = v.pixel(x, y);
            for (int ch = 0; ch < 3; ++ch) {
                rgb.pixels.push_back(static_cast<std::uint8_t>(std::min(255, p[ch] + 255 - p[3])));
            }
        }
    }
    return rgb;
}

void save(const Rgb& rgb, const std::string& name) {
    const char* dir = std::getenv("BEZEL_COLOUR_GOLDEN_OUT");
    if (dir == nullptr || *dir == '\0') return;
    Image image(rgb.width, rgb.height);
    for (int y = 0; y < rgb.height; ++y) {
        for (int x = 0; x < rgb.width; ++x) {
            const std::uint8_t* p = &rgb.pixels[static_cast<std::size_t>(3 * (y * rgb.width + x))];
            image.at(x, y) = Rgba8{p[0], p[1], p[2], 255};
        }
    }
    const std::filesystem::path out = std::filesystem::path(dir) / name;
    std::filesystem::create_directories(out.parent_path());
    EXPECT_TRUE(write_png(out.string(), image, PngColor::Rgb).ok()) << out;
}

// How far bezel's cell is from Chromium's, in 8-bit sRGB-encoded levels.
struct Difference {
    double mean = 0;            // mean absolute difference, the worst of the three channels
    int max = 0;                // largest difference of any channel
    double far_fraction = 0;    // fraction of pixels with a channel differing by > kFarLevels
};
constexpr int kFarLevels = 32;

Difference compare(const Rgb& bezel, const Rgb& chromium) {
    Difference d;
    const std::size_t n = static_cast<std::size_t>(bezel.width) * static_cast<std::size_t>(bezel.height);
    double sum[3] = {0, 0, 0};
    std::size_t far = 0;
    for (std::size_t i = 0; i < n; ++i) {
        int worst = 0;
        for (int ch = 0; ch < 3; ++ch) {
            const int e = std::abs(bezel.pixels[3 * i + ch] - chromium.pixels[3 * i + ch]);
            sum[ch] += e;
            worst = std::max(worst, e);
        }
        d.max = std::max(d.max, worst);
        if (worst > kFarLevels) ++far;
    }
    d.mean = std::max({sum[0], sum[1], sum[2]}) / static_cast<double>(n);
    d.far_fraction = static_cast<double>(far) / static_cast<double>(n);
    return d;
}

// What a cell may differ by. Painted (COLRv1) glyphs: both renderers evaluate the same paint graph
// in the same colour space (sRGB-encoded values, straight-colour gradient interpolation), so the
// mean difference stays at a fraction of a level; what remains is anti-aliasing on edges (Skia's
// supersampled coverage against bezel's exact area), where single pixels differ by up to a
// quarter of the range, bounded by the fraction of far pixels. The figures measured for every
// cell are in tests/golden/colour/README.md; these bounds leave about 1.5x headroom over the worst.
struct Tolerance {
    double mean = 1.0;            // levels of 255, the worst channel's mean
    double far_fraction = 0.01;   // of the cell's pixels, differing by > kFarLevels
};
// Bitmap glyphs: the two resample the strike with different filters (Skia: bilinear or mipmapped
// in sRGB-encoded values; bezel: box when shrinking, bilinear when enlarging, in linear light),
// so detail and edges differ, the more so the further the strike is shrunk: 32 px from a 109 or
// 136 px strike loses most of its detail either way.
constexpr Tolerance kBitmapEnlargedTolerance{2.0, 0.02};
constexpr Tolerance kBitmapShrunkTolerance{6.0, 0.07};

// Glyphs where bezel follows the COLR specification and Chromium does not, each with the
// tolerance that admits the documented difference (tests/golden/colour/README.md explains each).
const std::map<std::string, Tolerance>& colr_overrides() {
    static const std::map<std::string, Tolerance> overrides = {};
    return overrides;
}

struct FontCache {
    std::map<std::string, Font> fonts;
    Font* get(const std::string& relative) {
        auto it = fonts.find(relative);
        if (it != fonts.end()) return &it->second;
        Expected<Font> font = Font::open(std::string(BEZEL_SOURCE_DIR) + "/" + relative);
        if (!font.ok()) {
            ADD_FAILURE() << font.error().message;
            return nullptr;
        }
        return &fonts.emplace(relative, std::move(*font)).first->second;
    }
};

std::string figures(const std::string& label, const Difference& d, const Tolerance& t) {
    char line[256];
    std::snprintf(line, sizeof line, "%-58s mean %5.2f (≤ %.2f)  max %3d  far %6.3f%% (≤ %.3f%%)",
                  label.c_str(), d.mean, t.mean, d.max, 100 * d.far_fraction,
                  100 * t.far_fraction);
    return line;
}

// The paint graphs of these glyphs loop (PaintColrGlyph of each other): bezel refuses them with an
// error naming the glyph, Chromium draws nothing; checked by LoopingGraphIsRefusedAndChromiumDrawsNothing.
bool is_cycle_glyph(const std::string& glyph) {
    return glyph.rfind("paintcolrglyph_cycle_", 0) == 0;
}

TEST(ColourGolden, ManifestListsEveryColrV1GlyphOfTheTestFontAtBothSizes) {
    const std::vector<Cell> cells = read_manifest();
    FontCache fonts;
    const std::string relative = "fonts-test/colour/test_glyphs-glyf_colr_1.ttf";
    Font* font = fonts.get(relative);
    ASSERT_NE(font, nullptr);
    std::map<std::string, int> listed;   // glyph → sizes listed
    for (const Cell& c : cells) {
        if (c.format != "COLRv1") continue;
        EXPECT_EQ(c.font, relative);
        ASSERT_EQ(c.text.size(), 1u) << c.label();
        // The manifest's gid is the one the page's code point reaches in this font.
        EXPECT_EQ(font->glyph_for_char(c.text[0]), std::optional<GlyphId>(c.gid)) << c.label();
        EXPECT_EQ(font->glyph_name(c.gid), c.glyph);
        EXPECT_EQ(color_format(*font, c.gid), ColorFormat::ColrV1) << c.label();
        listed[c.glyph] += 1;
    }
    // 200 base glyphs of the font are reached from its cmap (make_goldens.py enumerates them).
    EXPECT_EQ(listed.size(), 200u);
    for (const auto& [glyph, sizes] : listed) EXPECT_EQ(sizes, 2) << glyph;
}

TEST(ColourGolden, ColrV1GlyphsMatchChromiumWithinTolerance) {
    const std::vector<Cell> cells = read_manifest();
    FontCache fonts;
    Painter painter;
    std::vector<std::uint8_t> buffer;
    std::vector<std::string> failures;
    int compared = 0;
    for (const Cell& c : cells) {
        if (c.format != "COLRv1" || is_cycle_glyph(c.glyph)) continue;
        Font* font = fonts.get(c.font);
        ASSERT_NE(font, nullptr);
        Expected<ColorGlyph> glyph = load_color_glyph(*font, c.gid, ColorGlyphOptions{});
        if (!glyph.ok()) {
            failures.push_back(c.label() + ": " + glyph.error().message);
            continue;
        }
        const double s = c.size_px / static_cast<double>(font->metrics().units_per_em);
        PaintOptions options;
        options.transform = Affine{s, 0, 0, -s, static_cast<double>(c.pen_x),
                                   static_cast<double>(c.pen_y)};
        options.foreground = Rgba8{0, 0, 0, 255};
        buffer.assign(static_cast<std::size_t>(4 * c.width * c.height), 0);
        RgbaView target{buffer.data(), c.width, c.height, 4 * std::ptrdiff_t{c.width}};
        Status painted = painter.paint(*glyph, options, target);
        if (!painted.ok()) {
            failures.push_back(c.label() + ": " + painted.error().message);
            continue;
        }
        const Rgb mine = over_white(target);
        save(mine, c.file);
        const Rgb golden = read_golden(c.file);
        ASSERT_EQ(golden.width, c.width) << c.file;
        ASSERT_EQ(golden.height, c.height) << c.file;
        const auto over = colr_overrides().find(c.glyph);
        const Tolerance t = over != colr_overrides().end() ? over->second : Tolerance{};
        const Difference d = compare(mine, golden);
        ++compared;
        if (d.mean > t.mean || d.far_fraction > t.far_fraction) {
            failures.push_back(figures(c.label(), d, t));
        }
    }
    EXPECT_EQ(compared, 2 * (200 - 2));
    std::string report;
    for (const std::string& f : failures) report += f + "\n";
    EXPECT_TRUE(failures.empty()) << failures.size() << " of " << compared
                                  << " cells differ from Chromium beyond tolerance:\n" << report;
}

TEST(ColourGolden, LoopingGraphIsRefusedAndChromiumDrawsNothing) {
    const std::vector<Cell> cells = read_manifest();
    FontCache fonts;
    int seen = 0;
    for (const Cell& c : cells) {
        if (c.format != "COLRv1" || !is_cycle_glyph(c.glyph)) continue;
        ++seen;
        const Rgb golden = read_golden(c.file);
        EXPECT_TRUE(std::all_of(golden.pixels.begin(), golden.pixels.end(),
                                [](std::uint8_t v) { return v == 255; }))
            << c.file << ": Chromium drew something for a looping graph";
        Font* font = fonts.get(c.font);
        ASSERT_NE(font, nullptr);
        Expected<ColorGlyph> glyph = load_color_glyph(*font, c.gid, ColorGlyphOptions{});
        ASSERT_FALSE(glyph.ok()) << c.label() << ": a looping paint graph was accepted";
        EXPECT_NE(glyph.error().message.find(c.glyph), std::string::npos) << glyph.error().message;
        EXPECT_NE(glyph.error().message.find("loop"), std::string::npos) << glyph.error().message;
    }
    EXPECT_EQ(seen, 4);   // two glyphs at two sizes
}

// The strike scaled to the size and placed by its metrics: its box is the strike's box times
// size/strike, rounded to whole pixels (scale_rgba fills a whole target).
TEST(ColourGolden, BitmapGlyphsMatchChromiumWithinBitmapTolerances) {
    const std::vector<Cell> cells = read_manifest();
    FontCache fonts;
    std::vector<std::string> failures;
    std::map<std::string, int> compared;   // format → cells
    for (const Cell& c : cells) {
        if (c.format != "CBDT" && c.format != "sbix") continue;
        Font* font = fonts.get(c.font);
        ASSERT_NE(font, nullptr);
        EXPECT_EQ(color_format(*font, c.gid), ColorFormat::Bitmap) << c.label();
        Expected<ColorBitmap> bitmap = load_color_bitmap(*font, c.gid, c.size_px);
        if (!bitmap.ok()) {
            failures.push_back(c.label() + ": " + bitmap.error().message);
            continue;
        }
        const double k = c.size_px / bitmap->strike_px;
        const int x0 = static_cast<int>(std::lround(c.pen_x + bitmap->left * k));
        const int y0 = static_cast<int>(std::lround(c.pen_y - bitmap->top * k));
        const int x1 = static_cast<int>(std::lround(c.pen_x + (bitmap->left + bitmap->width) * k));
        const int y1 = static_cast<int>(std::lround(c.pen_y - (bitmap->top - bitmap->height) * k));
        std::vector<std::uint8_t> cell(static_cast<std::size_t>(4 * c.width * c.height), 0);
        RgbaView target{cell.data(), c.width, c.height, 4 * std::ptrdiff_t{c.width}};
        ASSERT_TRUE(x0 >= 0 && y0 >= 0 && x1 <= c.width && y1 <= c.height)
            << c.label() << ": the bitmap's box [" << x0 << ", " << x1 << ") x [" << y0 << ", "
            << y1 << ") leaves the cell";
        const BitmapFilter filter = k < 1 ? BitmapFilter::Box : BitmapFilter::Bilinear;
        scale_rgba(bitmap->view(), target.sub(x0, y0, x1 - x0, y1 - y0), filter);
        const Rgb mine = over_white(target);
        save(mine, c.file);
        const Rgb golden = read_golden(c.file);
        ASSERT_EQ(golden.width, c.width) << c.file;
        const Difference d = compare(mine, golden);
        compared[c.format] += 1;
        const Tolerance& t = k < 1 ? kBitmapShrunkTolerance : kBitmapEnlargedTolerance;
        if (d.mean > t.mean || d.far_fraction > t.far_fraction) {
            failures.push_back(figures(c.label() + " (" + c.format + ")", d, t));
        }
    }
    EXPECT_EQ(compared["CBDT"], 2);
    EXPECT_EQ(compared["sbix"], 48);   // 15 twemoji + 9 samples glyphs at two sizes
    std::string report;
    for (const std::string& f : failures) report += f + "\n";
    EXPECT_TRUE(failures.empty()) << failures.size()
                                  << " bitmap cells differ from Chromium beyond tolerance:\n"
                                  << report;
}

}  // namespace
}  // namespace bezel
