// `bezel surface` end to end: golden pictures (wire and solid, orthographic and perspective),
// OBJ/STL output, and errors for malformed input. Runs the built CLI binary.
// Goldens live in tests/golden/surface/; regenerate with BEZEL_UPDATE_GOLDEN=1 after a deliberate
// change (and say why in the commit).
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "bezel/image.hpp"
#include "support/cli_run.hpp"
#include "support/golden.hpp"

namespace {

using bezel::test::CliRun;

bezel::test::TempDir& scratch() {
    static bezel::test::TempDir dir("bezel-surface-cli");
    return dir;
}
CliRun run(const std::vector<std::string>& args) {
    std::vector<std::string> a = {"surface"};
    a.insert(a.end(), args.begin(), args.end());
    return bezel::test::run_bezel(a, scratch().path());
}
std::string data(const std::string& name) {
    return std::string(BEZEL_SOURCE_DIR) + "/tests/data/surfaces/" + name;
}
std::string write_scratch(const std::string& name, const std::string& text) {
    std::filesystem::path p = scratch().path() / name;
    std::ofstream(p) << text;
    return p.string();
}

class SurfaceCli : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(std::filesystem::exists(bezel::test::cli_path())) << bezel::test::cli_path();
    }
};

// Renders to PNG and compares the luma with the golden. Tolerance: at most 0.5% of pixels may
// differ by more than 2/255 and none by more than 48/255 (floating-point differences between
// compilers move an anti-aliased edge or a depth-sort tie by a fraction of a pixel, no more).
void expect_golden(const std::string& name, std::vector<std::string> args) {
    const std::string golden = std::string(BEZEL_GOLDEN_DIR) + "/surface/" + name + ".png";
    const std::string out = (scratch().path() / (name + ".png")).string();
    args.insert(args.end(), {"--size", "128x128", "-o", out});
    CliRun r = run(args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    if (bezel::test::update_golden()) return bezel::test::replace_golden(out, golden);
    auto got = bezel::read_png_gray(out);
    ASSERT_TRUE(got.ok()) << got.error().message;
    auto want = bezel::read_png_gray(golden);
    ASSERT_TRUE(want.ok()) << want.error().message << " (BEZEL_UPDATE_GOLDEN=1 creates it)";
    ASSERT_EQ(got->width(), want->width());
    ASSERT_EQ(got->height(), want->height());
    int worst = 0, off = 0, inked = 0;
    for (int y = 0; y < want->height(); ++y)
        for (int x = 0; x < want->width(); ++x) {
            int d = std::abs(got->at(x, y) - want->at(x, y));
            worst = std::max(worst, d);
            off += d > 2;
            inked += want->at(x, y) < 250;
        }
    EXPECT_LE(worst, 48) << name;
    EXPECT_LE(off, want->width() * want->height() / 200) << name;
    EXPECT_GT(inked, 500) << name << ": the golden should show a surface";
}

TEST_F(SurfaceCli, TeapotSolidSmoothMatchesGolden) {
    expect_golden("teapot_solid", {"--patch", data("teapot.json"), "--view", "-35,25"});
}
TEST_F(SurfaceCli, TeapotSolidFlatOrthoMatchesGolden) {
    expect_golden("teapot_flat_ortho", {"--patch", data("teapot.json"), "--view", "-60,35",
                                        "--projection", "ortho", "--shading", "flat", "--steps", "4"});
}
TEST_F(SurfaceCli, TeapotWireMatchesGolden) {
    expect_golden("teapot_wire", {"--patch", data("teapot.json"), "--mode", "wire"});
}
TEST_F(SurfaceCli, SaddleWireOrthoMatchesGolden) {
    expect_golden("saddle_wire", {"--patch", data("saddle.json"), "--mode", "wire", "--projection",
                                  "ortho", "--view", "20,30", "--iso-lines", "7"});
}
TEST_F(SurfaceCli, BSplineGridAndHermiteSolidMatchGolden) {
    expect_golden("bspline_solid", {"--patch", data("bspline.json"), "--view", "200,40"});
    expect_golden("hermite_solid", {"--patch", data("hermite.json"), "--eye", "6,-5,4",
                                    "--target", "2,1,0"});
}

// The camera in the mouth of the teapot's spout: the spout around it crosses the near plane and
// is cut there (no spikes from points just in front of the eye), and the view keeps its field of
// view rather than fitting a surface that surrounds the eye.
TEST_F(SurfaceCli, CameraInTheSpoutSeesItClippedAtTheNearPlane) {
    const std::vector<std::string> camera = {"--patch", data("teapot.json"), "--eye", "3.1,0,2.25",
                                             "--target", "-2,0,0.8"};
    expect_golden("teapot_spout_solid", camera);
    std::vector<std::string> wire = camera;
    wire.insert(wire.end(), {"--mode", "wire"});
    expect_golden("teapot_spout_wire", wire);
}

TEST_F(SurfaceCli, MeshFormatsHaveTheRightCounts) {
    // 32 patches × 2·3² triangles with --steps 3, 16 vertices each.
    CliRun obj = run({"--patch", data("teapot.json"), "--steps", "3", "-O", "obj"});
    ASSERT_EQ(obj.exit_code, 0) << obj.err;
    std::size_t v = 0, vn = 0, f = 0;
    std::size_t pos = 0;
    while (pos < obj.out.size()) {
        std::size_t end = obj.out.find('\n', pos);
        std::string line = obj.out.substr(pos, end - pos);
        v += line.rfind("v ", 0) == 0, vn += line.rfind("vn ", 0) == 0, f += line.rfind("f ", 0) == 0;
        pos = end == std::string::npos ? obj.out.size() : end + 1;
    }
    EXPECT_EQ(v, 32u * 16);
    EXPECT_EQ(vn, 32u * 16);
    EXPECT_EQ(f, 32u * 18);

    const std::string stl = (scratch().path() / "t.stl").string();
    CliRun bin = run({"--patch", data("teapot.json"), "--steps", "3", "-o", stl});
    ASSERT_EQ(bin.exit_code, 0) << bin.err;
    std::string bytes = bezel::test::slurp(stl);
    ASSERT_EQ(bytes.size(), 84u + 50u * 32 * 18);
    std::uint32_t count;
    std::memcpy(&count, bytes.data() + 80, 4);
    EXPECT_EQ(count, 32u * 18);

    CliRun ascii = run({"--patch", data("saddle.json"), "--steps", "2", "-O", "stl-ascii"});
    ASSERT_EQ(ascii.exit_code, 0) << ascii.err;
    EXPECT_EQ(ascii.out.rfind("solid bezel\n", 0), 0u);
}

TEST_F(SurfaceCli, ErrorsNameTheirInput) {
    struct Case {
        std::string file_text;  // written to a scratch file and passed as --patch
        std::vector<std::string> extra;
        int code;
        std::string says;
    };
    const std::string pt = "[0,0,0]";
    std::string fifteen = pt;
    for (int k = 1; k < 15; ++k) fifteen += "," + pt;
    const Case cases[] = {
        {"{\"patches\": [[", {}, 1, "not valid JSON"},
        {"[1,2]", {}, 1, "JSON object"},
        {"{\"patches\": [[" + fifteen + "]]}", {}, 1, "patches[0] has 15 points"},
        {"{\"patches\": [[" + fifteen + ",[0,\"a\",0]]]}", {}, 1, "patches[0][15]"},
        // JSON has no NaN or infinity; an overflowing number is refused by the parser.
        {"{\"patches\": [[" + fifteen + ",[0,1e999,0]]]}", {}, 1, "not valid JSON"},
        {"{\"basis\": \"nurbs\", \"patches\": []}", {}, 1, "\"basis\""},
        {"{\"patches\": []}", {}, 1, "no patches"},
        {"{\"basis\": \"bezier\", \"patches\": [[" + fifteen + "," + pt + "]]}", {"--basis", "hermite"}, 1,
         "not --basis hermite"},
        {"{\"basis\": \"bezier\", \"grid\": [[" + pt + "]]}", {}, 1, "needs basis bspline"},
        {"{\"basis\": \"bspline\", \"grid\": [[" + pt + "," + pt + "]]}", {}, 1, "grid 1x2"},
        {"{\"patches\": [[" + fifteen + "," + pt + "]]}", {"--size", "100000x10"}, 2, "--size"},
        {"{\"patches\": [[" + fifteen + "," + pt + "]]}", {"--size", "0x10"}, 2, "--size"},
        {"{\"patches\": [[" + fifteen + "," + pt + "]]}", {"--view", "10,100"}, 2, "--view"},
        {"{\"patches\": [[" + fifteen + "," + pt + "]]}", {"--eye", "1,nan,2"}, 2, "--eye"},
        {"{\"patches\": [[" + fifteen + "," + pt + "]]}", {"-o", "x.gif"}, 2, "x.gif"},
    };
    int k = 0;
    for (const Case& c : cases) {
        std::string file = write_scratch("case" + std::to_string(k++) + ".json", c.file_text);
        std::vector<std::string> args = {"--patch", file};
        args.insert(args.end(), c.extra.begin(), c.extra.end());
        if (std::find(args.begin(), args.end(), "-o") == args.end()) args.insert(args.end(), {"-O", "png"});
        CliRun r = run(args);
        EXPECT_EQ(r.exit_code, c.code) << c.file_text << "\n" << r.err;
        EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
        EXPECT_EQ(r.err.rfind("bezel: ", 0), 0u) << r.err;
    }
    CliRun missing = run({"--patch", "no-such-file.json"});
    EXPECT_EQ(missing.exit_code, 1);
    EXPECT_NE(missing.err.find("no-such-file.json"), std::string::npos);
    // A tolerance that needs more grid steps than the limit is refused, not attempted.
    CliRun tiny = run({"--patch", data("teapot.json"), "--tolerance", "1e-9", "-O", "obj"});
    EXPECT_EQ(tiny.exit_code, 1);
    EXPECT_NE(tiny.err.find("steps"), std::string::npos) << tiny.err;
}

}  // namespace
