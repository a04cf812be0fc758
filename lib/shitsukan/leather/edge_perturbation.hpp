// shitsukan/leather/edge_perturbation.hpp — tokai1994 §3.1 processing 4: every edge of the
// scale pattern bent into a pseudo-fractal curve by midpoint displacement, once per edge, so
// the two scales on its sides still fit each other.
//
// Manual
//   PerturbationParams prm;             // p = 0.015 (fig. 7), 4 levels, decay 1/2
//   ScalePattern pattern;
//   PerturbationReport report;
//   Status s = perturb_subdivision(sub, prm, seed, width, height, &pattern, &report);
//
// Recursion (chosen here; the paper cites midpoint displacement without details): for an
// edge with end points A, B (taken in lexicographic order, so both neighbours agree) and unit
// normal n of the chord, offsets f along n start at f(0) = f(1) = 0; at level k = 1..L every
// segment's midpoint gets the mean of its ends plus p · decay^(k-1) · Rnd. Rnd in [-1, 1) is
// hashed from the seed, the bit patterns of A and B and the midpoint's index (core/hash.hpp),
// so the curve does not depend on which polygon asks first. Points: A + s (B - A) + f(s) n.
//
// Bound that keeps the tiling (chosen here, and why it suffices). Each polygon is convex
// before perturbation; let c be its centroid. The fan triangles (A, B, c) over all edges of
// all polygons partition the region. Let G bound the curve's slope |f'| against its chord.
// (i) If G < tan of the four base angles of the edge's two fan triangles, the curve lies in
// the rhombus |f(s)| <= G min(s, l - s), inside the union of its two fan triangles: curves of
// different edges cannot cross or touch, so no gap, no overlap, no self-intersection.
// (ii) If moreover |s - s0| G + G min(s, l - s) < h along the chord for both neighbours (h:
// distance from c to the chord's line, s0: c's foot), the angle seen from c grows
// monotonically along the curve, so every polygon stays star-shaped from c (the relief step
// casts rays from the centroid). G = safety · min(bounds (i), (ii)), safety = 0.6.
// The slope of a midpoint-displacement curve is at most sum_k amp_k / (l / 2^k), so G is
// enforced by capping each level's amplitude: level k gets the share 2^-k / (1 - 2^-L) of
// G (coarse bends keep their amplitude, fine wiggles give way first). Edges on the outer
// boundary stay straight: the union of the polygons is the rectangle exactly.
// Cost: O(E 2^L) time and memory for E interior edges and L levels.
#pragma once

#include <cstdint>

#include "shitsukan/core/status.hpp"
#include "shitsukan/geom/planar_subdivision.hpp"
#include "shitsukan/leather/scale_pattern.hpp"

namespace shitsukan {

struct PerturbationParams {
    float p = 0.015f;     // given (fig. 7): first-level amplitude, pattern units (W = 1)
    int levels = 4;       // chosen: 2^4 = 16 segments per edge, smooth at 512 px
    float decay = 0.5f;   // chosen: amplitude halves with the segment (H = 1)
    float safety = 0.6f;  // chosen: fraction of the tiling bound actually used
};

constexpr int kMaxPerturbationLevels = 10;

struct PerturbationReport {
    int edges = 0;            // interior edges perturbed
    int clamped = 0;          // edges where some level's amplitude was capped by the bound
    double max_offset = 0.0;  // largest |f| over all edges
};

// The offsets f[0 .. 2^levels] of the edge a-b (any order: the canonical order is used inside).
// level_cap (optional, `levels` entries): the largest amplitude allowed at each level.
void midpoint_displacement(Vec2d a, Vec2d b, const PerturbationParams& prm, std::uint32_t seed,
                           double* f, const double* level_cap = nullptr);

// Perturb every interior edge of `sub` and write its polygons (counter-clockwise, float,
// centroids) into `out`, which tiles [0, width] x [0, height] when `sub` does.
Status perturb_subdivision(const PlanarSubdivision& sub, const PerturbationParams& prm,
                           std::uint32_t seed, float width, float height, ScalePattern* out,
                           PerturbationReport* report = nullptr);

// The same output without perturbation (p = 0): the straight polygons as a ScalePattern.
Status subdivision_to_pattern(const PlanarSubdivision& sub, float width, float height,
                              ScalePattern* out);

}  // namespace shitsukan
