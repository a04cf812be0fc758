// Lesson 16: the random fractal lattice's rules written out (okada1987 §2, eqs. (1)-(4)),
// on fig. 1's 2D quadtree and on one 3D step (figs. 2-5).
// Figure: okada1987 figs. 1 and 2 (paper_figures/okada1987/fig01_02_lattice_levels.cpp).
//
// Lesson 10 calls the library; here every rule is a line of this file. Fig. 1 (§2.1): a
// square's four vertices hold values; cut it into four, and each of the five new points gets
// "the linear interpolation of the four vertices plus a random value":
//   an edge midpoint  = (its edge's two ends) / 2       + g·L(n)       (eq. (1) in 2D)
//   the square centre = (the square's four vertices) / 4 + g·L(n)      (bilinear at the centre)
//   L(n) = exp(-(n-1)·beta)                                            (eq. (2))
// with g ~ N(0, 1). Repeat on every small square down to the unit spacing: level n has
// spacing 2^(R-n). In 3D (§2.2) each level has three steps instead of two:
//   (1) edge midpoints  = mean of the edge's 2 ends              + g·L(n)   eq. (1)
//   (2) face centres    = mean of the face's 4 EDGE MIDPOINTS    + g·L(n)   eq. (3)
//   (3) cube centres    = mean of the cube's 6 face centres      + g·L(n)   eq. (4)
// (eq. (3) averages what step (1) just made, not the face's corners: the 2D square centre
// above is the one place the paper says "vertices").
//
// g must be the library's number for the same point (a hash of the coordinates,
// core/hash.hpp) for the comparison to mean anything: the program checks its 65 x 65 heights
// against build_quadtree_lattice and its 5^3 lattice against build_fractal_lattice, bit for
// bit, and writes the height field as 16_lattice_rules.png.
// Run: make examples   (the PNG appears in build/examples/out/)
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "shitsukan/core/detmath.hpp"
#include "shitsukan/core/gaussian.hpp"
#include "shitsukan/core/hash.hpp"
#include "shitsukan/image/colormap.hpp"
#include "shitsukan/image/image_io.hpp"
#include "shitsukan/solid/fractal_lattice.hpp"
#include "shitsukan/solid/fractal_node.hpp"
#include "shitsukan/solid/quadtree_lattice.hpp"

using namespace shitsukan;

namespace {

// eq. (2): L(n) = exp(-(n-1)·beta), level 1 at amplitude 1 (the library's reading).
float amplitude(int n, float beta) { return float(det_exp(-double(n - 1) * double(beta))); }

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Fig. 1: the 2D quadtree, level by level. Returns the (2^R + 1)^2 heights, x fastest.
std::vector<float> quadtree_by_hand(int R, float beta, std::uint32_t seed) {
    const int side = (1 << R) + 1;
    std::vector<float> z(std::size_t(side) * side, 0.0f);  // the four corners start at 0
    auto at = [&](int x, int y) -> float& { return z[std::size_t(y) * side + x]; };
    std::printf("fig. 1, R = %d: level  spacing  new points  sd of the corrections  L(n)\n", R);
    for (int n = 1; n <= R; ++n) {
        const int h = 1 << (R - n);  // half the old square's side: the new spacing
        const float L = amplitude(n, beta);
        auto g = [&](int x, int y) { return hash_gaussian(seed, kQuadtreeStream, x, y) * L; };
        double sum2 = 0.0;
        int count = 0;
        // Each old square's four edge midpoints (an edge shared by two squares is done once):
        // (x, y) lies on a horizontal edge when x is an odd multiple of h and y an even one.
        for (int y = 0; y < side; y += h)
            for (int x = 0; x < side; x += h) {
                const bool odd_x = (x / h) % 2 == 1, odd_y = (y / h) % 2 == 1;
                if (odd_x == odd_y) continue;  // a vertex or a centre, not an edge midpoint
                const float ends = odd_x ? (at(x - h, y) + at(x + h, y))
                                         : (at(x, y - h) + at(x, y + h));
                const float e = g(x, y);
                at(x, y) = ends * 0.5f + e;
                sum2 += double(e) * e, ++count;
            }
        // Each old square's centre from its four vertices.
        for (int y = h; y < side; y += 2 * h)
            for (int x = h; x < side; x += 2 * h) {
                const float e = g(x, y);
                at(x, y) = (at(x - h, y - h) + at(x + h, y - h) + at(x - h, y + h) +
                            at(x + h, y + h)) * 0.25f + e;
                sum2 += double(e) * e, ++count;
            }
        std::printf("                 %d  %7d  %10d  %20.4f  %.4f\n", n, h, count,
                    std::sqrt(sum2 / count), double(L));
    }
    return z;
}

// Figs. 2-5: the 3D lattice of 2^R + 1 points a side, the three steps of each level.
// Parents are summed in the order x-, x+, y-, y+, z-, z+ (the library's order, so the float
// sums round the same way).
std::vector<float> lattice_by_hand(int R, float beta, std::uint32_t seed) {
    const int side = (1 << R) + 1;
    std::vector<float> v(std::size_t(side) * side * side, 0.0f);  // eight corners 0
    auto at = [&](int x, int y, int z) -> float& {
        return v[(std::size_t(z) * side + y) * side + x];
    };
    for (int n = 1; n <= R; ++n) {
        const int h = 1 << (R - n);
        const float L = amplitude(n, beta);
        // steps (1), (2), (3): the nodes that are odd multiples of h on 1, 2, 3 axes
        for (int odd_wanted = 1; odd_wanted <= 3; ++odd_wanted)
            for (int z = 0; z < side; z += h)
                for (int y = 0; y < side; y += h)
                    for (int x = 0; x < side; x += h) {
                        const int c[3] = {x, y, z};
                        float parents[6];
                        int k = 0;
                        for (int axis = 0; axis < 3; ++axis) {
                            if ((c[axis] / h) % 2 == 0) continue;  // an even axis: no parent
                            int lo[3] = {x, y, z}, hi[3] = {x, y, z};
                            lo[axis] -= h, hi[axis] += h;
                            parents[k++] = at(lo[0], lo[1], lo[2]);
                            parents[k++] = at(hi[0], hi[1], hi[2]);
                        }
                        if (k != 2 * odd_wanted) continue;
                        const float e =
                            gaussian_from_bits_float(hash_coords(seed, kLatticeStream, x, y, z)) * L;
                        float d;
                        if (k == 2)  // eq. (1): edge midpoint
                            d = (parents[0] + parents[1]) * 0.5f + e;
                        else if (k == 4)  // eq. (3): the four edge midpoints of step (1)
                            d = (parents[0] + parents[1] + parents[2] + parents[3]) * 0.25f + e;
                        else  // eq. (4): the six face centres of step (2)
                            d = (parents[0] + parents[1] + parents[2] + parents[3] +
                                 parents[4] + parents[5]) / 6.0f + e;
                        at(x, y, z) = d;
                    }
    }
    return v;
}

}  // namespace

int main() {
    const int R = 6;
    const float beta = 0.9f;            // the library's default (solid/fractal_params.hpp)
    const std::uint32_t seed = 1987u;

    // ---- fig. 1: the 2D quadtree ----
    const std::vector<float> mine = quadtree_by_hand(R, beta, seed);
    QuadtreeParams q;
    q.R = R, q.beta = beta, q.seed = seed;
    std::vector<float> library(mine.size());
    int side = 0;
    Status s = build_quadtree_lattice(q, library.data(), library.size() * sizeof(float), side);
    if (!s) {
        std::fprintf(stderr, "16_lattice_rules: %s\n", s.message());
        return 1;
    }
    int differ = 0;
    for (std::size_t i = 0; i < mine.size(); ++i) differ += !same_bits(mine[i], library[i]);
    std::printf("2D: %zu heights written out here, %d differ from build_quadtree_lattice\n",
                mine.size(), differ);

    // ---- figs. 2-5: one 3D lattice, R = 2 (5^3 points, two levels) ----
    const int R3 = 2;
    const std::vector<float> mine3 = lattice_by_hand(R3, beta, seed);
    FractalParams p;
    p.R = R3, p.beta = beta, p.seed = seed;
    std::vector<float> buffer(mine3.size());
    LatticeView view;
    s = build_fractal_lattice(p, buffer.data(), buffer.size() * sizeof(float), view);
    if (!s) {
        std::fprintf(stderr, "16_lattice_rules: %s\n", s.message());
        return 1;
    }
    int differ3 = 0;
    for (std::size_t i = 0; i < mine3.size(); ++i) differ3 += !same_bits(mine3[i], view.values[i]);
    std::printf("3D: %zu nodes written out here, %d differ from build_fractal_lattice\n",
                mine3.size(), differ3);

    // ---- the height field, 4 pixels a point ----
    float lo = mine[0], hi = mine[0];
    for (float z : mine) lo = z < lo ? z : lo, hi = z > hi ? z : hi;
    const int scale = 4;
    RgbImage image(side * scale, side * scale);
    for (int y = 0; y < side * scale; ++y)
        for (int x = 0; x < side * scale; ++x) {
            const float z = mine[std::size_t(y / scale) * side + x / scale];
            image.at(x, side * scale - 1 - y) = colormap(ColorMap::perceptual, (z - lo) / (hi - lo));
        }
    s = write_png("16_lattice_rules.png", image.view());
    if (!s) {
        std::fprintf(stderr, "16_lattice_rules: %s\n", s.message());
        return 1;
    }
    std::printf("wrote 16_lattice_rules.png (%d x %d, heights %.3f .. %.3f)\n", side * scale,
                side * scale, double(lo), double(hi));
    return differ == 0 && differ3 == 0 ? 0 : 1;
}
