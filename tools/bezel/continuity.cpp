// `bezel continuity`: the continuity class (C0 / G1 / C1 / C2, or broken) of every joint of an
// SVG path, as text or JSON (see smooth_output.hpp).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <memory>

#include "bezel/smooth.hpp"
#include "cli_common.hpp"
#include "commands.hpp"
#include "parse_check.hpp"
#include "smooth_output.hpp"

namespace bezel::cli {
namespace {

constexpr const char* kContinuityCommand = "bezel continuity";

struct ContinuityArgs {
    std::string path;  // SVG path data
    double tolerance = kDefaultContinuityTolerance;
    std::string format;       // -O
    std::string output_file;  // -o
};

int run_continuity(const ContinuityArgs& args) {
    auto format = choose_format(args.format, args.output_file, OutputFormat::Text);
    if (!format) return fail_usage(format.error().message, kContinuityCommand);
    if (*format == OutputFormat::Svg)
        return fail_usage("-O svg: continuity prints text or json", kContinuityCommand);
    auto path = parse_svg_path(args.path);
    if (!path) return fail_usage("PATH: " + path.error().message, kContinuityCommand);
    auto joints = analyze_continuity(*path, args.tolerance);
    if (!joints) return fail_runtime(joints.error().message);
    std::string document = *format == OutputFormat::Json
                               ? format_continuity_json(*joints, args.tolerance)
                               : format_continuity_text(*joints, args.tolerance);
    return write_result(args.output_file, document);
}

}  // namespace

Command add_continuity_command(CLI::App& app) {
    auto args = std::make_shared<ContinuityArgs>();
    CLI::App* cmd = app.add_subcommand(
        "continuity", "Classify each joint of an SVG path as C0, G1, C1 or C2");
    cmd->footer(
        "A joint is where a segment ends and the next begins within a contour, and for a\n"
        "closed contour (Z) the last segment back to the first. Classes, each implying the\n"
        "previous: C0 the pieces meet; G1 same tangent direction (angle <= tolerance rad);\n"
        "C1 equal first derivatives; C2 equal second derivatives, where equal means\n"
        "|a - b| <= tolerance * max(|a|, |b|, size of the two pieces).\n"
        "Examples:\n"
        "  bezel continuity 'M0 0 C1 1 2 1 3 0 S5 -1 6 0'\n"
        "  bezel continuity \"$(bezel smooth --method natural --points '0,0 1,2 3,1' -O path)\" -O json");
    cmd->add_option("PATH", args->path, "SVG path data")->required()->type_name("PATH");
    cmd->add_option("--tolerance", args->tolerance,
                    "Relative tolerance of the tests (default 1e-9)")
        ->type_name("T")
        ->check(positive_number());
    cmd->add_option("-O,--output-format", args->format,
                    "text or json; default: from the -o file's extension, else text")
        ->type_name("FORMAT")
        ->check(CLI::IsMember({"text", "json"}));
    cmd->add_option("-o,--output-file", args->output_file,
                    "Write here instead of stdout (atomically: no partial file on failure)")
        ->type_name("FILE");
    return Command{cmd, [args] { return run_continuity(*args); }};
}

}  // namespace bezel::cli
