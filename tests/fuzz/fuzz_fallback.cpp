// fuzz_fallback — random text over a random font list: 1 to 6 fonts drawn from the bundled test
// fonts (outline fonts of several scripts, a bitmap-only colour font, a collection's faces, a
// variable font at random coordinates, files that do not exist), and a fallback source that
// names random fonts of the same pool. Through FontCollection::open, layout_text over the
// collection and TextRenderer::render_gray (render() when the text holds colour glyphs).
// Properties: no crash; a list with a missing file or a face out of range is an Error naming
// the file; every placed glyph's font is in the collection, its cluster inside the text, its
// position finite; the fallback never grows the collection past kMaxCollectionFonts; every font
// the renderer draws with has outlines or colour glyphs; a gray page holds no colour glyph; a
// rendered page has the layout's size or an Error.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "bezel/text.hpp"
#include "fuzz_reader.hpp"

namespace {

using bezel::fuzz::FuzzReader;

const std::string kDir = BEZEL_FONTS_DIR;
const std::vector<std::string> kPool = {
    kDir + "/dejavu-sans/DejaVuSans.ttf",
    kDir + "/cantarell/Cantarell-Regular.otf",
    kDir + "/noto-arabic/NotoSansArabic-Regular.ttf",
    kDir + "/noto-hebrew/NotoSansHebrew-Regular.ttf",
    kDir + "/noto-devanagari/NotoSansDevanagari-Regular.ttf",
    kDir + "/noto-cjk/NotoSansCJKjp-Subset.otf",
    kDir + "/noto-color-emoji/NotoColorEmoji-subset.ttf",
    kDir + "/edge-cases/EdgeCases.ttf",
    kDir + "/edge-cases/EdgeCases.ttc",
    kDir + "/edge-cases/EdgeCasesVariable.ttf",
    kDir + "/no-such-font.ttf",
};

bezel::FontSource pick(FuzzReader& in) {
    bezel::FontSource s;
    s.file = kPool[in.below(kPool.size())];
    s.face_index = in.byte() < 220 ? 0 : in.byte() % 4;
    if (in.byte() > 200) s.variations.push_back({in.flag() ? "wght" : in.rest(4), in.number()});
    return s;
}

// Names a font of the pool for every other request, chosen by the input.
class PoolFallback : public bezel::FallbackSource {
public:
    explicit PoolFallback(std::string choices) : choices_(std::move(choices)) {}
    bezel::Expected<std::optional<bezel::FontSource>> font_for(
        const bezel::FallbackRequest& request) override {
        BEZEL_FUZZ_CHECK(!request.cluster.empty());
        if (choices_.empty()) return std::optional<bezel::FontSource>{};
        const auto c = static_cast<unsigned char>(choices_[next_++ % choices_.size()]);
        if (c % 4 == 0) return std::optional<bezel::FontSource>{};
        if (c % 4 == 2) return bezel::Error{"fallback source failed"};
        return std::optional<bezel::FontSource>(bezel::FontSource{kPool[(c / 4) % kPool.size()], 0, {}});
    }

private:
    std::string choices_;
    std::size_t next_ = 0;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzReader in(data, size);
    std::vector<bezel::FontSource> sources(1 + in.below(6));
    for (bezel::FontSource& s : sources) s = pick(in);
    const bool with_fallback = in.flag();
    const std::string choices = in.rest(in.below(16));
    bezel::TextRenderOptions options;
    options.shape.size_px = 1 + in.byte() % 32;
    // All five: Auto, LTR, RTL and the vertical TopToBottom, BottomToTop.
    options.shape.direction = static_cast<bezel::Direction>(in.byte() % 5);
    options.layout.width_px = in.byte() < 128 ? 0 : in.byte();
    const std::string text = in.rest(256);

    auto fonts = bezel::FontCollection::open(sources);
    if (!fonts) {
        BEZEL_FUZZ_CHECK(!fonts.error().message.empty());
        return 0;
    }
    if (with_fallback) fonts->set_fallback(std::make_shared<PoolFallback>(choices));

    auto layout = bezel::layout_text(*fonts, text, options.shape, options.layout);
    BEZEL_FUZZ_CHECK(fonts->size() <= bezel::kMaxCollectionFonts);
    if (layout) {
        for (const auto& g : layout->glyphs) {
            BEZEL_FUZZ_CHECK(g.font < fonts->size());
            BEZEL_FUZZ_CHECK(g.cluster <= text.size());
            BEZEL_FUZZ_CHECK(std::isfinite(g.x_px) && std::isfinite(g.y_px));
        }
        const bezel::MissingGlyphs missing = bezel::find_missing_glyphs(*layout, text);
        BEZEL_FUZZ_CHECK(missing.count <= layout->glyphs.size());
    }
    if (!bezel::decode_utf8(text).ok()) BEZEL_FUZZ_CHECK(!layout.ok());

    // The renderer takes outline fonts and colour fonts (the bitmap-only one draws in colour); a
    // gray page refuses text that holds a colour glyph, which render() then draws in RGBA.
    auto renderer = bezel::TextRenderer::open(std::move(*fonts), std::size_t{1} << 20);
    if (!renderer) return 0;
    auto page = renderer->render_gray(text, options);
    for (std::size_t i = 0; i < renderer->fonts().size(); ++i)
        BEZEL_FUZZ_CHECK(renderer->fonts().font(i).require_outlines().ok() ||
                         renderer->fonts().font(i).has_color_bitmaps());
    if (page) {
        BEZEL_FUZZ_CHECK(page->width() <= bezel::kMaxImageDim && page->height() <= bezel::kMaxImageDim);
        BEZEL_FUZZ_CHECK(!renderer->last_text_has_color());
    } else if (renderer->last_text_has_color()) {
        auto colour = renderer->render(text, options);
        if (colour)
            BEZEL_FUZZ_CHECK(colour->width() <= bezel::kMaxImageDim &&
                             colour->height() <= bezel::kMaxImageDim);
    }
    return 0;
}
