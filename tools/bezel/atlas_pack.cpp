#include "atlas_pack.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

namespace bezel::cli {

Expected<AtlasPacking> pack_shelves(const std::vector<AtlasRect>& sizes, int max_dim) {
    const long long pad = kAtlasPaddingPx;
    long long area = 0, widest = 0;
    for (const AtlasRect& r : sizes) {
        if (r.width == 0 || r.height == 0) continue;
        area += (r.width + pad) * (r.height + pad);
        widest = std::max<long long>(widest, r.width + 2 * pad);
    }
    long long width = 1;
    while (width * width < area || width < widest) width *= 2;
    if (width > max_dim)
        return Error{"atlas would be " + std::to_string(width) + " px wide, more than " +
                     std::to_string(max_dim)};

    std::vector<std::size_t> order(sizes.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return sizes[a].height > sizes[b].height;
    });
    AtlasPacking out;
    out.rects.resize(sizes.size());
    // Invariant: (x, y) is the next free corner; columns [0, pad) and rows [0, pad) stay empty.
    long long x = pad, y = pad, shelf = 0;
    for (std::size_t i : order) {
        const AtlasRect& r = sizes[i];
        if (r.width == 0 || r.height == 0) continue;
        if (x + r.width + pad > width) {
            y += shelf + pad;
            x = pad;
            shelf = 0;
        }
        out.rects[i] = {static_cast<int>(x), static_cast<int>(y), r.width, r.height};
        x += r.width + pad;
        shelf = std::max<long long>(shelf, r.height);
        if (y + shelf + pad > max_dim)
            return Error{"atlas would be more than " + std::to_string(max_dim) + " px tall"};
    }
    out.width = static_cast<int>(width);
    out.height = static_cast<int>(std::max<long long>(1, y + shelf + pad));
    return out;
}

}  // namespace bezel::cli
