// bezel/limits.hpp — every named limit of the library in one place: the walls hostile or runaway
// input meets instead of the memory limit or a hang (HarfBuzz's HB_*_MAX style).
//
// Each constant is DEFINED in its module's header, beside the function it guards, so that the
// module still reads on its own and existing names keep working; this header includes them all
// and is the table of record. The static_asserts below pin the table to the definitions: changing
// a limit means changing its line here too (tests/limits_test.cpp includes this header, and
// crosses every limit to check the error it gets).
//
//  limit                       value           module     why
//  --------------------------- --------------- ---------- ------------------------------------------
//  kMaxBitmapDim               16384 px        raster     largest fill target side; 16384² A8 is 256 MiB
//  kMaxImageDim                32768 px        image      largest image read (PNG header checked
//                                                         before any pixel is allocated) or allocated
//  kMaxEdges                   2^22 segments   raster     per fill, checked before work (for paths by
//                                                         Wang's bound, before flattening); ~200× the
//                                                         most complex CJK glyph at 512 px
//  kMaxBandCells               2^18 floats     raster     scratch per band (1 MiB): bounds memory,
//                                                         not what can be drawn (tall fills band)
//  kMaxFlattenDepth            16              flatten    deepest halving of one curve
//  kMaxSegmentsPerCurve        2^16            flatten    segments one curve may become, any method
//  kMaxFlattenCoordinatePx     2^50 px         flatten    beyond it no 1/8 px step exists in a double;
//                                                         keeps squares and cross products finite
//  kMaxSvgPathLength           16 MiB          path       path data bytes parse_svg_path reads
//  kMaxSvgPathPoints           2^23 points     path       parsed points (arcs expand: 16 MiB of arcs
//                                                         could otherwise ask for tens of GB)
//  kMaxCubicsPerArc            512             path       cubics per elliptical arc; error already
//                                                         below double rounding at 512
//  kMaxFontSizePx              16384 px        font       FreeType's 26.6 fixed point overflows past it
//  kMaxFaceIndex               65535           font       FreeType keeps the face in 16 bits
//  kMaxTextBytes               16 MiB          text       UTF-8 bytes one shape/layout/render call takes
//  kDefaultGlyphCacheBytes     16 MiB          text       default bound of a GlyphCache's bitmaps (LRU)
//  kMaxTextCodePoints          1000            CLI        --text of `bezel outline`: one listing each
//  kMaxIntersectWork           2^18 pairs      intersect  sub-curve pairs per segment pair; random
//                                                         cubic pairs need ≤ 34
//  kMaxPathIntersections       2^20            intersect  results per path call
//  kMaxPathSegmentPairs        2^24            intersect  box-overlapping segment pairs per path call
//  kIntersectLeafDepth         20              intersect  subdivision depth (2^-20 in parameter)
//  kMaxSmoothPoints            2^20            smooth     input points of any method (work and output
//                                                         are linear in it)
//  kMaxSmoothCoordinate        2^100           smooth     keeps phantom points, spans and products finite
//  kMaxChaikinIterations       24              smooth     each round doubles the points
//  kMaxChaikinOutputPoints     2^22            smooth     checked before any work (64 MiB)
//  kMaxStrokeSegments          2^18            stroke     output segments of one stroke
//  kMaxDashes                  2^16            stroke     dash intervals one stroke may emit
//  kMaxSurfacePatches          16384           surface    patches per surface
//  kMaxBSplineGridSide         256             surface    control points per side of a B-spline grid
//  kMaxTessellationSteps       512             surface    steps per patch side
//  kMaxMeshTriangles           2^22            surface    triangles per mesh
//  kMaxSurfaceImageDim         8192 px         surface    rendered image side
#pragma once

#include "bezel/flatten.hpp"
#include "bezel/font.hpp"
#include "bezel/image.hpp"
#include "bezel/intersect.hpp"
#include "bezel/path.hpp"
#include "bezel/raster.hpp"
#include "bezel/smooth.hpp"
#include "bezel/stroke.hpp"
#include "bezel/surface.hpp"
#include "bezel/text.hpp"

namespace bezel::limits_table {

static_assert(kMaxBitmapDim == 16384);
static_assert(kMaxImageDim == 32768);
static_assert(kMaxEdges == std::size_t{1} << 22);
static_assert(kMaxBandCells == std::size_t{1} << 18);
static_assert(kMaxFlattenDepth == 16);
static_assert(kMaxSegmentsPerCurve == std::size_t{1} << 16);
static_assert(kMaxFlattenCoordinatePx == 0x1p50);
static_assert(kMaxSvgPathLength == std::size_t{16} << 20);
static_assert(kMaxSvgPathPoints == std::size_t{1} << 23);
static_assert(kMaxCubicsPerArc == 512);
static_assert(kMaxFontSizePx == 16384.0);
static_assert(kMaxFaceIndex == 0xFFFF);
static_assert(kMaxTextBytes == std::size_t{1} << 24);
static_assert(kDefaultGlyphCacheBytes == std::size_t{1} << 24);
static_assert(kMaxIntersectWork == std::size_t{1} << 18);
static_assert(kMaxPathIntersections == std::size_t{1} << 20);
static_assert(kMaxPathSegmentPairs == std::size_t{1} << 24);
static_assert(kIntersectLeafDepth == 20);
static_assert(kMaxSmoothPoints == std::size_t{1} << 20);
static_assert(kMaxSmoothCoordinate == 0x1p100);
static_assert(kMaxChaikinIterations == 24);
static_assert(kMaxChaikinOutputPoints == std::size_t{1} << 22);
static_assert(kMaxStrokeSegments == std::size_t{1} << 18);
static_assert(kMaxDashes == std::size_t{1} << 16);
static_assert(kMaxSurfacePatches == 16384);
static_assert(kMaxBSplineGridSide == 256);
static_assert(kMaxTessellationSteps == 512);
static_assert(kMaxMeshTriangles == std::size_t{1} << 22);
static_assert(kMaxSurfaceImageDim == 8192);

}  // namespace bezel::limits_table
