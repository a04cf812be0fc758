// shitsukan/geom/isotropic_remesh.hpp — near-uniform triangles of a chosen edge length on an
// implicit surface (the bubble-mesh substitute of hirota1998 §5.1).
//
// Manual
//   ImplicitFunction sphere = [](Vec3 p, const void*) { return length(p) - 1.0f; };
//   MarchingTetrahedraOptions mt;
//   mt.box_min = {-1.2f, -1.2f, -1.2f};  mt.box_max = {1.2f, 1.2f, 1.2f};  mt.spacing = 0.2f;
//   TriangleMesh mesh;
//   Status s = marching_tetrahedra(sphere, nullptr, mt, mesh);  // or any closed mesh on f = 0
//   IsotropicRemeshOptions opt;
//   opt.target_edge_length = 0.1f;                         // L
//   opt.surface = sphere;  opt.user = nullptr;             // f = 0 is the surface
//   IsotropicRemeshStats stats;
//   if (s) s = isotropic_remesh(opt, mesh, &stats);       // mesh replaced in place
//   // stats.after.edge_length_cv, stats.after.fraction_angle_above_25, ...
//   MeshQuality q;
//   if (s) s = mesh_quality(mesh, q);                     // the same numbers for any mesh
//   return s;
//
// hirota1998 §5.1 re-meshes a digitised branch with Shimada's bubble mesh so that the node
// distances vary little. This is the usual isotropic remeshing loop instead (one pass =
// the five steps below, all loops in index order, so the result is deterministic):
//   1. split every edge longer than 4/3·L at its midpoint;
//   2. collapse every edge shorter than 4/5·L into its midpoint (into the boundary vertex when
//      one end is on the boundary; never an interior edge between two boundary vertices),
//      refused when the link condition fails (the ends share neighbours other than the
//      edge's opposite vertices), an opposite vertex would keep fewer than 3 neighbours, a
//      triangle's normal would flip, or a new edge would exceed 4/3·L;
//   3. flip edges when that brings the valences closer to 6 (4 on the boundary), measured as
//      the sum of squared deviations of the 4 vertices, unless a triangle would fold over;
//   4. tangential smoothing: every interior vertex moves `smoothing` (½) of the way to the
//      area-weighted centroid of its one-ring triangles, the component along the surface
//      normal (∇f/|∇f|) removed; a boundary vertex moves toward the midpoint of its two
//      boundary neighbours and keeps its z;
//   5. projection to f = 0 with `newton_steps` steps p -= f ∇f / |∇f|² (central-difference
//      gradient, step L/20); boundary vertices use the gradient without its z component, so
//      they stay on their plane z = const (the open ends of a cut trunk,
//      marching_tetrahedra.hpp).
// Collapses and flips keep the half-edge twins current as they go, and sweep in index order
// until nothing changes (at most kRemeshSweeps sweeps); splits lock the vertices of each split
// patch until the sweep ends and the half-edges are rebuilt between split sweeps. Dead
// triangles and vertices are compacted away (keeping index order) after each pass's
// collapses. The final normals are ∇f/|∇f| at the final positions.
//
// Input: a manifold triangle mesh (mesh_topology.hpp) with finite positions and no
// degenerate triangles (a repeated vertex or |cross| <= 1e-10·(longest edge)²); each is refused
// with a Status saying which triangle. Ranges: target_edge_length > 0 and finite; passes in
// [1, 100]; newton_steps in [0, 20]; smoothing in [0, 1]; surface not null; an expected result
// above kMaxRemeshVertices vertices (from the mesh area and L) is too_large.
// Host side: allocates.
#pragma once

#include "shitsukan/core/status.hpp"
#include "shitsukan/geom/marching_tetrahedra.hpp"  // ImplicitFunction
#include "shitsukan/geom/mesh.hpp"

namespace shitsukan {

struct IsotropicRemeshOptions {
    float target_edge_length = 0.0f;  // L
    int passes = 8;                   // chosen here: converged by then (the bark's branch mesh,
                                      // docs/papers/hirota1998.md §6)
    int newton_steps = 3;
    float smoothing = 0.5f;
    ImplicitFunction surface = nullptr;  // f, the surface is f = 0
    const void* user = nullptr;
};

// Sweeps of one step within a pass before it gives up (chosen here: a split sweep locks the
// patches it changed, and a collapse can make a neighbouring edge short; measured on the
// branch: at most 6 sweeps are needed).
constexpr int kRemeshSweeps = 12;
constexpr int kMaxRemeshVertices = 1 << 24;  // chosen here: ~1 GB of work arrays

struct MeshQuality {
    int vertices = 0;
    int triangles = 0;
    int boundary_vertices = 0;
    double edge_length_mean = 0;
    double edge_length_cv = 0;  // standard deviation / mean over the unique edges
    double edge_length_min = 0, edge_length_max = 0;
    double min_angle_degrees = 0;        // the smallest angle of any triangle
    double fraction_angle_above_25 = 0;  // triangles whose smallest angle exceeds 25 degrees
    double area = 0;
};

struct IsotropicRemeshStats {
    MeshQuality before, after;
    long splits = 0, collapses = 0, flips = 0;
};

Status isotropic_remesh(const IsotropicRemeshOptions& options, TriangleMesh& mesh,
                        IsotropicRemeshStats* stats = nullptr);

// Edge lengths, angles and counts of any manifold mesh (the same checks as the remesher's
// input: a Status for NaN, degenerate or non-manifold triangles).
Status mesh_quality(const TriangleMesh& mesh, MeshQuality& out);

}  // namespace shitsukan
