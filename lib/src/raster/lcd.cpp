// Rasterizer::fill_path in CoverageFormat::Lcd: coverage sampled at 3× horizontal resolution,
// then FreeType's 5-tap FIR filter across subpixels.
//
// Sampling: subpixel k of the output covers display x in [k/3, (k+1)/3], i.e. the path mapped by
// scale(3, 1)·transform, rasterized exactly (float coverage, no 8-bit rounding before the filter).
// The samples are taken two subpixels beyond each side of the target, because the filter reaches
// two subpixels out: a shape just outside the target still bleeds into its border subpixels.
//
// Filter: out[k] = Σ_{j=−2..2} taps[j+2] · s[k+j] / 256, rounded to 8 bits. With the default taps
// (sum 256) every sample's coverage is spread over five subpixels without loss, so a full interior
// stays 255 and the total coverage is unchanged (up to rounding) when the outline keeps
// kLcdPaddingPx display pixels from the target's sides.
//
// Order: byte 3p + k of a row is subpixel k of display pixel p, left to right (FreeType's
// FT_PIXEL_MODE_LCD layout), whatever the panel: the samples are positions on the screen, so
// the bytes do not depend on FillOptions::lcd_order, which names the colours they are (R, G, B
// on an RGB panel, B, G, R on a BGR one; image.hpp's LcdOrder). blend_lcd_mask, given the same
// order, sends each byte to its colour.
//
// Memory: the float samples are processed in bands of at most kMaxBandCells floats (the path is
// re-flattened per band, which only tall targets need), so scratch stays bounded.
#include <algorithm>
#include <cmath>
#include <string>

#include "bezel/raster.hpp"
#include "raster/fill_common.hpp"
#include "raster/overlap.hpp"

namespace bezel {

namespace {

constexpr int kFilterReach = raster_detail::kLcdFilterReach;

void filter_row(const float* samples, int width, const LcdFilter& f, std::uint8_t* out) {
    for (int k = 0; k < width; ++k) {
        // samples[k + kFilterReach] is subpixel k.
        const float* s = samples + k;
        const double v = f.taps[0] * double(s[0]) + f.taps[1] * double(s[1]) +
                         f.taps[2] * double(s[2]) + f.taps[3] * double(s[3]) +
                         f.taps[4] * double(s[4]);
        const double byte = std::min(255.0, v * (255.0 / 256.0) + 0.5);
        out[k] = static_cast<std::uint8_t>(byte);
    }
}

}  // namespace

Status Rasterizer::fill_path_lcd(const Path& path, const Affine& transform,
                                 const MaskView& target, const FillOptions& options) {
    const int W = target.width, H = target.height;
    if (Status st = raster_detail::check_lcd_target(target); !st) return st;
    const int samples_w = W + 2 * kFilterReach;
    if (!transform.is_finite()) return Error{"fill_path (LCD): transform is not finite"};
    FeatureScratch& scratch = features();
    std::vector<float>& samples = scratch.lcd_samples;

    const int band_rows = std::max(
        1, std::min(H, static_cast<int>(kMaxBandCells / static_cast<std::size_t>(samples_w))));
    const std::size_t need = static_cast<std::size_t>(band_rows) * static_cast<std::size_t>(samples_w);
    if (samples.size() < need) samples.resize(need);
    const Affine to_samples = Affine::scale(3.0, 1.0) * transform;
    for (int y0 = 0; y0 < H; y0 += band_rows) {
        const int rows = std::min(band_rows, H - y0);
        const FloatMaskView band{samples.data(), samples_w, rows, samples_w};
        const Affine m = Affine::translate({double(kFilterReach), -double(y0)}) * to_samples;
        // The first band's fill checks the path; a later band only moves the rows.
        if (Status st = fill_path_gray(path, m, band, options); !st) return st;
        for (int r = 0; r < rows; ++r)
            filter_row(band.row(r), W, options.lcd_filter, target.row(y0 + r));
    }
    return ok_status();
}

}  // namespace bezel
