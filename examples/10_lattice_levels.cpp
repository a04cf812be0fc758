// Lesson 10: the 3D random fractal lattice, level by level (okada1987 §2.2, eqs. (1)-(5)).
// Figure: paper_figures/okada1987/fig01_02_lattice_levels.cpp.
//
// The lattice has 2^R + 1 points a side (R = 6: 65). It starts from its 8 corners; each
// level n halves the spacing and fills in, in three steps:
//   (1) every edge midpoint   = mean of the edge's 2 ends            + g·exp(-(n-1)·beta)
//   (2) every face centre     = mean of the face's 4 EDGE MIDPOINTS  + g·exp(-(n-1)·beta)
//   (3) every cube centre     = mean of the cube's 6 face centres    + g·exp(-(n-1)·beta)
// with g ~ N(0, 1). Eq. (5): the correction "value minus the mean of its parents" has mean
// 0 and standard deviation exp(-(n-1)·beta). This program builds the lattice with 1, 2, ...,
// 6 levels, measures those corrections, and writes the z = 32 slice after each level.
// Run: make examples   (10_lattice_levels.png appears in build/examples/out/)
#include <cmath>
#include <cstdio>
#include <vector>

#include "shitsukan/image/colormap.hpp"
#include "shitsukan/image/image_io.hpp"
#include "shitsukan/solid/solid.hpp"

using namespace shitsukan;

int main() {
    FractalParams params;  // R = 6, beta = 0.9, seed 1987, corners 0
    const int side = int(lattice_side(params.R));
    std::vector<float> values(std::size_t(side) * side * side);
    const int panel = 130;
    RgbImage strip(6 * panel + 5 * 4, panel, Rgb8{255, 255, 255});
    std::printf("level  spacing  new nodes  mean of eps   sd of eps   exp(-(n-1)beta)\n");
    for (int n = 1; n <= params.R; ++n) {
        LatticeView v;
        Status s =
            build_fractal_lattice(params, values.data(), values.size() * sizeof(float), v, n);
        if (!s) {
            std::fprintf(stderr, "%s\n", s.message());
            return 1;
        }
        // The corrections of this level's nodes: value - (parents' mean), recomputed with the
        // same rules as the build and g = 0.
        double sum = 0, sum2 = 0;
        long count = 0;
        for (int z = 0; z < side; ++z)
            for (int y = 0; y < side; ++y)
                for (int x = 0; x < side; ++x) {
                    const NodeClass c = classify_node(params.R, x, y, z);
                    if (c.level != n) continue;
                    const int h = c.half;
                    auto at = [&](int axis, int sign) {
                        return v.at(x + (axis == 0) * sign * h, y + (axis == 1) * sign * h,
                                    z + (axis == 2) * sign * h);
                    };
                    float parents[6];  // the parent rule (fractal_node.hpp), g = 0
                    for (int k = 0; k < 2 * c.odd_count; ++k) {
                        const ParentStep p = parent_step(c.odd_axes, k);
                        parents[k] = at(p.axis, p.sign);
                    }
                    const float mean = node_from_parents(c.odd_count, parents, 0.0f);
                    const double eps = double(v.at(x, y, z) - mean);
                    sum += eps, sum2 += eps * eps, ++count;
                }
        const double m = sum / double(count), sd = std::sqrt(sum2 / double(count) - m * m);
        std::printf("%5d  %7d  %9ld  %11.4f  %10.4f  %15.4f\n", n, 1 << (params.R - n), count, m,
                    sd, double(level_amplitude(n, params.beta)));
        // The z = 32 slice, each defined node drawn as the square it is nearest to.
        const int spacing = 1 << (params.R - n);
        for (int j = 0; j < panel; ++j)
            for (int i = 0; i < panel; ++i) {
                int x = int(std::lround(64.0 * (i + 0.5) / panel / spacing)) * spacing;
                int y = int(std::lround(64.0 * (1.0 - (j + 0.5) / panel) / spacing)) * spacing;
                strip.at((n - 1) * (panel + 4) + i, j) =
                    colormap(ColorMap::diverging, (v.at(x, y, 32) + 2.0f) / 4.0f);
            }
    }
    std::printf("(level 1 has only 19 new nodes: its sd is a rough estimate)\n");
    Status s = write_png("10_lattice_levels.png", strip.view());
    if (!s) {
        std::fprintf(stderr, "%s\n", s.message());
        return 1;
    }
    std::printf("wrote 10_lattice_levels.png (z = 32 after levels 1..6, blue -2 .. red +2)\n");
    return 0;
}
