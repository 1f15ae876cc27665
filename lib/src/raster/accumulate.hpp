// Private: drawing line segments as signed-area deltas into a dense accumulation band.
//
// The band is `rows` rows in groups of kGroupRows, column-major inside a group (sweep.hpp): cell
// i of row j is row_of(band, j)[i · kGroupRows]. Each group has one flag byte per block of kBlock
// columns that records "this block has deltas". After all edges are drawn, the coverage of pixel
// (i, j) is the prefix sum of cells 0..i of row j.
//
// The maths (font-rs, after libart). Take one piece of an edge inside one pixel row, going down
// by dy (signed: +dy downwards, −dy upwards — the winding direction) between x = xa and x = xb.
// It adds to each pixel i of that row dy times the fraction of the pixel that lies to the RIGHT
// of the piece; pixels wholly to the right get dy. If the piece lies inside one column i with
// mean offset m = (xa + xb)/2 − i, pixel i gets dy·(1 − m) and every pixel after it gets dy, so
// as DELTAS:  acc[i] += dy·(1 − m),  acc[i+1] += dy·m.
// A piece crossing several columns is cut at each integer x into sub-pieces with dy_k =
// s·width_k (s = dy/dx of the piece), each handled as above. Summed over a closed polygon, each
// row's deltas add to zero past the polygon, and the prefix sum is the signed coverage
// (winding-number weighted area) of each pixel.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>

#include "raster/sweep.hpp"

namespace bezel::raster_detail {

struct Band;

// Draws the full rows [r0, r1) of the steep edge x(y) = x0 + (y − y0)·dxdy, |dxdy| ≤ 1
// (inv_slope = |dy/dx|, dir = ±1 its winding sign), which covers every one of those rows whole
// and lies in [0, width] there: the cells draw_line's row-by-row loop would add.
using SteepRowsFn = void (*)(const Band& band, int r0, int r1, double x0, double y0, double dxdy,
                             double inv_slope, double dir);
// The same for an edge that stays inside column ic (two cells a row).
using StemRowsFn = void (*)(const Band& band, int r0, int r1, int ic, double x0, double y0,
                            double dxdy, double dir);
// draw_line gives a steep edge's full rows to those kernels when it has at least this many.
// The kernels draw eight rows (one group) a step, masking the rows of a partial group, so an
// edge need not cross a whole aligned group. Below 4 rows a kernel call costs more than the
// scalar rows it replaces; the first and last partial rows stay scalar, since blending their
// y and x ends in the kernel was slower at every size (the A/B is in docs/perf-log.md).
inline constexpr int kVectorMinRows = 4;
struct SteepKernels {
    SteepRowsFn steep[2];  // indexed by kMark
    StemRowsFn stems[2];
};
// Null when the CPU (or the build) has no AVX2 (draw_avx2.cpp); kernel_table() (kernels.hpp)
// says whether fills use them.
const SteepKernels* avx2_steep_kernels();

struct Band {
    float* acc;                  // kBandAlign-aligned
    std::uint8_t* flags;
    std::ptrdiff_t stride;       // floats per group, group_cells(width)
    std::ptrdiff_t flag_stride;  // bytes per group, row_flag_bytes(width)
    int width, rows;
    const SteepKernels* steep;   // kernel_table().steep, or null: every row drawn one by one
};

// Cell 0 of row j (cell i is at [i · kGroupRows]) and the flag row of j's group.
inline float* row_of(const Band& band, int j) {
    return band.acc + (j >> kGroupShift) * band.stride + (j & (kGroupRows - 1));
}
inline std::uint8_t* flags_of(const Band& band, int j) {
    return band.flags + (j >> kGroupShift) * band.flag_stride;
}
inline constexpr int kCell = kGroupRows;  // floats from one cell of a row to the next

// Marks the blocks holding cells i0..i1 (inclusive).
inline void mark_cells(std::uint8_t* frow, int i0, int i1) {
    const int b0 = i0 >> kBlockShift, b1 = i1 >> kBlockShift;
    frow[b0] = 1;
    frow[b1] = 1;
    for (int b = b0 + 1; b < b1; ++b) frow[b] = 1;
}

// Every drawing function takes kMark: true marks the blocks it writes (sparse bands, swept by
// flags); false leaves the flags alone, for a DENSE band that is swept whole (narrow boxes,
// where nearly every block has an edge anyway; SweepKernels::dense_*).

// Adds one in-row piece (xa → xb, vertical extent dy) of an edge whose dy per unit of x is
// `slope` (signed as dy) to the deltas of one row.
// Precondition: 0 ≤ xa, xb ≤ width, so indices ≤ width + 1 < stride.
template <bool kMark = true>
inline void draw_row_piece(float* row, std::uint8_t* frow, double xa, double xb, double dy,
                           double slope) {
    int i0 = static_cast<int>(xa);  // floor: xa ≥ 0
    int i1 = static_cast<int>(xb);
    if (i0 != i1) {
        if (xa > xb) {
            std::swap(xa, xb);
            std::swap(i0, i1);
        }
        if (xb == static_cast<double>(i0 + 1)) i1 = i0;  // ends on the column's right border
    }
    if (i0 == i1) {
        // One column: m = mean offset inside the pixel.
        const double right = dy * (0.5 * (xa + xb) - i0);
        row[i0 * kCell] += static_cast<float>(dy - right);
        row[(i0 + 1) * kCell] += static_cast<float>(right);
        if constexpr (kMark) {
            frow[i0 >> kBlockShift] = 1;
            frow[(i0 + 1) >> kBlockShift] = 1;
        }
        return;
    }
    // Several columns; s = dy per unit of x: the edge's slope, computed once per edge (a
    // division per row was the hottest line of wide pieces at 256 px). It is this piece's
    // dy / (xb − xa) up to rounding, so the piece's deltas add up to its dy within a few ulps.
    // The first sub-piece has width w0 = (i0+1) − xa and mean offset 1 − w0/2, so it adds
    // s·w0·(w0/2) to acc[i0] and s·w0·(1 − w0/2) to acc[i0+1]. Each full column adds s/2 to
    // itself and s/2 to the next; the last sub-piece (width w1 = xb − i1, mean offset w1/2) adds
    // s·w1·(1 − w1/2) to acc[i1] and s·w1·(w1/2) to acc[i1+1].
    const double s = slope;
    const double w0 = (i0 + 1) - xa;
    const double d0 = s * w0;
    row[i0 * kCell] += static_cast<float>(d0 * (0.5 * w0));
    double carry = d0 * (1.0 - 0.5 * w0);  // pending delta for the next column
    const double half = 0.5 * s;
    for (int i = i0 + 1; i < i1; ++i) {
        row[i * kCell] += static_cast<float>(carry + half);
        carry = half;
    }
    const double w1 = xb - i1;
    const double d1 = s * w1;
    row[i1 * kCell] += static_cast<float>(carry + d1 * (1.0 - 0.5 * w1));
    row[(i1 + 1) * kCell] += static_cast<float>(d1 * (0.5 * w1));
    if constexpr (kMark) mark_cells(frow, i0, i1 + 1);
}

// Adds c0, c1, c2 to cells i, i + 1, i + 2 of a row (marking their blocks when kMark).
template <bool kMark>
inline void add_three_cells(float* row, std::uint8_t* frow, int i, float c0, float c1, float c2) {
    float* cell = row + i * kCell;
    cell[0] += c0;
    cell[kCell] += c1;
    cell[2 * kCell] += c2;
    if constexpr (kMark) {
        frow[i >> kBlockShift] = 1;
        frow[(i + 2) >> kBlockShift] = 1;
    }
}

// One in-row piece that spans at most two columns (it crosses at most one column border: every
// piece with |xb − xa| ≤ 1, and wider ones up to 2), drawn without a branch on whether it
// crosses the border: the common piece of every steep edge, of most segments at small sizes and
// of most shallow row pieces in sparse bands.
// With lo ≤ hi its x ends, i = ⌊lo⌋ and X = i + 1, the part [lo, xm], xm = min(hi, X), lies in
// column i and the part [xm, hi] in column i + 1 (empty unless the piece crosses X). Their
// vertical extents are dy₁ (given) and dy₀ = dy − dy₁, and each adds as the one-column case of
// draw_row_piece with its own mean offset m₀ = (lo + xm)/2 − i, m₁ = (xm + hi)/2 − X:
//   acc[i] += dy₀(1 − m₀),  acc[i+1] += dy₀·m₀ + dy₁(1 − m₁),  acc[i+2] += dy₁·m₁.
// The result is continuous in dy₁, so rounding in it moves coverage by O(hi − lo) only.
// Writes cells i..i+2 ≤ width + 2 < stride (row_cells keeps three guard cells).
template <bool kMark>
inline void add_narrow_piece(float* row, std::uint8_t* frow, int i, double lo, double xm,
                             double hi, double dy, double dy1) {
    const double X = static_cast<double>(i + 1);
    const double dy0 = dy - dy1;
    const double r0 = dy0 * (0.5 * (lo + xm) - (X - 1.0));
    const double r1 = dy1 * (0.5 * (xm + hi) - X);
    add_three_cells<kMark>(row, frow, i, static_cast<float>(dy0 - r0),
                           static_cast<float>(r0 + (dy1 - r1)), static_cast<float>(r1));
}

// A narrow piece of an edge whose |dy/dx| is `inv_slope` (finite; a vertical edge passes a huge
// value, as hi − xm is then exactly 0), of vertical extent ady ≥ 0 in direction dir = ±1:
// dy₁ = dir·min((hi − xm)·|dy/dx|, ady), the min keeping it within dy where rounding makes the
// product overshoot.
template <bool kMark = true>
inline void draw_narrow_piece(float* row, std::uint8_t* frow, double xa, double xb, double ady,
                              double dir, double inv_slope) {
    const double lo = std::min(xa, xb), hi = std::max(xa, xb);
    const int i = static_cast<int>(lo);  // floor: lo > −1 (see draw_line)
    const double xm = std::min(hi, static_cast<double>(i + 1));
    const double dy1 = dir * std::min((hi - xm) * inv_slope, ady);
    add_narrow_piece<kMark>(row, frow, i, lo, xm, hi, dir * ady, dy1);
}

// Whether the in-row piece xa → xb crosses at most one column border (⌊hi⌋ ≤ ⌊lo⌋ + 1), so it
// lies in two columns and draw_narrow_piece draws it exactly, whatever its width (< 2).
inline bool within_two_columns(double xa, double xb) {
    return static_cast<int>(std::max(xa, xb)) - static_cast<int>(std::min(xa, xb)) <= 1;
}

// |dy/dx| for draw_narrow_piece, finite for a vertical edge.
inline double inverse_slope(double adx, double ady) { return ady / std::max(adx, 1e-300); }

// Rows [ja, jb) of an edge from (x0, y0) to (x1, y1) that stays inside column ic (draw_line's
// stem case), each row's piece clipped to the edge's y range; x at a row border by the formula.
template <bool kMark>
inline void draw_stem_rows(const Band& band, int ja, int jb, int ic, double x0, double y0,
                           double x1, double y1, double dxdy, double dir) {
    for (int j = ja; j < jb; ++j) {
        // The edge's first row starts at y0, even where y0 is in (−1, 0): the direct route's
        // excursions above row 0, which row 0 takes, as every other path of draw_line does.
        const double ya = j == static_cast<int>(y0) ? y0 : static_cast<double>(j);
        const double yb = std::min(y1, static_cast<double>(j + 1));
        const double xa = ya == y0 ? x0 : x0 + (ya - y0) * dxdy;
        const double xb = yb == y1 ? x1 : x0 + (yb - y0) * dxdy;
        const double dy = dir * (yb - ya);
        const double right = dy * (0.5 * (xa + xb) - ic);
        float* cell = row_of(band, j) + ic * kCell;
        cell[0] += static_cast<float>(dy - right);
        cell[kCell] += static_cast<float>(right);
        if constexpr (kMark) {
            std::uint8_t* f = flags_of(band, j);
            f[ic >> kBlockShift] = 1;
            f[(ic + 1) >> kBlockShift] = 1;
        }
    }
}

// Draws the edge (x0, y0) → (x1, y1) into the band.
// Precondition: 0 ≤ x ≤ width and 0 ≤ y ≤ rows for both ends (the caller clips); the direct
// route also passes coordinates in (−1, 0), which truncation puts in column / row 0.
//
// Three shapes, by what one row's piece can span:
//   one row, |dx| ≤ 1   a single narrow piece (small sizes: most segments);
//   steep, |dx| ≤ |dy|  each row's piece spans at most two columns: narrow pieces, x taken
//                       fresh from the end point at each row border (no drift); an edge that
//                       stays inside one column (stems) takes a cheaper two-cell loop;
//   shallow             the general row piece, which walks the columns.
template <bool kMark = true>
inline void draw_line(const Band& band, double x0, double y0, double x1, double y1) {
    if (y0 == y1) return;  // horizontal edges carry no cover (and y = rows has no row)
    double dir = 1.0;
    if (y0 > y1) {
        std::swap(x0, x1);
        std::swap(y0, y1);
        dir = -1.0;
    }
    int j = static_cast<int>(y0);  // floor (or 0 for y0 in (−1, 0))
    // Last row the edge reaches: ⌈y1⌉ − 1, and never above row j.
    int jl = static_cast<int>(y1);
    if (static_cast<double>(jl) == y1) --jl;
    jl = std::max(jl, j);
    float* row = row_of(band, j);
    std::uint8_t* frow = flags_of(band, j);
    const double dx = x1 - x0, ady = y1 - y0, adx = std::fabs(dx);
    if (j == jl) {  // inside one row: no division beyond the slope
        if (adx <= 1.0 || (kMark && within_two_columns(x0, x1)))
            draw_narrow_piece<kMark>(row, frow, x0, x1, ady, dir, inverse_slope(adx, ady));
        else
            draw_row_piece<kMark>(row, frow, x0, x1, dir * ady, dir * (ady / adx));
        return;
    }
    const double dxdy = dx / ady;
    const double xlo = std::min(x0, x1), xhi = std::max(x0, x1);
    const int ic = static_cast<int>(xlo);
    if (xhi <= static_cast<double>(ic + 1)) {
        // The whole edge stays in column ic (stems, steep edges at large sizes): each row's piece
        // adds dy·(1 − m) and dy·m at ic, ic + 1 with m the piece's mean x − ic, and m moves by
        // dxdy per full row. Only the first and last rows are partial. The full rows between
        // them go to the vector kernel when there is one and they are at least
        // kVectorMinRows.
        if (band.steep != nullptr && jl - j - 1 >= kVectorMinRows) {
            draw_stem_rows<kMark>(band, j, j + 1, ic, x0, y0, x1, y1, dxdy, dir);
            band.steep->stems[kMark](band, j + 1, jl, ic, x0, y0, dxdy, dir);
            draw_stem_rows<kMark>(band, jl, jl + 1, ic, x0, y0, x1, y1, dxdy, dir);
            return;
        }
        const double yb0 = static_cast<double>(j + 1);
        double xa = x0 + (yb0 - y0) * dxdy;  // x where the edge leaves row j
        double dy = dir * (yb0 - y0);
        double right = dy * (0.5 * (x0 + xa) - ic);
        const int b0 = ic >> kBlockShift, b1 = (ic + 1) >> kBlockShift;
        for (;;) {
            float* cell = row_of(band, j) + ic * kCell;
            cell[0] += static_cast<float>(dy - right);
            cell[kCell] += static_cast<float>(right);
            if constexpr (kMark) {
                std::uint8_t* f = flags_of(band, j);
                f[b0] = 1;
                f[b1] = 1;
            }
            ++j;
            if (j >= jl) break;
            const double xb = xa + dxdy;  // full row: dy = dir, m = mean of xa, xb
            right = dir * (0.5 * (xa + xb) - ic);
            dy = dir;
            xa = xb;
        }
        // Last row, from y = j to y1; the clamp keeps rounding from leaving the column.
        const double ya = static_cast<double>(j);
        xa = std::clamp(x0 + (ya - y0) * dxdy, xlo, xhi);
        dy = dir * (y1 - ya);
        right = dy * (0.5 * (xa + x1) - ic);
        float* cell = row_of(band, j) + ic * kCell;
        cell[0] += static_cast<float>(dy - right);
        cell[kCell] += static_cast<float>(right);
        if constexpr (kMark) {
            std::uint8_t* f = flags_of(band, j);
            f[b0] = 1;
            f[b1] = 1;
        }
        return;
    }
    double ya = y0, xa = x0;
    if (adx <= ady) {
        // Steep: a row's piece moves |dxdy| ≤ 1 in x. Interior rows are full (|dy| = 1). The
        // rows strictly between the first and the last go to the vector kernel when there is
        // one and they are at least kVectorMinRows, the first and last piece by piece; x at a
        // row border is the same formula either way.
        const double inv_slope = inverse_slope(adx, ady);
        // Rows j .. end − 1, each ending at its bottom border.
        const auto rows_to = [&](int end) {
            for (; j < end; ++j) {
                const double yb = static_cast<double>(j + 1);
                const double xb = x0 + (yb - y0) * dxdy;
                draw_narrow_piece<kMark>(row_of(band, j), flags_of(band, j), xa, xb, yb - ya,
                                         dir, inv_slope);
                ya = yb;
                xa = xb;
            }
        };
        if (band.steep != nullptr && jl - j - 1 >= kVectorMinRows) {
            rows_to(j + 1);
            band.steep->steep[kMark](band, j, jl, x0, y0, dxdy, inv_slope, dir);
            j = jl;
            ya = static_cast<double>(j);
            xa = x0 + (ya - y0) * dxdy;
        }
        rows_to(jl);
        draw_narrow_piece<kMark>(row_of(band, j), flags_of(band, j), xa, x1, y1 - ya, dir,
                                 inv_slope);
        return;
    }
    // Shallow. In sparse bands a row piece that crosses one column border or none (two thirds
    // of them at 256 px; most others cross two or three) is a narrow piece: three cells, no loop.
    // Dense bands keep the column walk: there such pieces are rare, and the extra test made the
    // small sizes slower (docs/perf-log.md).
    const double inv_slope = ady / adx;  // adx > ady > 0
    const double slope = dir * inv_slope;  // signed as the row pieces' dy
    for (; j <= jl; ++j) {
        const double yb = std::min(y1, static_cast<double>(j + 1));
        // Clamped to the edge's own x range: rounding must not push an index past the band.
        const double xb = yb == y1 ? x1 : std::clamp(x0 + (yb - y0) * dxdy, xlo, xhi);
        if (kMark && within_two_columns(xa, xb))
            draw_narrow_piece<kMark>(row_of(band, j), flags_of(band, j), xa, xb, yb - ya, dir,
                                     inv_slope);
        else
            draw_row_piece<kMark>(row_of(band, j), flags_of(band, j), xa, xb, dir * (yb - ya),
                                  slope);
        ya = yb;
        xa = xb;
    }
}

// Clips the edge to the band [0, width] × [0, rows] and draws what remains.
//   y: parts above or below the band cover nothing in it and are dropped.
//   x: the edge is clamped POINTWISE into [0, width]. Exact for pixels inside: a pixel i in
//      [0, width) gets the fraction clamp(i + 1 − x, 0, 1) of its square to the right of an edge
//      point at x, which is unchanged when x < 0 becomes 0 (both 1) or x > width becomes width
//      (both 0). So parts left of the band become a vertical edge at x = 0 (their cover still
//      counts) and parts right of it a vertical edge at x = width, which touches no pixel.
// Coordinates may be any finite doubles: interpolation uses halved differences, which cannot
// overflow.
void clip_and_draw_line(const Band& band, double x0, double y0, double x1, double y1);

// Parameter t at which a + t·(b − a) = v, for a ≠ b and v between them. Plainly when b − a is
// finite (the difference of two distinct doubles is never 0, so v − a over it is in [0, 1]);
// with halved operands only where b − a overflows (a and b huge with opposite signs, where
// b/2 − a/2 cannot). Halving always would lose subnormals: an edge from y = −2⁻¹⁰⁷⁴ to 2⁻¹⁰⁷⁴
// halves both to 0 and clipped at y = 0 gave t = 0/0 (fuzz_raster finding, regression
// tests/fuzz/regressions/fuzz_raster/subnormal-edge-clipped-at-zero).
inline double param_at(double a, double b, double v) {
    const double d = b - a;
    if (std::fabs(d) <= std::numeric_limits<double>::max()) return (v - a) / d;
    return (0.5 * v - 0.5 * a) / (0.5 * b - 0.5 * a);
}

// a + t·(b − a) for t in [0, 1], overflow-free for any finite a, b: each partial sum lies
// between a and b.
inline double lerp_safe(double a, double b, double t) {
    const double half = t * (0.5 * b - 0.5 * a);
    return a + half + half;
}

// The clipping of clip_and_draw_line for a box [0, W] × [0, H], handing each remaining piece
// (at most three, every coordinate inside the box, direction kept) to draw(xa, ya, xb, yb).
// Shared with the exact overlap pass, which needs the same bounded, overflow-free edges.
template <typename Draw>
void clip_line(double W, double H, double x0, double y0, double x1, double y1, Draw&& draw) {
    if (y0 == y1 || (y0 <= 0.0 && y1 <= 0.0) || (y0 >= H && y1 >= H)) return;

    // Clip in y, keeping the edge's direction (its winding sign).
    if (y0 < 0.0 || y0 > H || y1 < 0.0 || y1 > H) {
        const double ya = std::clamp(y0, 0.0, H), yb = std::clamp(y1, 0.0, H);
        const double xa = ya == y0 ? x0 : lerp_safe(x0, x1, param_at(y0, y1, ya));
        const double xb = yb == y1 ? x1 : lerp_safe(x0, x1, param_at(y0, y1, yb));
        x0 = xa; y0 = ya; x1 = xb; y1 = yb;
        if (y0 == y1) return;
    }

    if (x0 >= 0.0 && x0 <= W && x1 >= 0.0 && x1 <= W) {
        draw(x0, y0, x1, y1);
        return;
    }
    if (x0 >= W && x1 >= W) return;  // right of the box: touches no pixel
    if (x0 <= 0.0 && x1 <= 0.0) {     // left of the box: its cover, as a vertical edge at x = 0
        draw(0.0, y0, 0.0, y1);
        return;
    }

    // Crosses x = 0 and/or x = W: cut there (at most two cuts), then each piece is wholly left,
    // inside or right.
    struct Cut { double t, x, y; };
    Cut cuts[4];
    int n = 0;
    cuts[n++] = {0.0, x0, y0};
    for (double X : {0.0, W}) {
        if ((x0 < X && x1 > X) || (x0 > X && x1 < X)) {
            const double t = param_at(x0, x1, X);
            cuts[n++] = {t, X, std::clamp(lerp_safe(y0, y1, t), std::min(y0, y1), std::max(y0, y1))};
        }
    }
    if (n == 3 && cuts[2].t < cuts[1].t) std::swap(cuts[1], cuts[2]);
    cuts[n++] = {1.0, x1, y1};
    for (int k = 0; k + 1 < n; ++k) {
        const Cut& a = cuts[k];
        const Cut& b = cuts[k + 1];
        const double xm = 0.5 * a.x + 0.5 * b.x;
        if (xm >= W) continue;
        if (xm <= 0.0) {
            draw(0.0, a.y, 0.0, b.y);
        } else {
            draw(std::clamp(a.x, 0.0, W), a.y, std::clamp(b.x, 0.0, W), b.y);
        }
    }
}

}  // namespace bezel::raster_detail
