#include "glyph_texels.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <string>

namespace bezel_imgui::detail {

namespace {
// `glyph` (prepared at pen offset 0, GlyphBoxMode::Tight; `b` its path's tight bounds) moved to
// the pen offset `offset`: its box by GlyphBoxMode::Tight's rule (columns floor(x0 + dx) ..
// ceil(x1 + dx) of the outline's tight bounds, rows likewise), so that draw() fills it there
// without loading the outline again.
void move_pen(bezel::PreparedGlyph& glyph, const bezel::Rect& b, bezel::Vec2 offset) {
    glyph.options.offset_px = offset;
    if (b.is_empty()) return;
    const double x0 = std::floor(b.x0 + offset.x), x1 = std::ceil(b.x1 + offset.x);
    const double y0 = std::floor(b.y0 + offset.y), y1 = std::ceil(b.y1 + offset.y);
    glyph.box.left = static_cast<int>(x0);
    glyph.box.top = -static_cast<int>(y0);
    glyph.box.width = static_cast<int>(x1 - x0);
    glyph.box.height = static_cast<int>(y1 - y0);
}

struct Phase {
    int kx = 0, ky = 0;           // pen at (kx/h, ky/v) px
    bezel::GlyphBox box;
    std::size_t at = 0;           // its bitmap in the scratch buffer
};
}  // namespace

bezel::Status render_glyph_texels(bezel::GlyphRasterizer& rasterizer, bezel::GlyphId gid,
                                  bezel::GlyphRenderOptions options, Oversample oversample,
                                  bool monochrome, std::size_t max_store_bytes,
                                  std::vector<std::uint8_t>& store,
                                  std::vector<std::uint8_t>& scratch, GlyphTexels& out) {
    int h = oversample.h, v = oversample.v;
    Phase phases[64];   // h, v ≤ kMaxOversample = 8
    int count = 0;
    scratch.clear();
    out = GlyphTexels{};
    out.offset = store.size();
    // Texel ranges over every render: m = h·(left + c) − kx, n = v·(row − top) − ky.
    long m_min = LONG_MAX, m_max = LONG_MIN, n_min = LONG_MAX, n_max = LONG_MIN;
    options.offset_px = {0, 0};
    options.box = bezel::GlyphBoxMode::Tight;
    auto prepared = rasterizer.prepare(gid, options);
    if (!prepared) return prepared.error();
    // A bitmap strike is whole pixels, placed at the whole pixel nearest the pen: its subpixel
    // phases would all be the same bitmap, so it is drawn once, as with OversampleH = V = 1.
    if (prepared->box.bitmap_strike) h = v = 1;
    out.advance_px = static_cast<float>(prepared->box.advance_px);
    const bezel::Rect bounds = h * v > 1 ? prepared->path.bounds() : bezel::Rect{};
    // Its texels: about h·v times its box (each box is within kMaxBitmapDim², so no overflow).
    const std::size_t need = static_cast<std::size_t>(prepared->box.width + 1) * h *
                             static_cast<std::size_t>(prepared->box.height + 1) * v;
    if (need > max_store_bytes || store.size() > max_store_bytes - need)
        return bezel::Error{"its " + std::to_string(prepared->box.width) + "x" +
                            std::to_string(prepared->box.height) + " px bitmap, " +
                            std::to_string(h) + "x" + std::to_string(v) +
                            " oversampled, does not fit the atlas with the glyphs before it (" +
                            std::to_string(max_store_bytes) + " texels at most)"};
    for (int ky = 0; ky < v; ++ky) {
        for (int kx = 0; kx < h; ++kx) {
            const bezel::Vec2 offset{static_cast<double>(kx) / h, static_cast<double>(ky) / v};
            // A colour glyph's box comes from its paint, not its path: prepared anew.
            if (prepared->box.color && (kx | ky) != 0) {
                options.offset_px = offset;
                prepared = rasterizer.prepare(gid, options);
                if (!prepared) return prepared.error();
            } else if ((kx | ky) != 0) {
                move_pen(*prepared, bounds, offset);
            }
            const bezel::PreparedGlyph* glyph = &*prepared;
            const bezel::GlyphBox& box = glyph->box;
            if (box.width <= 0 || box.height <= 0) continue;
            Phase& p = phases[count++];
            p.kx = kx;
            p.ky = ky;
            p.box = box;
            p.at = scratch.size();
            scratch.resize(p.at + static_cast<std::size_t>(box.width) * box.height);
            const bezel::MaskView target{scratch.data() + p.at, box.width, box.height, box.width};
            if (auto drawn = rasterizer.draw(*glyph, target); !drawn) return drawn.error();
            m_min = std::min(m_min, static_cast<long>(h) * box.left - kx);
            m_max = std::max(m_max, static_cast<long>(h) * (box.left + box.width - 1) - kx);
            n_min = std::min(n_min, static_cast<long>(v) * -box.top - ky);
            n_max = std::max(n_max, static_cast<long>(v) * (box.height - 1 - box.top) - ky);
        }
    }
    if (count == 0) return bezel::ok_status();

    out.width = static_cast<int>(m_max - m_min + 1);
    out.height = static_cast<int>(n_max - n_min + 1);
    store.resize(out.offset + static_cast<std::size_t>(out.width) * out.height, 0);
    std::uint8_t* texels = store.data() + out.offset;
    for (int i = 0; i < count; ++i) {
        const Phase& p = phases[i];
        for (int r = 0; r < p.box.height; ++r) {
            const long n = static_cast<long>(v) * (r - p.box.top) - p.ky;
            std::uint8_t* row = texels + (n - n_min) * out.width;
            const std::uint8_t* src = scratch.data() + p.at + static_cast<std::size_t>(r) * p.box.width;
            for (int c = 0; c < p.box.width; ++c)
                row[static_cast<long>(h) * (p.box.left + c) - p.kx - m_min] = src[c];
        }
    }
    if (monochrome) {
        std::uint8_t* end = texels + static_cast<std::size_t>(out.width) * out.height;
        for (std::uint8_t* t = texels; t != end; ++t) *t = *t >= 128 ? 255 : 0;
    }
    out.x0 = static_cast<float>(static_cast<double>(m_min) / h + (h - 1) / (2.0 * h));
    out.y0 = static_cast<float>(static_cast<double>(n_min) / v + (v - 1) / (2.0 * v));
    out.x1 = out.x0 + static_cast<float>(out.width) / h;
    out.y1 = out.y0 + static_cast<float>(out.height) / v;
    return bezel::ok_status();
}

}  // namespace bezel_imgui::detail
