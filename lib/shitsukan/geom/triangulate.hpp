// shitsukan/geom/triangulate.hpp — triangulating a planar polygon with holes (ear clipping).
//
// Manual
//   std::vector<Vec2> outer = {{0, 0}, {4, 0}, {4, 3}, {0, 3}};
//   std::vector<Vec2> hole1 = {{1, 1}, {1, 2}, {2, 2}, {2, 1}};
//   std::vector<std::vector<Vec2>> rings = {outer, hole1};   // any orientation
//   std::vector<Vec2> points; std::vector<uint32_t> tris;
//   Status s = triangulate_polygon(rings, points, tris);
//   // points: every ring vertex once (outer first, then holes in the given order)
//   // tris: counter-clockwise triangles (3 indices each) covering outer minus holes
//   return s;
// Algorithm: orient the outer ring counter-clockwise and holes clockwise; join each hole to
// the polygon by a bridge to its nearest visible vertex (holes taken right to left, as in
// D. Eberly, "Triangulation by Ear Clipping"), then clip ears. O(n^2) for n vertices: meant
// for letters and profiles (tens to hundreds of vertices), not for big meshes.
// Errors: fewer than 3 vertices in a ring, non-finite coordinates, zero-area outer ring, or a
// polygon the ear clipper cannot finish (self-intersecting input); too_large when the vertex
// count times kTriangulateBytesPerVertex is over the memory budget (core/memory_budget.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"

namespace shitsukan {

// Working set per ring vertex (chosen here, from the arrays: points 8 B, index loops and their
// copies while holes are bridged 16 B, hole order 8 B, triangles 12 B = 44 B, rounded up).
constexpr std::uint64_t kTriangulateBytesPerVertex = 64;

Status triangulate_polygon(const std::vector<std::vector<Vec2>>& rings, std::vector<Vec2>& points,
                           std::vector<std::uint32_t>& triangles);

// Twice the signed area (positive = counter-clockwise), shoelace formula, in double.
double signed_area2(const std::vector<Vec2>& ring);

}  // namespace shitsukan
