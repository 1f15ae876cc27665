// fuzz_font — font bytes → Font::open → metrics, cmap, names, variation axes → outlines of a few
// glyphs at several sizes, hinted and not → bezel's Rasterizer. Each input is written to one
// per-process file in /dev/shm (or $TMPDIR) and opened as users open fonts: Font::open(file)
// maps it through FontFace::open, whose bytes reach FreeType as a memory font would
// (FT_New_Memory_Face), so the file route covers the memory one too. Properties: no crash or
// sanitizer report; every outline bezel returns is finite and its raw points agree with its
// contour ends; rasterizing it succeeds or fails with a message.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bezel/font.hpp"
#include "bezel/raster.hpp"
#include "fuzz_font_file.hpp"
#include "fuzz_reader.hpp"

namespace {

void check_outline(const bezel::GlyphOutline& g, bezel::Rasterizer& raster) {
    BEZEL_FUZZ_CHECK(g.path.is_finite());
    if (!g.contour_ends.empty()) BEZEL_FUZZ_CHECK(g.contour_ends.back() + 1 == g.points.size());
    for (std::size_t i = 1; i < g.contour_ends.size(); ++i)
        BEZEL_FUZZ_CHECK(g.contour_ends[i - 1] < g.contour_ends[i]);
    // A 64×64 window on the glyph's box: clipping handles the parts outside.
    static std::vector<std::uint8_t> pixels(64 * 64);
    const bezel::Rect box = g.path.bounds();
    const bezel::Affine at = box.is_empty() ? bezel::Affine::identity()
                                            : bezel::Affine::translate({-box.x0, -box.y0});
    auto status = raster.fill_path(g.path, at, bezel::MaskView{pixels.data(), 64, 64, 64});
    if (!status) BEZEL_FUZZ_CHECK(!status.error().message.empty());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::string file = bezel::fuzz::scratch_font_file("font");
    if (!bezel::fuzz::write_font_file(file, data, size)) std::abort();
    auto opened = bezel::Font::open(file, 0);
    if (!opened) {
        BEZEL_FUZZ_CHECK(opened.error().message.find(file) != std::string::npos);
        return 0;
    }
    bezel::Font& font = *opened;
    (void)font.family_name();
    (void)font.style_name();
    (void)font.metrics();
    BEZEL_FUZZ_CHECK(font.face_count() >= 1);
    for (char32_t c : {U'A', U'g', U' ', U'\u00e9', U'\U0001F600'}) (void)font.glyph_for_char(c);
    auto axes = font.axes();
    if (!axes.empty()) {
        std::vector<bezel::VariationSetting> settings;
        for (const auto& axis : axes) settings.push_back({axis.tag, axis.max_value});
        (void)font.set_variations(settings);
    }

    bezel::Rasterizer raster;
    const std::size_t glyphs = font.glyph_count();
    std::vector<bezel::GlyphId> gids{0, 1, 2, 3};
    if (glyphs > 4) gids.push_back(static_cast<bezel::GlyphId>(glyphs - 1));
    gids.push_back(static_cast<bezel::GlyphId>(glyphs));  // one past the end: an error
    for (bezel::GlyphId gid : gids) {
        (void)font.glyph_name(gid);
        for (double size : {1.0, 12.0, 300.0}) {
            for (bezel::Hinting hinting : {bezel::Hinting::None, bezel::Hinting::Light, bezel::Hinting::Full,
                                             bezel::Hinting::Auto}) {
                auto g = font.outline(gid, {size, hinting});
                if (gid >= glyphs) BEZEL_FUZZ_CHECK(!g.ok());
                if (g) check_outline(*g, raster);
                (void)font.glyph_metrics(gid, {size, hinting});
            }
        }
    }
    return 0;
}
