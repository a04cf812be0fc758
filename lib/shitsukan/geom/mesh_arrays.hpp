// shitsukan/geom/mesh_arrays.hpp — mesh builders into caller arrays (no allocation), for a
// microcontroller that keeps its mesh in a static array or on the stack.
//
// Manual (no allocation: the caller owns the arrays)
//   Vec3 pos[kBoxVertexCount], nrm[kBoxVertexCount];  Vec2 uv[kBoxVertexCount];
//   std::uint32_t idx[3 * kBoxTriangleCount];
//   MeshView box;
//   Status s = make_box_arrays({-1, -1, -1}, {1, 1, 1}, pos, nrm, uv, kBoxVertexCount, idx,
//                              3 * kBoxTriangleCount, &box);
//   // box now points into pos/nrm/uv/idx: draw it with draw_mesh (raster/rasterizer.hpp)
//   return s;
//
// The box is exactly make_box's (geom/mesh_builders.hpp, which calls this): 6 faces of 4
// vertices each (flat normals, uv (0..1, 0..1) per face), 2 counter-clockwise triangles a
// face, in the same order, so a figure drawn from either gives the same pixels.
// Sizes: capacities are counts of elements; too small is buffer_too_small naming the count
// needed. Errors: non-finite corners or min >= max on an axis (invalid_argument), null
// arrays or output (invalid_argument). uvs may be null (then out->uvs is null).
// Not here yet: sphere, cylinder and torus into arrays (issue 12; make_uv_sphere & co. in
// mesh_builders.hpp still fill a std::vector mesh).
// small-device: yes (no allocation)
#pragma once

#include <cstdint>

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"
#include "shitsukan/geom/mesh_view.hpp"

namespace shitsukan {

constexpr int kBoxVertexCount = 24;
constexpr int kBoxTriangleCount = 12;

Status make_box_arrays(Vec3 min_corner, Vec3 max_corner, Vec3* positions, Vec3* normals,
                       Vec2* uvs, int vertex_capacity, std::uint32_t* indices,
                       int index_capacity, MeshView* out);

}  // namespace shitsukan
