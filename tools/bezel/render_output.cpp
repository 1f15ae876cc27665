#include "render_output.hpp"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <thread>

#include "cli_common.hpp"

namespace bezel::cli {

namespace {

// A gray page and the PNG stream deflating its finished rows. The stream starts at the first
// finished rows, when the page has its size; it is declared after `page`, so it is destroyed
// (its workers joined) first.
struct PngBands final : PageRowsSink {
    PngBands(int worker_count, const PngOptions& png_options)
        : workers(worker_count), options(png_options) {}
    void rows_final(int rows) override {
        if (!png) png.emplace(page.view(), workers, options);
        png->rows_final(rows);
    }
    int workers;
    PngOptions options;
    Mask page;
    std::optional<PngGrayStream> png;
};

}  // namespace

Expected<PageFormat> pick_page_format(const std::string& format_option,
                                      const std::string& output_file, bool stdout_is_terminal) {
    auto picked = pick_output_format(format_option, output_file,
                                     {{".png", "png"},
                                      {".pgm", "pgm"},
                                      {".ppm", "ppm"},
                                      {".ans", "ansi"},
                                      {".ansi", "ansi", false}},
                                     stdout_is_terminal ? "ansi" : "png");
    if (!picked) return picked.error();
    const std::string& name = *picked;
    if (name == "png") return PageFormat::Png;
    if (name == "pgm") return PageFormat::Pgm;
    if (name == "ppm") return PageFormat::Ppm;
    if (name == "ansi") return PageFormat::Ansi;
    return Error{"-O '" + name + "': unknown output format (expected png, pgm, ppm or ansi)"};
}

int terminal_columns() {
    if (!::isatty(STDOUT_FILENO)) return 0;
    winsize ws{};
    if (::ioctl(STDOUT_FILENO, TIOCGWINSZ, &ws) == 0 && ws.ws_col > 0) return ws.ws_col;
    if (const char* env = std::getenv("COLUMNS")) {
        int n = std::atoi(env);
        if (n > 0) return n;
    }
    return 80;
}

Expected<FileBytes> encode_page(const Image& page, PageFormat format, bool gray_ok,
                                  bool has_alpha, int ansi_columns, const PngOptions& png_options) {
    switch (format) {
        case PageFormat::Pgm: return encode_pgm(page);
        case PageFormat::Ppm: return encode_ppm(page);
        case PageFormat::Ansi: {
            const std::string ansi = encode_ansi(page, ansi_columns);
            return FileBytes(ansi.begin(), ansi.end());
        }
        case PageFormat::Png: break;
    }
    PngColor color = has_alpha ? PngColor::Rgba : gray_ok ? PngColor::Gray : PngColor::Rgb;
    return encode_png(page, color, png_options);
}

Expected<FileBytes> render_gray_page(TextRenderer& renderer, std::string_view text,
                                       const TextRenderOptions& options, PageFormat format,
                                       const PngOptions& png, const std::string& destination) {
    if (format != PageFormat::Png && format != PageFormat::Pgm)
        return Error{"a gray page is written as PNG or PGM only"};
    if (format == PageFormat::Pgm) {
        auto page = renderer.render_gray(text, options);
        if (!page) return page.error();
        return encode_pgm(page->view());
    }
    // Deflating is the largest part of `bezel render`'s time on a page of text, so the PNG's
    // bands are deflated by workers on the other cores (at least one) while this thread draws
    // the lines below them, then by all of them.
    PngBands bands(static_cast<int>(std::max(2u, std::thread::hardware_concurrency()) - 1), png);
    if (auto drawn = renderer.render_gray_streaming(text, options, bands.page, bands); !drawn)
        return drawn.error();
    auto encoded = bands.png->finish();  // the sink's last call, with the page height, made `png`
    if (!encoded) return Error{destination + ": " + encoded.error().message};
    return encoded;
}

}  // namespace bezel::cli
