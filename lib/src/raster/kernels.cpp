// The kernel table; see kernels.hpp.
#include "raster/kernels.hpp"

namespace bezel::raster_detail {

const KernelTable& baseline_table() {
    static const KernelTable t{"sse2", &sse2_kernels(), nullptr, nullptr};
    return t;
}

const KernelTable* avx2_table() {
    // Each part is null without AVX2; all three come from the same cpu_has_avx2() answer.
    static const KernelTable t{"avx2", avx2_kernels(), avx2_steep_kernels(), avx2_batch_kernels()};
    return t.sweep != nullptr ? &t : nullptr;
}

const KernelTable& kernel_table() {
    static const KernelTable& t = avx2_table() != nullptr ? *avx2_table() : baseline_table();
    return t;
}

}  // namespace bezel::raster_detail
