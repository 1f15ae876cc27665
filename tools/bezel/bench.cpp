// `bezel bench`: bezel's glyph rasterizer against FreeType's smooth rasterizer on every glyph of a
// font, per size: ns per glyph and the ratio FreeType / bezel (> 1: bezel is faster).
//
// What is timed, per glyph, on the same unhinted outline (loaded outside the timing) and the same
// preallocated A8 target of the glyph's box (FreeType's, GlyphBoxMode::FreeType; clearing
// included on both sides):
//   bezel     GlyphRasterizer::draw of the prepared glyph, as `bezel glyph` renders it
//             (flattening at kDefaultRasterTolerancePx + fill, which writes every pixel; accurate
//             overlap for glyphs the font marks as overlapping);
//   freetype  render_with_freetype (bezel/freetype_reference.hpp): memset +
//             FT_Outline_Render(FT_RASTER_FLAG_AA). Its outline is cached by the Font after the
//             first call for a glyph, so each glyph is rendered once untimed and then `inner`
//             times timed, and bezel the same way.
// Per size: ns/glyph = min over --repeat runs of (Σ over glyphs of the timed calls) /
// (inner · glyphs), in thread CPU time. stb_truetype and AGG are compared in tools/bench
// (bench_raster, built by `./dev bench`), not here.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>

#include "bezel/freetype_reference.hpp"
#include "bezel/font.hpp"
#include "bezel/glyph.hpp"
#include "cli_common.hpp"
#include "commands.hpp"

namespace bezel::cli {
namespace {

// Largest --sizes entry, in pixels, and most entries; largest --repeat.
constexpr double kMaxBenchSizePx = 2048.0;
constexpr std::size_t kMaxBenchSizes = 64;
constexpr int kMaxBenchRepeat = 1000;
// One timed run of a glyph set lasts at least this long, so the clock's resolution is irrelevant.
constexpr double kMinRunNs = 20e6;

struct BenchArgs {
    std::string font = BEZEL_DEFAULT_FONT;
    std::string sizes = "12,16,24,32,48,64,96,128,192,256,384,512";
    std::string read_file;
    bool json = false;
    int repeat = 3;
};

struct BenchRow {
    double size = 0, bezel_ns = 0, freetype_ns = 0, ratio = 0;
    std::size_t glyphs = 0;
};

const std::string kBenchCommand = "bezel bench";

double thread_ns() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) * 1e9 + double(ts.tv_nsec);
}

Expected<std::vector<double>> parse_sizes(const std::string& text) {
    std::vector<double> out;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        const std::optional<double> v = parse_number(item);
        if (!v || !(*v > 0 && *v <= kMaxBenchSizePx))
            return Error{"--sizes '" + text + "': '" + item + "' is not a size in (0, " +
                         std::to_string(int(kMaxBenchSizePx)) + "] px"};
        out.push_back(*v);
    }
    if (out.empty() || out.size() > kMaxBenchSizes)
        return Error{"--sizes '" + text + "': expected 1 to " + std::to_string(kMaxBenchSizes) +
                     " sizes"};
    return out;
}

// Σ over glyphs of the time of `inner` calls of `render(glyph)` after one untimed call.
template <typename F>
double time_set(const std::vector<PreparedGlyph>& glyphs, int inner, F&& render) {
    double total = 0;
    for (const PreparedGlyph& g : glyphs) {
        render(g);
        const double t0 = thread_ns();
        for (int i = 0; i < inner; ++i) render(g);
        total += thread_ns() - t0;
    }
    return total;
}

Expected<BenchRow> bench_size(Font& font, double size, int repeat) {
    GlyphRasterizer rasterizer(font);
    GlyphRenderOptions options;
    options.size_px = size;
    options.box = GlyphBoxMode::FreeType;   // the control box: FreeType's bitmap
    std::vector<PreparedGlyph> glyphs;
    std::size_t most = 0;
    for (GlyphId gid = 0; gid < font.glyph_count(); ++gid) {
        auto g = rasterizer.prepare(gid, options);
        if (!g) return g.error();
        if (g->box.width == 0 || g->box.height == 0 || g->path.empty()) continue;
        most = std::max(most, std::size_t(g->box.width) * std::size_t(g->box.height));
        glyphs.push_back(std::move(*g));
    }
    BenchRow row;
    row.size = size;
    row.glyphs = glyphs.size();
    if (glyphs.empty()) return row;
    std::vector<std::uint8_t> pixels(most);
    auto target = [&](const PreparedGlyph& g) {
        return MaskView{pixels.data(), g.box.width, g.box.height, g.box.width};
    };
    Status failed = ok_status();
    auto bezel = [&](const PreparedGlyph& g) {
        Status s = rasterizer.draw(g, target(g));
        if (!s) failed = s;
    };
    const OutlineOptions outline_options{size, Hinting::None};
    auto freetype = [&](const PreparedGlyph& g) {
        // The pen at (−left, top) from the bitmap's top-left corner, as draw() puts it.
        Status s = render_with_freetype(font, g.gid, outline_options, target(g),
                                        {-double(g.box.left), double(g.box.top)});
        if (!s) failed = s;
    };
    // Calls per glyph so that one run takes ≥ kMinRunNs for the faster of the two.
    const double probe = std::min(time_set(glyphs, 1, bezel), time_set(glyphs, 1, freetype));
    if (!failed) return failed.error();
    const int inner = static_cast<int>(std::clamp(std::ceil(kMinRunNs / std::max(probe, 1.0)), 1.0, 4096.0));
    double best_bezel = HUGE_VAL, best_ft = HUGE_VAL;
    for (int r = 0; r < repeat; ++r) {
        best_bezel = std::min(best_bezel, time_set(glyphs, inner, bezel));
        best_ft = std::min(best_ft, time_set(glyphs, inner, freetype));
    }
    if (!failed) return failed.error();
    const double calls = double(inner) * double(glyphs.size());
    row.bezel_ns = best_bezel / calls;
    row.freetype_ns = best_ft / calls;
    row.ratio = row.freetype_ns / row.bezel_ns;
    return row;
}

std::string format_table(const std::string& font, const std::vector<BenchRow>& rows) {
    std::string out = "font " + font + " (unhinted, all glyphs; ratio = freetype / bezel, > 1: bezel faster)\n";
    char line[160];
    std::snprintf(line, sizeof line, "%8s %7s %12s %12s %7s\n", "size", "glyphs", "bezel ns",
                  "freetype ns", "ratio");
    out += line;
    for (const BenchRow& r : rows) {
        std::snprintf(line, sizeof line, "%8g %7zu %12.1f %12.1f %7.2f\n", r.size, r.glyphs,
                      r.bezel_ns, r.freetype_ns, r.ratio);
        out += line;
    }
    return out;
}

std::string format_json(const std::vector<BenchRow>& rows) {
    nlohmann::ordered_json arr = nlohmann::ordered_json::array();
    for (const BenchRow& r : rows)
        arr.push_back({{"size", r.size}, {"bezel_ns", r.bezel_ns}, {"freetype_ns", r.freetype_ns},
                       {"ratio", r.ratio}, {"glyphs", r.glyphs}});
    return arr.dump(2) + "\n";
}

// Reads the JSON this command writes back; the error names the file and what is wrong.
Expected<std::vector<BenchRow>> read_rows(const std::string& file) {
    std::ifstream in(file);
    if (!in) return Error{file + ": cannot open"};
    nlohmann::json doc = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
    if (doc.is_discarded() || !doc.is_array())
        return Error{file + ": not a JSON array of bench rows"};
    std::vector<BenchRow> rows;
    for (const auto& item : doc) {
        const char* keys[] = {"size", "bezel_ns", "freetype_ns", "ratio", "glyphs"};
        for (const char* k : keys)
            if (!item.is_object() || !item.contains(k) || !item[k].is_number())
                return Error{file + ": row " + std::to_string(rows.size()) + " has no number '" +
                             k + "'"};
        BenchRow r;
        r.size = item["size"].get<double>();
        r.bezel_ns = item["bezel_ns"].get<double>();
        r.freetype_ns = item["freetype_ns"].get<double>();
        r.ratio = item["ratio"].get<double>();
        r.glyphs = item["glyphs"].get<std::size_t>();
        rows.push_back(r);
    }
    return rows;
}

int run_bench(const BenchArgs& args) {
    if (!args.read_file.empty()) {
        auto rows = read_rows(args.read_file);
        if (!rows) return fail_runtime(rows.error().message);
        return write_result("", args.json ? format_json(*rows) : format_table(args.read_file, *rows));
    }
    auto sizes = parse_sizes(args.sizes);
    if (!sizes) return fail_usage(sizes.error().message, kBenchCommand);
    if (args.repeat < 1 || args.repeat > kMaxBenchRepeat)
        return fail_usage("--repeat " + std::to_string(args.repeat) + ": expected 1.." +
                              std::to_string(kMaxBenchRepeat),
                          kBenchCommand);
    auto font = Font::open(args.font);
    if (!font) return fail_runtime(font.error().message);
    std::vector<BenchRow> rows;
    for (double size : *sizes) {
        auto row = bench_size(*font, size, args.repeat);
        if (!row) return fail_runtime(row.error().message);
        rows.push_back(*row);
    }
    return write_result("", args.json ? format_json(rows) : format_table(args.font, rows));
}

}  // namespace

Command add_bench_command(CLI::App& app) {
    auto args = std::make_shared<BenchArgs>();
    CLI::App* cmd = app.add_subcommand(
        "bench", "Time bezel's rasterizer against FreeType's on every glyph of a font");
    cmd->footer(
        "Per size: ns per glyph for bezel (Rasterizer::fill_path) and FreeType (FT_Outline_Render,\n"
        "smooth AA) on the same unhinted outlines and preallocated targets, clearing included, and\n"
        "the ratio freetype/bezel (> 1: bezel is faster). Thread CPU time, best of --repeat runs.\n"
        "stb_truetype and AGG are compared by tools/bench (bench_raster; `./dev bench`).\n"
        "--json prints [{size, bezel_ns, freetype_ns, ratio, glyphs}], which --read reads back.\n"
        "Examples:\n"
        "  bezel bench --sizes 12,48,512\n"
        "  bezel bench --font font.otf --json --repeat 5 > run.json\n"
        "  bezel bench --read run.json");
    cmd->add_option("--font", args->font, "Font file; default: the bundled DejaVu Sans")
        ->capture_default_str()
        ->type_name("FILE");
    cmd->add_option("--sizes", args->sizes, "Comma-separated em sizes in pixels")
        ->capture_default_str()
        ->type_name("LIST");
    cmd->add_option("--repeat", args->repeat, "Timed runs per size; the fastest counts")
        ->capture_default_str()
        ->type_name("N");
    cmd->add_flag("--json", args->json, "Print JSON instead of a table");
    cmd->add_option("--read", args->read_file, "Print a saved --json result instead of timing")
        ->type_name("FILE");
    return Command{cmd, [args] { return run_bench(*args); }};
}

}  // namespace bezel::cli
