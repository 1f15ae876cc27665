// `bezel info`: what a font file holds — names, metrics, glyph count, outline format, variation
// axes and named instances, the table directory, and the scripts its cmap covers.
#include <CLI/CLI.hpp>
#include <memory>

#include "cli_common.hpp"
#include "commands.hpp"
#include "font_args.hpp"
#include "font_list.hpp"
#include "parse_check.hpp"
#include "info.hpp"

namespace bezel::cli {
namespace {

constexpr const char* kInfoCommand = "bezel info";

struct InfoArgs {
    std::string file = BEZEL_DEFAULT_FONT;
    int face_index = 0;
    FontListArgs fonts;        // --font, --fallback (with --coverage)
    std::string coverage;      // --coverage or TEXT
    std::string format;        // -O
    std::string output_file;   // -o
    CLI::App* cmd = nullptr;
};

// --coverage: which of the text's characters the font maps.
int run_coverage(const InfoArgs& args, OutputFormat format) {
    auto text = decode_utf8(args.coverage);
    if (!text) return fail_usage("--coverage: " + text.error().message, kInfoCommand);
    if (text->size() > kMaxTextCodePoints)
        return fail_usage("--coverage: " + std::to_string(text->size()) +
                              " characters, more than the " + std::to_string(kMaxTextCodePoints) +
                              " allowed",
                          kInfoCommand);
    FontArgs font_args;
    font_args.file = args.file;
    font_args.face_index = args.face_index;
    CoverageReport report;
    if (has_font_list(args.fonts)) {
        auto fonts = open_font_list(font_args, args.fonts, font_file_given(font_args, *args.cmd), {});
        if (!fonts) return fail_runtime(fonts.error().message);
        auto listed = coverage_of(*fonts, args.coverage);
        if (!listed) return fail_runtime(listed.error().message);
        report = std::move(*listed);
    } else {
        auto font = open_font(font_args);
        if (!font) return fail_runtime(font.error().message);
        report = coverage_of(*font, *text);
    }
    return write_result(args.output_file, format == OutputFormat::Json
                                              ? format_coverage_json(report)
                                              : format_coverage_text(report));
}

int run_info(InfoArgs& args) {
    auto format = choose_format(args.format, args.output_file, OutputFormat::Text);
    if (!format) return fail_usage(format.error().message, kInfoCommand);
    if (*format == OutputFormat::Svg)
        return fail_usage(args.output_file + ": bezel info writes text or JSON, not SVG",
                          kInfoCommand);
    const std::size_t given = args.cmd->count("--coverage") + args.cmd->count("TEXT");
    if (given > 1) return fail_usage("give the text once: --coverage or TEXT", kInfoCommand);
    auto word = lone_word_as_text(args.file, *args.cmd, given > 0, "--coverage");
    if (!word) return fail_runtime(word.error().message);
    if (word->has_value()) args.coverage = std::move(**word);
    if (given > 0 || word->has_value()) return run_coverage(args, *format);
    if (has_font_list(args.fonts))
        return fail_usage("--font and --fallback go with --coverage (a font list's coverage); "
                          "describe one font at a time",
                          kInfoCommand);
    auto info = font_info(args.file, args.face_index);
    if (!info) return fail_runtime(info.error().message);
    const std::string document =
        *format == OutputFormat::Json ? format_info_json(*info) : format_info_text(*info);
    return write_result(args.output_file, document);
}

}  // namespace

Command add_info_command(CLI::App& app) {
    auto args = std::make_shared<InfoArgs>();
    CLI::App* cmd = app.add_subcommand(
        "info", "Describe a font: names, metrics, axes, glyph count, tables, scripts covered");
    args->cmd = cmd;
    cmd->footer(
        "Metrics are font units, y up. A script counts as covered when the cmap maps a few\n"
        "representative letters of it. With --coverage (or TEXT: a lone word that is no font\n"
        "file), only which of the text's characters the font maps, each once; with --font or\n"
        "--fallback, which font of the list draws each (font fallback, as render draws it).\n"
        "\"colour\" lists the colour-glyph tables (COLRv1, COLRv0, CBDT, sbix; SVG glyphs are\n"
        "drawn from their outlines) and each CPAL palette's entries (--palette N picks one).\n"
        "Examples:\n"
        "  bezel info\n"
        "  bezel info 'Grüße, Ελλάδα'\n"
        "  bezel info font.ttc --face-index 1 -O json\n"
        "  bezel info font.otf -o info.json");
    cmd->add_option("FONT", args->file,
                    "Font file (TTF, OTF, TTC/OTC); default: the bundled DejaVu Sans")
        ->capture_default_str()
        ->type_name("FILE");
    cmd->add_option("TEXT", args->coverage, "Text whose coverage to report, as --coverage");
    cmd->add_option("--face-index", args->face_index, "Face to describe in a font collection")
        ->capture_default_str()
        ->check(non_negative_number());
    cmd->add_option("--coverage", args->coverage,
                    "Report which characters of this text (UTF-8) the font maps, instead of the "
                    "description")
        ->type_name("TEXT");
    add_font_list_options(*cmd, args->fonts);
    cmd->add_option("-O,--output-format", args->format,
                    "text or json; default: from the -o file's extension, else text")
        ->type_name("FORMAT")
        ->check(CLI::IsMember({"text", "json"}));
    cmd->add_option("-o,--output-file", args->output_file,
                    "Write here instead of stdout (atomically: no partial file on failure)")
        ->type_name("FILE");
    return Command{cmd, [args] { return run_info(*args); }};
}

}  // namespace bezel::cli
