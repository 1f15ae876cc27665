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

std::string bytes_of(const std::vector<std::uint8_t>& v) { return std::string(v.begin(), v.end()); }

// A gray page and the PNG stream deflating its finished rows. The stream starts at the first
// finished rows, when the page has its size; it is declared after `page`, so it is destroyed
// (its workers joined) first.
struct PngBands final : PageRowsSink {
    explicit PngBands(int worker_count) : workers(worker_count) {}
    void rows_final(int rows) override {
        if (!png) png.emplace(page.view(), workers);
        png->rows_final(rows);
    }
    int workers;
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

Expected<std::string> encode_page(const Image& page, PageFormat format, bool gray_ok,
                                  bool has_alpha, int ansi_columns) {
    switch (format) {
        case PageFormat::Pgm: return bytes_of(encode_pgm(page));
        case PageFormat::Ppm: return bytes_of(encode_ppm(page));
        case PageFormat::Ansi: return encode_ansi(page, ansi_columns);
        case PageFormat::Png: break;
    }
    PngColor color = has_alpha ? PngColor::Rgba : gray_ok ? PngColor::Gray : PngColor::Rgb;
    auto png = encode_png(page, color);
    if (!png) return png.error();
    return bytes_of(*png);
}

Expected<std::string> render_gray_page(TextRenderer& renderer, std::string_view text,
                                       const TextRenderOptions& options, PageFormat format,
                                       const std::string& destination) {
    if (format != PageFormat::Png && format != PageFormat::Pgm)
        return Error{"a gray page is written as PNG or PGM only"};
    if (format == PageFormat::Pgm) {
        auto page = renderer.render_gray(text, options);
        if (!page) return page.error();
        return bytes_of(encode_pgm(page->view()));
    }
    // Deflating is the largest part of `bezel render`'s time on a page of text, so the PNG's
    // bands are deflated by workers on the other cores (at least one) while this thread draws
    // the lines below them, then by all of them.
    PngBands bands(static_cast<int>(std::max(2u, std::thread::hardware_concurrency()) - 1));
    if (auto drawn = renderer.render_gray_streaming(text, options, bands.page, bands); !drawn)
        return drawn.error();
    auto encoded = bands.png->finish();  // the sink's last call, with the page height, made `png`
    if (!encoded) return Error{destination + ": " + encoded.error().message};
    return bytes_of(*encoded);
}

}  // namespace bezel::cli
