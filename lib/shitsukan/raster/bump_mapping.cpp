// small-device: yes (no allocation, no exceptions)
#include "shitsukan/raster/bump_mapping.hpp"

#include <cmath>

namespace shitsukan {

bool triangle_texture_tangents(Vec3 p0, Vec3 p1, Vec3 p2, Vec2 t0, Vec2 t1, Vec2 t2, Vec3* dpdx,
                               Vec3* dpdy) {
    // Solve [e1 e2] = [dP/dx dP/dy] [d1 d2] for the texture-space derivatives.
    Vec3 e1 = p1 - p0, e2 = p2 - p0;
    Vec2 d1 = t1 - t0, d2 = t2 - t0;
    float det = d1.x * d2.y - d2.x * d1.y;
    if (!(std::fabs(det) > 0.0f) || !is_finite(det)) {
        *dpdx = {0, 0, 0};
        *dpdy = {0, 0, 0};
        return false;
    }
    float inv = 1.0f / det;
    *dpdx = (e1 * d2.y - e2 * d1.y) * inv;
    *dpdy = (e2 * d1.x - e1 * d2.x) * inv;
    return true;
}

Status mesh_texture_tangents(const MeshView& mesh, Vec3* dpdx, Vec3* dpdy, int capacity) {
    if (mesh.uvs == nullptr || mesh.positions == nullptr ||
        (mesh.indices == nullptr && mesh.triangle_count > 0))
        return Status::error(StatusCode::invalid_argument,
                             "texture tangents: the mesh needs positions, uvs and indices");
    if (dpdx == nullptr || dpdy == nullptr || capacity < mesh.triangle_count)
        return Status::error(StatusCode::invalid_argument,
                             "texture tangents: buffers hold %d triangles, the mesh has %d",
                             capacity, mesh.triangle_count);
    for (int t = 0; t < mesh.triangle_count; ++t) {
        const std::uint32_t* k = mesh.indices + 3 * t;
        for (int c = 0; c < 3; ++c)
            if (k[c] >= std::uint32_t(mesh.vertex_count))
                return Status::error(StatusCode::invalid_argument,
                                     "texture tangents: triangle %d uses vertex %u of %d", t,
                                     unsigned(k[c]), mesh.vertex_count);
        triangle_texture_tangents(mesh.positions[k[0]], mesh.positions[k[1]],
                                  mesh.positions[k[2]], mesh.uvs[k[0]], mesh.uvs[k[1]],
                                  mesh.uvs[k[2]], &dpdx[t], &dpdy[t]);
    }
    return Status::success();
}

TangentFrame orthonormal_tangent_frame(Vec3 n, Vec3 dpdx, Vec3 dpdy) {
    TangentFrame f;
    f.n = normalize(n);
    Vec3 t = dpdx - f.n * dot(dpdx, f.n);  // Gram-Schmidt against the interpolated normal
    if (!(length(t) > 1e-6f * (length(dpdx) + 1e-20f))) {
        // dP/dx unusable: any unit vector perpendicular to n.
        Vec3 axis = std::fabs(f.n.x) < 0.9f ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
        t = axis - f.n * dot(axis, f.n);
    }
    f.t = normalize(t);
    f.b = cross(f.n, f.t);
    if (dot(f.b, dpdy) < 0.0f) f.b = -f.b;  // a mirrored mapping keeps texture +y
    return f;
}

Vec3 perturb_normal(const TangentFrame& frame, Vec3 m) {
    return normalize(frame.t * m.x + frame.b * m.y + frame.n * m.z);
}

}  // namespace shitsukan
