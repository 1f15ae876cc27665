// Tests of bezel::Font against FreeType itself and against hand-computed outlines of the
// edge-case fonts (fonts-test/edge-cases/README.md says which glyph holds which case).
//
// The reference for every outline is FreeType's own FT_Outline_Decompose of the same glyph
// loaded the same way. Two adjustments make the comparison exact up to double rounding (1e-9 px):
//   - FT_Outline_Decompose computes implied midpoints in integers, truncating (a + b) / 2; the
//     reference decomposes a copy of the outline with every coordinate doubled, where the
//     midpoint is exact, and halves the result.
//   - FreeType ends every contour that ends on-curve with a line back to its start; bezel's Path
//     leaves that line to Close, so the reference drops it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include <unistd.h>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H
#include FT_MULTIPLE_MASTERS_H

#include "bezel/font.hpp"
#include "font/outline_convert.hpp"

namespace bezel {
namespace {

const std::string kFonts = BEZEL_FONTS_DIR;
const std::string kDejaVu = kFonts + "/dejavu-sans/DejaVuSans.ttf";
const std::string kCantarell = kFonts + "/cantarell/Cantarell-Regular.otf";
const std::string kEdge = kFonts + "/edge-cases/EdgeCases.ttf";
const std::string kEdgeVariable = kFonts + "/edge-cases/EdgeCasesVariable.ttf";
const std::string kEdgeCollection = kFonts + "/edge-cases/EdgeCases.ttc";

// FreeType ≤ 2.13.2 declares contour indices and counts `short`, later versions unsigned.
using ContourIndex = std::remove_pointer_t<decltype(FT_Outline::contours)>;
using OutlineCount = decltype(FT_Outline::n_points);

// Coordinates in the edge-case fonts are font units; at this size a pixel is a font unit.
constexpr double kEdgeUpem = 1000.0;

Font open_or_die(const std::string& file, int face_index = 0) {
    Expected<Font> font = Font::open(file, face_index);
    if (!font) {
        ADD_FAILURE() << font.error().message;
        std::abort();
    }
    return std::move(font).value();
}

GlyphId gid_for(const Font& font, char32_t c) {
    std::optional<GlyphId> gid = font.glyph_for_char(c);
    EXPECT_TRUE(gid.has_value()) << "U+" << std::hex << static_cast<unsigned>(c);
    return gid.value_or(0);
}

// ---- The FreeType reference ---------------------------------------------------------------------

struct Decomposed {
    // One entry per FreeType callback; a Move starts a contour.
    struct Op {
        Verb verb;
        std::vector<FT_Vector> pts;
    };
    std::vector<Op> ops;
};

int on_move(const FT_Vector* to, void* user) {
    static_cast<Decomposed*>(user)->ops.push_back({Verb::Move, {*to}});
    return 0;
}
int on_line(const FT_Vector* to, void* user) {
    static_cast<Decomposed*>(user)->ops.push_back({Verb::Line, {*to}});
    return 0;
}
int on_conic(const FT_Vector* c, const FT_Vector* to, void* user) {
    static_cast<Decomposed*>(user)->ops.push_back({Verb::Quad, {*c, *to}});
    return 0;
}
int on_cubic(const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* user) {
    static_cast<Decomposed*>(user)->ops.push_back({Verb::Cubic, {*c1, *c2, *to}});
    return 0;
}

// FreeType's decomposition of `outline` as a bezel Path, points mapped by (x, y) ↦ (x·scale,
// −y·scale). Returns false when FreeType rejects the outline.
bool reference_path(const FT_Outline& outline, double scale, Path& out) {
    std::vector<FT_Vector> doubled(outline.points, outline.points + outline.n_points);
    for (FT_Vector& v : doubled) {
        v.x *= 2;
        v.y *= 2;
    }
    FT_Outline copy = outline;
    copy.points = doubled.data();
    const FT_Outline_Funcs funcs = {on_move, on_line, on_conic, on_cubic, 0, 0};
    Decomposed d;
    if (FT_Outline_Decompose(&copy, &funcs, &d) != 0) return false;

    auto px = [scale](FT_Vector v) {
        return Point{static_cast<double>(v.x) / 2.0 * scale,
                     0.0 - static_cast<double>(v.y) / 2.0 * scale};
    };
    out.clear();
    for (std::size_t i = 0; i < d.ops.size(); ++i) {
        const Decomposed::Op& op = d.ops[i];
        const bool contour_ends = i + 1 == d.ops.size() || d.ops[i + 1].verb == Verb::Move;
        switch (op.verb) {
            case Verb::Move: out.move_to(px(op.pts[0])); break;
            case Verb::Line:
                // FreeType's closing line (always the contour's last call when the contour
                // ends on-curve): Close stands for it in bezel.
                if (!contour_ends) out.line_to(px(op.pts[0]));
                break;
            case Verb::Quad: out.quad_to(px(op.pts[0]), px(op.pts[1])); break;
            case Verb::Cubic: out.cubic_to(px(op.pts[0]), px(op.pts[1]), px(op.pts[2])); break;
            case Verb::Close: break;
        }
        if (contour_ends) out.close();
    }
    return true;
}

::testing::AssertionResult same_path(const Path& actual, const Path& expected, double tol) {
    if (actual.verbs() != expected.verbs()) {
        return ::testing::AssertionFailure() << "verbs differ: " << actual.verbs().size()
                                             << " vs " << expected.verbs().size() << " verbs";
    }
    if (actual.points().size() != expected.points().size()) {
        return ::testing::AssertionFailure() << "point counts differ";
    }
    for (std::size_t i = 0; i < actual.points().size(); ++i) {
        const Point a = actual.points()[i], e = expected.points()[i];
        if (!(std::abs(a.x - e.x) <= tol && std::abs(a.y - e.y) <= tol)) {
            return ::testing::AssertionFailure() << "point " << i << ": (" << a.x << ", " << a.y
                                                 << ") vs (" << e.x << ", " << e.y << ")";
        }
    }
    return ::testing::AssertionSuccess();
}

// A FreeType face of its own, loaded independently of bezel.
class FtFace {
public:
    explicit FtFace(const std::string& file, int face_index = 0) {
        EXPECT_EQ(FT_Init_FreeType(&library_), 0);
        EXPECT_EQ(FT_New_Face(library_, file.c_str(), face_index, &face_), 0) << file;
    }
    ~FtFace() {
        FT_Done_Face(face_);
        FT_Done_FreeType(library_);
    }
    FtFace(const FtFace&) = delete;
    FtFace& operator=(const FtFace&) = delete;
    FT_Face get() const { return face_; }

    // Loads `gid` as bezel does for `options`; returns the scale from outline units to pixels.
    double load(GlyphId gid, const OutlineOptions& options) {
        if (options.hinting != Hinting::None) {
            const FT_Int32 mode = options.hinting == Hinting::Light  ? FT_LOAD_TARGET_LIGHT
                                  : options.hinting == Hinting::Auto ? FT_LOAD_FORCE_AUTOHINT
                                                                     : FT_LOAD_DEFAULT;
            EXPECT_EQ(FT_Set_Char_Size(face_, 0, std::lround(options.size_px * 64.0), 72, 72), 0);
            EXPECT_EQ(FT_Load_Glyph(face_, gid, mode | FT_LOAD_NO_BITMAP), 0);
            return 1.0 / 64.0;
        }
        EXPECT_EQ(FT_Load_Glyph(face_, gid,
                                FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP),
                  0);
        return options.size_px / face_->units_per_EM;
    }
    void set_design_coordinates(const std::vector<double>& values) {
        std::vector<FT_Fixed> coords;
        for (double v : values) coords.push_back(std::lround(v * 65536.0));
        EXPECT_EQ(FT_Set_Var_Design_Coordinates(face_, static_cast<FT_UInt>(coords.size()),
                                                coords.data()),
                  0);
    }

private:
    FT_Library library_ = nullptr;
    FT_Face face_ = nullptr;
};

// Every glyph of the face: bezel's Path equals FreeType's decomposition to 1e-9 px, and bezel's
// points are FreeType's points, scaled, with kinds from their tags.
void expect_every_glyph_matches_freetype(Font& font, FtFace& ft, const OutlineOptions& options) {
    const double kTolPx = 1e-9;  // double rounding of the scale and of midpoints only
    std::size_t mismatches = 0;
    for (GlyphId gid = 0; gid < font.glyph_count() && mismatches < 5; ++gid) {
        Expected<GlyphOutline> outline = font.outline(gid, options);
        ASSERT_TRUE(outline) << outline.error().message;
        const double scale = ft.load(gid, options);
        const FT_Outline& ft_outline = ft.get()->glyph->outline;

        Path expected;
        ASSERT_TRUE(reference_path(ft_outline, scale, expected)) << "gid " << gid;
        ::testing::AssertionResult same = same_path(outline->path, expected, kTolPx);
        if (!same) {
            ADD_FAILURE() << font.file() << " gid " << gid << " (" << font.glyph_name(gid)
                          << "): " << same.message();
            ++mismatches;
            continue;
        }
        ASSERT_EQ(outline->points.size(), static_cast<std::size_t>(ft_outline.n_points));
        ASSERT_EQ(outline->contour_ends.size(), static_cast<std::size_t>(ft_outline.n_contours));
        for (int c = 0; c < ft_outline.n_contours; ++c) {
            ASSERT_EQ(outline->contour_ends[c], static_cast<std::size_t>(ft_outline.contours[c]));
        }
        for (int i = 0; i < ft_outline.n_points; ++i) {
            const OutlinePoint& p = outline->points[i];
            ASSERT_EQ(p.pos.x, static_cast<double>(ft_outline.points[i].x) * scale);
            ASSERT_EQ(p.pos.y, 0.0 - static_cast<double>(ft_outline.points[i].y) * scale);
            const int tag = FT_CURVE_TAG(ft_outline.tags[i]);
            const PointKind kind = tag == FT_CURVE_TAG_ON      ? PointKind::OnCurve
                                   : tag == FT_CURVE_TAG_CONIC ? PointKind::OffConic
                                                               : PointKind::OffCubic;
            ASSERT_EQ(p.kind, kind) << "gid " << gid << " point " << i;
        }
    }
    EXPECT_EQ(mismatches, 0u);
}

// ---- Every glyph against FreeType -------------------------------------------------------------

TEST(FontOutline, EveryDejaVuGlyphMatchesFreeTypeDecompose) {
    Font font = open_or_die(kDejaVu);
    FtFace ft(kDejaVu);
    ASSERT_EQ(font.glyph_count(), 6253u);
    expect_every_glyph_matches_freetype(font, ft, {37.5, Hinting::None});
    expect_every_glyph_matches_freetype(font, ft, {13.0, Hinting::Full});
}

TEST(FontOutline, EveryCantarellGlyphMatchesFreeTypeDecompose) {
    Font font = open_or_die(kCantarell);
    FtFace ft(kCantarell);
    ASSERT_EQ(font.glyph_count(), 1322u);
    expect_every_glyph_matches_freetype(font, ft, {37.5, Hinting::None});
    expect_every_glyph_matches_freetype(font, ft, {13.0, Hinting::Full});
}

TEST(FontOutline, EveryEdgeCaseGlyphMatchesFreeTypeDecompose) {
    for (const std::string& file : {kEdge, kEdgeVariable}) {
        Font font = open_or_die(file);
        FtFace ft(file);
        for (double size : {1.0, 17.0, 1000.0, kMaxFontSizePx}) {
            expect_every_glyph_matches_freetype(font, ft, {size, Hinting::None});
            expect_every_glyph_matches_freetype(font, ft, {size, Hinting::Full});
        }
    }
}

TEST(FontOutline, VariedGlyphsMatchFreeTypeDecompose) {
    Font font = open_or_die(kEdgeVariable);
    FtFace ft(kEdgeVariable);
    for (double wght : {100.0, 250.0, 900.0}) {
        ASSERT_TRUE(font.set_variations({{"wght", wght}}));
        ft.set_design_coordinates({wght});
        expect_every_glyph_matches_freetype(font, ft, {64.0, Hinting::None});
    }
}

// The unhinted path scales font units in double; FreeType's own unhinted scaling (at a size set
// with FT_Set_Char_Size) rounds to 26.6. They agree within FreeType's roundings, each ≤ 1/128 px:
// a simple glyph's point is rounded once, and the whole glyph is shifted by its rounded phantom
// point pp1 when hmtx's left side bearing differs from xMin (DejaVu's U+2422: lsb −125, xMin
// −126), so ≤ 2/128 px. A composite adds one rounded component offset per nesting level (DejaVu
// nests up to 4 deep): ≤ 6/128 px. The 16.16 scale factor adds < 0.001 px at these sizes.
// Measured: DejaVu worst simple 0.0113 px, composite 0.0222 px; Cantarell 0.0078 px.
TEST(FontOutline, ExactScalingAgreesWithFreeTypeScalingWithinItsRounding) {
    for (const std::string& file : {kDejaVu, kCantarell}) {
        Font font = open_or_die(file);
        FtFace ft(file);
        const double size_px = 41.3;
        ASSERT_EQ(FT_Set_Char_Size(ft.get(), 0, std::lround(size_px * 64.0), 72, 72), 0);
        const double ft_size_px = std::lround(size_px * 64.0) / 64.0;  // what FreeType was given
        double worst_simple_px = 0.0, worst_composite_px = 0.0;
        for (GlyphId gid = 0; gid < font.glyph_count(); ++gid) {
            Expected<GlyphOutline> outline = font.outline(gid, {ft_size_px, Hinting::None});
            ASSERT_TRUE(outline);
            ASSERT_EQ(FT_Load_Glyph(ft.get(), gid, FT_LOAD_NO_RECURSE | FT_LOAD_NO_HINTING), 0);
            const bool composite = ft.get()->glyph->format == FT_GLYPH_FORMAT_COMPOSITE;
            ASSERT_EQ(FT_Load_Glyph(ft.get(), gid, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP), 0);
            const FT_Outline& o = ft.get()->glyph->outline;
            ASSERT_EQ(outline->points.size(), static_cast<std::size_t>(o.n_points));
            double& worst = composite ? worst_composite_px : worst_simple_px;
            for (int i = 0; i < o.n_points; ++i) {
                const Point theirs{o.points[i].x / 64.0, -o.points[i].y / 64.0};
                worst = std::max(worst, std::abs(outline->points[i].pos.x - theirs.x));
                worst = std::max(worst, std::abs(outline->points[i].pos.y - theirs.y));
            }
        }
        EXPECT_LE(worst_simple_px, 2.0 / 128 + 0.001) << file;
        EXPECT_LE(worst_composite_px, 6.0 / 128 + 0.001) << file;
    }
}

// ---- Random outlines against FreeType ---------------------------------------------------------

// Random tag sequences, valid and not: bezel accepts exactly the outlines FreeType accepts and
// builds the same path from them.
TEST(OutlineConvert, RandomTagSequencesMatchFreeTypeDecompose) {
    std::mt19937 rng(20240607);
    std::uniform_int_distribution<int> coord(-3000, 3000);
    std::uniform_int_distribution<int> contour_count(0, 4);
    std::uniform_int_distribution<int> contour_length(1, 9);
    std::uniform_int_distribution<int> percent(0, 99);
    int well_formed = 0, accepted = 0, rejected = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        // Mostly well-formed outlines (no contour starting with a cubic point, cubic points in
        // pairs, never right after a conic point, and followed by an on-curve one), sometimes any tags at all, so that both of
        // FreeType's outcomes are exercised.
        const bool anything = percent(rng) < 25;
        std::vector<FT_Vector> pts;
        std::vector<char> tags;
        std::vector<ContourIndex> ends;
        const int contours = contour_count(rng);
        for (int c = 0; c < contours; ++c) {
            const int length = contour_length(rng);
            const std::size_t first = pts.size();
            auto push = [&](char tag) {
                pts.push_back(FT_Vector{coord(rng), coord(rng)});
                tags.push_back(tag);
            };
            while (pts.size() - first < static_cast<std::size_t>(length)) {
                const int r = percent(rng);
                const bool after_conic = pts.size() > first && tags.back() == FT_CURVE_TAG_CONIC;
                const bool after_cubic = pts.size() > first && tags.back() == FT_CURVE_TAG_CUBIC;
                if (anything) {
                    push(static_cast<char>(r % 3 == 0   ? FT_CURVE_TAG_ON
                                           : r % 3 == 1 ? FT_CURVE_TAG_CONIC
                                                        : FT_CURVE_TAG_CUBIC));
                } else if (after_cubic) {
                    push(FT_CURVE_TAG_ON);  // a cubic's end point: cubics imply no points
                } else if (r < 60 || pts.size() == first || after_conic) {
                    push(r % 2 == 0 ? FT_CURVE_TAG_ON : FT_CURVE_TAG_CONIC);
                } else {
                    push(FT_CURVE_TAG_CUBIC);
                    push(FT_CURVE_TAG_CUBIC);
                }
            }
            ends.push_back(static_cast<ContourIndex>(pts.size() - 1));
        }
        FT_Outline outline{};
        outline.n_contours = static_cast<OutlineCount>(ends.size());
        outline.n_points = static_cast<OutlineCount>(pts.size());
        outline.points = pts.data();
        outline.tags = tags.data();
        outline.contours = ends.data();

        const double scale = 0.37;
        std::vector<OutlinePoint> points;
        std::vector<std::size_t> contour_ends;
        ASSERT_TRUE(font_detail::read_ft_outline(outline, scale, points, contour_ends));
        Path actual;
        const bool ours = font_detail::path_from_points(points, contour_ends, actual).ok();
        Path expected;
        const bool theirs = reference_path(outline, scale, expected);
        ASSERT_EQ(ours, theirs) << "trial " << trial;
        if (!anything) {
            ++well_formed;
            ASSERT_TRUE(ours) << "trial " << trial << ": a well-formed outline was rejected";
        }
        if (ours) {
            ++accepted;
            ASSERT_TRUE(same_path(actual, expected, 1e-9)) << "trial " << trial;
        } else {
            ++rejected;
        }
    }
    // Both outcomes were exercised (the counts are fixed by the seed).
    EXPECT_GT(well_formed, 14000);
    EXPECT_GT(accepted, well_formed);
    EXPECT_GT(rejected, 1000);
}

TEST(OutlineConvert, MalformedStructureIsAnErrorNotACrash) {
    FT_Vector pts[3] = {{0, 0}, {10, 0}, {10, 10}};
    char tags[3] = {FT_CURVE_TAG_ON, FT_CURVE_TAG_ON, FT_CURVE_TAG_ON};
    std::vector<OutlinePoint> points;
    std::vector<std::size_t> ends;

    ContourIndex decreasing[2] = {2, 1};
    FT_Outline o{2, 3, pts, tags, decreasing, 0};
    EXPECT_FALSE(font_detail::read_ft_outline(o, 1.0, points, ends));

    ContourIndex past_end[1] = {3};
    o = FT_Outline{1, 3, pts, tags, past_end, 0};
    EXPECT_FALSE(font_detail::read_ft_outline(o, 1.0, points, ends));

    ContourIndex short_of_end[1] = {1};
    o = FT_Outline{1, 3, pts, tags, short_of_end, 0};
    EXPECT_FALSE(font_detail::read_ft_outline(o, 1.0, points, ends));

    ContourIndex ok_end[1] = {2};
    char bad_tags[3] = {FT_CURVE_TAG_ON, 3, FT_CURVE_TAG_ON};
    o = FT_Outline{1, 3, pts, bad_tags, ok_end, 0};
    Status s = font_detail::read_ft_outline(o, 1.0, points, ends);
    ASSERT_FALSE(s);
    EXPECT_EQ(s.error().message, "point 1 has an undefined tag");

    // Contour ends handed to path_from_points directly are checked too.
    Path path;
    std::vector<OutlinePoint> three(3);
    EXPECT_FALSE(font_detail::path_from_points(three, {5}, path));
    EXPECT_FALSE(font_detail::path_from_points(three, {1, 0}, path));
}

// ---- The edge cases, one by one (EdgeCases.ttf, README.md beside it) --------------------------

class EdgeCases : public ::testing::Test {
protected:
    Font font = open_or_die(kEdge);
    // At 1000 px a pixel is a font unit: expected points are the font's, y negated.
    GlyphOutline outline_of(char32_t c) {
        Expected<GlyphOutline> o = font.outline(gid_for(font, c), {kEdgeUpem, Hinting::None});
        EXPECT_TRUE(o) << (o ? "" : o.error().message);
        return o ? std::move(o).value() : GlyphOutline{};
    }
};

Path build(std::initializer_list<std::pair<Verb, std::vector<Point>>> ops) {
    Path p;
    for (const auto& [verb, pts] : ops) {
        switch (verb) {
            case Verb::Move: p.move_to(pts[0]); break;
            case Verb::Line: p.line_to(pts[0]); break;
            case Verb::Quad: p.quad_to(pts[0], pts[1]); break;
            case Verb::Cubic: p.cubic_to(pts[0], pts[1], pts[2]); break;
            case Verb::Close: p.close(); break;
        }
    }
    return p;
}

TEST_F(EdgeCases, AllOffCurveContourIsFourQuadsFromTheLastFirstMidpoint) {
    // 'A': off-curve points (100,100) (100,501) (501,501) (501,100), font units, y up.
    GlyphOutline o = outline_of('A');
    const Path expected = build({
        {Verb::Move, {{300.5, -100}}},  // midpoint of the last and the first point
        {Verb::Quad, {{100, -100}, {100, -300.5}}},
        {Verb::Quad, {{100, -501}, {300.5, -501}}},
        {Verb::Quad, {{501, -501}, {501, -300.5}}},
        {Verb::Quad, {{501, -100}, {300.5, -100}}},
        {Verb::Close, {}},
    });
    EXPECT_EQ(o.path.verbs(), expected.verbs());
    EXPECT_EQ(o.path.points(), expected.points());  // exact: midpoints of integers in double
    ASSERT_EQ(o.points.size(), 4u);
    for (const OutlinePoint& p : o.points) EXPECT_EQ(p.kind, PointKind::OffConic);
}

TEST_F(EdgeCases, ContourStartingOffCurveStartsAtLastOnCurvePointOrMidpoint) {
    GlyphOutline o = outline_of('B');
    const Path expected = build({
        // Contour 0 ends on-curve at (150,500): it starts there, the line back is the Close.
        {Verb::Move, {{150, -500}}},
        {Verb::Quad, {{150, -700}, {350, -700}}},
        {Verb::Quad, {{450, -600}, {450, -500}}},
        {Verb::Close, {}},
        // Contour 1 starts at (150,400) and ends at (150,101), both off-curve.
        {Verb::Move, {{150, -250.5}}},
        {Verb::Quad, {{150, -400}, {450, -400}}},
        {Verb::Quad, {{450, -100}, {300, -100.5}}},
        {Verb::Quad, {{150, -101}, {150, -250.5}}},
        {Verb::Close, {}},
    });
    EXPECT_EQ(o.path.verbs(), expected.verbs());
    EXPECT_EQ(o.path.points(), expected.points());
    EXPECT_EQ(o.contour_ends, (std::vector<std::size_t>{4, 8}));
}

TEST_F(EdgeCases, SinglePointContoursAreDegenerateContours) {
    GlyphOutline o = outline_of('.');
    const Path expected = build({
        {Verb::Move, {{250, -300}}},  // a lone on-curve point: Move + Close, no segment
        {Verb::Close, {}},
        {Verb::Move, {{100, 0}}},
        {Verb::Line, {{250, -150}}},
        {Verb::Line, {{400, 0}}},
        {Verb::Close, {}},
        {Verb::Move, {{250, -400}}},  // a lone off-curve point: a zero-length quad
        {Verb::Quad, {{250, -400}, {250, -400}}},
        {Verb::Close, {}},
    });
    EXPECT_EQ(o.path.verbs(), expected.verbs());
    EXPECT_EQ(o.path.points(), expected.points());
    EXPECT_EQ(o.contour_ends, (std::vector<std::size_t>{0, 3, 4}));
    // The control box includes the lone points: they are part of the outline's data.
    EXPECT_EQ(o.metrics.bounds_px, Rect(100, -400, 400, 0));
}

TEST_F(EdgeCases, CompositeAppliesComponentOffsetAndScale) {
    // 'C' = 'A' moved by (50, 0) + 'O' scaled by 0.5 and moved by (600, 200).
    GlyphOutline c = outline_of('C');
    GlyphOutline a = outline_of('A');
    GlyphOutline o = outline_of('O');
    ASSERT_EQ(c.points.size(), a.points.size() + o.points.size());
    EXPECT_EQ(c.contour_ends, (std::vector<std::size_t>{3, 7, 11}));
    for (std::size_t i = 0; i < a.points.size(); ++i) {
        EXPECT_EQ(c.points[i].pos, a.points[i].pos + Point(50, 0));
        EXPECT_EQ(c.points[i].kind, a.points[i].kind);
    }
    for (std::size_t i = 0; i < o.points.size(); ++i) {
        // y down: a move up by 200 font units is −200 px.
        EXPECT_EQ(c.points[a.points.size() + i].pos, o.points[i].pos * 0.5 + Point(600, -200));
    }
    EXPECT_EQ(c.path.verbs().size(), a.path.verbs().size() + o.path.verbs().size());
    EXPECT_EQ(c.metrics.bounds_px, Rect(150, -550, 950, -100));
    EXPECT_EQ(c.metrics.advance_px, 1000);
    EXPECT_EQ(c.metrics.left_bearing_px, 150);
}

TEST_F(EdgeCases, EmptyGlyphHasEmptyPathAndItsAdvance) {
    GlyphOutline space = outline_of(' ');
    EXPECT_TRUE(space.path.empty());
    EXPECT_TRUE(space.points.empty());
    EXPECT_TRUE(space.contour_ends.empty());
    EXPECT_TRUE(space.metrics.bounds_px.is_empty());
    EXPECT_EQ(space.metrics.advance_px, 300);
    EXPECT_EQ(space.metrics.left_bearing_px, 0);
    Expected<GlyphOutline> hinted = font.outline(space.gid, {12, Hinting::Full});
    ASSERT_TRUE(hinted);
    EXPECT_TRUE(hinted->path.empty());
}

TEST_F(EdgeCases, OverlappingContoursAreKeptAndFlagged) {
    GlyphOutline o = outline_of('O');
    const Path expected = build({
        {Verb::Move, {{100, -100}}}, {Verb::Line, {{100, -500}}}, {Verb::Line, {{500, -500}}},
        {Verb::Line, {{500, -100}}}, {Verb::Close, {}},
        {Verb::Move, {{300, -300}}}, {Verb::Line, {{300, -700}}}, {Verb::Line, {{700, -700}}},
        {Verb::Line, {{700, -300}}}, {Verb::Close, {}},
    });
    EXPECT_EQ(o.path.verbs(), expected.verbs());
    EXPECT_EQ(o.path.points(), expected.points());
    EXPECT_TRUE(o.overlapping_contours);
    EXPECT_FALSE(outline_of('A').overlapping_contours);
}

TEST_F(EdgeCases, ScalingIsExactAtAnySize) {
    // 'A' at 3 px: every coordinate is its font-unit value × 3/1000 in double.
    Expected<GlyphOutline> o = font.outline(gid_for(font, 'A'), {3.0, Hinting::None});
    ASSERT_TRUE(o);
    EXPECT_EQ(o->points[1].pos, Point(100 * (3.0 / 1000), 0.0 - 501 * (3.0 / 1000)));
    EXPECT_EQ(o->metrics.advance_px, 600 * (3.0 / 1000));
}

TEST_F(EdgeCases, FaceDataAndNames) {
    EXPECT_EQ(font.family_name(), "Bezel Edge Cases");
    EXPECT_EQ(font.style_name(), "Regular");
    EXPECT_EQ(font.face_count(), 1);
    EXPECT_EQ(font.face_index(), 0);
    EXPECT_EQ(font.glyph_count(), 7u);
    EXPECT_TRUE(font.is_scalable());
    EXPECT_FALSE(font.has_cubic_outlines());
    EXPECT_TRUE(font.axes().empty());
    EXPECT_EQ(font.glyph_name(gid_for(font, '.')), "period");
    EXPECT_EQ(font.glyph_name(0), ".notdef");
    EXPECT_EQ(font.glyph_name(7), "gid7");  // out of range: no name, no error
    EXPECT_FALSE(font.glyph_for_char(U'Z').has_value());
    EXPECT_FALSE(font.glyph_for_char(0x110000).has_value());
    EXPECT_FALSE(font.glyph_for_char(0xFFFFFFFF).has_value());
}

// ---- Metrics of known glyphs (values read from the fonts with fontTools) ----------------------

TEST(FontMetricsTest, DejaVuSansFaceAndGlyphMetrics) {
    Font font = open_or_die(kDejaVu);
    EXPECT_EQ(font.family_name(), "DejaVu Sans");
    EXPECT_FALSE(font.has_cubic_outlines());
    const FontMetrics m = font.metrics();
    EXPECT_EQ(m.units_per_em, 2048);
    EXPECT_EQ(m.ascender, 1901);
    EXPECT_EQ(m.descender, -483);
    EXPECT_EQ(m.line_gap, 0);

    const GlyphId g = gid_for(font, U'g');
    EXPECT_EQ(g, 74u);
    EXPECT_EQ(font.glyph_name(g), "g");
    // At 2048 px a pixel is a font unit: hmtx advance 1300, glyf bbox (113, −426)–(1114, 1147).
    Expected<GlyphMetrics> gm = font.glyph_metrics(g, {2048, Hinting::None});
    ASSERT_TRUE(gm);
    EXPECT_EQ(gm->advance_px, 1300);
    EXPECT_EQ(gm->left_bearing_px, 113);
    EXPECT_EQ(gm->bounds_px, Rect(113, -1147, 1114, 426));
    gm = font.glyph_metrics(g, {16, Hinting::None});
    ASSERT_TRUE(gm);
    EXPECT_EQ(gm->advance_px, 1300 * (16.0 / 2048));

    Expected<GlyphMetrics> space = font.glyph_metrics(gid_for(font, U' '), {2048, Hinting::None});
    ASSERT_TRUE(space);
    EXPECT_EQ(space->advance_px, 651);
    EXPECT_TRUE(space->bounds_px.is_empty());
}

TEST(FontMetricsTest, CantarellIsCubicWithKnownMetrics) {
    Font font = open_or_die(kCantarell);
    EXPECT_EQ(font.family_name(), "Cantarell");
    EXPECT_TRUE(font.has_cubic_outlines());
    const FontMetrics m = font.metrics();
    EXPECT_EQ(m.units_per_em, 1000);
    EXPECT_EQ(m.ascender, 983);
    EXPECT_EQ(m.descender, -217);
    const GlyphId g = gid_for(font, U'g');
    Expected<GlyphOutline> o = font.outline(g, {1000, Hinting::None});
    ASSERT_TRUE(o);
    EXPECT_EQ(o->metrics.advance_px, 570);
    EXPECT_EQ(o->metrics.bounds_px, Rect(52, -492, 487, 227));  // CFF control box, y negated
    bool has_cubic = false;
    for (Verb v : o->path.verbs()) {
        EXPECT_NE(v, Verb::Quad);
        has_cubic = has_cubic || v == Verb::Cubic;
    }
    EXPECT_TRUE(has_cubic);
}

TEST(FontMetricsTest, GlyphMetricsEqualOutlineMetrics) {
    Font font = open_or_die(kDejaVu);
    for (GlyphId gid = 0; gid < font.glyph_count(); gid += 7) {
        for (Hinting hinting : {Hinting::None, Hinting::Light, Hinting::Full, Hinting::Auto}) {
            const OutlineOptions options{11.0, hinting};
            Expected<GlyphMetrics> m = font.glyph_metrics(gid, options);
            Expected<GlyphOutline> o = font.outline(gid, options);
            ASSERT_TRUE(m && o);
            EXPECT_EQ(m->advance_px, o->metrics.advance_px);
            EXPECT_EQ(m->bounds_px, o->metrics.bounds_px);
            EXPECT_EQ(m->left_bearing_px, o->metrics.left_bearing_px);
        }
    }
}

TEST(FontMetricsTest, CompositeGlyphHasItsComponentsPoints) {
    // DejaVu's 'Agrave' is a composite of 'A' and 'grave'.
    Font font = open_or_die(kDejaVu);
    const OutlineOptions options{100, Hinting::None};
    Expected<GlyphOutline> agrave = font.outline(gid_for(font, U'À'), options);
    Expected<GlyphOutline> a = font.outline(gid_for(font, U'A'), options);
    ASSERT_TRUE(agrave && a);
    ASSERT_GT(agrave->points.size(), a->points.size());
    for (std::size_t i = 0; i < a->points.size(); ++i) {
        EXPECT_EQ(agrave->points[i].pos, a->points[i].pos);  // 'A' is placed with no offset
    }
}

// ---- Hinting ----------------------------------------------------------------------------------

TEST(FontHinting, HintingMovesPointsAtSmallSizesAndRoundsAdvances) {
    Font font = open_or_die(kDejaVu);
    const GlyphId a = gid_for(font, U'a');
    Expected<GlyphOutline> plain = font.outline(a, {11, Hinting::None});
    Expected<GlyphOutline> hinted = font.outline(a, {11, Hinting::Full});
    ASSERT_TRUE(plain && hinted);
    ASSERT_EQ(plain->points.size(), hinted->points.size());
    double moved_px = 0;
    for (std::size_t i = 0; i < plain->points.size(); ++i) {
        moved_px = std::max(moved_px, distance(plain->points[i].pos, hinted->points[i].pos));
    }
    EXPECT_GT(moved_px, 0.05);  // the hinter snaps stems and heights to the pixel grid
    EXPECT_LT(moved_px, 2.0);   // …without wrecking the glyph
    // TrueType hinting rounds the advance to whole pixels.
    EXPECT_EQ(hinted->metrics.advance_px, std::round(hinted->metrics.advance_px));
    EXPECT_NEAR(hinted->metrics.advance_px, plain->metrics.advance_px, 1.0);
    // Unhinted advance: 1255 font units at 11 px per 2048.
    EXPECT_EQ(plain->metrics.advance_px, 1255 * (11.0 / 2048));
}

TEST(FontHinting, LightHintingMovesPointsOnlyVerticallyAndAutoIsNotTheFontsOwn) {
    Font font = open_or_die(kDejaVu);
    for (char32_t c : {U'a', U'H', U'g', U'e'}) {
        const GlyphId gid = gid_for(font, c);
        Expected<GlyphOutline> plain = font.outline(gid, {11, Hinting::None});
        Expected<GlyphOutline> light = font.outline(gid, {11, Hinting::Light});
        Expected<GlyphOutline> full = font.outline(gid, {11, Hinting::Full});
        Expected<GlyphOutline> autohint = font.outline(gid, {11, Hinting::Auto});
        ASSERT_TRUE(plain && light && full && autohint);
        ASSERT_EQ(plain->points.size(), light->points.size());
        double moved_x = 0, moved_y = 0;
        for (std::size_t i = 0; i < plain->points.size(); ++i) {
            moved_x = std::max(moved_x, std::fabs(plain->points[i].pos.x - light->points[i].pos.x));
            moved_y = std::max(moved_y, std::fabs(plain->points[i].pos.y - light->points[i].pos.y));
        }
        // x only as FreeType's 26.6 scaling rounds it (half of 1/64 px); y snapped to the grid.
        EXPECT_LE(moved_x, 0.5 / 64 + 1e-9) << char(c);
        EXPECT_GT(moved_y, 0.05) << char(c);
        // DejaVu has its own TrueType instructions: the auto-hinter places points elsewhere.
        bool differs = false;
        for (std::size_t i = 0; i < full->points.size(); ++i)
            differs = differs || full->points[i].pos != autohint->points[i].pos;
        EXPECT_TRUE(differs) << char(c);
    }
}

TEST(FontHinting, HintedSizeChangesTakeEffect) {
    // The hinted char size is cached per Font; switching sizes must not reuse a stale one.
    Font font = open_or_die(kDejaVu);
    const GlyphId a = gid_for(font, U'a');
    Expected<GlyphOutline> at11 = font.outline(a, {11, Hinting::Full});
    Expected<GlyphOutline> at22 = font.outline(a, {22, Hinting::Full});
    Expected<GlyphOutline> at11_again = font.outline(a, {11, Hinting::Full});
    ASSERT_TRUE(at11 && at22 && at11_again);
    EXPECT_EQ(at11->path.points(), at11_again->path.points());
    EXPECT_NE(at11->metrics.advance_px, at22->metrics.advance_px);
}

// ---- Variable fonts ---------------------------------------------------------------------------

TEST(FontVariations, AxesAreListed) {
    Font font = open_or_die(kEdgeVariable);
    const std::vector<VariationAxis> axes = font.axes();
    ASSERT_EQ(axes.size(), 1u);
    EXPECT_EQ(axes[0].tag, "wght");
    EXPECT_EQ(axes[0].name, "Weight");
    EXPECT_EQ(axes[0].min_value, 100);
    EXPECT_EQ(axes[0].default_value, 400);
    EXPECT_EQ(axes[0].max_value, 900);
}

TEST(FontVariations, OutlineAndAdvanceFollowWeight) {
    // 'I' is a bar from x = 100 to 300 with advance 400 at wght 400; gvar moves its right edge
    // and advance by +200 at 900 and −100 at 100, linearly in between.
    Font font = open_or_die(kEdgeVariable);
    const GlyphId bar = gid_for(font, U'I');
    auto right_edge_and_advance = [&](std::optional<double> wght) {
        if (wght) {
            EXPECT_TRUE(font.set_variations({{"wght", *wght}}));
        } else {
            EXPECT_TRUE(font.set_variations({}));  // back to the defaults
        }
        Expected<GlyphOutline> o = font.outline(bar, {kEdgeUpem, Hinting::None});
        EXPECT_TRUE(o);
        return std::pair<double, double>{o->metrics.bounds_px.x1, o->metrics.advance_px};
    };
    EXPECT_EQ(right_edge_and_advance(std::nullopt), std::make_pair(300.0, 400.0));
    EXPECT_EQ(right_edge_and_advance(900), std::make_pair(500.0, 600.0));
    EXPECT_EQ(right_edge_and_advance(650), std::make_pair(400.0, 500.0));
    EXPECT_EQ(right_edge_and_advance(100), std::make_pair(200.0, 300.0));
    EXPECT_EQ(right_edge_and_advance(400), std::make_pair(300.0, 400.0));
    EXPECT_EQ(right_edge_and_advance(std::nullopt), std::make_pair(300.0, 400.0));
}

TEST(FontVariations, UnknownAxesAndOutOfRangeValuesAreErrors) {
    Font font = open_or_die(kEdgeVariable);
    Status s = font.set_variations({{"wdth", 100}});
    ASSERT_FALSE(s);
    EXPECT_EQ(s.error().message, kEdgeVariable + ": unknown variation axis 'wdth'");
    s = font.set_variations({{"wght", 901}});
    ASSERT_FALSE(s);
    EXPECT_EQ(s.error().message, kEdgeVariable + ": variation wght=901 out of range [100, 900]");
    EXPECT_FALSE(font.set_variations({{"wght", std::nan("")}}));
    EXPECT_FALSE(font.set_variations({{"wght", -HUGE_VAL}}));
    EXPECT_TRUE(font.set_variations({{"wght", 100}, {"wght", 900}}));  // the last one wins
    Expected<GlyphMetrics> m = font.glyph_metrics(gid_for(font, U'I'), {kEdgeUpem, Hinting::None});
    ASSERT_TRUE(m);
    EXPECT_EQ(m->advance_px, 600);

    Font plain = open_or_die(kEdge);
    s = plain.set_variations({{"wght", 700}});
    ASSERT_FALSE(s);
    EXPECT_EQ(s.error().message, kEdge + ": variation axis 'wght': the font has no variation axes");
    EXPECT_TRUE(plain.set_variations({}));
}

// ---- Collections ------------------------------------------------------------------------------

// Debian ships no .ttc among the installed packages' fonts, so make_fonts.py builds one from the
// two edge-case fonts with fontTools' TTCollection.
TEST(FontCollection, FacesOfACollectionOpenByIndex) {
    Font first = open_or_die(kEdgeCollection, 0);
    Font second = open_or_die(kEdgeCollection, 1);
    EXPECT_EQ(first.face_count(), 2);
    EXPECT_EQ(second.face_count(), 2);
    EXPECT_EQ(second.face_index(), 1);
    EXPECT_EQ(first.family_name(), "Bezel Edge Cases");
    EXPECT_EQ(second.family_name(), "Bezel Variable");
    EXPECT_TRUE(first.axes().empty());
    EXPECT_EQ(second.axes().size(), 1u);
    FtFace ft(kEdgeCollection, 1);
    expect_every_glyph_matches_freetype(second, ft, {50, Hinting::None});
}

// ---- Errors -----------------------------------------------------------------------------------

std::string temp_path(const std::string& name) {
    return (std::filesystem::temp_directory_path() /
            ("bezel_font_test_" + std::to_string(::getpid()) + "_" + name))
        .string();
}

void write_prefix(const std::string& from, const std::string& to, std::size_t bytes) {
    std::ifstream in(from, std::ios::binary);
    std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_LE(bytes, data.size());
    std::ofstream(to, std::ios::binary).write(data.data(), static_cast<std::streamsize>(bytes));
}

TEST(FontErrors, MissingFileAndDirectoryAreNamed) {
    const std::string missing = kFonts + "/no-such-font.ttf";
    Expected<Font> f = Font::open(missing);
    ASSERT_FALSE(f);
    EXPECT_EQ(f.error().message, missing + ": no such file");
    f = Font::open(kFonts);
    ASSERT_FALSE(f);
    EXPECT_EQ(f.error().message, kFonts + ": is a directory, not a font file");
}

TEST(FontErrors, NonFontAndTruncatedFilesGiveFreeTypesReason) {
    const std::string not_font = kFonts + "/edge-cases/make_fonts.py";
    Expected<Font> f = Font::open(not_font);
    ASSERT_FALSE(f);
    EXPECT_EQ(f.error().message, not_font + ": FreeType error 0x02 (unknown file format)");

    // Cut inside the table directory, and in the middle of the glyph data: FreeType rejects
    // both when it opens the face.
    for (std::size_t bytes : {0, 11, 100, 379860}) {
        const std::string truncated = temp_path("truncated_" + std::to_string(bytes) + ".ttf");
        write_prefix(kDejaVu, truncated, bytes);
        f = Font::open(truncated);
        EXPECT_FALSE(f) << bytes << " bytes";
        if (!f && bytes == 0) {
            EXPECT_EQ(f.error().message, truncated + ": empty file, not a font");
        } else if (!f) {
            EXPECT_EQ(f.error().message.rfind(truncated + ": FreeType error 0x", 0), 0u);
        }
        std::filesystem::remove(truncated);
    }
}

TEST(FontErrors, TruncatedFontsNeverCrash) {
    // Prefixes of every length class of the small edge-case font: opening may fail, and if it
    // succeeds every glyph either loads or fails with a message naming the file.
    std::ifstream in(kEdge, std::ios::binary);
    const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string truncated = temp_path("prefix.ttf");
    int opened = 0;
    for (std::size_t bytes = 0; bytes < data.size(); bytes += 7) {
        std::ofstream(truncated, std::ios::binary | std::ios::trunc)
            .write(data.data(), static_cast<std::streamsize>(bytes));
        Expected<Font> f = Font::open(truncated);
        if (!f) continue;
        ++opened;
        for (GlyphId gid = 0; gid < f->glyph_count(); ++gid) {
            for (Hinting hinting : {Hinting::None, Hinting::Light, Hinting::Full, Hinting::Auto}) {
                Expected<GlyphOutline> o = f->outline(gid, {20, hinting});
                if (!o) {
                    EXPECT_EQ(o.error().message.rfind(truncated + ": glyph ", 0), 0u);
                }
            }
        }
    }
    std::filesystem::remove(truncated);
    // FreeType opens the longer prefixes (54 of the 128 here) and fails per glyph instead: the
    // loop above did reach glyph loading.
    EXPECT_GT(opened, 0);
}

TEST(FontErrors, BadFaceIndexIsNamed) {
    Expected<Font> f = Font::open(kEdgeCollection, 2);
    ASSERT_FALSE(f);
    EXPECT_EQ(f.error().message, kEdgeCollection + ": face index 2 out of range (the file has 2 faces)");
    f = Font::open(kEdge, 1);
    ASSERT_FALSE(f);
    EXPECT_EQ(f.error().message, kEdge + ": face index 1 out of range (the file has 1 face)");
    f = Font::open(kEdge, -1);
    ASSERT_FALSE(f);
    EXPECT_EQ(f.error().message, kEdge + ": face index -1 out of range (0..65535)");
    f = Font::open(kEdge, kMaxFaceIndex + 1);
    ASSERT_FALSE(f);
}

TEST(FontErrors, BadSizesAreNamed) {
    Font font = open_or_die(kEdge);
    const GlyphId a = gid_for(font, U'A');
    const double bad_sizes[] = {0.0, -0.0, -1.0, std::nan(""), HUGE_VAL, -HUGE_VAL,
                                kMaxFontSizePx * 1.0001, std::numeric_limits<double>::denorm_min() * -1};
    for (double size : bad_sizes) {
        for (Hinting hinting : {Hinting::None, Hinting::Light, Hinting::Full, Hinting::Auto}) {
            Expected<GlyphOutline> o = font.outline(a, {size, hinting});
            ASSERT_FALSE(o) << size;
            EXPECT_NE(o.error().message.find("font size"), std::string::npos);
            EXPECT_FALSE(font.glyph_metrics(a, {size, hinting}));
        }
    }
    Expected<GlyphOutline> o = font.outline(a, {-2.5, Hinting::None});
    ASSERT_FALSE(o);
    EXPECT_EQ(o.error().message, kEdge + ": font size -2.5 px out of range (0, 16384]");
    // The bounds themselves: the largest size is accepted, and so is the smallest positive one.
    EXPECT_TRUE(font.outline(a, {kMaxFontSizePx, Hinting::None}));
    EXPECT_TRUE(font.outline(a, {kMaxFontSizePx, Hinting::Full}));
    EXPECT_TRUE(font.outline(a, {std::numeric_limits<double>::denorm_min(), Hinting::None}));
    EXPECT_TRUE(font.outline(a, {std::numeric_limits<double>::denorm_min(), Hinting::Full}));
}

TEST(FontErrors, GlyphIdOutOfRangeIsNamed) {
    Font font = open_or_die(kEdge);
    for (GlyphId gid : {GlyphId{7}, GlyphId{65535}, GlyphId{0xFFFFFFFF}}) {
        Expected<GlyphOutline> o = font.outline(gid, {12, Hinting::None});
        ASSERT_FALSE(o);
        EXPECT_EQ(o.error().message, kEdge + ": glyph id " + std::to_string(gid) +
                                         " out of range (the font has 7 glyphs)");
        EXPECT_FALSE(font.glyph_metrics(gid, {12, Hinting::Full}));
    }
}

TEST(FontLifetime, FontsMoveAndWorkIndependently) {
    std::vector<Font> fonts;
    for (int i = 0; i < 3; ++i) fonts.push_back(open_or_die(i == 1 ? kCantarell : kDejaVu));
    Font moved = std::move(fonts[0]);
    fonts[0] = open_or_die(kEdge);
    EXPECT_EQ(moved.family_name(), "DejaVu Sans");
    EXPECT_EQ(fonts[0].family_name(), "Bezel Edge Cases");
    EXPECT_EQ(fonts[1].family_name(), "Cantarell");
    // Loading at a hinted size in one Font does not disturb another of the same file.
    Expected<GlyphOutline> a1 = moved.outline(68, {9, Hinting::Full});
    Expected<GlyphOutline> a2 = fonts[2].outline(68, {30, Hinting::Full});
    Expected<GlyphOutline> a3 = moved.outline(68, {9, Hinting::Full});
    ASSERT_TRUE(a1 && a2 && a3);
    EXPECT_EQ(a1->path.points(), a3->path.points());
}

}  // namespace
}  // namespace bezel
