// Owning masks from views.
#include <cstring>

#include "bezel/image.hpp"

namespace bezel {

Mask to_mask(ConstMaskView view) {
    Mask m(view.width, view.height);
    for (int y = 0; y < view.height; ++y) {
        if (view.width > 0) std::memcpy(&m.at(0, y), view.row(y), static_cast<std::size_t>(view.width));
    }
    return m;
}

}  // namespace bezel
