// bench_raster — bezel's rasterizer against FreeType's smooth rasterizer, stb_truetype and AGG,
// on the same unhinted glyph outlines and the same preallocated A8 targets, in one run.
//
//   bench_raster [--font F]... [--sizes 12,16,...] [--glyphs ascii|all] [--reps N] [--json]
//                [--accuracy] [--breakdown] [--tolerance PX] [--only freetype|bezel|stb|agg]
//                [--inner N]   (N passes per rep instead of ≥ 20 ms: for callgrind counts)
//
// What is timed, per glyph, with the outline already loaded and converted outside the loop (bezel's
// from the font module, Font::outline via GlyphRasterizer::prepare; FreeType's its own FT_Outline),
// into the glyph's FreeType box (GlyphBoxMode::FreeType):
//   freetype  memset of the target + FT_Outline_Render(FT_RASTER_FLAG_AA) into it (the smooth
//             rasterizer flattens conics/cubics itself).
//   bezel     Rasterizer::fill_path of that outline placed in the box: flatten
//             (kDefaultRasterTolerancePx = 0.01 px, WangUniform, or --tolerance) + rasterize; the
//             fill writes every pixel, so clearing is included. The rasterizer alone is timed, not
//             the glyph path's per-call setup, so the figures track the rasterizer's own speed.
//   stb       stbtt_Rasterize (flatness 0.35 px, as stbtt_GetGlyphBitmap uses), which writes every
//             pixel of the target itself. Its own parse of the glyph (stbtt_GetGlyphShape) is
//             done outside the loop.
//   agg       renderer clear + rasterizer_scanline_aa over conv_curve(path_storage) +
//             render_scanlines_aa_solid (scanline_u8, gray8).
// Reported: ns per glyph = min over --reps runs (default 15) of (total time over all glyphs) /
// glyphs, the renderers' runs interleaved (time_interleaved), and the ratio FreeType time /
// bezel time (> 1 means bezel is faster).
//
// --accuracy also measures, per size, the error of bezel and FreeType against the reference:
// the same outline scaled by 16, rendered with bezel's float coverage and box-filtered 16×16
// back (mean and max |error| in 1/255 units).
#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <algorithm>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "bezel/diagnostics.hpp"
#include "bezel/font.hpp"
#include "bezel/glyph.hpp"
#include "bezel/raster.hpp"

#ifdef BEZEL_HAVE_STB
#define STB_TRUETYPE_IMPLEMENTATION
#define STBTT_STATIC
#include <stb_truetype.h>
#endif

#ifdef BEZEL_HAVE_AGG
#include <agg_conv_curve.h>
#include <agg_path_storage.h>
#include <agg_pixfmt_gray.h>
#include <agg_rasterizer_scanline_aa.h>
#include <agg_renderer_base.h>
#include <agg_renderer_scanline.h>
#include <agg_scanline_u.h>
#endif

namespace {

using bench::parse_sizes;
using bench::thread_ns;

// One glyph at one size. The box is FreeType's (GlyphBoxMode::FreeType: the 26.6 control box,
// floor/ceil), the same A8 target for every renderer.
struct Glyph {
    unsigned gid = 0;
    FT_Outline outline{};           // FreeType's own, owned copy, translated so its box starts at (0, 0)
    bezel::Path path;               // that outline in the box: pixels, y down, box at (0, 0)
    int width = 0, height = 0;      // the A8 target
    int box_x0 = 0, box_y1 = 0;     // box in y-up pixels (for stb, which parses the font itself)
#ifdef BEZEL_HAVE_AGG
    agg::path_storage agg_path;
#endif
};

struct Options {
    std::vector<std::string> fonts;
    std::vector<int> sizes{12, 16, 24, 32, 48, 64, 96, 128, 192, 256, 384, 512};
    bool all_glyphs = false;
    // 15, as the status runs of docs/rasterizer.md: on a guest whose speed drifts for minutes at
    // a time the minimum of 5 let the drift through (a ratio of 1.76 where the next run gave
    // 2.31; docs/perf-log.md).
    int reps = 15;
    int inner = 0;  // 0: adaptive (see time_ns_per_glyph); N: exactly N passes per rep
    bool json = false;
    bool accuracy = false;
    bool breakdown = false;  // also time bezel's flatten and fill apart
    double tolerance_px = bezel::kDefaultRasterTolerancePx;
    std::string only;  // time just this renderer (for profilers: callgrind, perf)
    bool runs(const char* name) const { return only.empty() || only == name; }
};

#ifdef BEZEL_HAVE_AGG
void to_agg(const bezel::Path& path, agg::path_storage& out) {
    const auto& pts = path.points();
    std::size_t i = 0;
    for (bezel::Verb v : path.verbs()) {
        switch (v) {
            case bezel::Verb::Move: out.move_to(pts[i].x, pts[i].y); i += 1; break;
            case bezel::Verb::Line: out.line_to(pts[i].x, pts[i].y); i += 1; break;
            case bezel::Verb::Quad:
                out.curve3(pts[i].x, pts[i].y, pts[i + 1].x, pts[i + 1].y);
                i += 2;
                break;
            case bezel::Verb::Cubic:
                out.curve4(pts[i].x, pts[i].y, pts[i + 1].x, pts[i + 1].y, pts[i + 2].x, pts[i + 2].y);
                i += 3;
                break;
            case bezel::Verb::Close: out.close_polygon(); break;
        }
    }
}
#endif

struct Face {
    std::string file;
    FT_Face face = nullptr;
    std::optional<bezel::Font> font;   // bezel's view of the same file
    std::optional<bezel::GlyphRasterizer> rasterizer;
    std::vector<unsigned char> bytes;  // for stb
#ifdef BEZEL_HAVE_STB
    stbtt_fontinfo stb{};
    bool stb_ok = false;
#endif
};

std::vector<unsigned> glyph_set(FT_Face face, bool all) {
    std::vector<unsigned> gids;
    if (all) {
        for (FT_Long g = 0; g < face->num_glyphs; ++g) gids.push_back(static_cast<unsigned>(g));
    } else {
        for (FT_ULong c = 33; c < 127; ++c) {
            FT_UInt g = FT_Get_Char_Index(face, c);
            if (g) gids.push_back(g);
        }
    }
    return gids;
}

// bezel's glyph comes from the font module (GlyphRasterizer::prepare: Font::outline, the path
// FreeType's FT_Outline_Decompose would give, in double); FreeType's rasterizer keeps its own
// FT_Outline, loaded at the same size.
std::vector<Glyph> load_glyphs(FT_Library lib, Face& f, int size, bool all, double tolerance_px) {
    std::vector<Glyph> out;
    FT_Set_Pixel_Sizes(f.face, 0, static_cast<FT_UInt>(size));
    bezel::GlyphRenderOptions options;
    options.size_px = size;
    options.box = bezel::GlyphBoxMode::FreeType;
    options.fill.flatten.tolerance_px = tolerance_px;
    for (unsigned gid : glyph_set(f.face, all)) {
        if (FT_Load_Glyph(f.face, gid, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP)) continue;
        FT_GlyphSlot slot = f.face->glyph;
        if (slot->format != FT_GLYPH_FORMAT_OUTLINE || slot->outline.n_points == 0) continue;
        auto prepared = f.rasterizer->prepare(gid, options);
        if (!prepared) {
            std::fprintf(stderr, "bench_raster: %s\n", prepared.error().message.c_str());
            continue;
        }
        const bezel::GlyphBox& box = prepared->box;
        if (box.width == 0 || box.height == 0) continue;
        Glyph g;
        g.gid = gid;
        g.width = box.width;
        g.height = box.height;
        g.box_x0 = box.left;
        g.box_y1 = box.top;
        g.path = prepared->path.transformed(
            bezel::Affine::translate({-double(box.left), double(box.top)}));
        FT_Outline_New(lib, static_cast<FT_UInt>(slot->outline.n_points),
                       slot->outline.n_contours, &g.outline);
        FT_Outline_Copy(&slot->outline, &g.outline);
        FT_Outline_Translate(&g.outline, -g.box_x0 * 64, -(g.box_y1 - g.height) * 64);
#ifdef BEZEL_HAVE_AGG
        to_agg(g.path, g.agg_path);
#endif
        out.push_back(std::move(g));
    }
    return out;
}

struct Target {
    std::vector<unsigned char> pixels;
    void fit(const std::vector<Glyph>& glyphs) {
        std::size_t most = 0;
        for (const Glyph& g : glyphs) most = std::max(most, std::size_t(g.width) * g.height);
        pixels.assign(most, 0);
    }
};

int g_inner = 0;  // --inner

// One renderer under test: `passes` runs over the glyph set make one timed run (≥ 20 ms, so the
// clock's resolution is irrelevant — unless --inner fixed the count: instruction counts under
// valgrind --tool=callgrind need the same work in every run, whatever the machine's load), and
// `best` is the least ns per glyph over the runs so far.
class Contender {
public:
    virtual ~Contender() = default;
    // Thread CPU ns of `passes` passes over the glyphs.
    virtual double run_ns(int passes) = 0;
    int passes = 1;
    double best = 1e300;
};

template <typename F>
class ContenderOf final : public Contender {
public:
    ContenderOf(const std::vector<Glyph>& glyphs, F render) : glyphs_(glyphs), render_(std::move(render)) {}
    double run_ns(int n) override {
        const double t0 = thread_ns();
        for (int i = 0; i < n; ++i)
            for (const Glyph& g : glyphs_) render_(g);
        return thread_ns() - t0;
    }

private:
    const std::vector<Glyph>& glyphs_;
    F render_;
};

template <typename F>
std::unique_ptr<Contender> contender(const std::vector<Glyph>& glyphs, F render) {
    return std::make_unique<ContenderOf<F>>(glyphs, std::move(render));
}

// Times the contenders in alternation: run r times each of them once, starting from a different
// one each time (r mod their count). On a shared or virtual machine the speed drifts by tens of
// percent within seconds (up to a third of the time stolen); timed one after the other, a slow
// stretch would land on one renderer and move the ratio, while interleaved runs sample the same
// stretches for each, and the minimum over runs keeps each one's quiet moments.
void time_interleaved(const std::vector<std::unique_ptr<Contender>>& cs, std::size_t glyphs, int reps) {
    for (const auto& c : cs) {
        c->passes = g_inner > 0 ? g_inner : 1;
        while (g_inner == 0 && c->run_ns(c->passes) < 20e6 && c->passes < (1 << 20)) c->passes *= 2;
    }
    const std::size_t n = cs.size();
    for (int r = 0; r < reps; ++r)
        for (std::size_t k = 0; k < n; ++k) {
            Contender& c = *cs[(static_cast<std::size_t>(r) + k) % n];
            c.best = std::min(c.best, c.run_ns(c.passes) / (double(c.passes) * double(glyphs)));
        }
}

// ns per glyph of one renderer timed alone (the --breakdown parts).
template <typename F>
double time_ns_per_glyph(const std::vector<Glyph>& glyphs, int reps, F&& render) {
    std::vector<std::unique_ptr<Contender>> one;
    one.push_back(contender(glyphs, std::forward<F>(render)));
    time_interleaved(one, glyphs.size(), reps);
    return one[0]->best;
}

void render_freetype(FT_Library lib, const Glyph& g, unsigned char* px) {
    std::memset(px, 0, std::size_t(g.width) * g.height);
    FT_Bitmap bm{};
    bm.rows = static_cast<unsigned>(g.height);
    bm.width = static_cast<unsigned>(g.width);
    bm.pitch = g.width;
    bm.buffer = px;
    bm.num_grays = 256;
    bm.pixel_mode = FT_PIXEL_MODE_GRAY;
    FT_Raster_Params params{};
    params.target = &bm;
    params.flags = FT_RASTER_FLAG_AA;
    FT_Outline_Render(lib, const_cast<FT_Outline*>(&g.outline), &params);
}

// Reference coverage: outline ×16 rendered with float coverage, each 16×16 block averaged.
std::vector<double> reference_16x(bezel::Rasterizer& r, const Glyph& g) {
    const int W = g.width * 16, H = g.height * 16;
    std::vector<float> big(std::size_t(W) * H);
    (void)r.fill_path(g.path, bezel::Affine::scale(16.0),
                      bezel::FloatMaskView{big.data(), W, H, W});
    std::vector<double> out(std::size_t(g.width) * g.height, 0.0);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) out[std::size_t(y / 16) * g.width + x / 16] += big[std::size_t(y) * W + x];
    for (double& v : out) v /= 256.0;
    return out;
}

struct ErrorStats {
    double sum = 0, max = 0;
    std::size_t n = 0;
    void add(double e) { sum += e; max = std::max(max, e); ++n; }
    double mean() const { return n ? sum / double(n) : 0.0; }
};

}  // namespace

int main(int argc, char** argv) {
    Options opt;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) { std::fprintf(stderr, "bench_raster: %s needs a value\n", a.c_str()); std::exit(2); }
            return argv[++i];
        };
        if (a == "--font") opt.fonts.push_back(next());
        else if (a == "--sizes") opt.sizes = parse_sizes(next());
        else if (a == "--glyphs") opt.all_glyphs = next() == "all";
        else if (a == "--reps") opt.reps = std::max(1, std::atoi(next().c_str()));
        else if (a == "--inner") opt.inner = std::max(1, std::atoi(next().c_str()));
        else if (a == "--json") opt.json = true;
        else if (a == "--accuracy") opt.accuracy = true;
        else if (a == "--breakdown") opt.breakdown = true;
        else if (a == "--tolerance") opt.tolerance_px = std::atof(next().c_str());
        else if (a == "--only") opt.only = next();
        else { std::fprintf(stderr, "bench_raster: unknown option %s\n", a.c_str()); return 2; }
    }
    if (opt.fonts.empty()) {
        opt.fonts = {std::string(BEZEL_FONTS_DIR) + "/dejavu-sans/DejaVuSans.ttf",
                     std::string(BEZEL_FONTS_DIR) + "/cantarell/Cantarell-Regular.otf"};
    }
    if (opt.sizes.empty()) { std::fprintf(stderr, "bench_raster: no valid --sizes\n"); return 2; }
    g_inner = opt.inner;

    FT_Library lib;
    if (FT_Init_FreeType(&lib)) { std::fprintf(stderr, "bench_raster: FreeType init failed\n"); return 1; }
    // The peer's version as loaded at run time (./dev bench can point it at another build).
    FT_Int ft_major = 0, ft_minor = 0, ft_patch = 0;
    FT_Library_Version(lib, &ft_major, &ft_minor, &ft_patch);
    std::fprintf(stderr, "bench_raster: FreeType %d.%d.%d, bezel kernels %s\n", ft_major, ft_minor,
                 ft_patch, bezel::raster_kernel_name());
    std::vector<Face> faces;
    for (const std::string& file : opt.fonts) {
        Face f;
        f.file = file;
        if (FT_New_Face(lib, file.c_str(), 0, &f.face)) {
            std::fprintf(stderr, "bench_raster: %s: cannot open font\n", file.c_str());
            return 1;
        }
        auto font = bezel::Font::open(file);
        if (!font) {
            std::fprintf(stderr, "bench_raster: %s\n", font.error().message.c_str());
            return 1;
        }
        f.font.emplace(std::move(*font));
        std::ifstream in(file, std::ios::binary);
        f.bytes.assign(std::istreambuf_iterator<char>(in), {});
        faces.push_back(std::move(f));
    }
    // Each rasterizer borrows its Font, which stays put once `faces` is complete.
    for (Face& f : faces) f.rasterizer.emplace(*f.font);
#ifdef BEZEL_HAVE_STB
    for (Face& f : faces)
        f.stb_ok = stbtt_InitFont(&f.stb, f.bytes.data(), stbtt_GetFontOffsetForIndex(f.bytes.data(), 0)) != 0;
#endif

    bezel::Rasterizer rast;
    bezel::FlattenOptions flat_opts;
    flat_opts.tolerance_px = opt.tolerance_px;
    bezel::FillOptions fill_opts;  // NonZero
    fill_opts.flatten = flat_opts;
    std::string json = "{\"kernels\":\"" + std::string(bezel::raster_kernel_name()) + "\",\"results\":[";
    bool first_json = true;
    if (!opt.json) {
        std::printf("%-22s %5s %6s %10s %10s %8s %10s %10s%s\n", "font", "size", "glyphs", "freetype",
                    "bezel", "ft/bezel", "stb", "agg", opt.accuracy ? "   err bezel mean/max  err ft mean/max (1/255)" : "");
    }
    for (Face& f : faces) {
        std::string name = f.file.substr(f.file.find_last_of('/') + 1);
        for (int size : opt.sizes) {
            std::vector<Glyph> glyphs = load_glyphs(lib, f, size, opt.all_glyphs, opt.tolerance_px);
            if (glyphs.empty()) continue;
            Target t;
            t.fit(glyphs);
            unsigned char* px = t.pixels.data();

            // The renderers' runs interleave (time_interleaved); each stays -1 when left out.
            std::vector<std::unique_ptr<Contender>> cs;
            Contender *c_ft = nullptr, *c_bz = nullptr, *c_stb = nullptr, *c_agg = nullptr;
            const auto add = [&](std::unique_ptr<Contender> c) {
                cs.push_back(std::move(c));
                return cs.back().get();
            };
            if (opt.runs("freetype"))
                c_ft = add(contender(glyphs, [&](const Glyph& g) { render_freetype(lib, g, px); }));
            if (opt.runs("bezel"))
                c_bz = add(contender(glyphs, [&](const Glyph& g) {
                    (void)rast.fill_path(g.path, bezel::Affine::identity(),
                                         bezel::MaskView{px, g.width, g.height, g.width}, fill_opts);
                }));
#ifdef BEZEL_HAVE_STB
            // stb parses its own glyph data; done once per glyph outside the timed loop.
            std::vector<std::pair<stbtt_vertex*, int>> shapes;
            std::size_t stb_k = 0;
            float stb_scale = 0.0f;
            if (f.stb_ok && opt.runs("stb")) {
                stb_scale = stbtt_ScaleForMappingEmToPixels(&f.stb, float(size));
                for (const Glyph& g : glyphs) {
                    stbtt_vertex* v = nullptr;
                    int n = stbtt_GetGlyphShape(&f.stb, int(g.gid), &v);
                    shapes.push_back({v, n});
                }
                c_stb = add(contender(glyphs, [&](const Glyph& g) {
                    const auto& s = shapes[stb_k++ % shapes.size()];
                    stbtt__bitmap bm{g.width, g.height, g.width, px};
                    stbtt_Rasterize(&bm, 0.35f, s.first, s.second, stb_scale, stb_scale, 0.0f, 0.0f,
                                    g.box_x0, -g.box_y1, 1, nullptr);
                }));
            }
#endif
#ifdef BEZEL_HAVE_AGG
            agg::rasterizer_scanline_aa<> ras;
            agg::scanline_u8 sl;
            if (opt.runs("agg"))
                c_agg = add(contender(glyphs, [&](const Glyph& g) {
                    agg::rendering_buffer rb(px, unsigned(g.width), unsigned(g.height), g.width);
                    agg::pixfmt_gray8 pf(rb);
                    agg::renderer_base<agg::pixfmt_gray8> rbase(pf);
                    rbase.clear(agg::gray8(0));
                    ras.reset();
                    agg::conv_curve<agg::path_storage> curves(const_cast<agg::path_storage&>(g.agg_path));
                    ras.add_path(curves);
                    agg::render_scanlines_aa_solid(ras, sl, rbase, agg::gray8(255));
                }));
#endif
            time_interleaved(cs, glyphs.size(), opt.reps);
            const auto best = [](const Contender* c) { return c ? c->best : -1.0; };
            const double ft = best(c_ft), bz = best(c_bz), stb = best(c_stb), agg_ns = best(c_agg);
#ifdef BEZEL_HAVE_STB
            for (auto& s : shapes) stbtt_FreeShape(&f.stb, s.first);
#endif
            if (opt.breakdown) {
                std::vector<bezel::Polylines> flat(glyphs.size());
                for (std::size_t k = 0; k < glyphs.size(); ++k)
                    bezel::flatten(glyphs[k].path, bezel::Affine::identity(), flat_opts, flat[k]);
                bezel::Polylines scratch;
                double fl = time_ns_per_glyph(glyphs, opt.reps, [&](const Glyph& g) {
                    scratch.clear();
                    bezel::flatten(g.path, bezel::Affine::identity(), flat_opts, scratch);
                });
                std::size_t k = 0, segs = 0;
                for (const auto& p : flat) segs += p.points.size();
                double fi = time_ns_per_glyph(glyphs, opt.reps, [&](const Glyph& g) {
                    (void)rast.fill(flat[k++ % flat.size()],
                                    bezel::MaskView{px, g.width, g.height, g.width});
                });
                std::fprintf(stderr, "  breakdown %s %d px: flatten %.0f ns, fill %.0f ns, %.0f segments/glyph\n",
                             name.c_str(), size, fl, fi, double(segs) / double(flat.size()));
            }
            ErrorStats eb, ef;
            if (opt.accuracy) {
                std::vector<unsigned char> mine, theirs;
                for (const Glyph& g : glyphs) {
                    std::vector<double> ref = reference_16x(rast, g);
                    mine.assign(ref.size(), 0);
                    theirs.assign(ref.size(), 0);
                    (void)rast.fill_path(g.path, bezel::Affine::identity(),
                                         bezel::MaskView{mine.data(), g.width, g.height, g.width},
                                         fill_opts);
                    render_freetype(lib, g, theirs.data());
                    for (std::size_t i = 0; i < ref.size(); ++i) {
                        eb.add(std::fabs(mine[i] - ref[i] * 255.0));
                        ef.add(std::fabs(theirs[i] - ref[i] * 255.0));
                    }
                }
            }
            if (opt.json) {
                char buf[512];
                std::snprintf(buf, sizeof buf,
                              "%s{\"font\":\"%s\",\"size\":%d,\"glyphs\":%zu,\"freetype_ns\":%.1f,"
                              "\"bezel_ns\":%.1f,\"ratio\":%.3f,\"stb_ns\":%.1f,\"agg_ns\":%.1f%s",
                              first_json ? "" : ",", name.c_str(), size, glyphs.size(), ft, bz,
                              ft / bz, stb, agg_ns, opt.accuracy ? "," : "}");
                json += buf;
                if (opt.accuracy) {
                    std::snprintf(buf, sizeof buf,
                                  "\"bezel_err_mean\":%.4f,\"bezel_err_max\":%.3f,"
                                  "\"freetype_err_mean\":%.4f,\"freetype_err_max\":%.3f}",
                                  eb.mean(), eb.max, ef.mean(), ef.max);
                    json += buf;
                }
                first_json = false;
            } else {
                // A renderer left out (--only, or not installed) shows as -1, its ratio as 0.
                std::printf("%-22s %5d %6zu %10.0f %10.0f %8.2f %10.0f %10.0f", name.c_str(), size,
                            glyphs.size(), ft, bz, ft > 0 && bz > 0 ? ft / bz : 0.0, stb, agg_ns);
                if (opt.accuracy)
                    std::printf("   %7.3f / %6.2f     %7.3f / %6.2f", eb.mean(), eb.max, ef.mean(), ef.max);
                std::printf("\n");
                std::fflush(stdout);
            }
            for (Glyph& g : glyphs) FT_Outline_Done(lib, &g.outline);
        }
    }
    if (opt.json) std::printf("%s]}\n", json.c_str());
    for (Face& f : faces) FT_Done_Face(f.face);
    FT_Done_FreeType(lib);
    return 0;
}
