// shitsukan/bark/cylinder_lattice.hpp — hirota1998 §3.1, Fig. 3: the two-layer cylinder.
//
// Manual
//   CylinderParams p;  p.species = species_preset(Species::pine);
//   BarkCylinder bark;
//   Status s = build_cylinder(p, bark);         // nodes, springs, triangles, constants
//   if (!s) return s;
//   int i = bark.node(3, 5), sp = bark.spring(3, 5, 0);   // indices (spring: -1 where none)
//   float t = 0.5f * p.T;
//   Vec3 x = node_position(bark, std::uint32_t(i), t, bark.net.W.data());  // unrolled (u, z) at t
//
// Layout (Table 1's R0 = sqrt(3)·L0·N_R/(4 pi) decoded, docs/papers/hirota1998.md §2): the
// circumference 2 pi R0 = N_R·(sqrt(3)/2)·L0 holds N_R columns a_h = (sqrt(3)/2)·L0 apart, each
// with N_H nodes L0 apart; odd columns are shifted up by L0/2. That is the equilateral triangular
// lattice of spacing L0 with vertical lattice lines: node (c, r) sits at
//     u = c·a_h,  z = (r + (c mod 2)/2)·L0,
// and has up to six neighbours at distance L0:
//     dir 0 "up"          (c, r) - (c,   r + 1)         axial spring, family 1
//     dir 1 "up-right"    (c, r) - (c+1, r + p)         diagonal, family 2   (p = c mod 2)
//     dir 2 "down-right"  (c, r) - (c+1, r + p - 1)     diagonal, family 2
// Column N_R - 1 joins column 0 across the seam; the top and bottom rows are free edges
// (or, periodic_along, row N_H - 1 joins row 0: see the second build_cylinder).
// No spring is horizontal: hoop tension is carried by the diagonals.
//
// The two layers (§3.1): the surface layer is the mechanical lattice above; the inner layer
// is the same lattice one layer thickness D deeper, moved by the growth (kinematic). Each
// surface node is tied to the inner node beneath it by a shear spring. Growth (§3.1, "the
// inner layer expands in radius and height"; linear in t, base fixed, chosen here):
//     R(t) = R0 + delta_r·t,  H(t) = H0 + delta_h·t,
// so the anchor of surface node (u, z) is (u·R(t)/R0, z·H(t)/H0) unrolled, and a spring with
// reference direction n is pulled at the growth strain rate
//     g_s = (delta_r/R0)·n_u^2 + (delta_h/H0)·n_z^2.
// The cylinder is simulated unrolled (2 degrees of freedom per node, periodic in u): a
// cylinder is developable, and radial motion is held by the layer below.
//
// Constants (§5.1, connection_area.hpp): k = E_f·S/l0 with S = (face length)·D, and
// k_sh = G·A/D. Critical strains (§3.1 "sigma: material variation", Table 1; the distribution
// is not given, chosen here): eps_c = (kappa_f - 1)·max(0.05, 1 + sigma·clamp(g, -3, 3)),
// g = hash_gaussian(seed, 11, c, r, dir): addressed by the spring's coordinates, so the
// numbering of springs changes nothing.
#pragma once

#include <cstdint>
#include <vector>

#include "shitsukan/bark/bark_params.hpp"
#include "shitsukan/bark/connection_area.hpp"
#include "shitsukan/bark/spring_network.hpp"

namespace shitsukan {

struct BarkCylinder {
    CylinderParams params;
    float R0 = 0, H0 = 0, a_h = 0;
    float circumference = 0;                        // 2 pi R0 = N_R·a_h
    SpringNetwork net;                              // the surface layer
    std::vector<ConnectionTriangle> triangles;      // seam-corrected corners (reference)
    std::vector<std::int32_t> spring_triangles;     // 2 per spring, -1 where none
    std::vector<float> node_area, spring_face;      // connection areas (Fig. 9)
    std::vector<std::int32_t> spring_index;         // 3 per node: spring (c, r, dir) or -1
    bool periodic_along = false;                    // rows wrap: row N_H - 1 joins row 0

    int node(int c, int r) const { return c * params.N_H + r; }
    int column_of(int p) const { return p / params.N_H; }
    int row_of(int p) const { return p % params.N_H; }
    int spring(int c, int r, int dir) const { return spring_index[3 * node(c, r) + dir]; }
};

// Builds the lattice, the constants and the thresholds. reverse_springs numbers the springs in
// reverse (tests: the results must not depend on it).
// Largest spring stiffness k = E·S/l0 over the shear spring k_sh = G·A/D of either of its
// nodes (chosen here: 2^21 = 2.1e6). The solver (spring_network.hpp) solves each node's block
// K_p = k_sh·I + sum k n n^T in float, whose 24-bit significand keeps k_sh in a sum with k
// only while k / k_sh < 2^24: past that K_p turns singular (fuzz_bark: E2 = 4.8e12 on
// L0 = 2.2e-4 cm, a ratio of 2.6e7, gave NaN displacements under an ok Status). 2^21 leaves
// 3 bits; the ratio grows as (D / L0)^2, and the bark tool's smallest L0, 0.001 cm, reaches
// 1.4e6 with Table 2's values. build_cylinder refuses a stiffer spring (out_of_range).
constexpr double kMaxSpringAnchorRatio = 2097152.0;

Status build_cylinder(const CylinderParams& params, BarkCylinder& out,
                      bool reverse_springs = false);
// The same lattice periodic along the axis too (periodic_along, for bark as a texture,
// bark_texture.hpp; chosen here): row N_H - 1 joins row 0 as column N_R - 1 joins column 0,
// so there are no free edges; triangles across the axial seam get reference corners one
// height H0 = N_H·L0 up. The anchors grow as before (z·(1 + eps_z) is linear, so the period
// grows to H(t)). Needs N_H >= 3. periodic_along = false is build_cylinder above.
Status build_cylinder(const CylinderParams& params, bool periodic_along, BarkCylinder& out,
                      bool reverse_springs = false);

// The spring's canonical key and its lattice coordinates.
inline std::uint64_t cylinder_spring_key(int c, int r, int dir) {
    return (std::uint64_t(std::uint32_t(c)) << 32) | (std::uint64_t(std::uint32_t(r)) << 2) |
           std::uint64_t(dir);
}

// The critical strain of spring (c, r, dir) of layer generation g (§3.1 sigma, chosen here):
// (kappa - 1)·max(0.05, 1 + sigma·clamp(gauss, -3, 3)), gauss = hash_gaussian(seed, 11, c, r,
// dir + 4·g). Generation 0 is the two-layer cylinder; the four-layer bark draws fresh
// thresholds for every new layer.
float spring_critical_strain(float kappa, float sigma, std::uint32_t seed, int c, int r, int dir,
                             int generation = 0);

// The anchor of a reference point (u, z) at time t: (u·(1 + eps_theta), z·(1 + eps_z)).
Vec3 cylinder_anchor(const BarkCylinder& bark, Vec3 reference, float t);
// Node p at time t, unrolled: anchor + t·W_p (W: the displacement field valid at t).
Vec3 node_position(const BarkCylinder& bark, std::uint32_t p, float t, const Vec3* W);
// A seam-corrected reference corner of node p, moved to time t the same way.
Vec3 corner_position(const BarkCylinder& bark, Vec3 reference, std::uint32_t p, float t,
                     const Vec3* W);
// Is spring s intact at time t (not broken, or broken later)?
inline bool intact_at(const BarkSpring& s, float t) { return s.t_break < 0 || s.t_break > t; }

}  // namespace shitsukan
