// bezel_rasterizer: Rasterizer::fill_path into a caller mask.
#include <cmath>

#include "bezel/limits.hpp"
#include "capi/handles.hpp"

using namespace bezel;
using namespace bezel::capi_detail;

extern "C" {

void bezel_fill_options_init(bezel_fill_options* options) {
    if (!options) return;
    *options = bezel_fill_options{};
    options->rule = BEZEL_FILL_NONZERO;
    options->tolerance_px = kDefaultRasterTolerancePx;
    options->coverage = BEZEL_COVERAGE_GRAY;
}

bezel_status bezel_rasterizer_create(bezel_rasterizer** out) {
    static const char* const fn = "bezel_rasterizer_create";
    return guarded(nullptr, fn, [&]() -> bezel_status {
        if (!out) return null_argument(nullptr, fn, "out");
        *out = new bezel_rasterizer{};
        return BEZEL_STATUS_OK;
    });
}

void bezel_rasterizer_destroy(bezel_rasterizer* rasterizer) { delete rasterizer; }

const char* bezel_rasterizer_last_error(const bezel_rasterizer* rasterizer) {
    return rasterizer ? rasterizer->error.c_str() : bezel_last_error();
}

bezel_status bezel_rasterizer_fill(bezel_rasterizer* rasterizer, const bezel_path* path,
                                   const bezel_transform* transform,
                                   const bezel_fill_options* options, std::uint8_t* buffer,
                                   std::size_t buffer_size, int width, int height,
                                   std::ptrdiff_t stride) {
    static const char* const fn = "bezel_rasterizer_fill";
    if (!rasterizer) return null_argument(nullptr, fn, "rasterizer");
    ErrorSlot* err = &rasterizer->error;
    return guarded(err, fn, [&]() -> bezel_status {
        if (!path) return null_argument(err, fn, "path");
        bezel_fill_options o;
        bezel_fill_options_init(&o);
        if (options) o = *options;
        FillOptions fill;
        const int rule = raw_enum(o.rule);
        if (rule != BEZEL_FILL_NONZERO && rule != BEZEL_FILL_EVENODD)
            return fail(err, BEZEL_STATUS_INVALID_ARGUMENT,
                        std::string(fn) + ": rule " + std::to_string(rule) +
                            " is not a bezel_fill_rule (0..1)");
        fill.rule = rule == BEZEL_FILL_EVENODD ? FillRule::EvenOdd : FillRule::NonZero;
        fill.overlap = o.accurate_overlap ? OverlapMode::Accurate : OverlapMode::Accumulate;
        if (!(o.tolerance_px > 0 && std::isfinite(o.tolerance_px)))
            return fail(err, BEZEL_STATUS_INVALID_ARGUMENT,
                        std::string(fn) + ": tolerance_px " + std::to_string(o.tolerance_px) +
                            " is not finite and > 0");
        fill.flatten.tolerance_px = o.tolerance_px;
        if (bezel_status s =
                to_coverage(err, fn, raw_enum(o.coverage), fill.format, fill.lcd_order))
            return s;
        if (width < 0 || height < 0 || width > kMaxBitmapDim || height > kMaxBitmapDim)
            return fail(err, BEZEL_STATUS_OUT_OF_RANGE,
                        std::string(fn) + ": mask " + std::to_string(width) + "x" +
                            std::to_string(height) + " is outside 0.." +
                            std::to_string(kMaxBitmapDim) + " px a side (kMaxBitmapDim)");
        const int bytes_per_px = fill.format == CoverageFormat::Lcd ? 3 : 1;
        const std::size_t row_bytes = static_cast<std::size_t>(width) * bytes_per_px;
        if (bezel_status s = check_buffer(err, std::string(fn) + ": mask", buffer, buffer_size,
                                          stride, row_bytes, static_cast<std::size_t>(height)))
            return s;
        const Affine m = transform ? Affine{transform->a, transform->b, transform->c,
                                            transform->d, transform->e, transform->f}
                                   : Affine{};
        const MaskView target{row_bytes == 0 || height == 0 ? nullptr : buffer,
                              static_cast<int>(row_bytes), height, stride};
        // An empty mask is written nothing; the fill still checks the path and transform.
        Status filled = rasterizer->raster.fill_path(path->path, m, target, fill);
        if (!filled)
            return fail(err, BEZEL_STATUS_INVALID_ARGUMENT,
                        std::string(fn) + ": " + filled.error().message);
        return BEZEL_STATUS_OK;
    });
}

}  // extern "C"
