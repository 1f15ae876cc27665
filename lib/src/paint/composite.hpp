// Private: PaintComposite's 28 modes on one premultiplied pixel (composite.cpp has the formulas).
#pragma once

#include "bezel/paint.hpp"
#include "paint/pixel.hpp"

namespace bezel::paint_detail {

// `source` composited onto `backdrop` by `mode` (W3C Compositing and Blending Level 1), both
// premultiplied; the result is premultiplied with every channel in [0, 1].
Pixel composite(CompositeMode mode, const Pixel& source, const Pixel& backdrop);

}  // namespace bezel::paint_detail
