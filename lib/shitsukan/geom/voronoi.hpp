// shitsukan/geom/voronoi.hpp — Voronoi division of the plane, clipped to a convex region
// (tokai1994 §3.1 processing 3: "division in the continuous plane").
//
// Manual
//   const Vec2d square[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};   // convex, counter-clockwise
//   const Vec2d sites[3] = {{0.2, 0.3}, {0.7, 0.2}, {0.5, 0.8}};
//   int n = 3;
//   VoronoiCells cells;
//   Status s = voronoi_cells(sites, n, square, 4, cells);
//   if (!s) return s;
//   for (int i = 0; i < n; ++i) {                  // cell i belongs to sites[i]
//       int k; const Vec2d* v = cells.cell(i, &k);   // k == 0: empty (see below)
//   }
//   // cells.on_region_edge[2 * j + 0/1]: the region edges vertex j lies on (-1: none)
//
// Exactness. The combinatorial structure is exact for any finite double input: it is decided
// only by the signs of orient2d and incircle (predicates.hpp). Four or more cocircular sites
// (every square of a square lattice, every hexagon corner of a triangular lattice) make ONE
// Voronoi vertex: adjacent Delaunay triangles whose fourth point is exactly on the circle
// (incircle == 0) are merged, so a lattice cell has exactly 4 or 6 vertices, never a
// zero-length edge. Each Voronoi vertex is computed once, as the circumcentre of the three
// lexicographically smallest sites on its circle, so every cell around it gets the same bits,
// whatever the order of the input or of insertion. Vertices are correctly rounded doubles:
// the circumcentre and the points where a cell edge (a bisector) meets a region edge are
// constructed in double-double from the sites and the region (double_double.hpp, polygon.hpp),
// never from the far ends of an edge, so sites an ulp apart, sites 1e8 away from a small
// region and thin regions all give cells that tile the region.
//
// Memory: count * kVoronoiBytesPerSite bytes must fit the memory budget, else too_large at
// once, the message giving the bytes.
//
// Stated cases: a duplicate site (same bits as an earlier one) gets an EMPTY cell; the first
// occurrence owns the region. Collinear sites give parallel strips. A single site owns the
// whole region. A site outside the region, or whose cell misses it, gets an empty cell.
// Sites on the region boundary are ordinary sites. Cells are counter-clockwise and start at
// their lexicographically smallest vertex.
//
// Algorithm: Delaunay triangulation (delaunay.hpp), union of cocircular triangles, one
// centre per group (the midpoint when the group's sites are corners of one axis-parallel
// rectangle, else filtered in doubles or x87 extended precision, double-double where the
// filters cannot prove the rounding: the same bits), the exact test of each centre against
// the region, the dual walk around each site, then Sutherland-Hodgman clipping (polygon.hpp)
// with canonical intersections (shared cell edges stay bit-identical) of the cells that have
// a vertex outside or near the boundary; the others come out of the clipping unchanged and
// skip it. Expected O(n log n) time, O(n) memory, on spread-out sites.
#pragma once

#include <cstdint>
#include <vector>

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"

namespace shitsukan {

// Working set per site, checked against the memory budget (core/memory_budget.hpp) before
// anything is allocated. The larger of two halves: while the cells are walked, the
// triangulation (~80 B), the cocircular groups, their centres and inside flags (~42 B) and
// the inside cells' vertex lists (~28 B); after the triangulation is freed, the centres, the
// lists and the result (~152 B: vertices 96 B, region-edge labels 48 B, offsets, duplicates).
// Measured peak 221 B per site at 1e6 uniform sites (172 B on the square lattice). Chosen
// here: 256 B per site, so 2e7 sites (5.1 GB) are refused at once under the default 4 GiB
// budget.
constexpr std::uint64_t kVoronoiBytesPerSite = 256;

struct VoronoiCells {
    std::vector<Vec2d> vertices;      // all cells' vertices, concatenated
    std::vector<int> offsets;         // cell i = vertices[offsets[i] .. offsets[i + 1])
    std::vector<int> on_region_edge;  // 2 per vertex: region edge indices through it, or -1
    std::vector<int> duplicate_of;    // per site: -1, or the earlier identical site

    int cell_count() const { return offsets.empty() ? 0 : int(offsets.size()) - 1; }
    const Vec2d* cell(int i, int* count) const {
        *count = offsets[std::size_t(i) + 1] - offsets[std::size_t(i)];
        return vertices.data() + offsets[std::size_t(i)];
    }
};

// sites: count >= 1 finite points. region: a convex counter-clockwise polygon, area > 0
// (check_convex_region, exact). Sites and region coordinates: 0 or magnitude in [1e-50, 1e50].
Status voronoi_cells(const Vec2d* sites, int count, const Vec2d* region, int region_count,
                     VoronoiCells& out);

}  // namespace shitsukan
