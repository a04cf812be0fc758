// shitsukan/solid/fractal_lattice.hpp — okada1987 §2.2 / okada1989 Type I: the whole 3D
// random fractal lattice in one array, built level by level with eqs. (1)-(4).
//
// Manual
//   FractalParams p;                                   // R = 6: 65^3 points
//   static float values[65 * 65 * 65];                 // caller memory (1,098,500 bytes)
//   LatticeView lattice;
//   Status s = build_fractal_lattice(p, values, sizeof values, lattice);
//   if (!s) return s;
//   float v = lattice.at(32, 32, 32);                  // integer lattice coordinates 0..2^R
//   // stop after level 3 (okada1987 fig. 2): only nodes on a spacing-8 grid are set,
//   // the rest hold NaN
//   s = build_fractal_lattice(p, values, sizeof values, lattice, 3);
//   return s;
//
// Memory: lattice_bytes(R) = (2^R + 1)^3 · 4 bytes; O(2^{3R}) (okada1989 §2-1). A buffer
// smaller than that is refused with both byte counts in the message; R is limited to
// kTypeIMaxDepth. Layout: x fastest, then y, then z: index (z·side + y)·side + x.
// Order of one level n (h = 2^(R-n)): step (1) all edge midpoints, step (2) all face
// centres, step (3) all cube centres; within a step pattern by pattern (which axes are odd:
// x, y, z for edges; xy, xz, yz for faces). With NoiseSource::sequential each pattern scans
// z, y, x upwards and the numbers g are drawn from Pcg32(seed) in exactly that order. With
// NoiseSource::hash (g a function of the node) the order within a step changes nothing: the
// nodes of a step depend only on older ones.
// small-device: yes (caller buffer, no allocation)
#pragma once

#include <cstddef>
#include <cstdint>

#include "shitsukan/core/status.hpp"
#include "shitsukan/solid/fractal_params.hpp"

namespace shitsukan {

// A read-only view of a Type I lattice array (it does not own the values).
struct LatticeView {
    const float* values = nullptr;
    int R = 0;
    int side = 0;  // 2^R + 1

    float at(int x, int y, int z) const {
        return values[(std::size_t(z) * std::size_t(side) + std::size_t(y)) * std::size_t(side) +
                      std::size_t(x)];
    }
};

// Builds levels 1..levels (all R levels when levels < 0) into buffer. Nodes of later levels
// are set to NaN so that a partial lattice cannot be mistaken for a finished one.
Status build_fractal_lattice(const FractalParams& params, float* buffer, std::size_t buffer_bytes,
                             LatticeView& out, int levels = -1);

}  // namespace shitsukan
