// Clipping edges to the accumulation band (the slow path; edges inside the band go straight to
// draw_line). See accumulate.hpp for why pointwise clamping in x is exact.
#include "raster/accumulate.hpp"


namespace bezel::raster_detail {

void clip_and_draw_line(const Band& band, double x0, double y0, double x1, double y1) {
    clip_line(band.width, band.rows, x0, y0, x1, y1,
              [&band](double xa, double ya, double xb, double yb) {
                  draw_line(band, xa, ya, xb, yb);
              });
}

}  // namespace bezel::raster_detail
