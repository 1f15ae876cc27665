// bezel/diagnostics.hpp — introspection for benchmarks and bug reports, not needed to render.
//
// What is here describes how this build and this CPU run the library (so a benchmark result or a
// bug report can say which code produced it); nothing here changes any output.
#pragma once

#pragma GCC visibility push(default)  // the public API of libbezel.so (docs/architecture.md)
namespace bezel {

// The SIMD level of the raster's coverage sweep chosen for this CPU at run time: "avx2" or
// "sse2". A static string.
const char* raster_kernel_name();

}  // namespace bezel
#pragma GCC visibility pop
