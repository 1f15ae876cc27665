// `bezel glyph`: glyph bitmaps from the library's GlyphRasterizer, as ASCII art, JSON (a stable
// contract), PNG or PGM/PPM. Boxes follow FreeType's bitmap_left / bitmap_top
// (GlyphBoxMode::FreeType).
#include <CLI/CLI.hpp>
#include <cmath>
#include <iostream>
#include <memory>

#include "cli_common.hpp"
#include "color_args.hpp"
#include "commands.hpp"
#include "font_args.hpp"
#include "font_list.hpp"
#include "glyph_bitmap.hpp"
#include "glyph_choice.hpp"
#include "parse_check.hpp"
#include "missing_glyphs.hpp"

namespace bezel::cli {
namespace {

enum class GlyphFormat { Ascii, Json, Png, Pnm };

struct GlyphArgs {
    PngOptions png;  // --compression
    FontArgs font;
    FontListArgs fonts;         // --font, --fallback
    ColorArgs color;            // --palette, --custom-palette
    double slant = 0;           // --font-slant
    double bold = 0;            // --font-bold
    GlyphChoice which;
    std::string format, output_file;
    std::string fill = "nonzero", lcd, offset, flatten = "wang", overlap = "auto";
    double tolerance_px = kDefaultRasterTolerancePx;
    CLI::App* cmd = nullptr;
    bool strict = false;   // --strict
    std::string foreground, background;   // picture colours ("": black on white)
    bool coverage = false;                // --coverage: PNG/PGM of the coverage itself
    int margin_px = 0;                    // --margin
    bool embedded_bitmaps = false;        // --embedded-bitmaps
};

const std::string kGlyphCommand = "bezel glyph";

// -O wins; else the -o file's extension; else ASCII on stdout.
Expected<GlyphFormat> pick_format(const GlyphArgs& args) {
    auto name = pick_output_format(args.format, args.output_file,
                                   {{".txt", "ascii"}, {".json", "json"}, {".png", "png"},
                                    {".pgm", "pgm"}, {".ppm", "pgm"}},
                                   "ascii");
    if (!name) return name.error();
    if (*name == "ascii") return GlyphFormat::Ascii;
    if (*name == "json") return GlyphFormat::Json;
    if (*name == "png") return GlyphFormat::Png;
    return GlyphFormat::Pnm;
}

Expected<Vec2> parse_offset(const std::string& text) {
    if (text.empty()) return Vec2{};
    const std::size_t comma = text.find(',');
    double v[2] = {0, 0};
    std::string parts[2] = {text.substr(0, comma),
                            comma == std::string::npos ? std::string() : text.substr(comma + 1)};
    for (int i = 0; i < 2; ++i) {
        const std::optional<double> number = parse_number(parts[i]);
        if (!number || !std::isfinite(*number))
            return Error{"--offset '" + text + "': expected DX,DY (two numbers, pixels)"};
        v[i] = *number;
        if (std::fabs(v[i]) > kMaxGlyphOffsetPx)
            return Error{"--offset '" + text + "': beyond ±" + plain_number(kMaxGlyphOffsetPx) +
                         " px"};
    }
    return Vec2{v[0], v[1]};
}

FlattenMethod method_named(const std::string& name) {
    if (name == "distance") return FlattenMethod::DistanceSubdivision;
    if (name == "parabola") return FlattenMethod::ParabolaIntegral;
    if (name == "classic") return FlattenMethod::ClassicFlatness;
    return FlattenMethod::WangUniform;
}

int run_glyph(GlyphArgs& args) {
    auto format = pick_format(args);
    if (!format) return fail_usage(format.error().message, kGlyphCommand);
    auto offset = parse_offset(args.offset);
    if (!offset) return fail_usage(offset.error().message, kGlyphCommand);
    if (Status t = check_tolerance(args.tolerance_px); !t)
        return fail_usage(t.error().message, kGlyphCommand);

    GlyphRenderOptions options;
    options.size_px = args.font.size_px;
    options.hinting = hinting_of(args.font);
    options.embedded_bitmaps = args.embedded_bitmaps;
    options.slant = args.slant;
    options.bold = args.bold;
    options.offset_px = *offset;
    options.box = GlyphBoxMode::FreeType;   // the JSON contract: FT_Render_Glyph's box
    auto color = color_options(args.color);
    if (!color) return fail_usage(color.error().message, kGlyphCommand);
    options.color = std::move(*color);
    if (!args.foreground.empty()) {
        // A COLR glyph's text-colour entries take the ink (checked at parsing).
        if (auto ink = parse_color(args.foreground)) options.color.foreground = *ink;
    }
    FillOptions& fill = options.fill;
    fill.format = args.lcd.empty() ? CoverageFormat::Gray : CoverageFormat::Lcd;
    fill.lcd_order = args.lcd == "bgr" ? LcdOrder::Bgr : LcdOrder::Rgb;
    fill.rule = args.fill == "evenodd" ? FillRule::EvenOdd : FillRule::NonZero;
    if (args.bold > 0 && fill.rule != FillRule::NonZero)
        return fail_usage("--font-bold needs --fill nonzero: the emboldened outline overlaps "
                          "itself, and even-odd would cut the overlaps out",
                          kGlyphCommand);
    fill.overlap = args.overlap == "accurate" ? OverlapMode::Accurate : OverlapMode::Accumulate;
    fill.flatten.tolerance_px = args.tolerance_px;
    fill.flatten.method = method_named(args.flatten);

    if (int settled = settle_glyph_choice(args.which, args.font, *args.cmd, kGlyphCommand))
        return settled;
    // FONT alone opens as it always did (its checks and messages); a list through
    // open_font_list, FONT's variations on the first font.
    auto variations = requested_variations(args.font);
    if (!variations) return fail_runtime(variations.error().message);
    if (!has_font_list(args.fonts)) {
        auto font = open_font(args.font, nullptr, FontUse::Glyphs);
        if (!font) return fail_runtime(font.error().message);
    }
    auto fonts = open_font_list(args.font, args.fonts, font_file_given(args.font, *args.cmd), std::move(*variations));
    if (!fonts) return fail_runtime(fonts.error().message);
    if (Status s = check_palette(options.color, *fonts); !s) return fail_runtime(s.error().message);
    auto requests = requested_glyphs(args.which, *fonts);
    if (!requests) return fail_runtime(requests.error().message);
    const bool listed = fonts->size() > 1;
    if (Status s = report_missing_glyphs(font_list_names(*fonts), missing_of(*requests),
                                         args.strict);
        !s)
        return fail_runtime(s.error().message);

    // Each glyph's outline is loaded once; its box is added to the pixel budget before its
    // pixels are allocated.
    std::vector<std::unique_ptr<GlyphRasterizer>> rasterizers;   // the fallback may have added fonts
    for (std::size_t i = 0; i < fonts->size(); ++i)
        rasterizers.push_back(std::make_unique<GlyphRasterizer>(fonts->font(i)));
    Font* font = &fonts->font(0);
    std::vector<GlyphBitmap> glyphs;
    std::size_t pixels = 0;
    for (const GlyphRequest& r : *requests) {
        font = &fonts->font(r.font);
        GlyphRasterizer& rasterizer = *rasterizers[r.font];
        auto prepared = rasterizer.prepare(r.gid, options);
        if (!prepared) return fail_runtime(prepared.error().message);
        if (rasterizer.color_format(r.gid) == ColorFormat::Svg)
            std::cerr << "bezel: warning: " << font->file() << ": glyph " << r.gid << " ("
                      << font->glyph_name(r.gid)
                      << ") is an SVG colour glyph, which bezel does not paint: drawn from its "
                         "outline\n";
        const GlyphBox& box = prepared->box;
        pixels += static_cast<std::size_t>(box.width) * static_cast<std::size_t>(box.height);
        if (pixels > kMaxGlyphOutputPixels)
            return fail_runtime(font->file() + ": the glyphs need more than " +
                                std::to_string(kMaxGlyphOutputPixels) +
                                " pixels, the most one call renders; use a smaller --font-size");
        GlyphBitmap g{r.gid, font->glyph_name(r.gid), r.code_point,
                      listed ? font->file() : std::string(), box, fill.format, fill.lcd_order, {}};
        const int row_bytes = box.width * g.bytes_per_pixel();
        g.pixels.assign(static_cast<std::size_t>(row_bytes) * static_cast<std::size_t>(box.height), 0);
        const Status st =
            box.color ? rasterizer.draw_rgba(*prepared, RgbaView{g.pixels.data(), box.width,
                                                                 box.height, row_bytes})
                      : rasterizer.draw(*prepared, MaskView{g.pixels.data(), row_bytes,
                                                            box.height, row_bytes});
        if (!st) return fail_runtime(font->file() + ": " + st.error().message);
        glyphs.push_back(std::move(g));
    }

    std::string document;
    switch (*format) {
        case GlyphFormat::Ascii: document = glyphs_ascii(glyphs, options); break;
        case GlyphFormat::Json: document = glyphs_json(glyphs, options); break;
        case GlyphFormat::Png:
        case GlyphFormat::Pnm: {
            GlyphPictureOptions picture_options;
            picture_options.margin_px = args.margin_px;
            picture_options.png = args.png;
            if (!args.coverage) {
                auto parsed = picture_colours(args.foreground, args.background);
                if (!parsed) return fail_usage(parsed.error().message, kGlyphCommand);
                picture_options.colours = *parsed;
            }
            auto picture = *format == GlyphFormat::Png ? glyphs_png(glyphs, picture_options)
                                                       : glyphs_pnm(glyphs, picture_options);
            if (!picture) return fail_runtime(font->file() + ": " + picture.error().message);
            document = std::move(*picture);
            break;
        }
    }
    return write_result(args.output_file, document);
}

}  // namespace

Command add_glyph_command(CLI::App& app) {
    auto args = std::make_shared<GlyphArgs>();
    CLI::App* cmd = app.add_subcommand("glyph", "Render glyph bitmaps with bezel's rasterizer");
    args->cmd = cmd;
    cmd->footer(
        "Bitmaps are unhinted (unless --hinting) coverage, 0 = empty, 255 = covered, placed as\n"
        "FreeType places FT_Render_Glyph's bitmap: left = bitmap_left, top = bitmap_top (rows\n"
        "above the baseline), from the outline's control box in 26.6 at the pen (0,0) + --offset.\n"
        "Glyphs the font marks as overlapping (OVERLAP_SIMPLE/COMPOUND) use the accurate overlap\n"
        "mode; --overlap accurate uses it for every glyph. --lcd samples 3x horizontally through\n"
        "FreeType's default 5-tap filter; the box is one pixel wider on each side and each pixel\n"
        "has three subpixel coverages, left to right: R, G, B for rgb, B, G, R for bgr.\n"
        "Colour glyphs (COLRv1, COLRv0, CBDT, sbix) are drawn in colour (--palette,\n"
        "--custom-palette; text-colour entries take --foreground), boxed around their paint;\n"
        "SVG glyphs are drawn from their outlines, with a warning.\n"
        "--embedded-bitmaps draws a glyph from the font's monochrome or gray bitmap strike\n"
        "(EBDT) when it has one of exactly --font-size pixels per em holding the glyph, at the\n"
        "whole pixel nearest the pen; other glyphs and sizes are drawn from their outlines.\n"
        "Formats: ascii (default; one character per pixel, per subpixel with --lcd; a colour\n"
        "glyph's alpha); json, an array with one object per glyph: gid, name, char and\n"
        "code_point (when known), size, left, top, width (pixels), height, advance, mode\n"
        "(gray|lcd-rgb|lcd-bgr|rgba), overlap (accumulate|accurate) and rows (one hex string per\n"
        "row, 2 digits per pixel, 6 for LCD, 8 for rgba: R, G, B, A premultiplied);\n"
        "png and pgm (PPM with --lcd or colours): all glyphs side by side, one column apart, on\n"
        "a common baseline, as a picture: ink on paper, black on white unless --foreground/\n"
        "--background (colour glyphs make it RGB); with --coverage the coverage itself (0 =\n"
        "empty, 255 = covered; RGBA on transparent when it holds colour glyphs).\n"
        "Examples:\n"
        "  bezel glyph --char g --font-size 24\n"
        "  bezel glyph font.ttf --text 'Hamburg' --font-size 32 -o hamburg.png\n"
        "  bezel glyph --gid 36 --font-size 12 --lcd rgb --offset 0.25,0 -O json\n"
        "  bezel glyph NotoColorEmoji.ttf --char 😀 --font-size 64 -o emoji.png");
    add_font_args(*cmd, args->font);
    add_font_list_options(*cmd, args->fonts);
    add_color_options(*cmd, args->color);
    add_slant_option(*cmd, args->slant);
    add_bold_option(*cmd, args->bold);
    add_glyph_choice(*cmd, args->which, "Each character of a string (cmap, no shaping)");
    cmd->add_option("-O,--output-format", args->format,
                    "ascii, json, png or pgm; default: from the -o file's extension, else ascii")
        ->type_name("FORMAT")
        ->check(CLI::IsMember({"ascii", "json", "png", "pgm"}));
    add_picture_options(*cmd, args->output_file, args->fill, args->tolerance_px);
    cmd->add_option("--lcd", args->lcd, "LCD subpixel rendering for an rgb or bgr panel")
        ->type_name("ORDER")
        ->check(CLI::IsMember({"rgb", "bgr"}));
    cmd->add_option("--offset", args->offset, "Pen position DX,DY in pixels (x right, y down)")
        ->type_name("DX,DY");
    cmd->add_option("--flatten", args->flatten,
                    "Flattening method: wang, distance, parabola or classic")
        ->capture_default_str()
        ->type_name("METHOD")
        ->check(CLI::IsMember({"wang", "distance", "parabola", "classic"}));
    cmd->add_option("--overlap", args->overlap,
                    "auto (accurate for glyphs marked as overlapping) or accurate (for all)")
        ->capture_default_str()
        ->check(CLI::IsMember({"auto", "accurate"}));
    add_strict_option(*cmd, args->strict);
    add_colour_options(*cmd, args->foreground, args->background);
    cmd->add_flag("--coverage", args->coverage,
                  "png/pgm of the coverage itself (gray, or RGB subpixels with --lcd; 255 = "
                  "covered) instead of a picture")
        ->excludes("--foreground")
        ->excludes("--background");
    cmd->add_option("--margin", args->margin_px,
                    "png/pgm: empty pixels around the glyphs on every side (default 0)")
        ->type_name("PX")
        ->check(in_range(0.0, static_cast<double>(kMaxGlyphMarginPx)));
    cmd->add_flag("--embedded-bitmaps", args->embedded_bitmaps,
                  "Draw glyphs from the font's monochrome/gray bitmap strike of exactly "
                  "--font-size ppem where it has one (default: outlines)");
    add_compression_option(*cmd, args->png);
    return Command{cmd, [args] { return run_glyph(*args); }};
}

}  // namespace bezel::cli
