// shitsukan/geom/planar_subdivision.hpp — polygons that tile a region, with each edge stored
// once and knowing the polygons on its two sides.
//
// Manual
//   // two unit squares side by side, each counter-clockwise
//   const Vec2d vertices[8] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {1, 0}, {2, 0}, {2, 1}, {1, 1}};
//   const int offsets[3] = {0, 4, 8};   // polygon f = vertices[offsets[f] .. offsets[f + 1])
//   int polygon_count = 2;
//   PlanarSubdivision sub;
//   Status s = build_planar_subdivision(vertices, offsets, polygon_count, sub);
//   if (!s) return s;
//   for (const auto& e : sub.edges) {      // e.v0 -> e.v1 runs counter-clockwise around e.left;
//       int beyond = e.right;              // e.right is the polygon beyond it, -1 outside
//   }
//   int f = 0;
//   for (int k = sub.face_offsets[f]; k < sub.face_offsets[f + 1]; ++k) {
//       int e = sub.face_edges[k];        // >= 0: edge e run v0 -> v1; < 0: edge ~e run v1 -> v0
//   }
//
// Vertices are welded by exact equality (same bits), so the input polygons must share their
// common boundary vertex for vertex. A vertex lying inside another polygon's edge (a T
// junction) leaves both pieces with one side only: they look like outer boundary edges, which
// outer_edges_on_box() reports. An edge run twice in the same direction (an overlap) is
// refused with a Status. Why shared edges: tokai1994 perturbs each edge of the scale pattern
// once, so the two scales on its sides keep fitting each other (processing 4).
// Algorithm: one pass over the polygons' edges with two hash maps (vertex bits -> vertex,
// vertex pair -> edge): O(total vertex count) expected time and memory; too_large at once
// when the total vertex count times kPlanarSubdivisionBytesPerVertex is over the memory budget
// (core/memory_budget.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"

namespace shitsukan {

// Working set per polygon vertex (chosen here, from the containers: a vertex 16 B and its hash
// node ~40 B, an edge 16 B and its hash node ~40 B, a face edge 4 B = 116 B, rounded up).
constexpr std::uint64_t kPlanarSubdivisionBytesPerVertex = 128;

struct PlanarSubdivision {
    struct Edge {
        int v0, v1;  // vertex indices; v0 -> v1 counter-clockwise around `left`
        int left;    // polygon on the left of v0 -> v1
        int right;   // polygon on the right, -1 when the edge is on the outer boundary
    };
    std::vector<Vec2d> vertices;
    std::vector<Edge> edges;
    std::vector<int> face_offsets;  // polygon f's edges: face_edges[face_offsets[f] .. [f + 1])
    std::vector<int> face_edges;    // e >= 0: edge e forward; ~e (< 0): edge e backward

    int face_count() const { return face_offsets.empty() ? 0 : int(face_offsets.size()) - 1; }
    int face_vertex(int face_edge) const {  // the vertex where a face edge starts
        return face_edge >= 0 ? edges[std::size_t(face_edge)].v0
                              : edges[std::size_t(~face_edge)].v1;
    }
};

// Polygons: offsets has polygon_count + 1 entries; each polygon >= 3 distinct vertices, CCW.
Status build_planar_subdivision(const Vec2d* vertices, const int* offsets, int polygon_count,
                                PlanarSubdivision& out);

// The outer boundary edges of a subdivision that tiles the axis-parallel box [lo, hi] all lie
// on the box: a check used by the tests and the leather pipeline.
bool outer_edges_on_box(const PlanarSubdivision& sub, Vec2d lo, Vec2d hi);

}  // namespace shitsukan
