// `bezel bench` end to end, for shape only (speed is never asserted in tests): the JSON rows,
// the ratio's definition, reading a saved result back, and usage errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/cli_run.hpp"

namespace {

using bezel::test::CliRun;

const std::string kEdge = std::string(BEZEL_FONTS_DIR) + "/edge-cases/EdgeCases.ttf";

bezel::test::TempDir& scratch() {
    static bezel::test::TempDir dir("bezel-bench-cli");
    return dir;
}
CliRun run(std::vector<std::string> args) {
    args.insert(args.begin(), "bench");
    return bezel::test::run_bezel(args, scratch().path());
}

}  // namespace

TEST(BenchCli, JsonRowsHaveTheContractAndReadBack) {
    ASSERT_TRUE(std::filesystem::exists(bezel::test::cli_path()));
    CliRun r = run({"--font", kEdge, "--sizes", "12,20", "--repeat", "1", "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json doc = nlohmann::json::parse(r.out);
    ASSERT_TRUE(doc.is_array());
    ASSERT_EQ(doc.size(), 2u);
    EXPECT_EQ(doc[0]["size"], 12.0);
    EXPECT_EQ(doc[1]["size"], 20.0);
    for (const auto& row : doc) {
        // EdgeCases.ttf: .notdef, A, B, C, O and period have outlines; the space does not.
        EXPECT_EQ(row["glyphs"], 6);
        EXPECT_GT(row["bezel_ns"].get<double>(), 0.0);
        EXPECT_GT(row["freetype_ns"].get<double>(), 0.0);
        EXPECT_NEAR(row["ratio"].get<double>(),
                    row["freetype_ns"].get<double>() / row["bezel_ns"].get<double>(),
                    1e-9 * row["ratio"].get<double>());
    }
    // --read prints a saved result: as the same JSON, or as the table.
    const std::string saved = (scratch().path() / "run.json").string();
    {
        std::ofstream(saved) << r.out;
    }
    CliRun back = run({"--read", saved, "--json"});
    ASSERT_EQ(back.exit_code, 0) << back.err;
    EXPECT_EQ(nlohmann::json::parse(back.out), doc);
    CliRun table = run({"--read", saved});
    ASSERT_EQ(table.exit_code, 0) << table.err;
    EXPECT_NE(table.out.find("ratio"), std::string::npos);
}

TEST(BenchCli, TextTableHasOneLinePerSize) {
    CliRun r = run({"--font", kEdge, "--sizes", "9", "--repeat", "1"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("freetype ns"), std::string::npos);
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 3);  // title, header, one size
}

TEST(BenchCli, ErrorsNameTheirInput) {
    struct Case {
        std::vector<std::string> args;
        int code;
        std::string says;
    };
    const std::string bad = (scratch().path() / "bad.json").string();
    {
        std::ofstream(bad) << "[{\"size\": 12}]";
    }
    const Case cases[] = {
        {{"--sizes", "0"}, 2, "--sizes"},
        {{"--sizes", "12,abc"}, 2, "'abc'"},
        {{"--sizes", "99999"}, 2, "--sizes"},
        {{"--repeat", "0"}, 2, "--repeat"},
        {{"--font", "no-such.ttf", "--sizes", "12"}, 1, "no-such.ttf"},
        {{"--read", bad}, 1, "bezel_ns"},
        {{"--read", "missing.json"}, 1, "missing.json"},
    };
    for (const Case& c : cases) {
        CliRun r = run(c.args);
        EXPECT_EQ(r.exit_code, c.code) << c.args.back() << ": " << r.err;
        EXPECT_EQ(r.err.rfind("bezel: ", 0), 0u) << r.err;
        EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
    }
}
