// small-device: yes (no allocation, no exceptions)
#include "shitsukan/geom/mesh_arrays.hpp"

#include "shitsukan/core/scalar.hpp"

namespace shitsukan {

Status make_box_arrays(Vec3 lo, Vec3 hi, Vec3* positions, Vec3* normals, Vec2* uvs,
                       int vertex_capacity, std::uint32_t* indices, int index_capacity,
                       MeshView* out) {
    if (!out || !positions || !normals || !indices)
        return Status::error(StatusCode::invalid_argument,
                             "make_box_arrays: null positions, normals, indices or output");
    if (!is_finite(lo) || !is_finite(hi) || !(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z))
        return Status::error(StatusCode::invalid_argument,
                             "make_box: need finite corners with min < max on every axis "
                             "(got (%g,%g,%g) .. (%g,%g,%g))",
                             double(lo.x), double(lo.y), double(lo.z), double(hi.x), double(hi.y),
                             double(hi.z));
    if (vertex_capacity < kBoxVertexCount || index_capacity < 3 * kBoxTriangleCount)
        return Status::error(StatusCode::buffer_too_small,
                             "make_box_arrays: a box needs %d vertices and %d indices (got "
                             "capacity %d and %d)",
                             kBoxVertexCount, 3 * kBoxTriangleCount, vertex_capacity,
                             index_capacity);
    int nv = 0, ni = 0;
    // Each face: normal axis, sign; its four corners get their own vertices (flat normals).
    for (int axis = 0; axis < 3; ++axis) {
        for (int sign = -1; sign <= 1; sign += 2) {
            Vec3 n{};
            n[axis] = float(sign);
            const int u_axis = (axis + 1) % 3, v_axis = (axis + 2) % 3;
            const std::uint32_t base = std::uint32_t(nv);
            for (int k = 0; k < 4; ++k) {
                const int du = (k == 1 || k == 2), dv = (k >= 2);
                Vec3 p;
                p[axis] = sign > 0 ? hi[axis] : lo[axis];
                p[u_axis] = du ? hi[u_axis] : lo[u_axis];
                p[v_axis] = dv ? hi[v_axis] : lo[v_axis];
                positions[nv] = p;
                normals[nv] = n;
                if (uvs) uvs[nv] = Vec2{float(du), float(dv)};
                ++nv;
            }
            // Two triangles (base, +1, +2) and (base, +2, +3), each turned counter-clockwise
            // as seen from outside (the side n points to).
            for (int t = 0; t < 2; ++t) {
                std::uint32_t a = base, b = base + 1 + std::uint32_t(t), c = b + 1;
                const Vec3 face = cross(positions[b] - positions[a], positions[c] - positions[a]);
                if (dot(face, n) < 0.0f) {
                    const std::uint32_t s = b;
                    b = c;
                    c = s;
                }
                indices[ni++] = a;
                indices[ni++] = b;
                indices[ni++] = c;
            }
        }
    }
    MeshView v;
    v.positions = positions;
    v.normals = normals;
    v.uvs = uvs;
    v.vertex_count = nv;
    v.indices = indices;
    v.triangle_count = ni / 3;
    *out = v;
    return Status::success();
}

}  // namespace shitsukan
