// `bezel fill` end to end: exact pixels for rectangles, fill rules, the transform, the picture
// formats (PGM bytes, a PNG golden) and errors that name their input.
//
// The golden lives in tests/golden/fill/; regenerate with BEZEL_UPDATE_GOLDEN=1 after a
// deliberate change (and say why in the commit).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "bezel/image.hpp"
#include "support/cli_run.hpp"
#include "support/golden.hpp"

namespace {

using bezel::test::CliRun;

bezel::test::TempDir& scratch() {
    static bezel::test::TempDir dir("bezel-fill-cli");
    return dir;
}
CliRun run(std::vector<std::string> args) {
    args.insert(args.begin(), "fill");
    return bezel::test::run_bezel(args, scratch().path());
}

// The PGM on stdout as a mask (asserting its header): the coverage (--coverage) unless
// `picture`, then the picture in the colours `args` give (black on white by default).
bezel::Mask pgm(const std::vector<std::string>& args, int w, int h, bool picture = false) {
    std::vector<std::string> a = args;
    a.insert(a.end(), {"--width", std::to_string(w), "--height", std::to_string(h), "-O", "pgm"});
    if (!picture) a.push_back("--coverage");
    CliRun r = run(a);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const std::string header = "P5\n" + std::to_string(w) + " " + std::to_string(h) + "\n255\n";
    bezel::Mask m(w, h);
    if (r.out.size() != header.size() + std::size_t(w * h) || r.out.rfind(header, 0) != 0) {
        ADD_FAILURE() << "not a " << w << "x" << h << " PGM";
        return m;
    }
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            m.at(x, y) = static_cast<std::uint8_t>(r.out[header.size() + std::size_t(y * w + x)]);
    return m;
}

class FillCli : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(std::filesystem::exists(bezel::test::cli_path())) << bezel::test::cli_path();
    }
};

}  // namespace

TEST_F(FillCli, RectangleCoverageIsExact) {
    // x from 1.5 to 5, y from 2 to 4.25: columns 1 half covered, row 4 a quarter.
    const bezel::Mask m = pgm({"M1.5,2 H5 V4.25 H1.5 Z"}, 7, 6);
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 7; ++x) {
            const double cx = std::max(0.0, std::min(5.0, x + 1.0) - std::max(1.5, double(x)));
            const double cy = std::max(0.0, std::min(4.25, y + 1.0) - std::max(2.0, double(y)));
            EXPECT_NEAR(m.at(x, y), 255 * cx * cy, 0.5 + 1e-9) << x << "," << y;
        }
}

TEST_F(FillCli, EvenOddCancelsTheInnerSquare) {
    const std::string path = "M0,0 h10 v10 h-10 z M2,2 h6 v6 h-6 z";
    const bezel::Mask nz = pgm({path}, 10, 10);
    const bezel::Mask eo = pgm({path, "--fill", "evenodd"}, 10, 10);
    EXPECT_EQ(nz.at(5, 5), 255);
    EXPECT_EQ(eo.at(5, 5), 0);
    EXPECT_EQ(eo.at(1, 5), 255);
}

TEST_F(FillCli, TransformMapsThePath) {
    // The unit square scaled by 4 and moved to (2, 2) is the square 2..6.
    EXPECT_EQ(pgm({"M0,0 h1 v1 h-1 z", "--transform", "4,0,0,4,2,2"}, 8, 8),
              pgm({"M2,2 h4 v4 h-4 z"}, 8, 8));
}

TEST_F(FillCli, AccurateOverlapRendersADoubledSquareLikeOne) {
    const std::string one = "M1.25,1.5 h5 v4 h-5 z";
    EXPECT_EQ(pgm({one + one, "--overlap", "accurate"}, 8, 8), pgm({one}, 8, 8));
    EXPECT_NE(pgm({one + one}, 8, 8), pgm({one}, 8, 8));
}

TEST_F(FillCli, PngMatchesGoldenAndPgm) {
    // A circle-ish curve with a hole; tolerance 1/255 per pixel.
    const std::vector<std::string> args = {
        "M20,4 C29,4 36,11 36,20 C36,29 29,36 20,36 C11,36 4,29 4,20 C4,11 11,4 20,4 Z "
        "M20,12 Q12,20 20,28 Q28,20 20,12 Z",
        "--fill", "evenodd", "--width", "40", "--height", "40"};
    const std::string golden = std::string(BEZEL_GOLDEN_DIR) + "/fill/circle_hole.png";
    const std::string out = (scratch().path() / "c.png").string();
    std::vector<std::string> a = args;
    a.insert(a.end(), {"-o", out});
    CliRun r = run(a);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(r.out.empty());
    auto got = bezel::read_png_gray(out);
    ASSERT_TRUE(got.ok()) << got.error().message;
    // Ink on paper: black on white is the coverage inverted, byte for byte.
    const bezel::Mask coverage = pgm({args[0], "--fill", "evenodd"}, 40, 40);
    EXPECT_EQ(*got, pgm({args[0], "--fill", "evenodd"}, 40, 40, true));
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 40; ++x) ASSERT_EQ(got->at(x, y), 255 - coverage.at(x, y)) << x << "," << y;
    if (bezel::test::update_golden()) return bezel::test::replace_golden(out, golden);
    auto want = bezel::read_png_gray(golden);
    ASSERT_TRUE(want.ok()) << want.error().message;
    ASSERT_EQ(want->width(), 40);
    int worst = 0;
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 40; ++x) worst = std::max(worst, std::abs(got->at(x, y) - want->at(x, y)));
    EXPECT_LE(worst, 1);
}

TEST_F(FillCli, AsciiHasOneLinePerRow) {
    CliRun r = run({"M1,1 h3 v2 h-3 z", "--width", "6", "--height", "4"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out, "|\n| @@@\n| @@@\n|\n");
}

TEST_F(FillCli, ErrorsNameTheirInput) {
    struct Case {
        std::vector<std::string> args;
        int code;
        std::string says;
    };
    const Case cases[] = {
        {{"M0,0 L5,5 Q", "--width", "8", "--height", "8"}, 2, "offset"},
        {{"L5,5", "--width", "8", "--height", "8"}, 2, "offset 0"},
        {{"M0,0 h1 v1 z", "--width", "0", "--height", "8"}, 2, "--width 0"},
        {{"M0,0 h1 v1 z", "--width", "8", "--height", "100000"}, 2, "--height 100000: expected 1 to 8192 pixels"},
        {{"M0,0 h1 v1 z", "--width", "8", "--height", "8", "--transform", "1,0,0,1,0"}, 2, "--transform"},
        {{"M0,0 h1 v1 z", "--width", "8", "--height", "8", "--transform", "1,0,0,1,0,x"}, 2, "'x'"},
        {{"M0,0 h1 v1 z", "--width", "8", "--height", "8", "--transform", "1,0,0,1,0,inf"}, 2, "--transform"},
        {{"M0,0 h1 v1 z", "--width", "8", "--height", "8", "--fill", "odd"}, 2, "--fill"},
        {{"M0,0 h1 v1 z", "--width", "8", "--height", "8", "-o", "out.gif"}, 2, "out.gif"},
        {{"M0,0 h1 v1 z", "--width", "8"}, 2, "--height"},
        {{"M0,0 h1 v1 z", "--width", "8", "--height", "8", "-o", "no/dir/x.png"}, 1, "no/dir/x.png"},
        // 1e12 px of curve at 1e-9 px tolerance: past the flattener's per-curve cap.
        {{"M0,0 Q1e12,0 1e12,1e12 Z", "--width", "8", "--height", "8", "--tolerance", "1e-9"},
         1, "65536 segments per curve"},
    };
    for (const Case& c : cases) {
        CliRun r = run(c.args);
        EXPECT_EQ(r.exit_code, c.code) << c.args[0] << ": " << r.err;
        EXPECT_EQ(r.err.rfind("bezel: ", 0), 0u) << r.err;
        EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
        EXPECT_TRUE(r.out.empty());
    }
    EXPECT_FALSE(std::filesystem::exists(scratch().path() / "out.gif"));
}
