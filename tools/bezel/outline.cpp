// `bezel outline`: a glyph's outline point by point — contours, on/off-curve points, directions
// and segments — as text, JSON or an annotated SVG (see outline_model.hpp for the data).
#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>

#include "cli_common.hpp"
#include "commands.hpp"
#include "font_args.hpp"
#include "glyph_choice.hpp"
#include "missing_glyphs.hpp"
#include "outline_model.hpp"

namespace bezel::cli {
namespace {

struct OutlineArgs {
    FontArgs font;
    GlyphChoice which;           // --char, --gid, --text
    std::string format;          // -O
    std::string output_file;     // -o
    CLI::App* cmd = nullptr;
    bool strict = false;         // --strict
};

int run_outline(OutlineArgs& args) {
    auto format = choose_format(args.format, args.output_file, OutputFormat::Text);
    if (!format) return fail_usage(format.error().message, "bezel outline");

    if (int settled = settle_glyph_choice(args.which, args.font, *args.cmd, "bezel outline"))
        return settled;
    OutlineReport report;
    auto font = open_font(args.font, &report.variations);
    if (!font) return fail_runtime(font.error().message);
    auto glyphs = requested_glyphs(args.which, *font);
    if (!glyphs) return fail_runtime(glyphs.error().message);
    if (Status s = report_missing_glyphs(font->file(), missing_of(*glyphs), args.strict); !s)
        return fail_runtime(s.error().message);

    report.font_file = font->file();
    report.family = font->family_name();
    report.style = font->style_name();
    report.face_index = font->face_index();
    report.cubic = font->has_cubic_outlines();
    report.metrics = font->metrics();
    report.size_px = args.font.size_px;
    report.hinting = hinting_of(args.font);

    const OutlineOptions options{args.font.size_px, report.hinting};
    double pen_x = 0;
    for (const GlyphRequest& request : *glyphs) {
        auto outline = font->outline(request.gid, options);
        if (!outline) return fail_runtime(outline.error().message);
        GlyphReport glyph;
        glyph.gid = request.gid;
        glyph.name = font->glyph_name(request.gid);
        glyph.code_point = request.code_point;
        glyph.pen_x_px = pen_x;
        glyph.outline = std::move(*outline);
        glyph.contours = describe_contours(glyph.outline);
        pen_x += glyph.outline.metrics.advance_px;
        report.glyphs.push_back(std::move(glyph));
    }

    std::string document;
    switch (*format) {
        case OutputFormat::Text: document = format_text(report); break;
        case OutputFormat::Json: document = format_json(report); break;
        case OutputFormat::Svg: document = format_svg(report); break;
    }
    return write_result(args.output_file, document);
}

}  // namespace

Command add_outline_command(CLI::App& app) {
    auto args = std::make_shared<OutlineArgs>();
    CLI::App* cmd = app.add_subcommand(
        "outline",
        "Show a glyph's outline: contours, on/off-curve points, directions and segments");
    args->cmd = cmd;
    cmd->footer(
        "Coordinates are pixels at --font-size, y down, pen at (0,0) on the baseline.\n"
        "Examples:\n"
        "  bezel outline --char g\n"
        "  bezel outline font.ttf --char U+00E9 --font-size 512 -o eacute.svg\n"
        "  bezel outline font.ttf --text 'Hamburg' -O json");
    add_font_args(*cmd, args->font);

    add_glyph_choice(*cmd, args->which,
                     "Each character of a string (cmap lookup, no shaping); SVG places the "
                     "glyphs along their advances");

    cmd->add_option("-O,--output-format", args->format,
                    "text, json or svg; default: from the -o file's extension, else text")
        ->type_name("FORMAT")
        ->check(CLI::IsMember({"text", "json", "svg"}));
    cmd->add_option("-o,--output-file", args->output_file,
                    "Write here instead of stdout (atomically: no partial file on failure)")
        ->type_name("FILE");
    add_strict_option(*cmd, args->strict);

    return Command{cmd, [args] { return run_outline(*args); }};
}

}  // namespace bezel::cli
