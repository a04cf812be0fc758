// shitsukan/geom/delaunay.hpp — Delaunay triangulation of points in the plane (exact predicates).
//
// Manual
//   const Vec2d points[5] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.4, 0.6}};
//   int n = 5;
//   DelaunayTriangulation dt;
//   Status s = build_delaunay(points, n, dt);   // points: n finite Vec2d, n >= 1
//   if (!s) return s;
//   const DelaunayTriangle& t = dt.triangles[0];
//   // t.v[0..2]  counter-clockwise point indices (indices >= n are the 4 frame points added
//   //            far outside, see below)
//   // t.n[i]     the triangle across the edge opposite v[i] (-1 outside the frame)
//   int any = dt.point_triangle[4];   // one triangle incident to point i (-1 for a duplicate)
//   int dup = dt.duplicate_of[4];     // -1, or the smallest index of an identical earlier point
//
// Memory: count * kDelaunayBytesPerPoint bytes must fit the memory budget, else too_large at
// once (before any allocation), the message giving the bytes.
// Coordinate range: each coordinate is 0 or has magnitude in [1e-50, 1e50] (else a Status);
// a box to cover may reach below 1e-50 (it is widened onto the range). The frame is at least
// 2^-20 of the coordinates' magnitude wide, so points far narrower than their coordinates
// ((0, 0.5) and (1e-17, 0.5)) still get a frame distinct from them. An insertion that finds no
// cavity is reported as a Status (degenerate), never an abort.
// The in-circle determinant is a degree-4 polynomial of coordinate differences; outside this
// range its products (or their rounding-error terms) overflow or underflow, the "exact" sign
// is lost and the insertion could not find its cavity.
//
// Algorithm (Bowyer 1981 / Watson 1981, incremental): points are sorted along a Hilbert curve
// and inserted coarse to fine (every 64th point of the curve, then the other 16th, 4th and
// the rest, each round along the curve: Amenta, Choi & Rote's BRIO rounds, deterministic)
// into a frame of 4 points placed 10 bounding-box half-extents from the data's centre,
// so every input point is interior. Each insertion walks from the last new triangle to the
// triangle containing the point (visibility walk, exact orient2d), collects the cavity of
// triangles whose circumcircle contains the point STRICTLY (exact incircle > 0), and
// re-triangulates it as a fan from the point. Tie-break: a point exactly on a circumcircle
// (incircle == 0) does not enter the cavity, so cocircular points (lattices) give some valid
// triangulation of their convex polygon; the Voronoi diagram built on top merges such
// triangles (voronoi.hpp).
// Expected O(n log n) for the sort, O(n) expected for the insertions on spread-out data
// (O(1) walk and cavity per point in these rounds); worst case O(n^2).
#pragma once

#include <cstdint>
#include <vector>

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"

namespace shitsukan {

constexpr double kDelaunayMinCoordinate = 1e-50;  // smallest non-zero |coordinate|
constexpr double kDelaunayMaxCoordinate = 1e50;   // largest |coordinate| (points, box)
// Working set per point, checked against the memory budget (core/memory_budget.hpp) before
// anything is allocated: points 16 B, ~2 triangles 48 B, their marks 8 B, the cavity's
// vertex table 4 B, index arrays 12 B, sort keys 8 B (16 B while sorting, before any
// triangle exists) = 96 B; measured peak 118.5 B per point at 1e6 uniform points with the
// earlier 16-byte keys, two marks per triangle and two vertex tables. Chosen here: 128 B per
// point.
constexpr std::uint64_t kDelaunayBytesPerPoint = 128;

struct DelaunayTriangle {
    int v[3];  // counter-clockwise
    int n[3];  // neighbour across the edge opposite v[i], -1 beyond the frame
};

struct DelaunayTriangulation {
    int input_count = 0;        // n; points[n .. n + 3] are the frame
    std::vector<Vec2d> points;  // the input points followed by the 4 frame points
    std::vector<DelaunayTriangle> triangles;
    std::vector<int> point_triangle;   // size n + 4
    std::vector<int> duplicate_of;     // size n
    std::vector<int> insertion_order;  // input indices in Hilbert order (spatially coherent)
};

Status build_delaunay(const Vec2d* points, int count, DelaunayTriangulation& out);
// The same, with the frame also enclosing the box [cover_lo, cover_hi] (e.g. a clip region):
// every point of that box is then nearer to some input point than to any frame point.
Status build_delaunay(const Vec2d* points, int count, DelaunayTriangulation& out, Vec2d cover_lo,
                      Vec2d cover_hi);
// keep_hilbert_numbering = true: `points`, `triangles` and `point_triangle` use the Hilbert
// numbering k (point k is input point insertion_order[k]; frame points stay n .. n + 3), which
// keeps later walks over the triangulation cache-friendly; duplicate_of keeps input indices.
Status build_delaunay(const Vec2d* points, int count, DelaunayTriangulation& out, Vec2d cover_lo,
                      Vec2d cover_hi, bool keep_hilbert_numbering);

}  // namespace shitsukan
