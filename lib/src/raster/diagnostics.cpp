// The raster half of bezel/diagnostics.hpp.
#include "bezel/diagnostics.hpp"

#include "raster/sweep.hpp"

namespace bezel {

const char* raster_kernel_name() { return raster_detail::best_kernels().name; }

}  // namespace bezel
