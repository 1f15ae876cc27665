// The README's library example, built against the INSTALLED bezel package by the InstallPackage
// test (keep the two in step): render a line of text to a PNG. The font path comes from the
// command line instead of being fixed.
#include <bezel/text.hpp>
#include <cstdio>

int main(int argc, char** argv) {
    const char* font = argc > 1 ? argv[1] : "fonts-test/dejavu-sans/DejaVuSans.ttf";
    auto renderer = bezel::TextRenderer::open(font);   // Font + HarfBuzz shaper + glyph cache
    if (!renderer) { std::fprintf(stderr, "%s\n", renderer.error().message.c_str()); return 1; }

    bezel::TextRenderOptions options;
    options.shape.size_px = 32;                         // em size in pixels
    options.shape.features = bezel::parse_features("kern,liga").value();
    options.layout.margin_px = 8;
    options.foreground = bezel::parse_color("#1a3a6b").value();
    auto image = renderer->render("Hello, bezel! AV office", options);
    if (!image) { std::fprintf(stderr, "%s\n", image.error().message.c_str()); return 1; }

    auto written = bezel::write_png("hello-bezel.png", *image, bezel::PngColor::Rgb);
    if (!written) { std::fprintf(stderr, "%s\n", written.error().message.c_str()); return 1; }
    std::printf("hello-bezel.png: %dx%d, %zu glyphs cached\n", image->width(), image->height(),
                renderer->cache().stats().entries);
    return 0;
}
