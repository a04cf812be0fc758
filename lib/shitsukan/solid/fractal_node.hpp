// shitsukan/solid/fractal_node.hpp — the three rules of one recursion level (okada1987 eqs.
// (1)-(4)), written once and shared by lattice Types I, II and III.
//
// Manual
//   int R = 6;  std::int32_t x = 8, y = 0, z = 0;   // a node of a 65^3 lattice
//   std::uint32_t seed = 1987;
//   float L = level_amplitude(3, 0.9f);         // fractal_params.hpp: L_r^(n), eq. (2)
//   NodeClass c = classify_node(R, x, y, z);    // level n, half spacing h, which axes are odd
//   float g  = node_gaussian(seed, x, y, z);    // N(0, 1) of the node (hash)
//   float dv1 = 0.1f, dv2 = -0.3f;
//   float de = edge_midpoint(dv1, dv2, g * L);  // eq. (1)
//   const float edge_values[4] = {0.1f, 0.2f, -0.1f, 0.0f};
//   float dp = face_centre(edge_values, g * L); // eq. (3), four edge midpoints
//   const float face_values[6] = {0.1f, 0.2f, -0.1f, 0.0f, 0.3f, 0.05f};
//   float dc = cube_centre(face_values, g * L); // eq. (4), six face centres
//   ParentStep p = parent_step(c.odd_axes, 0);  // the parent rule, i < 2·odd_count
//   const float parents[2] = {dv1, dv2};        // read at c.half along p.axis, p.sign, ...
//   float d  = node_from_parents(c.odd_count, parents, g * L);  // eq. (1), (3) or (4)
//   #include "shitsukan/solid/fractal_params.hpp"
//
// Lattice coordinates are integers 0..2^R on each axis. A node first appears at level
// n = R - t, where 2^t is the largest power of two dividing all three coordinates (t capped
// at R; the eight corners are level 0). At that level the coordinates divided by h = 2^t
// are odd on 1 axis (an edge midpoint), 2 axes (a face centre) or 3 axes (a cube centre).
// Its parents are the neighbours at distance h along its odd axes, taken in the fixed order
// axis x-, x+, y-, y+, z-, z+. Every type sums the parents in that order with the same
// float operations, which is what makes Types I, II and III agree bit for bit.
// small-device: yes (inline, no allocation)
#pragma once

#include <cstdint>

#include "shitsukan/core/hash.hpp"

namespace shitsukan {

struct NodeClass {
    int level = 0;      // 0 for the eight initial corners, else 1..R
    int half = 0;       // h = 2^(R - level): distance to the parents
    int odd_axes = 0;   // bit 0: x, bit 1: y, bit 2: z are odd multiples of h
    int odd_count = 0;  // 1 edge midpoint, 2 face centre, 3 cube centre (0 for corners)
};

inline NodeClass classify_node(int R, std::int32_t x, std::int32_t y, std::int32_t z) {
    std::uint32_t bits = std::uint32_t(x) | std::uint32_t(y) | std::uint32_t(z) |
                         (std::uint32_t(1) << R);
    int t = 0;
    while (((bits >> t) & 1u) == 0u) ++t;  // t <= R because bit R is set
    NodeClass c;
    c.level = R - t;
    c.half = 1 << t;
    if (c.level == 0) return c;
    c.odd_axes = int((std::uint32_t(x) >> t) & 1u) | int(((std::uint32_t(y) >> t) & 1u) << 1) |
                 int(((std::uint32_t(z) >> t) & 1u) << 2);
    c.odd_count = (c.odd_axes & 1) + ((c.odd_axes >> 1) & 1) + ((c.odd_axes >> 2) & 1);
    return c;
}

// The hash stream of the lattice's random numbers (0); the 2D quadtree lattice uses 1.
constexpr std::uint32_t kLatticeStream = 0u;
constexpr std::uint32_t kQuadtreeStream = 1u;

// g ~ N(0, 1) of the node (x, y, z): the same number whoever asks first (okada1989 §3-3).
// gaussian_from_bits_float: the lattice's hot path stays in float on a single-precision FPU.
inline float node_gaussian(std::uint32_t seed, std::int32_t x, std::int32_t y, std::int32_t z) {
    return gaussian_from_bits_float(hash_coords(seed, kLatticeStream, x, y, z));
}

// The same number with the seed's hash start computed once (a lattice draws millions):
// node_gaussian_from(hash_start(seed, kLatticeStream), x, y, z) == node_gaussian(seed, x, y, z).
// The hash adds x, then y, then z (core/hash.hpp): the Type I build computes the x and (x, y)
// parts once for many nodes and draws a run's numbers together (gaussians_from_bits_float).
inline float node_gaussian_from(std::uint64_t start, std::int32_t x, std::int32_t y,
                                std::int32_t z) {
    return gaussian_from_bits_float(hash_coords_from(start, x, y, z));
}

// The parent rule, written once (Types I, II and III, the tests and example 10 all use it):
// a node that is an odd multiple of h on the axes in `odd_axes` (bit 0 x, bit 1 y, bit 2 z)
// has 2·odd_count parents, the neighbours at distance h along its odd axes, in the canonical
// order x-, x+, y-, y+, z-, z+ (even axes skipped). Parent i is one step of h along `axis` in
// direction `sign`.
struct ParentStep {
    int axis = 0;  // 0 x, 1 y, 2 z
    int sign = -1;
};

constexpr ParentStep parent_step(int odd_axes, int i) {
    int skip = i / 2, axis = 0;
    while (!((odd_axes >> axis) & 1) || skip-- > 0) ++axis;  // the (i/2)-th odd axis
    return ParentStep{axis, (i % 2) ? +1 : -1};
}

// okada1987 eq. (1): D_e = (D_v1 + D_v2)/2 + g·L_r, the edge midpoint from its two ends.
inline float edge_midpoint(float dv1, float dv2, float g_times_l) {
    return (dv1 + dv2) * 0.5f + g_times_l;
}

// okada1987 eq. (3): D_p = (1/4)·sum of the face's four EDGE MIDPOINTS (computed in step (1)
// of the same level, not the face's corners) + g·L_r.
inline float face_centre(const float edge[4], float g_times_l) {
    return (edge[0] + edge[1] + edge[2] + edge[3]) * 0.25f + g_times_l;
}

// okada1987 eq. (4): D_c = (1/6)·sum of the six face centres + g·L_r.
inline float cube_centre(const float face[6], float g_times_l) {
    return (face[0] + face[1] + face[2] + face[3] + face[4] + face[5]) / 6.0f + g_times_l;
}

// A node from its parents in parent_step's order: eq. (1), (3) or (4) by its odd-axis count.
inline float node_from_parents(int odd_count, const float* parents, float g_times_l) {
    if (odd_count == 1) return edge_midpoint(parents[0], parents[1], g_times_l);
    if (odd_count == 2) return face_centre(parents, g_times_l);
    return cube_centre(parents, g_times_l);
}

}  // namespace shitsukan
