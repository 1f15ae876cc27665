// `bezel surface`: bicubic patches from a JSON file, drawn as a wireframe or a shaded solid (PNG
// through bezel's rasterizer), or tessellated to a mesh (OBJ, STL).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <memory>

#include "bezel/image.hpp"
#include "bezel/surface.hpp"
#include "cli_common.hpp"
#include "commands.hpp"
#include "parse_check.hpp"
#include "surface_input.hpp"

namespace bezel::cli {
namespace {

constexpr const char* kSurfaceCommand = "bezel surface";

struct SurfaceArgs {
    PngOptions png;  // --compression
    std::string patch_file;            // --patch
    std::string basis;                 // --basis
    std::string view = "-35,25";       // --view az,el
    std::string eye, target, up = "0,0,1";
    std::string projection = "perspective";
    std::string mode = "solid";
    std::string shading = "smooth";
    std::string size = "512x512";
    int steps = 0;                     // --steps
    double tolerance = 0;              // --tolerance
    int iso_lines = 5;
    double line_width = 1.0;
    std::string background = "white", foreground;
    std::string format;                // -O
    std::string output_file;           // -o
    CLI::App* cmd = nullptr;
};

enum class SurfaceFormat { Png, Obj, Stl, StlAscii };

Expected<SurfaceFormat> pick_format(const SurfaceArgs& args) {
    auto picked = pick_output_format(args.format, args.output_file,
                                     {{".png", "png"}, {".obj", "obj"}, {".stl", "stl"}}, "png");
    if (!picked) return picked.error();
    const std::string& name = *picked;
    if (name == "png") return SurfaceFormat::Png;
    if (name == "obj") return SurfaceFormat::Obj;
    if (name == "stl") return SurfaceFormat::Stl;
    return SurfaceFormat::StlAscii;  // CLI11 checked the name
}

// The control nets' bounding box: centre and half-diagonal (the surfaces lie inside it).
void net_bounds(const std::vector<Patch>& patches, Vec3& centre, double& radius) {
    Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (const Patch& p : patches) {
        const Patch b = p.to_bezier();
        for (const auto& row : b.g)
            for (const Vec3& q : row) {
                lo = {std::min(lo.x, q.x), std::min(lo.y, q.y), std::min(lo.z, q.z)};
                hi = {std::max(hi.x, q.x), std::max(hi.y, q.y), std::max(hi.z, q.z)};
            }
    }
    centre = (lo + hi) * 0.5;
    radius = (hi - lo).length() * 0.5;
}

Expected<Camera> make_camera(const SurfaceArgs& args, const std::vector<Patch>& patches) {
    Vec3 centre;
    double radius;
    net_bounds(patches, centre, radius);
    const Projection proj =
        args.projection == "ortho" ? Projection::Orthographic : Projection::Perspective;
    Camera cam;
    if (args.cmd->count("--eye") > 0) {
        auto eye = parse_vec3(args.eye, "--eye");
        if (!eye) return eye.error();
        cam.eye = *eye;
        cam.target = centre;
        if (args.cmd->count("--target") > 0) {
            auto target = parse_vec3(args.target, "--target");
            if (!target) return target.error();
            cam.target = *target;
        }
        auto up = parse_vec3(args.up, "--up");
        if (!up) return up.error();
        cam.up = *up;
        cam.projection = proj;
        return cam;
    }
    double az = 0, el = 0;
    char tail = 0;
    if (std::sscanf(args.view.c_str(), "%lf,%lf%c", &az, &el, &tail) != 2 || !std::isfinite(az) ||
        !(el >= -90 && el <= 90))
        return Error{"--view '" + args.view + "': expected azimuth,elevation in degrees (elevation -90 to 90)"};
    // Four radii away: a moderate perspective (the picture is fitted to the surface anyway).
    return orbit_camera(centre, az, el, 4.0 * std::max(radius, 1e-300), proj);
}

int run_surface(const SurfaceArgs& args) {
    auto format = pick_format(args);
    if (!format) return fail_usage(format.error().message, kSurfaceCommand);
    auto size = parse_size(args.size);
    if (!size) return fail_usage(size.error().message, kSurfaceCommand);
    std::optional<SurfaceBasis> basis;
    if (!args.basis.empty())
        basis = args.basis == "hermite" ? SurfaceBasis::Hermite
                : args.basis == "bspline" ? SurfaceBasis::BSpline : SurfaceBasis::Bezier;
    if (args.cmd->count("--target") > 0 && args.cmd->count("--eye") == 0)
        return fail_usage("--target needs --eye", kSurfaceCommand);

    auto patches = read_surface_file(args.patch_file, basis);
    if (!patches) return fail_runtime(patches.error().message);
    auto camera = make_camera(args, *patches);
    if (!camera) return fail_usage(camera.error().message, kSurfaceCommand);

    const bool picture = *format == SurfaceFormat::Png;
    const bool wire = args.mode == "wire";
    Vec3 centre;
    double radius;
    net_bounds(*patches, centre, radius);
    TessellateOptions tess;
    tess.steps = args.steps;
    // Default: half a pixel for pictures (the fitted scale is about min(W,H) per 2 radii), a
    // thousandth of the size for meshes.
    tess.tolerance = args.tolerance > 0 ? args.tolerance
                     : picture ? radius / std::min(size->first, size->second)
                               : 1e-3 * radius;

    std::string document;
    if (!picture) {
        auto mesh = tessellate(*patches, tess);
        if (!mesh) return fail_runtime(args.patch_file + ": " + mesh.error().message);
        document = *format == SurfaceFormat::Obj   ? to_obj(*mesh)
                   : *format == SurfaceFormat::Stl ? to_stl_binary(*mesh)
                                            : to_stl_ascii(*mesh);
    } else {
        auto view = View::fit(*camera, size->first, size->second, *patches,
                              0.04 * std::min(size->first, size->second));
        if (!view) return fail_usage(view.error().message, kSurfaceCommand);
        auto background = parse_color(args.background);
        if (!background) return fail_usage("--background: " + background.error().message, kSurfaceCommand);
        Expected<Image> image = Error{""};
        if (wire) {
            WireStyle style;
            style.iso_lines = args.iso_lines;
            style.line_width_px = args.line_width;
            style.background = *background;
            if (!args.foreground.empty()) {
                auto fg = parse_color(args.foreground);
                if (!fg) return fail_usage("--foreground: " + fg.error().message, kSurfaceCommand);
                style.color = *fg;
            }
            image = render_wireframe(*patches, *view, style);
        } else {
            auto mesh = tessellate(*patches, tess);
            if (!mesh) return fail_runtime(args.patch_file + ": " + mesh.error().message);
            SolidStyle style;
            style.shading = args.shading == "flat" ? Shading::Flat : Shading::Smooth;
            style.background = *background;
            if (!args.foreground.empty()) {
                auto fg = parse_color(args.foreground);
                if (!fg) return fail_usage("--foreground: " + fg.error().message, kSurfaceCommand);
                style.color = *fg;
            }
            image = render_solid(*mesh, *view, style);
        }
        if (!image) return fail_runtime(args.patch_file + ": " + image.error().message);
        auto png = encode_png(*image, PngColor::Rgb, args.png);
        if (!png) return fail_runtime(png.error().message);
        document.assign(png->begin(), png->end());
    }
    return write_result(args.output_file, document);
}

}  // namespace

Command add_surface_command(CLI::App& app) {
    auto args = std::make_shared<SurfaceArgs>();
    CLI::App* cmd = app.add_subcommand(
        "surface", "Bicubic surface patches: wireframe or shaded PNG, or an OBJ/STL mesh");
    args->cmd = cmd;
    cmd->footer(
        "Patch file: {\"basis\": \"bezier\", \"patches\": [[16 points [x,y,z]], ...]}, point 4i+j\n"
        "  is G[i][j] (i along s); Hermite rows: Q(0,.), Q(1,.), dQ/ds(0,.), dQ/ds(1,.), columns\n"
        "  value(0), value(1), dQ/dt(0), dQ/dt(1); or {\"basis\": \"bspline\", \"grid\": [[row of\n"
        "  points], ...]} for the C2 surface of a control grid. The picture is fitted to the\n"
        "  surface. Wireframes do not remove hidden lines.\n"
        "Examples:\n"
        "  bezel surface --patch teapot.json --view -35,25 --mode solid -o teapot.png\n"
        "  bezel surface --patch saddle.json --projection ortho --mode wire --size 256x256 -o s.png\n"
        "  bezel surface --patch teapot.json --tolerance 0.001 -o teapot.obj");
    cmd->add_option("--patch", args->patch_file, "The patch JSON file ('-': stdin)")
        ->required()
        ->type_name("FILE");
    cmd->add_option("--basis", args->basis,
                    "bezier, hermite or bspline (default: the file's \"basis\", else bezier)")
        ->type_name("BASIS")
        ->check(CLI::IsMember({"bezier", "hermite", "bspline"}));
    cmd->add_option("--view", args->view,
                    "Azimuth,elevation in degrees around the surface, z up (default -35,25)")
        ->type_name("AZ,EL");
    cmd->add_option("--eye", args->eye, "Camera position (instead of --view)")->type_name("X,Y,Z");
    cmd->add_option("--target", args->target, "With --eye: point looked at (default: the centre)")
        ->type_name("X,Y,Z");
    cmd->add_option("--up", args->up, "With --eye: up direction (default 0,0,1)")->type_name("X,Y,Z");
    cmd->get_option("--view")->excludes(cmd->get_option("--eye"));
    cmd->add_option("--projection", args->projection, "perspective (default) or ortho")
        ->type_name("P")
        ->check(CLI::IsMember({"perspective", "ortho"}));
    cmd->add_option("--mode", args->mode, "solid (default) or wire")
        ->type_name("MODE")
        ->check(CLI::IsMember({"solid", "wire"}));
    cmd->add_option("--shading", args->shading, "solid: smooth (default, per pixel) or flat")
        ->type_name("S")
        ->check(CLI::IsMember({"smooth", "flat"}));
    cmd->add_option("--size", args->size, "Picture size WxH in pixels (default 512x512)")
        ->type_name("WxH");
    auto* steps = cmd->add_option("--steps", args->steps, "Grid steps per patch side")
                      ->type_name("N")
                      ->check(in_range(1, kMaxTessellationSteps));
    auto* tol = cmd->add_option("--tolerance", args->tolerance,
                                "Mesh error bound in world units (default: ~0.5 px in pictures, "
                                "1/1000 of the size for meshes)")
                    ->type_name("T")
                    ->check(in_range(1e-12, 1e12));
    steps->excludes(tol);
    cmd->add_option("--iso-lines", args->iso_lines, "wire: iso-curves per patch and direction (2-64, default 5)")
        ->type_name("N")
        ->check(in_range(2, 64));
    cmd->add_option("--line-width", args->line_width, "wire: line width in pixels (default 1)")
        ->type_name("PX")
        ->check(in_range(0.01, 64.0));
    cmd->add_option("--background", args->background, "Background colour (default white)")
        ->type_name("COLOR");
    cmd->add_option("--foreground", args->foreground, "Surface or line colour")->type_name("COLOR");
    cmd->add_option("-O,--output-format", args->format,
                    "png, obj, stl (binary) or stl-ascii; default: from -o's extension, else png")
        ->type_name("FORMAT")
        ->check(CLI::IsMember({"png", "obj", "stl", "stl-ascii"}));
    cmd->add_option("-o,--output-file", args->output_file,
                    "Write here instead of stdout (atomically: no partial file on failure)")
        ->type_name("FILE");
    add_compression_option(*cmd, args->png);
    return Command{cmd, [args] { return run_surface(*args); }};
}

}  // namespace bezel::cli
