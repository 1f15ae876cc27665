// `bezel render`: a paragraph of text to a picture — shaped by HarfBuzz, laid out (newlines,
// wrapping, alignment), rasterized through the glyph cache and blended in linear light — as PNG,
// PGM, PPM or an ANSI preview for the terminal. Options follow hb-view where they overlap.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>

#include "bezel/stroke.hpp"
#include "bezel/text.hpp"
#include "cli_common.hpp"
#include "color_args.hpp"
#include "commands.hpp"
#include "draw.hpp"
#include "font_args.hpp"
#include "font_list.hpp"
#include "missing_glyphs.hpp"
#include "parse_check.hpp"
#include "render_output.hpp"
#include "sample_text.hpp"

namespace bezel::cli {
namespace {

constexpr const char* kRenderCommand = "bezel render";
// A paragraph size: body text on a screen is 13-20 px; 20 px keeps the README picture legible.
// (hb-view's 256 px default suits one word, not a paragraph.)
constexpr double kDefaultRenderSizePx = 20.0;
// Terminal previews draw one pixel per column and two per row, so glyphs are 10 px tall (five
// rows) unless --font-size says otherwise, and horizontal lines wrap at the terminal's width.
constexpr double kDefaultPreviewSizePx = 10.0;
constexpr double kDefaultMarginPx = 16.0;   // hb-view's default margin
constexpr double kDefaultPreviewMarginPx = 1.0;
// Widest --stroke, px: past it the stroke buries the text at any size a page uses, and the
// stroker's work grows with the width.
constexpr double kMaxStrokePx = 1000.0;
// Most pixels of an outlined page (as TextRenderer's page limit: 64 Mpx, 256 MiB of RGBA).
constexpr double kMaxOutlinedPagePixels = double{1 << 26};

struct RenderArgs {
    FontArgs font;
    FontListArgs fonts;         // --font, --fallback
    ColorArgs color;            // --palette, --custom-palette
    double slant = 0;           // --font-slant
    double bold = 0;            // --font-bold
    std::string text;           // TEXT or --text
    std::string text_file;      // --text-file
    std::string features;       // --features
    std::string direction;      // --direction
    std::string script;         // --script
    std::string language;       // --language
    double width_px = 0;        // --width
    double margin_px = kDefaultMarginPx;
    double line_height = 0;     // --line-height
    std::string align = "start";
    std::string foreground = "#000000";
    std::string background = "#FFFFFF";
    std::string lcd;            // --lcd rgb|bgr
    std::string rendering = "perceptual";  // --rendering
    double gamma = kDefaultTextGamma;       // --gamma
    double contrast = kDefaultTextContrast; // --contrast
    double stroke_px = 0;       // --stroke: outlined text this wide; 0 = filled glyphs
    std::string format;         // -O
    std::string output_file;    // -o
    bool strict = false;        // --strict
    PngOptions png;             // --compression
    CLI::App* cmd = nullptr;
};

// --rendering NAME: the library's TextRendering.
Expected<TextRendering> parse_rendering(const std::string& name) {
    if (name == "perceptual") return TextRendering::Perceptual;
    if (name == "linear") return TextRendering::Linear;
    return Error{"'" + name + "': expected perceptual or linear"};
}

// --gamma G and --contrast C as typed: finite numbers in the library's ranges (NaN fails too).
Expected<double> parse_text_gamma(const std::string& text) {
    const std::optional<double> g = parse_number(text);
    if (!g) return Error{"'" + text + "': not a number"};
    if (!(*g >= kMinTextGamma && *g <= kMaxTextGamma))
        return Error{"'" + text + "': must be >= " + svg_number(kMinTextGamma) + " and <= " +
                     svg_number(kMaxTextGamma)};
    return *g;
}
Expected<double> parse_text_contrast(const std::string& text) {
    const std::optional<double> k = parse_number(text);
    if (!k) return Error{"'" + text + "': not a number"};
    if (!(*k >= 0.0 && *k <= kMaxTextContrast))
        return Error{"'" + text + "': must be >= 0 and <= " + svg_number(kMaxTextContrast)};
    return *k;
}

Expected<bezel::Direction> parse_direction(const std::string& name) {
    if (name.empty() || name == "auto") return bezel::Direction::Auto;
    if (name == "ltr") return bezel::Direction::LeftToRight;
    if (name == "rtl") return bezel::Direction::RightToLeft;
    if (name == "ttb") return bezel::Direction::TopToBottom;
    if (name == "btt") return bezel::Direction::BottomToTop;
    return Error{"--direction '" + name + "': expected ltr, rtl, ttb, btt or auto"};
}

// The --text-file contents ('-': stdin), at most kMaxTextBytes, valid UTF-8, one trailing newline
// dropped (as hb-view does, so a file's last line does not add an empty one).
Expected<std::string> read_text_file(const std::string& file) {
    std::string text;
    std::FILE* f = file == "-" ? stdin : std::fopen(file.c_str(), "rb");
    if (!f) return Error{file + ": cannot open file"};
    char buffer[65536];
    std::size_t n;
    while ((n = std::fread(buffer, 1, sizeof buffer, f)) > 0) {
        text.append(buffer, n);
        if (text.size() > kMaxTextBytes) break;
    }
    bool failed = std::ferror(f) != 0;
    if (f != stdin) std::fclose(f);
    if (failed) return Error{file + ": read failed"};
    if (text.size() > kMaxTextBytes)
        return Error{file + ": longer than " + std::to_string(kMaxTextBytes) + " bytes"};
    if (auto valid = decode_utf8(text); !valid) return Error{file + ": " + valid.error().message};
    if (!text.empty() && text.back() == '\n') text.pop_back();
    if (!text.empty() && text.back() == '\r') text.pop_back();
    return text;
}

// Outlined text (--stroke W): each glyph's outline stroked W px wide (round joins, so corners
// keep their shape at any width) instead of filled. The stroke's pieces overlap by design, so they
// are filled with the accurate overlap mode; each glyph is stroked, rasterized into its own box
// and blended at its pen, bypassing the glyph cache (a stroked glyph is not a cached bitmap;
// one CLI call can afford stroking every placed glyph). `missing` receives the layout's .notdef
// glyphs, as TextRenderer::missing_glyphs does for filled text.
Expected<Image> render_outlined(TextRenderer& renderer, const std::string& text,
                                const TextRenderOptions& options, double stroke_px,
                                MissingGlyphs& missing) {
    FontCollection& fonts = renderer.fonts();
    // The first font's coordinates as TextRenderer sets them (its own, then the command line's).
    std::vector<VariationSetting> first;
    fonts.variations_for(0, options.shape.variations, first);
    if (auto set = fonts.font(0).set_variations(first); !set) return set.error();
    auto layout = layout_text(fonts, text, options.shape, options.layout);
    if (!layout) return layout.error();
    missing = find_missing_glyphs(*layout, text);
    const double w = std::ceil(layout->width_px), h = std::ceil(layout->height_px);
    if (!(w <= kMaxImageDim && h <= kMaxImageDim && w * h <= kMaxOutlinedPagePixels))
        return Error{"outlined text page of " + plain_number(w) + "x" + plain_number(h) +
                     " px is too large (at most " + std::to_string(kMaxImageDim) + " px a side, " +
                     plain_number(kMaxOutlinedPagePixels) + " px in all)"};
    Image page(std::max(1, static_cast<int>(w)), std::max(1, static_cast<int>(h)),
               options.background);

    auto made = coverage_curve(options.foreground, options.background, options.coverage);
    if (!made) return made.error();
    const CoverageCurve& curve = *made;
    StrokeStyle style;
    style.width = stroke_px;
    style.join = LineJoin::Round;
    Rasterizer rasterizer;
    Mask coverage;
    // Pens as TextRenderer places them for the hinting mode (text_renderer.hpp).
    const bool whole_pixel_pen = hints_horizontally(options.hinting);
    for (PlacedGlyph g : layout->glyphs) {
        if (whole_pixel_pen) g.x_px = std::floor(g.x_px + 0.5);
        Font& font = fonts.font(g.font);
        auto outline = font.outline(g.gid, OutlineOptions{options.shape.size_px, options.hinting});
        if (!outline) return outline.error();
        // The synthetic slant, as GlyphRasterizer applies it (glyph.hpp).
        if (options.slant != 0) outline->path.transform(Affine::skew(-options.slant, 0));
        if (outline->path.empty()) continue;
        auto stroked = stroke(outline->path, style);
        if (!stroked) return Error{font.file() + ": glyph " + std::to_string(g.gid) + ": " +
                                   stroked.error().message};
        const Rect b = stroked->bounds();
        // The glyph's box in page pixels, clipped to the page (a pen far off the page draws
        // nothing, and the box never exceeds the page).
        const double x0 = std::max(0.0, std::floor(g.x_px + b.x0));
        const double y0 = std::max(0.0, std::floor(g.y_px + b.y0));
        const double x1 = std::min<double>(page.width(), std::ceil(g.x_px + b.x1));
        const double y1 = std::min<double>(page.height(), std::ceil(g.y_px + b.y1));
        if (!(x1 > x0 && y1 > y0)) continue;
        coverage = Mask(static_cast<int>(x1 - x0), static_cast<int>(y1 - y0));
        auto filled = rasterizer.fill_path(*stroked, Affine::translate({g.x_px - x0, g.y_px - y0}),
                                           coverage.view(),
                                           {FillRule::NonZero, OverlapMode::Accurate});
        if (!filled) return filled.error();
        blend_mask(page, coverage.view(), static_cast<int>(x0), static_cast<int>(y0),
                   options.foreground, curve);
    }
    return page;
}

int run_render(RenderArgs& args) {
    const bool tty = ::isatty(STDOUT_FILENO) != 0;
    auto format = pick_page_format(args.format, args.output_file, tty);
    if (!format) return fail_usage(format.error().message, kRenderCommand);
    const bool preview = *format == PageFormat::Ansi;
    const int columns = preview ? terminal_columns() : 0;

    if (preview && args.cmd->count("--font-size") == 0) args.font.size_px = kDefaultPreviewSizePx;
    if (args.cmd->count("TEXT") + args.cmd->count("--text") + args.cmd->count("--text-file") > 1)
        return fail_usage("give the text once: TEXT, --text or --text-file", kRenderCommand);
    // A lone positional word is FONT to CLI11; `bezel render 'Hello'` means the text.
    auto word = lone_word_as_text(
        args.font.file, *args.cmd,
        args.cmd->count("TEXT") + args.cmd->count("--text") + args.cmd->count("--text-file") > 0,
        "--text");
    if (!word) return fail_runtime(word.error().message);
    const bool text_from_font_word = word->has_value();
    if (text_from_font_word) args.text = std::move(**word);

    TextRenderOptions options;
    options.shape.size_px = args.font.size_px;
    options.hinting = hinting_of(args.font);
    options.slant = args.slant;
    options.shape.bold = args.bold;
    auto features = parse_features(args.features);
    if (!features) return fail_usage("--features: " + features.error().message, kRenderCommand);
    options.shape.features = std::move(*features);
    auto variations = requested_variations(args.font);
    if (!variations) return fail_runtime(variations.error().message);
    options.shape.variations = std::move(*variations);
    auto direction = parse_direction(args.direction);
    if (!direction) return fail_usage(direction.error().message, kRenderCommand);
    options.shape.direction = *direction;
    options.shape.script = args.script;
    options.shape.language = args.language;

    auto fg = parse_color(args.foreground);
    if (!fg) return fail_usage("--foreground: " + fg.error().message, kRenderCommand);
    auto bg = parse_color(args.background);
    if (!bg) return fail_usage("--background: " + bg.error().message, kRenderCommand);
    options.foreground = *fg;
    options.background = *bg;
    auto color = color_options(args.color);
    if (!color) return fail_usage(color.error().message, kRenderCommand);
    options.color = std::move(*color);
    options.format = args.lcd.empty() ? CoverageFormat::Gray : CoverageFormat::Lcd;
    options.lcd_order = args.lcd == "bgr" ? LcdOrder::Bgr : LcdOrder::Rgb;

    options.coverage.rendering = *parse_rendering(args.rendering);  // checked by the option
    options.coverage.gamma = args.gamma;
    options.coverage.contrast = args.contrast;
    if (options.coverage.rendering == TextRendering::Linear)
        for (const char* tuning : {"--gamma", "--contrast"})
            if (args.cmd->count(tuning) > 0)
                return fail_usage(std::string(tuning) + ": tunes --rendering perceptual; "
                                  "--rendering linear mixes exact coverage",
                                  kRenderCommand);

    if (args.stroke_px > 0 && args.bold > 0)
        return fail_usage("--font-bold does not combine with --stroke: the outline of the "
                          "emboldened ink is not drawn (stroke the plain glyphs, or fill bold ones)",
                          kRenderCommand);
    if (args.stroke_px > 0 && options.format != CoverageFormat::Gray)
        return fail_usage("--stroke draws gray coverage; it does not combine with --lcd", kRenderCommand);
    if (options.format == CoverageFormat::Lcd && bg->a != 255)
        return fail_usage("--lcd needs an opaque --background: a page's one alpha channel cannot "
                          "hold three subpixel coverages (leave out --lcd for gray text on a "
                          "transparent page)",
                          kRenderCommand);

    if (preview && args.cmd->count("--margin") == 0) args.margin_px = kDefaultPreviewMarginPx;
    options.layout.margin_px = args.margin_px;
    options.layout.width_px = args.width_px;
    // Vertical text's --width is its column length; the terminal's width does not bound it.
    const bool vertical = options.shape.direction == bezel::Direction::TopToBottom ||
                          options.shape.direction == bezel::Direction::BottomToTop;
    if (preview && args.cmd->count("--width") == 0 && columns > 0 && !vertical)
        options.layout.width_px = std::max(1.0, columns - 2 * args.margin_px);
    options.layout.line_height = args.line_height;
    options.layout.align = args.align == "center" ? Align::Center
                           : args.align == "end"  ? Align::End
                                                  : Align::Start;

    std::string text = kSampleText;
    if (args.cmd->count("--text-file") > 0) {
        auto read = read_text_file(args.text_file);
        if (!read) return fail_runtime(read.error().message);
        text = std::move(*read);
    } else if (args.cmd->count("TEXT") + args.cmd->count("--text") > 0 || text_from_font_word) {
        // Text on the command line that is not UTF-8 is a usage error naming the argument (a
        // --text-file's is a runtime one naming the file, read_text_file).
        const std::string where = args.cmd->count("--text") > 0 ? "--text" : "TEXT";
        if (auto valid = decode_utf8(args.text); !valid)
            return fail_usage(where + ": " + valid.error().message, kRenderCommand);
        text = args.text;
    }

    auto fonts = open_font_list(args.font, args.fonts,
                                font_file_given(args.font, *args.cmd), {});
    if (!fonts) return fail_runtime(fonts.error().message);
    if (Status s = check_palette(options.color, *fonts); !s) return fail_runtime(s.error().message);
    auto renderer = TextRenderer::open(std::move(*fonts));
    if (!renderer) return fail_runtime(renderer.error().message);
    const bool gray = options.format == CoverageFormat::Gray && fg->r == fg->g && fg->g == fg->b &&
                      bg->r == bg->g && bg->g == bg->b;
    const bool alpha = fg->a != 255 || bg->a != 255;
    const std::string destination = args.output_file.empty() ? "<stdout>" : args.output_file;
    Expected<FileBytes> bytes = FileBytes();
    MissingGlyphs outlined_missing;
    if (gray && !alpha && args.stroke_px == 0 &&
        (*format == PageFormat::Png || *format == PageFormat::Pgm)) {
        // Gray text to a gray file: the page is one byte per pixel from the start (the same
        // bytes the RGBA page would give after conversion, a quarter of the memory).
        bytes = render_gray_page(*renderer, text, options, *format, args.png, destination);
        // A gray page cannot show colour glyphs: such text becomes an RGB page.
        if (!bytes && renderer->last_text_has_color()) {
            auto page = renderer->render(text, options);
            if (!page) return fail_runtime(page.error().message);
            bytes = encode_page(*page, *format, false, alpha, columns, args.png);
            if (!bytes) return fail_runtime(destination + ": " + bytes.error().message);
        }
    } else {
        auto page = args.stroke_px > 0
                        ? render_outlined(*renderer, text, options, args.stroke_px, outlined_missing)
                        : renderer->render(text, options);
        if (!page) return fail_runtime(page.error().message);
        bytes = encode_page(*page, *format, gray && !alpha && !renderer->last_text_has_color(),
                            alpha, columns, args.png);
        if (!bytes) return fail_runtime(destination + ": " + bytes.error().message);
    }
    if (!bytes) return fail_runtime(bytes.error().message);
    const MissingGlyphs& missing =
        args.stroke_px > 0 ? outlined_missing : renderer->missing_glyphs();
    for (const std::string& w : renderer->fonts().warnings())
        std::cerr << "bezel: warning: " << w << "\n";
    if (const std::size_t svg = renderer->last_text_svg_glyphs(); svg > 0)
        std::cerr << "bezel: warning: " << svg << " glyph" << (svg == 1 ? " is an SVG colour glyph"
                                                                       : "s are SVG colour glyphs")
                  << ", which bezel does not paint: drawn from the outline\n";
    if (Status s = report_missing_glyphs(font_list_names(renderer->fonts()), missing, args.strict);
        !s)
        return fail_runtime(s.error().message);
    return write_result(args.output_file,
                        std::string_view(reinterpret_cast<const char*>(bytes->data()), bytes->size()));
}

}  // namespace

Command add_render_command(CLI::App& app) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App* cmd = app.add_subcommand(
        "render", "Render a paragraph of text to PNG, PGM, PPM or a terminal preview");
    args->cmd = cmd;
    args->font.size_px = kDefaultRenderSizePx;
    cmd->footer(
        "With no TEXT, a sample paragraph. With no -o, PNG to stdout, or an ANSI preview when\n"
        "stdout is a terminal (then --font-size defaults to 10, --margin to 1 and horizontal lines\n"
        "wrap at the terminal's width). Colours: #RRGGBB, #RRGGBBAA, #RGB, #RGBA, a CSS colour name\n"
        "(yellow, rebeccapurple, ...) or transparent. PNG is gray for gray-on-gray, RGBA for\n"
        "translucent colours. Characters the font lacks are drawn as its .notdef box, with a\n"
        "warning (an error with --strict).\n"
        "Examples:\n"
        "  bezel render -o hello.png\n"
        "  bezel render DejaVuSans.ttf 'Wafer office' --font-size 48 --features=-liga -o w.png\n"
        "  bezel render --text-file page.txt --width 640 --align center -o page.png\n"
        "  bezel render NotoSansCJKjp-Subset.otf '縦書き、「日本語」' --direction ttb -o v.png\n"
        "  bezel render 'Outline' --font-size 96 --stroke 2 -o outline.png\n"
        "  bezel render -O ansi 'Hello'");
    add_font_args(*cmd, args->font);
    add_font_list_options(*cmd, args->fonts);
    add_color_options(*cmd, args->color);
    add_slant_option(*cmd, args->slant);
    add_bold_option(*cmd, args->bold);
    cmd->add_option("TEXT", args->text, "The text (UTF-8); default: a sample paragraph");
    cmd->add_option("--text", args->text, "The text, as hb-view's --text")->type_name("STRING");
    cmd->add_option("--text-file", args->text_file, "Read the text from a file ('-': stdin)")
        ->type_name("FILE");
    cmd->add_option("--features", args->features,
                    "OpenType features, hb-view syntax: \"kern,-liga,+smcp,aalt=2\"")
        ->type_name("LIST")
        ->check(parse_check([](const std::string& v) { return parse_features(v); }, "features"));
    cmd->add_option("--direction", args->direction,
                    "ltr, rtl or auto: the paragraph's base direction (default auto: from its "
                    "first strong character); runs of the other direction inside it are still "
                    "ordered by bidi, where hb-view's --direction shapes all of the text one way. "
                    "ttb or btt: vertical text, one column per paragraph, columns right to left, "
                    "as hb-view draws them")
        ->type_name("DIR");
    cmd->add_option("--script", args->script, "ISO 15924 script tag, e.g. Arab (default: from the text)")
        ->type_name("TAG")
        ->check(parse_check(check_script_tag, "script"));
    cmd->add_option("--language", args->language, "BCP 47 language tag, e.g. ar")
        ->type_name("TAG")
        ->check(parse_check(check_language_tag, "language"));
    cmd->add_option("--width", args->width_px,
                    "Wrap lines to this width in pixels (default: no wrapping, only the text's "
                    "newlines); vertical text (--direction ttb/btt): wrap columns at this height")
        ->type_name("PX")
        ->check(in_range(0.0, static_cast<double>(kMaxImageDim)));
    cmd->add_option("--margin", args->margin_px, "Margin on all four sides, pixels (default 16)")
        ->type_name("PX")
        ->check(in_range(0.0, static_cast<double>(kMaxImageDim)));
    cmd->add_option("--line-height", args->line_height,
                    "Baseline distance as a multiple of the font's line height (default 1); "
                    "vertical text: the distance between columns, a multiple of the vertical "
                    "line height")
        ->type_name("X")
        ->check(in_range(0.0, 100.0));
    cmd->add_option("--align", args->align, "start, center or end (default start)")
        ->type_name("ALIGN")
        ->check(CLI::IsMember({"start", "center", "end"}));
    cmd->add_option("--foreground", args->foreground, "Text colour (default #000000)")
        ->type_name("COLOR");
    cmd->add_option("--background", args->background, "Page colour (default #FFFFFF)")
        ->type_name("COLOR");
    cmd->add_option("--lcd", args->lcd, "LCD subpixel rendering for rgb or bgr panels")
        ->type_name("ORDER")
        ->check(CLI::IsMember({"rgb", "bgr"}));
    cmd->add_option("--rendering", args->rendering,
                    "How coverage becomes ink: perceptual (default: text as heavy as hb-view "
                    "draws it, both dark on light and light on dark) or linear (exact coverage "
                    "mixed in linear light, for compositing)")
        ->type_name("NAME")
        ->check(parse_check(parse_rendering, "rendering"));
    cmd->add_option("--gamma", args->gamma,
                    "perceptual: mix coverage as if pixel values v were light v^G; 1 mixes the "
                    "encoded values as they are (as hb-view), 2.2 is near linear light "
                    "(default " + svg_number(kDefaultTextGamma) + ", range 1-3)")
        ->type_name("G")
        ->check(parse_check(parse_text_gamma, "gamma"));
    cmd->add_option("--contrast", args->contrast,
                    "perceptual: lift coverage c by C*c*(1-c) first, heavier text in both "
                    "polarities (default " + svg_number(kDefaultTextContrast) + ", range 0-1)")
        ->type_name("C")
        ->check(parse_check(parse_text_contrast, "contrast"));
    cmd->add_option("--stroke", args->stroke_px,
                    "Outlined text: stroke each glyph's outline this many pixels wide (round "
                    "joins) instead of filling it")
        ->type_name("PX")
        ->check(in_range(0.0, kMaxStrokePx));
    cmd->add_option("-O,--output-format", args->format,
                    "png, pgm, ppm or ansi; default: from the -o file's extension")
        ->type_name("FORMAT");
    cmd->add_option("-o,--output-file", args->output_file,
                    "Write here instead of stdout (atomically: no partial file on failure)")
        ->type_name("FILE");
    add_strict_option(*cmd, args->strict);
    add_compression_option(*cmd, args->png);
    return Command{cmd, [args] { return run_render(*args); }};
}

}  // namespace bezel::cli
