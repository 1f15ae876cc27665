// `bezel outline`: a glyph's outline point by point — contours, on/off-curve points, directions
// and segments — as text, JSON or an annotated SVG (see outline_model.hpp for the data).
#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>

#include "cli_common.hpp"
#include "commands.hpp"
#include "font_args.hpp"
#include "outline_model.hpp"

namespace bezel::cli {
namespace {

struct OutlineArgs {
    FontArgs font;
    std::string chr;             // --char
    GlyphId gid = 0;             // --gid
    std::string text;            // --text
    std::string format;          // -O
    std::string output_file;     // -o
    CLI::Option* gid_option = nullptr;
    CLI::Option* text_option = nullptr;
};

// One glyph to outline: a gid and, when it came from a character, that character.
struct GlyphRequest {
    GlyphId gid = 0;
    std::optional<char32_t> code_point;
};

// Resolves --char / --gid / --text to glyphs. Characters the font does not map: an error for
// --char (the user asked for that glyph), .notdef with a warning for --text (as hb-view draws).
Expected<std::vector<GlyphRequest>> requested_glyphs(const OutlineArgs& args, const Font& font) {
    std::vector<GlyphRequest> out;
    if (args.gid_option->count() > 0) {
        if (args.gid >= font.glyph_count())
            return Error{"--gid " + std::to_string(args.gid) + ": out of range, " + font.file() +
                         " has " + std::to_string(font.glyph_count()) + " glyphs"};
        out.push_back({args.gid, std::nullopt});
        return out;
    }
    if (args.text_option->count() > 0) {
        auto cps = decode_utf8(args.text);
        if (!cps) return Error{"--text: " + cps.error().message};
        if (cps->empty()) return Error{"--text: empty string"};
        if (cps->size() > kMaxTextCodePoints)
            return Error{"--text: " + std::to_string(cps->size()) + " characters, more than the " +
                         std::to_string(kMaxTextCodePoints) + " allowed"};
        for (char32_t cp : *cps) {
            auto gid = font.glyph_for_char(cp);
            if (!gid)
                std::cerr << "bezel: warning: " << font.file() << ": no glyph for "
                          << format_code_point(cp) << ", using .notdef\n";
            out.push_back({gid.value_or(0), cp});
        }
        return out;
    }
    auto cp = parse_code_point(args.chr);
    if (!cp) return cp.error();
    auto gid = font.glyph_for_char(*cp);
    if (!gid) return Error{font.file() + ": no glyph for " + format_code_point(*cp)};
    out.push_back({*gid, *cp});
    return out;
}

int run_outline(const OutlineArgs& args) {
    auto format = choose_format(args.format, args.output_file, OutputFormat::Text);
    if (!format) return fail_usage(format.error().message, "bezel outline");
    if (auto size_ok = check_font_size(args.font); !size_ok)
        return fail_runtime(size_ok.error().message);

    auto font = open_font(args.font);
    if (!font) return fail_runtime(font.error().message);
    auto glyphs = requested_glyphs(args, *font);
    if (!glyphs) return fail_runtime(glyphs.error().message);

    OutlineReport report;
    report.font_file = font->file();
    report.family = font->family_name();
    report.style = font->style_name();
    report.face_index = font->face_index();
    report.cubic = font->has_cubic_outlines();
    report.metrics = font->metrics();
    if (!args.font.variations.empty()) report.variations = *parse_variations(args.font.variations);
    report.size_px = args.font.size_px;
    report.hinting = args.font.hinting;

    const OutlineOptions options{args.font.size_px, args.font.hinting};
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
    auto written = write_output(args.output_file, document);
    if (!written) return fail_runtime(written.error().message);
    return kExitOk;
}

}  // namespace

Command add_outline_command(CLI::App& app) {
    auto args = std::make_shared<OutlineArgs>();
    CLI::App* cmd = app.add_subcommand(
        "outline",
        "Show a glyph's outline: contours, on/off-curve points, directions and segments");
    cmd->footer(
        "Coordinates are pixels at --font-size, y down, pen at (0,0) on the baseline.\n"
        "Examples:\n"
        "  bezel outline --char g\n"
        "  bezel outline font.ttf --char U+00E9 --font-size 512 -o eacute.svg\n"
        "  bezel outline font.ttf --text 'Hamburg' -O json");
    add_font_args(*cmd, args->font);

    // Exactly one of --char, --gid, --text: the option group turns "none" and "more than one"
    // into parse errors (exit 2) with CLI11's message.
    CLI::Option_group* which = cmd->add_option_group("glyph", "Which glyph(s), exactly one of:");
    which->add_option("--char", args->chr, "A character: itself in UTF-8, or U+XXXX")
        ->type_name("C")
        ->check(CLI::Validator(
            [](std::string& value) {
                auto cp = parse_code_point(value);
                return cp ? std::string() : cp.error().message;
            },
            "", "char"));
    args->gid_option = which->add_option("--gid", args->gid, "A glyph id")->type_name("N");
    args->text_option =
        which->add_option("--text", args->text,
                          "Each character of a string (cmap lookup, no shaping); SVG places the "
                          "glyphs along their advances")
            ->type_name("STR");
    which->require_option(1);

    cmd->add_option("-O,--output-format", args->format,
                    "text, json or svg; default: from the -o file's extension, else text")
        ->type_name("FORMAT")
        ->check(CLI::IsMember({"text", "json", "svg"}));
    cmd->add_option("-o,--output-file", args->output_file,
                    "Write here instead of stdout (atomically: no partial file on failure)")
        ->type_name("FILE");

    return Command{cmd, [args] { return run_outline(*args); }};
}

}  // namespace bezel::cli
