// shitsukan/geom/polygon.hpp — simple polygons: area, centroid, containment, convex clipping.
//
// Manual
//   double a = polygon_area(v, n);           // signed: > 0 counter-clockwise (shoelace)
//   Vec2d m = polygon_centroid(v, n);        // area centroid (the "m" of tokai1994 fig. 12)
//   bool in = point_in_polygon(v, n, q);     // crossing rule, half-open: see below
//   Status s = check_convex_region(r, m);    // r: m >= 3 vertices, convex, CCW, area > 0
//                                            // (collinear vertices allowed)
//   clip_to_convex_region(poly, r, m, &scratch);  // Sutherland-Hodgman, exact sides
//
// point_in_polygon counts crossings of the ray from q toward +x with the edges, each edge
// taken as half-open in y ([ymin, ymax)) and crossing x computed from the edge's lower end
// point, so a point on an edge shared by two polygons (same end points, bit for bit) is
// inside exactly one of them. Float and double versions.
//
// Clipping (Sutherland & Hodgman 1974) against each region edge k in turn: a vertex is kept
// when the EXACT orientation (predicates.hpp) puts it inside or on the edge's line, an
// intersection is made where an edge strictly crosses the line. The intersection is computed
// from the segment's end points in lexicographic order, so two cells that share a segment get
// the same bits; on an axis-parallel region edge the fixed coordinate is copied exactly. Each
// vertex records up to two region edges it lies on (ClipVertex::on), which lets a caller find
// the parts of a cell's boundary that run along the region's boundary. A vertex closer than
// kClipSnapRelative * (region diameter) to an edge's line is moved onto it (chosen here: the
// rounded lattice vertex 7 * (1/7) misses x = 1 by an ulp and would leave a cell 1e-17 wide).
// Cost: area, centroid and containment O(n); clipping O(n m) for n cell and m region vertices.
#pragma once

#include <vector>

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"

namespace shitsukan {

double polygon_area(const Vec2d* v, int n);
double polygon_area(const Vec2* v, int n);  // accumulated in double
Vec2d polygon_centroid(const Vec2d* v, int n);
Vec2d polygon_centroid(const Vec2* v, int n);
bool point_in_polygon(const Vec2d* v, int n, Vec2d q);
bool point_in_polygon(const Vec2* v, int n, Vec2 q);

Status check_convex_region(const Vec2d* region, int m);

constexpr double kClipSnapRelative = 1e-12;

struct ClipVertex {
    Vec2d p;
    int on[2] = {-1, -1};  // region edges (index k: region[k] -> region[k + 1]) through p
};

// poly: a convex counter-clockwise polygon, replaced by its part inside the region (possibly
// empty). The region must pass check_convex_region.
void clip_to_convex_region(std::vector<ClipVertex>* poly, const Vec2d* region, int m,
                           std::vector<ClipVertex>* scratch);
// The same with the snap distance computed once by the caller (many cells, one region).
double clip_snap_distance(const Vec2d* region, int m);
void clip_to_convex_region(std::vector<ClipVertex>* poly, const Vec2d* region, int m, double snap,
                           std::vector<ClipVertex>* scratch);

}  // namespace shitsukan
