// shitsukan/geom/predicates.hpp — exact geometric predicates on doubles (orientation, in-circle).
//
// Manual
//   Vec2d a{0, 0}, b{1, 0}, c{0, 1}, d{0.5, 0.5};
//   double o = orient2d(a, b, c);     // > 0: a, b, c counter-clockwise; < 0: clockwise;
//                                     // 0: collinear
//   double s = incircle(a, b, c, d);  // a, b, c counter-clockwise: > 0 d inside their circle,
//                                     // < 0 outside, 0 exactly on it (cocircular)
// The SIGN is exact as long as no product overflows or underflows: with every coordinate 0 or
// of magnitude in [1e-50, 1e50] (what build_delaunay enforces) the degree-4 in-circle terms
// and their rounding-error terms stay normal doubles. The magnitude is only an approximation.
// Exact zero is what makes a square or triangular lattice of Voronoi seeds come out with
// exactly four (six) vertices per cell.
//
// Algorithm: J. R. Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast Robust
// Geometric Predicates" (1997): a floating-point filter with his error bounds answers almost
// every call; when the determinant is too close to zero the same determinant is evaluated
// exactly: orient2d and in-circle with exact coordinate differences with floating-point
// expansions (sums of non-overlapping doubles, Shewchuk's stage B), the general in-circle as
// 192 products of four doubles summed in two 2048-bit fixed-point integers (32-bit limbs, no
// heap, about 1.3 KB of stack; Shewchuk's full expansion product needed 37.8 KB, too much
// for a microcontroller: issue 12; ~2x slower, on the rare calls with inexact differences).
// The square lattice's cocircular case (an axis-parallel rectangle) is decided by
// comparisons before any exact stage. Every stack frame here stays under 2.4 KB.
#pragma once

#include "shitsukan/core/vec.hpp"

namespace shitsukan {

double orient2d(Vec2d a, Vec2d b, Vec2d c);
double incircle(Vec2d a, Vec2d b, Vec2d c, Vec2d d);

// The exact evaluations behind the filters (for tests and for callers who want them).
double orient2d_exact(Vec2d a, Vec2d b, Vec2d c);
double incircle_exact(Vec2d a, Vec2d b, Vec2d c, Vec2d d);

}  // namespace shitsukan
