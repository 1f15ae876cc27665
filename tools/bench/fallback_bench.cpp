// bench_fallback_bench: the cost of font fallback, in one process through
// TextRenderer::render_gray (glyph caches warm, as a program rendering many pages has them),
// 16 px text wrapped at 800 px, pages of as many characters as tools/bench/render_page.txt:
//   single    Latin, Arabic, Hebrew and symbol words (arrows, math) in DejaVu Sans alone, which
//             has them all;
//   list      the same text from a list of four fonts, each word from another: Cantarell (Latin),
//             Noto Sans Arabic, Noto Sans Hebrew, DejaVu Sans (the symbols);
//   latin     render_page.txt's prose in Cantarell alone;
//   scripts   Latin, Arabic, Hebrew, Devanagari (and CJK when fonts-test/noto-cjk has its font)
//             words from Cantarell and the Noto fonts: more scripts than any one font here has.
// Reported: the median time of each (runs interleaved, so a change in the machine's load hits
// them alike) and the ratios list / single (the bar: at most 1.5) and scripts / latin.
//
//   bench_fallback_bench [RUNS]      (default 41)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "bezel/text.hpp"

namespace {

const std::string kFonts = BEZEL_FONTS_DIR;

std::u32string read_page() {
    std::ifstream in(std::string(BEZEL_FONTS_DIR) + "/../tools/bench/render_page.txt");
    std::string utf8((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (char& c : utf8)
        if (c == '\n') c = ' ';   // one paragraph: the renderer wraps it
    auto text = bezel::decode_utf8(utf8);
    if (!text) {
        std::fprintf(stderr, "render_page.txt: %s\n", text.error().message.c_str());
        std::exit(1);
    }
    return *text;
}

std::string utf8_of(const std::u32string& text) {
    std::string out;
    for (char32_t c : text) bezel::append_utf8(out, c);
    return out;
}

// `words` in turn until `length` characters.
std::u32string cycle(const std::vector<std::u32string>& words, std::size_t length) {
    std::u32string out;
    for (std::size_t i = 0; out.size() < length; ++i) out += words[i % words.size()];
    out.resize(length);
    return out;
}

const std::vector<std::u32string> kLatin = {U"The quick brown fox jumps over the lazy dog. "};
const std::u32string kArabicWords =
    U"\u0645\u0631\u062D\u0628\u0627 \u0628\u0627\u0644\u0639\u0627\u0644\u0645 ";
const std::u32string kHebrewWords = U"\u05E9\u05DC\u05D5\u05DD \u05E2\u05D5\u05DC\u05DD ";
const std::u32string kSymbolWords = U"\u2192 \u2211\u221E \u2264 \u2713 ";
const std::u32string kDevanagariWords =
    U"\u0928\u092E\u0938\u094D\u0924\u0947 \u0926\u0941\u0928\u093F\u092F\u093E ";
const std::u32string kCjkWords = U"\u4F60\u597D\u4E16\u754C\uFF0C\u3053\u3093\u306B\u3061\u306F ";

bezel::TextRenderer open_list(const std::vector<std::string>& files) {
    std::vector<bezel::FontSource> sources;
    for (const std::string& f : files) sources.push_back({f, 0, {}});
    auto fonts = bezel::FontCollection::open(sources);
    if (!fonts) {
        std::fprintf(stderr, "%s\n", fonts.error().message.c_str());
        std::exit(1);
    }
    auto renderer = bezel::TextRenderer::open(std::move(*fonts));
    if (!renderer) {
        std::fprintf(stderr, "%s\n", renderer.error().message.c_str());
        std::exit(1);
    }
    return std::move(*renderer);
}

double time_render(bezel::TextRenderer& renderer, const std::string& text,
                   const bezel::TextRenderOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    auto page = renderer.render_gray(text, options);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!page) {
        std::fprintf(stderr, "render: %s\n", page.error().message.c_str());
        std::exit(1);
    }
    return s;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 41;
    const std::string cantarell = kFonts + "/cantarell/Cantarell-Regular.otf";
    const std::string dejavu = kFonts + "/dejavu-sans/DejaVuSans.ttf";
    const std::string arabic = kFonts + "/noto-arabic/NotoSansArabic-Regular.ttf";
    const std::string hebrew = kFonts + "/noto-hebrew/NotoSansHebrew-Regular.ttf";
    const std::string devanagari = kFonts + "/noto-devanagari/NotoSansDevanagari-Regular.ttf";
    const std::string cjk_font = kFonts + "/noto-cjk/NotoSansCJK-subset.otf";
    const bool cjk = std::filesystem::exists(cjk_font);

    const std::u32string page = read_page();
    const std::string latin = utf8_of(page);
    const std::string mixed = utf8_of(
        cycle({kLatin[0], kArabicWords, kHebrewWords, kSymbolWords}, page.size()));
    std::vector<std::u32string> script_words = {kLatin[0], kArabicWords, kHebrewWords,
                                                kDevanagariWords};
    std::vector<std::string> script_fonts = {cantarell, arabic, hebrew, devanagari};
    if (cjk) {
        script_words.push_back(kCjkWords);
        script_fonts.push_back(cjk_font);
    }
    const std::string scripts = utf8_of(cycle(script_words, page.size()));

    struct Case {
        const char* name;
        bezel::TextRenderer renderer;
        const std::string* text;
        std::vector<double> times;
    };
    std::vector<Case> cases;
    cases.push_back({"single", open_list({dejavu}), &mixed, {}});
    cases.push_back({"list", open_list({cantarell, arabic, hebrew, dejavu}), &mixed, {}});
    cases.push_back({"latin", open_list({cantarell}), &latin, {}});
    cases.push_back({"scripts", open_list(script_fonts), &scripts, {}});
    bezel::TextRenderOptions options;
    options.shape.size_px = 16;
    options.layout.width_px = 800;
    options.layout.margin_px = 16;
    for (Case& c : cases) time_render(c.renderer, *c.text, options);   // warm the caches
    for (int i = 0; i < runs; ++i)
        for (Case& c : cases) c.times.push_back(time_render(c.renderer, *c.text, options));
    std::printf("characters a page: %zu; runs: %d; scripts page: %zu fonts%s\n", page.size(), runs,
                script_fonts.size(), cjk ? " (with CJK)" : "");
    std::printf("%-9s %9s\n", "page", "ms");
    double t[4];
    for (std::size_t i = 0; i < cases.size(); ++i) {
        t[i] = median(cases[i].times);
        std::printf("%-9s %9.3f\n", cases[i].name, t[i] * 1e3);
    }
    std::printf("list / single    %.2f (bar: <= 1.5)\n", t[1] / t[0]);
    std::printf("scripts / latin  %.2f\n", t[3] / t[2]);
    return 0;
}
