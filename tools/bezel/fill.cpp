// `bezel fill`: any vector path (SVG path data) rasterized by bezel into a W × H image: a picture
// (ink on paper, picture.hpp) or the raw coverage (--coverage), as PNG, PGM or ASCII art.
#include <CLI/CLI.hpp>
#include <cmath>
#include <memory>

#include "bezel/image.hpp"
#include "bezel/path.hpp"
#include "bezel/raster.hpp"
#include "cli_common.hpp"
#include "commands.hpp"
#include "glyph_bitmap.hpp"
#include "picture.hpp"

namespace bezel::cli {
namespace {

// Largest --width or --height: 8192 px (a 64 MiB mask). The rasterizer itself takes up to
// kMaxBitmapDim; the tool keeps its output files reasonable.
constexpr int kMaxFillDim = 8192;

enum class FillFormat { Png, Pgm, Ascii };

struct FillArgs {
    PngOptions png;  // --compression
    std::string path_data, format, output_file, fill = "nonzero", transform, overlap = "accumulate";
    std::string foreground, background;   // picture colours ("": black on white)
    bool coverage = false;                // --coverage: the coverage itself, not a picture
    int width = 0, height = 0;
    double tolerance_px = kDefaultRasterTolerancePx;
};

const std::string kFillCommand = "bezel fill";

Expected<FillFormat> pick_format(const FillArgs& args) {
    auto name = pick_output_format(args.format, args.output_file,
                                   {{".png", "png"}, {".pgm", "pgm"}, {".txt", "ascii"}}, "ascii");
    if (!name) return name.error();
    if (*name == "png") return FillFormat::Png;
    if (*name == "pgm") return FillFormat::Pgm;
    return FillFormat::Ascii;
}

// "a,b,c,d,e,f" (SVG matrix order: x' = a·x + c·y + e, y' = b·x + d·y + f).
Expected<Affine> parse_transform(const std::string& text) {
    if (text.empty()) return Affine::identity();
    double v[6];
    std::size_t at = 0;
    for (int i = 0; i < 6; ++i) {
        const std::size_t comma = i < 5 ? text.find(',', at) : text.size();
        if (comma == std::string::npos) break;
        const std::string item = text.substr(at, comma - at);
        const std::optional<double> number = parse_number(item);
        if (!number || !std::isfinite(*number))
            return Error{"--transform '" + text + "': item " + std::to_string(i + 1) + " '" +
                         item + "' is not a finite number"};
        v[i] = *number;
        at = comma + 1;
        if (i == 5) return Affine{v[0], v[1], v[2], v[3], v[4], v[5]};
    }
    return Error{"--transform '" + text + "': expected six numbers a,b,c,d,e,f"};
}

Status check_dim(const char* option, int v) {
    if (v >= 1 && v <= kMaxFillDim) return ok_status();
    return Error{std::string(option) + " " + std::to_string(v) + ": expected 1 to " +
                 std::to_string(kMaxFillDim) + " pixels"};
}

int run_fill(const FillArgs& args) {
    auto format = pick_format(args);
    if (!format) return fail_usage(format.error().message, kFillCommand);
    if (Status s = check_dim("--width", args.width); !s) return fail_usage(s.error().message, kFillCommand);
    if (Status s = check_dim("--height", args.height); !s)
        return fail_usage(s.error().message, kFillCommand);
    auto transform = parse_transform(args.transform);
    if (!transform) return fail_usage(transform.error().message, kFillCommand);
    if (Status t = check_tolerance(args.tolerance_px); !t)
        return fail_usage(t.error().message, kFillCommand);
    auto path = parse_svg_path(args.path_data);
    if (!path) return fail_usage("PATH: " + path.error().message, kFillCommand);

    Mask mask(args.width, args.height);
    Rasterizer raster;
    FlattenOptions flatten = raster_flatten_defaults();
    flatten.tolerance_px = args.tolerance_px;
    const FillRule rule = args.fill == "evenodd" ? FillRule::EvenOdd : FillRule::NonZero;
    const OverlapMode overlap =
        args.overlap == "accurate" ? OverlapMode::Accurate : OverlapMode::Accumulate;
    if (Status s = raster.fill_path(*path, *transform, mask.view(), {rule, overlap, flatten}); !s)
        return fail_runtime("PATH: " + s.error().message);

    std::string document;
    if (*format == FillFormat::Ascii) {
        document = ascii_art(mask.view());
    } else if (args.coverage && *format == FillFormat::Pgm) {
        const std::vector<std::uint8_t> pgm = encode_pgm(mask.view());
        document.assign(pgm.begin(), pgm.end());
    } else if (args.coverage) {
        auto png = encode_png_gray(mask.view(), args.png);
        if (!png) return fail_runtime(png.error().message);
        document.assign(png->begin(), png->end());
    } else {
        auto colours = picture_colours(args.foreground, args.background);
        if (!colours) return fail_usage(colours.error().message, kFillCommand);
        if (*format == FillFormat::Pgm && !colours->gray())
            return fail_usage("-O pgm: a PGM picture is gray; give gray opaque colours, or write PNG",
                              kFillCommand);
        const Image picture = paint_coverage(mask.view(), *colours);
        if (*format == FillFormat::Pgm) {
            document = picture_pnm(picture, true);
        } else {
            auto png =
                picture_png(picture, colours->gray(), colours->translucent(), args.png);
            if (!png) return fail_runtime(png.error().message);
            document = std::move(*png);
        }
    }
    return write_result(args.output_file, document);
}

}  // namespace

Command add_fill_command(CLI::App& app) {
    auto args = std::make_shared<FillArgs>();
    CLI::App* cmd = app.add_subcommand("fill", "Rasterize any vector path (SVG path data)");
    cmd->footer(
        "The path is in pixels, y down, mapped by --transform, filled with exact area per pixel,\n"
        "curves flattened within --tolerance. PNG and PGM are a picture, ink on paper (black on\n"
        "white unless --foreground/--background), or with --coverage the coverage itself, gray\n"
        "(0 = empty, 255 = covered). Formats: png, pgm, ascii (one character per pixel); default:\n"
        "from the -o file's extension (.png, .pgm, .txt), else ascii.\n"
        "Examples:\n"
        "  bezel fill 'M2,2 L30,4 L16,28 Z' --width 32 --height 32 -o triangle.png\n"
        "  bezel fill 'M0,0 h10 v10 h-10 z M2,2 h6 v6 h-6 z' --width 12 --height 12 --fill evenodd\n"
        "  bezel fill 'M0,0 C10,0 10,10 0,10 z' --width 64 --height 64 --transform 6,0,0,6,2,2 "
        "-o bump.pgm");
    cmd->add_option("PATH", args->path_data, "SVG path data")->required();
    cmd->add_option("--width", args->width, "Image width in pixels")->required()->type_name("W");
    cmd->add_option("--height", args->height, "Image height in pixels")->required()->type_name("H");
    cmd->add_option("-O,--output-format", args->format,
                    "png, pgm or ascii; default: from the -o file's extension, else ascii")
        ->type_name("FORMAT")
        ->check(CLI::IsMember({"png", "pgm", "ascii"}));
    add_picture_options(*cmd, args->output_file, args->fill, args->tolerance_px);
    cmd->add_option("--transform", args->transform,
                    "Affine map a,b,c,d,e,f applied to the path (SVG matrix order)")
        ->type_name("A,B,C,D,E,F");
    cmd->add_option("--overlap", args->overlap,
                    "accumulate (plain area accumulation) or accurate (overlapping contours "
                    "resolved exactly)")
        ->capture_default_str()
        ->check(CLI::IsMember({"accumulate", "accurate"}));
    add_colour_options(*cmd, args->foreground, args->background);
    cmd->add_flag("--coverage", args->coverage,
                  "PNG/PGM of the coverage itself (gray, 255 = covered) instead of a picture")
        ->excludes("--foreground")
        ->excludes("--background");
    add_compression_option(*cmd, args->png);
    return Command{cmd, [args] { return run_fill(*args); }};
}

}  // namespace bezel::cli
