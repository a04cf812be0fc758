// shitsukan/geom/mesh_view.hpp — an indexed triangle mesh over caller memory.
//
// Manual
//   MeshView m;
//   m.positions = pos; m.vertex_count = 8;        // required
//   m.normals = nrm;   m.uvs = uv; m.colors = col; // optional (nullptr = absent)
//   m.indices = idx;   m.triangle_count = 12;      // 3 indices per triangle, CCW = front
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
