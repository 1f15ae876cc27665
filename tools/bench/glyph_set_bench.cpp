// bench_glyph_set — "the 94 ASCII glyphs of a font at size S into buffers": bezel's set call
// (Rasterizer::fill_paths) against FreeType's per-glyph loop, which is what a FreeType atlas
// does, and against bezel's own per-glyph loop.
//
//   bench_glyph_set [--font F]... [--sizes 12,16,24] [--reps N] [--inner N] [--threads-reps N]
//                   [--only freetype|bezel-loop|bezel-set|bezel-atlas]
//
// The glyphs are those of bench_raster (tools/bench/raster_bench.cpp): unhinted outlines loaded
// once outside the timing, FreeType's FT_Outline and bezel's Path of the same glyph in its
// FreeType box (GlyphBoxMode::FreeType). Each glyph has its own buffer (separate allocations),
// the same for every renderer. One pass renders the whole set:
//   freetype     per glyph, memset of its buffer + FT_Outline_Render(FT_RASTER_FLAG_AA);
//   bezel-loop   per glyph, Rasterizer::fill_path (which writes every pixel: clearing included);
//   bezel-set    one Rasterizer::fill_paths over the set (jobs built once, outside the timing,
//                as FreeType's FT_Bitmaps are);
//   bezel-atlas  the same call into one atlas, each glyph a sub-rectangle of it (rows of glyphs
//                packed left to right).
// Single thread: thread CPU time, the renderers' runs interleaved, min over --reps of ns per
// glyph (bench_raster's method). Two threads (reported apart, WALL time): the set split in two
// halves, each thread with its own Rasterizer (bezel) or FT_Library (FreeType), the min over
// --threads-reps runs of the wall time of both halves; on a machine shared with other work this
// figure is the noisier one.
#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "bench_common.hpp"
#include "bezel/diagnostics.hpp"
#include "bezel/font.hpp"
#include "bezel/glyph.hpp"
#include "bezel/raster.hpp"

namespace {

using bench::parse_sizes;
using bench::thread_ns;

double wall_ns() {
    return std::chrono::duration<double, std::nano>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

struct Glyph {
    FT_Outline outline{};   // FreeType's own copy, translated so its box starts at (0, 0)
    bezel::Path path;       // the same outline in the box: pixels, y down
    int width = 0, height = 0;
    std::vector<unsigned char> buffer;   // the glyph's own target
    int atlas_x = 0, atlas_y = 0;        // its rectangle in the atlas
};

struct Options {
    std::vector<std::string> fonts;
    std::vector<int> sizes{12, 16, 24};
    int reps = 15;
    int thread_reps = 15;
    int inner = 0;   // 0: passes chosen for ≥ 20 ms a run; N: exactly N (callgrind)
    std::string only;
    bool runs(const char* name) const { return only.empty() || only == name; }
};

std::vector<Glyph> load_glyphs(FT_Library lib, FT_Face face, bezel::GlyphRasterizer& rasterizer,
                               int size) {
    std::vector<Glyph> out;
    FT_Set_Pixel_Sizes(face, 0, static_cast<FT_UInt>(size));
    bezel::GlyphRenderOptions options;
    options.size_px = size;
    options.box = bezel::GlyphBoxMode::FreeType;
    for (FT_ULong c = 33; c < 127; ++c) {
        const FT_UInt gid = FT_Get_Char_Index(face, c);
        if (gid == 0 || FT_Load_Glyph(face, gid, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP)) continue;
        FT_GlyphSlot slot = face->glyph;
        if (slot->format != FT_GLYPH_FORMAT_OUTLINE || slot->outline.n_points == 0) continue;
        auto prepared = rasterizer.prepare(gid, options);
        if (!prepared) {
            std::fprintf(stderr, "bench_glyph_set: %s\n", prepared.error().message.c_str());
            continue;
        }
        const bezel::GlyphBox& box = prepared->box;
        if (box.width == 0 || box.height == 0) continue;
        Glyph g;
        g.width = box.width;
        g.height = box.height;
        g.path = prepared->path.transformed(
            bezel::Affine::translate({-double(box.left), double(box.top)}));
        FT_Outline_New(lib, static_cast<FT_UInt>(slot->outline.n_points), slot->outline.n_contours,
                       &g.outline);
        FT_Outline_Copy(&slot->outline, &g.outline);
        FT_Outline_Translate(&g.outline, -box.left * 64, -(box.top - box.height) * 64);
        g.buffer.assign(std::size_t(g.width) * std::size_t(g.height), 0);
        out.push_back(std::move(g));
    }
    return out;
}

void render_freetype(FT_Library lib, Glyph& g) {
    std::memset(g.buffer.data(), 0, g.buffer.size());
    FT_Bitmap bm{};
    bm.rows = static_cast<unsigned>(g.height);
    bm.width = static_cast<unsigned>(g.width);
    bm.pitch = g.width;
    bm.buffer = g.buffer.data();
    bm.num_grays = 256;
    bm.pixel_mode = FT_PIXEL_MODE_GRAY;
    FT_Raster_Params params{};
    params.target = &bm;
    params.flags = FT_RASTER_FLAG_AA;
    FT_Outline_Render(lib, &g.outline, &params);
}

bezel::MaskView view_of(Glyph& g) { return {g.buffer.data(), g.width, g.height, g.width}; }

// Shelf packing: glyphs left to right in rows of at most `atlas_w` pixels. Returns the height.
int pack(std::vector<Glyph>& glyphs, int atlas_w) {
    int x = 0, y = 0, shelf = 0;
    for (Glyph& g : glyphs) {
        if (x + g.width > atlas_w) {
            x = 0;
            y += shelf;
            shelf = 0;
        }
        g.atlas_x = x;
        g.atlas_y = y;
        x += g.width;
        shelf = std::max(shelf, g.height);
    }
    return y + shelf;
}

// One renderer: `pass()` renders the whole set once.
struct Contender {
    const char* name;
    std::function<void()> pass;
    int passes = 1;
    double best = -1;   // ns per glyph
};

// bench_raster's method: passes for ≥ 20 ms a run (unless --inner), runs interleaved starting
// from a different renderer each round, the minimum kept.
void time_interleaved(std::vector<Contender>& cs, std::size_t glyphs, int reps, int inner) {
    const auto run = [](Contender& c) {
        const double t0 = thread_ns();
        for (int i = 0; i < c.passes; ++i) c.pass();
        return thread_ns() - t0;
    };
    for (Contender& c : cs) {
        c.passes = inner > 0 ? inner : 1;
        while (inner == 0 && run(c) < 20e6 && c.passes < (1 << 20)) c.passes *= 2;
    }
    for (int r = 0; r < reps; ++r)
        for (std::size_t k = 0; k < cs.size(); ++k) {
            Contender& c = cs[(static_cast<std::size_t>(r) + k) % cs.size()];
            const double ns = run(c) / (double(c.passes) * double(glyphs));
            c.best = c.best < 0 ? ns : std::min(c.best, ns);
        }
}

// Two threads, each running `half(t)` (t = 0, 1) `passes` times; min over reps of the wall time
// per glyph. The renderers alternate round by round, as above.
void time_two_threads(std::vector<std::pair<Contender*, std::function<void(int)>>>& cs,
                      std::size_t glyphs, int reps) {
    const auto run = [](int passes, const std::function<void(int)>& half) {
        const double t0 = wall_ns();
        std::thread other([&] {
            for (int i = 0; i < passes; ++i) half(1);
        });
        for (int i = 0; i < passes; ++i) half(0);
        other.join();
        return wall_ns() - t0;
    };
    for (auto& [c, half] : cs) c->best = -1;
    for (int r = 0; r < reps; ++r)
        for (std::size_t k = 0; k < cs.size(); ++k) {
            auto& [c, half] = cs[(static_cast<std::size_t>(r) + k) % cs.size()];
            const double ns = run(c->passes, half) / (double(c->passes) * double(glyphs));
            c->best = c->best < 0 ? ns : std::min(c->best, ns);
        }
}

}  // namespace

int main(int argc, char** argv) {
    Options opt;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "bench_glyph_set: %s needs a value\n", a.c_str());
                std::exit(2);
            }
            return argv[++i];
        };
        if (a == "--font") opt.fonts.push_back(next());
        else if (a == "--sizes") opt.sizes = parse_sizes(next());
        else if (a == "--reps") opt.reps = std::max(1, std::atoi(next().c_str()));
        else if (a == "--threads-reps") opt.thread_reps = std::max(0, std::atoi(next().c_str()));
        else if (a == "--inner") opt.inner = std::max(1, std::atoi(next().c_str()));
        else if (a == "--only") opt.only = next();
        else {
            std::fprintf(stderr, "bench_glyph_set: unknown option %s\n", a.c_str());
            return 2;
        }
    }
    if (opt.fonts.empty())
        opt.fonts = {std::string(BEZEL_FONTS_DIR) + "/dejavu-sans/DejaVuSans.ttf",
                     std::string(BEZEL_FONTS_DIR) + "/cantarell/Cantarell-Regular.otf"};
    if (opt.sizes.empty()) {
        std::fprintf(stderr, "bench_glyph_set: no valid --sizes\n");
        return 2;
    }

    FT_Library lib, lib2;   // the second for the second thread (a library is one thread's)
    if (FT_Init_FreeType(&lib) || FT_Init_FreeType(&lib2)) {
        std::fprintf(stderr, "bench_glyph_set: FreeType init failed\n");
        return 1;
    }
    FT_Int ft_major = 0, ft_minor = 0, ft_patch = 0;
    FT_Library_Version(lib, &ft_major, &ft_minor, &ft_patch);
    std::fprintf(stderr, "bench_glyph_set: FreeType %d.%d.%d, bezel kernels %s\n", ft_major,
                 ft_minor, ft_patch, bezel::raster_kernel_name());
    std::printf("%-22s %5s %6s | %9s %9s %9s %9s %8s %8s | 2 threads: %9s %9s %8s\n", "font",
                "size", "glyphs", "freetype", "bz-loop", "bz-set", "bz-atlas", "ft/set",
                "loop/set", "freetype", "bz-set", "ft/set");
    for (const std::string& file : opt.fonts) {
        FT_Face face = nullptr;
        if (FT_New_Face(lib, file.c_str(), 0, &face)) {
            std::fprintf(stderr, "bench_glyph_set: %s: cannot open font\n", file.c_str());
            return 1;
        }
        auto font = bezel::Font::open(file);
        if (!font) {
            std::fprintf(stderr, "bench_glyph_set: %s\n", font.error().message.c_str());
            return 1;
        }
        bezel::GlyphRasterizer glyph_rasterizer(*font);
        const std::string name = file.substr(file.find_last_of('/') + 1);
        for (int size : opt.sizes) {
            std::vector<Glyph> glyphs = load_glyphs(lib, face, glyph_rasterizer, size);
            if (glyphs.empty()) continue;
            const int atlas_w = 16 * size;
            const int atlas_h = pack(glyphs, atlas_w);
            std::vector<unsigned char> atlas(std::size_t(atlas_w) * std::size_t(atlas_h), 0);
            const bezel::MaskView atlas_view{atlas.data(), atlas_w, atlas_h, atlas_w};
            std::vector<bezel::FillJob> jobs, atlas_jobs;
            for (Glyph& g : glyphs) {
                bezel::FillJob job;
                job.path = &g.path;
                job.target = view_of(g);
                jobs.push_back(job);
                job.target = atlas_view.sub(g.atlas_x, g.atlas_y, g.width, g.height);
                atlas_jobs.push_back(job);
            }
            const std::size_t half = jobs.size() / 2;

            bezel::Rasterizer rast, rast2;
            const bezel::FillOptions fill;
            const auto check = [](const bezel::Status& s) {
                if (!s) {
                    std::fprintf(stderr, "bench_glyph_set: %s\n", s.error().message.c_str());
                    std::exit(1);
                }
            };
            std::vector<Contender> cs;
            if (opt.runs("freetype"))
                cs.push_back({"freetype", [&] {
                                  for (Glyph& g : glyphs) render_freetype(lib, g);
                              }});
            if (opt.runs("bezel-loop"))
                cs.push_back({"bezel-loop", [&] {
                                  for (Glyph& g : glyphs)
                                      (void)rast.fill_path(g.path, bezel::Affine::identity(),
                                                           view_of(g), fill);
                              }});
            if (opt.runs("bezel-set"))
                cs.push_back({"bezel-set", [&] { check(rast.fill_paths(jobs, fill)); }});
            if (opt.runs("bezel-atlas"))
                cs.push_back({"bezel-atlas", [&] { check(rast.fill_paths(atlas_jobs, fill)); }});
            time_interleaved(cs, glyphs.size(), opt.reps, opt.inner);
            const auto best = [&](const char* n) {
                for (const Contender& c : cs)
                    if (std::strcmp(c.name, n) == 0) return c.best;
                return -1.0;
            };
            const auto passes = [&](const char* n) {
                for (const Contender& c : cs)
                    if (std::strcmp(c.name, n) == 0) return c.passes;
                return 1;
            };
            const double ft = best("freetype"), loop = best("bezel-loop"), set = best("bezel-set"),
                         at = best("bezel-atlas");

            // Two threads: the first half of the set on this thread, the second on another.
            Contender ft2{"freetype", {}, passes("freetype")}, set2{"bezel-set", {}, passes("bezel-set")};
            std::vector<std::pair<Contender*, std::function<void(int)>>> cs2;
            if (opt.thread_reps > 0 && opt.runs("freetype"))
                cs2.push_back({&ft2, [&](int t) {
                                   const std::size_t b = t == 0 ? 0 : half,
                                                     e = t == 0 ? half : glyphs.size();
                                   for (std::size_t k = b; k < e; ++k)
                                       render_freetype(t == 0 ? lib : lib2, glyphs[k]);
                               }});
            if (opt.thread_reps > 0 && opt.runs("bezel-set"))
                cs2.push_back({&set2, [&](int t) {
                                   if (t == 0)
                                       check(rast.fill_paths(jobs.data(), half, fill));
                                   else
                                       check(rast2.fill_paths(jobs.data() + half,
                                                              jobs.size() - half, fill));
                               }});
            if (!cs2.empty()) time_two_threads(cs2, glyphs.size(), opt.thread_reps);
            const double ft_t = ft2.best, set_t = set2.best;
            const auto ratio = [](double a, double b) { return a > 0 && b > 0 ? a / b : 0.0; };
            std::printf("%-22s %5d %6zu | %9.0f %9.0f %9.0f %9.0f %8.2f %8.2f | %20.0f %9.0f %8.2f\n",
                        name.c_str(), size, glyphs.size(), ft, loop, set, at, ratio(ft, set),
                        ratio(loop, set), ft_t, set_t, ratio(ft_t, set_t));
            std::fflush(stdout);
            for (Glyph& g : glyphs) FT_Outline_Done(lib, &g.outline);
        }
        FT_Done_Face(face);
    }
    FT_Done_FreeType(lib2);
    FT_Done_FreeType(lib);
    return 0;
}
