// shitsukan/leather/edge_perturbation.hpp — tokai1994 §3.1 processing 4: every edge of the
// scale pattern bent into a pseudo-fractal curve by midpoint displacement, once per edge, so
// the two scales on its sides still fit each other.
//
// Manual
//   ScaleParams sp;  ScaleDivision steps;            // scale_division.hpp: the cells to bend
//   Status s = divide_scales(sp, steps);
//   PerturbationParams prm;             // p = 0.015 (fig. 7), 4 levels, decay 1/2
//   ScalePattern pattern;
//   PerturbationReport report;
//   std::uint32_t seed = 7;
//   if (s) s = perturb_subdivision(steps.cells, prm, seed, sp.width, sp.height, pattern, &report);
//   return s;
//   #include "shitsukan/leather/scale_division.hpp"
//
// Recursion (chosen here; the paper cites midpoint displacement without details): for an
// edge with end points A, B (taken in lexicographic order, so both neighbours agree) and unit
// normal n of the chord, offsets f along n start at f(0) = f(1) = 0; at level k = 1..L every
// segment's midpoint gets the mean of its ends plus p · decay^(k-1) · Rnd. Rnd in [-1, 1) is
// hashed from the seed, the bit patterns of A and B and the midpoint's index (core/hash.hpp),
// so the curve does not depend on which polygon asks first. Points: A + s (B - A) + f(s) n.
//
// The requested amplitude, and what keeps the tiling (chosen here; the pieces in
// perturbation_tiling.hpp, the two drivers in perturb_subdivision.cpp and perturb_two_stage.cpp). Every curve is first made
// with the requested p; only a curve that would break the tiling is scaled down, as a whole
// (offsets lambda f, lambda < 1), just enough. Each polygon is convex before perturbation; let
// c be its centroid. The fan triangles (A, B, c) over all edges of all polygons partition the
// region. A curve is accepted when (i) every point stays strictly inside `safety` times the
// height of the fan triangle on its side of the chord: curves of different edges then lie in
// disjoint triangles and cannot cross or touch (no gap, no overlap, no self-intersection: the
// curve is a graph over its chord); and (ii) seen from both centres the curve turns
// monotonically, so every polygon stays star-shaped from c. lambda is 1 when the curve fits,
// else the largest value that fits (bisection to 2^-20). Finally every polygon, rounded to
// float, must be counter-clockwise and star-shaped from its own float centroid (the relief
// step casts rays from it); a polygon that is not halves its bent edges and is checked again
// (after 12 halvings the edges go straight: the polygon is convex again). The report gives the
// RMS offset requested and realised and the number of edges scaled down. Edges on the outer
// boundary stay straight: the union of the polygons is the rectangle exactly.
// Cost: O(E 2^L) time and memory for E interior edges and L levels (x 20 for the edges that
// need the bisection).
#pragma once

#include <cstdint>
#include <vector>

#include "shitsukan/core/status.hpp"
#include "shitsukan/geom/planar_subdivision.hpp"
#include "shitsukan/leather/scale_pattern.hpp"

namespace shitsukan {

struct PerturbationParams {
    float p = 0.015f;     // given (fig. 7): first-level amplitude, pattern units (W = 1)
    int levels = 4;       // chosen: 2^4 = 16 segments per edge, smooth at 512 px
    float decay = 0.5f;   // chosen: amplitude halves with the segment (H = 1)
    float safety = 0.6f;  // chosen: share of the fan triangle's height a curve may use
    // Seamless tiling (tileable.hpp; not in the paper): periods > 0 key every edge's random
    // numbers and its canonical end order by its coordinates wrapped by these periods (a
    // period of 0: that axis is not wrapped, its coordinates only quantised), so an edge and
    // its copy one period away get the same curve although their end points differ in the
    // last bits. The key quantises to 2^-24 of the period (chosen: far below a pixel, far
    // above double rounding). Both 0 (the default): keyed by the exact bits, as the figures.
    float period_x = 0.0f, period_y = 0.0f;
};

constexpr int kMaxPerturbationLevels = 10;

struct PerturbationReport {
    int edges = 0;               // interior edges perturbed
    int shrunk = 0;              // edges scaled down (lambda < 1) to keep the tiling
    double max_offset = 0.0;     // largest realised |f| over all edges
    double requested_rms = 0.0;  // RMS offset of the curves made with the requested p
    double realised_rms = 0.0;   // RMS offset after scaling down (== requested: p honoured)
};

// Whether a-b is already in the canonical order every user of an edge's curve agrees on
// (lexicographic; with periods, by the quantised direction, see PerturbationParams).
bool edge_ends_in_order(Vec2d a, Vec2d b, const PerturbationParams& prm);

// The offsets f[0 .. 2^levels] of the edge a-b (any order: the canonical order is used inside).
// level_cap (optional, `levels` entries): the largest amplitude allowed at each level.
void midpoint_displacement(Vec2d a, Vec2d b, const PerturbationParams& prm, std::uint32_t seed,
                           double* f, const double* level_cap = nullptr);

// Perturb every interior edge of `sub` and write its polygons (counter-clockwise, float,
// centroids) into `out`, which tiles [0, width] x [0, height] when `sub` does.
Status perturb_subdivision(const PlanarSubdivision& sub, const PerturbationParams& prm,
                           std::uint32_t seed, float width, float height, ScalePattern& out,
                           PerturbationReport* report = nullptr);

// tokai1994's stage order (§3.1): the stage-1 curves are bent first and the stage-2 cells fill
// the bent stage-1 polygons. `cells` is the final (straight) subdivision of the straight
// stage-1 polygons `stage1` (cell_stage1: final polygon -> stage-1 polygon), as divide_scales
// makes it. Each stage-1 edge gets ONE curve (as in perturb_subdivision, written to
// stage1_out: fig. 5); the final polygons take the pieces of that curve between their
// junctions, the junctions moved onto it (the stage-2 edges are the straight cells' edges with
// their stage-1 ends on the curve), and each stage-2 edge then gets its own curve. So fig. 5's
// curves are fig. 7's row boundaries, point for point. The tiling is kept by the same final
// check as above, on both levels: every polygon counter-clockwise, star-shaped from its own
// float centroid and winding once (then polygons sharing their edges point for point tile the
// rectangle); a curve that breaks it is scaled down, a stage-1 curve in both patterns at once.
Status perturb_two_stage(const PlanarSubdivision& stage1, const PlanarSubdivision& cells,
                         const std::vector<int>& cell_stage1, const PerturbationParams& prm,
                         std::uint32_t seed, float width, float height, ScalePattern& stage1_out,
                         ScalePattern& out, PerturbationReport* report = nullptr);

// The same output without perturbation (p = 0): the straight polygons as a ScalePattern.
Status subdivision_to_pattern(const PlanarSubdivision& sub, float width, float height,
                              ScalePattern& out);

}  // namespace shitsukan
