// bench_fallback_bench: the cost of font fallback. A page of mixed-script text drawn from a list
// of fonts against a single-font page of the same number of characters, both in one process
// through TextRenderer::render_gray (glyph cache warm, as a program rendering many pages has
// it), wrapped at 800 px, 16 px text:
//   latin     tools/bench/render_page.txt's prose in Cantarell alone;
//   mixed     Latin, Arabic, Hebrew and Devanagari words (plus CJK when fonts-test/noto-cjk has
//             its font), each script from its own font: Cantarell, then the Noto fonts;
//   mixed-1   the same mixed text in a one-font list (Cantarell: the scripts it lacks draw as
//             .notdef): shaping and layout of those characters without the fallback search.
// Reported: the median time of each (runs interleaved, so a change in the machine's load hits
// them alike) and the ratios mixed / latin (the bar: at most 1.5) and mixed / mixed-1.
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

// Words of each script in turn until `length` characters.
std::u32string mixed_text(std::size_t length, bool cjk) {
    std::vector<std::u32string> words = {
        U"The quick brown fox jumps over the lazy dog. ",
        U"\u0645\u0631\u062D\u0628\u0627 \u0628\u0627\u0644\u0639\u0627\u0644\u0645 ",
        U"\u05E9\u05DC\u05D5\u05DD \u05E2\u05D5\u05DC\u05DD ",
        U"\u0928\u092E\u0938\u094D\u0924\u0947 \u0926\u0941\u0928\u093F\u092F\u093E ",
    };
    if (cjk) words.push_back(U"\u4F60\u597D\u4E16\u754C\uFF0C\u3053\u3093\u306B\u3061\u306F ");
    std::u32string out;
    for (std::size_t i = 0; out.size() < length; ++i) out += words[i % words.size()];
    out.resize(length);
    return out;
}

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
    const std::string cjk_font = kFonts + "/noto-cjk/NotoSansCJK-subset.otf";
    const bool cjk = std::filesystem::exists(cjk_font);
    std::vector<std::string> list = {cantarell,
                                     kFonts + "/noto-arabic/NotoSansArabic-Regular.ttf",
                                     kFonts + "/noto-hebrew/NotoSansHebrew-Regular.ttf",
                                     kFonts + "/noto-devanagari/NotoSansDevanagari-Regular.ttf"};
    if (cjk) list.push_back(cjk_font);

    const std::u32string page = read_page();
    const std::string latin = utf8_of(page);
    const std::string mixed = utf8_of(mixed_text(page.size(), cjk));

    bezel::TextRenderer latin_renderer = open_list({cantarell});
    bezel::TextRenderer mixed_renderer = open_list(list);
    bezel::TextRenderer mixed_one = open_list({cantarell});
    bezel::TextRenderOptions options;
    options.shape.size_px = 16;
    options.layout.width_px = 800;
    options.layout.margin_px = 16;
    // Warm the glyph caches.
    time_render(latin_renderer, latin, options);
    time_render(mixed_renderer, mixed, options);
    time_render(mixed_one, mixed, options);
    std::vector<double> t_latin, t_mixed, t_one;
    for (int i = 0; i < runs; ++i) {
        t_latin.push_back(time_render(latin_renderer, latin, options));
        t_mixed.push_back(time_render(mixed_renderer, mixed, options));
        t_one.push_back(time_render(mixed_one, mixed, options));
    }
    const double l = median(t_latin), m = median(t_mixed), o = median(t_one);
    std::printf("characters a page: %zu; fonts in the mixed list: %zu%s; runs: %d\n", page.size(),
                list.size(), cjk ? " (with CJK)" : "", runs);
    std::printf("%-9s %9s\n", "page", "ms");
    std::printf("%-9s %9.3f\n", "latin", l * 1e3);
    std::printf("%-9s %9.3f\n", "mixed", m * 1e3);
    std::printf("%-9s %9.3f\n", "mixed-1", o * 1e3);
    std::printf("mixed / latin   %.2f (bar: <= 1.5)\n", m / l);
    std::printf("mixed / mixed-1 %.2f\n", m / o);
    return 0;
}
