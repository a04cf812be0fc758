// shitsukan/solid/periodic_lattice.hpp — a seamless (periodic) okada1987 random fractal
// lattice: opposite faces equal at every level, so slices and volumes of the solid texture
// tile with no seam. Exact, not blended.
//
// Manual
//   FractalParams p;                                // R = 6, beta 0.9, hash noise
//   PeriodicLattice lattice;
//   Status s = lattice.build(p);                    // (2^R + 1)^3 floats, like Type I
//   if (!s) return s;
//   float d = periodic_turbulence(lattice.view(), Vec3{70.5f, -3.0f, 10.0f});  // any point
//   Vec3 p3{-5.0f, 130.0f, 7.5f};
//   Vec3 q = wrap_lattice_point(p3, lattice.view().R);   // into [0, 2^R)^3
//   // solid_density(material, lattice.view(), q) then tiles when the material's pattern is
//   // periodic with a period dividing 2^R (marble with layer_period = 2^R / n, see below).
//
// How (the same eqs. (1)-(4) as fractal_lattice.hpp, level by level, step by step): the
// random number g of a node is drawn for its coordinates taken modulo N = 2^R,
// node_gaussian(seed, x mod N, y mod N, z mod N), and the eight initial corners are one
// value (corners[0]). A node on the face x = N then gets the same g as its twin on x = 0, and
// its parents (at distance h along its odd axes, all on that face) are by induction over
// the levels the twins of the x = 0 node's parents: every value on x = N equals the one on
// x = 0 bit for bit, for each axis. Trilinear D(P) (eq. (6)) of the lattice repeated every N
// is then continuous everywhere; inside one period it is the same field as a Type I lattice
// (interior nodes draw the same g).
// What tiles: D itself; marble whose stripes repeat with a period dividing N along the slice
// (okada1989's layer_period: tileable_layer_period() picks the nearest such period); wood's
// rings are concentric about an axis and do not repeat, so a wood slice does not tile.
// Errors: what validate_fractal_params refuses (R in [0, kTypeIMaxDepth]), NoiseSource::
// sequential (a stream has no twins: use hash noise), corners that are not all equal,
// a budget below lattice_bytes(R) (too_large).
// Host side (owns a std::vector).
#pragma once

#include <cstdint>
#include <vector>

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"
#include "shitsukan/solid/fractal_lattice.hpp"
#include "shitsukan/solid/lattice_store.hpp"

namespace shitsukan {

class PeriodicLattice {
public:
    Status build(const FractalParams& params, std::uint64_t budget_bytes = kDefaultLatticeBudget);
    LatticeView view() const;  // aborts if build() failed or was never called
    bool empty() const { return values_.empty(); }

private:
    std::vector<float> values_;
    LatticeView view_;
};

// Each coordinate reduced into [0, 2^R): t - 2^R·floor(t / 2^R). NaN becomes 0.
Vec3 wrap_lattice_point(Vec3 p, int R);

// D(P) of the lattice repeated every 2^R along each axis (eq. (6) after wrapping).
float periodic_turbulence(const LatticeView& lattice, Vec3 p);

// The layer period closest to `period` that divides 2^R (2^R / n, n >= 1 the nearest whole
// number of layers): okada1989 marble with it tiles along z.
float tileable_layer_period(float period, int R);

}  // namespace shitsukan
