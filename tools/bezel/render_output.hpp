// tools/bezel/render_output.hpp — how `bezel render` picks its output format and encodes a page.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "bezel/expected.hpp"
#include "bezel/image.hpp"
#include "bezel/text.hpp"

namespace bezel::cli {

enum class PageFormat { Png, Pgm, Ppm, Ansi };

// -O wins; else the -o file's extension (.png, .pgm, .ppm, .ans/.ansi); else ANSI when stdout is
// a terminal, PNG otherwise. An unknown extension is an error naming the file.
Expected<PageFormat> pick_page_format(const std::string& format_option,
                                      const std::string& output_file, bool stdout_is_terminal);

// The terminal's width in columns when stdout is one (TIOCGWINSZ, else $COLUMNS, else 80);
// 0 when stdout is not a terminal.
int terminal_columns();

// The file's bytes (a byte vector, as the PNG writers give them: a page's PNG is not copied
// again on its way out).
using FileBytes = std::vector<std::uint8_t>;

// The page as the file's bytes. PNG picks the smallest layout that loses nothing: gray when both
// colours are opaque grays (and the mode is not LCD), RGBA when either colour is translucent,
// RGB otherwise. ANSI is box-filtered to `ansi_columns` (0 = no limit).
Expected<FileBytes> encode_page(const Image& page, PageFormat format, bool gray_ok,
                                  bool has_alpha, int ansi_columns, const PngOptions& png);
// Gray text (TextRenderer::render_gray: opaque gray colours, gray mode) drawn as one sRGB byte
// per pixel and written as PNG (8-bit gray) or PGM; other formats are an Error. For PNG (unless
// PngCompression::Small), bands of rows are deflated on the other cores while the lines below
// them are still drawn. Drawing
// errors come back as render_gray gives them; encoding errors are prefixed with `destination`.
Expected<FileBytes> render_gray_page(TextRenderer& renderer, std::string_view text,
                                       const TextRenderOptions& options, PageFormat format,
                                       const PngOptions& png, const std::string& destination);

}  // namespace bezel::cli
