// `bezel stroke`: the outline of a stroked path (joins, caps, dashes) as SVG path data, an SVG
// picture, or a PNG drawn with bezel's own rasterizer.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>

#include "bezel/stroke.hpp"
#include "cli_common.hpp"
#include "commands.hpp"
#include "picture.hpp"
#include "draw.hpp"
#include "stroke_output.hpp"

namespace bezel::cli {
namespace {

constexpr const char* kStrokeCommand = "bezel stroke";

struct StrokeArgs {
    PngOptions png;  // --compression
    std::string path;         // PATH (SVG path data)
    std::string path_file;    // --path-file
    double width = 1;         // --width
    std::string join = "miter", cap = "butt";
    double miter_limit = 4;   // --miter-limit
    std::string dash;         // --dash
    double dash_offset = 0;   // --dash-offset
    double tolerance = 0.01;  // --tolerance
    std::string size;         // --size WxH (png)
    std::string transform;    // --transform a,b,c,d,e,f (png)
    std::string format;       // -O
    std::string output_file;  // -o
    std::string foreground, background;   // png: ink and paper ("": black on white)
    CLI::App* cmd = nullptr;
};

// -O wins; else the -o file's extension (.svg, .png, .path/.txt); else path data.
Expected<StrokeFormat> pick_format(const StrokeArgs& args) {
    auto picked = pick_output_format(
        args.format, args.output_file,
        {{".path", "path"}, {".svg", "svg"}, {".png", "png"}, {".txt", "path", false}}, "path");
    if (!picked) return picked.error();
    const std::string& name = *picked;
    if (name == "path") return StrokeFormat::Path;
    if (name == "svg") return StrokeFormat::Svg;
    return StrokeFormat::Png;  // CLI11 checked the name
}

// Numbers separated by commas and/or whitespace; `what` names the option in errors.
Expected<std::vector<double>> parse_numbers(const std::string& text, const std::string& what) {
    std::vector<double> out;
    const char* s = text.c_str();
    while (true) {
        while (*s == ',' || std::isspace(static_cast<unsigned char>(*s))) ++s;
        if (*s == '\0') break;
        char* end = nullptr;
        double v = std::strtod(s, &end);
        if (end == s || !std::isfinite(v))
            return Error{what + " '" + text + "': expected a number at '" + std::string(s) + "'"};
        out.push_back(v);
        s = end;
    }
    return out;
}

Expected<StrokeStyle> style_of(const StrokeArgs& args) {
    StrokeStyle s;
    if (!(std::isfinite(args.width) && args.width > 0))
        return Error{"--width " + svg_number(args.width) + ": must be a finite number > 0"};
    if (!(args.miter_limit >= 1))
        return Error{"--miter-limit " + svg_number(args.miter_limit) + ": must be >= 1"};
    if (!(std::isfinite(args.tolerance) && args.tolerance > 0))
        return Error{"--tolerance " + svg_number(args.tolerance) + ": must be a finite number > 0"};
    s.width = args.width;
    s.miter_limit = args.miter_limit;
    s.tolerance = args.tolerance;
    s.join = args.join == "round" ? LineJoin::Round : args.join == "bevel" ? LineJoin::Bevel
                                                                           : LineJoin::Miter;
    s.cap = args.cap == "round" ? LineCap::Round : args.cap == "square" ? LineCap::Square
                                                                        : LineCap::Butt;
    if (!args.dash.empty()) {
        auto d = parse_numbers(args.dash, "--dash");
        if (!d) return d.error();
        s.dashes = std::move(*d);
        double sum = 0;
        for (double v : s.dashes) {
            if (v < 0) return Error{"--dash '" + args.dash + "': lengths must be >= 0"};
            sum += v;
        }
        if (!(sum > 0)) return Error{"--dash '" + args.dash + "': the lengths must not all be 0"};
    }
    if (!std::isfinite(args.dash_offset))
        return Error{"--dash-offset: must be a finite number"};
    s.dash_offset = args.dash_offset;
    return s;
}

Expected<PngFrame> frame_of(const StrokeArgs& args) {
    PngFrame f;
    if (!args.transform.empty()) {
        auto m = parse_numbers(args.transform, "--transform");
        if (!m) return m.error();
        if (m->size() != 6)
            return Error{"--transform '" + args.transform + "': expected 6 numbers a,b,c,d,e,f"};
        f.transform = {(*m)[0], (*m)[1], (*m)[2], (*m)[3], (*m)[4], (*m)[5]};
    }
    if (!args.size.empty()) {
        int w = 0, h = 0;
        char x = 0, extra = 0;
        std::istringstream in(args.size);
        if (!(in >> w >> x >> h) || (x != 'x' && x != 'X') || (in >> extra) || w < 1 || h < 1 ||
            w > kMaxStrokePngDim || h > kMaxStrokePngDim)
            return Error{"--size '" + args.size + "': expected WxH, each 1.." +
                         std::to_string(kMaxStrokePngDim)};
        f.width = w;
        f.height = h;
    }
    return f;
}

Expected<std::string> read_path_file(const std::string& file) {
    std::ostringstream data;
    if (file == "-") {
        data << std::cin.rdbuf();
    } else {
        std::ifstream in(file, std::ios::binary);
        if (!in) return Error{file + ": cannot open the path file"};
        data << in.rdbuf();
    }
    return data.str();
}

int run_stroke(const StrokeArgs& args) {
    if (args.cmd->count("PATH") + args.cmd->count("--path-file") != 1)
        return fail_usage("the path: give PATH or --path-file (exactly one)", kStrokeCommand);
    auto format = pick_format(args);
    if (!format) return fail_usage(format.error().message, kStrokeCommand);
    auto style = style_of(args);
    if (!style) return fail_usage(style.error().message, kStrokeCommand);
    bool png_only = !args.size.empty() || !args.transform.empty();
    if (png_only && *format != StrokeFormat::Png)
        return fail_usage("--size and --transform apply only to -O png", kStrokeCommand);
    auto frame = frame_of(args);
    if (!frame) return fail_usage(frame.error().message, kStrokeCommand);

    std::string data = args.path;
    std::string input = "PATH";
    if (args.cmd->count("--path-file") > 0) {
        auto text = read_path_file(args.path_file);
        if (!text) return fail_runtime(text.error().message);
        data = std::move(*text);
        input = args.path_file;
    }
    auto path = parse_svg_path(data);
    if (!path) {
        std::string msg = input + ": " + path.error().message;
        return args.cmd->count("--path-file") > 0 ? fail_runtime(msg) : fail_usage(msg, kStrokeCommand);
    }
    auto outline = stroke(*path, *style);
    if (!outline) return fail_runtime(input + ": " + outline.error().message);

    std::string document;
    switch (*format) {
        case StrokeFormat::Path: document = to_svg_path(*outline) + "\n"; break;
        case StrokeFormat::Svg: document = format_stroke_svg(*path, *outline, *style); break;
        case StrokeFormat::Png: {
            auto colours = picture_colours(args.foreground, args.background);
            if (!colours) return fail_usage(colours.error().message, kStrokeCommand);
            auto png = format_stroke_png(*outline, *frame, *colours, args.png);
            if (!png) return fail_runtime(png.error().message);
            document = std::move(*png);
            break;
        }
    }
    return write_result(args.output_file, document);
}

}  // namespace

Command add_stroke_command(CLI::App& app) {
    auto args = std::make_shared<StrokeArgs>();
    CLI::App* cmd = app.add_subcommand(
        "stroke", "The outline of a stroked path: joins, caps, dashes (path data, SVG or PNG)");
    args->cmd = cmd;
    cmd->footer(
        "The outline is a path that fills the stroke with the non-zero rule (its pieces may\n"
        "overlap). Coordinates are the path's own, y down; PNG pixels are path units unless\n"
        "--transform maps them. Dashes follow SVG's stroke-dasharray / stroke-dashoffset.\n"
        "Examples:\n"
        "  bezel stroke 'M10,10 C40,80 80,-20 110,50' --width 8 --join round --cap round\n"
        "  bezel stroke 'M0,0 L50,0 L50,50 Z' --width 4 --dash 6,3 -o dashed.svg\n"
        "  bezel stroke --path-file glyph.path --width 3 --join round -o glyph.png");
    // PATH or --path-file, exactly one (checked in run_stroke). Not an option group: CLI11 2.1
    // fills a group's positional after the command's own, so the hidden stray-argument
    // positional every command gets (main.cpp) would take PATH, and without that catcher an
    // empty argument after PATH sends CLI11's subcommand lookup into a loop (a fuzz_cli
    // finding: `bezel stroke x "" -l`).
    CLI::Option* path_opt =
        cmd->add_option("PATH", args->path, "SVG path data (or --path-file)")->type_name("PATH");
    cmd->add_option("--path-file", args->path_file, "A file ('-': stdin) holding SVG path data")
        ->type_name("FILE")
        ->excludes(path_opt);
    cmd->add_option("--width", args->width, "Stroke width, path units (default 1)")
        ->type_name("W");
    cmd->add_option("--join", args->join, "miter (default), round or bevel")
        ->type_name("JOIN")
        ->check(CLI::IsMember({"miter", "round", "bevel"}));
    cmd->add_option("--miter-limit", args->miter_limit,
                    "Miter length / width beyond which a miter becomes a bevel (default 4, as SVG)")
        ->type_name("X");
    cmd->add_option("--cap", args->cap, "butt (default), round or square")
        ->type_name("CAP")
        ->check(CLI::IsMember({"butt", "round", "square"}));
    cmd->add_option("--dash", args->dash, "On/off lengths, e.g. \"4,2\" (an odd list repeats)")
        ->type_name("LIST");
    cmd->add_option("--dash-offset", args->dash_offset, "Where the dash pattern starts (default 0)")
        ->type_name("D");
    cmd->add_option("--tolerance", args->tolerance,
                    "Largest distance of the outline from the exact stroke (default 0.01)")
        ->type_name("T");
    cmd->add_option("--size", args->size,
                    "png: canvas WxH in pixels (default: the outline's box plus a margin)")
        ->type_name("WxH");
    cmd->add_option("--transform", args->transform,
                    "png: affine map a,b,c,d,e,f from path units to pixels (x' = ax+cy+e, "
                    "y' = bx+dy+f); without --size the picture is fitted to the mapped outline")
        ->type_name("M");
    cmd->add_option("-O,--output-format", args->format,
                    "path, svg or png; default: from the -o file's extension, else path")
        ->type_name("FORMAT")
        ->check(CLI::IsMember({"path", "svg", "png"}));
    cmd->add_option("-o,--output-file", args->output_file,
                    "Write here instead of stdout (atomically: no partial file on failure)")
        ->type_name("FILE");
    add_colour_options(*cmd, args->foreground, args->background);
    add_compression_option(*cmd, args->png);
    return Command{cmd, [args] { return run_stroke(*args); }};
}

}  // namespace bezel::cli
