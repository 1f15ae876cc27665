// The bad-input catalogue: the CLI fed what an untrusted user or file can give it — truncated,
// corrupted, empty and non-font files as fonts, a directory or a missing file, zero, negative,
// NaN and enormous font sizes, malformed path data, unknown options, unwritable output paths,
// invalid UTF-8 text. Each must give ONE error line (`bezel: …` naming the input; a usage error
// may add the "Run '… --help'" hint line), exit code 1 or 2, and leave no output or temporary
// file behind. Setting BEZEL_CATALOGUE=FILE writes the table of docs/cli.md (input, command,
// exit code, message) from the real runs.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "bezel/text.hpp"
#include "support/cli_run.hpp"

namespace bezel {
namespace {

namespace fs = std::filesystem;
using test::CliRun;
using test::TempDir;

const std::string kDejaVu = std::string(BEZEL_FONTS_DIR) + "/dejavu-sans/DejaVuSans.ttf";

struct BadInput {
    std::string what;                 // the catalogue's "input" column
    std::vector<std::string> args;    // run in a scratch directory holding the bad files
    int exit_code;                    // 1 (runtime) or 2 (usage)
    std::string names;                // the error line must contain this (the input it names)
};

void write_file(const fs::path& file, const std::string& bytes) {
    std::ofstream out(file, std::ios::binary);
    out << bytes;
}

// The bad files, made from DejaVu Sans's own bytes.
void make_bad_files(const fs::path& dir) {
    const std::string font = test::slurp(kDejaVu);
    ASSERT_GT(font.size(), 100000u);
    write_file(dir / "truncated-header.ttf", font.substr(0, 10));
    write_file(dir / "truncated.ttf", font.substr(0, font.size() / 2));
    // Every table record's offset (at 12 + 16·i + 8, big-endian) pointed past the end of the file.
    std::string corrupt = font;
    const int tables = (static_cast<unsigned char>(corrupt[4]) << 8) | static_cast<unsigned char>(corrupt[5]);
    for (int i = 0; i < tables; ++i)
        for (int k = 0; k < 4; ++k) corrupt[12 + 16 * i + 8 + k] = static_cast<char>(0x7F);
    write_file(dir / "corrupt-offsets.ttf", corrupt);
    // The glyf table's bytes overwritten with 0xFF: the file opens, glyph loading fails.
    std::string garbled = font;
    for (int i = 0; i < tables; ++i) {
        const std::size_t rec = 12 + 16 * static_cast<std::size_t>(i);
        if (garbled.compare(rec, 4, "glyf") != 0) continue;
        auto be32 = [&](std::size_t at) {
            return (std::size_t{static_cast<unsigned char>(garbled[at])} << 24) |
                   (std::size_t{static_cast<unsigned char>(garbled[at + 1])} << 16) |
                   (std::size_t{static_cast<unsigned char>(garbled[at + 2])} << 8) |
                   std::size_t{static_cast<unsigned char>(garbled[at + 3])};
        };
        const std::size_t offset = be32(rec + 8), length = be32(rec + 12);
        for (std::size_t k = offset; k < offset + length && k < garbled.size(); ++k) garbled[k] = '\xFF';
    }
    write_file(dir / "garbled-glyf.ttf", garbled);
    write_file(dir / "empty.ttf", "");
    write_file(dir / "text.ttf", "this is not a font\n");
    write_file(dir / "latin1.txt", "a\xE9z\n");  // é in Latin-1: not UTF-8
    // A colour-bitmap-only font (CBDT, no outlines), under the name people know it by.
    write_file(dir / "NotoColorEmoji.ttf",
               test::slurp(std::string(BEZEL_FONTS_DIR) + "/noto-color-emoji/NotoColorEmoji-subset.ttf"));
    // COLR fonts whose paint graphs loop or nest 10,000 deep (tests/data/colour).
    const std::string colour = std::string(BEZEL_SOURCE_DIR) + "/tests/data/colour/";
    write_file(dir / "colr-loop.ttf", test::slurp(colour + "colr_loop.ttf"));
    write_file(dir / "colr-deep.ttf", test::slurp(colour + "colr_deep.ttf"));
    write_file(dir / "colr-bad-palette.ttf", test::slurp(colour + "colr_bad_palette.ttf"));
    fs::create_directory(dir / "a-directory.ttf");
}

std::vector<BadInput> catalogue() {
    return {
        {"truncated font (first 10 bytes)", {"outline", "truncated-header.ttf", "--char", "g", "-o", "out.svg"}, 1, "truncated-header.ttf"},
        {"truncated font (first half)", {"outline", "truncated.ttf", "--char", "g", "-o", "out.svg"}, 1, "truncated.ttf"},
        {"corrupted font (table offsets past the end)", {"outline", "corrupt-offsets.ttf", "--char", "g", "-o", "out.svg"}, 1, "corrupt-offsets.ttf"},
        {"corrupted font (glyf bytes garbled)", {"outline", "garbled-glyf.ttf", "--char", "g", "-o", "out.svg"}, 1, "garbled-glyf.ttf"},
        {"corrupted font, text rendering", {"render", "garbled-glyf.ttf", "--text", "g", "-o", "out.png"}, 1, "garbled-glyf.ttf"},
        {"empty file as a font", {"outline", "empty.ttf", "--char", "g", "-o", "out.svg"}, 1, "empty.ttf"},
        {"text file as a font", {"info", "text.ttf"}, 1, "text.ttf"},
        {"directory as a font", {"outline", "a-directory.ttf", "--char", "g", "-o", "out.svg"}, 1, "a-directory.ttf"},
        {"missing font file", {"outline", "missing.ttf", "--char", "g", "-o", "out.svg"}, 1, "missing.ttf"},
        {"missing font file (render)", {"render", "missing.ttf", "--text", "g", "-o", "out.png"}, 1, "missing.ttf"},
        {"face index out of range", {"outline", kDejaVu, "--face-index", "3", "--char", "g", "-o", "out.svg"}, 1, "face"},
        {"font size 0", {"outline", kDejaVu, "--char", "g", "--font-size", "0", "-o", "out.svg"}, 2, "--font-size: '0'"},
        {"negative font size", {"outline", kDejaVu, "--char", "g", "--font-size", "-12", "-o", "out.svg"}, 2, "--font-size: '-12'"},
        {"NaN font size", {"outline", kDejaVu, "--char", "g", "--font-size", "nan", "-o", "out.svg"}, 2, "--font-size: 'nan'"},
        {"enormous font size", {"outline", kDejaVu, "--char", "g", "--font-size", "1e9", "-o", "out.svg"}, 2, "--font-size: '1e9'"},
        {"font size 0 (glyph)", {"glyph", kDejaVu, "--char", "g", "--font-size", "0", "-o", "out.png"}, 2, "--font-size: '0'"},
        {"enormous font size (render)", {"render", kDejaVu, "--text", "g", "--font-size", "1e300", "-o", "out.png"}, 2, "--font-size: '1e300'"},
        {"font size not a number", {"render", kDejaVu, "--text", "g", "--font-size", "big", "-o", "out.png"}, 2, "--font-size: 'big': not a number"},
        {"NaN font size (atlas)", {"atlas", kDejaVu, "--chars", "ab", "--font-size", "nan", "-o", "out.png"}, 2, "--font-size: 'nan'"},
        {"malformed variations", {"outline", kDejaVu, "--char", "g", "--variations", "wght", "-o", "out.svg"}, 2, "--variations: 'wght': expected TAG=VALUE"},
        {"unknown variation axis", {"outline", kDejaVu, "--char", "g", "--variations", "wght=700", "-o", "out.svg"}, 1, "wght"},
        {"malformed path data", {"intersect", "M0 0 L", "M0 0L1 1", "-o", "out.json"}, 2, "path"},
        {"path data with a letter inside a number", {"continuity", "M0 0 L1x 2"}, 2, "offset"},
        {"path data overflowing a double", {"intersect", "M0 0L1e999 0", "M0 1L1 0"}, 2, "offset"},
        {"unknown option", {"outline", kDejaVu, "--char", "g", "--bogus"}, 2, "--bogus"},
        {"unknown command", {"outlines", kDejaVu}, 2, "outlines"},
        {"stray empty argument (hung CLI11 2.1 before)", {"smooth", "--method", "natural", "--points", "0,0 1,1 2,0", "", "-o", "out.svg"}, 2, "unexpected argument ''"},
        {"empty argument after the stroke path (hung CLI11 2.1 before)", {"stroke", "M0 0 L1 1", "", "--width", "2"}, 2, "unexpected argument ''"},
        {"stroke with neither path nor path file", {"stroke", "--width", "2"}, 2, "PATH or --path-file"},
        {"unknown output format", {"outline", kDejaVu, "--char", "g", "-o", "out.xyz"}, 2, "out.xyz"},
        {"output into a missing directory", {"outline", kDejaVu, "--char", "g", "-o", "no-such-dir/out.svg"}, 1, "no-such-dir/out.svg"},
        // (Permissions do not stop root, which CI may be: /proc refuses new files to everyone.)
        {"output where files cannot be created", {"render", kDejaVu, "--text", "g", "-o", "/proc/out.png"}, 1, "/proc/out.png"},
        {"output under a regular file", {"smooth", "--method", "natural", "--points", "0,0 1,1", "-o", "text.ttf/out.svg"}, 1, "text.ttf/out.svg"},
        {"output onto a directory", {"outline", kDejaVu, "--char", "g", "-O", "svg", "-o", "a-directory.ttf"}, 1, "a-directory.ttf"},
        {"invalid UTF-8 text (lone continuation byte)", {"render", kDejaVu, "--text", "a\x80z", "-o", "out.png"}, 2, "--text: text byte 1"},
        {"invalid UTF-8 text (surrogate)", {"render", kDejaVu, "--text", "\xED\xA0\x80", "-o", "out.png"}, 2, "--text: text byte 0"},
        {"invalid UTF-8 TEXT argument", {"render", kDejaVu, "a\x80z", "-o", "out.png"}, 2, "TEXT: text byte 1"},
        {"invalid UTF-8 in a --text-file", {"render", kDejaVu, "--text-file", "latin1.txt", "-o", "out.png"}, 1, "latin1.txt: text byte 1"},
        {"invalid UTF-8 --char", {"outline", kDejaVu, "--char", "\xC3", "-o", "out.svg"}, 2, "--char: '\xC3': text byte 0"},
        {"invalid UTF-8 --text (glyph)", {"glyph", kDejaVu, "--text", "a\x80z", "-o", "out.png"}, 2, "--text: text byte 1"},
        {"--text past the 1000-character limit", {"outline", kDejaVu, "--text", std::string(1001, 'a')}, 2, "--text: 1001 characters"},
        {"tolerance out of range", {"glyph", kDejaVu, "--char", "g", "--tolerance", "0", "-o", "out.png"}, 2, "--tolerance 0: expected"},
        {"missing --text-file", {"render", kDejaVu, "--text-file", "missing.txt", "-o", "out.png"}, 1, "missing.txt"},
        {"a lone word that looks like a missing font", {"render", "Missing.otf", "-o", "out.png"}, 1, "Missing.otf: no such font file (to use these words as text, give them with --text)"},
        {"unknown hinting mode", {"render", kDejaVu, "--text", "g", "--hinting", "strong", "-o", "out.png"}, 2, "--hinting"},
        {"negative synthetic bold", {"render", kDejaVu, "--text", "g", "--font-bold", "-0.02", "-o", "out.png"}, 2, "--font-bold: -0.02 is not in 0 to 0.25"},
        {"synthetic bold with outlined text", {"render", kDejaVu, "--text", "g", "--font-bold", "0.02", "--stroke", "1", "-o", "out.png"}, 2, "--font-bold does not combine with --stroke"},
        {"unknown direction", {"render", kDejaVu, "--text", "g", "--direction", "up", "-o", "out.png"}, 2, "--direction 'up': expected ltr, rtl, ttb, btt or auto"},
        {"subpixel text on a transparent page", {"render", kDejaVu, "--text", "g", "--lcd", "rgb", "--background", "transparent", "-o", "out.png"}, 2, "--lcd needs an opaque --background"},
        {"gamma out of range", {"render", kDejaVu, "--text", "g", "--gamma", "0.5", "-o", "out.png"}, 2, "--gamma"},
        {"unknown compression level", {"render", kDejaVu, "--text", "g", "--compression", "best", "-o", "out.png"}, 2, "--compression"},
        {"a COLR paint graph that loops", {"render", "colr-loop.ttf", "--text", "B", "-o", "out.png"}, 1, "colr-loop.ttf: glyph"},
        {"a COLR paint graph 10,000 deep", {"glyph", "colr-deep.ttf", "--char", "A", "-o", "out.png"}, 1, "colr-deep.ttf: glyph"},
        {"a COLR palette index past CPAL's entries", {"glyph", "colr-bad-palette.ttf", "--char", "A", "-O", "json"}, 1, "colr-bad-palette.ttf: glyph"},
        {"--palette past the font's palettes", {"glyph", "colr-bad-palette.ttf", "--char", "A", "--palette", "7", "-O", "json"}, 1, "--palette 7"},
        {"the outline of a colour bitmap font", {"outline", "NotoColorEmoji.ttf", "--char", "U+1F600", "-o", "out.svg"}, 1, "NotoColorEmoji.ttf: a bitmap-only font (no outlines): its glyphs are colour bitmaps"},
        {"a character the font lacks, with --strict", {"render", kDejaVu, "--text", "a\xE4\xB8\xAD", "--strict", "-o", "out.png"}, 1, "no glyph for U+4E2D"},
        {"a character the font lacks, with --strict (atlas)", {"atlas", kDejaVu, "--chars", "a\xE4\xB8\xAD", "--strict", "-o", "out.png", "--json", "out.json"}, 1, "no glyph for U+4E2D"},
        {"misspelt option", {"render", kDejaVu, "--font-sise", "12"}, 2, "unknown option --font-sise; did you mean --font-size?"},
        {"misspelt command", {"rendr", "Hello"}, 2, "rendr: not a bezel command; did you mean render?"},
        {"malformed --script", {"render", kDejaVu, "--text", "g", "--script", "Ar", "-o", "out.png"}, 2, "--script: script 'Ar'"},
        {"unknown --script", {"render", kDejaVu, "--text", "g", "--script", "Xyzw", "-o", "out.png"}, 2, "--script: script 'Xyzw'"},
        {"malformed --language", {"render", kDejaVu, "--text", "g", "--language", "en us", "-o", "out.png"}, 2, "--language: language 'en us'"},
        {"malformed --features", {"render", kDejaVu, "--text", "g", "--features", "kern=x", "-o", "out.png"}, 2, "--features: feature 'kern=x'"},
        {"margin out of range", {"render", kDejaVu, "--text", "g", "--margin", "-5", "-o", "out.png"}, 2, "--margin: -5 is not in 0 to 32768"},
        {"misspelt colour name", {"fill", "M0 0h1v1z", "--width", "4", "--height", "4", "--foreground", "yelow", "-o", "out.png"}, 2, "'yelow': not a CSS colour name"},
    };
}

std::vector<std::string> lines_of(const std::string& s) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start < s.size()) {
        std::size_t end = s.find('\n', start);
        if (end == std::string::npos) end = s.size();
        lines.push_back(s.substr(start, end - start));
        start = end + 1;
    }
    return lines;
}

std::string shell_quote(const std::string& a) {
    if (a.find_first_of(" '\"\\$\x80\xC3\xED") == std::string::npos && !a.empty()) return a;
    std::string out = "'";
    for (unsigned char c : a) {
        if (c == '\'') out += "'\\''";
        else if (c >= 0x80) { char buf[8]; std::snprintf(buf, sizeof buf, "\\x%02X", c); out += buf; }
        else out += static_cast<char>(c);
    }
    return out + "'";
}

TEST(BadInputs, EachGivesOneErrorLineNamingTheInputAndNoOutputFile) {
    TempDir dir("bezel-bad-inputs");
    make_bad_files(dir.path());
    const std::vector<std::string> before = dir.entries();
    std::string table =
        "| input | command | exit | message |\n|---|---|---|---|\n";
    for (const BadInput& bad : catalogue()) {
        SCOPED_TRACE(bad.what);
        const CliRun r = test::run_bezel(bad.args, dir.path());
        const std::vector<std::string> err = lines_of(r.err);
        EXPECT_EQ(r.exit_code, bad.exit_code) << r.err;
        EXPECT_TRUE(r.out.empty()) << r.out.substr(0, 200);
        ASSERT_FALSE(err.empty());
        EXPECT_EQ(err[0].rfind("bezel: ", 0), 0u) << err[0];
        EXPECT_NE(err[0].find(bad.names), std::string::npos) << err[0];
        // One line; a usage error may add the hint to --help.
        EXPECT_LE(err.size(), bad.exit_code == 2 ? 2u : 1u) << r.err;
        if (err.size() == 2) {
            EXPECT_NE(err[1].find("--help"), std::string::npos) << err[1];
        }
        EXPECT_EQ(dir.entries(), before) << "a file was left behind";

        std::string command = "bezel";
        for (std::string a : bad.args) {
            if (a == kDejaVu) a = "DejaVuSans.ttf";
            if (a.size() > 40) a = a.substr(0, 8) + "...(" + std::to_string(a.size()) + " bytes)";
            command += " " + shell_quote(a);
        }
        std::string message = err[0];
        for (std::size_t at; (at = message.find(kDejaVu)) != std::string::npos;)
            message.replace(at, kDejaVu.size(), "DejaVuSans.ttf");
        for (std::size_t at; (at = message.find('|')) != std::string::npos;) message.replace(at, 1, "\\|");
        if (!decode_utf8(message).ok()) {  // the table is UTF-8: show a bad input's bytes as \xNN
            std::string escaped;
            for (unsigned char c : message) {
                char buf[8];
                std::snprintf(buf, sizeof buf, "\\x%02X", c);
                escaped += c >= 0x80 ? std::string(buf) : std::string(1, static_cast<char>(c));
            }
            message = escaped;
        }
        table += "| " + bad.what + " | `" + command + "` | " + std::to_string(r.exit_code) + " | `" +
                 message + "` |\n";
    }
    if (const char* out = std::getenv("BEZEL_CATALOGUE")) std::ofstream(out) << table;
}

}  // namespace
}  // namespace bezel
