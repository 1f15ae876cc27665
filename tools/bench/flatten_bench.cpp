// bench_flatten: every flattening method on every glyph of the test fonts, at 12 px and 512 px.
//
// For each font × size × method it prints, as a markdown table: the total segments produced, the
// largest distance measured between any curve and its polyline (dense sampling, both directions),
// and the time per glyph. A second table sweeps the tolerance for the bounded methods, the data
// behind kDefaultFlattenTolerancePx.
//
// Glyphs come from the font module (Font::outline at size = units per em: bezel Paths in font
// units, y down); the flatten transform scales them to pixels, so the tolerance is in pixels. Timing: the whole font flattened into one reused Polylines, best of
// five runs, divided by the glyph count (so it includes the walk over lines and moves).
//
// Usage: bench_flatten [tolerance_px]   (default: kDefaultFlattenTolerancePx)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bezel/flatten.hpp"
#include "bezel/font.hpp"

namespace {

using bezel::Affine;
using bezel::CubicBez;
using bezel::FlattenMethod;
using bezel::FlattenOptions;
using bezel::Path;
using bezel::Point;
using bezel::Polylines;
using bezel::QuadBez;

struct Font {
    std::string label;
    double units_per_em = 0;
    std::vector<Path> glyphs;
};

// The font's glyphs through the font module: Font::outline at size_px = units_per_em scales by
// exactly 1, so the paths are in font units (y down, every contour closed).
bool load_font(const std::string& file, const std::string& label, Font& font) {
    auto opened = bezel::Font::open(file);
    if (!opened) {
        std::fprintf(stderr, "%s\n", opened.error().message.c_str());
        return false;
    }
    font.label = label;
    font.units_per_em = opened->metrics().units_per_em;
    for (bezel::GlyphId gid = 0; gid < opened->glyph_count(); ++gid) {
        auto outline = opened->outline(gid, {font.units_per_em, bezel::Hinting::None});
        if (!outline) continue;
        if (!outline->path.empty()) font.glyphs.push_back(std::move(outline->path));
    }
    return true;
}

// --- Error measurement: dense samples of each curve against its polyline -------------------------

double segment_distance(Point p, Point a, Point b) {
    bezel::Vec2 ab = b - a, ap = p - a;
    double len2 = ab.length_squared();
    double s = len2 > 0 ? std::clamp(ap.dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (ap - ab * s).length();
}
double polyline_distance(const std::vector<Point>& poly, Point p) {
    double best = HUGE_VAL;
    for (std::size_t i = 0; i + 1 < poly.size(); ++i) best = std::min(best, segment_distance(p, poly[i], poly[i + 1]));
    return best;
}

// Hausdorff distance between a curve and a polyline, by sampling: n curve samples against the
// polyline, and each polyline vertex and segment midpoint against the curve samples' polyline.
// n is chosen so the samples' own polyline is within tol/100 of the curve (Wang's bound).
template <typename Curve>
double hausdorff(const Curve& c, double second_diff_bound, const std::vector<Point>& poly, double tol) {
    double n_real = std::sqrt(second_diff_bound / (8.0 * tol / 100.0));
    std::size_t n = static_cast<std::size_t>(std::clamp(std::ceil(n_real), 16.0, 4096.0));
    std::vector<Point> ref(n + 1);
    for (std::size_t i = 0; i <= n; ++i) ref[i] = c.eval(static_cast<double>(i) / static_cast<double>(n));
    double worst = 0;
    for (Point p : ref) worst = std::max(worst, polyline_distance(poly, p));
    for (std::size_t i = 0; i < poly.size(); ++i) {
        worst = std::max(worst, polyline_distance(ref, poly[i]));
        if (i + 1 < poly.size()) worst = std::max(worst, polyline_distance(ref, bezel::lerp(poly[i], poly[i + 1], 0.5)));
    }
    return worst;
}

// The largest curve-to-polyline distance over every curve of every glyph.
double measure_max_error(const Font& font, const Affine& m, const FlattenOptions& options) {
    double worst = 0;
    Polylines out;
    for (const Path& glyph : font.glyphs) {
        const auto& pts = glyph.points();
        std::size_t pi = 0;
        Point last;
        for (bezel::Verb v : glyph.verbs()) {
            switch (v) {
                case bezel::Verb::Move: case bezel::Verb::Line: last = m * pts[pi++]; break;
                case bezel::Verb::Close: break;
                case bezel::Verb::Quad: {
                    QuadBez q{last, m * pts[pi], m * pts[pi + 1]};
                    pi += 2;
                    Path one;
                    one.move_to(q.p0);
                    one.quad_to(q.p1, q.p2);
                    out.clear();
                    bezel::flatten(one, Affine::identity(), options, out);
                    std::vector<Point> poly(out.points.begin(), out.points.end());
                    if (poly.empty() || poly.back() != q.p2) poly.push_back(q.p2);  // closing dedup
                    worst = std::max(worst, hausdorff(q, 2.0 * (q.p0 - q.p1 * 2.0 + q.p2).length(), poly,
                                                      options.tolerance_px));
                    last = q.p2;
                    break;
                }
                case bezel::Verb::Cubic: {
                    CubicBez c{last, m * pts[pi], m * pts[pi + 1], m * pts[pi + 2]};
                    pi += 3;
                    Path one;
                    one.move_to(c.p0);
                    one.cubic_to(c.p1, c.p2, c.p3);
                    out.clear();
                    bezel::flatten(one, Affine::identity(), options, out);
                    std::vector<Point> poly(out.points.begin(), out.points.end());
                    if (poly.empty() || poly.back() != c.p3) poly.push_back(c.p3);
                    double dm = 6.0 * std::max((c.p0 - c.p1 * 2.0 + c.p2).length(), (c.p1 - c.p2 * 2.0 + c.p3).length());
                    worst = std::max(worst, hausdorff(c, dm, poly, options.tolerance_px));
                    last = c.p3;
                    break;
                }
            }
        }
    }
    return worst;
}

struct Timing {
    std::size_t segments = 0;
    double ns_per_glyph = 0;
};

Timing time_font(const Font& font, const Affine& m, const FlattenOptions& options) {
    Polylines out;
    Timing t;
    double best = HUGE_VAL;
    for (int run = 0; run < 5; ++run) {
        std::size_t segments = 0;
        auto start = std::chrono::steady_clock::now();
        for (const Path& glyph : font.glyphs) {
            out.clear();
            bezel::flatten(glyph, m, options, out);
            segments += out.points.size();  // closed contours: one segment per point
        }
        auto end = std::chrono::steady_clock::now();
        best = std::min(best, std::chrono::duration<double, std::nano>(end - start).count());
        t.segments = segments;
    }
    t.ns_per_glyph = best / static_cast<double>(font.glyphs.size());
    return t;
}

const char* method_name(FlattenMethod m) {
    switch (m) {
        case FlattenMethod::ClassicFlatness: return "ClassicFlatness (ε = 1e-4)";
        case FlattenMethod::DistanceSubdivision: return "DistanceSubdivision";
        case FlattenMethod::WangUniform: return "WangUniform";
        case FlattenMethod::ParabolaIntegral: return "ParabolaIntegral";
    }
    return "?";
}

}  // namespace

int main(int argc, char** argv) {
    double tol = argc > 1 ? std::atof(argv[1]) : bezel::kDefaultFlattenTolerancePx;
    if (!(tol > 0)) {
        std::fprintf(stderr, "usage: bench_flatten [tolerance_px > 0]\n");
        return 2;
    }
    std::vector<Font> fonts(2);
    const std::string dir = BEZEL_FONTS_DIR;
    if (!load_font(dir + "/dejavu-sans/DejaVuSans.ttf", "DejaVu Sans", fonts[0]) ||
        !load_font(dir + "/cantarell/Cantarell-Regular.otf", "Cantarell", fonts[1])) {
        return 1;
    }

    const FlattenMethod methods[] = {FlattenMethod::ClassicFlatness, FlattenMethod::DistanceSubdivision,
                                     FlattenMethod::WangUniform, FlattenMethod::ParabolaIntegral};
    std::printf("Tolerance %.4g px. Segments: total over all glyphs; error: max over all curves (px); time: ns per glyph.\n\n", tol);
    std::printf("| font (glyphs) | size | method | segments | max error px | ns/glyph |\n");
    std::printf("|---|---:|---|---:|---:|---:|\n");
    for (const Font& font : fonts) {
        for (double size : {12.0, 512.0}) {
            Affine m = Affine::scale(size / font.units_per_em);
            for (FlattenMethod method : methods) {
                FlattenOptions o{tol, method};
                Timing t = time_font(font, m, o);
                double err = measure_max_error(font, m, o);
                std::printf("| %s (%zu) | %.0f | %s | %zu | %.4f | %.0f |\n", font.label.c_str(), font.glyphs.size(),
                            size, method_name(method), t.segments, err, t.ns_per_glyph);
            }
        }
    }

    std::printf("\nTolerance sweep at 512 px, both fonts together (segments, max measured error px):\n\n");
    std::printf("| tolerance px | WangUniform | DistanceSubdivision | ParabolaIntegral |\n|---:|---|---|---|\n");
    for (double sweep : {0.25, 0.125, 0.1, 0.0625, 0.05, 0.03125}) {
        std::printf("| %.4g |", sweep);
        for (FlattenMethod method : {FlattenMethod::WangUniform, FlattenMethod::DistanceSubdivision,
                                     FlattenMethod::ParabolaIntegral}) {
            std::size_t segments = 0;
            double err = 0;
            for (const Font& font : fonts) {
                Affine m = Affine::scale(512.0 / font.units_per_em);
                FlattenOptions o{sweep, method};
                Polylines out;
                for (const Path& glyph : font.glyphs) {
                    out.clear();
                    bezel::flatten(glyph, m, o, out);
                    segments += out.points.size();
                }
                err = std::max(err, measure_max_error(font, m, o));
            }
            std::printf(" %zu, %.4f |", segments, err);
        }
        std::printf("\n");
    }
    return 0;
}
