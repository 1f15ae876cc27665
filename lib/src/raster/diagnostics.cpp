// The raster half of bezel/diagnostics.hpp.
#include "bezel/diagnostics.hpp"

#include "raster/kernels.hpp"

namespace bezel {

const char* raster_kernel_name() { return raster_detail::kernel_table().name; }

}  // namespace bezel
