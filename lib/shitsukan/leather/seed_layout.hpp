// shitsukan/leather/seed_layout.hpp — where the Voronoi seeds go (tokai1994 §3.1 processing 1)
// and how they move (processing 2, eq. (1): M = D·a·Rnd, Rnd uniform in [-1, 1]).
//
// Manual
//   SeedLayout s;
//   Status st = square_lattice_seeds(1, 1, 0.1f, 0.2f, 7, s);  // fig. 3 (e)-(h): x and y
//   if (st) st = triangular_lattice_seeds(1, 1, 0.1f, 0.2f, 7, s);  // fig. 3 (a)-(d)
//   Stage1SeedParams p1;                      // fig. 4: W, H, D, d, a, seed (fig. 7's values)
//   if (st) st = stage1_seeds(p1, s);
//   Stage2Columns c;
//   if (st) st = stage2_columns(1, 0.1f, 0.5f, c);       // fig. 6: W, D, edge ratio -> columns
//   if (st) st = stage2_row_seeds(c, 0.25f, 0.5, 3, 7, s);  // one row: a, y, row id, seed
//   if (!st) return st;
//   Vec2d lattice_point = s.original[0], moved = s.moved[0];  // before and after eq. (1)
//
// Parameters: width, height > 0 (the pattern rectangle [0, W] x [0, H]); D > 0 the seed
// spacing, at most 4096 seeds per row or column; a in [0, 1] the relative displacement
// (a > 0.5 lets neighbours pass each other: allowed, the Voronoi division copes); d >= 0 the
// distance of the two stage-1 seed rows from the centre line x = W / 2.
//
// Rnd is drawn from the coordinate hash of (seed, stream, lattice indices), so a seed's move
// does not depend on how many seeds were generated before it (docs/DESIGN.md: determinism).
//
// Stage-2 spacing law (chosen here; the paper only says the spacing narrows toward the left
// and right edges): with u = |x - W/2| / (W/2) in [0, 1],
//   s(u) = D · (1 - (1 - r) · u^2),   r = edge ratio (default 0.5: edge scales half as wide).
// On each side the first column lies half a spacing from the centre line (x = W/2 ± s(0)/2),
// the next ones step outward by s evaluated at the middle of each step, until one column
// lies beyond each edge; all distances (and spacings) are stretched by one common factor so
// that a column lies exactly on each edge; that column (and any beyond) is dropped, and the
// rest stretched from the centre line once more (a few percent) so that each edge lies midway
// between the last column and its mirror image about the edge (x = 0, x = W). stage2_row_seeds
// adds the mirror image of each row's outermost moved seed, as stage 1 mirrors its rows about
// y = 0 and y = H (chosen here): the border is then the Voronoi edge between a seed and its
// image, so the edge scales are whole scales, about s(1) wide like their neighbours, instead
// of halves of a cell cut by the border (0.28-0.51 of the median width on fig. 7 before). The
// centre line gets no column: it is where the left and right stage-1 polygons meet (the joint
// pattern), so scales end there instead of being cut in two. In stage 2, eq. (1) uses the
// local spacing s_k as "D", so a narrow column moves proportionally less.
#pragma once

#include <cstdint>
#include <vector>

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"

namespace shitsukan {

struct SeedLayout {
    std::vector<Vec2d> original;  // lattice points (processing 1)
    std::vector<Vec2d> moved;     // after the displacement of eq. (1) (processing 2)
};

// tokai1994 eq. (1): M = D · a · Rnd.
inline float seed_displacement(float D, float a, float rnd) { return D * a * rnd; }

// Rnd in [-1, 1) from the hash of (seed, stream, i, j).
float hashed_rnd(std::uint32_t seed, std::uint32_t stream, std::int32_t i, std::int32_t j);

// Streams of hashed_rnd, one per use.
enum SeedStream : std::uint32_t {
    kStreamLatticeX = 1,
    kStreamLatticeY = 2,
    kStreamStage1 = 3,
    kStreamStage2 = 4,
    kStreamPerturbation = 5,
};

constexpr float kDefaultEdgeRatio = 0.5f;  // chosen: stage-2 spacing at the edges = D / 2

// Square lattice (i D, j D) over the rectangle plus one ring outside it (chosen: lattice
// points on the border, so the border cuts cells through their middle, never to slivers),
// each seed moved along x and along y by independent eq. (1) displacements.
Status square_lattice_seeds(float width, float height, float D, float a, std::uint32_t seed,
                            SeedLayout& out);
// Triangular lattice: rows D·sqrt(3)/2 apart, odd rows shifted by D/2; moved along x and y.
Status triangular_lattice_seeds(float width, float height, float D, float a, std::uint32_t seed,
                                SeedLayout& out);

// Stage 1 (fig. 4): two rows parallel to y at x = W/2 - d (left) and x = W/2 + d (right),
// y = (j + 1/2) Dy for j = 0 .. N - 1, Dy = H / N, N = H / D rounded (at least 1), moved along
// y by eq. (1) with D; then two rows beyond each border, the mirror images of the two inside
// rows nearest to it (chosen here: the seeds are symmetric about y = 0 and y = H, so the
// Voronoi edges run along the border and the border rows are whole scales, 0.75-1.25 Dy high
// at a = 0.25; the paper's figs. 7-10 show no cut rows; rows centred on the border left
// 0.25-0.75 D slivers). Seed index 2 (j + 2) + side, j = -2 .. N + 1.
struct Stage1SeedParams {
    float width = 1.0f, height = 1.0f;  // the pattern region [0, W] x [0, H]
    float D = 0.1f;                     // seed spacing along y (chosen default, as ScaleParams)
    float d = 0.1f;                     // distance of each row from the centre line (fig. 7: D)
    float a = 0.25f;                    // relative displacement of eq. (1) (fig. 7)
    std::uint32_t seed = 1;
};
Status stage1_seeds(const Stage1SeedParams& prm, SeedLayout& out);

struct Stage2Columns {
    std::vector<double> x;        // column positions, increasing
    std::vector<double> spacing;  // the local spacing s_k used in eq. (1)
    std::vector<int> index;       // signed column number: -1, -2, ... left, 1, 2, ... right
    // The first and last columns are mirrored about x = left and x = right (stage2_columns:
    // the borders 0 and W); false for columns that repeat (a tileable belly) and have none.
    bool mirrored = false;
    double left = 0.0, right = 0.0;
};

// Stage 2 (fig. 6): column positions from the spacing law above.
Status stage2_columns(float width, float D, float edge_ratio, Stage2Columns& out);
float stage2_spacing(float width, float D, float edge_ratio, double x);  // s(u(x))

// One stage-2 row at height row_y: a seed on every column (side < 0: left columns only,
// side > 0: right only, 0: all), moved along x by s_k · a · Rnd; row_id selects the random
// numbers (the tokai pipeline uses the stage-1 seed index). With columns.mirrored, the first
// (last) column's seed is followed by its mirror image about x = left (x = right), original
// and moved alike.
Status stage2_row_seeds(const Stage2Columns& columns, float a, double row_y, int row_id,
                        std::uint32_t seed, SeedLayout& out, int side = 0);

}  // namespace shitsukan
