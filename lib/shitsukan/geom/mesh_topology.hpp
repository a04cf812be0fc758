// shitsukan/geom/mesh_topology.hpp — is a triangle mesh a manifold, and what is its shape?
//
// Manual
//   TriangleMesh mesh;
//   Status s = make_cylinder(0.5f, 0.0f, 1.0f, 16, false, mesh);  // an open tube
//   MeshTopology topo;
//   if (s) s = mesh_topology(mesh, topo);       // counts; s explains the first problem found
//   bool tube = s && topo.boundary_loops == 2 && topo.euler_characteristic == 0;
//   return s;
//   #include "shitsukan/geom/mesh_builders.hpp"
//
//   std::vector<int> opposite;                   // the half-edge twins of a manifold mesh
//   Status s = halfedge_opposites(mesh.indices.data(), mesh.triangle_count(),
//                                 mesh.vertex_count(), opposite);
//   // half-edge h = 3·t + k runs from indices[h] to indices[3·t + (k + 1) % 3];
//   // opposite[h] is the half-edge running the other way, or -1 on a boundary.
//
// What "manifold" means here (an oriented 2-manifold, possibly with boundary):
//   - every index is in range and no triangle repeats a vertex;
//   - every directed edge a -> b occurs once (twice means two triangles disagree on the
//     orientation, or the surface is folded onto itself), and every undirected edge belongs to
//     one triangle (boundary) or two (interior);
//   - the triangles around every vertex form one fan (a disc, or a half-disc on the boundary):
//     two cones touching at a vertex are refused.
// The counts (V counts referenced vertices only; E edges; F triangles):
//   euler_characteristic = V - E + F   (sphere 2, torus 0, open cylinder 0, pair of pants -1)
//   boundary_loops       = the number of closed chains of boundary edges.
// halfedge_opposites() refuses a non-manifold mesh with the same messages (the remesher and
// the topology check share it). Host side: allocates its work arrays.
#pragma once

#include <cstdint>
#include <vector>

#include "shitsukan/core/status.hpp"
#include "shitsukan/geom/mesh.hpp"

namespace shitsukan {

struct MeshTopology {
    bool manifold = false;
    int vertices = 0;      // referenced by at least one triangle
    int unreferenced = 0;  // positions no triangle uses
    int edges = 0;
    int triangles = 0;
    int boundary_edges = 0;
    int boundary_loops = 0;
    int euler_characteristic = 0;  // V - E + F
};

// Twins of every half-edge (see the manual). On success opposite->size() == 3·triangles.
Status halfedge_opposites(const std::uint32_t* indices, int triangles, int vertex_count,
                          std::vector<int>& opposite);

// Fills *out (manifold = true) or returns the first problem (out->manifold = false and the
// plain counts V, F are still filled in).
Status mesh_topology(const TriangleMesh& mesh, MeshTopology& out);

}  // namespace shitsukan
