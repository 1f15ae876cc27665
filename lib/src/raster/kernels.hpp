// Private: the one run-time choice of the rasterizer's kernels.
//
// The pipeline is the same on every CPU (docs/rasterizer.md, "How fill_path renders a glyph");
// only the kernels of three steps have an AVX2 form: the segment batches, the full rows of long
// steep edges and stems, and the sweep. Their baseline forms
// (x86-64's SSE2, or SIMDe's translation of it elsewhere) run everywhere. The table is chosen
// once, the first time a fill asks: the AVX2 table when the CPU has AVX2, else the baseline.
// Each AVX2 kernel is tested against its baseline form (bit for bit where the baseline is the
// same arithmetic, within float rounding where not) and every sweep against the scalar
// reference (scalar_kernels(), sweep.hpp); tests/raster_test.cpp RasterKernels.*.
#pragma once

#include "raster/accumulate.hpp"
#include "raster/draw_batch.hpp"
#include "raster/sweep.hpp"

namespace bezel::raster_detail {

struct KernelTable {
    const char* name;                 // "sse2" or "avx2"
    const SweepKernels* sweep;        // never null
    const SteepKernels* steep;        // null: long steep edges drawn row by row
    const BatchKernels* batch;        // null: the baseline batch loops (draw_batch.hpp)
};

// The baseline table: SSE2 sweeps, every other kernel null.
const KernelTable& baseline_table();
// The AVX2 table; null when the CPU (or the build) has no AVX2.
const KernelTable* avx2_table();
// The table fills use, chosen once.
const KernelTable& kernel_table();

}  // namespace bezel::raster_detail
