// Built against the INSTALLED bezel package by the InstallPackage test: opens a font, takes the
// outline of 'g', and prints its segment count and the SVG path data's length. Exit 0 on success.
#include <cstdio>

#include <bezel/font.hpp>
#include <bezel/path.hpp>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: consumer FONT\n");
        return 2;
    }
    auto font = bezel::Font::open(argv[1]);
    if (!font) {
        std::fprintf(stderr, "consumer: %s\n", font.error().message.c_str());
        return 1;
    }
    auto gid = font->glyph_for_char(U'g');
    if (!gid) return 1;
    auto outline = font->outline(*gid, bezel::OutlineOptions{32.0, false});
    if (!outline) {
        std::fprintf(stderr, "consumer: %s\n", outline.error().message.c_str());
        return 1;
    }
    std::printf("g: %zu verbs, %zu points\n", outline->path.verbs().size(),
                outline->path.points().size());
    return outline->path.empty() ? 1 : 0;
}
