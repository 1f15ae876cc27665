// GammaTable: a coverage-to-alpha map for compositors that blend in a non-linear space.
//
// Formula, for coverage c in 0..255, x = c/255:
//   g   = x^(1/gamma)                        (gamma > 1 lifts mid coverage, as light-on-dark
//                                             text needs when blending sRGB bytes)
//   y   = g + contrast · g · (1 − g)         (an extra, symmetric lift of the middle)
//   out = round(255 · y)
// Properties: 0 → 0 and 255 → 255 for every setting; identity at gamma 1, contrast 0; monotone
// non-decreasing, because dy/dg = 1 + contrast·(1 − 2g) ≥ 1 − contrast ≥ 0 for g in [0, 1] and
// contrast ≤ 1, and g is increasing in x.
// Out-of-range settings are clamped rather than rejected (the constructor cannot fail): a gamma
// that is not a finite number > 0 is taken as 1, contrast is clamped to [0, 1] (NaN → 0).
#include <algorithm>
#include <cmath>

#include "bezel/raster.hpp"

namespace bezel {

GammaTable::GammaTable(double gamma, double contrast) {
    if (!(gamma > 0.0) || !std::isfinite(gamma)) gamma = 1.0;
    contrast = contrast > 0.0 ? std::min(contrast, 1.0) : 0.0;
    for (int c = 0; c < 256; ++c) {
        const double g = std::pow(c / 255.0, 1.0 / gamma);
        const double y = g + contrast * g * (1.0 - g);
        table_[static_cast<std::size_t>(c)] =
            static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(y, 0.0, 1.0)));
    }
}

void GammaTable::apply(const MaskView& mask) const {
    if (mask.data == nullptr) return;
    for (int y = 0; y < mask.height; ++y) {
        std::uint8_t* row = mask.row(y);
        for (int x = 0; x < mask.width; ++x) row[x] = table_[row[x]];
    }
}

}  // namespace bezel
