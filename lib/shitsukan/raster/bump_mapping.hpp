// shitsukan/raster/bump_mapping.hpp — bump mapping (Blinn 1978, "Simulation of wrinkled
// surfaces", cited as ref. 19 by tokai1994 §4) with a normal map in an orthonormal tangent frame.
//
// Manual
//   TriangleMesh mesh;                                 // any mesh with uvs
//   Status s = make_uv_sphere(1.0f, 16, 8, mesh);
//   if (!s) return s;
//   Vec3 dpdx, dpdy;                                   // once per triangle
//   triangle_texture_tangents(mesh.positions[0], mesh.positions[1], mesh.positions[2],
//                             mesh.uvs[0], mesh.uvs[1], mesh.uvs[2], &dpdx, &dpdy);
//   // or for a whole mesh, into caller buffers of mesh.triangle_count entries:
//   const int capacity = mesh.view().triangle_count;
//   std::vector<Vec3> dpdx_buf(static_cast<std::size_t>(capacity)), dpdy_buf(dpdx_buf);
//   s = mesh_texture_tangents(mesh.view(), dpdx_buf.data(), dpdy_buf.data(), capacity);
//   Vec3 interpolated_normal{0, 0, 1}, leather_normal = normalize(Vec3{0.1f, 0.0f, 1.0f});
//   TangentFrame f = orthonormal_tangent_frame(interpolated_normal, dpdx_buf[0], dpdy_buf[0]);
//   Vec3 n = perturb_normal(f, leather_normal);       // leather_normal in the texture frame
//   return s;
//   #include "shitsukan/geom/mesh_builders.hpp"
//
// Blinn 1978 perturbs the surface normal N by D = (F_u (N x P_v) - F_v (N x P_u)) / |N| for a
// height F(u, v). When the texture is laid on the surface with equal scale in both directions
// (the arc-length mapping of geom/bezier_patch_mesh.hpp does this) that is the same as
// expressing the height field's own normal (-F_x, -F_y, 1)/|.| in the frame (T, B, N) of the
// texture's x and y directions on the surface, which is what the leather normal map stores.
// The frame must be orthonormal: T is dP/dx made perpendicular to the *interpolated* normal
// (Gram-Schmidt), B = N x T with the sign of dP/dy. Skipping that step (using dP/dx, dP/dy
// as they come) tilts and scales the bumps wherever the mapping shears, a classic bug.
// Small-device: float, no allocation.
#pragma once

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"
#include "shitsukan/geom/mesh_view.hpp"

namespace shitsukan {

struct TangentFrame {
    Vec3 t{1, 0, 0};  // texture +x on the surface
    Vec3 b{0, 1, 0};  // texture +y on the surface
    Vec3 n{0, 0, 1};  // surface normal
};

// dP/dx and dP/dy of a triangle whose vertices p_i carry texture points t_i. Returns false
// (and sets both to 0) when the texture triangle has no area.
bool triangle_texture_tangents(Vec3 p0, Vec3 p1, Vec3 p2, Vec2 t0, Vec2 t1, Vec2 t2, Vec3* dpdx,
                               Vec3* dpdy);

// triangle_texture_tangents for every triangle of a mesh (dpdx[t], dpdy[t] for triangle t;
// 0 where the texture triangle has no area). invalid_argument when the mesh has no uvs, an
// index is out of range, or capacity < mesh.triangle_count.
Status mesh_texture_tangents(const MeshView& mesh, Vec3* dpdx, Vec3* dpdy, int capacity);

// Gram-Schmidt: t = (dpdx - (dpdx·n) n)/|.|, b = sign · n x t with sign = sign(dpdy · (n x t)).
// Falls back to any frame around n when dpdx is zero or parallel to n.
TangentFrame orthonormal_tangent_frame(Vec3 n, Vec3 dpdx, Vec3 dpdy);

// m.x·t + m.y·b + m.z·n, normalised.
Vec3 perturb_normal(const TangentFrame& frame, Vec3 map_normal);

}  // namespace shitsukan
