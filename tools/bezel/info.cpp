// `bezel info`: what a font file holds — names, metrics, glyph count, outline format, variation
// axes and named instances, the table directory, and the scripts its cmap covers.
#include <CLI/CLI.hpp>
#include <memory>

#include "cli_common.hpp"
#include "commands.hpp"
#include "parse_check.hpp"
#include "info.hpp"

namespace bezel::cli {
namespace {

struct InfoArgs {
    std::string file = BEZEL_DEFAULT_FONT;
    int face_index = 0;
    std::string format;        // -O
    std::string output_file;   // -o
};

int run_info(const InfoArgs& args) {
    auto format = choose_format(args.format, args.output_file, OutputFormat::Text);
    if (!format) return fail_usage(format.error().message, "bezel info");
    if (*format == OutputFormat::Svg)
        return fail_usage(args.output_file + ": bezel info writes text or JSON, not SVG",
                          "bezel info");
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
    cmd->footer(
        "Metrics are font units, y up. A script counts as covered when the cmap maps a few\n"
        "representative letters of it.\n"
        "Examples:\n"
        "  bezel info\n"
        "  bezel info font.ttc --face-index 1 -O json\n"
        "  bezel info font.otf -o info.json");
    cmd->add_option("FONT", args->file,
                    "Font file (TTF, OTF, TTC/OTC); default: the bundled DejaVu Sans")
        ->capture_default_str()
        ->type_name("FILE");
    cmd->add_option("--face-index", args->face_index, "Face to describe in a font collection")
        ->capture_default_str()
        ->check(non_negative_number());
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
