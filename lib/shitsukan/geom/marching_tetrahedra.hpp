// shitsukan/geom/marching_tetrahedra.hpp — the zero set of an implicit function as triangles.
//
// Manual
//   auto sphere = [](Vec3 p) { return length(p) - 1.0f; };        // f < 0 inside
//   MarchingTetrahedraOptions opt;
//   opt.box_min = {-1.2f, -1.2f, -1.2f};  opt.box_max = {1.2f, 1.2f, 1.2f};
//   opt.spacing = 0.05f;
//   TriangleMesh mesh;
//   Status s = marching_tetrahedra(sphere, opt, mesh);            // closed, outward, manifold
//   // A trunk: opt.cut_z_min = opt.cut_z_max = true leaves it open at z = box_min.z and
//   // z = box_max.z (cut, not capped); its rims lie exactly on those planes.
//   // A plain function pointer works too: marching_tetrahedra(&f, user_pointer, opt, mesh).
//   return s;
//
// Algorithm
//   - The box is divided into nx·ny·nz cubes, n = ceil(extent / spacing) per axis, so the
//     spacing used per axis is extent / n <= spacing and the grid's outer planes are exactly the
//     box's faces. f is sampled at the grid nodes, one z layer of nodes at a time (index order
//     x fastest, then y, then z: deterministic, two layers in memory).
//   - Every cube is cut into 6 tetrahedra around its main diagonal (0,0,0)-(1,1,1) (Kuhn /
//     Freudenthal). The same diagonal in every cube makes neighbouring cubes cut their shared
//     face along the same diagonal, so the tetrahedra fill the box face to face.
//   - Inside means f < 0; f = 0 and NaN count as outside. A tetrahedron with 1 or 3 nodes
//     inside gives one triangle, with 2 inside a quad split along its shorter diagonal.
//   - A surface vertex sits on a grid edge (an axis edge, a face diagonal or the body diagonal)
//     at the linear zero of f, t = f0 / (f0 - f1), clamped to [1e-4, 1 - 1e-4] (chosen here:
//     no zero-length edges when f vanishes at a node). Vertices are welded by grid-edge id, so
//     the triangles share them: the result is a manifold surface (closed where it stays
//     inside the box, open exactly on a cut face).
//   - Triangles are counter-clockwise seen from outside (f > 0), so their normals point out.
//   - Faces of the box: a cut face (cut_z_min, cut_z_max) leaves the surface open there; on
//     every other face the nodes count as outside (f forced positive), which caps a surface
//     that reaches that face within the last cell.
//   Vertex normals are the normalised (central-difference) gradient of f when
//   opt.compute_normals is set, else left zero.
// Ranges: box finite with box_max > box_min on every axis; spacing > 0 and finite; at most
// kMaxMarchingNodes grid nodes (too_large otherwise, with the bytes it would need). The mesh
// holds at most 2^31 vertices. Host side: allocates (two node layers plus the output).
#pragma once

#include <cstdint>
#include <utility>

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"
#include "shitsukan/geom/mesh.hpp"

namespace shitsukan {

// f(p, user) < 0 inside, > 0 outside, 0 on the surface.
using ImplicitFunction = float (*)(Vec3 p, const void* user);

struct MarchingTetrahedraOptions {
    Vec3 box_min{-1, -1, -1};
    Vec3 box_max{1, 1, 1};
    float spacing = 0.1f;    // grid spacing h (the largest used on any axis)
    bool cut_z_min = false;  // leave the surface open at z = box_min.z
    bool cut_z_max = false;  // leave the surface open at z = box_max.z
    bool compute_normals = true;
};

// Chosen here: 2^27 nodes, a 512^3 grid; the surface of a finer grid would take gigabytes.
constexpr long long kMaxMarchingNodes = 1LL << 27;

struct MarchingTetrahedraStats {
    int nx = 0, ny = 0, nz = 0;  // cubes per axis
    Vec3 cell{0, 0, 0};          // the spacing used per axis
    long long evaluations = 0;   // calls of f (grid nodes + normals)
};

Status marching_tetrahedra(ImplicitFunction f, const void* user,
                           const MarchingTetrahedraOptions& options, TriangleMesh& out,
                           MarchingTetrahedraStats* stats = nullptr);

// Convenience for lambdas and functors taking (Vec3) and returning float.
template <class F, class = decltype(float(std::declval<const F&>()(Vec3{})))>
Status marching_tetrahedra(const F& f, const MarchingTetrahedraOptions& options, TriangleMesh& out,
                           MarchingTetrahedraStats* stats = nullptr) {
    return marching_tetrahedra(
        [](Vec3 p, const void* u) -> float { return float((*static_cast<const F*>(u))(p)); }, &f,
        options, out, stats);
}

// The central-difference gradient of f at p with step `step` (6 calls of f).
Vec3 implicit_gradient(ImplicitFunction f, const void* user, Vec3 p, float step);

}  // namespace shitsukan
