// `bezel smooth` and `bezel continuity` end to end: the JSON contract, reading the tool's own
// output back, exit codes and error lines. Runs the built CLI binary.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "bezel/smooth.hpp"
#include "support/cli_run.hpp"

namespace {

using bezel::test::CliRun;

// Runs `bezel <args>` with args written as on a shell command line (single quotes only), in a
// scratch directory.
CliRun run(const std::string& args) {
    static bezel::test::TempDir dir("bezel-smooth-cli");
    return bezel::test::run_bezel(bezel::test::split_args(args), dir.path());
}

class SmoothCli : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(std::filesystem::exists(bezel::test::cli_path())) << bezel::test::cli_path();
    }
};

}  // namespace

// The stable contract: {"segments": [[[x,y] ×4], …]}, here the hand-solved natural spline of
// (0,0) (1,1) (2,0) (see smooth_test.cpp), every number reading back to the library's double.
TEST_F(SmoothCli, NaturalSplineJsonIsTheSegmentsContract) {
    CliRun r = run("smooth --method natural --points '0,0 1,1 2,0'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto doc = nlohmann::json::parse(r.out);
    ASSERT_TRUE(doc.is_object());
    ASSERT_EQ(doc.size(), 1u);
    const auto& segs = doc.at("segments");
    ASSERT_EQ(segs.size(), 2u);
    auto lib = bezel::natural_spline({{0, 0}, {1, 1}, {2, 0}});
    ASSERT_TRUE(lib.ok());
    std::size_t i = 0;
    for (const bezel::PathSeg& s : lib->segments()) {
        bezel::CubicBez c = s.to_cubic();
        const bezel::Point pts[4] = {c.p0, c.p1, c.p2, c.p3};
        ASSERT_EQ(segs[i].size(), 4u);
        for (int k = 0; k < 4; ++k) {
            EXPECT_EQ(segs[i][k][0].get<double>(), pts[k].x);
            EXPECT_EQ(segs[i][k][1].get<double>(), pts[k].y);
        }
        ++i;
    }
}

// Chaikin's polygon is {"points": …}, and --points-file reads it back: cutting once, then once
// more from the file, equals cutting twice.
TEST_F(SmoothCli, ChaikinPointsReadBackThroughPointsFile) {
    std::string file = (std::filesystem::temp_directory_path() /
                        ("bezel-chaikin-" + std::to_string(::getpid()) + ".json")).string();
    CliRun once = run("smooth --method chaikin --iterations 1 --closed --points '0,0 8,0 8,8 0,8' -o '" +
                   file + "'");
    ASSERT_EQ(once.exit_code, 0) << once.err;
    CliRun again = run("smooth --method chaikin --iterations 1 --closed --points-file '" + file + "'");
    CliRun twice = run("smooth --method chaikin --iterations 2 --closed --points '0,0 8,0 8,8 0,8'");
    std::filesystem::remove(file);
    ASSERT_EQ(again.exit_code, 0) << again.err;
    ASSERT_EQ(twice.exit_code, 0) << twice.err;
    EXPECT_EQ(again.out, twice.out);
    EXPECT_EQ(nlohmann::json::parse(twice.out).at("points").size(), 16u);
    // --limit gives the curve as segments.
    CliRun limit = run("smooth --method chaikin --limit --closed --points '0,0 8,0 8,8 0,8'");
    ASSERT_EQ(limit.exit_code, 0) << limit.err;
    EXPECT_EQ(nlohmann::json::parse(limit.out).at("segments").size(), 4u);
}

TEST_F(SmoothCli, EveryMethodWritesJsonSvgPathAndPng) {
    const std::string pts = "--points '20,120 60,30 140,40 180,130 120,170'";
    for (const char* m : {"chaikin", "bspline", "natural", "catmull-rom", "hermite"}) {
        std::string base = std::string("smooth --method ") + m + " " + pts;
        CliRun json = run(base + " -O json");
        ASSERT_EQ(json.exit_code, 0) << m << ": " << json.err;
        EXPECT_TRUE(nlohmann::json::accept(json.out)) << m;
        CliRun svg = run(base + " -O svg");
        ASSERT_EQ(svg.exit_code, 0) << m << ": " << svg.err;
        EXPECT_EQ(svg.out.rfind("<svg ", 0), 0u) << m;
        EXPECT_NE(svg.out.find("</svg>"), std::string::npos) << m;
        CliRun path = run(base + " -O path");
        ASSERT_EQ(path.exit_code, 0) << m << ": " << path.err;
        EXPECT_EQ(path.out.rfind("M20 120", 0), 0u) << m << ": " << path.out;
        CliRun png = run(base + " -O png");
        ASSERT_EQ(png.exit_code, 0) << m << ": " << png.err;
        EXPECT_EQ(png.out.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8)) << m;
    }
}

TEST_F(SmoothCli, HermiteTakesTangentsAndClosedCurvesCloseWithZ) {
    CliRun r = run("smooth --method hermite --points '0,0 3,0' --tangents '3,3 3,-3' -O path");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out, "M0 0C1 1 2 1 3 0\n");  // P1 = P0 + T0/3, P2 = P1 − T1/3
    CliRun c = run("smooth --method natural --closed --points '0,0 4,0 4,4 0,4 0,0' -O path");
    ASSERT_EQ(c.exit_code, 0) << c.err;
    EXPECT_EQ(c.out.substr(c.out.size() - 2), "Z\n");
}

// Usage errors exit 2, input the library rejects exits 1; each is one line naming the input.
TEST_F(SmoothCli, ErrorsAreOneLineWithTheRightExitCode) {
    CliRun bad_number = run("smooth --method natural --points '0,0 1,x'");
    EXPECT_EQ(bad_number.exit_code, 2);
    EXPECT_NE(bad_number.err.find("bezel: --points: 'x' at offset 6 is not a finite number"),
              std::string::npos) << bad_number.err;
    CliRun odd = run("smooth --method natural --points '0,0 1'");
    EXPECT_EQ(odd.exit_code, 2);
    EXPECT_NE(odd.err.find("3 numbers, expected x,y pairs"), std::string::npos) << odd.err;
    CliRun wrong_option = run("smooth --method natural --alpha 0.5 --points '0,0 1,1'");
    EXPECT_EQ(wrong_option.exit_code, 2);
    EXPECT_NE(wrong_option.err.find("--alpha applies only to --method catmull-rom"),
              std::string::npos) << wrong_option.err;
    CliRun no_points = run("smooth --method natural");
    EXPECT_EQ(no_points.exit_code, 2);
    CliRun too_few = run("smooth --method natural --points '1,1'");
    EXPECT_EQ(too_few.exit_code, 1);
    EXPECT_EQ(too_few.err, "bezel: natural spline: 1 point, at least 2 needed\n");
    CliRun repeated = run("smooth --method natural --points '0,0 1,1 1,1'");
    EXPECT_EQ(repeated.exit_code, 1);
    EXPECT_NE(repeated.err.find("points[1] and points[2] are both (1, 1)"), std::string::npos);
    CliRun missing = run("smooth --method natural --points-file /nonexistent/points.txt");
    EXPECT_EQ(missing.exit_code, 1);
    EXPECT_EQ(missing.err, "bezel: /nonexistent/points.txt: cannot open file\n");
    CliRun bad_json_file = run("smooth --method natural --points-file /dev/null");
    EXPECT_EQ(bad_json_file.exit_code, 1);  // empty: zero points
}

TEST_F(SmoothCli, ContinuityPrintsEachJointAsTextOrJson) {
    CliRun text = run("continuity 'M0 0 L1 0 L2 0 L2 1'");
    ASSERT_EQ(text.exit_code, 0) << text.err;
    EXPECT_NE(text.out.find("joint 0: segment 0 -> 1 (contour 0) at 1,0: C2"), std::string::npos)
        << text.out;
    EXPECT_NE(text.out.find("joint 1: segment 1 -> 2 (contour 0) at 2,0: C0"), std::string::npos)
        << text.out;
    CliRun json = run("continuity 'M0 0 C1 1 2 1 3 0 S5 -1 6 0 Z' -O json");
    ASSERT_EQ(json.exit_code, 0) << json.err;
    auto doc = nlohmann::json::parse(json.out);
    EXPECT_EQ(doc.at("tolerance").get<double>(), 1e-9);
    const auto& joints = doc.at("joints");
    ASSERT_EQ(joints.size(), 3u);  // C→S, S→closing line, closing line→C
    EXPECT_EQ(joints[0].at("class"), "C1");  // S reflects the handle: C1, the bend flips
    EXPECT_EQ(joints[0].at("incoming"), 0);
    EXPECT_EQ(joints[0].at("outgoing"), 1);
    EXPECT_EQ(joints[2].at("outgoing"), 0);
    CliRun bad = run("continuity 'M0 0 L'");
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_EQ(bad.err.rfind("bezel: PATH: path data offset", 0), 0u) << bad.err;
}
