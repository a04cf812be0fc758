// shitsukan/geom/mesh_view.hpp — an indexed triangle mesh over caller memory.
//
// Manual
//   const Vec3 pos[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
//   const Vec3 nrm[3] = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
//   const std::uint32_t idx[3] = {0, 1, 2};
//   MeshView m;
//   m.positions = pos; m.vertex_count = 3;        // required
//   m.normals = nrm;                              // optional: uvs, colors too (nullptr = absent)
//   m.indices = idx;   m.triangle_count = 1;      // 3 indices per triangle, CCW = front
// This is what the rasterizer reads: plain pointers and counts, no allocation, so a
// microcontroller can keep a mesh in flash. Host code builds a TriangleMesh (mesh.hpp) and
// passes mesh.view().
#pragma once

#include <cstdint>

#include "shitsukan/core/vec.hpp"

namespace shitsukan {

struct MeshView {
    const Vec3* positions = nullptr;  // object space
    const Vec3* normals = nullptr;    // per vertex, unit length (optional)
    const Vec2* uvs = nullptr;        // per vertex (optional)
    const Vec3* colors = nullptr;     // per vertex linear RGB in [0, 1] (optional)
    int vertex_count = 0;
    const std::uint32_t* indices = nullptr;  // 3·triangle_count entries, counter-clockwise front
    int triangle_count = 0;
};

}  // namespace shitsukan
