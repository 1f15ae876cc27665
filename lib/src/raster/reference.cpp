// The reference rasterizer; see reference.hpp for the formulation.
#include "raster/reference.hpp"

#include <algorithm>
#include <cmath>

namespace bezel::raster_detail {

namespace {

struct Cells {
    int width, height;
    std::vector<double> cover, area;  // height × width each
    void add(int i, int j, double dy, double m) {
        cover[static_cast<std::size_t>(j) * width + i] += dy;
        area[static_cast<std::size_t>(j) * width + i] += dy * m;
    }
};

void add_edge(Cells& cells, Point p, Point q) {
    if (p.y == q.y) return;
    const double W = cells.width, H = cells.height;
    // Parameters where the edge crosses an integer x in [0, W] or integer y in [0, H]; outside
    // those ranges nothing changes cell (left parts all fold to x = 0).
    std::vector<double> ts{0.0, 1.0};
    auto crossings = [&](double a, double b, double lo, double hi) {
        if (a == b) return;
        double k0 = std::max(lo, std::ceil(std::min(a, b)));
        double k1 = std::min(hi, std::floor(std::max(a, b)));
        for (double k = k0; k <= k1; k += 1.0) {
            double t = (k - a) / (b - a);
            if (t > 0.0 && t < 1.0) ts.push_back(t);
        }
    };
    crossings(p.x, q.x, 0.0, W);
    crossings(p.y, q.y, 0.0, H);
    std::sort(ts.begin(), ts.end());
    for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
        Point a = lerp(p, q, ts[k]), b = lerp(p, q, ts[k + 1]);
        double ym = 0.5 * (a.y + b.y), xm = 0.5 * (a.x + b.x);
        if (ym <= 0.0 || ym >= H || xm >= W) continue;
        int j = static_cast<int>(std::floor(ym));
        double dy = b.y - a.y;
        if (xm <= 0.0) {
            cells.add(0, j, dy, 0.0);
        } else {
            int i = std::min(static_cast<int>(std::floor(xm)), cells.width - 1);
            cells.add(i, j, dy, xm - i);
        }
    }
}

double apply_rule(double a, FillRule rule) {
    double v = std::fabs(a);
    if (rule == FillRule::EvenOdd) {
        v = std::fmod(v, 2.0);
        v = v > 1.0 ? 2.0 - v : v;
    }
    return std::min(v, 1.0);
}

}  // namespace

std::vector<double> reference_coverage(const Polylines& lines, FillRule rule, int width,
                                       int height, Vec2 origin) {
    std::vector<double> out(static_cast<std::size_t>(width) * height, 0.0);
    if (width <= 0 || height <= 0) return out;
    Cells cells{width, height, out, out};
    std::size_t start = 0;
    for (std::size_t end : lines.contour_ends) {
        for (std::size_t k = start; k < end; ++k) {
            std::size_t next = k + 1 < end ? k + 1 : start;  // closed implicitly
            add_edge(cells, lines.points[k] + origin, lines.points[next] + origin);
        }
        start = end;
    }
    for (int j = 0; j < height; ++j) {
        double run = 0.0;  // Σ cover of the cells to the left
        for (int i = 0; i < width; ++i) {
            std::size_t idx = static_cast<std::size_t>(j) * width + i;
            out[idx] = apply_rule(run + cells.cover[idx] - cells.area[idx], rule);
            run += cells.cover[idx];
        }
    }
    return out;
}

std::vector<unsigned char> reference_u8(const Polylines& lines, FillRule rule, int width,
                                        int height, Vec2 origin) {
    std::vector<double> c = reference_coverage(lines, rule, width, height, origin);
    std::vector<unsigned char> out(c.size());
    for (std::size_t i = 0; i < c.size(); ++i)
        out[i] = static_cast<unsigned char>(std::lround(c[i] * 255.0));
    return out;
}

}  // namespace bezel::raster_detail
