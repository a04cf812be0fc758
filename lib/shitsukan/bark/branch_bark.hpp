// shitsukan/bark/branch_bark.hpp — hirota1998 §5: cracks on a branching trunk (Figs. 9, 11).
//
// Manual
//   BranchBarkParams p;                          // the chosen branch values
//   p.edge_length = 0.8f;                        // coarser than the figure's, to be quick
//   BranchBark bark;
//   Status s = build_branch_bark(p, bark);      // mesh, springs on its edges, constants
//   CrackRun run;
//   if (s) s = grow_branch_bark(bark, CrackRunOptions{}, run);
//   if (!s) return s;
//   std::uint32_t i = 0;  float t = 0.5f * p.growth.duration;
//   Vec3 x = branch_node_position(bark, i, t, bark.net.W.data());   // node i at time t
//
// §5.1: the paper digitised a real branch and re-meshed it near-uniformly (bubble mesh); here
// the shape is branch_shape.hpp's implicit trunk + branch, meshed to edge length L0. On the
// irregular mesh every node is a small volume and every mesh edge a spring; the constants come
// from the connection areas of Fig. 9 (connection_area.hpp), with the same function as the
// cylinder: k = E·S/l0 (S = |C1-P-C2|·D), k_sh = G·A/D.
//
// §5.2: the growth is an isotropic enlargement plus an offset along the normal (Fig. 10); each
// surface node is tied by its shear spring to its anchor A_i(t) on the grown inner layer, and a
// spring feels the linearised growth strain rate of its edge (edge_growth_rate). In 3D each
// node has three degrees of freedom; the solver and the event driver are the cylinder's
// (spring_network.hpp, crack_events.hpp).
//
// Material (chosen here, docs/papers/hirota1998.md §6): isotropic, E = 117.3e7, G = 53.3e7, kappa =
// 1.015 for every spring: at the crotch "axial" and "around" are undefined (the paper's own point),
// and the growth's anisotropy alone orients the cracks. Thresholds from a hash of the spring's two
// end positions (sorted), stream 13: independent of how the mesh is numbered.
#pragma once

#include <cstdint>
#include <vector>

#include "shitsukan/bark/branch_shape.hpp"
#include "shitsukan/bark/connection_area.hpp"
#include "shitsukan/bark/crack_events.hpp"
#include "shitsukan/bark/spring_network.hpp"
#include "shitsukan/geom/mesh.hpp"

namespace shitsukan {

struct BranchBarkParams {
    BranchShapeParams shape;
    float edge_length = 0.33f;  // L0 (Table 2), the remesher's target
    AnisotropicGrowth growth;   // r_h 0.010, r_n 0.05 cm over T = 100 s (chosen here)
    float E = 117.3e7f, G = 53.3e7f;  // Table 2 (tallow / pine values)
    float kappa = 1.015f;             // Table 2's kappa2 for every spring (chosen here)
    float sigma = 0.0175f;            // as the cylinder
    float D = 0.55f;                  // as the cylinder
    float tolerance = 1e-3f;
    std::uint32_t seed = 1998;
};

Status validate(const BranchBarkParams& p);

// Springs and connection triangles of any triangle mesh: one spring per edge, in the order of
// (smaller vertex, larger vertex). Refuses non-finite positions, degenerate triangles and edges
// shared by more than two triangles.
Status mesh_springs(const TriangleMesh& mesh, std::vector<ConnectionTriangle>& triangles,
                    std::vector<std::uint32_t>& edge_nodes /* 2 per spring */);

struct BranchBark {
    BranchBarkParams params;
    TriangleMesh mesh;                          // the reference shape (normals = grad f)
    BranchMeshStats mesh_stats;
    std::vector<ConnectionTriangle> triangles;  // the mesh's triangles with their springs
    std::vector<std::int32_t> spring_triangles; // 2 per spring, -1 where none
    std::vector<float> node_area, spring_face;  // Fig. 9
    SpringNetwork net;                          // dim 3
};

Status build_branch_bark(const BranchBarkParams& params, BranchBark& out);
// The same on a mesh of your own (positions, unit normals per vertex, a manifold): the bark of
// any shape. params.shape is used only for the growth's centre if you set it there.
Status build_bark_on_mesh(const BranchBarkParams& params, const TriangleMesh& mesh,
                          BranchBark& out);
Status grow_branch_bark(BranchBark& bark, const CrackRunOptions& options, CrackRun& out);

// Node i at time t: its anchor A_i(t) plus t·W_i.
Vec3 branch_node_position(const BranchBark& bark, std::uint32_t i, float t, const Vec3* W);

// The springs a crack map shows at t: broken, or intact but in no intact triangle (a crack
// opened by sliding, as crack_regions.hpp explains for the cylinder). 1 = cracked.
std::vector<std::uint8_t> cracked_springs(const BranchBark& bark, float t);

// §5.3 "cracks connect naturally between trunk and branch", measured. A point of the reference
// shape lies in the trunk zone when f_trunk < f_branch - depth, in the branch zone when
// f_branch < f_trunk - depth, and in the crotch between (limb_distances). Springs count as
// cracked as cracked_springs says, and belong to the zone of their midpoint. Two measures:
//   - networks: cracked springs joined when two of them share a triangle; a network crosses
//     the crotch when it holds springs of both the trunk and the branch zone (it may go round
//     the junction, and one network spanning the bark crosses once however it does);
//   - crossing paths: the same joining within the crotch zone only; a path crosses when it
//     shares a triangle with a cracked spring of the trunk zone and one of the branch zone:
//     how many separate cracks run across the crotch.
// Densities are broken springs per cm^2 of node area (by node position) in each zone; the
// growth strains the mean of each zone's edge growth at the end (edge_growth_rate x T), the
// drive the cracks answer to (§5.2: the normal offset shortens a concave crotch); the crotch's
// edges also split by direction: across the junction when f_trunk - f_branch changes along the
// edge by more than its length (it changes by about twice the length straight across, not at
// all along the junction), along it otherwise.
constexpr float kCrotchDepth = 0.5f;  // chosen here: 1.5 L0, past the crotch's blend

struct CrotchCrackStats {
    int networks = 0;    // crack networks (any size)
    int crossing = 0;    // of them, reaching depth into both limbs
    int largest_crossing = 0;  // springs in the largest crossing network
    int crossing_paths = 0;    // cracks within the crotch zone joining both limbs' cracks
    double density_trunk = 0, density_crotch = 0, density_branch = 0;
    double growth_trunk = 0, growth_crotch = 0, growth_branch = 0;  // mean edge growth at T
    double growth_crotch_across = 0, growth_crotch_along = 0;
};
Status crotch_crack_stats(const BranchBark& bark, float t, float depth, CrotchCrackStats& out);

}  // namespace shitsukan
