// bezel_imgui (integrations/imgui): the Dear ImGui atlas bezel builds, against ImGui's own
// stb_truetype builder and an independent supersampled reference, its options and bad input, the
// SVG icon, and the SDL example under Xvfb.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <imgui.h>
#include <imgui_internal.h>

#include "bezel/font.hpp"
#include "bezel/image.hpp"
#include "bezel_imgui.hpp"
#include "support/cli_run.hpp"

namespace {

const std::string kDejaVu = std::string(BEZEL_FONTS_DIR) + "/dejavu-sans/DejaVuSans.ttf";
const std::string kCantarell = std::string(BEZEL_FONTS_DIR) + "/cantarell/Cantarell-Regular.otf";
const std::string kCjk = std::string(BEZEL_FONTS_DIR) + "/noto-cjk/NotoSansCJKjp-Subset.otf";

std::vector<char> read_file(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Font bytes kept by the test (FontDataOwnedByAtlas = false), so one file feeds many atlases.
struct FontBytes {
    std::vector<char> bytes;
    explicit FontBytes(const std::string& file) : bytes(read_file(file)) {}
};

ImFont* add_font(ImFontAtlas& atlas, FontBytes& font, float size, ImFontConfig cfg = {},
                 const ImWchar* ranges = nullptr) {
    cfg.FontDataOwnedByAtlas = false;
    return atlas.AddFontFromMemoryTTF(font.bytes.data(), static_cast<int>(font.bytes.size()), size,
                                      &cfg, ranges);
}

// A texel of a built atlas (alpha texture).
int texel(const ImFontAtlas& atlas, int x, int y) {
    return atlas.TexPixelsAlpha8[y * atlas.TexWidth + x];
}

// --- every requested glyph ----------------------------------------------------------------------

TEST(BezelImGuiAtlas, HoldsEveryRequestedGlyphOfMergedFonts) {
    FontBytes latin(kDejaVu), cjk(kCjk);
    const char* cjk_text = "日本語のテキスト、漢字とカタカナ。한국어";
    ImVector<ImWchar> cjk_ranges;
    ImFontGlyphRangesBuilder rb;
    rb.AddText(cjk_text);
    rb.AddChar('A');   // also in the first font: the first font's glyph must win
    rb.BuildRanges(&cjk_ranges);

    ImFontAtlas atlas;
    atlas.FontBuilderFlags = bezel_imgui::NoHinting;   // advances as the font's, unrounded
    ImFont* font = add_font(atlas, latin, 16);
    ImFontConfig merge;
    merge.MergeMode = true;
    add_font(atlas, cjk, 16, merge, cjk_ranges.Data);
    atlas.FontBuilderIO = bezel_imgui::builder();
    ASSERT_TRUE(atlas.Build()) << bezel_imgui::last_build_error();
    EXPECT_EQ(bezel_imgui::last_build_error(), "");

    auto dejavu = bezel::Font::open(kDejaVu);
    ASSERT_TRUE(dejavu.ok());
    int checked = 0;
    for (const ImWchar* r = atlas.GetGlyphRangesDefault(); r[0]; r += 2)
        for (unsigned cp = r[0]; cp <= r[1]; ++cp) {
            const ImFontGlyph* g = font->FindGlyphNoFallback(static_cast<ImWchar>(cp));
            EXPECT_EQ(g != nullptr, dejavu->glyph_for_char(cp).has_value()) << "U+" << std::hex << cp;
            ++checked;
        }
    EXPECT_EQ(checked, 0xFF - 0x20 + 1);   // ImGui's default: U+0020..U+00FF
    for (const ImWchar* r = cjk_ranges.Data; r[0]; r += 2)
        for (unsigned cp = r[0]; cp <= r[1]; ++cp) {
            const ImFontGlyph* g = font->FindGlyphNoFallback(static_cast<ImWchar>(cp));
            ASSERT_NE(g, nullptr) << "U+" << std::hex << cp;
            if (cp < 0x3000) continue;
            // An ideograph has ink: its texels are in the texture and not all zero.
            int ink = 0;
            for (int y = static_cast<int>(g->V0 * atlas.TexHeight); y < g->V1 * atlas.TexHeight; ++y)
                for (int x = static_cast<int>(g->U0 * atlas.TexWidth); x < g->U1 * atlas.TexWidth; ++x)
                    ink += texel(atlas, x, y) > 0;
            EXPECT_GT(ink, 20) << "U+" << std::hex << cp;
        }
    // 'A' comes from DejaVu (the first config), not from the merged CJK font.
    auto a_gid = dejavu->glyph_for_char('A');
    const bezel::FontMetrics m = dejavu->metrics();
    auto a_metrics =
        dejavu->glyph_metrics(*a_gid, {16.0 * m.units_per_em / (m.ascender - m.descender)});
    ASSERT_TRUE(a_metrics.ok());
    EXPECT_NEAR(font->FindGlyph('A')->AdvanceX, a_metrics->advance_px, 1e-3);
}

// ImGui's own default font (ProggyClean, compressed inside ImGui), which Build() adds when no
// font is configured.
TEST(BezelImGuiAtlas, BuildsImGuisDefaultFont) {
    ImFontAtlas atlas;
    atlas.FontBuilderIO = bezel_imgui::builder();
    ASSERT_TRUE(atlas.Build()) << bezel_imgui::last_build_error();
    ASSERT_EQ(atlas.Fonts.Size, 1);
    for (unsigned cp = 0x21; cp <= 0x7E; ++cp) {
        const ImFontGlyph* g = atlas.Fonts[0]->FindGlyphNoFallback(static_cast<ImWchar>(cp));
        ASSERT_NE(g, nullptr) << "U+" << std::hex << cp;
        EXPECT_TRUE(g->Visible) << "U+" << std::hex << cp;
    }
}

// --- metrics against ImGui's stb_truetype builder ----------------------------------------------

struct BuiltFont {
    ImFontAtlas atlas;
    ImFont* font = nullptr;
};

void build(BuiltFont& b, FontBytes& bytes, float size, const ImFontBuilderIO* io,
           const ImFontConfig& cfg = {}) {
    b.font = add_font(b.atlas, bytes, size, cfg);
    b.atlas.FontBuilderIO = io;
    ASSERT_TRUE(b.atlas.Build()) << bezel_imgui::last_build_error();
}

// Advance and glyph box (X0, Y0, X1, Y1) of every glyph of ImGui's default ranges (ASCII and
// Latin-1) within 1 px of the stb_truetype builder's, unhinted, at the default oversampling (3×1)
// and at none, on a TrueType and a CFF font. Ascent and descent equal.
TEST(BezelImGuiAtlas, MetricsWithinOnePixelOfStbTruetype) {
    for (const std::string& file : {kDejaVu, kCantarell}) {
        FontBytes bytes(file);
        for (float size : {13.0f, 16.0f, 24.0f}) {
            for (int oversample : {1, 3}) {
                ImFontConfig cfg;
                cfg.OversampleH = oversample;
                cfg.FontBuilderFlags = bezel_imgui::NoHinting;
                BuiltFont ours, stb;
                build(ours, bytes, size, bezel_imgui::builder(), cfg);
                build(stb, bytes, size, ImFontAtlasGetBuilderForStbTruetype(), cfg);
                SCOPED_TRACE(file + " " + std::to_string(size) + " px, oversample " +
                             std::to_string(oversample));
                EXPECT_EQ(ours.font->Ascent, stb.font->Ascent);
                EXPECT_EQ(ours.font->Descent, stb.font->Descent);
                ASSERT_EQ(ours.font->Glyphs.Size, stb.font->Glyphs.Size);
                for (const ImFontGlyph& s : stb.font->Glyphs) {
                    const ImFontGlyph* g = ours.font->FindGlyphNoFallback(static_cast<ImWchar>(s.Codepoint));
                    ASSERT_NE(g, nullptr) << "U+" << std::hex << s.Codepoint;
                    EXPECT_NEAR(g->AdvanceX, s.AdvanceX, 1.0f) << "U+" << std::hex << s.Codepoint;
                    if (!s.Visible) continue;
                    EXPECT_NEAR(g->X0, s.X0, 1.0f) << "U+" << std::hex << s.Codepoint;
                    EXPECT_NEAR(g->Y0, s.Y0, 1.0f) << "U+" << std::hex << s.Codepoint;
                    EXPECT_NEAR(g->X1, s.X1, 1.0f) << "U+" << std::hex << s.Codepoint;
                    EXPECT_NEAR(g->Y1, s.Y1, 1.0f) << "U+" << std::hex << s.Codepoint;
                }
            }
        }
    }
}

// --- coverage against an independent 64×64-sample reference ----------------------------------

// The outline as line segments with their winding direction, flattened here on its own (uniform
// parameter steps, n = ⌈√(‖second difference‖ / (8 · 0.001))⌉, so each chord is within 0.001 px of
// its curve), not by bezel's flattener.
struct Edge {
    double x0, y0, x1, y1;
};

std::vector<Edge> reference_edges(const bezel::Path& path) {
    std::vector<Edge> edges;
    for (std::size_t i = 0; i < path.segment_count(); ++i) {
        const bezel::PathSeg s = path.segment(i);
        const bezel::Point* p = s.p;
        auto at = [&](double t) -> bezel::Point {
            const double u = 1 - t;
            if (s.kind == bezel::SegKind::Line) return {u * p[0].x + t * p[1].x, u * p[0].y + t * p[1].y};
            if (s.kind == bezel::SegKind::Quad)
                return {u * u * p[0].x + 2 * u * t * p[1].x + t * t * p[2].x,
                        u * u * p[0].y + 2 * u * t * p[1].y + t * t * p[2].y};
            return {u * u * u * p[0].x + 3 * u * u * t * p[1].x + 3 * u * t * t * p[2].x + t * t * t * p[3].x,
                    u * u * u * p[0].y + 3 * u * u * t * p[1].y + 3 * u * t * t * p[2].y + t * t * t * p[3].y};
        };
        double dd = 0;
        if (s.kind == bezel::SegKind::Quad)
            dd = std::hypot(p[0].x - 2 * p[1].x + p[2].x, p[0].y - 2 * p[1].y + p[2].y);
        if (s.kind == bezel::SegKind::Cubic)
            dd = 1.5 * std::max(std::hypot(p[0].x - 2 * p[1].x + p[2].x, p[0].y - 2 * p[1].y + p[2].y),
                                std::hypot(p[1].x - 2 * p[2].x + p[3].x, p[1].y - 2 * p[2].y + p[3].y));
        const int n = std::max(1, static_cast<int>(std::ceil(std::sqrt(dd / (8 * 0.001)))));
        bezel::Point a = p[0];
        for (int k = 1; k <= n; ++k) {
            const bezel::Point b = k == n ? s.end() : at(static_cast<double>(k) / n);
            edges.push_back({a.x, a.y, b.x, b.y});
            a = b;
        }
    }
    return edges;
}

// The x intervals inside the outline (non-zero winding) along the horizontal line at y.
std::vector<std::pair<double, double>> inside_at(const std::vector<Edge>& edges, double y) {
    std::vector<std::pair<double, int>> xs;
    for (const Edge& e : edges) {
        if ((e.y0 <= y) == (e.y1 <= y)) continue;   // half-open in y: each vertex counted once
        const double t = (y - e.y0) / (e.y1 - e.y0);
        xs.push_back({e.x0 + t * (e.x1 - e.x0), e.y1 > e.y0 ? 1 : -1});
    }
    std::sort(xs.begin(), xs.end());
    std::vector<std::pair<double, double>> spans;
    int winding = 0;
    for (std::size_t i = 0; i < xs.size(); ++i) {
        const int before = winding;
        winding += xs[i].second;
        if (before == 0 && winding != 0) spans.push_back({xs[i].first, xs[i].first});
        if (before != 0 && winding == 0) spans.back().second = xs[i].first;
    }
    return spans;
}

constexpr int kRefSamples = 64;   // per pixel, each axis: 4096 point samples per window

// Samples x = x0 + (i + ½)/64, i = 0..63, that fall in [a, b).
int samples_in(double x0, double a, double b) {
    const auto first = [&](double v) {   // smallest i with sample ≥ v
        return std::clamp(static_cast<int>(std::ceil((v - x0) * kRefSamples - 0.5)), 0, kRefSamples);
    };
    return first(b) - first(a);
}

// Mean absolute error, in units of full coverage, between a glyph's atlas texels and the
// reference coverage of the one-pixel windows they stand for (texel (t, r) of a glyph drawn with
// oversampling h × v: the window whose centre is at X0 + (t + ½)/h, Y0 + (r + ½)/v from the pen),
// over the texels of the rectangle grown by 2 px (ink a builder left out of its rectangle counts
// as error), divided by the number of texels the reference inks.
double glyph_error(const ImFontAtlas& atlas, const ImFontGlyph& g, float baseline_y,
                   const std::vector<Edge>& edges, int h, int v) {
    const int u0 = static_cast<int>(std::lround(g.U0 * atlas.TexWidth));
    const int v0 = static_cast<int>(std::lround(g.V0 * atlas.TexHeight));
    const int w = static_cast<int>(std::lround(g.U1 * atlas.TexWidth)) - u0;
    const int hh = static_cast<int>(std::lround(g.V1 * atlas.TexHeight)) - v0;
    const double qx = g.X0, qy = g.Y0 - baseline_y;
    double error = 0;
    int inked = 0;
    for (int r = -2 * v; r < hh + 2 * v; ++r) {
        const double wy = qy + (r + 0.5) / v - 0.5;
        std::vector<Edge> local;   // the edges that reach this window's rows
        for (const Edge& e : edges)
            if (std::max(e.y0, e.y1) >= wy && std::min(e.y0, e.y1) <= wy + 1) local.push_back(e);
        std::vector<std::vector<std::pair<double, double>>> rows(kRefSamples);
        for (int j = 0; j < kRefSamples; ++j) rows[j] = inside_at(local, wy + (j + 0.5) / kRefSamples);
        for (int t = -2 * h; t < w + 2 * h; ++t) {
            const double wx = qx + (t + 0.5) / h - 0.5;
            int count = 0;
            for (const auto& spans : rows)
                for (const auto& [a, b] : spans) count += samples_in(wx, a, b);
            const double ref = static_cast<double>(count) / (kRefSamples * kRefSamples);
            const bool in_rect = t >= 0 && t < w && r >= 0 && r < hh;
            const double got = in_rect ? texel(atlas, u0 + t, v0 + r) / 255.0 : 0.0;
            error += std::abs(got - ref);
            inked += ref > 0;
        }
    }
    return inked ? error / inked : 0;
}

// Over ASCII '!'..'~' of DejaVu Sans, unhinted, the mean of the per-glyph errors above: bezel's
// must be under 1/255 and below stb_truetype's, at 13 and 24 px without oversampling and at
// 16 px with ImGui's default 3×1.
TEST(BezelImGuiAtlas, CoverageCloserThanStbTruetypeToSupersampledReference) {
    FontBytes bytes(kDejaVu);
    auto font = bezel::Font::open(kDejaVu);
    ASSERT_TRUE(font.ok());
    const bezel::FontMetrics m = font->metrics();
    for (auto [size, oversample] : {std::pair{13.0f, 1}, std::pair{24.0f, 1}, std::pair{16.0f, 3}}) {
        {
            ImFontConfig cfg;
            cfg.OversampleH = oversample;
            cfg.FontBuilderFlags = bezel_imgui::NoHinting;
            static const ImWchar ascii[] = {0x21, 0x7E, 0};
            cfg.GlyphRanges = ascii;
            BuiltFont ours, stb;
            build(ours, bytes, size, bezel_imgui::builder(), cfg);
            build(stb, bytes, size, ImFontAtlasGetBuilderForStbTruetype(), cfg);
            const double em_px = size * m.units_per_em / (m.ascender - m.descender);
            double sum_ours = 0, sum_stb = 0;
            int n = 0;
            for (unsigned cp = 0x21; cp <= 0x7E; ++cp) {
                auto gid = font->glyph_for_char(cp);
                ASSERT_TRUE(gid.has_value());
                auto outline = font->outline(*gid, {em_px});
                ASSERT_TRUE(outline.ok());
                const auto edges = reference_edges(outline->path);
                const ImFontGlyph* a = ours.font->FindGlyphNoFallback(static_cast<ImWchar>(cp));
                const ImFontGlyph* b = stb.font->FindGlyphNoFallback(static_cast<ImWchar>(cp));
                ASSERT_TRUE(a && b);
                sum_ours += glyph_error(ours.atlas, *a, IM_ROUND(ours.font->Ascent), edges, oversample, 1);
                sum_stb += glyph_error(stb.atlas, *b, IM_ROUND(stb.font->Ascent), edges, oversample, 1);
                ++n;
            }
            const double mean_ours = sum_ours / n * 255, mean_stb = sum_stb / n * 255;
            std::printf("coverage error, %g px, oversample %d: bezel %.3f/255, stb_truetype %.3f/255\n",
                        size, oversample, mean_ours, mean_stb);
            EXPECT_LT(mean_ours, 1.0) << size << " px, oversample " << oversample;
            EXPECT_LT(mean_ours, mean_stb) << size << " px, oversample " << oversample;
        }
    }
}

}  // namespace

namespace {

// --- bad input: ImGui's failure path with bezel's message ---------------------------------------

std::string failed_build(ImFontAtlas& atlas) {
    atlas.FontBuilderIO = bezel_imgui::builder();
    EXPECT_FALSE(atlas.Build());
    EXPECT_EQ(atlas.TexPixelsAlpha8, nullptr);
    EXPECT_FALSE(atlas.IsBuilt());
    return bezel_imgui::last_build_error();
}

TEST(BezelImGuiBadInput, BytesThatAreNotAFontFailTheBuildWithBezelsMessage) {
    std::vector<char> junk(4096, 'x');
    ImFontAtlas atlas;
    ImFontConfig cfg;
    cfg.FontDataOwnedByAtlas = false;
    std::snprintf(cfg.Name, sizeof cfg.Name, "junk.ttf");
    atlas.AddFontFromMemoryTTF(junk.data(), static_cast<int>(junk.size()), 16, &cfg);
    const std::string msg = failed_build(atlas);
    EXPECT_NE(msg.find("junk.ttf (ImGui font config 0)"), std::string::npos) << msg;
    EXPECT_NE(msg.find("FreeType error"), std::string::npos) << msg;
}

TEST(BezelImGuiBadInput, FaceIndexOutOfRangeFailsTheBuild) {
    FontBytes bytes(kDejaVu);
    ImFontAtlas atlas;
    ImFontConfig cfg;
    cfg.FontNo = 3;
    add_font(atlas, bytes, 16, cfg);
    const std::string msg = failed_build(atlas);
    EXPECT_NE(msg.find("face index"), std::string::npos) << msg;
}

TEST(BezelImGuiBadInput, InvertedGlyphRangeFailsTheBuildNamingIt) {
    FontBytes bytes(kDejaVu);
    static const ImWchar ranges[] = {0x20, 0x7E, 0x7A, 0x61, 0};
    ImFontAtlas atlas;
    add_font(atlas, bytes, 16, {}, ranges);
    const std::string msg = failed_build(atlas);
    EXPECT_NE(msg.find("glyph range 1 (U+007A..U+0061) is empty"), std::string::npos) << msg;
}

TEST(BezelImGuiBadInput, FontWithoutAnyRequestedGlyphFailsTheBuild) {
    FontBytes bytes(kDejaVu);
    static const ImWchar ranges[] = {0xE000, 0xE0FF, 0};   // Private Use: not in DejaVu Sans
    ImFontAtlas atlas;
    add_font(atlas, bytes, 16, {}, ranges);
    const std::string msg = failed_build(atlas);
    EXPECT_NE(msg.find("none of the code points"), std::string::npos) << msg;
}

TEST(BezelImGuiBadInput, OversampleAndSizeOutOfRangeFailTheBuild) {
    FontBytes bytes(kDejaVu);
    {
        ImFontAtlas atlas;
        ImFontConfig cfg;
        cfg.OversampleH = bezel_imgui::kMaxOversample + 1;
        add_font(atlas, bytes, 16, cfg);
        EXPECT_NE(failed_build(atlas).find("OversampleH 9"), std::string::npos);
    }
    {
        ImFontAtlas atlas;
        add_font(atlas, bytes, 16);
        atlas.ConfigData[0].SizePixels = -1;
        EXPECT_NE(failed_build(atlas).find("SizePixels"), std::string::npos);
    }
}

// 1500 px glyphs in a 64 px wide atlas: the first few fill the tallest texture it may grow to
// (64 × 32768 texels); the build stops with an error before drawing (or allocating) the rest.
TEST(BezelImGuiBadInput, GlyphsLargerThanTheAtlasFailTheBuildBeforeAllocatingThem) {
    FontBytes bytes(kDejaVu);
    static const ImWchar ranges[] = {'A', 'Z', 0};
    ImFontAtlas atlas;
    atlas.TexDesiredWidth = 64;
    ImFontConfig cfg;
    cfg.OversampleH = 1;
    add_font(atlas, bytes, 1500, cfg, ranges);
    const std::string msg = failed_build(atlas);
    EXPECT_NE(msg.find("does not fit the atlas"), std::string::npos) << msg;
}

TEST(BezelImGuiBadInput, AFailedBuildLeavesTheNextGoodBuildWorking) {
    FontBytes bytes(kDejaVu);
    ImFontAtlas atlas;
    add_font(atlas, bytes, 16);
    atlas.ConfigData[0].OversampleV = 0;
    failed_build(atlas);
    atlas.ConfigData[0].OversampleV = 1;
    EXPECT_TRUE(atlas.Build()) << bezel_imgui::last_build_error();
    EXPECT_EQ(bezel_imgui::last_build_error(), "");
    EXPECT_NE(atlas.Fonts[0]->FindGlyphNoFallback('g'), nullptr);
}

// --- ImFontConfig's options ---------------------------------------------------------------------

const ImFontGlyph& glyph_of(BuiltFont& b, ImWchar c) {
    const ImFontGlyph* g = b.font->FindGlyphNoFallback(c);
    EXPECT_NE(g, nullptr);
    static const ImFontGlyph none{};
    return g ? *g : none;
}

TEST(BezelImGuiOptions, GlyphOffsetMovesEveryBoxByIt) {
    FontBytes bytes(kDejaVu);
    ImFontConfig plain, moved;
    moved.GlyphOffset = ImVec2(1.5f, -2.0f);
    BuiltFont a, b;
    build(a, bytes, 16, bezel_imgui::builder(), plain);
    build(b, bytes, 16, bezel_imgui::builder(), moved);
    for (ImWchar c : {'A', 'g', '}'}) {
        EXPECT_FLOAT_EQ(glyph_of(b, c).X0, glyph_of(a, c).X0 + 1.5f);
        EXPECT_FLOAT_EQ(glyph_of(b, c).Y1, glyph_of(a, c).Y1 - 2.0f);
        EXPECT_FLOAT_EQ(glyph_of(b, c).AdvanceX, glyph_of(a, c).AdvanceX);
    }
}

TEST(BezelImGuiOptions, PixelSnapSpacingAndAdvanceLimitsReachTheGlyphs) {
    FontBytes bytes(kDejaVu);
    ImFontConfig cfg;
    cfg.FontBuilderFlags = bezel_imgui::NoHinting;
    cfg.PixelSnapH = true;
    cfg.GlyphExtraSpacing = ImVec2(1, 0);
    cfg.GlyphMinAdvanceX = 9;
    cfg.GlyphMaxAdvanceX = 11;
    BuiltFont b;
    build(b, bytes, 16, bezel_imgui::builder(), cfg);
    for (const ImFontGlyph& g : b.font->Glyphs) {
        if (g.Codepoint == '\t') continue;   // ImGui's own: IM_TABSIZE spaces
        EXPECT_EQ(g.AdvanceX, std::round(g.AdvanceX)) << "U+" << std::hex << g.Codepoint;
        EXPECT_GE(g.AdvanceX, 9 + 1) << "U+" << std::hex << g.Codepoint;
        EXPECT_LE(g.AdvanceX, 11 + 1) << "U+" << std::hex << g.Codepoint;
        // PixelSnapH draws without horizontal oversampling: boxes on whole pixels.
        if (g.Visible) {
            EXPECT_EQ(g.X0, std::floor(g.X0)) << "U+" << std::hex << g.Codepoint;
        }
    }
}

int ink_sum(const BuiltFont& b, const ImFontGlyph& g) {
    int sum = 0;
    for (int y = static_cast<int>(std::lround(g.V0 * b.atlas.TexHeight)); y < std::lround(g.V1 * b.atlas.TexHeight); ++y)
        for (int x = static_cast<int>(std::lround(g.U0 * b.atlas.TexWidth)); x < std::lround(g.U1 * b.atlas.TexWidth); ++x)
            sum += texel(b.atlas, x, y);
    return sum;
}

TEST(BezelImGuiOptions, RasterizerMultiplyBoldAndMonochromeChangeTheInk) {
    FontBytes bytes(kDejaVu);
    static const ImWchar just_o[] = {'o', 'o', 0};
    ImFontConfig plain, dark, bold, mono;
    plain.GlyphRanges = dark.GlyphRanges = bold.GlyphRanges = mono.GlyphRanges = just_o;
    plain.FontBuilderFlags = dark.FontBuilderFlags = bezel_imgui::NoHinting;
    dark.RasterizerMultiply = 1.5f;
    bold.FontBuilderFlags = bezel_imgui::NoHinting | bezel_imgui::Bold;
    mono.FontBuilderFlags = bezel_imgui::NoHinting | bezel_imgui::Monochrome;
    BuiltFont p, d, b, m;
    build(p, bytes, 16, bezel_imgui::builder(), plain);
    build(d, bytes, 16, bezel_imgui::builder(), dark);
    build(b, bytes, 16, bezel_imgui::builder(), bold);
    build(m, bytes, 16, bezel_imgui::builder(), mono);
    const ImFontGlyph& o = glyph_of(p, 'o');
    EXPECT_GT(ink_sum(d, glyph_of(d, 'o')), ink_sum(p, o) * 1.2);
    EXPECT_GT(ink_sum(b, glyph_of(b, 'o')), ink_sum(p, o) * 1.2);
    // Bold widens the advance by size/24 em, FreeType's FT_GlyphSlot_Embolden strength.
    auto font = bezel::Font::open(kDejaVu);
    const bezel::FontMetrics fm = font->metrics();
    const double em_px = 16.0 * fm.units_per_em / (fm.ascender - fm.descender);
    EXPECT_NEAR(glyph_of(b, 'o').AdvanceX - o.AdvanceX, em_px * bezel_imgui::kBoldStrength, 1e-3);
    const ImFontGlyph& mo = glyph_of(m, 'o');
    for (int y = static_cast<int>(std::lround(mo.V0 * m.atlas.TexHeight)); y < std::lround(mo.V1 * m.atlas.TexHeight); ++y)
        for (int x = static_cast<int>(std::lround(mo.U0 * m.atlas.TexWidth)); x < std::lround(mo.U1 * m.atlas.TexWidth); ++x)
            EXPECT_TRUE(texel(m.atlas, x, y) == 0 || texel(m.atlas, x, y) == 255);
}

TEST(BezelImGuiOptions, HintingFlagsMapAsImGuiFreeTypesDo) {
    EXPECT_EQ(bezel_imgui::hinting_for_flags(0), bezel::Hinting::Full);
    EXPECT_EQ(bezel_imgui::hinting_for_flags(bezel_imgui::NoHinting), bezel::Hinting::None);
    EXPECT_EQ(bezel_imgui::hinting_for_flags(bezel_imgui::LightHinting), bezel::Hinting::Light);
    EXPECT_EQ(bezel_imgui::hinting_for_flags(bezel_imgui::ForceAutoHint), bezel::Hinting::Auto);
    EXPECT_EQ(bezel_imgui::hinting_for_flags(bezel_imgui::NoHinting | bezel_imgui::LightHinting),
              bezel::Hinting::None);
    // Full hinting puts horizontal stems on whole pixels: the advance of 'm' is an integer.
    FontBytes bytes(kDejaVu);
    BuiltFont full, none;
    ImFontConfig unhinted;
    unhinted.FontBuilderFlags = bezel_imgui::NoHinting;
    build(full, bytes, 13, bezel_imgui::builder());
    build(none, bytes, 13, bezel_imgui::builder(), unhinted);
    EXPECT_EQ(glyph_of(full, 'm').AdvanceX, std::round(glyph_of(full, 'm').AdvanceX));
    EXPECT_NE(glyph_of(none, 'm').AdvanceX, std::round(glyph_of(none, 'm').AdvanceX));
}

// The Bitmap flag draws a font's embedded strike at its size, once even when oversampled.
// fonts-test/bitmap-strike: ascender − descender is one em, so SizePixels 16 is 16 ppem, where
// 'A' has a 1-bit 8×10 checkerboard strike (inked where x + y is odd), advance 11 px; its
// outline is a filled rectangle, which is what the same glyph is without the flag.
TEST(BezelImGuiOptions, BitmapFlagDrawsTheFontsStrikeAtItsSize) {
    FontBytes bytes(std::string(BEZEL_FONTS_DIR) + "/bitmap-strike/BitmapStrike.ttf");
    static const ImWchar just_a[] = {'A', 'A', 0};
    ImFontConfig strike, outline;
    strike.GlyphRanges = outline.GlyphRanges = just_a;
    strike.OversampleH = outline.OversampleH = 3;
    strike.FontBuilderFlags = bezel_imgui::NoHinting | bezel_imgui::Bitmap;
    outline.FontBuilderFlags = bezel_imgui::NoHinting;
    BuiltFont s, o;
    build(s, bytes, 16, bezel_imgui::builder(), strike);
    build(o, bytes, 16, bezel_imgui::builder(), outline);
    const ImFontGlyph& a = glyph_of(s, 'A');
    EXPECT_FLOAT_EQ(a.X1 - a.X0, 8.0f);
    EXPECT_FLOAT_EQ(a.Y1 - a.Y0, 10.0f);
    EXPECT_FLOAT_EQ(a.AdvanceX, 11.0f);
    const int u0 = static_cast<int>(std::lround(a.U0 * s.atlas.TexWidth));
    const int v0 = static_cast<int>(std::lround(a.V0 * s.atlas.TexHeight));
    for (int y = 0; y < 10; ++y)
        for (int x = 0; x < 8; ++x)
            EXPECT_EQ(texel(s.atlas, u0 + x, v0 + y), (x + y) % 2 ? 255 : 0) << x << "," << y;
    // Without the flag: the outline, whose middle texels are all fully covered.
    const ImFontGlyph& r = glyph_of(o, 'A');
    const int cx = static_cast<int>(std::lround((r.U0 + r.U1) / 2 * o.atlas.TexWidth));
    const int cy = static_cast<int>(std::lround((r.V0 + r.V1) / 2 * o.atlas.TexHeight));
    EXPECT_EQ(texel(o.atlas, cx, cy), 255);
    EXPECT_EQ(texel(o.atlas, cx + 1, cy), 255);
}

TEST(BezelImGuiOptions, EllipsisCharOutsideTheRangesIsAddedAndUsed) {
    FontBytes bytes(kDejaVu);
    static const ImWchar ascii[] = {0x20, 0x7E, 0};
    ImFontConfig cfg;
    cfg.EllipsisChar = 0x2026;
    BuiltFont c;
    cfg.GlyphRanges = ascii;
    build(c, bytes, 16, bezel_imgui::builder(), cfg);
    EXPECT_NE(c.font->FindGlyphNoFallback(0x2026), nullptr);
    EXPECT_EQ(c.font->EllipsisChar, 0x2026);
}

// --- SVG icon -----------------------------------------------------------------------------------

TEST(BezelImGuiIcon, SvgPathIsDrawnIntoItsGlyphWithExactCoverage) {
    FontBytes bytes(kDejaVu);
    ImFontAtlas atlas;
    ImFont* font = add_font(atlas, bytes, 16);
    bezel_imgui::SvgIconOptions o;
    o.size_px = 20;
    o.view_box = 10;
    // The left half of the box, and a triangle over the right half: 1/2 + 1/4 of the area.
    auto icon = bezel_imgui::add_svg_icon(atlas, font, 0xE000, "M0 0H5V10H0Z M5 10L10 10L10 0Z", o);
    ASSERT_TRUE(icon.ok()) << icon.error().message;
    atlas.FontBuilderIO = bezel_imgui::builder();
    ASSERT_TRUE(atlas.Build()) << bezel_imgui::last_build_error();
    ASSERT_TRUE(bezel_imgui::draw_svg_icon(atlas, *icon).ok());
    const ImFontGlyph* g = font->FindGlyphNoFallback(0xE000);
    ASSERT_NE(g, nullptr);
    EXPECT_EQ(g->X1 - g->X0, 20);
    EXPECT_EQ(g->AdvanceX, 21);
    const ImFontAtlasCustomRect& r = atlas.CustomRects[icon->rect_id];
    long sum = 0;
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 20; ++x) {
            const int t = texel(atlas, r.X + x, r.Y + y);
            sum += t;
            if (x < 10) {
                EXPECT_EQ(t, 255);
            }
        }
    EXPECT_NEAR(sum / 255.0, 0.75 * 400, 1.0);   // area, pixels; 8-bit rounding on the diagonal
}

TEST(BezelImGuiIcon, BadPathDataIsAnErrorNamingTheIcon) {
    ImFontAtlas atlas;
    ImFont* font = atlas.AddFontDefault();
    auto icon = bezel_imgui::add_svg_icon(atlas, font, 0xE001, "M0 0 L 5", {});
    ASSERT_FALSE(icon.ok());
    EXPECT_NE(icon.error().message.find("SVG icon U+E001"), std::string::npos) << icon.error().message;
    EXPECT_FALSE(bezel_imgui::add_svg_icon(atlas, nullptr, 0xE001, "M0 0H1V1Z", {}).ok());
    EXPECT_FALSE(bezel_imgui::draw_svg_icon(atlas, bezel_imgui::SvgIcon{}).ok());   // not built
}

}  // namespace

#ifdef BEZEL_IMGUI_EXAMPLE
namespace {

// --- the SDL example under Xvfb -----------------------------------------------------------------

struct ItemRect {
    std::string name;
    int x0, y0, x1, y1;
};

// The example renders 3 frames in a virtual X server (xvfb-run), saves the last and prints where
// ImGui put each text item. Every item's rectangle holds text (ink: pixels much brighter than
// the dark background), and nothing is drawn anywhere else.
TEST(BezelImGuiExample, ScreenshotUnderXvfbHasTextWhereImGuiPutItAndNowhereElse) {
    bezel::test::TempDir dir("bezel-imgui");
    const auto run = bezel::test::run_program(
        "/usr/bin/xvfb-run",
        {"-a", "-s", "-screen 0 1024x768x24", BEZEL_IMGUI_EXAMPLE, "--frames", "3",
         "--screenshot", "shot.png", "--cjk-font", kCjk},
        // SDL's video drivers keep allocations at exit (libdbus, X11 and GL libraries they
        // dlopen and close, which LeakSanitizer cannot even name): leak checking is off for the
        // example alone; bezel_imgui's code runs leak-checked in this process's own tests.
        dir.path(), {"SDL_RENDER_DRIVER=software", "ASAN_OPTIONS=detect_leaks=0:abort_on_error=1"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    std::vector<ItemRect> items;
    std::istringstream out(run.out);
    for (std::string word; out >> word;) {
        ASSERT_EQ(word, "item") << run.out;
        ItemRect r;
        out >> r.name >> r.x0 >> r.y0 >> r.x1 >> r.y1;
        items.push_back(r);
    }
    ASSERT_EQ(items.size(), 7u) << run.out;
    auto shot = bezel::read_png_gray((dir.path() / "shot.png").string());
    ASSERT_TRUE(shot.ok()) << shot.error().message;
    const bezel::Mask& m = *shot;
    ASSERT_EQ(m.width(), 960);
    ASSERT_EQ(m.height(), 540);
    const int background = m.at(m.width() - 1, m.height() - 1);
    auto ink = [&](int x, int y) { return m.at(x, y) > background + 64; };
    std::vector<bool> in_item(static_cast<std::size_t>(m.width()) * m.height(), false);
    for (const ItemRect& r : items) {
        int count = 0;
        for (int y = std::max(0, r.y0 - 2); y < std::min(m.height(), r.y1 + 2); ++y)
            for (int x = std::max(0, r.x0 - 2); x < std::min(m.width(), r.x1 + 2); ++x) {
                count += ink(x, y);
                in_item[static_cast<std::size_t>(y) * m.width() + x] = true;
            }
        const int area = (r.x1 - r.x0) * (r.y1 - r.y0);
        // Text inks a few percent of its line box; an empty or missing line inks nothing.
        EXPECT_GT(count, area / 25) << r.name << " (" << count << " ink pixels of " << area << ")";
    }
    int stray = 0;
    for (int y = 0; y < m.height(); ++y)
        for (int x = 0; x < m.width(); ++x)
            stray += !in_item[static_cast<std::size_t>(y) * m.width() + x] && ink(x, y);
    EXPECT_EQ(stray, 0);
}

TEST(BezelImGuiExample, BadArgumentsExitWithUsage) {
    bezel::test::TempDir dir("bezel-imgui");
    const auto run = bezel::test::run_program(BEZEL_IMGUI_EXAMPLE, {"--frames", "0", "--screenshot", "x.png"},
                                              dir.path());
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_NE(run.err.find("--frames: '0'"), std::string::npos) << run.err;
}

}  // namespace
#endif
