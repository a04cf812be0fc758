// shitsukan/geom/mesh_arrays.hpp — mesh builders into caller arrays (no allocation), for a
// microcontroller that keeps its mesh in a static array or on the stack.
//
// Manual (no allocation: the caller owns the arrays)
//   Vec3 pos[kBoxVertexCount], nrm[kBoxVertexCount];  Vec2 uv[kBoxVertexCount];
//   std::uint32_t idx[3 * kBoxTriangleCount];
//   MeshView box;
//   Status s = make_box_arrays({-1, -1, -1}, {1, 1, 1}, pos, nrm, uv, kBoxVertexCount, idx,
//                              3 * kBoxTriangleCount, box);
//   // box now points into pos/nrm/uv/idx: draw it with draw_mesh (raster/rasterizer.hpp)
//   return s;
//
// The box is exactly make_box's (geom/mesh_builders.hpp, which calls this): 6 faces of 4
// vertices each (flat normals, uv (0..1, 0..1) per face), 2 counter-clockwise triangles a
// face, in the same order, so a figure drawn from either gives the same pixels.
// Sizes: capacities are counts of elements; too small is buffer_too_small naming the count
// needed. Errors: non-finite corners or min >= max on an axis (invalid_argument), null
// arrays or output (invalid_argument). uvs may be null (then out->uvs is null).
//
//   MeshSizes need = uv_sphere_sizes(32, 16);        // vertices, and indices at most
//   make_uv_sphere_arrays(1.0f, 32, 16, pos, nrm, uv, vcap, idx, icap, view);
//   make_cylinder_arrays(0.5f, 0.0f, 2.0f, 48, true, ...);   cylinder_sizes(48, true)
//   make_torus_arrays(1.0f, 0.35f, 64, 32, ...);               torus_sizes(64, 32)
//   make_revolution_arrays(profile, n, 96, ...);               revolution_sizes(profile, n, 96)
// The sphere, cylinder, torus and revolution are mesh_builders.hpp's (which call these): the
// same vertices and triangles in the same order, so figures get the same pixels. `indices`
// of MeshSizes is an upper bound (zero-area triangles at poles and on the axis are dropped;
// the view's triangle_count says how many were written). A revolution's profile must not
// repeat a point twice in a row here (make_revolution drops repeats before calling).
// Segment counts lie in [3, kMaxMeshSegments] (stacks from 2); a *_sizes call with counts
// out of range returns {0, 0}.
// small-device: yes (no allocation)
#pragma once

#include <cstdint>

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"
#include "shitsukan/geom/mesh_view.hpp"

namespace shitsukan {

constexpr int kBoxVertexCount = 24;

constexpr int kBoxTriangleCount = 12;
constexpr int kMaxMeshSegments = 4096;

struct MeshSizes {
    int vertices = 0;
    int indices = 0;  // at most (3 per triangle)
};

Status make_box_arrays(Vec3 min_corner, Vec3 max_corner, Vec3* positions, Vec3* normals, Vec2* uvs,
                       int vertex_capacity, std::uint32_t* indices, int index_capacity,
                       MeshView& out);

MeshSizes uv_sphere_sizes(int slices, int stacks);
Status make_uv_sphere_arrays(float radius, int slices, int stacks, Vec3* positions, Vec3* normals,
                             Vec2* uvs, int vertex_capacity, std::uint32_t* indices,
                             int index_capacity, MeshView& out);

MeshSizes cylinder_sizes(int slices, bool caps);
Status make_cylinder_arrays(float radius, float y0, float y1, int slices, bool caps,
                            Vec3* positions, Vec3* normals, Vec2* uvs, int vertex_capacity,
                            std::uint32_t* indices, int index_capacity, MeshView& out);

MeshSizes torus_sizes(int major_segments, int minor_segments);
Status make_torus_arrays(float major_radius, float minor_radius, int major_segments,
                         int minor_segments, Vec3* positions, Vec3* normals, Vec2* uvs,
                         int vertex_capacity, std::uint32_t* indices, int index_capacity,
                         MeshView& out);

MeshSizes revolution_sizes(const Vec2d* profile, int count, int segments);
Status make_revolution_arrays(const Vec2d* profile, int count, int segments, Vec3* positions,
                              Vec3* normals, Vec2* uvs, int vertex_capacity,
                              std::uint32_t* indices, int index_capacity, MeshView& out);

}  // namespace shitsukan
