// shitsukan/leather/tileable.hpp — seamless tiling (not in tokai1994): the scale
// patterns of §3.1 on a torus, so the height, normal and colour maps of §3.2 repeat with no
// seam. Exact, not blended: the same Voronoi division, the same two-stage division and the
// same edge perturbation on both sides of every seam.
//
// Manual
//   #include "shitsukan/leather/maps.hpp"
//
//   TileParams tp;                          // the crocodile belly (fig. 7's d, a, p)
//   tp.layout = TileLayout::belly;          // tiles along x and y (the tile edge: a joint)
//   ScalePattern torus;
//   TileReport rep;
//   Status s = generate_tileable_pattern(tp, torus, &rep);   // rep.Dx, rep.Dy: spacing used
//   LeatherMaps maps;                       // maps.hpp: a wrapped pattern is covered first
//   if (s) s = make_leather_maps(torus, 128, 128, table1_section(Table1Section::convex),
//                                ReliefOptions{}, maps);
//   if (!s) return s;                       // maps.height tiles: column 0 follows column 127
//
// How (chosen here). A periodic Voronoi division is built from geom's ordinary one: the seeds
// of one tile and their wrapped copies fill a block of 2m + 1 tiles along each periodic axis
// (m tiles on each side of the kept one, at least 6 cells: 3 x 3 tiles for the lattices and
// for the belly at D = 0.1; more for tiles of very few, big scales, where processing
// 4's shrinking near the block's straight border reached the middle tile), every copy moved
// by the same eq. (1) displacement,
// drawn from the seed's WRAPPED lattice indices (hashed_rnd of (i mod nx, j mod ny)), and the
// stage-2 rows take their random numbers from the wrapped stage-1 row too. The whole of §3.1
// (both stages, the T-junction stitching, processing 4) runs on the block; the edge
// perturbation keys each edge by its wrapped, quantised coordinates (PerturbationParams::
// period_x / period_y), so an edge and its copy one period away bend alike. The middle tile's
// polygons are then periodic copies of each other across its borders; the polygons whose
// centroid lies in the middle tile are kept, one per scale, shifted to [0, W) x [0, H): each
// original seed's cell, continuing across the border. (Copies agree to double rounding,
// ~1e-16 of the tile; the maps tile to float precision.)
//
// Layouts and what must close (the tile is kept, the spacing is chosen so the lattice closes):
//   square_lattice      fig. 3 (e)-(h): nx = round(W / D) columns, ny = round(H / D) rows,
//                       spacing Dx = W / nx, Dy = H / ny (equal to D when D divides the tile);
//                       seeds at ((i + 1/2) Dx, (j + 1/2) Dy), moved along x and y by eq. (1);
//                       tiles along x and y.
//   triangular_lattice  fig. 3 (a)-(d): nx = round(W / D), Dx = W / nx; an even number of rows
//                       ny = 2 round(H / (Dx sqrt(3))) (odd rows shifted by Dx / 2 must meet
//                       even rows across the seam), Dy = H / ny (within a few % of
//                       Dx sqrt(3) / 2: the triangles are stretched that little along y);
//                       tiles along x and y.
//   belly               figs. 4-7: the two-stage crocodile belly in every tile of the block:
//                       ny = round(H / D) stage-1 rows per side, Dy = H / ny, at (j + 1/2) Dy;
//                       the stage-2 columns (narrowing toward x = 0 and x = W, fig. 6) repeat
//                       with the tile, with no column on its edge (ScaleDivision::
//                       column_period): the edge is a joint like the centre line, where the
//                       right half of one tile meets the left half of the next, its scales
//                       whole on both sides (chosen here; the plain pattern cuts its edge
//                       scales through their middle instead). Tiles along x and y.
// Cost: the block's tile count (9 at D = 0.1, belly and lattices) times the plain
// pattern's division and perturbation (measured: the belly tile 1.9x the plain fig. 7
// pattern).
#pragma once

#include "shitsukan/core/progress.hpp"
#include "shitsukan/core/status.hpp"
#include "shitsukan/leather/scale_division.hpp"
#include "shitsukan/leather/scale_pattern.hpp"

namespace shitsukan {

enum class TileLayout { belly, square_lattice, triangular_lattice };

struct TileParams {
    TileLayout layout = TileLayout::belly;
    // width, height: the tile; D, a, perturbation, seed for every layout; d and edge_ratio for
    // the belly. Same ranges as the plain pattern (check_scale_params).
    ScaleParams scales;
};

struct TileReport {
    int columns = 0, rows = 0;   // lattice columns / rows per tile (belly: 0 and stage-1 rows)
    float Dx = 0.0f, Dy = 0.0f;  // the spacing that closes the lattice (belly: Dx = D)
    int polygons = 0;            // scales per tile
    PerturbationReport perturbation;
};

// The torus pattern: each scale of the tile once (wrap_x / wrap_y set on the periodic axes);
// its polygons' areas sum to W·H (checked: refused otherwise, like generate_scale_pattern).
// `progress` hears 0.05 after the division(s), 0.9 after the perturbation, 1 at the end.
Status generate_tileable_pattern(const TileParams& prm, ScalePattern& out,
                                 TileReport* report = nullptr, Progress progress = {});

// A plain pattern covering [0, W] x [0, H] from a torus pattern: every polygon and those of its
// copies shifted by ±W (wrap_x) and ±H (wrap_y) whose bounds meet the rectangle. Used by
// make_leather_maps for wrapped patterns; the cover's polygons may reach outside the
// rectangle (the label rasterizer clips).
Status torus_cover(const ScalePattern& torus, ScalePattern& out);

}  // namespace shitsukan
