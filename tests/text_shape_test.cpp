// Tests of UTF-8 decoding, feature parsing and the HarfBuzz Shaper.
//
// Shaping results are compared with hb-shape's, stored in tests/golden/shaping/expected.tsv
// (one case per line; generate.sh regenerates it). The cases shape at size_px = units per em, so
// bezel's pixels are font units and hb-shape's integer positions must match to 1e-6.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "bezel/font.hpp"
#include "bezel/text.hpp"

namespace bezel {
namespace {

const std::string kFonts = BEZEL_FONTS_DIR;
const std::string kDejaVu = kFonts + "/dejavu-sans/DejaVuSans.ttf";
const std::string kHebrew = kFonts + "/noto-hebrew/NotoSansHebrew-Regular.ttf";
const std::string kArabic = kFonts + "/noto-arabic/NotoSansArabic-Regular.ttf";
const std::string kVariable = kFonts + "/edge-cases/EdgeCasesVariable.ttf";
const std::string kCollection = kFonts + "/edge-cases/EdgeCases.ttc";

Shaper open_shaper(const std::string& file, int face = 0) {
    auto shaper = Shaper::open(file, face);
    if (!shaper) {
        ADD_FAILURE() << shaper.error().message;
        std::abort();
    }
    return std::move(shaper).value();
}

ShapedRun shape_ok(Shaper& shaper, std::string_view text, const ShapeOptions& options) {
    auto run = shaper.shape(text, options);
    if (!run) {
        ADD_FAILURE() << run.error().message;
        return {};
    }
    return std::move(run).value();
}

// --- UTF-8 ----------------------------------------------------------------------------------

TEST(Utf8, DecodesEveryLength) {
    auto cps = decode_utf8("a\xC3\xA9\xE2\x82\xAC\xF0\x9F\x98\x80");
    ASSERT_TRUE(cps.ok());
    EXPECT_EQ(*cps, (std::u32string{U'a', U'\u00E9', U'\u20AC', U'\U0001F600'}));
}

TEST(Utf8, ErrorNamesTheByteOffsetOfTheBadSequence) {
    struct Case {
        std::string text;
        std::size_t offset;
    };
    const Case cases[] = {
        {"ab\x80", 2},                  // continuation byte first
        {"abc\xC0\x80", 3},             // overlong 2-byte NUL
        {"\xE0\x80\x80", 0},            // overlong 3-byte
        {"x\xF0\x80\x80\x80", 1},       // overlong 4-byte
        {"\xED\xA0\x80", 0},            // UTF-16 surrogate D800
        {"\xF4\x90\x80\x80", 0},        // U+110000
        {"ok\xE2\x82", 2},              // truncated at the end
        {"\xC3\x28", 0},                // a lead byte followed by ASCII
        {"\xFF", 0},
    };
    for (const Case& c : cases) {
        auto r = decode_utf8(c.text);
        ASSERT_FALSE(r.ok()) << "offset " << c.offset;
        EXPECT_EQ(r.error().message, "text byte " + std::to_string(c.offset) + ": invalid UTF-8");
    }
}

TEST(Utf8, AppendRoundTripsBoundaryCodePoints) {
    const char32_t cps[] = {0x0, 0x7F, 0x80, 0x7FF, 0x800, 0xD7FF, 0xE000, 0xFFFF, 0x10000,
                            0x10FFFF};
    std::string s;
    for (char32_t cp : cps) append_utf8(s, cp);
    EXPECT_EQ(s.size(), 1u + 1 + 2 + 2 + 3 + 3 + 3 + 3 + 4 + 4);
    auto back = decode_utf8(s);
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(*back, std::u32string(std::begin(cps), std::end(cps)));
}

// --- Features -------------------------------------------------------------------------------

TEST(Features, ParsesHbViewSyntax) {
    auto f = parse_features("kern,-liga +smcp, aalt=2,liga[3:5]=0,dlig[2:]");
    ASSERT_TRUE(f.ok()) << f.error().message;
    ASSERT_EQ(f->size(), 6u);
    EXPECT_EQ((*f)[0].tag, "kern");
    EXPECT_EQ((*f)[0].value, 1u);
    EXPECT_EQ((*f)[0].start, 0u);
    EXPECT_EQ((*f)[0].end, SIZE_MAX);
    EXPECT_EQ((*f)[1].tag, "liga");
    EXPECT_EQ((*f)[1].value, 0u);
    EXPECT_EQ((*f)[2].tag, "smcp");
    EXPECT_EQ((*f)[2].value, 1u);
    EXPECT_EQ((*f)[3].tag, "aalt");
    EXPECT_EQ((*f)[3].value, 2u);
    EXPECT_EQ((*f)[4].tag, "liga");
    EXPECT_EQ((*f)[4].value, 0u);
    EXPECT_EQ((*f)[4].start, 3u);
    EXPECT_EQ((*f)[4].end, 5u);
    EXPECT_EQ((*f)[5].tag, "dlig");
    EXPECT_EQ((*f)[5].start, 2u);
    EXPECT_EQ((*f)[5].end, SIZE_MAX);
    auto empty = parse_features(" , ");
    ASSERT_TRUE(empty.ok());
    EXPECT_TRUE(empty->empty());
}

TEST(Features, UnknownSyntaxIsAnErrorNamingTheItem) {
    for (const char* bad : {"kernx", "=2", "liga[", "liga[3:5", "liga=x", "+", "ke*n"}) {
        auto f = parse_features(std::string("kern,") + bad);
        ASSERT_FALSE(f.ok()) << bad;
        EXPECT_NE(f.error().message.find(std::string("feature '") + bad + "'"), std::string::npos)
            << f.error().message;
    }
}

// --- Shaping against hb-shape ---------------------------------------------------------------

struct Expected1 {
    GlyphId gid;
    std::uint32_t cluster;
    double x_offset, y_offset, x_advance, y_advance;
};

// Parses hb-shape's "[gid=cluster@dx,dy+ax,ay|...]" (the @ and ,ay parts only when non-zero).
std::vector<Expected1> parse_hb_shape(const std::string& s) {
    std::vector<Expected1> out;
    std::string body = s.substr(1, s.size() - 2);
    std::stringstream items(body);
    std::string item;
    while (std::getline(items, item, '|')) {
        Expected1 e{};
        const char* p = item.c_str();
        char* end = nullptr;
        e.gid = static_cast<GlyphId>(std::strtoul(p, &end, 10));
        p = end + 1;   // '='
        e.cluster = static_cast<std::uint32_t>(std::strtoul(p, &end, 10));
        p = end;
        if (*p == '@') {
            e.x_offset = std::strtod(p + 1, &end);
            e.y_offset = std::strtod(end + 1, &end);
            p = end;
        }
        if (*p == '+') {
            e.x_advance = std::strtod(p + 1, &end);
            p = end;
            if (*p == ',') e.y_advance = std::strtod(p + 1, &end);
        }
        out.push_back(e);
    }
    return out;
}

Expected<ShapeOptions> options_from_hb(const std::string& options, double size_px) {
    ShapeOptions o;
    o.size_px = size_px;
    std::stringstream words(options == "-" ? "" : options);
    std::string w;
    while (words >> w) {
        auto value = w.substr(w.find('=') + 1);
        if (w.rfind("--features=", 0) == 0) {
            auto f = parse_features(value);
            if (!f) return f.error();
            o.features = *f;
        } else if (w.rfind("--direction=", 0) == 0) {
            o.direction = value == "rtl" ? Direction::RightToLeft : Direction::LeftToRight;
        } else if (w.rfind("--language=", 0) == 0) {
            o.language = value;
        } else if (w.rfind("--script=", 0) == 0) {
            o.script = value;
        } else if (w.rfind("--variations=", 0) == 0) {
            o.variations.push_back({value.substr(0, 4), std::stod(value.substr(5))});
        } else {
            return Error{"unknown option " + w};
        }
    }
    return o;
}

TEST(Shaper, MatchesHbShapeOnGoldenCases) {
    std::ifstream in(std::string(BEZEL_GOLDEN_DIR) + "/shaping/expected.tsv");
    ASSERT_TRUE(in) << "tests/golden/shaping/expected.tsv missing";
    std::string line;
    int cases = 0;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::vector<std::string> fields;
        std::stringstream ss(line);
        std::string field;
        while (std::getline(ss, field, '\t')) fields.push_back(field);
        ASSERT_EQ(fields.size(), 4u) << line;
        SCOPED_TRACE(fields[0] + " " + fields[1] + " '" + fields[2] + "'");
        const std::string file = kFonts + "/" + fields[0];
        auto font = Font::open(file);
        ASSERT_TRUE(font.ok()) << font.error().message;
        Shaper shaper = open_shaper(file);
        auto options = options_from_hb(fields[1], font->metrics().units_per_em);
        ASSERT_TRUE(options.ok()) << options.error().message;
        ShapedRun run = shape_ok(shaper, fields[2], *options);
        const auto expected = parse_hb_shape(fields[3]);
        ASSERT_EQ(run.glyphs.size(), expected.size()) << fields[3];
        double advance = 0;
        for (std::size_t i = 0; i < expected.size(); ++i) {
            const ShapedGlyph& g = run.glyphs[i];
            const Expected1& e = expected[i];
            EXPECT_EQ(g.gid, e.gid) << "glyph " << i;
            EXPECT_EQ(g.cluster, e.cluster) << "glyph " << i;
            EXPECT_NEAR(g.x_advance_px, e.x_advance, 1e-6) << "glyph " << i;
            EXPECT_NEAR(g.y_advance_px, -e.y_advance, 1e-6) << "glyph " << i;
            EXPECT_NEAR(g.x_offset_px, e.x_offset, 1e-6) << "glyph " << i;
            EXPECT_NEAR(g.y_offset_px, -e.y_offset, 1e-6) << "glyph " << i;
            advance += e.x_advance;
        }
        EXPECT_NEAR(run.advance_px, advance, 1e-6);
        ++cases;
    }
    EXPECT_GE(cases, 20);
}

// --- Features, variations, direction --------------------------------------------------------

TEST(Shaper, LigaOffSplitsTheFiLigatureAndKernOffWidensAV) {
    Shaper shaper = open_shaper(kDejaVu);
    ShapeOptions o;
    o.size_px = 2048;   // DejaVu's units per em
    EXPECT_EQ(shape_ok(shaper, "fi", o).glyphs.size(), 1u);
    o.features = *parse_features("-liga");
    EXPECT_EQ(shape_ok(shaper, "fi", o).glyphs.size(), 2u);
    o.features.clear();
    const double kerned = shape_ok(shaper, "AV", o).advance_px;
    o.features = *parse_features("-kern");
    const double plain = shape_ok(shaper, "AV", o).advance_px;
    EXPECT_NEAR(plain - kerned, 1401 - 1270, 1e-6);   // DejaVu's A–V kerning, font units
}

TEST(Shaper, AdvancesScaleLinearlyWithSizeAtSubpixelPrecision) {
    Shaper shaper = open_shaper(kDejaVu);
    ShapeOptions o;
    o.features = *parse_features("-kern");
    o.size_px = 13.3;
    const ShapedRun run = shape_ok(shaper, "AW", o);
    ASSERT_EQ(run.glyphs.size(), 2u);
    // 1/1024 px units: within 1e-3 px of the exact scaled advance.
    EXPECT_NEAR(run.glyphs[0].x_advance_px, 1401 * 13.3 / 2048, 1e-3);
    EXPECT_NEAR(run.glyphs[1].x_advance_px, 2025 * 13.3 / 2048, 1e-3);
}

TEST(Shaper, VariationsChangeAdvancesAndAreValidated) {
    Shaper shaper = open_shaper(kVariable);
    ShapeOptions o;
    o.size_px = 1000;
    EXPECT_NEAR(shape_ok(shaper, "I", o).advance_px, 400, 1e-6);
    o.variations = {{"wght", 900}};
    EXPECT_NEAR(shape_ok(shaper, "I", o).advance_px, 600, 1e-6);
    o.variations = {{"wght", 250}};   // −100 at 100, linear: 400 − 100·(150/300)
    EXPECT_NEAR(shape_ok(shaper, "I", o).advance_px, 350, 1e-6);
    o.variations.clear();   // back to the default instance
    EXPECT_NEAR(shape_ok(shaper, "I", o).advance_px, 400, 1e-6);

    o.variations = {{"wdth", 100}};
    auto unknown = shaper.shape("I", o);
    ASSERT_FALSE(unknown.ok());
    EXPECT_EQ(unknown.error().message, kVariable + ": unknown variation axis 'wdth'");
    o.variations = {{"wght", 1000}};
    auto range = shaper.shape("I", o);
    ASSERT_FALSE(range.ok());
    EXPECT_EQ(range.error().message, kVariable + ": variation wght=1000 out of range [100, 900]");
    o.variations = {{"wght", std::nan("")}};
    EXPECT_FALSE(shaper.shape("I", o).ok());

    Shaper plain = open_shaper(kDejaVu);
    o.variations = {{"wght", 700}};
    auto none = plain.shape("I", o);
    ASSERT_FALSE(none.ok());
    EXPECT_NE(none.error().message.find("the font has no variation axes"), std::string::npos);
}

TEST(Shaper, DirectionAndScriptComeFromTheTextWhenNotGiven) {
    Shaper shaper = open_shaper(kHebrew);
    ShapeOptions o;
    const ShapedRun run = shape_ok(shaper, "שלום", o);
    EXPECT_EQ(run.direction, Direction::RightToLeft);
    EXPECT_EQ(run.script, "Hebr");
    ASSERT_EQ(run.glyphs.size(), 4u);
    EXPECT_EQ(run.glyphs.front().cluster, 6u);   // visual order: the last letter first
    EXPECT_EQ(run.glyphs.back().cluster, 0u);

    o.direction = Direction::LeftToRight;
    const ShapedRun ltr = shape_ok(shaper, "שלום", o);
    EXPECT_EQ(ltr.direction, Direction::LeftToRight);
    EXPECT_EQ(ltr.glyphs.front().cluster, 0u);

    Shaper latin = open_shaper(kDejaVu);
    const ShapedRun l = shape_ok(latin, "abc", ShapeOptions{});
    EXPECT_EQ(l.direction, Direction::LeftToRight);
    EXPECT_EQ(l.script, "Latn");
}

TEST(Shaper, ArabicJoiningFormsDifferFromIsolatedLetters) {
    Shaper shaper = open_shaper(kArabic);
    ShapeOptions o;
    // ب alone and ب at the start of بب are different glyphs (isolated vs initial form).
    const ShapedRun alone = shape_ok(shaper, "ب", o);
    const ShapedRun joined = shape_ok(shaper, "بب", o);
    ASSERT_EQ(alone.glyphs.size(), 1u);
    ASSERT_EQ(joined.glyphs.size(), 2u);
    EXPECT_NE(alone.glyphs[0].gid, joined.glyphs[1].gid);   // visual order: cluster 0 is last
    EXPECT_NE(joined.glyphs[0].gid, joined.glyphs[1].gid);  // final vs initial
}

TEST(Shaper, RepeatedShapingGivesIdenticalRuns) {
    Shaper shaper = open_shaper(kDejaVu);
    ShapeOptions o;
    o.size_px = 16;
    const ShapedRun a = shape_ok(shaper, "office AVAW", o);
    shape_ok(shaper, "something else entirely", o);
    const ShapedRun b = shape_ok(shaper, "office AVAW", o);
    ASSERT_EQ(a.glyphs.size(), b.glyphs.size());
    for (std::size_t i = 0; i < a.glyphs.size(); ++i) {
        EXPECT_EQ(a.glyphs[i].gid, b.glyphs[i].gid);
        EXPECT_EQ(a.glyphs[i].x_advance_px, b.glyphs[i].x_advance_px);
    }
}

TEST(Shaper, EmptyTextShapesToNoGlyphs) {
    Shaper shaper = open_shaper(kDejaVu);
    const ShapedRun run = shape_ok(shaper, "", ShapeOptions{});
    EXPECT_TRUE(run.glyphs.empty());
    EXPECT_EQ(run.advance_px, 0);
}

TEST(Shaper, CollectionFacesOpenByIndex) {
    Shaper face1 = open_shaper(kCollection, 1);   // EdgeCasesVariable
    ShapeOptions o;
    o.size_px = 1000;
    o.variations = {{"wght", 900}};
    EXPECT_NEAR(shape_ok(face1, "I", o).advance_px, 600, 1e-6);
    auto bad = Shaper::open(kCollection, 2);
    ASSERT_FALSE(bad.ok());
    // The message Font::open gives: both read the file through one FontFace.
    EXPECT_EQ(bad.error().message,
              kCollection + ": face index 2 out of range (the file has 2 faces)");
}

// --- Bad input ------------------------------------------------------------------------------

TEST(Shaper, OpenErrorsNameTheFile) {
    auto missing = Shaper::open(kFonts + "/nope.ttf");
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().message, kFonts + "/nope.ttf: no such file");
    auto dir = Shaper::open(kFonts);
    ASSERT_FALSE(dir.ok());
    EXPECT_EQ(dir.error().message, kFonts + ": is a directory, not a font file");
    const std::string readme = kFonts + "/dejavu-sans/README.md";
    auto not_font = Shaper::open(readme);
    ASSERT_FALSE(not_font.ok());
    EXPECT_EQ(not_font.error().message, readme + ": FreeType error 0x02 (unknown file format)");
    auto negative = Shaper::open(kDejaVu, -1);
    ASSERT_FALSE(negative.ok());
    EXPECT_NE(negative.error().message.find("face index -1 out of range"), std::string::npos);
}

TEST(Shaper, BadOptionsAndTextAreErrorsNamingThem) {
    Shaper shaper = open_shaper(kDejaVu);
    auto error_of = [&](std::string_view text, const ShapeOptions& o) {
        auto r = shaper.shape(text, o);
        return r.ok() ? std::string("(no error)") : r.error().message;
    };
    ShapeOptions o;
    EXPECT_EQ(error_of("ab\xC3", o), "text byte 2: invalid UTF-8");
    o.size_px = 0;
    EXPECT_EQ(error_of("a", o), "font size 0 px: out of range (0, 16384]");
    o.size_px = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(error_of("a", o), "font size nan px: out of range (0, 16384]");
    o.size_px = 1e9;
    EXPECT_EQ(error_of("a", o), "font size 1e+09 px: out of range (0, 16384]");
    o = ShapeOptions{};
    o.script = "Arabic";
    EXPECT_EQ(error_of("a", o), "script 'Arabic': not an ISO 15924 tag (four letters, e.g. Arab)");
    o = ShapeOptions{};
    o.language = "en_US";
    EXPECT_EQ(error_of("a", o), "language 'en_US': not a BCP 47 tag (e.g. ar, hi, sr-Latn)");
    o = ShapeOptions{};
    o.features = {FeatureSetting{"kernel", 1, 0, SIZE_MAX}};
    EXPECT_EQ(error_of("a", o), "feature 'kernel': the tag must have 1 to 4 characters");
    o = ShapeOptions{};
    o.language = "sr-Latn";
    o.script = "latn";
    EXPECT_EQ(error_of("a", o), "(no error)");
}

TEST(Shaper, TextLongerThanTheLimitIsRejectedBeforeShaping) {
    Shaper shaper = open_shaper(kDejaVu);
    const std::string huge(kMaxTextBytes + 1, 'a');
    auto r = shaper.shape(huge, ShapeOptions{});
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().message, "text of 16777217 bytes: longer than the 16777216 allowed");
}

}  // namespace
}  // namespace bezel
