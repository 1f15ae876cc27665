// `bezel atlas`: the glyphs of a set of characters rendered once and packed into one coverage
// texture (gray PNG: value = coverage, 0 = empty; or --format rgba: colour glyphs in colour, the
// rest white with alpha = coverage), with JSON that tells a toolkit where each glyph is and how
// to place it:
//
// {
//   "font": file, "size_px": number, "hinting": "none"|"light"|"full"|"auto", "format": "gray"|"rgba",
//   "width": px, "height": px, "padding": px,
//   "glyphs": [{"char": string, "code_point": "U+XXXX", "gid": int,
//               "x", "y", "width", "height": the texture rectangle (px, y down),
//               "left", "top": bitmap offset from the pen (FreeType's bitmap_left / bitmap_top),
//               "advance": px, "color": whether the glyph is drawn in colour}]
// }
//
// A glyph's pixel (i, j) goes at (pen_x + left + i, pen_y − top + j) on the page. Glyphs are
// rendered at a whole-pixel pen, hinted as --hinting says, exactly as GlyphRasterizer renders
// them.
#include <CLI/CLI.hpp>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "atlas_pack.hpp"
#include "bezel/text.hpp"
#include "cli_common.hpp"
#include "color_args.hpp"
#include "commands.hpp"
#include "font_args.hpp"
#include "font_list.hpp"
#include "missing_glyphs.hpp"

namespace bezel::cli {
namespace {

constexpr const char* kAtlasCommand = "bezel atlas";
constexpr double kDefaultAtlasSizePx = 32.0;
// Distinct characters one atlas takes: all of a large CJK set, still a bounded amount of work
// (the texture side limit kMaxImageDim bounds the pixels).
constexpr std::size_t kMaxAtlasChars = 1u << 16;

struct AtlasArgs {
    PngOptions png;  // --compression
    FontArgs font;
    FontListArgs fonts;         // --font, --fallback
    ColorArgs color;            // --palette, --custom-palette
    double slant = 0;           // --font-slant
    double bold = 0;            // --font-bold
    std::string chars;
    std::string output_file;   // -o: the PNG
    std::string json_file;     // --json (default: stdout)
    std::string format = "gray";   // --format: gray or rgba
    bool strict = false;       // --strict
    CLI::App* cmd = nullptr;
};

struct Entry {
    char32_t code_point;
    GlyphId gid;
    GlyphBox box;
    std::size_t font;   // in the font list
};

int run_atlas(AtlasArgs& args) {
    const std::size_t given = args.cmd->count("--chars") + args.cmd->count("CHARS");
    auto word = lone_word_as_text(args.font.file, *args.cmd, given > 0, "--chars");
    if (!word) return fail_runtime(word.error().message);
    if (word->has_value()) {
        args.chars = std::move(**word);
    } else if (given != 1) {
        return fail_usage(given == 0 ? "no characters given: give --chars or CHARS"
                                     : "give the characters once: --chars or CHARS",
                          kAtlasCommand);
    }
    if (args.output_file == "-" && (args.json_file.empty() || args.json_file == "-"))
        return fail_usage("-o - and the JSON cannot both go to stdout (give --json FILE)", kAtlasCommand);
    auto code_points = decode_utf8(args.chars);
    if (!code_points) return fail_usage("--chars: " + code_points.error().message, kAtlasCommand);
    std::u32string distinct;
    for (char32_t c : *code_points)
        if (distinct.find(c) == std::u32string::npos) distinct.push_back(c);
    if (distinct.empty()) return fail_usage("--chars: no characters given", kAtlasCommand);
    if (distinct.size() > kMaxAtlasChars)
        return fail_usage("--chars: more than " + std::to_string(kMaxAtlasChars) +
                              " distinct characters",
                          kAtlasCommand);

    // FONT alone opens as it always did (its checks and messages); a list through
    // open_font_list, FONT's variations on the first font.
    auto variations = requested_variations(args.font);
    if (!variations) return fail_runtime(variations.error().message);
    if (!has_font_list(args.fonts)) {
        auto font = open_font(args.font, nullptr, FontUse::Glyphs);
        if (!font) return fail_runtime(font.error().message);
    }
    auto fonts = open_font_list(args.font, args.fonts, font_file_given(args.font, *args.cmd),
                                std::move(*variations));
    if (!fonts) return fail_runtime(fonts.error().message);
    std::vector<std::unique_ptr<GlyphRasterizer>> rasterizers;
    for (std::size_t i = 0; i < fonts->size(); ++i)
        rasterizers.push_back(std::make_unique<GlyphRasterizer>(fonts->font(i)));
    GlyphRenderOptions options;
    auto color = color_options(args.color);
    if (!color) return fail_usage(color.error().message, kAtlasCommand);
    options.color = std::move(*color);
    // The texture is tinted by the toolkit: text-colour entries of COLR glyphs are white too.
    options.color.foreground = {255, 255, 255, 255};
    if (Status s = check_palette(options.color, *fonts); !s) return fail_runtime(s.error().message);
    const bool rgba = args.format == "rgba";
    options.size_px = args.font.size_px;
    options.hinting = hinting_of(args.font);
    options.slant = args.slant;
    options.bold = args.bold;

    std::vector<Entry> entries;
    std::vector<PreparedGlyph> prepared;   // entries[i]'s glyph
    std::vector<AtlasRect> sizes;
    MissingGlyphs missing;
    for (char32_t c : distinct) {
        // The first font of the list that maps c (or the fallback's); the first font's .notdef
        // when none does.
        const std::optional<std::size_t> found = fonts->font_for(std::u32string(1, c));
        const std::size_t font = found.value_or(0);
        std::optional<GlyphId> gid;
        if (found) gid = fonts->font(font).glyph_for_char(c);
        while (rasterizers.size() < fonts->size())
            rasterizers.push_back(std::make_unique<GlyphRasterizer>(fonts->font(rasterizers.size())));
        if (!gid) {
            if (missing.count == 0) missing.first_code_point = c;
            ++missing.count;
        }
        // Each missing character gets its own copy of .notdef, so every character listed in
        // the JSON has its rectangle.
        // Loaded once: its box places it, and draw_set draws it from the same outline.
        auto glyph = rasterizers[font]->prepare(gid.value_or(0), options);
        if (!glyph) return fail_runtime(glyph.error().message);
        entries.push_back({c, gid.value_or(0), glyph->box, font});
        sizes.push_back({0, 0, glyph->box.width, glyph->box.height});
        prepared.push_back(std::move(*glyph));
    }
    if (Status s = report_missing_glyphs(font_list_names(*fonts), missing, args.strict); !s)
        return fail_runtime(s.error().message);
    auto packing = pack_shelves(sizes, kMaxImageDim);
    if (!packing) return fail_runtime(packing.error().message);

    // Gray: one coverage byte a pixel (a colour glyph gives its alpha). RGBA: premultiplied while
    // drawn, straight in the PNG.
    Mask texture(rgba ? 0 : packing->width, rgba ? 0 : packing->height);
    std::vector<std::uint8_t> colour_texture;
    if (rgba) colour_texture.assign(4 * static_cast<std::size_t>(packing->width) * packing->height, 0);
    const RgbaView colour_view{colour_texture.data(), packing->width, packing->height,
                               4 * static_cast<std::ptrdiff_t>(packing->width)};
    if (rgba) {
        for (std::size_t i = 0; i < entries.size(); ++i) {
            const AtlasRect& r = packing->rects[i];
            if (r.width == 0) continue;
            const Status drawn = rasterizers[entries[i].font]->draw_rgba(
                prepared[i], colour_view.sub(r.x, r.y, r.width, r.height));
            if (!drawn) return fail_runtime(drawn.error().message);
        }
    } else {
        // Each font's glyphs in one set call, each into its rectangle of the texture.
        std::vector<GlyphDrawJob> jobs;
        for (std::size_t font = 0; font < rasterizers.size(); ++font) {
            jobs.clear();
            for (std::size_t i = 0; i < entries.size(); ++i) {
                const AtlasRect& r = packing->rects[i];
                if (entries[i].font == font && r.width > 0)
                    jobs.push_back({&prepared[i], texture.view().sub(r.x, r.y, r.width, r.height)});
            }
            if (Status drawn = rasterizers[font]->draw_set(jobs); !drawn)
                return fail_runtime(drawn.error().message);
        }
    }
    const bool listed = fonts->size() > 1;
    nlohmann::ordered_json glyphs = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const Entry& e = entries[i];
        const AtlasRect& r = packing->rects[i];
        std::string utf8;
        append_utf8(utf8, e.code_point);
        glyphs.push_back({{"char", utf8},          {"code_point", format_code_point(e.code_point)},
                          {"gid", e.gid},          {"x", r.x},
                          {"y", r.y},              {"width", r.width},
                          {"height", r.height},    {"left", e.box.left},
                          {"top", e.box.top},      {"advance", e.box.advance_px},
                          {"color", e.box.color}});
        if (listed) glyphs.back()["font"] = e.font;
    }
    nlohmann::ordered_json doc = {{"font", fonts->source(0).file},
                                  {"size_px", args.font.size_px},
                                  {"hinting", hinting_name(options.hinting)},
                                  {"format", args.format},
                                  {"width", packing->width},
                                  {"height", packing->height},
                                  {"padding", kAtlasPaddingPx},
                                  {"glyphs", std::move(glyphs)}};
    if (listed) {
        // The list, which each glyph's "font" indexes.
        nlohmann::ordered_json files = nlohmann::ordered_json::array();
        for (std::size_t i = 0; i < fonts->size(); ++i) files.push_back(fonts->source(i).file);
        doc["fonts"] = std::move(files);
    }

    auto png = rgba ? encode_png(to_image(colour_view), PngColor::Rgba, args.png)
                    : encode_png_gray(texture.view(), args.png);
    if (!png) return fail_runtime(args.output_file + ": " + png.error().message);
    // The JSON is written last: a toolkit that sees it can rely on the texture beside it.
    auto written = write_output(args.output_file, std::string(png->begin(), png->end()));
    if (!written) return fail_runtime(written.error().message);
    return write_result(args.json_file, doc.dump(2) + "\n");
}

}  // namespace

Command add_atlas_command(CLI::App& app) {
    auto args = std::make_shared<AtlasArgs>();
    CLI::App* cmd = app.add_subcommand(
        "atlas", "Pack the glyphs of some characters into a texture, with JSON metrics");
    args->cmd = cmd;
    args->font.size_px = kDefaultAtlasSizePx;
    cmd->footer(
        "The texture is a gray PNG of coverage (0 empty, 255 full), not a picture: a toolkit\n"
        "tints it when it draws, so there are no colours to choose. With --format rgba it is an\n"
        "RGBA PNG (straight alpha): colour glyphs (COLR, CBDT, sbix) in their colours, the rest\n"
        "white, to be tinted; each glyph's \"color\" says which. Shelf-packed with 1 px of\n"
        "padding, its width a power of two, its height tight. The JSON lists per character its\n"
        "gid, texture rectangle x/y/width/height, bitmap left/top (as FreeType) and advance.\n"
        "Glyphs are drawn at whole-pixel pens, hinted as --hinting says.\n"
        "A character the font lacks gets its .notdef glyph, with a warning (--strict: an error).\n"
        "Examples:\n"
        "  bezel atlas --chars 'abcdefghijklmnopqrstuvwxyz' --font-size 24 -o atlas.png "
        "--json atlas.json\n"
        "  bezel atlas 0123456789 -o digits.png --json digits.json");
    add_font_args(*cmd, args->font);
    add_font_list_options(*cmd, args->fonts);
    add_color_options(*cmd, args->color);
    add_slant_option(*cmd, args->slant);
    add_bold_option(*cmd, args->bold);
    cmd->add_option("CHARS", args->chars,
                    "The characters, as --chars; a lone word that is no font file is CHARS");
    cmd->add_option("--chars", args->chars, "The characters (UTF-8); repeats are packed once")
        ->type_name("STRING");
    cmd->add_option("-o,--output-file", args->output_file, "The texture, a PNG (gray, or RGBA with --format rgba)")
        ->required()
        ->type_name("FILE");
    cmd->add_option("--json", args->json_file, "The metrics as JSON (default: stdout)")
        ->type_name("FILE");
    cmd->add_option("--format", args->format,
                    "gray: a coverage texture (a colour glyph gives its alpha); rgba: colour "
                    "glyphs in their colours, other glyphs white with alpha = coverage "
                    "(default gray)")
        ->check(CLI::IsMember({"gray", "rgba"}));
    add_strict_option(*cmd, args->strict);
    add_compression_option(*cmd, args->png);
    return Command{cmd, [args] { return run_atlas(*args); }};
}

}  // namespace bezel::cli
