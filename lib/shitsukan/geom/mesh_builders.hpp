// shitsukan/geom/mesh_builders.hpp — triangle meshes for the papers' objects.
//
// Manual (every builder replaces *out, appends nothing; returns a Status on bad input)
//   TriangleMesh m, dst;
//   Status s = make_box({-1, -1, -1}, {1, 1, 1}, m);  // 6 faces, per-face normals, uv per face
//   if (s) s = make_uv_sphere(1.0f, 64, 32, m);      // poles on the y axis
//   if (s) s = make_cylinder(0.5f, 0.0f, 2.0f, 48, true, m);  // axis y from y0 to y1, caps
//   if (s) s = make_torus(1.0f, 0.35f, 64, 32, m);   // around the y axis, in the xz plane
//   const Vec2d profile[4] = {{0.0, 0.0}, {0.6, 0.1}, {0.4, 0.8}, {0.0, 1.0}};  // (r, y), r >= 0
//   if (s) s = make_revolution(profile, 4, 96, m);   // revolved about the y axis
//   std::vector<Vec2d> points;
//   if (s) s = sample_spline(profile, 4, 16, points);  // Catmull-Rom through them, in double
//   std::vector<std::vector<Vec2>> outline = {{{0, 0}, {2, 0}, {2, 1}, {0, 1}},
//                                             {{0.5f, 0.3f}, {0.5f, 0.6f}, {1.0f, 0.6f}}};
//   if (s) s = make_extrusion(outline, -0.1f, 0.1f, m);  // outline[0] outer (any orientation),
//                                                         // outline[1..] holes; along z
//   if (s) s = make_block_text("NAGOYA", 1.0f, 0.3f, m);  // block capitals (block_letters.hpp),
//                                                          // baseline y = 0, depth along z
//   if (s) s = make_sphere_without_octant(1.0f, 24, m);   // closed: the x,y,z > 0 octant
//                                                          // removed, three quarter-disc faces
//   if (s) s = append(dst, m, Mat4::translate({3, 0, 0}));  // merge, moving points and normals
//   if (s) s = compute_vertex_normals(dst);                 // area-weighted smooth normals
//   return s;
// Sizes: segment counts 3..4096; radii > 0 and finite. Counter-clockwise front faces,
// outward normals, closed solids are watertight (shared vertices along seams are duplicated
// only where normals or uvs differ, never leaving a crack).
#pragma once

#include <vector>

#include "shitsukan/core/status.hpp"
#include "shitsukan/geom/mesh.hpp"

namespace shitsukan {

Status make_box(Vec3 min_corner, Vec3 max_corner, TriangleMesh& out);
Status make_uv_sphere(float radius, int slices, int stacks, TriangleMesh& out);
Status make_cylinder(float radius, float y0, float y1, int slices, bool caps, TriangleMesh& out);
Status make_torus(float major_radius, float minor_radius, int major_segments, int minor_segments,
                  TriangleMesh& out);
Status make_revolution(const Vec2d* profile, int count, int segments, TriangleMesh& out);
Status sample_spline(const Vec2d* control, int count, int samples_per_segment,
                     std::vector<Vec2d>& out);
Status make_extrusion(const std::vector<std::vector<Vec2>>& outline, float z0, float z1,
                      TriangleMesh& out);
Status make_block_text(const char* text, float letter_height, float depth, TriangleMesh& out);
Status make_sphere_without_octant(float radius, int subdivisions, TriangleMesh& out);
// Both check the indices (and append the transform's invertibility) and say what is wrong.
Status append(TriangleMesh& dst, const TriangleMesh& src, const Mat4& transform);
Status compute_vertex_normals(TriangleMesh& mesh);

}  // namespace shitsukan
