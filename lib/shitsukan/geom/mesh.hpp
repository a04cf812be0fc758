// shitsukan/geom/mesh.hpp — host-side owning triangle mesh.
//
// Manual
//   TriangleMesh mesh;
//   uint32_t a = mesh.add_vertex({0, 0, 0}, {0, 0, 1}, {0, 0});   // position, normal, uv
//   uint32_t b = mesh.add_vertex({1, 0, 0}, {0, 0, 1}, {1, 0});
//   uint32_t c = mesh.add_vertex({0, 1, 0}, {0, 0, 1}, {0, 1});
//   mesh.add_triangle(a, b, c);                  // counter-clockwise = front
//   // mesh.colors is optional: empty, or one colour per vertex.
//   MeshView view = mesh.view();                 // what the rasterizer reads (mesh_view.hpp)
//   // append(dst, src, transform) merges meshes (mesh_builders.hpp)
// Builders (box, sphere, torus, revolution, extrusion, cut faces) are in
// geom/mesh_builders.hpp; OBJ export in geom/obj.hpp.
#pragma once

#include <cstdint>
#include <vector>

#include "shitsukan/core/vec.hpp"
#include "shitsukan/geom/mesh_view.hpp"

namespace shitsukan {

struct TriangleMesh {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;  // same count as positions (may be empty before compute)
    std::vector<Vec2> uvs;      // same count as positions, or empty
    std::vector<Vec3> colors;   // same count as positions, or empty
    std::vector<std::uint32_t> indices;

    std::uint32_t add_vertex(Vec3 p, Vec3 n = {}, Vec2 uv = {}) {
        positions.push_back(p);
        normals.push_back(n);
        uvs.push_back(uv);
        return std::uint32_t(positions.size() - 1);
    }
    void add_triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        indices.push_back(a);
        indices.push_back(b);
        indices.push_back(c);
    }
    int vertex_count() const { return int(positions.size()); }
    int triangle_count() const { return int(indices.size() / 3); }

    MeshView view() const {
        MeshView v;
        v.positions = positions.empty() ? nullptr : positions.data();
        v.normals =
            normals.size() == positions.size() && !normals.empty() ? normals.data() : nullptr;
        v.uvs = uvs.size() == positions.size() && !uvs.empty() ? uvs.data() : nullptr;
        v.colors = colors.size() == positions.size() && !colors.empty() ? colors.data() : nullptr;
        v.vertex_count = int(positions.size());
        v.indices = indices.empty() ? nullptr : indices.data();
        v.triangle_count = int(indices.size() / 3);
        return v;
    }
};

}  // namespace shitsukan
