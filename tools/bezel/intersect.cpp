// `bezel intersect`: where two paths meet (or where one path meets itself), as text, JSON, an
// annotated SVG or a PNG (see intersect_output.hpp for the formats).
#include <CLI/CLI.hpp>
#include <memory>

#include "cli_common.hpp"
#include "commands.hpp"
#include "picture.hpp"
#include "intersect_output.hpp"

namespace bezel::cli {
namespace {

struct IntersectArgs {
    PngOptions png;  // --compression
    std::string path_a, path_b;  // SVG path data
    std::string format;          // -O
    std::string output_file;     // -o
    std::string foreground, background;   // png: ink and paper ("": black on white)
    CLI::Option* b_option = nullptr;
};

enum class IntersectFormat { Text, Json, Svg, Png };

// -O wins; else the -o file's extension (.txt, .json, .svg, .png); else text.
Expected<IntersectFormat> pick_format(const IntersectArgs& args) {
    auto name = pick_output_format(
        args.format, args.output_file,
        {{".txt", "text"}, {".json", "json"}, {".svg", "svg"}, {".png", "png", false}}, "text");
    if (!name) return name.error();
    if (*name == "png") return IntersectFormat::Png;
    if (*name == "json") return IntersectFormat::Json;
    if (*name == "svg") return IntersectFormat::Svg;
    return IntersectFormat::Text;   // CLI11 checked the name
}

int run_intersect(const IntersectArgs& args) {
    const std::string command = "bezel intersect";
    auto format = pick_format(args);
    if (!format) return fail_usage(format.error().message, command);

    IntersectReport report;
    auto a = parse_svg_path(args.path_a);
    if (!a) return fail_usage("PATH_A: " + a.error().message, command);
    report.a = std::move(*a);
    report.self = args.b_option->count() == 0;
    if (!report.self) {
        auto b = parse_svg_path(args.path_b);
        if (!b) return fail_usage("PATH_B: " + b.error().message, command);
        report.b = std::move(*b);
    }

    auto result = report.self ? self_intersect_path(report.a) : intersect_paths(report.a, report.b);
    if (!result) return fail_runtime(result.error().message);
    report.result = std::move(*result);

    std::string document;
    switch (*format) {
        case IntersectFormat::Text: document = format_intersect_text(report); break;
        case IntersectFormat::Json: document = format_intersect_json(report); break;
        case IntersectFormat::Svg: document = format_intersect_svg(report); break;
        case IntersectFormat::Png: {
            auto colours = picture_colours(args.foreground, args.background);
            if (!colours) return fail_usage(colours.error().message, command);
            auto png = format_intersect_png(report, *colours, args.png);
            if (!png) return fail_runtime(png.error().message);
            document = std::move(*png);
            break;
        }
    }
    return write_result(args.output_file, document);
}

}  // namespace

Command add_intersect_command(CLI::App& app) {
    auto args = std::make_shared<IntersectArgs>();
    CLI::App* cmd = app.add_subcommand(
        "intersect", "Where two paths cross, touch or overlap (one path: its self-intersections)");
    cmd->footer(
        "Paths are SVG path data. Segments are numbered from 0 over the whole path; the implicit\n"
        "closing line of a closed contour counts. t is the parameter within the segment.\n"
        "Examples:\n"
        "  bezel intersect 'M0,0 C10,10 20,-10 30,0' 'M0,5 L30,-5'\n"
        "  bezel intersect 'M0,0 C30,30 -10,30 20,0' -O json\n"
        "  bezel intersect 'M0,0 L10,10' 'M0,10 L10,0' -o crossing.svg");
    cmd->add_option("PATH_A", args->path_a, "First path (SVG path data)")->required();
    args->b_option = cmd->add_option("PATH_B", args->path_b, "Second path; omit for self-intersections");
    cmd->add_option("-O,--output-format", args->format,
                    "text, json, svg or png; default: from the -o file's extension, else text")
        ->type_name("FORMAT")
        ->check(CLI::IsMember({"text", "json", "svg", "png"}));
    cmd->add_option("-o,--output-file", args->output_file,
                    "Write here instead of stdout (atomically: no partial file on failure)")
        ->type_name("FILE");
    add_colour_options(*cmd, args->foreground, args->background);
    add_compression_option(*cmd, args->png);
    return Command{cmd, [args] { return run_intersect(*args); }};
}

}  // namespace bezel::cli
