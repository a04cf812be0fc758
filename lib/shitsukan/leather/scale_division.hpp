// shitsukan/leather/scale_division.hpp — the crocodile-belly scale pattern of tokai1994 §3.1:
// the two-stage Voronoi division (stage 1 vertical, stage 2 horizontal inside each stage-1
// polygon) followed by the edge perturbation, delivered as a ScalePattern.
//
// Manual
//   ScaleParams prm;                        // fig. 7: d = 1.0 D, a = 0.25, p = 0.015
//   ScalePattern pattern;
//   Status s = generate_scale_pattern(prm, pattern);   // polygons tiling [0,W] x [0,H]
//   ScaleDivision steps;                    // optional: every intermediate (figs. 4-6)
//   if (s) s = generate_scale_pattern(prm, pattern, &steps);
//   return s;
//
//   Single stage (fig. 2, fig. 3): divide_single_stage(seeds, n, W, H, sub) then
//   perturb_subdivision(sub, prm.perturbation, seed, W, H, pattern).
//
// Steps (§3.1 (1), (2), each with processings 1-4):
//   stage 1: two seed rows parallel to y at distance d from the centre line, spacing D,
//            moved along y (seed_layout.hpp), Voronoi division of the rectangle;
//   stage 2: for each stage-1 polygon, one seed row parallel to x through its (moved) seed,
//            on the columns of its own half (left or right of the centre line; both when
//            d = 0), narrowing toward the left and right edges, moved along x (the
//            outermost seeds mirrored about x = 0 and x = W, chosen: whole edge scales);
//            Voronoi division clipped to that polygon. The pieces of a stage-1 edge seen
//            from its two sides are split at each other's end points (T junctions become
//            vertices), so the final polygons share every edge and form one planar
//            subdivision;
//   processing 4 in the paper's order (perturb_two_stage, edge_perturbation.hpp): each
//            stage-1 edge bent once into one curve (fig. 5), the stage-2 cells filling the
//            bent stage-1 polygons (their junctions moved onto the curves), then each stage-2
//            edge bent. Fig. 7's row boundaries are fig. 5's curves point for point. (The
//            Voronoi division of stage 2 is computed in the straight, convex stage-1 polygons
//            and carried onto the bent ones: the same cells up to the bend, and exact.)
//
// Parameters (validated, Status on error): width, height > 0 and D > 0, all three normal
// floats (subnormal sizes left gaps in the float pattern), D <= min(width, height) (chosen:
// one scale must fit across; thinner regions left rows without cells); D > 0 (chosen default 0.1: ten
// rows on the unit square); d = 0 or 1e-6 max(W, H) <= d <= W (default 1.0 D); a in [0, 1]; edge_ratio in (0.05, 1];
// perturbation.p >= 0. NaN anywhere is refused.
//
// Cost: stage 1 is one Voronoi division of n1 ~ 2 H / D seeds, O(n1 log n1); stage 2 one
// Voronoi division per stage-1 polygon (its row of k ~ W / D seeds), O(N log k) for the N
// final cells; the T-junction pass sorts the points on each stage-1 edge, O(N log N); memory
// O(N). Measured: 120 scales in ~1 ms (fig. 7), 50 000 scales (D = 0.005) in ~0.7 s.
#pragma once

#include <cstdint>
#include <vector>

#include "shitsukan/core/progress.hpp"
#include "shitsukan/core/status.hpp"
#include "shitsukan/geom/planar_subdivision.hpp"
#include "shitsukan/leather/edge_perturbation.hpp"
#include "shitsukan/leather/scale_pattern.hpp"
#include "shitsukan/leather/seed_layout.hpp"

namespace shitsukan {

// Stage-2 junctions on a stage-1 edge closer than this (times the region size) are welded.
constexpr double kWeldRelative = 1e-9;

struct ScaleParams {
    float width = 1.0f, height = 1.0f;     // the paper's square pattern region
    float D = 0.1f;                        // chosen: seed spacing, 10 rows on the unit square
    float d = 0.1f;                        // given (fig. 7): d = 1.0 D
    float a = 0.25f;                       // given (fig. 7)
    float edge_ratio = kDefaultEdgeRatio;  // chosen: stage-2 spacing at the edges / D
    PerturbationParams perturbation;       // p = 0.015 given (fig. 7); recursion chosen
    std::uint32_t seed = 1;
};

struct ScaleDivision {
    SeedLayout stage1_seeds;
    std::vector<int> stage1_row_id;  // stage-1 seed -> the row id of its stage-2 random numbers
                                     // (empty: the seed's index; tileable: its wrapped index)
    // Tileable belly (tileable.hpp), 0 otherwise: > 0, the stage-2 columns of one tile this
    // wide repeat across the region with no column on the tile's edge (a joint, like the
    // centre line), and each stage-1 polygon's side (left / right half of its tile) is its
    // row id's low bit.
    float column_period = 0.0f;
    PlanarSubdivision stage1;      // stage-1 polygons, before perturbation
    std::vector<int> stage1_site;  // stage-1 polygon -> its seed index
    Stage2Columns columns;
    SeedLayout stage2_seeds;       // every row, concatenated
    std::vector<int> stage2_row;   // stage-2 seed -> stage-1 polygon of its row
    PlanarSubdivision cells;       // final polygons, before perturbation
    std::vector<int> cell_stage1;  // final polygon -> stage-1 polygon
    ScalePattern stage1_pattern;   // the bent stage-1 polygons (fig. 5; generate_scale_pattern)
    PerturbationReport perturbation;
};

Status check_scale_params(const ScaleParams& prm);

// The memory a scale pattern needs (the byte budget of core/memory_budget.hpp), estimated
// before anything is allocated: N scales times (1024 + 128 · 2^levels) bytes (measured here:
// ~0.7 KB + 87 B · 2^levels a scale at D = 0.005 and 0.0025, levels 4 and 7, rounded up),
// with N = stage-1 rows (2 (ceil(H / D) + 3)) times the stage-2 columns a row gets
// ((W / 2) / D · atanh(sqrt(1 - r)) / sqrt(1 - r) + 2 per side, both sides when d = 0).
// generate_scale_pattern and divide_scales refuse (too_large, with the byte count) when it is
// over memory_budget().
std::uint64_t scale_pattern_bytes(const ScaleParams& prm);

// Processings 1-3 of both stages (no perturbation): stage1_seeds (seed_layout.hpp), then the
// two steps below.
Status divide_scales(const ScaleParams& prm, ScaleDivision& out);

// Stage 1, processings 1-2: the ScaleParams' share of stage1_seeds.
Stage1SeedParams stage1_seed_params(const ScaleParams& prm);

// Stage 1, processing 3: the Voronoi division of [0, W] x [0, H] by out.stage1_seeds.moved
// (fig. 4 -> the polygons of fig. 5 before their edges bend).
Status stage1_vertical_division(const ScaleParams& prm, ScaleDivision& out);

// Stage 2, processings 1-3 in every stage-1 polygon (fig. 6): its row of seeds
// (stage2_row_for_polygon: processings 1-2), the row's Voronoi division clipped to the polygon
// (stage2_divide_polygon: processing 3), then the T-junction stitching (weld_stage1_edge_points,
// stitch_t_junctions) into one planar subdivision, out.cells.
Status stage2_horizontal_division(const ScaleParams& prm, ScaleDivision& out);

// Everything: both stages, then processing 4; `steps` (optional) keeps the intermediates.
// `progress` (core/progress.hpp) hears 0.05 after stage 1, 0.5 after stage 2, 0.95 after the
// perturbation and 1 at the end.
Status generate_scale_pattern(const ScaleParams& prm, ScalePattern& pattern,
                              ScaleDivision* steps = nullptr, Progress progress = {});

// One Voronoi division of [0, W] x [0, H] (fig. 2, fig. 3): polygons with area.
Status divide_single_stage(const Vec2d* seeds, int count, float width, float height,
                           PlanarSubdivision& out, std::vector<int>* face_site = nullptr);

}  // namespace shitsukan
