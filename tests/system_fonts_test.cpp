// System fonts through fontconfig (bezel/system_fonts.hpp). Every test but the last loads a
// configuration written here whose <dir>s are the repository's fonts-test folders and whose
// <cachedir> is private, so results do not depend on the machine's fonts; the last opens the
// machine's own configuration and checks only that what it finds opens.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

#include "bezel/font.hpp"
#include "bezel/system_fonts.hpp"

namespace fs = std::filesystem;

namespace bezel {
namespace {

const std::string kFonts = BEZEL_FONTS_DIR;
const std::vector<std::string> kScriptFolders = {"dejavu-sans",     "cantarell",
                                                 "noto-arabic",     "noto-hebrew",
                                                 "noto-devanagari", "noto-color-emoji"};

// A temporary folder holding a fonts.conf that lists `folders` of fonts-test/ and a private cache.
class TestConfig {
public:
    explicit TestConfig(const std::vector<std::string>& folders, const std::string& extra = "") {
        static int serial = 0;
        dir_ = fs::temp_directory_path() /
               ("bezel-fc-" + std::to_string(::getpid()) + "-" + std::to_string(serial++));
        fs::create_directories(dir_);
        std::ofstream out(file());
        out << "<?xml version=\"1.0\"?>\n<!DOCTYPE fontconfig SYSTEM \"urn:fontconfig:fonts.dtd\">\n"
            << "<fontconfig>\n";
        for (const std::string& f : folders) out << "  <dir>" << kFonts << "/" << f << "</dir>\n";
        out << "  <cachedir>" << (dir_ / "cache").string() << "</cachedir>\n" << extra
            << "</fontconfig>\n";
    }
    TestConfig(const TestConfig&) = delete;
    TestConfig& operator=(const TestConfig&) = delete;
    ~TestConfig() {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }
    std::string file() const { return (dir_ / "fonts.conf").string(); }

private:
    fs::path dir_;
};

SystemFonts open_config(const TestConfig& config) {
    auto fonts = SystemFonts::open({config.file()});
    EXPECT_TRUE(fonts.ok()) << (fonts.ok() ? "" : fonts.error().message);
    return std::move(fonts).value();
}

// The fonts-test file a source names, as "folder/file", for readable expectations.
std::string short_name(const FontSource& s) {
    const fs::path p(s.file);
    return p.parent_path().filename().string() + "/" + p.filename().string();
}

std::string fallback_name(SystemFonts& fonts, const FallbackQuery& q) {
    auto r = fonts.fallback(q);
    if (!r.ok()) return "error: " + r.error().message;
    return r->has_value() ? short_name(**r) : "none";
}

// One fixture: the six script fonts, opened once per test.
class SystemFontsTest : public ::testing::Test {
protected:
    TestConfig config{kScriptFolders};
    SystemFonts fonts = open_config(config);
};

TEST_F(SystemFontsTest, IndexesEveryFontOfTheConfiguredFolders) {
    EXPECT_EQ(fonts.font_count(), kScriptFolders.size());
    EXPECT_NE(fonts.configuration().find(config.file()), std::string::npos);
}

TEST_F(SystemFontsTest, MatchFindsAFamilyByName) {
    auto dejavu = fonts.match("DejaVu Sans");
    ASSERT_TRUE(dejavu.ok()) << dejavu.error().message;
    EXPECT_EQ(dejavu->file, kFonts + "/dejavu-sans/DejaVuSans.ttf");
    EXPECT_EQ(dejavu->face_index, 0);
    EXPECT_TRUE(dejavu->variations.empty());

    auto cantarell = fonts.match("Cantarell:style=Regular");
    ASSERT_TRUE(cantarell.ok()) << cantarell.error().message;
    EXPECT_EQ(short_name(*cantarell), "cantarell/Cantarell-Regular.otf");
    // What match gives opens as the family asked for.
    auto font = Font::open(cantarell->file, cantarell->face_index);
    ASSERT_TRUE(font.ok());
    EXPECT_EQ(font->family_name(), "Cantarell");
}

TEST_F(SystemFontsTest, MatchHonoursTheLanguageOfThePattern) {
    // No family: the language decides (as fc-match ":lang=hi" does).
    auto hindi = fonts.match(":lang=hi");
    ASSERT_TRUE(hindi.ok()) << hindi.error().message;
    EXPECT_EQ(short_name(*hindi), "noto-devanagari/NotoSansDevanagari-Regular.ttf");
}

TEST_F(SystemFontsTest, PatternThatDoesNotParseIsAnErrorNamingIt) {
    struct Case {
        std::string pattern, says;
    };
    for (const Case& c : std::vector<Case>{
             {"DejaVu Sans:size=abc", "'size=abc' is not a value 'size' can take"},
             {":weight=[1 x]", "is not a value 'weight' can take"},
             {"DejaVu Sans:colour=1", "unknown property 'colour'"},
             {"DejaVu Sans:blod", "unknown style word 'blod'"},
         }) {
        auto r = fonts.match(c.pattern);
        ASSERT_FALSE(r.ok()) << c.pattern;
        const std::string& m = r.error().message;
        EXPECT_NE(m.find("font pattern '" + c.pattern + "'"), std::string::npos) << m;
        EXPECT_NE(m.find(c.says), std::string::npos) << m;
        EXPECT_EQ(m.find('\n'), std::string::npos) << m;
        // The fallback query reports the same.
        auto f = fonts.fallback({c.pattern, U"a"});
        ASSERT_FALSE(f.ok());
        EXPECT_NE(f.error().message.find(c.says), std::string::npos) << f.error().message;
    }
    // Escaped separators, style words and several values are fontconfig's syntax, not errors.
    for (const char* ok : {"DejaVu\\:Sans", "DejaVu Sans:bold:italic", "DejaVu Sans:weight=bold,light",
                           "DejaVu Sans-12:oblique", "", "monospace"}) {
        EXPECT_TRUE(fonts.match(ok).ok()) << ok;
    }
}

TEST_F(SystemFontsTest, RandomPatternsGiveAFontOrAOneLineError) {
    // Pieces of fontconfig's syntax in random order, fixed seed: every pattern either matches or
    // is refused with one line naming it, and fallback agrees with match on which.
    const std::vector<std::string> pieces = {"DejaVu Sans", "Cantarell", ":", "=", "_", ",", "-", "\\",
                                             "weight", "bold", "size", "12", "abc", "lang", "ar",
                                             "style", "Oblique", "[1 2]", "slant", "colour", "x"};
    std::mt19937 rng(35);
    std::size_t matched = 0, refused = 0;
    for (int i = 0; i < 500; ++i) {
        std::string pattern;
        const int n = 1 + static_cast<int>(rng() % 8);
        for (int k = 0; k < n; ++k) pattern += pieces[rng() % pieces.size()];
        auto m = fonts.match(pattern);
        auto f = fonts.fallback({pattern, U"a"});
        ASSERT_EQ(m.ok(), f.ok()) << pattern;
        if (m.ok()) {
            ++matched;
            EXPECT_FALSE(m->file.empty()) << pattern;
            continue;
        }
        ++refused;
        const std::string& e = m.error().message;
        EXPECT_EQ(e.rfind("font pattern '" + pattern + "': ", 0), 0u) << e;
        EXPECT_EQ(e.find('\n'), std::string::npos) << e;
    }
    // Both outcomes occur, so the sweep tests something.
    EXPECT_GT(matched, 50u);
    EXPECT_GT(refused, 50u);
    EXPECT_LE(fonts.stats().lists, kMaxSystemFontLists);
}

TEST_F(SystemFontsTest, FallbackFindsTheOnlyFontCoveringACluster) {
    // U+06C1 ARABIC LETTER HEH GOAL: only Noto Sans Arabic has it (DejaVu Sans's Arabic does not).
    EXPECT_EQ(fallback_name(fonts, {"Cantarell", U"\u06C1"}),
              "noto-arabic/NotoSansArabic-Regular.ttf");
    // Devanagari KA + VIRAMA + SSA (a conjunct, one cluster).
    EXPECT_EQ(fallback_name(fonts, {"Cantarell", U"\u0915\u094D\u0937"}),
              "noto-devanagari/NotoSansDevanagari-Regular.ttf");
    EXPECT_EQ(fallback_name(fonts, {"", U"\U0001F600"}), "dejavu-sans/DejaVuSans.ttf");
}

TEST_F(SystemFontsTest, FallbackForAClusterNoFontCoversIsNothing) {
    EXPECT_EQ(fallback_name(fonts, {"Cantarell", U"\u4E00"}), "none");  // CJK: no CJK font here
    // Each font covers part of the cluster but none all of it: Noto Sans Arabic lacks the
    // combining acute U+0301, DejaVu Sans lacks U+06C1.
    EXPECT_EQ(fallback_name(fonts, {"Cantarell", U"\u06C1\u0301"}), "none");
    EXPECT_EQ(fallback_name(fonts, {"Cantarell", std::u32string_view(U"\U0010FFFF")}), "none");
}

TEST_F(SystemFontsTest, DefaultIgnorablesDoNotBlockCoverage) {
    // Noto Sans Arabic lacks VS1 (U+FE00), which DejaVu Sans has; DejaVu lacks the letter.
    EXPECT_EQ(fallback_name(fonts, {"Cantarell", U"\u06C1\uFE00"}),
              "noto-arabic/NotoSansArabic-Regular.ttf");
    EXPECT_EQ(fallback_name(fonts, {"Cantarell", U"\u200D\u06C1\u200C\U000E0001\U000E0100"}),
              "noto-arabic/NotoSansArabic-Regular.ttf");
    // The colour emoji font has U+1F600 but not VS16.
    FallbackQuery emoji{"", U"\U0001F600\uFE0F"};
    emoji.prefer_colour = true;
    EXPECT_EQ(fallback_name(fonts, emoji), "noto-color-emoji/NotoColorEmoji-subset.ttf");
}

TEST_F(SystemFontsTest, ThePrimaryPatternOrdersTheFallback) {
    // Both DejaVu Sans and Noto Sans Arabic have BEH U+0628: the primary family comes first.
    EXPECT_EQ(fallback_name(fonts, {"DejaVu Sans", U"\u0628"}), "dejavu-sans/DejaVuSans.ttf");
    EXPECT_EQ(fallback_name(fonts, {"Noto Sans Arabic", U"\u0628"}),
              "noto-arabic/NotoSansArabic-Regular.ttf");
    // Both DejaVu Sans and Noto Sans Hebrew have ALEF U+05D0.
    EXPECT_EQ(fallback_name(fonts, {"Noto Sans Hebrew", U"\u05D0"}),
              "noto-hebrew/NotoSansHebrew-Regular.ttf");
    EXPECT_EQ(fallback_name(fonts, {"DejaVu Sans", U"\u05D0"}), "dejavu-sans/DejaVuSans.ttf");
}

TEST_F(SystemFontsTest, ColourPreferenceAndOutlineRequirement) {
    FallbackQuery q{"DejaVu Sans", U"\U0001F600"};
    EXPECT_EQ(fallback_name(fonts, q), "dejavu-sans/DejaVuSans.ttf");
    q.prefer_colour = true;
    EXPECT_EQ(fallback_name(fonts, q), "noto-color-emoji/NotoColorEmoji-subset.ttf");
    // The colour font is bitmap-only (CBDT): excluded when outlines are required.
    q.require_outlines = true;
    EXPECT_EQ(fallback_name(fonts, q), "dejavu-sans/DejaVuSans.ttf");
}

TEST_F(SystemFontsTest, RepeatQueriesAreAnsweredFromTheCachedSort) {
    EXPECT_EQ(fonts.stats().sorts, 0u);
    ASSERT_EQ(fallback_name(fonts, {"Cantarell", U"\u06C1"}), "noto-arabic/NotoSansArabic-Regular.ttf");
    EXPECT_EQ(fonts.stats().sorts, 1u);
    // Other clusters, the same pattern: no new sort.
    for (int i = 0; i < 100; ++i) {
        ASSERT_EQ(fallback_name(fonts, {"Cantarell", U"\u0915\u094D\u0937"}),
                  "noto-devanagari/NotoSansDevanagari-Regular.ttf");
        ASSERT_EQ(fallback_name(fonts, {"Cantarell", U"\u4E00"}), "none");
    }
    EXPECT_EQ(fonts.stats().sorts, 1u);
    EXPECT_EQ(fonts.stats().fallback_queries, 201u);
    // Each pattern, and each colour or outline flag, is a list of its own.
    FallbackQuery colour{"Cantarell", U"\u06C1"};
    colour.prefer_colour = true;
    ASSERT_TRUE(fonts.fallback(colour).ok());
    ASSERT_TRUE(fonts.fallback({"DejaVu Sans", U"\u06C1"}).ok());
    ASSERT_TRUE(fonts.fallback({"Cantarell", U"x"}).ok());
    EXPECT_EQ(fonts.stats().sorts, 3u);
    EXPECT_EQ(fonts.stats().lists, 3u);
}

TEST_F(SystemFontsTest, ListCacheStaysWithinkMaxSystemFontLists) {
    for (std::size_t i = 0; i <= kMaxSystemFontLists; ++i) {
        ASSERT_TRUE(fonts.fallback({"DejaVu Sans:size=" + std::to_string(i + 1), U"a"}).ok());
    }
    SystemFontsStats s = fonts.stats();
    EXPECT_EQ(s.sorts, kMaxSystemFontLists + 1);
    EXPECT_EQ(s.lists, kMaxSystemFontLists);
    EXPECT_EQ(s.evictions, 1u);
    // The most recent list is still there; the first one was dropped and is sorted again.
    ASSERT_TRUE(fonts.fallback({"DejaVu Sans:size=" + std::to_string(kMaxSystemFontLists + 1), U"a"}).ok());
    EXPECT_EQ(fonts.stats().sorts, kMaxSystemFontLists + 1);
    ASSERT_TRUE(fonts.fallback({"DejaVu Sans:size=1", U"a"}).ok());
    EXPECT_EQ(fonts.stats().sorts, kMaxSystemFontLists + 2);
    EXPECT_EQ(fonts.stats().lists, kMaxSystemFontLists);
}

TEST_F(SystemFontsTest, MovedObjectKeepsItsConfigurationAndCache) {
    ASSERT_TRUE(fonts.fallback({"Cantarell", U"\u06C1"}).ok());
    SystemFonts moved = std::move(fonts);
    EXPECT_EQ(moved.font_count(), kScriptFolders.size());
    EXPECT_EQ(fallback_name(moved, {"Cantarell", U"\u06C1"}), "noto-arabic/NotoSansArabic-Regular.ttf");
    EXPECT_EQ(moved.stats().sorts, 1u);
}

TEST(SystemFonts, NamedInstanceOpensAsItsDesignCoordinates) {
    // EdgeCasesVariable.ttf: one axis, wght 100..400..900, named instances Regular (400) and
    // Black (900); fontconfig lists Black as index 2 << 16. EdgeCases.ttc holds it as face 1.
    TestConfig config({"edge-cases"});
    SystemFonts fonts = open_config(config);
    auto black = fonts.match("Bezel Variable:style=Black");
    ASSERT_TRUE(black.ok()) << black.error().message;
    const bool collection = fs::path(black->file).extension() == ".ttc";
    EXPECT_EQ(black->face_index, collection ? 1 : 0) << black->file;
    ASSERT_EQ(black->variations.size(), 1u);
    EXPECT_EQ(black->variations[0].tag, "wght");
    EXPECT_EQ(black->variations[0].value, 900.0);
    auto font = Font::open(black->file, black->face_index);
    ASSERT_TRUE(font.ok());
    EXPECT_EQ(font->family_name(), "Bezel Variable");
    EXPECT_TRUE(font->set_variations(black->variations).ok());

    // The variable font itself at a weight fontconfig maps into the axis: coordinates between
    // Regular and Black, as FcFontRenderPrepare computes them.
    auto semibold = fonts.match("Bezel Variable:variable=true:weight=150");
    ASSERT_TRUE(semibold.ok()) << semibold.error().message;
    ASSERT_EQ(semibold->variations.size(), 1u);
    EXPECT_EQ(semibold->variations[0].tag, "wght");
    EXPECT_GT(semibold->variations[0].value, 400.0);
    EXPECT_LT(semibold->variations[0].value, 900.0);
    // Variations written in the pattern reach the source.
    auto light = fonts.match("Bezel Variable:fontvariations=wght=300");
    ASSERT_TRUE(light.ok()) << light.error().message;
    ASSERT_EQ(light->variations.size(), 1u);
    EXPECT_EQ(light->variations[0].value, 300.0);
}

TEST(SystemFonts, BareEnvironmentOpensEmptyAndFindsNothing) {
    TestConfig config({});
    auto fonts = SystemFonts::open({config.file()});
    ASSERT_TRUE(fonts.ok()) << fonts.error().message;
    EXPECT_EQ(fonts->font_count(), 0u);
    auto m = fonts->match("DejaVu Sans");
    ASSERT_FALSE(m.ok());
    EXPECT_NE(m.error().message.find("font pattern 'DejaVu Sans': no font matches"),
              std::string::npos) << m.error().message;
    EXPECT_NE(m.error().message.find("lists no fonts"), std::string::npos) << m.error().message;
    auto f = fonts->fallback({"DejaVu Sans", U"a"});
    ASSERT_TRUE(f.ok()) << f.error().message;
    EXPECT_FALSE(f->has_value());
    FallbackQuery colour{"", U"\U0001F600"};
    colour.prefer_colour = true;
    colour.require_outlines = true;
    ASSERT_TRUE(fonts->fallback(colour).ok());
}

TEST(SystemFonts, DefaultConfigurationHonoursFontconfigFile) {
    // The system configuration is fontconfig's usual one: FONTCONFIG_FILE, when set, names it.
    TestConfig config({"cantarell"});
    const char* old = std::getenv("FONTCONFIG_FILE");
    const std::string saved = old != nullptr ? old : "";
    ::setenv("FONTCONFIG_FILE", config.file().c_str(), 1);
    auto fonts = SystemFonts::open();
    if (old != nullptr) ::setenv("FONTCONFIG_FILE", saved.c_str(), 1);
    else ::unsetenv("FONTCONFIG_FILE");
    ASSERT_TRUE(fonts.ok()) << fonts.error().message;
    EXPECT_EQ(fonts->font_count(), 1u);
    auto m = fonts->match("sans-serif");
    ASSERT_TRUE(m.ok()) << m.error().message;
    EXPECT_EQ(short_name(*m), "cantarell/Cantarell-Regular.otf");
}

TEST(SystemFonts, ConfigurationFileThatCannotBeLoadedIsAnErrorNamingIt) {
    auto missing = SystemFonts::open({"/nonexistent/bezel/fonts.conf"});
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().message,
              "/nonexistent/bezel/fonts.conf: no such fontconfig configuration file");
    // Not XML: fontconfig rejects it (and prints its parser's reason on stderr).
    const fs::path bad = fs::temp_directory_path() / ("bezel-fc-bad-" + std::to_string(::getpid()) + ".conf");
    std::ofstream(bad) << "<fontconfig><dir>unclosed</fontconfig>\n";
    auto broken = SystemFonts::open({bad.string()});
    fs::remove(bad);
    ASSERT_FALSE(broken.ok());
    EXPECT_NE(broken.error().message.find(bad.string() + ": fontconfig cannot load"),
              std::string::npos) << broken.error().message;
}

TEST(SystemFonts, SeparateObjectsOnThreadsAnswerAsOneThread) {
    // The threading contract: one SystemFonts per thread, each loading its own configuration.
    TestConfig config(kScriptFolders);
    const std::vector<std::u32string> clusters = {U"\u06C1", U"\u0915\u094D\u0937", U"\u4E00",
                                                  U"a", U"\u05D0", U"\U0001F600\uFE0F"};
    auto answers = [&](std::vector<std::string>& out) {
        auto fonts = SystemFonts::open({config.file()});
        if (!fonts.ok()) {
            out.push_back("error: " + fonts.error().message);
            return;
        }
        for (int round = 0; round < 20; ++round) {
            for (const std::u32string& c : clusters) {
                FallbackQuery q{round % 2 ? "Cantarell" : "Noto Sans Hebrew", c};
                q.prefer_colour = round % 3 == 0;
                out.push_back(fallback_name(*fonts, q));
            }
        }
        auto m = fonts->match("Cantarell");
        out.push_back(m.ok() ? short_name(*m) : m.error().message);
    };
    std::vector<std::string> expected;
    answers(expected);
    std::vector<std::vector<std::string>> got(4);
    std::vector<std::thread> threads;
    for (auto& g : got) threads.emplace_back(answers, std::ref(g));
    for (std::thread& t : threads) t.join();
    for (const auto& g : got) EXPECT_EQ(g, expected);
}

TEST(SystemFonts, DefaultIgnorableIsUnicodesProperty) {
    // DerivedCoreProperties.txt from Debian's unicode-data: every code point agrees.
    std::ifstream in("/usr/share/unicode/DerivedCoreProperties.txt");
    ASSERT_TRUE(in) << "needs Debian's unicode-data (./dev installs it)";
    std::vector<bool> expected(0x110000, false);
    std::string line;
    std::size_t ranges = 0;
    while (std::getline(in, line)) {
        const auto semi = line.find(';');
        if (line.empty() || line[0] == '#' || semi == std::string::npos) continue;
        if (line.find("; Default_Ignorable_Code_Point") == std::string::npos) continue;
        const std::string cps = line.substr(0, line.find(' '));
        const auto dots = cps.find("..");
        const unsigned long first = std::stoul(cps.substr(0, dots), nullptr, 16);
        const unsigned long last =
            dots == std::string::npos ? first : std::stoul(cps.substr(dots + 2), nullptr, 16);
        for (unsigned long c = first; c <= last; ++c) expected[c] = true;
        ++ranges;
    }
    ASSERT_GT(ranges, 10u);
    std::size_t mismatches = 0;
    for (char32_t c = 0; c < 0x110000; ++c) {
        if (is_default_ignorable(c) != expected[c] && mismatches++ < 10) {
            ADD_FAILURE() << "U+" << std::hex << static_cast<unsigned>(c) << ": bezel says "
                          << is_default_ignorable(c);
        }
    }
    EXPECT_EQ(mismatches, 0u);
    EXPECT_FALSE(is_default_ignorable(0x110000));
}

TEST(SystemFonts, SystemConfigurationOpensWhateverItFinds) {
    // The machine's own fonts: none, or fonts that open as fontconfig describes them.
    auto fonts = SystemFonts::open();
    ASSERT_TRUE(fonts.ok()) << fonts.error().message;
    auto m = fonts->match("sans-serif");
    if (fonts->font_count() == 0) {
        ASSERT_FALSE(m.ok());
        return;
    }
    ASSERT_TRUE(m.ok()) << m.error().message;
    auto font = Font::open(m->file, m->face_index);
    ASSERT_TRUE(font.ok()) << font.error().message;
    EXPECT_TRUE(font->set_variations(m->variations).ok());
    auto f = fonts->fallback({"sans-serif", U"a"});
    ASSERT_TRUE(f.ok()) << f.error().message;
    EXPECT_TRUE(f->has_value());
}

}  // namespace
}  // namespace bezel
