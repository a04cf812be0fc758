// shitsukan/bark/branch_shape.hpp — hirota1998 §5: a trunk with a branch, meshed near-uniformly,
// and its anisotropic growth (isotropic scaling + normal offset, Fig. 10).
//
// Manual
//   BranchShapeParams shape;                               // the chosen values
//   TriangleMesh mesh;  BranchMeshStats stats;
//   Status s = make_branch_mesh(shape, 0.6f, mesh, &stats);   // 0.33: ~3,500 nodes; n = ∇f/|∇f|
//   Vec3 p{0.5f, 1.0f, 2.0f};
//   float f = branch_shape_value(shape, p);                // < 0 inside the wood
//   LimbDistances d = limb_distances(shape, p);            // trunk / branch zones (fig11)
//   return s;
//
//   AnisotropicGrowth g;  g.r_h = 0.010f;  g.r_n = 0.05f;  g.duration = 100;  // fig11 values
//   g.centre = branch_base_centre(shape);                  // c = (0, 0, 0)
//   Vec3 A = anisotropic_growth_anchor(g, X_i, n_i, t);     // c + s(t)(X_i - c) + d(t) n_i
//   float rate = edge_growth_rate(g, X_i, X_j, n_i, n_j);   // ε̂_ij, per unit time
//
// The paper (§5.1) digitised a real branching trunk and re-meshed it with the bubble mesh;
// there is no scan here, so the shape is an implicit surface (docs/papers/hirota1998.md §6):
//   f(p) = smin(f_trunk(p), f_branch(p); k),
//   f_trunk(p)  = |p - proj_trunk(p)| - R_t      (distance to the vertical z axis minus R_t),
//   f_branch(p) = |p - proj_branch(p)| - R_b     (distance to the half-line from the branch
//                 origin o along u = (sin θ, 0, cos θ), minus R_b),
//   smin(a, b; k) = b + h(a - b) - k h (1 - h),  h = clamp(½ + ½(b - a)/k, 0, 1): the
//                 polynomial (quadratic) smooth minimum, equal to min(a, b) when |a - b| >= k
//                 and at most k/4 below it; its gradient is h ∇a + (1 - h) ∇b (the normals).
// The surface is cut by z = 0 and z = height (open: trunk bottom, trunk top, branch end:
// 3 boundary loops, Euler characteristic -1) and meshed by marching tetrahedra at spacing
// L0/2 followed by isotropic remeshing to L0 (geom/marching_tetrahedra.hpp,
// geom/isotropic_remesh.hpp).
//
// Anisotropic growth (§5.2, Fig. 10): "the length growth is done by the isotropic enlargement
// of the whole, and the thickness growth is supplemented by the enlargement along the normal":
//   isotropic_scaling(g, t)  s(t) = 1 + r_h·t/T
//   normal_offset(g, t)      d(t) = r_n·t/T          (a displacement in cm, not a ratio)
//   anchor                   A_i(t) = c + s(t)(X_i - c) + d(t) n_i
//   edge_growth_rate         ε̂_ij = r_h/T + (r_n/T)·(e_ij·(n_j - n_i))/l0_ij,
//                            e_ij = (X_j - X_i)/l0_ij: the linearised strain rate of the edge
//                            between the anchors, d/dt |A_j - A_i| / l0 at t = 0.
// On a cylinder of radius R this is r_h/T along the axis and (r_h + r_n/R)/T around it, so a
// thinner limb grows faster around (the drawback §5.2 names); Fig. 11's r_r = r_h + r_n/R_t.
// A negative r_n gives length-dominated growth (young branches, §5.2).
#pragma once

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"
#include "shitsukan/geom/isotropic_remesh.hpp"
#include "shitsukan/geom/mesh.hpp"

namespace shitsukan {

struct BranchShapeParams {
    // chosen here: the paper's branch is a scan; a 2.5 cm trunk gives ~55 nodes around at L0.
    float trunk_radius = 2.5f;
    // chosen here: z in [0, 16] cm leaves 10 cm of trunk above the branch origin.
    float height = 16.0f;
    // chosen here: a visibly thinner limb (0.6 R_t) so the hoop-rate difference shows.
    float branch_radius = 1.5f;
    // chosen here: the branch axis starts on the trunk axis at z = 6 cm (inside the trunk).
    Vec3 branch_origin{0.0f, 0.0f, 6.0f};
    // chosen here: 40 degrees from vertical, in the x-z plane: both limbs leave through the top
    // plane, so the mesh has 3 separate open ends.
    float branch_angle_degrees = 40.0f;
    // chosen here: polynomial smooth-min radius 1 cm: a smooth crotch, larger than L0.
    float blend = 1.0f;
};

Status validate_branch_shape(const BranchShapeParams& params);

// f(p) < 0 inside the wood (see the manual) and its analytic gradient.
float branch_shape_value(const BranchShapeParams& params, Vec3 p);
Vec3 branch_shape_gradient(const BranchShapeParams& params, Vec3 p);
inline Vec3 branch_shape_normal(const BranchShapeParams& params, Vec3 p) {
    return normalize(branch_shape_gradient(params, p));
}
// The unit direction u of the branch axis and the base centre c of the trunk (0, 0, 0).
Vec3 branch_axis_direction(const BranchShapeParams& params);
inline Vec3 branch_base_centre(const BranchShapeParams&) { return Vec3{0.0f, 0.0f, 0.0f}; }

// For classifying cracks into the trunk and branch zones (fig11): the distances of p to the
// two axes and the signed distances to the two limbs' surfaces (f_trunk, f_branch above).
struct LimbDistances {
    float trunk_axis = 0, branch_axis = 0;  // |p - proj(p)|
    float f_trunk = 0, f_branch = 0;        // minus the radius
};
LimbDistances limb_distances(const BranchShapeParams& params, Vec3 p);

// The box the shape is meshed in: z in [0, height] exactly, x and y with a margin of
// blend/4 + 2·spacing around the limbs.
void branch_shape_box(const BranchShapeParams& params, float spacing, Vec3* box_min, Vec3* box_max);

struct BranchMeshStats {
    int marching_vertices = 0, marching_triangles = 0;
    IsotropicRemeshStats remesh;
    int boundary_loops = 0;
    int euler_characteristic = 0;
};

// Marching tetrahedra at spacing L0/2 (cut at z = 0 and z = height) + isotropic remeshing to
// L0 (8 passes); normals n_i = ∇f/|∇f| (analytic). L0 in [0.05, 5] cm (too_large below:
// chosen here, ~160k nodes at 0.05 cm).
Status make_branch_mesh(const BranchShapeParams& params, float target_edge_length,
                        TriangleMesh& out, BranchMeshStats* stats = nullptr);

// ---- §5.2 anisotropic growth ----
struct AnisotropicGrowth {
    float r_h = 0.010f;       // isotropic (length) growth over the duration (chosen, §6 of
                              // docs/papers/hirota1998.md)
    float r_n = 0.05f;        // normal offset over the duration, cm ((r_r - r_h)·R_t)
    float duration = 100.0f;  // T
    Vec3 centre{0, 0, 0};     // c: the fixed point of the scaling (the trunk's base centre)
};

Status validate_growth(const AnisotropicGrowth& growth);

float isotropic_scaling(const AnisotropicGrowth& growth, float t);  // s(t)
float normal_offset(const AnisotropicGrowth& growth, float t);      // d(t)
Vec3 anisotropic_growth_anchor(const AnisotropicGrowth& growth, Vec3 x, Vec3 n, float t);
float edge_growth_rate(const AnisotropicGrowth& growth, Vec3 xi, Vec3 xj, Vec3 ni, Vec3 nj);

}  // namespace shitsukan
