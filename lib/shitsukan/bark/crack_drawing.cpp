// hirota1998 Fig. 4: cracks at the middle of broken springs (see crack_drawing.hpp).
#include "shitsukan/bark/crack_drawing.hpp"

#include <cmath>

#include "shitsukan/bark/crack_regions.hpp"

namespace shitsukan {

namespace {

// Centroid of triangle tri at time t, moved by whole (grown) circumferences next to `near`.
Vec3 triangle_centroid(const BarkCylinder& bark, int tri, float t, const Vec3* W, Vec3 near) {
    const ConnectionTriangle& ct = bark.triangles[std::size_t(tri)];
    Vec3 sum{};
    for (int k = 0; k < 3; ++k) sum += corner_position(bark, ct.corner[k], ct.node[k], t, W);
    Vec3 c = sum * (1.0f / 3.0f);
    const float C = bark.circumference * (1.0f + hoop_strain(bark.params, t));
    while (c.x - near.x > 0.5f * C) c.x -= C;
    while (near.x - c.x > 0.5f * C) c.x += C;
    return c;
}

}  // namespace

CrackRibbon crack_ribbon(const BarkCylinder& bark, std::uint32_t spring, float t, const Vec3* W) {
    const BarkSpring& sp = bark.net.springs[spring];
    CrackRibbon r;
    r.spring = spring;
    r.node[0] = node_position(bark, sp.i, t, W);
    // x_j next to x_i: the grown reference offset plus the displacement difference.
    r.node[1] = r.node[0] + cylinder_anchor(bark, sp.n * sp.l0, t) + (W[sp.j] - W[sp.i]) * t;
    const Vec3 d = r.node[1] - r.node[0];
    r.l = length(d);
    r.l0 = sp.l0;
    r.width = r.l - r.l0;  // Fig. 4: the width is l - l0
    r.along = d * (1.0f / r.l);
    r.midpoint = (r.node[0] + r.node[1]) * 0.5f;
    const std::int32_t* tris = &bark.spring_triangles[2 * std::size_t(spring)];
    r.face[0] = triangle_centroid(bark, tris[0], t, W, r.midpoint);
    r.face[1] = tris[1] >= 0 ? triangle_centroid(bark, tris[1], t, W, r.midpoint)
                             : r.midpoint * 2.0f - r.face[0];  // free edge: mirror C1
    return r;
}

Status crack_ribbons(const BarkCylinder& bark, float t, const Vec3* W,
                     std::vector<CrackRibbon>& out, bool include_weak) {
    if (!W)
        return Status::error(StatusCode::invalid_argument,
                             "crack_ribbons: null displacement field W");
    out.clear();
    std::vector<std::uint8_t> strong;
    if (include_weak) strong_springs(bark, t, &strong);
    for (std::size_t s = 0; s < bark.net.springs.size(); ++s) {
        const BarkSpring& sp = bark.net.springs[s];
        const bool broken = !intact_at(sp, t);
        const bool weak = include_weak && !broken && !strong[s];
        if (!broken && !weak) continue;
        CrackRibbon r = crack_ribbon(bark, std::uint32_t(s), t, W);
        if (weak) r.weak = true, r.width = 0.0f;
        out.push_back(r);
    }
    return Status::success();
}

void ribbon_quads(const CrackRibbon& r, Vec3 quads[2][4], float min_width) {
    const float half = 0.5f * (r.width > min_width ? r.width : min_width);
    const Vec3 h = r.along * half;
    const Vec3 ends[2] = {r.face[0], r.face[1]};
    for (int q = 0; q < 2; ++q) {
        quads[q][0] = ends[q] - h;
        quads[q][1] = r.midpoint - h;
        quads[q][2] = r.midpoint + h;
        quads[q][3] = ends[q] + h;
    }
}

float mean_crack_width(const BarkCylinder& bark, const std::uint32_t* springs, int count, float t,
                       const Vec3* W) {
    if (count <= 0) return 0.0f;
    double sum = 0.0;
    for (int i = 0; i < count; ++i) sum += crack_ribbon(bark, springs[i], t, W).width;
    return float(sum / count);
}

}  // namespace shitsukan
