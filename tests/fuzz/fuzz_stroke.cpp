// fuzz_stroke — random paths (NaN, inf, 1e30, degenerate and cusped curves) and random styles
// (widths, joins, caps, miter limits, dash patterns, tolerances — sane and hostile) through
// stroke() and dash(). Properties: no crash and bounded work; a result is finite and within
// kMaxStrokeSegments; it rasterizes (or fails with a message).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "bezel/raster.hpp"
#include "bezel/stroke.hpp"
#include "fuzz_reader.hpp"

namespace {

using bezel::fuzz::FuzzReader;

bezel::StrokeStyle read_style(FuzzReader& in) {
    bezel::StrokeStyle s;
    s.width = in.byte() < 220 ? 0.25 * (1 + in.byte() % 40) : in.number();
    s.join = static_cast<bezel::LineJoin>(in.byte() % 3);
    s.cap = static_cast<bezel::LineCap>(in.byte() % 3);
    s.miter_limit = in.byte() < 220 ? 1.0 + (in.byte() % 16) * 0.5 : in.number();
    for (std::size_t i = 0, n = in.below(5); i < n; ++i)
        s.dashes.push_back(in.byte() < 220 ? 0.5 * (in.byte() % 20) : in.number());
    s.dash_offset = in.byte() < 220 ? (in.byte() % 16) * 0.5 : in.number();
    // Tolerances down to 1/1000 keep a run short; smaller ones (and hostile values) sometimes.
    s.tolerance = in.byte() < 230 ? 0.001 * (1 + in.byte() % 100) : in.number();
    return s;
}

std::size_t segments(const bezel::Path& p) { return p.segment_count(); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzReader in(data, size);
    const bezel::StrokeStyle style = read_style(in);
    const bezel::Path path = bezel::fuzz::read_path(in, 16);
    auto outline = bezel::stroke(path, style);
    if (!outline) {
        BEZEL_FUZZ_CHECK(!outline.error().message.empty());
    } else {
        BEZEL_FUZZ_CHECK(outline->is_finite());
        BEZEL_FUZZ_CHECK(segments(*outline) <= bezel::kMaxStrokeSegments);
        std::vector<std::uint8_t> pixels(32 * 32);
        bezel::Rasterizer raster;
        (void)raster.fill_path(*outline, bezel::Affine::identity(),
                               bezel::MaskView{pixels.data(), 32, 32, 32});  // NonZero
    }
    auto dashed = bezel::dash(path, style.dashes, style.dash_offset);
    if (dashed) BEZEL_FUZZ_CHECK(dashed->is_finite());
    return 0;
}
