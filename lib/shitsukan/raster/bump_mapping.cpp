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
