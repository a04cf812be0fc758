// shitsukan/geom/polygon.hpp — simple polygons: area, centroid, containment, convex clipping.
//
// Manual
//   const Vec2d v[4] = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
//   int n = 4;
//   double a = polygon_area(v, n);           // signed: > 0 counter-clockwise (shoelace)
//   Vec2d m = polygon_centroid(v, n);        // area centroid (the "m" of tokai1994 fig. 12)
//   bool in = point_in_polygon(v, n, Vec2d{1, 0.5});  // crossing rule, half-open: see below
//   const Vec2d r[3] = {{0, 0}, {1, 0}, {0, 1}};
//   Status s = check_convex_region(r, 3);    // r: m >= 3 vertices, convex, CCW, area > 0
//                                            // (collinear vertices allowed, see below)
//   std::vector<ClipVertex> poly(4), scratch;
//   for (int i = 0; i < 4; ++i) poly[std::size_t(i)].p = v[i];
//   clip_to_convex_region(&poly, r, 3, &scratch);  // Sutherland-Hodgman, exact sides
//   return s;
//
// point_in_polygon counts crossings of the ray from q toward +x with the edges, each edge
// taken as half-open in y ([ymin, ymax)) and crossing x computed from the edge's lower end
// point, so a point on an edge shared by two polygons (same end points, bit for bit) is
// inside exactly one of them. Float and double versions.
//
// polygon_area and polygon_centroid work relative to the first vertex, so a polygon far from
// the origin keeps its digits (and its sign).
//
// check_convex_region is exact (orient2d): every turn is to the left or straight on, no edge
// has length 0, no straight-on vertex turns back (a spike), and the edge directions go round
// exactly once (a doubly wound pentagram-like outline turns left everywhere and is refused).
// So a region that passes is a convex counter-clockwise polygon with area > 0, whatever its
// position or scale.
//
// Clipping (Sutherland & Hodgman 1974) against each region edge k in turn: a vertex is kept
// when the EXACT orientation (predicates.hpp) puts it inside or on the edge's line, an
// intersection is made where an edge strictly crosses the line. The intersection is computed
// from the segment's end points in lexicographic order, so two cells that share a segment get
// the same bits; on an axis-parallel region edge the fixed coordinate is copied exactly. Each
// vertex records up to two region edges it lies on (ClipVertex::on), which lets a caller find
// the parts of a cell's boundary that run along the region's boundary. A vertex closer than
// kClipSnapRelative * min(region diameter, region width) to an edge's line is moved onto it
// (chosen here: a rounded lattice vertex that should lie on x = 1 can miss it by an ulp and
// would leave a cell 1e-17 wide; the width keeps a thin region from being snapped away).
//
// Where the edge leaving a vertex carries its SUPPORT (ClipVertex::bisector: the two sites
// whose bisector it lies on, or ClipVertex::along: the region edge it runs along), the
// intersection with a region edge is constructed from that support and the region edge alone,
// in double-double (double_double.hpp), with the two sites in lexicographic order: the point
// is then correctly rounded and independent of how far away the edge's end points are (a
// Voronoi vertex 1e9 away no longer drags the clip point off by 1e-7). Without a support the
// intersection is interpolated between the end points.
// A polygon reaching beyond the guard box (the region's bounding box grown by its larger side
// on every side, chosen here) is clipped to that box first, the same way: a vertex 1e48 out
// is rounded by ~1e32 and could not be judged against region edges 1 apart (two nearly
// parallel edges made a far cell into a sliver between them: fuzz finding 8). The box holds
// the region, so the exact result is the same.
// Cost: area, centroid and containment O(n); clipping O(n m) for n cell and m region vertices.
#pragma once

#include <vector>

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"

namespace shitsukan {

// (double shoelace: a polygon whose area is far below its coordinates times an ulp, e.g. a
// triangle of area 0.4 reaching 1e34, comes out 0; check_convex_region is exact)
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
    // Support of the edge from this vertex to the next one (optional, see above).
    Vec2d bisector[2] = {};     // the edge lies on the bisector of these two sites ...
    bool has_bisector = false;  // ... when true
    int along = -1;             // or on region edge `along` (>= 0)
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
