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
// for a microcontroller; ~2x slower, on the rare calls with inexact differences).
// The square lattice's cocircular cases are decided before any exact stage: an axis-parallel
// rectangle by comparisons, two chords mirrored about a horizontal, vertical or diagonal line
// (an isosceles trapezoid) by exact sums of four doubles. Then a double-double evaluation
// from the exact coordinate differences (doubles, or double-doubles where the differences
// are not exact) with a proven error bound decides the nearly cocircular sets (a rounded
// lattice's); only exact zeros and what it cannot prove reach the exact sums. Every stack
// frame here stays under 2.5 KB.
// The filters are inline (the triangulation and the Voronoi cells call them millions of times;
// a call per test cost more than the test), the exact stages are not.
#pragma once

#include <cmath>

#include "shitsukan/core/vec.hpp"

namespace shitsukan {

// The exact evaluations behind the filters (for tests and for callers who want them).
double orient2d_exact(Vec2d a, Vec2d b, Vec2d c);
double incircle_exact(Vec2d a, Vec2d b, Vec2d c, Vec2d d);
// What incircle does when its filter cannot decide: the lattice rectangle and mirrored-chord
// tests, then the exact determinant from exact coordinate differences.
double incircle_unfiltered(Vec2d a, Vec2d b, Vec2d c, Vec2d d);

inline double orient2d(Vec2d a, Vec2d b, Vec2d c) {
    const double detleft = (a.x - c.x) * (b.y - c.y);
    const double detright = (a.y - c.y) * (b.x - c.x);
    const double det = detleft - detright;
    const double detsum = std::fabs(detleft) + std::fabs(detright);
    constexpr double eps = 1.1102230246251565e-16;            // 2^-53
    constexpr double errbound = (3.0 + 16.0 * eps) * eps;     // Shewchuk's ccwerrboundA
    if (std::fabs(det) >= errbound * detsum && det != 0.0) return det;
    if (detsum == 0.0) return 0.0;  // both products exactly 0 in floating point -> collinear
    return orient2d_exact(a, b, c);
}

inline double incircle(Vec2d a, Vec2d b, Vec2d c, Vec2d d) {
    const double adx = a.x - d.x, bdx = b.x - d.x, cdx = c.x - d.x;
    const double ady = a.y - d.y, bdy = b.y - d.y, cdy = c.y - d.y;
    const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
    const double alift = adx * adx + ady * ady;
    const double cdxady = cdx * ady, adxcdy = adx * cdy;
    const double blift = bdx * bdx + bdy * bdy;
    const double adxbdy = adx * bdy, bdxady = bdx * ady;
    const double clift = cdx * cdx + cdy * cdy;
    const double det =
        alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
    const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * alift +
                             (std::fabs(cdxady) + std::fabs(adxcdy)) * blift +
                             (std::fabs(adxbdy) + std::fabs(bdxady)) * clift;
    constexpr double eps = 1.1102230246251565e-16;               // 2^-53
    constexpr double errbound = (10.0 + 96.0 * eps) * eps;       // Shewchuk's iccerrboundA
    if (std::fabs(det) > errbound * permanent) return det;
    return incircle_unfiltered(a, b, c, d);
}

}  // namespace shitsukan
