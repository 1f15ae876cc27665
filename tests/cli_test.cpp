// End-to-end tests of the `bezel` binary (BEZEL_CLI_PATH): exit codes, error lines, help, and
// the outline subcommand's text, JSON and SVG output checked against the font data.
//
// Reference values come from the fonts themselves (fontTools): DejaVu Sans has 2048 units/em,
// so at --font-size 2048 an unhinted outline's pixel coordinates are exactly its font units with
// y negated. Cantarell Regular is CFF with 1000 units/em.

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "support/cli_run.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const std::string kDejaVu = std::string(BEZEL_FONTS_DIR) + "/dejavu-sans/DejaVuSans.ttf";
const std::string kCantarell = std::string(BEZEL_FONTS_DIR) + "/cantarell/Cantarell-Regular.otf";
// Generated fonts, 1000 units/em, described in fonts-test/edge-cases/README.md.
const std::string kEdge = std::string(BEZEL_FONTS_DIR) + "/edge-cases/EdgeCases.ttf";
const std::string kEdgeVariable = std::string(BEZEL_FONTS_DIR) + "/edge-cases/EdgeCasesVariable.ttf";
const std::string kEdgeCollection = std::string(BEZEL_FONTS_DIR) + "/edge-cases/EdgeCases.ttc";

using bezel::test::CliRun;
using bezel::test::slurp;

std::size_t count_lines(const std::string& s) {
    std::size_t n = 0;
    for (char c : s) n += c == '\n';
    return n;
}

std::size_t count(const std::string& haystack, const std::string& needle) {
    std::size_t n = 0;
    for (auto at = haystack.find(needle); at != std::string::npos;
         at = haystack.find(needle, at + needle.size()))
        ++n;
    return n;
}

class Cli : public ::testing::Test {
protected:
    bezel::test::TempDir tmp_{"bezel-cli-test"};
    const fs::path& dir_ = tmp_.path();

    // Runs the CLI with `args` (no shell), stdout and stderr captured through files in dir_.
    CliRun run(const std::vector<std::string>& args) {
        return bezel::test::run_bezel(args, dir_);
    }

    // The outline JSON of `args`, checked to succeed.
    json outline_json(std::vector<std::string> args) {
        args.insert(args.begin(), "outline");
        args.push_back("-O");
        args.push_back("json");
        CliRun r = run(args);
        EXPECT_EQ(r.exit_code, 0) << r.err;
        return json::parse(r.out, nullptr, /*allow_exceptions=*/false);
    }

    // Files in the temp dir other than the captured stdout/stderr.
    std::vector<std::string> files() const { return tmp_.entries(); }
};

// Usage errors: exit 2, CLI11's message on the first line, a --help hint on the second.
void expect_usage_error(const CliRun& r, const std::string& mentions) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_EQ(r.err.rfind("bezel: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(mentions), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--help"), std::string::npos) << r.err;
}

// Runtime errors: exit 1 and exactly one line `bezel: <input>: <what>` naming the input.
void expect_runtime_error(const CliRun& r, const std::string& names_input) {
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_EQ(r.err.rfind("bezel: ", 0), 0u) << r.err;
    EXPECT_EQ(count_lines(r.err), 1u) << r.err;
    EXPECT_NE(r.err.find(names_input), std::string::npos) << r.err;
}

TEST_F(Cli, OutlineOfBundledFontSucceedsWithoutFontArgument) {
    CliRun r = run({"outline", "--char", "g", "--font-size", "64"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(r.err.empty()) << r.err;
    EXPECT_NE(r.out.find("DejaVu Sans"), std::string::npos);
    EXPECT_NE(r.out.find("glyph 'g' U+0067  gid 74  name g"), std::string::npos) << r.out;
}

TEST_F(Cli, UsageErrorsExitTwo) {
    expect_usage_error(run({"outline", "--char", "g", "--bogus"}), "--bogus");
    expect_usage_error(run({"outline", kDejaVu}), "no glyph given");
    expect_usage_error(run({"outline", "--char", "g", "--gid", "3"}), "more than one way");
    expect_usage_error(run({"outline", "--char", "g", "--text", "ab"}), "more than one way");
    expect_usage_error(run({"outline", "--char", "g", "-O", "png"}), "png");
    expect_usage_error(run({"outline", "--char", "ab"}), "--char: 'ab': expected one character");
    // A value out of range is the command line's fault too, whatever the subcommand.
    expect_usage_error(run({"outline", kDejaVu, "--char", "g", "--font-size", "0"}), "--font-size: '0': must be > 0");
    expect_usage_error(run({"outline", kDejaVu, "--char", "g", "--font-size", "-5"}), "--font-size: '-5'");
    expect_usage_error(run({"outline", kDejaVu, "--char", "g", "--font-size", "1e9"}), "--font-size: '1e9'");
    expect_usage_error(run({"outline", kDejaVu, "--char", "g", "--font-size", "nan"}), "--font-size: 'nan'");
    expect_usage_error(run({"outline", kDejaVu, "--text", ""}), "--text: empty string");
    expect_usage_error(run({"outline", "--char", "U+D800"}), "U+D800");
    expect_usage_error(run({"outline", "--char", "g", "--font-size", "big"}), "--font-size: 'big': not a number");
    expect_usage_error(run({"outline", "--char", "g", "--variations", "wght"}),
                       "--variations: 'wght': expected TAG=VALUE");
    expect_usage_error(run({"outline", "--gid", "-1"}), "-1");
    expect_usage_error(run({}), "subcommand");
    expect_usage_error(run({"frobnicate"}), "frobnicate");
}

TEST_F(Cli, UnknownOutputExtensionWithoutFormatIsUsageErrorNamingFile) {
    CliRun r = run({"outline", "--char", "g", "-o", "g.png"});
    expect_usage_error(r, "g.png");
    EXPECT_TRUE(files().empty());
}

TEST_F(Cli, RuntimeErrorsExitOneWithOneLineNamingInput) {
    expect_runtime_error(run({"outline", "no/such/font.ttf", "--char", "g"}), "no/such/font.ttf");
    expect_runtime_error(run({"outline", dir_.string(), "--char", "g"}), dir_.string());
    fs::path not_a_font = dir_ / "notes.ttf";
    std::ofstream(not_a_font) << "this is not a font\n";
    expect_runtime_error(run({"outline", not_a_font.string(), "--char", "g"}), "notes.ttf");
    expect_runtime_error(run({"outline", kDejaVu, "--gid", "6253"}), "--gid 6253");
    expect_runtime_error(run({"outline", kDejaVu, "--gid", "4000000000"}), "--gid");
    expect_runtime_error(run({"outline", kDejaVu, "--char", "g", "--face-index", "3"}), "DejaVuSans.ttf");
    // A private-use code point DejaVu Sans does not map: an error with --strict (a warning and
    // .notdef without, MissingGlyphCli in bad_inputs_cli_test.cpp).
    expect_runtime_error(run({"outline", kDejaVu, "--char", "U+10FFFD", "--strict"}), "U+10FFFD");
    expect_runtime_error(run({"outline", kDejaVu, "--char", "g", "--variations", "wght=700"}), "wght");
}

TEST_F(Cli, LastGlyphIdIsAccepted) {
    CliRun r = run({"outline", kDejaVu, "--gid", "6252", "-O", "json"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST_F(Cli, HelpListsEveryOption) {
    CliRun top = run({"--help"});
    EXPECT_EQ(top.exit_code, 0);
    for (const char* s : {"outline", "--version", "--help", "Exit status"})
        EXPECT_NE(top.out.find(s), std::string::npos) << s << "\n" << top.out;

    CliRun sub = run({"outline", "--help"});
    EXPECT_EQ(sub.exit_code, 0);
    for (const char* s : {"FONT", "--face-index", "--font-size", "--variations", "--hinting",
                          "--char", "--gid", "--text", "-O", "--output-format", "-o",
                          "--output-file", "--help"})
        EXPECT_NE(sub.out.find(s), std::string::npos) << s << "\n" << sub.out;
}

TEST_F(Cli, VersionPrintsNameAndVersion) {
    CliRun r = run({"--version"});
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_EQ(r.out.rfind("bezel ", 0), 0u) << r.out;
    EXPECT_EQ(count_lines(r.out), 1u);
}

// DejaVu 'o': contours end at points 11 and 23; at 2048 px pixels are font units, y negated.
TEST_F(Cli, JsonOfDejaVuOMatchesFontData) {
    json j = outline_json({kDejaVu, "--char", "o", "--font-size", "2048"});
    ASSERT_FALSE(j.is_discarded());
    EXPECT_EQ(j["size"].get<double>(), 2048.0);
    EXPECT_EQ(j["font"]["units_per_em"].get<int>(), 2048);
    EXPECT_EQ(j["font"]["outlines"], "quadratic");
    ASSERT_EQ(j["glyphs"].size(), 1u);
    const json& g = j["glyphs"][0];
    EXPECT_EQ(g["gid"].get<int>(), 82);
    EXPECT_EQ(g["name"], "o");
    EXPECT_EQ(g["char"], "o");
    EXPECT_EQ(g["code_point"], "U+006F");
    EXPECT_EQ(g["advance"].get<double>(), 1253.0);
    ASSERT_EQ(g["contours"].size(), 2u);
    EXPECT_EQ(g["contours"][0]["points"].size(), 12u);
    EXPECT_EQ(g["contours"][1]["points"].size(), 12u);
    EXPECT_EQ(g["contours"][1]["first_point"].get<int>(), 12);
    const json& p0 = g["contours"][0]["points"][0];
    EXPECT_EQ(p0["x"].get<double>(), 627.0);
    EXPECT_EQ(p0["y"].get<double>(), -991.0);
    EXPECT_EQ(p0["kind"], "on");
    const json& p1 = g["contours"][0]["points"][1];
    EXPECT_EQ(p1["x"].get<double>(), 479.0);
    EXPECT_EQ(p1["y"].get<double>(), -991.0);
    EXPECT_EQ(p1["kind"], "off-conic");
    // DejaVu lists the counter first. TrueType: outer contours run clockwise as seen, counters
    // counter-clockwise; with y down a clockwise contour has a positive shoelace area.
    EXPECT_EQ(g["contours"][0]["direction"], "counter-clockwise");
    EXPECT_EQ(g["contours"][1]["direction"], "clockwise");
    EXPECT_LT(g["contours"][0]["signed_area"].get<double>(), 0.0);
    EXPECT_GT(g["contours"][1]["signed_area"].get<double>(), 0.0);
    // The counter lies inside the outer contour's box: (279, 127)..(961, 991) font units.
    EXPECT_EQ(g["bounds"], json::array({113.0, -1147.0, 1141.0, 29.0}));
}

TEST_F(Cli, JsonOfDejaVuGHasTwoContoursOf12And29Points) {
    json j = outline_json({kDejaVu, "--char", "U+0067", "--font-size", "2048"});
    ASSERT_FALSE(j.is_discarded());
    const json& g = j["glyphs"][0];
    EXPECT_EQ(g["gid"].get<int>(), 74);
    EXPECT_EQ(g["advance"].get<double>(), 1300.0);
    ASSERT_EQ(g["contours"].size(), 2u);
    EXPECT_EQ(g["contours"][0]["points"].size(), 12u);
    EXPECT_EQ(g["contours"][1]["points"].size(), 29u);
    EXPECT_EQ(g["contours"][0]["points"][0]["x"].get<double>(), 930.0);
    EXPECT_EQ(g["contours"][0]["points"][0]["y"].get<double>(), -573.0);
}

// CFF: cubic control points, and outer contours run counter-clockwise. Cantarell 'o' lists the
// outer contour first, starting at (277, −10) font units.
TEST_F(Cli, JsonOfCantarellOHasCubicPointsAndCffDirections) {
    json j = outline_json({kCantarell, "--char", "o", "--font-size", "1000"});
    ASSERT_FALSE(j.is_discarded());
    EXPECT_EQ(j["font"]["outlines"], "cubic");
    const json& g = j["glyphs"][0];
    ASSERT_EQ(g["contours"].size(), 2u);
    EXPECT_EQ(g["contours"][0]["direction"], "counter-clockwise");
    EXPECT_EQ(g["contours"][1]["direction"], "clockwise");
    const json& p0 = g["contours"][0]["points"][0];
    EXPECT_EQ(p0["x"].get<double>(), 277.0);
    EXPECT_EQ(p0["y"].get<double>(), 10.0);
    EXPECT_EQ(g["contours"][0]["points"][1]["kind"], "off-cubic");
    for (const json& c : g["contours"]) {
        ASSERT_EQ(c["segments"].size(), 4u);
        for (const json& s : c["segments"]) EXPECT_EQ(s["kind"], "cubic");
    }
}

// Properties over every printable ASCII glyph of DejaVu Sans, in one --text run: the segments of
// each contour chain end to start and close; segment end points are on-curve points or the
// midpoints TrueType implies between two conic controls; the net signed area of every inked
// glyph is positive (clockwise outer contours enclose their counter-clockwise counters); glyphs
// sit on the pen.
TEST_F(Cli, TextRunSegmentsChainCloseAndFollowTrueTypeConventions) {
    std::string ascii;
    for (char c = '!'; c <= '~'; ++c) ascii += c;
    json j = outline_json({kDejaVu, "--text", ascii, "--font-size", "2048"});
    ASSERT_FALSE(j.is_discarded());
    ASSERT_EQ(j["glyphs"].size(), ascii.size());
    double pen = 0;
    for (const json& g : j["glyphs"]) {
        SCOPED_TRACE(g["name"].get<std::string>());
        EXPECT_EQ(g["pen_x"].get<double>(), pen);
        pen += g["advance"].get<double>();
        double net_area = 0;
        for (const json& c : g["contours"]) {
            net_area += c["signed_area"].get<double>();
            const json& pts = c["points"];
            const json& segs = c["segments"];
            // A lone point (DejaVu has such hinting anchors, e.g. in 'u') draws nothing.
            ASSERT_EQ(segs.empty(), pts.size() == 1);
            for (std::size_t i = 0; i < segs.size(); ++i) {
                const json& s = segs[i];
                const json& next = segs[(i + 1) % segs.size()];
                EXPECT_EQ(s["points"].back(), next["points"][0]);   // chained and closed
                EXPECT_EQ(s["points"].size(), s["kind"] == "line" ? 2u : 3u);
                // The end point is an on-curve point or the midpoint of two consecutive conics.
                double ex = s["points"].back()[0], ey = s["points"].back()[1];
                bool found = false;
                for (std::size_t k = 0; k < pts.size() && !found; ++k) {
                    const json& a = pts[k];
                    const json& b = pts[(k + 1) % pts.size()];
                    if (a["kind"] == "on")
                        found = a["x"] == ex && a["y"] == ey;
                    else if (b["kind"] == "off-conic")
                        found = std::abs((a["x"].get<double>() + b["x"].get<double>()) / 2 - ex) <= 1.0 / 64 &&
                                std::abs((a["y"].get<double>() + b["y"].get<double>()) / 2 - ey) <= 1.0 / 64;
                }
                EXPECT_TRUE(found) << "segment " << i << " ends at (" << ex << ", " << ey << ")";
            }
        }
        if (!g["contours"].empty()) {
            EXPECT_GT(net_area, 0.0);
        }
    }
}

// 'I' of the variable font: gvar moves the right edge (points 2, 3) and the advance by +200 at
// wght 900 and by −100 at wght 100.
TEST_F(Cli, VariationsMoveTheRightEdgeOfVariableI) {
    for (const auto& [setting, right_x, advance] : std::vector<std::tuple<std::string, double, double>>{
             {"", 300, 400}, {"wght=900", 500, 600}, {"wght=100", 200, 300}, {"wght=400", 300, 400}}) {
        SCOPED_TRACE(setting);
        std::vector<std::string> args = {kEdgeVariable, "--char", "I", "--font-size", "1000"};
        if (!setting.empty()) args.insert(args.end(), {"--variations", setting});
        json j = outline_json(args);
        ASSERT_FALSE(j.is_discarded());
        const json& g = j["glyphs"][0];
        EXPECT_EQ(g["advance"].get<double>(), advance);
        EXPECT_EQ(g["contours"][0]["points"][2]["x"].get<double>(), right_x);
        EXPECT_EQ(g["contours"][0]["points"][3]["x"].get<double>(), right_x);
        EXPECT_EQ(g["contours"][0]["points"][0]["x"].get<double>(), 100.0);
    }
    expect_runtime_error(run({"outline", kEdgeVariable, "--char", "I", "--variations", "wght=2000"}),
                         "wght");
    expect_runtime_error(run({"outline", kEdgeVariable, "--char", "I", "--variations", "wdth=80"}),
                         "wdth");
}

TEST_F(Cli, NamedInstanceSetsItsCoordinatesAndVariationsApplyOnTop) {
    // The variable face has instances 0 "Regular" (wght 400) and 1 "Black" (wght 900).
    auto outline = [&](std::vector<std::string> extra) {
        std::vector<std::string> args = {kEdgeVariable, "--char", "I", "--font-size", "1000"};
        args.insert(args.end(), extra.begin(), extra.end());
        return outline_json(args).dump();
    };
    const std::string black = outline({"--variations", "wght=900"});
    EXPECT_EQ(outline({"--named-instance", "Black"}), black);
    EXPECT_EQ(outline({"--named-instance", "1"}), black);
    EXPECT_EQ(outline({"--named-instance", "Black", "--variations", "wght=250"}),
              outline({"--variations", "wght=250"}));
    CliRun r = run({"render", kEdgeVariable, "--text", "I", "--named-instance", "Black", "-o",
                    "black.pgm"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    r = run({"render", kEdgeVariable, "--text", "I", "--variations", "wght=900", "-o", "900.pgm"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(bezel::test::slurp(tmp_.path() / "black.pgm") ==
                bezel::test::slurp(tmp_.path() / "900.pgm"));
    expect_runtime_error(run({"outline", kEdgeVariable, "--char", "I", "--named-instance", "Bold"}),
                         "--named-instance Bold: no such instance (it has 0 Regular, 1 Black)");
    expect_runtime_error(run({"outline", "--char", "I", "--named-instance", "0"}),
                         "the font has no named instances");
}

TEST_F(Cli, FaceIndexSelectsTheFaceOfACollection) {
    json j0 = outline_json({kEdgeCollection, "--char", "A"});
    json j1 = outline_json({kEdgeCollection, "--face-index", "1", "--char", "I"});
    EXPECT_EQ(j0["font"]["family"], "Bezel Edge Cases");
    EXPECT_EQ(j1["font"]["family"], "Bezel Variable");
    EXPECT_EQ(j1["font"]["face_index"].get<int>(), 1);
    expect_runtime_error(run({"outline", kEdgeCollection, "--face-index", "2", "--char", "I"}),
                         "EdgeCases.ttc");
}

// 'A' is four off-curve points (100,100) (100,501) (501,501) (501,100): the contour starts at the
// implied midpoint (300.5, 100) and runs clockwise.
TEST_F(Cli, OffCurveOnlyContourRunsThroughImpliedMidpoints) {
    json j = outline_json({kEdge, "--char", "A", "--font-size", "1000"});
    ASSERT_FALSE(j.is_discarded());
    const json& c = j["glyphs"][0]["contours"][0];
    EXPECT_EQ(c["direction"], "clockwise");
    for (const json& p : c["points"]) EXPECT_EQ(p["kind"], "off-conic");
    ASSERT_EQ(c["segments"].size(), 4u);
    EXPECT_EQ(c["segments"][0]["kind"], "quad");
    EXPECT_EQ(c["segments"][0]["points"][0], json::array({300.5, -100.0}));
    EXPECT_EQ(c["segments"][1]["points"][0], json::array({100.0, -300.5}));
    // |area| of the polygon through the four controls: 401 × 401.
    EXPECT_EQ(c["signed_area"].get<double>(), 401.0 * 401.0);
}

// '.' holds a single on-curve point, a triangle and a single off-curve point: the lone points
// are reported as degenerate contours and draw no line segments.
TEST_F(Cli, SinglePointContoursAreDegenerate) {
    json j = outline_json({kEdge, "--char", ".", "--font-size", "1000"});
    ASSERT_FALSE(j.is_discarded());
    const json& cs = j["glyphs"][0]["contours"];
    ASSERT_EQ(cs.size(), 3u);
    EXPECT_EQ(cs[0]["direction"], "degenerate");
    EXPECT_TRUE(cs[0]["segments"].empty());
    EXPECT_EQ(cs[1]["direction"], "clockwise");
    EXPECT_EQ(cs[1]["segments"].size(), 3u);
    EXPECT_EQ(cs[2]["direction"], "degenerate");
    EXPECT_EQ(cs[2]["points"][0]["kind"], "off-conic");
    CliRun text = run({"outline", kEdge, "--char", ".", "--font-size", "1000"});
    EXPECT_NE(text.out.find("contour 0: 1 point [0..0], degenerate (zero area)"), std::string::npos)
        << text.out;
    EXPECT_NE(text.out.find("segments: none"), std::string::npos);
}

TEST_F(Cli, EmptyGlyphHasNoContoursInEveryFormat) {
    json j = outline_json({kEdge, "--char", " ", "--font-size", "1000"});
    ASSERT_FALSE(j.is_discarded());
    const json& g = j["glyphs"][0];
    EXPECT_EQ(g["name"], "space");
    EXPECT_EQ(g["advance"].get<double>(), 300.0);
    EXPECT_TRUE(g["bounds"].is_null());
    EXPECT_TRUE(g["contours"].empty());
    CliRun text = run({"outline", kEdge, "--char", " "});
    EXPECT_EQ(text.exit_code, 0);
    EXPECT_NE(text.out.find("bounds (empty)  0 contours, 0 points"), std::string::npos) << text.out;
    CliRun svg = run({"outline", kEdge, "--char", " ", "-O", "svg"});
    EXPECT_EQ(svg.exit_code, 0);
    EXPECT_EQ(svg.out.substr(svg.out.size() - 7), "</svg>\n");
}

TEST_F(Cli, SvgOutputIsADocumentWithOutlinePointsAndContourMarks) {
    CliRun r = run({"outline", kDejaVu, "--char", "o", "-O", "svg", "--font-size", "64"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string& svg = r.out;
    EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
    EXPECT_EQ(svg.substr(svg.size() - 7), "</svg>\n");
    EXPECT_NE(svg.find("<path d=\"M"), std::string::npos);
    EXPECT_NE(svg.find("fill-rule=\"nonzero\""), std::string::npos);
    EXPECT_EQ(count(svg, "<text"), count(svg, "</text>"));
    // One point index label per point, and a start label per contour.
    for (const char* label : {">0<", ">11<", ">12<", ">23<", ">c0 ", ">c1 "})
        EXPECT_NE(svg.find(label), std::string::npos) << label;
    EXPECT_EQ(svg.find(">24<"), std::string::npos);
    for (const char* word : {"baseline", "ascender", "descender", "advance", "on-curve",
                             "off-curve", "control polygon"})
        EXPECT_NE(svg.find(word), std::string::npos) << word;
}

TEST_F(Cli, OutputFormatFollowsFileExtension) {
    for (const auto& [file, starts_with] : std::vector<std::pair<std::string, std::string>>{
             {"g.json", "{"}, {"g.SVG", "<svg"}, {"g.txt", "font "}}) {
        CliRun r = run({"outline", "--char", "g", "-o", file});
        EXPECT_EQ(r.exit_code, 0) << r.err;
        EXPECT_TRUE(r.out.empty());
        std::string written = slurp(dir_ / file);
        EXPECT_EQ(written.rfind(starts_with, 0), 0u) << file << ": " << written.substr(0, 40);
    }
    EXPECT_FALSE(json::parse(slurp(dir_ / "g.json"), nullptr, false).is_discarded());
    // -O wins over the extension.
    CliRun r = run({"outline", "--char", "g", "-O", "json", "-o", "g.dat"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_FALSE(json::parse(slurp(dir_ / "g.dat"), nullptr, false).is_discarded());
}

TEST_F(Cli, FailureLeavesNoPartialFileAndKeepsTheOldOne) {
    CliRun r = run({"outline", "missing.ttf", "--char", "g", "-o", "g.svg"});
    expect_runtime_error(r, "missing.ttf");
    EXPECT_TRUE(files().empty());

    std::ofstream(dir_ / "g.json") << "old";
    r = run({"outline", kDejaVu, "--gid", "99999", "-o", "g.json"});
    expect_runtime_error(r, "--gid 99999");
    EXPECT_EQ(slurp(dir_ / "g.json"), "old");
    EXPECT_EQ(files().size(), 1u);
}

TEST_F(Cli, UnwritableOutputIsRuntimeErrorNamingFile) {
    CliRun r = run({"outline", "--char", "g", "-o", "no-such-dir/g.svg"});
    expect_runtime_error(r, "no-such-dir/g.svg");
    r = run({"outline", "--char", "g", "-O", "svg", "-o", dir_.string()});
    expect_runtime_error(r, dir_.string());
}

TEST_F(Cli, TextOutputListsContoursPointsAndSegments) {
    CliRun r = run({"outline", kDejaVu, "--char", "o", "--font-size", "2048"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* s : {"contour 0: 12 points [0..11], counter-clockwise (hole by TrueType convention)",
                          "contour 1: 12 points [12..23], clockwise (outer by TrueType convention)", "   0    627.000   -991.000  on",
                          "   1    479.000   -991.000  off-conic", "segments:", "quad", "advance 1253.000"})
        EXPECT_NE(r.out.find(s), std::string::npos) << s << "\n" << r.out;
}

TEST_F(Cli, TextWithUnmappedCharacterWarnsAndUsesNotdef) {
    CliRun r = run({"outline", kDejaVu, "--text", "o\xf4\x8f\xbf\xbd", "-O", "json"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("U+10FFFD"), std::string::npos) << r.err;
    json j = json::parse(r.out, nullptr, false);
    ASSERT_EQ(j["glyphs"].size(), 2u);
    EXPECT_EQ(j["glyphs"][1]["gid"].get<int>(), 0);
}

// Malformed text given on the command line is the command line's fault, as a malformed --char is.
TEST_F(Cli, InvalidUtf8TextIsUsageErrorNamingOptionAndByte) {
    expect_usage_error(run({"outline", kDejaVu, "--text", "a\xff"}), "--text: text byte 1");
}

}  // namespace
