// End-to-end tests of `bezel intersect` (BEZEL_CLI_PATH): the JSON contract (shape, key order,
// 17 significant digits that read back to the library's doubles), self-intersection with one
// path, overlaps, SVG and PNG output, and exit codes.

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/cli_run.hpp"

#include "bezel/image.hpp"
#include "bezel/intersect.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

using bezel::test::CliRun;
using bezel::test::slurp;

class CliIntersect : public ::testing::Test {
protected:
    bezel::test::TempDir tmp_{"bezel-cli-isect"};
    const fs::path& dir_ = tmp_.path();

    // Runs the CLI with `args` (no shell) in dir_, stdout and stderr captured through files.
    CliRun run(std::vector<std::string> args) {
        args.insert(args.begin(), "intersect");
        return bezel::test::run_bezel(args, dir_);
    }

};

TEST_F(CliIntersect, JsonIsExactlyTheContract) {
    CliRun r = run({"M0,0 L4,4", "M0,4 L4,0", "-O", "json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out,
              "{\"intersections\": [\n"
              "  {\"seg_a\": 0, \"t_a\": 0.5, \"seg_b\": 0, \"t_b\": 0.5, \"x\": 2, \"y\": 2, "
              "\"kind\": \"cross\"}\n"
              "], \"overlaps\": []}\n");
}

TEST_F(CliIntersect, JsonNumbersReadBackToTheLibrarysDoubles) {
    const char* a = "M0,0 C0,14 3,-9 3,5";
    const char* b = "M-1,4 C13,4 -10,1 4,1";
    CliRun r = run({a, b, "-O", "json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    json doc = json::parse(r.out, nullptr, false);
    ASSERT_FALSE(doc.is_discarded()) << r.out;
    auto lib = bezel::intersect_paths(*bezel::parse_svg_path(a), *bezel::parse_svg_path(b));
    ASSERT_TRUE(lib.ok());
    ASSERT_EQ(doc["intersections"].size(), 9u);  // Lasser's example
    ASSERT_EQ(lib->intersections.size(), 9u);
    for (std::size_t i = 0; i < 9; ++i) {
        const json& x = doc["intersections"][i];
        const bezel::PathIntersection& p = lib->intersections[i];
        EXPECT_EQ(x["t_a"].get<double>(), p.t_a);  // bit for bit: 17 digits round-trip
        EXPECT_EQ(x["t_b"].get<double>(), p.t_b);
        EXPECT_EQ(x["x"].get<double>(), p.point.x);
        EXPECT_EQ(x["y"].get<double>(), p.point.y);
        EXPECT_EQ(x["kind"], "cross");
    }
    EXPECT_TRUE(doc["overlaps"].empty());
}

TEST_F(CliIntersect, OnePathGivesItsSelfIntersections) {
    CliRun r = run({"M0,0 L10,10 L10,0 L0,10 Z", "-O", "json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    json doc = json::parse(r.out);
    ASSERT_EQ(doc["intersections"].size(), 1u);
    EXPECT_EQ(doc["intersections"][0]["seg_a"], 0);
    EXPECT_EQ(doc["intersections"][0]["seg_b"], 2);
    EXPECT_EQ(doc["intersections"][0]["x"], 5.0);
}

TEST_F(CliIntersect, OverlapsAreParameterIntervals) {
    CliRun r = run({"M0,0 L10,0", "M5,0 L15,0", "-O", "json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    json doc = json::parse(r.out);
    EXPECT_TRUE(doc["intersections"].empty());
    ASSERT_EQ(doc["overlaps"].size(), 1u);
    EXPECT_EQ(doc["overlaps"][0]["t_a"], json::array({0.5, 1.0}));
    EXPECT_EQ(doc["overlaps"][0]["t_b"], json::array({0.0, 0.5}));
}

TEST_F(CliIntersect, TextIsTheDefault) {
    CliRun r = run({"M0,0 L4,4", "M0,4 L4,0"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("1 intersection, 0 overlaps"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("cross at (2, 2)"), std::string::npos) << r.out;
}

TEST_F(CliIntersect, SvgMarksEveryPoint) {
    CliRun r = run({"M0,0 C0,14 3,-9 3,5", "M-1,4 C13,4 -10,1 4,1", "-o", "x.svg"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::string svg = slurp(dir_ / "x.svg");
    EXPECT_EQ(svg.rfind("<svg", 0), 0u);
    std::size_t circles = 0;
    for (auto at = svg.find("<circle"); at != std::string::npos; at = svg.find("<circle", at + 1)) ++circles;
    EXPECT_EQ(circles, 9u);
}

TEST_F(CliIntersect, PngIsAGrayImageOfTheFixedSize) {
    CliRun r = run({"M0,0 L40,20", "M0,20 L40,0", "-o", "x.png"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto mask = bezel::read_png_gray((dir_ / "x.png").string());
    ASSERT_TRUE(mask.ok()) << mask.error().message;
    // 40 × 20 plus a margin of 6% of the longer side (2.4) all round: 44.8 × 24.8, scaled so
    // the longer side is 512 px: height ⌈512 · 24.8 / 44.8⌉ = ⌈283.4⌉.
    EXPECT_EQ(mask->width(), 512);
    EXPECT_EQ(mask->height(), 284);
    // Ink somewhere (the lines), white paper in the corner.
    EXPECT_EQ(mask->at(0, 0), 255);
    int dark = 0;
    for (std::uint8_t v : mask->pixels()) dark += v < 128;
    EXPECT_GT(dark, 500);
}

TEST_F(CliIntersect, BadPathDataIsAUsageErrorNamingTheArgument) {
    CliRun r = run({"M0,0 L1,x", "M0,1 L1,0"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.err.rfind("bezel: PATH_A: path data offset", 0), 0u) << r.err;
    EXPECT_TRUE(r.out.empty());
    CliRun f = run({"M0,0 L1,1", "-O", "bmp"});
    EXPECT_EQ(f.exit_code, 2);
}

}  // namespace
