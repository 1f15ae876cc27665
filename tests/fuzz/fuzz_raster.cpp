// fuzz_raster — random paths (NaN, inf, 1e30, 2^50, degenerate curves) through every flattening
// method and every fill of the Rasterizer: polylines and paths, NonZero and EvenOdd, 8-bit and
// float targets, and — where the raster module has them — the overlap modes and LCD. Properties:
// no crash, no unbounded work; flatten's output stays finite and within its segment bound; the
// float coverage lies in [0, 1], even-odd never exceeds non-zero, and the 8-bit target is the
// float coverage rounded (±1); a failing fill leaves the target untouched.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "bezel/flatten.hpp"
#include "bezel/raster.hpp"
#include "fuzz_reader.hpp"

namespace {

using bezel::fuzz::FuzzReader;

constexpr bezel::FlattenMethod kMethods[] = {
    bezel::FlattenMethod::ClassicFlatness, bezel::FlattenMethod::DistanceSubdivision,
    bezel::FlattenMethod::WangUniform, bezel::FlattenMethod::ParabolaIntegral};

bezel::Affine read_transform(FuzzReader& in) {
    switch (in.byte() % 4) {
        case 0: return bezel::Affine::identity();
        case 1: return bezel::Affine::scale(in.positive(1.0));
        case 2: return bezel::Affine::translate({in.number(), in.number()});
        default: {
            bezel::Affine m;
            m.a = in.number(); m.b = in.number(); m.c = in.number();
            m.d = in.number(); m.e = in.number(); m.f = in.number();
            return m;
        }
    }
}

// Coverage of one fill in both pixel types, checked against each other.
void fill_both(bezel::Rasterizer& raster, const bezel::Polylines& lines, bezel::FillRule rule,
               int w, int h, bezel::Vec2 origin, std::vector<float>& out) {
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(w) * h, 0xA5);
    out.assign(static_cast<std::size_t>(w) * h, -1.0f);
    bezel::FillOptions fill;
    fill.rule = rule;
    fill.origin = origin;
    auto s8 = raster.fill(lines, bezel::MaskView{bytes.data(), w, h, w}, fill);
    auto sf = raster.fill(lines, bezel::FloatMaskView{out.data(), w, h, w}, fill);
    BEZEL_FUZZ_CHECK(s8.ok() == sf.ok());
    if (!sf) {
        for (std::uint8_t b : bytes) BEZEL_FUZZ_CHECK(b == 0xA5);  // untouched on error
        for (float f : out) BEZEL_FUZZ_CHECK(f == -1.0f);
        out.clear();
        return;
    }
    for (std::size_t i = 0; i < out.size(); ++i) {
        BEZEL_FUZZ_CHECK(out[i] >= 0.0f && out[i] <= 1.0f);
        BEZEL_FUZZ_CHECK(std::fabs(bytes[i] - out[i] * 255.0f) <= 1.0f);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzReader in(data, size);
    const int w = 1 + static_cast<int>(in.byte() % 48), h = 1 + static_cast<int>(in.byte() % 48);
    const bezel::Affine transform = read_transform(in);
    bezel::FlattenOptions options;
    options.tolerance_px = in.byte() < 200 ? 0.01 * (1 + in.byte() % 50) : in.number();
    options.classic_flatness_epsilon = in.byte() < 200 ? 1e-3 : in.number();
    const bezel::Vec2 origin = in.byte() < 220 ? bezel::Vec2{in.byte() / 16.0, in.byte() / 16.0}
                                               : bezel::Vec2{in.number(), in.number()};
    const bezel::Path path = bezel::fuzz::read_path(in, 24);

    bezel::Rasterizer raster;
    std::vector<float> nonzero, evenodd;
    for (bezel::FlattenMethod method : kMethods) {
        options.method = method;
        bezel::Polylines lines;
        bezel::flatten(path, transform, options, lines);
        BEZEL_FUZZ_CHECK(lines.contour_ends.empty() || lines.contour_ends.back() == lines.points.size());
        BEZEL_FUZZ_CHECK(lines.points.size() <=
                         (path.verbs().size() + 1) * (bezel::kMaxSegmentsPerCurve + 1));
        for (const bezel::Point& p : lines.points)
            BEZEL_FUZZ_CHECK(std::isfinite(p.x) && std::isfinite(p.y));
        bezel::Polylines checked;
        auto status = bezel::flatten_checked(path, transform, options, checked);
        if (!status) BEZEL_FUZZ_CHECK(checked.points.empty() && !status.error().message.empty());

        fill_both(raster, lines, bezel::FillRule::NonZero, w, h, origin, nonzero);
        fill_both(raster, lines, bezel::FillRule::EvenOdd, w, h, origin, evenodd);
        BEZEL_FUZZ_CHECK(nonzero.size() == evenodd.size());
        for (std::size_t i = 0; i < nonzero.size(); ++i)
            BEZEL_FUZZ_CHECK(evenodd[i] <= nonzero[i] + 1e-6f);
    }

    // fill_path in every mode; the bytes only need to be written in range or left alone.
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(w) * h);
    std::vector<float> fmask(mask.size());
    for (bezel::FillRule rule : {bezel::FillRule::NonZero, bezel::FillRule::EvenOdd}) {
        const bezel::FillOptions fill{rule, bezel::OverlapMode::Accumulate, options};
        (void)raster.fill_path(path, transform, bezel::MaskView{mask.data(), w, h, w}, fill);
        if (raster.fill_path(path, transform, bezel::FloatMaskView{fmask.data(), w, h, w}, fill))
            for (float f : fmask) BEZEL_FUZZ_CHECK(f >= 0.0f && f <= 1.0f);
        // Combining fills keep coverage in [0, 1] whatever the target held (the float target
        // holds the fill above).
        for (bezel::CoverageCombine combine :
             {bezel::CoverageCombine::Over, bezel::CoverageCombine::Add}) {
            bezel::FillOptions combined = fill;
            combined.combine = combine;
            (void)raster.fill_path(path, transform, bezel::MaskView{mask.data(), w, h, w},
                                   combined);
            if (raster.fill_path(path, transform, bezel::FloatMaskView{fmask.data(), w, h, w},
                                 combined))
                for (float f : fmask) BEZEL_FUZZ_CHECK(f >= 0.0f && f <= 1.0f);
        }
        // The exact overlap pass (its float→byte conversion is where UBSan caught NaN).
        const bezel::FillOptions accurate{rule, bezel::OverlapMode::Accurate, options};
        (void)raster.fill_path(path, transform, bezel::MaskView{mask.data(), w, h, w}, accurate);
        std::vector<std::uint8_t> lcd(static_cast<std::size_t>(3 * w) * h);
        for (bezel::LcdOrder order : {bezel::LcdOrder::Rgb, bezel::LcdOrder::Bgr})
            for (bezel::OverlapMode overlap :
                 {bezel::OverlapMode::Accumulate, bezel::OverlapMode::Accurate}) {
                const bezel::FillOptions lcd_fill{rule, overlap, options, {},
                                                  bezel::CoverageFormat::Lcd, order};
                (void)raster.fill_path(path, transform,
                                       bezel::MaskView{lcd.data(), 3 * w, h, 3 * w}, lcd_fill);
            }
    }
    // Invalid targets are errors, never writes.
    const bezel::FillOptions fill{bezel::FillRule::NonZero, bezel::OverlapMode::Accumulate,
                                  options};
    BEZEL_FUZZ_CHECK(!raster.fill_path(path, transform, bezel::MaskView{nullptr, w, h, w}, fill));
    BEZEL_FUZZ_CHECK(!raster.fill_path(path, transform, bezel::MaskView{mask.data(), -w, h, w},
                                       fill));
    return 0;
}
