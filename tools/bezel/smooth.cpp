// `bezel smooth`: a smooth curve through (or guided by) a list of points — Chaikin corner cutting
// and its limit, uniform cubic B-splines, natural C² splines, Catmull-Rom, Hermite — as the
// stable JSON, SVG path data, an annotated SVG or a PNG (see smooth_output.hpp).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <memory>

#include "bezel/smooth.hpp"
#include "cli_common.hpp"
#include "commands.hpp"
#include "picture.hpp"
#include "parse_check.hpp"
#include "smooth_output.hpp"

namespace bezel::cli {
namespace {

constexpr const char* kSmoothCommand = "bezel smooth";

struct SmoothArgs {
    PngOptions png;  // --compression
    std::string method;             // --method
    std::string points;             // --points
    std::string points_file;        // --points-file
    bool closed = false;            // --closed
    int iterations = 4;             // --iterations (chaikin)
    bool limit = false;             // --limit (chaikin)
    double alpha = kCatmullRomCentripetal;          // --alpha (catmull-rom)
    double tension = kCatmullRomStandardTension;    // --tension (catmull-rom, hermite)
    std::string tangents;           // --tangents (hermite)
    std::string param = "uniform";  // --param (natural)
    bool free_ends = false;         // --free-ends (bspline)
    std::string format;             // -O
    std::string output_file;        // -o
    std::string foreground, background;   // png: ink and paper ("": black on white)
    CLI::App* cmd = nullptr;
};

enum class SmoothFormat { Json, Svg, Path, Png };

// -O wins; else the -o file's extension (.json, .svg, .png, .path/.txt); else JSON.
Expected<SmoothFormat> pick_format(const SmoothArgs& args) {
    auto picked = pick_output_format(
        args.format, args.output_file,
        {{".json", "json"}, {".svg", "svg"}, {".png", "png"}, {".path", "path"}, {".txt", "path", false}},
        "json");
    if (!picked) return picked.error();
    const std::string& name = *picked;
    if (name == "json") return SmoothFormat::Json;
    if (name == "svg") return SmoothFormat::Svg;
    if (name == "path") return SmoothFormat::Path;
    if (name == "png") return SmoothFormat::Png;
    return Error{"-O '" + name + "': unknown output format (expected json, svg, path or png)"};
}

// Options that only one method reads are refused with the others, rather than silently ignored.
Status check_method_options(const SmoothArgs& args) {
    struct Only {
        const char* option;
        std::vector<const char*> methods;
    };
    const Only only[] = {{"--iterations", {"chaikin"}},        {"--limit", {"chaikin"}},
                         {"--alpha", {"catmull-rom"}},         {"--tension", {"catmull-rom", "hermite"}},
                         {"--tangents", {"hermite"}},          {"--param", {"natural"}},
                         {"--free-ends", {"bspline"}}};
    for (const Only& o : only) {
        if (args.cmd->count(o.option) == 0) continue;
        bool fits = std::find(o.methods.begin(), o.methods.end(), args.method) != o.methods.end();
        if (!fits) {
            std::string list;
            for (const char* m : o.methods) list += (list.empty() ? "" : " or ") + std::string(m);
            return Error{std::string(o.option) + " applies only to --method " + list};
        }
    }
    if (args.cmd->count("--tangents") > 0 && args.cmd->count("--tension") > 0)
        return Error{"--tangents and --tension exclude each other (--tension sets cardinal tangents)"};
    return ok_status();
}

int run_smooth(const SmoothArgs& args) {
    auto format = pick_format(args);
    if (!format) return fail_usage(format.error().message, kSmoothCommand);
    if (auto ok = check_method_options(args); !ok) return fail_usage(ok.error().message, kSmoothCommand);

    Expected<std::vector<Vec2>> points = args.cmd->count("--points") > 0
                                             ? parse_vec2_list(args.points, "--points")
                                             : read_points_file(args.points_file);
    if (!points)
        return args.cmd->count("--points") > 0 ? fail_usage(points.error().message, kSmoothCommand)
                                               : fail_runtime(points.error().message);

    SmoothReport report;
    report.method = args.method;
    report.input = *points;
    report.closed = args.closed;

    Expected<Path> curve = Error{""};
    const std::string& m = args.method;
    if (m == "chaikin") {
        ChaikinOptions options{args.closed, true};
        if (args.limit) {
            curve = chaikin_limit(*points, options);
        } else {
            auto poly = chaikin(*points, args.iterations, options);
            if (!poly) return fail_runtime(poly.error().message);
            report.polyline = true;
            report.points = std::move(*poly);
            curve = Path{};
        }
    } else if (m == "bspline") {
        curve = bspline(*points, {args.closed, !args.free_ends});
    } else if (m == "natural") {
        SplineParam param = args.param == "chord" ? SplineParam::ChordLength : SplineParam::Uniform;
        curve = natural_spline(*points, {args.closed, param});
    } else if (m == "catmull-rom") {
        curve = catmull_rom(*points, {args.closed, args.alpha, args.tension});
    } else {  // hermite (CLI11 checked the name)
        if (args.cmd->count("--tangents") > 0) {
            auto tangents = parse_vec2_list(args.tangents, "--tangents");
            if (!tangents) return fail_usage(tangents.error().message, kSmoothCommand);
            curve = hermite(*points, *tangents, args.closed);
        } else {
            curve = cardinal_spline(*points, args.tension, args.closed);
        }
    }
    if (!curve) return fail_runtime(curve.error().message);
    report.curve = std::move(*curve);

    std::string document;
    switch (*format) {
        case SmoothFormat::Json: document = format_smooth_json(report); break;
        case SmoothFormat::Path: document = format_smooth_path(report); break;
        case SmoothFormat::Svg: document = format_smooth_svg(report); break;
        case SmoothFormat::Png: {
            auto colours = picture_colours(args.foreground, args.background);
            if (!colours) return fail_usage(colours.error().message, kSmoothCommand);
            auto png = format_smooth_png(report, *colours, args.png);
            if (!png) return fail_runtime(png.error().message);
            document = std::move(*png);
            break;
        }
    }
    return write_result(args.output_file, document);
}

}  // namespace

Command add_smooth_command(CLI::App& app) {
    auto args = std::make_shared<SmoothArgs>();
    CLI::App* cmd = app.add_subcommand(
        "smooth", "Smooth a point list: Chaikin, B-spline, natural spline, Catmull-Rom, Hermite");
    args->cmd = cmd;
    cmd->footer(
        "Points are x,y pairs (commas and/or spaces), in any units, y down. JSON output:\n"
        "  {\"segments\": [[[x,y],[x,y],[x,y],[x,y]], ...]} cubic pieces, or for Chaikin's\n"
        "  polygon {\"points\": [[x,y], ...]}, which --points-file reads back.\n"
        "Examples:\n"
        "  bezel smooth --method natural --points '0,0 40,60 100,20 160,80'\n"
        "  bezel smooth --method catmull-rom --alpha 0.5 --closed --points-file pts.json -o c.svg\n"
        "  bezel smooth --method chaikin --iterations 3 --points '0,0 100,0 100,100' -O path\n"
        "  bezel smooth --method hermite --points '0,0 100,0' --tangents '0,-150 0,150' -o h.png");
    cmd->add_option("--method", args->method,
                    "chaikin (corner cutting; --limit: its quadratic B-spline), bspline (uniform "
                    "cubic, ends pinned), natural (C2 interpolating), catmull-rom, hermite")
        ->required()
        ->type_name("METHOD")
        ->check(CLI::IsMember({"chaikin", "bspline", "natural", "catmull-rom", "hermite"}));
    CLI::Option_group* input = cmd->add_option_group("input", "The points, exactly one of:");
    input->add_option("--points", args->points, "\"x,y x,y ...\"")->type_name("LIST");
    input->add_option("--points-file", args->points_file,
                      "A file ('-': stdin) with x,y pairs, or JSON {\"points\": [[x,y], ...]}")
        ->type_name("FILE");
    input->require_option(1);
    cmd->add_flag("--closed", args->closed,
                  "A closed curve (a last point equal to the first is dropped)");
    cmd->add_option("--iterations", args->iterations, "chaikin: rounds of corner cutting (default 4)")
        ->type_name("N")
        ->check(in_range(0, kMaxChaikinIterations));
    cmd->add_flag("--limit", args->limit,
                  "chaikin: the limit curve (uniform quadratic B-spline) instead of the polygon");
    cmd->add_option("--alpha", args->alpha,
                    "catmull-rom: knot exponent, 0 uniform, 0.5 centripetal (default), 1 chordal")
        ->type_name("A")
        ->check(in_range(0.0, 1.0));
    cmd->add_option("--tension", args->tension,
                    "catmull-rom, hermite without --tangents: tangent scale τ (default 0.5, the "
                    "standard Catmull-Rom; 0 gives straight pieces)")
        ->type_name("T")
        ->check(in_range(0.0, 1e6));
    cmd->add_option("--tangents", args->tangents,
                    "hermite: one derivative dx,dy per point (default: cardinal, from --tension)")
        ->type_name("LIST");
    cmd->add_option("--param", args->param, "natural: knot spacing, uniform (default) or chord")
        ->type_name("P")
        ->check(CLI::IsMember({"uniform", "chord"}));
    cmd->add_flag("--free-ends", args->free_ends,
                  "bspline: do not pin the ends (the curve starts near the 2nd point)");
    cmd->add_option("-O,--output-format", args->format,
                    "json, svg, path or png; default: from the -o file's extension, else json")
        ->type_name("FORMAT")
        ->check(CLI::IsMember({"json", "svg", "path", "png"}));
    cmd->add_option("-o,--output-file", args->output_file,
                    "Write here instead of stdout (atomically: no partial file on failure)")
        ->type_name("FILE");
    add_colour_options(*cmd, args->foreground, args->background);
    add_compression_option(*cmd, args->png);
    return Command{cmd, [args] { return run_smooth(*args); }};
}

}  // namespace bezel::cli
