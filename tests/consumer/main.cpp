// The README's library example, built against the INSTALLED bezel package by the InstallPackage
// test (keep the two in step). The font path comes from the command line instead of being fixed.
#include <bezel/font.hpp>
#include <bezel/path.hpp>
#include <cstdio>

int main(int argc, char** argv) {
    const char* file = argc > 1 ? argv[1] : "fonts-test/dejavu-sans/DejaVuSans.ttf";
    auto font = bezel::Font::open(file);
    if (!font) { std::fprintf(stderr, "%s\n", font.error().message.c_str()); return 1; }

    bezel::GlyphId gid = font->glyph_for_char(U'g').value_or(0);
    auto outline = font->outline(gid, {/*size_px=*/48.0, /*hinting=*/false});
    if (!outline) { std::fprintf(stderr, "%s\n", outline.error().message.c_str()); return 1; }

    // Pixels, y down, pen at the origin on the baseline.
    const bezel::Path& path = outline->path;
    std::printf("area %.2f px², bounds x %.2f..%.2f\n", path.signed_area(),
                path.bounds().x0, path.bounds().x1);
    for (const bezel::PathSeg& seg : path.segments())
        std::printf("segment %zu of contour %zu ends at (%.2f, %.2f)\n",
                    seg.index, seg.contour, seg.end().x, seg.end().y);
    std::printf("%s\n", bezel::to_svg_path(path).c_str());
    return path.empty() ? 1 : 0;
}
