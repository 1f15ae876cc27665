// `bezel stroke` end to end: path data that reads back to the library's outline, SVG and PNG
// output, the PNG canvas options, exit codes and error lines. Runs the built CLI binary.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "bezel/image.hpp"
#include "bezel/stroke.hpp"
#include "support/cli_run.hpp"

namespace {

using bezel::test::CliRun;

bezel::test::TempDir& scratch() {
    static bezel::test::TempDir dir("bezel-stroke-cli");
    return dir;
}

// Runs `bezel <args>` with args written as on a shell command line (single quotes only).
CliRun run(const std::string& args) {
    return bezel::test::run_bezel(bezel::test::split_args(args), scratch().path());
}

class StrokeCli : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(std::filesystem::exists(bezel::test::cli_path())) << bezel::test::cli_path();
    }
};

bezel::Path library_stroke(const char* data, const bezel::StrokeStyle& style) {
    auto p = bezel::parse_svg_path(data);
    EXPECT_TRUE(p.ok());
    auto out = bezel::stroke(*p, style);
    EXPECT_TRUE(out.ok());
    return out.ok() ? *out : bezel::Path{};
}

}  // namespace

// The default output is the outline as SVG path data with round-trip numbers: parsing it gives
// the library's outline bit for bit.
TEST_F(StrokeCli, PathDataReadsBackAsTheLibraryOutline) {
    CliRun r = run("stroke 'M10,10 C40,80 80,-20 110,50 L120,10' --width 8 --join round "
                   "--cap square --dash 30,6 --dash-offset 4 --tolerance 0.005");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto back = bezel::parse_svg_path(r.out);
    ASSERT_TRUE(back.ok()) << back.error().message;
    bezel::StrokeStyle s;
    s.width = 8;
    s.join = bezel::LineJoin::Round;
    s.cap = bezel::LineCap::Square;
    s.dashes = {30, 6};
    s.dash_offset = 4;
    s.tolerance = 0.005;
    EXPECT_EQ(*back, library_stroke("M10,10 C40,80 80,-20 110,50 L120,10", s));
}

TEST_F(StrokeCli, SvgFromExtensionHasOutlineAndSource) {
    CliRun r = run("stroke 'M0,0 L50,0 L50,50 Z' --width 4 -o ring.svg");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(r.out.empty());
    std::string svg = bezel::test::slurp(scratch().path() / "ring.svg");
    EXPECT_EQ(svg.rfind("<svg", 0), 0u);
    EXPECT_NE(svg.find("fill-rule=\"nonzero\""), std::string::npos);
    EXPECT_NE(svg.find("<title>bezel stroke --width 4 --join miter --cap butt"), std::string::npos);
    EXPECT_NE(svg.find("</svg>"), std::string::npos);
}

// A PNG fitted to the outline: a 20-wide stroke of a 100-long line with butt caps covers
// x ∈ [10, 110], y ∈ [40, 60]; the canvas is that box plus 2 px, ink dark where it covers.
TEST_F(StrokeCli, PngFitsTheOutlineAndInksTheStroke) {
    CliRun r = run("stroke 'M10,50 L110,50' --width 20 -o line.png");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto png = bezel::read_png_gray((scratch().path() / "line.png").string());
    ASSERT_TRUE(png.ok()) << png.error().message;
    EXPECT_EQ(png->width(), 104);
    EXPECT_EQ(png->height(), 24);
    EXPECT_EQ(png->at(50, 12), 0);   // inside: full ink
    EXPECT_EQ(png->at(1, 12), 255);  // margin: paper
    EXPECT_EQ(png->at(50, 1), 255);
}

TEST_F(StrokeCli, PngSizeAndTransformPlaceTheOutline) {
    CliRun r = run("stroke 'M0,5 L10,5' --width 2 -O png --size 40x30 --transform 2,0,0,2,0,0 "
                   "-o scaled.png");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto png = bezel::read_png_gray((scratch().path() / "scaled.png").string());
    ASSERT_TRUE(png.ok());
    EXPECT_EQ(png->width(), 40);
    EXPECT_EQ(png->height(), 30);
    EXPECT_EQ(png->at(10, 10), 0);    // (5, 5) scaled by 2, inside the 4 px wide band y ∈ [8, 12]
    EXPECT_EQ(png->at(10, 14), 255);
    EXPECT_EQ(png->at(25, 10), 255);  // past the scaled end x = 20
}

TEST_F(StrokeCli, PathFileIsReadLikeTheArgument) {
    {
        std::ofstream f(scratch().path() / "in.path");
        f << "M0 0 Q20 40 40 0";
    }
    CliRun a = run("stroke --path-file in.path --width 3 --cap round");
    CliRun b = run("stroke 'M0 0 Q20 40 40 0' --width 3 --cap round");
    ASSERT_EQ(a.exit_code, 0) << a.err;
    EXPECT_EQ(a.out, b.out);
}

TEST_F(StrokeCli, UsageErrorsExitTwoWithOneLine) {
    struct Case {
        const char* args;
        const char* message;
    };
    const Case cases[] = {
        {"stroke 'M0,0 Lx' --width 2", "bezel: PATH: path data offset"},
        {"stroke 'M0,0 L1,1' --width 0", "bezel: --width 0: must be a finite number > 0"},
        {"stroke 'M0,0 L1,1' --miter-limit 0.5", "bezel: --miter-limit 0.5: must be >= 1"},
        {"stroke 'M0,0 L1,1' --tolerance -1", "bezel: --tolerance -1"},
        {"stroke 'M0,0 L1,1' --dash 1,x", "bezel: --dash '1,x': expected a number at 'x'"},
        {"stroke 'M0,0 L1,1' --dash 0,0", "bezel: --dash '0,0': the lengths must not all be 0"},
        {"stroke 'M0,0 L1,1' --dash 2,-1", "bezel: --dash '2,-1': lengths must be >= 0"},
        {"stroke 'M0,0 L1,1' -o out.bmp", "bezel: out.bmp: cannot tell the output format"},
        {"stroke 'M0,0 L1,1' --size 10x10", "bezel: --size and --transform apply only to -O png"},
        {"stroke 'M0,0 L1,1' -O png --size 10", "bezel: --size '10': expected WxH"},
        {"stroke 'M0,0 L1,1' -O png --transform 1,2", "bezel: --transform '1,2': expected 6"},
    };
    for (const Case& c : cases) {
        CliRun r = run(c.args);
        EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
        EXPECT_EQ(r.err.rfind(c.message, 0), 0u) << c.args << "\n" << r.err;
        EXPECT_TRUE(r.out.empty()) << c.args;
    }
    CliRun r = run("stroke 'M0,0 L1,1' --join sharp");
    EXPECT_EQ(r.exit_code, 2) << r.err;
}

TEST_F(StrokeCli, RuntimeErrorsExitOneAndLeaveNoFile) {
    CliRun r = run("stroke --path-file missing.path --width 2");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "bezel: missing.path: cannot open the path file\n");

    // A 1e-6 dash over a 1e6 line would be 5e11 dashes: kMaxDashes stops it.
    r = run("stroke 'M0,0 L1e6,0' --width 1 --dash 1e-6 -o never.path");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("more than the 65536 allowed"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(scratch().path() / "never.path"));

    r = run("stroke 'M0,0 L1e5,0' --width 10 -o huge.png");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("--transform"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(scratch().path() / "huge.png"));

    r = run("stroke 'M0,0 L1,0' --width 1 -o no-such-dir/out.path");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err.rfind("bezel: no-such-dir/out.path", 0), 0u) << r.err;
}
