// shitsukan/bark/bark_export.hpp — the simulated bark out of the program: CSV, SVG, a mesh.
//
// Manual
//   CylinderParams params;  params.N_R = 16;  params.N_H = 12;  // a small trunk (chosen 128 x 64)
//   params.species = species_preset(Species::camphor);
//   BarkCylinder bark;
//   Status s = build_cylinder(params, bark);
//   CrackRun run;
//   if (s) s = grow_and_crack(bark, CrackRunOptions{}, run);
//   if (!s) return s;
//   float T = params.T;
//   const Vec3* W = bark.net.W.data();
//   s = write_bark_csv(bark, T, W, "camphor");             // camphor_nodes.csv, _springs.csv,
//                                                          // _triangles.csv
//   if (s) s = write_crack_svg(bark, T, W, "camphor.svg"); // the unrolled crack map
//   TriangleMesh trunk;
//   if (s) s = make_trunk_mesh(bark, T, W, trunk);         // then write_obj(...)
//   return s;
//   #include "shitsukan/bark/crack_events.hpp"
//
// Files are written through core/output_file.hpp: the three CSV files appear together or not
// at all, and a failure names the path and the reason.
//
// CSV (so others can measure the regions independently; all lengths in cm at time t):
//   nodes:     id,c,r,u_cm,z_cm,area_cm2          unrolled positions (u around, z along)
//   springs:   id,i,j,c,r,dir,family,l0_cm,eps_c,t_break,width_cm
//              t_break -1 and width 0 while intact at t; width = l - l0 (Fig. 4) once broken
//   triangles: id,a,b,c,s_ab,s_bc,s_ca               the lattice triangles (with their springs)
// Rebuilding Table 3's regions from these: a triangle is intact when its three springs are;
// join the nodes of every spring that lies in an intact triangle; each component is a region.
//
// SVG: the unrolled trunk (u to the right, z up), the intact surface as the lattice triangles,
// every crack as Fig. 4's ribbon (crack_drawing.hpp), px_per_cm pixels per cm.
//
// Mesh: the deformed trunk at t in 3D (y = the trunk axis, radius R(t) = R0 + delta_r·t,
// angle = u/R(t)), one vertex per node plus a copy of column 0 closing the seam; uv = the
// unrolled position divided by the grown circumference and height (the crack map's
// coordinates), normals radial.
#pragma once

#include "shitsukan/bark/cylinder_lattice.hpp"
#include "shitsukan/core/status.hpp"
#include "shitsukan/geom/mesh.hpp"

namespace shitsukan {

Status write_bark_csv(const BarkCylinder& bark, float t, const Vec3* W, const char* prefix);
Status write_crack_svg(const BarkCylinder& bark, float t, const Vec3* W, const char* path,
                       float px_per_cm = 24.0f);
Status make_trunk_mesh(const BarkCylinder& bark, float t, const Vec3* W, TriangleMesh& out);

}  // namespace shitsukan
