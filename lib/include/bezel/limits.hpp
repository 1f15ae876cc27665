// bezel/limits.hpp — every named limit of the library, each stated once with its reason: the walls
// hostile or runaway input meets instead of the memory limit or a hang (HarfBuzz's HB_*_MAX
// style). Crossing one is an Error naming the input, checked before the work or the allocation it
// bounds. Module headers include this file and name the limit beside the function it guards;
// tests/limits_test.cpp crosses each one.
#pragma once

#include <cstddef>

#pragma GCC visibility push(default)  // the public API of libbezel.so (docs/architecture.md)
namespace bezel {

// --- image ------------------------------------------------------------------------------------
// Largest width or height of an image bezel reads or allocates, in pixels. A PNG claiming more is
// rejected before any pixel memory is allocated.
inline constexpr int kMaxImageDim = 1 << 15;

// --- raster -----------------------------------------------------------------------------------
// Largest fill target width or height, in pixels: a 16384² A8 target is already 256 MiB.
inline constexpr int kMaxBitmapDim = 16384;
// Most line segments one fill may have (polyline points, after flattening for paths), checked
// before any work (for paths by Wang's bound, before flattening). 4M segments is ~200× the most
// complex glyph of a CJK font at 512 px.
inline constexpr std::size_t kMaxEdges = std::size_t{1} << 22;
// The scratch accumulation buffer never exceeds this many floats (1 MiB, plus 32 bytes to align
// it); taller fills are processed in horizontal bands of whole 8-row groups. It bounds memory,
// not what can be drawn.
inline constexpr std::size_t kMaxBandCells = std::size_t{1} << 18;

// --- flatten ----------------------------------------------------------------------------------
// Deepest halving of one curve by the recursive methods: at most 2^16 pieces per curve.
inline constexpr int kMaxFlattenDepth = 16;
// Most line segments one curve may become, for every method. A curve that needs more (a curve of
// extent E pixels needs about √(E / tol) segments, so E/tol > ~10⁹) gets exactly this many, evenly
// spaced, and its bound is not met: flatten() accepts that silently, flatten_checked() reports it.
inline constexpr std::size_t kMaxSegmentsPerCurve = std::size_t{1} << kMaxFlattenDepth;
// Largest coordinate magnitude accepted after the transform: 2^50 px. Beyond it a double cannot
// hold 1/8-pixel steps, so no tolerance is meaningful, and the bound keeps every square and cross
// product in the methods far from overflow.
inline constexpr double kMaxFlattenCoordinatePx = 1125899906842624.0;  // 2^50

// --- path (SVG path data) ---------------------------------------------------------------------
// Longest path data parse_svg_path accepts, in bytes of input.
inline constexpr std::size_t kMaxSvgPathLength = std::size_t{16} << 20;  // 16 MiB
// Most points a parsed path may hold. Arcs expand into up to kMaxCubicsPerArc cubics each, so
// without this wall 16 MiB of arcs could ask for tens of gigabytes. Data without arcs never
// reaches it: a point costs at least 4 bytes (".1.1"), so 16 MiB holds at most 4 Mi points.
inline constexpr std::size_t kMaxSvgPathPoints = std::size_t{1} << 23;  // 8 Mi points, 128 MiB
// Most cubics one elliptical arc becomes. 512 cubics over a full turn already put the
// approximation error (≈ 6e-17 × radius) below double rounding, so the cap only binds when the
// requested tolerance is smaller than rounding can honour anyway.
inline constexpr int kMaxCubicsPerArc = 512;

// --- font -------------------------------------------------------------------------------------
// Largest em size accepted, in pixels: beyond it FreeType's 26.6 fixed point overflows.
inline constexpr double kMaxFontSizePx = 16384.0;
// Largest font, in bytes, a FontFace takes (a file, or bytes from memory): 1 GiB, far past any
// real font (colour emoji and CJK collections are tens of MiB), and inside the 32-bit lengths of
// HarfBuzz's blobs and sfnt table offsets.
inline constexpr std::size_t kMaxFontBytes = std::size_t{1} << 30;
// Largest face index accepted: FreeType keeps the face in the low 16 bits of its index (the
// high bits select a named instance of a variable font, which bezel does through variations).
inline constexpr int kMaxFaceIndex = 0xFFFF;
// Most sorted fallback lists one SystemFonts keeps (bezel/system_fonts.hpp), one per (pattern,
// prefer_colour, require_outlines) asked; the least recently used is dropped past it. A page uses
// a few families; each list is a sort of every font of the configuration (milliseconds with
// thousands of fonts) and holds at most one reference per font, so 32 lists save every repeat
// sort of a real document while a caller cycling through patterns cannot grow memory without end.
inline constexpr std::size_t kMaxSystemFontLists = 32;

// --- paint (colour glyphs) -----------------------------------------------------------------------
// Deepest a COLR paint graph may nest (PaintColrGlyph, PaintGlyph, transforms and composites each
// count a level): HarfBuzz's and Skia's limit too. Real emoji nest under 16; a graph that loops
// would otherwise recurse until the stack overflows, so past it the glyph is an Error.
inline constexpr int kMaxPaintDepth = 64;
// Most paint nodes one colour glyph may visit, a node shared by several parents counting at each
// visit: a DAG of depth 64 can reach 2^64 paths, so depth alone does not bound the work. The
// largest emoji of Noto's and Twitter's COLRv1 sets visit a few hundred.
inline constexpr std::size_t kMaxPaintNodes = std::size_t{1} << 16;
// Most colour stops the gradients of one colour glyph may hold in all (a gradient reached twice
// through shared paint offsets is built twice and counts twice). Each node may name 65535 stops,
// so the node budget alone would allow 2^32 of them; real gradients hold two to a dozen.
inline constexpr std::size_t kMaxPaintColorStops = std::size_t{1} << 16;
// Most outline points the PaintGlyph outlines of one colour glyph may hold in all (each glyph's
// outline is loaded once): 2^22 points, 64 MiB of Path. A COLR graph can name every glyph of the
// font; emoji hold a few thousand points.
inline constexpr std::size_t kMaxPaintOutlinePoints = std::size_t{1} << 22;
// Most bytes of one colour bitmap strike image (CBDT/sbix PNG) decoded: a 4096 × 4096 RGBA
// image. Emoji strikes are 136 or 160 px; a PNG declaring more is refused before it is decoded.
inline constexpr std::size_t kMaxColorBitmapBytes = std::size_t{64} << 20;

// --- text -------------------------------------------------------------------------------------
// Longest text one shape/layout/render call accepts, in bytes of UTF-8 (16 MiB). Past it, Error.
inline constexpr std::size_t kMaxTextBytes = std::size_t{1} << 24;
// Default bound of a GlyphCache's pixel memory (bytes of bitmaps it keeps; least recently used
// entries are evicted past it): 16 MiB, a few thousand glyphs at text sizes.
inline constexpr std::size_t kDefaultGlyphCacheBytes = std::size_t{1} << 24;
// Largest |component| of a glyph's pen offset (GlyphRenderOptions::offset_px), in pixels: with the
// outline's own extent it keeps every box coordinate, in 26.6 too, far inside int.
inline constexpr double kMaxGlyphOffsetPx = 16384.0;
// Largest synthetic slant (GlyphRenderOptions::slant): 45°; beyond it a glyph leans further than
// it is tall, which no oblique style does.
inline constexpr double kMaxSyntheticSlant = 1.0;
// Most fonts in one FontCollection, listed and found by system fallback together: each holds a
// FreeType face and a HarfBuzz face (about 100 KiB to a few MiB of tables mapped or parsed), and
// text draws from a handful; a page whose clusters would need more is refused rather than
// opening fonts without end.
inline constexpr std::size_t kMaxCollectionFonts = 64;
// Largest synthetic bold (GlyphRenderOptions::bold, ShapeOptions::bold), a fraction of the em:
// the ink grows by an eighth of the em on each side, which already fills the counter of a text
// face's lowercase o (about a quarter of the em wide); past it a glyph is a blob, not a bolder
// glyph. (HarfBuzz calls 0.01 to 0.05 typical; FreeType's FT_GlyphSlot_Embolden uses 1/24.)
inline constexpr double kMaxSyntheticBold = 0.25;

// --- intersect --------------------------------------------------------------------------------
// Deepest subdivision: parameter width 2⁻ᵏ. Pairs that still cannot be separated or isolated at
// 2⁻²⁰ (≈ 1e-6) are near-tangent and go to the tangent resolver instead of splitting further.
inline constexpr int kIntersectLeafDepth = 20;
// Most sub-curve pairs one segment pair may examine. Random cubic pairs need 4 on average and
// 34 at most (20000 pairs measured); curves that run within the touch tolerance of each other
// for a long stretch without being an overlap need the most. Exceeding it is an Error, not a
// hang (the wall is met within tens of milliseconds).
inline constexpr std::size_t kMaxIntersectWork = std::size_t{1} << 18;
// Most results intersect_paths / self_intersect_path return before giving up with an Error.
inline constexpr std::size_t kMaxPathIntersections = std::size_t{1} << 20;
// Most segment pairs with overlapping bounding boxes one path call may examine.
inline constexpr std::size_t kMaxPathSegmentPairs = std::size_t{1} << 24;

// --- smooth -----------------------------------------------------------------------------------
// Most input points (and tangents) any method accepts. Work and output are linear in the count,
// so this bounds both (a 2^20-point spline is 2^20 cubics, ~100 MB of Path).
inline constexpr std::size_t kMaxSmoothPoints = std::size_t{1} << 20;
// Largest coordinate magnitude accepted (2^100 ≈ 1.3e30, far beyond any drawing). It keeps every
// intermediate — differences, phantom points 2P₀ − P₁, squared distances, products of spans —
// finite; a result that would still overflow (e.g. chord-length spans in a ratio of 1e300) is an
// error, never a non-finite path.
inline constexpr double kMaxSmoothCoordinate = 0x1p100;
// Most Chaikin iterations. Each iteration doubles the point count, so from 21 iterations on even
// a triangle exceeds kMaxChaikinOutputPoints; after 8 the polygon's distance to the limit curve
// is already 4⁻⁸ ≈ 1.5e-5 of what it was — use chaikin_limit() for the exact curve.
inline constexpr int kMaxChaikinIterations = 24;
// Most points chaikin() may produce, checked before any work: after k rounds n points become
// n·2^k (closed, or open with kept ends) or (n−2)·2^k + 2 (open, ends cut). 4 Mi points = 64 MiB.
inline constexpr std::size_t kMaxChaikinOutputPoints = std::size_t{1} << 22;

// --- stroke -----------------------------------------------------------------------------------
// Most output segments one stroke may produce (256 Ki, about 12 MB of Path); past it, an Error
// rather than an unbounded allocation. A dashed stroke whose dashes alone would pass it (each
// dash is at least its two sides and two caps) fails before any dash is made.
inline constexpr std::size_t kMaxStrokeSegments = std::size_t{1} << 18;
// Most dash intervals one stroke or dash() may emit (64 Ki): a tiny dash over a long path is an
// Error. Stroking costs several µs per output segment, so both bounds keep one call on the worst
// inputs the fuzzer found within about a second (Release).
inline constexpr std::size_t kMaxDashes = std::size_t{1} << 16;

// --- surface ----------------------------------------------------------------------------------
// Most patches one surface may have, and the largest B-spline control grid side: bounds on work
// and memory met before anything is allocated (the Utah teapot has 32 patches).
inline constexpr std::size_t kMaxSurfacePatches = 16384;
inline constexpr int kMaxBSplineGridSide = 256;
// Most grid steps along one patch direction, and most triangles one mesh may hold.
inline constexpr int kMaxTessellationSteps = 512;
inline constexpr std::size_t kMaxMeshTriangles = std::size_t{1} << 22;
// Largest picture side, in pixels.
inline constexpr int kMaxSurfaceImageDim = 8192;

}  // namespace bezel
#pragma GCC visibility pop
