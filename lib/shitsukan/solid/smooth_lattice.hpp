// shitsukan/solid/smooth_lattice.hpp — a smoother refinement of the okada1987 lattice for
// texture output (chosen here; the paper figures keep eqs. (1)-(4) and (6)): the same random
// displacements g·L(n) at the same nodes, but each new node predicted by a cubic through four
// nodes instead of the mean of its two parents, so no crease runs along the node planes of
// the early levels and a tileable slice shows no seam line.
//
// Manual
//   FractalParams p;                              // R = 6, beta 0.9, hash noise
//   PeriodicLattice periodic;
//   Status s = periodic.build(p);
//   SmoothLattice smooth;
//   if (s) s = smooth.build(periodic.view(), LatticeWrap::periodic);
//   if (!s) return s;
//   float d = periodic_turbulence(smooth.view(), Vec3{70.5f, -3.0f, 10.0f});  // eq. (6) on it
//   FractalLattice type1;
//   s = type1.build(p);
//   if (s) s = smooth.build(type1.view(), LatticeWrap::clamp);                // a Type I one
//   return s;
//   #include "shitsukan/solid/lattice_store.hpp"
//   #include "shitsukan/solid/periodic_lattice.hpp"
//   #include "shitsukan/solid/turbulence.hpp"
//
// Why: a node of level n is the mean of its parents plus g·L(n) (eqs. (1), (3), (4)), so
// between the nodes of level n the values are linear in the coarse part: D(P) = eq. (6) of
// the lattice is piecewise linear at the scale of level 1 with a kink on the planes x, y or
// z = 2^(R-1) (and weaker ones at every later level). A vein displaced by k·D (eq. (9)) bends
// there, and a tileable slice (the whole period) has such a plane at its border and centre.
// How: the displacement of each node is recovered from the built lattice, d = V(node) - the
// mean of its parents (fractal_node.hpp's rule), then the lattice is rebuilt level by level
// with W(node) = the mean over its odd axes of the four-point cubic (-1, 9, 9, -1)/16 through
// W at -3h, -h, +h, +3h along that axis, plus d. Near the faces (LatticeWrap::clamp) a
// missing outer point gives the quadratic (-1, 6, 3)/8 through the three there, two missing
// the mean of the parents (eq. (1)); LatticeWrap::periodic reads across the faces (coordinates
// modulo 2^R), so the nodes on opposite faces stay equal bit for bit. The eight corners keep
// their values. The result is a lattice of the same size that eq. (6) interpolates as
// before; its kinks are only those of the last level, one lattice unit apart, at the last
// level's amplitude L(R).
// Errors: an empty view or one whose side is not 2^R + 1 -> invalid_argument; the memory
// budget (lattice_bytes(R)) -> too_large. Host side (owns a std::vector).
#pragma once

#include <vector>

#include "shitsukan/core/status.hpp"
#include "shitsukan/solid/fractal_lattice.hpp"

namespace shitsukan {

enum class LatticeWrap { clamp, periodic };

class SmoothLattice {
public:
    Status build(const LatticeView& source, LatticeWrap wrap);
    LatticeView view() const;  // aborts if build() failed or was never called
    bool empty() const { return values_.empty(); }

private:
    std::vector<float> values_;
    LatticeView view_;
};

}  // namespace shitsukan
