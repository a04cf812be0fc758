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
// exactly with floating-point expansions (sums of non-overlapping doubles). The exact
// in-circle path needs about 40 KB of stack and no heap.
#pragma once

#include "shitsukan/core/vec.hpp"

namespace shitsukan {

double orient2d(Vec2d a, Vec2d b, Vec2d c);
double incircle(Vec2d a, Vec2d b, Vec2d c, Vec2d d);

// The exact evaluations behind the filters (for tests and for callers who want them).
double orient2d_exact(Vec2d a, Vec2d b, Vec2d c);
double incircle_exact(Vec2d a, Vec2d b, Vec2d c, Vec2d d);

}  // namespace shitsukan
