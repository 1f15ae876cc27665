// `bezel info` end to end: the JSON contract against the library's own Font, the text form,
// variable fonts and collections, and error exits. Runs the built CLI binary.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "bezel/font.hpp"
#include "support/cli_run.hpp"

namespace {

using bezel::test::CliRun;
using nlohmann::json;

const std::string kFonts = BEZEL_FONTS_DIR;
const std::string kDejaVu = kFonts + "/dejavu-sans/DejaVuSans.ttf";

bezel::test::TempDir& scratch() {
    static bezel::test::TempDir dir("bezel-info-cli");
    return dir;
}

CliRun run(const std::vector<std::string>& args) {
    return bezel::test::run_bezel(args, scratch().path());
}

json run_json(const std::vector<std::string>& args) {
    CliRun r = run(args);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return json::parse(r.out);
}

std::set<std::string> tags_of(const json& list, const char* key) {
    std::set<std::string> out;
    for (const json& item : list)
        out.insert(key ? item.at(key).get<std::string>() : item.get<std::string>());
    return out;
}

class InfoCli : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(std::filesystem::exists(bezel::test::cli_path())) << bezel::test::cli_path();
    }
};

}  // namespace

TEST_F(InfoCli, JsonMatchesTheFontThroughTheLibrary) {
    const json j = run_json({"info", kDejaVu, "-O", "json"});
    auto font = bezel::Font::open(kDejaVu);
    ASSERT_TRUE(font.ok());
    const bezel::FontMetrics m = font->metrics();
    EXPECT_EQ(j.at("file"), kDejaVu);
    EXPECT_EQ(j.at("face_index"), 0);
    EXPECT_EQ(j.at("face_count"), 1);
    EXPECT_EQ(j.at("family"), "DejaVu Sans");
    EXPECT_EQ(j.at("style"), "Book");
    EXPECT_EQ(j.at("postscript_name"), "DejaVuSans");
    EXPECT_EQ(j.at("version"), "Version 2.37");
    EXPECT_EQ(j.at("glyph_count"), font->glyph_count());
    EXPECT_EQ(j.at("units_per_em"), 2048);
    EXPECT_EQ(j.at("ascender").get<double>(), m.ascender);
    EXPECT_EQ(j.at("descender").get<double>(), m.descender);
    EXPECT_EQ(j.at("line_gap").get<double>(), m.line_gap);
    EXPECT_EQ(j.at("outline_format"), "TrueType");
    EXPECT_TRUE(j.at("axes").empty());
    EXPECT_TRUE(j.at("named_instances").empty());
    // The table directory: the required TrueType tables, and 'head' is always 54 bytes.
    const auto tables = tags_of(j.at("tables"), "tag");
    for (const char* t : {"cmap", "glyf", "head", "hhea", "hmtx", "loca", "maxp", "name", "post",
                          "GPOS", "GSUB"})
        EXPECT_EQ(tables.count(t), 1u) << t;
    for (const json& t : j.at("tables")) {
        if (t.at("tag") == "head") {
            EXPECT_EQ(t.at("length"), 54);
        }
    }
    // DejaVu Sans covers Latin, Greek, Cyrillic, Hebrew and Arabic, not Devanagari or Han.
    const auto scripts = tags_of(j.at("scripts"), nullptr);
    for (const char* s : {"Latn", "Grek", "Cyrl", "Hebr", "Arab"})
        EXPECT_EQ(scripts.count(s), 1u) << s;
    EXPECT_EQ(scripts.count("Deva"), 0u);
    EXPECT_EQ(scripts.count("Hani"), 0u);
    // Keys in the documented order: the contract is stable.
    const auto ordered = nlohmann::ordered_json::parse(run({"info", kDejaVu, "-O", "json"}).out);
    std::vector<std::string> keys;
    for (auto it = ordered.begin(); it != ordered.end(); ++it) keys.push_back(it.key());
    EXPECT_EQ(keys, (std::vector<std::string>{
                        "file", "face_index", "face_count", "family", "style", "postscript_name",
                        "version", "glyph_count", "units_per_em", "outline_format", "ascender",
                        "descender", "line_gap", "axes", "named_instances", "tables", "scripts",
                        "color"}));
}

TEST_F(InfoCli, VariableFaceOfACollectionListsAxesAndInstances) {
    const json j =
        run_json({"info", kFonts + "/edge-cases/EdgeCases.ttc", "--face-index", "1", "-O", "json"});
    EXPECT_EQ(j.at("face_index"), 1);
    EXPECT_EQ(j.at("face_count"), 2);
    EXPECT_EQ(j.at("family"), "Bezel Variable");
    ASSERT_EQ(j.at("axes").size(), 1u);
    const json& wght = j.at("axes")[0];
    EXPECT_EQ(wght.at("tag"), "wght");
    EXPECT_EQ(wght.at("name"), "Weight");
    EXPECT_EQ(wght.at("min"), 100);
    EXPECT_EQ(wght.at("default"), 400);
    EXPECT_EQ(wght.at("max"), 900);
    ASSERT_EQ(j.at("named_instances").size(), 2u);
    EXPECT_EQ(j.at("named_instances")[0].at("name"), "Regular");
    EXPECT_EQ(j.at("named_instances")[0].at("coordinates").at("wght"), 400);
    EXPECT_EQ(j.at("named_instances")[1].at("name"), "Black");
    EXPECT_EQ(j.at("named_instances")[1].at("coordinates").at("wght"), 900);
    EXPECT_EQ(tags_of(j.at("tables"), "tag").count("fvar"), 1u);
}

TEST_F(InfoCli, OutlineFormatAndScriptsOfOtherFonts) {
    const json cff = run_json({"info", kFonts + "/cantarell/Cantarell-Regular.otf", "-O", "json"});
    EXPECT_EQ(cff.at("outline_format"), "CFF");
    const json deva = run_json(
        {"info", kFonts + "/noto-devanagari/NotoSansDevanagari-Regular.ttf", "-O", "json"});
    const auto scripts = tags_of(deva.at("scripts"), nullptr);
    EXPECT_EQ(scripts.count("Deva"), 1u);
    EXPECT_EQ(scripts.count("Arab"), 0u);
}

TEST_F(InfoCli, TextFormIsTheDefaultAndListsTheTables) {
    CliRun r = run({"info"});   // the bundled DejaVu Sans
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("family       DejaVu Sans\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("units/em     2048\n"), std::string::npos);
    EXPECT_NE(r.out.find("outlines     TrueType\n"), std::string::npos);
    EXPECT_NE(r.out.find("'head'         54 bytes\n"), std::string::npos);
    EXPECT_NE(r.out.find("scripts      Latn Grek Cyrl"), std::string::npos);
    EXPECT_TRUE(r.err.empty()) << r.err;
}

TEST_F(InfoCli, OutputFileFormatFollowsTheExtension) {
    CliRun r = run({"info", kDejaVu, "-o", "info.json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(r.out.empty());
    const json j = json::parse(bezel::test::slurp(scratch().path() / "info.json"));
    EXPECT_EQ(j.at("family"), "DejaVu Sans");
    std::filesystem::remove(scratch().path() / "info.json");
}

TEST_F(InfoCli, ErrorsAreOneLineWithTheRightExitCode) {
    const std::string missing = kFonts + "/missing.ttf";
    CliRun r = run({"info", missing});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "bezel: " + missing +
                         ": no such font file (to use these words as text, give them with "
                         "--coverage)\n");
    EXPECT_TRUE(r.out.empty());

    r = run({"info", kFonts + "/edge-cases/EdgeCases.ttc", "--face-index", "5"});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("face index"), std::string::npos) << r.err;

    r = run({"info", kFonts + "/dejavu-sans/README.md"});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err.rfind("bezel: " + kFonts + "/dejavu-sans/README.md: ", 0), 0u) << r.err;

    r = run({"info", kDejaVu, "-o", "x.svg"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.err.rfind("bezel: x.svg: bezel info writes text or JSON, not SVG\n", 0), 0u)
        << r.err;
    EXPECT_EQ(run({"info", kDejaVu, "-O", "svg"}).exit_code, 2);
    EXPECT_EQ(run({"info", kDejaVu, "--font-size", "12"}).exit_code, 2);
    EXPECT_EQ(run({"info", kDejaVu, "--face-index", "-1"}).exit_code, 2);
    EXPECT_TRUE(scratch().entries().empty());
}
