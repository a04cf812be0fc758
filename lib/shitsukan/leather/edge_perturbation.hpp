// shitsukan/leather/edge_perturbation.hpp — tokai1994 §3.1 processing 4: every edge of the
// scale pattern bent into a pseudo-fractal curve by midpoint displacement, once per edge, so
// the two scales on its sides still fit each other.
//
// Manual
//   PerturbationParams prm;             // p = 0.015 (fig. 7), 4 levels, decay 2^-1/2
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
// all polygons partition the region. Let G = max |f'| (the curve's largest slope against its
// chord). If G < tan of the four base angles of the edge's two fan triangles, the curve lies
// in the rhombus |f(s)| <= G min(s, l - s) inside the union of its two fan triangles, so
// curves of different edges cannot cross and each polygon keeps its neighbours. If moreover
// G (l/2 + L) < h for both neighbours (h: distance from c to the chord's line, L: largest
// distance along the chord from c's foot to A or B), the angle seen from c grows monotonically
// along the curve, so every polygon stays star-shaped from its old centroid (what the relief
// step needs). The curve is scaled down when needed to G = safety · min(those bounds), safety
// = 0.5. Edges on the outer boundary stay straight: the union stays the rectangle exactly.
#pragma once

#include <cstdint>

#include "shitsukan/core/status.hpp"
#include "shitsukan/geom/planar_subdivision.hpp"
#include "shitsukan/leather/scale_pattern.hpp"

namespace shitsukan {

struct PerturbationParams {
    float p = 0.015f;             // given (fig. 7): first-level amplitude, pattern units (W = 1)
    int levels = 4;               // chosen: 2^4 = 16 segments per edge, smooth at 512 px
    float decay = 0.70710678f;    // chosen: 2^-1/2 per level (Brownian, H = 1/2)
    float safety = 0.5f;          // chosen: fraction of the tiling bound actually used
};

constexpr int kMaxPerturbationLevels = 10;

struct PerturbationReport {
    int edges = 0;            // interior edges perturbed
    int clamped = 0;          // edges whose curve was scaled down to the bound
    double max_offset = 0.0;  // largest |f| over all edges
};

// The offsets f[0 .. 2^levels] of the edge a-b (any order: the canonical order is used inside),
// before the bound. Returns false for bad parameters.
void midpoint_displacement(Vec2d a, Vec2d b, const PerturbationParams& prm, std::uint32_t seed,
                           double* f);

// Perturb every interior edge of `sub` and write its polygons (counter-clockwise, float,
// centroids) into `out`, which tiles [0, width] x [0, height] when `sub` does.
Status perturb_subdivision(const PlanarSubdivision& sub, const PerturbationParams& prm,
                           std::uint32_t seed, float width, float height, ScalePattern* out,
                           PerturbationReport* report = nullptr);

// The same output without perturbation (p = 0): the straight polygons as a ScalePattern.
Status subdivision_to_pattern(const PlanarSubdivision& sub, float width, float height,
                              ScalePattern* out);

}  // namespace shitsukan
