// Private: the SSE2 intrinsics the raster's baseline code is written in (`_mm_*`, `__m128`,
// `__m128d`, `__m128i`).
//
// On x86-64 they are the compiler's own: every x86-64 CPU has SSE2, so this code needs no
// run-time check. Elsewhere (ARM64 and other architectures) the same names come from SIMDe
// ("SIMD Everywhere", Debian's libsimde-dev, header only), which implements each intrinsic with
// the target's vectors (NEON on ARM64) or portable C, WITH x86's results: rounding of the
// conversions to the current mode, x86's answer for NaN in min/max and for out-of-range
// conversions, the saturating packs. SIMDe's SIMDE_FAST_* options, which give those up for
// speed, are not set, so the raster computes the same values on every architecture (with
// -ffp-contract=off, set in CMakeLists.txt: ARM64 compilers would otherwise fuse a·b + c into
// one rounding where x86-64's baseline cannot, and the code's bounds and its bit-for-bit tests
// assume the operations as written).
//
// The AVX2 kernels (*_avx2.cpp) are x86-64 only and compile to nothing elsewhere; their getters
// return null there, so the baseline kernels run.
#pragma once

#if defined(__x86_64__) || defined(_M_X64)
#include <emmintrin.h>
#include <xmmintrin.h>
#else
#define SIMDE_ENABLE_NATIVE_ALIASES
#include <simde/x86/sse2.h>
#endif
