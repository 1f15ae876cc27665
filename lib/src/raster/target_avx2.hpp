// BEZEL_AVX2_BEGIN / BEZEL_AVX2_END: the region of a *_avx2.cpp file whose functions are
// compiled for AVX2 while the rest of the library stays baseline x86-64 (they run only after
// cpu_has_avx2() said yes).
//
// gcc: `#pragma GCC target("avx2")` between push_options and pop_options. clang ignores that
// pragma (it warns and compiles baseline code, which then cannot use the AVX2 intrinsics), so
// there the same region is `#pragma clang attribute`, which gives every function declared in it
// (lambdas and templates included) `__attribute__((target("avx2")))`. Both enable AVX2 without
// FMA: the kernels repeat baseline loops operation for operation and must not be contracted.
// Declarations included inside the region are compiled for AVX2 too, so a header included there
// must give its functions internal linkage (the linker must not pick an AVX2 copy for baseline
// callers); headers included before it stay baseline.
#pragma once

#if defined(__clang__)
#define BEZEL_AVX2_BEGIN \
    _Pragma("clang attribute push(__attribute__((target(\"avx2\"))), apply_to = function)")
#define BEZEL_AVX2_END _Pragma("clang attribute pop")
#elif defined(__GNUC__)
#define BEZEL_AVX2_BEGIN _Pragma("GCC push_options") _Pragma("GCC target(\"avx2\")")
#define BEZEL_AVX2_END _Pragma("GCC pop_options")
#endif
