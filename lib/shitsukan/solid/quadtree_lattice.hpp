// shitsukan/solid/quadtree_lattice.hpp — okada1987 §2.1 (fig. 1): the 2D random fractal
// lattice by quadtree, the height-field scheme the 3D lattice extends.
//
// Manual
//   QuadtreeParams q;                                 // R = 6: 65 x 65 heights
//   static float heights[65 * 65];
//   int side = 0;
//   Status s = build_quadtree_lattice(q, heights, sizeof heights, side);         // all levels
//   if (s) s = build_quadtree_lattice(q, heights, sizeof heights, side, 2);      // levels 1..2
//   return s;
//
// One level n (h = 2^(R-n)): each square of the previous level is cut into four, and its
// five new points get "the linear interpolation of the square's four vertices plus a
// random value" (§2.1): the four edge midpoints the mean of their edge's two ends, the
// centre the mean of the four vertices, each plus g·e^{-(n-1)·beta}. g is
// hash_gaussian(seed, 1, x, y, 0) (the lattice's hash, stream 1). Points of later levels
// hold NaN. Layout: x fastest, index y·side + x. Ranges as FractalParams: 0 <= R <= 12,
// beta >= 0, corners finite within +-kMaxFractalCorner (index i + 2j for the vertex (i, j)),
// default 0.
// small-device: yes (caller buffer, no allocation)
#pragma once

#include <cstddef>
#include <cstdint>

#include "shitsukan/core/status.hpp"

namespace shitsukan {

struct QuadtreeParams {
    int R = 6;
    float beta = 0.9f;  // as FractalParams (fractal_params.hpp gives the reason)
    std::uint32_t seed = 1987u;
    float corners[4] = {0, 0, 0, 0};
};

constexpr int kQuadtreeMaxDepth = 12;

Status build_quadtree_lattice(const QuadtreeParams& params, float* buffer,
                              std::size_t buffer_bytes, int& side, int levels = -1);

}  // namespace shitsukan
