#include "shitsukan/leather/products.hpp"
#include "shitsukan/core/detmath.hpp"

#include <cmath>

namespace shitsukan {

namespace {

// One control row of the body tube (see the manual's table).
struct BodyRow {
    float y, w, d, k;
};
constexpr BodyRow kBodyRows[4] = {
    {0.00f, 0.56f, 0.28f, 0.12f},
    {0.34f, 0.60f, 0.33f, 0.14f},
    {0.70f, 0.63f, 0.21f, 0.09f},
    {0.92f, 0.64f, 0.03f, 0.015f},
};

// The four control points of side `side` (0 front, 1 right, 2 back, 3 left) of a rounded
// rectangle: the sides meet at the 45-degree points of the corners, with the neighbouring
// control points on the 45-degree tangent there (G1 around the tube).
void body_row(const BodyRow& r, int side, Vec3 out[4]) {
    float w = r.w, d = r.d, k = r.k, y = r.y;
    switch (side) {
        case 0:  // front, x increasing
            out[0] = {-(w - k), y, d - k};
            out[1] = {-(w - 2 * k), y, d};
            out[2] = {w - 2 * k, y, d};
            out[3] = {w - k, y, d - k};
            break;
        case 1:  // right, z decreasing
            out[0] = {w - k, y, d - k};
            out[1] = {w, y, d - 2 * k};
            out[2] = {w, y, -(d - 2 * k)};
            out[3] = {w - k, y, -(d - k)};
            break;
        case 2:  // back, x decreasing
            out[0] = {w - k, y, -(d - k)};
            out[1] = {w - 2 * k, y, -d};
            out[2] = {-(w - 2 * k), y, -d};
            out[3] = {-(w - k), y, -(d - k)};
            break;
        default:  // left, z increasing
            out[0] = {-(w - k), y, -(d - k)};
            out[1] = {-w, y, -(d - 2 * k)};
            out[2] = {-w, y, d - 2 * k};
            out[3] = {-(w - k), y, d - k};
            break;
    }
}

}  // namespace

Handbag make_handbag() {
    Handbag bag;
    // Patches 0-3: the body tube, v up.
    for (int side = 0; side < 4; ++side)
        for (int j = 0; j < 4; ++j) {
            Vec3 row[4];
            body_row(kBodyRows[j], side, row);
            for (int i = 0; i < 4; ++i) bag.patches[side].p[i][j] = row[i];
        }
    // Patch 4: the bottom, bounded by the four bottom rows (front, right, back, left).
    {
        Vec3 f[4], r[4], b[4], l[4];
        body_row(kBodyRows[0], 0, f);
        body_row(kBodyRows[0], 1, r);
        body_row(kBodyRows[0], 2, b);
        body_row(kBodyRows[0], 3, l);
        BezierPatch q;
        for (int i = 0; i < 4; ++i) {
            q.p[i][0] = f[i];
            q.p[i][3] = b[3 - i];
            q.p[3][i] = r[i];
            q.p[0][i] = l[3 - i];
        }
        for (int i = 1; i < 3; ++i)
            for (int j = 1; j < 3; ++j) q.p[i][j] = {f[i].x, 0.0f, r[j].z};
        // Transposed so that du x dv points down (out of the bag).
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) bag.patches[4].p[i][j] = q.p[j][i];
    }
    // Patches 5-6: the handle, an arch with a half-round strap across it.
    {
        const Vec3 arch[2][4] = {
            {{-0.40f, 0.92f, 0}, {-0.40f, 1.25f, 0}, {-0.22f, 1.42f, 0}, {0.0f, 1.42f, 0}},
            {{0.0f, 1.42f, 0}, {0.22f, 1.42f, 0}, {0.40f, 1.25f, 0}, {0.40f, 0.92f, 0}},
        };
        const Vec3 centre{0.0f, 0.95f, 0.0f};  // the arch's outward normals point away from it
        const float radius = 0.045f;
        const float across[4] = {radius, radius, -radius, -radius};  // along z
        const float raise[4] = {0.0f, 4.0f * radius / 3.0f, 4.0f * radius / 3.0f, 0.0f};
        for (int h = 0; h < 2; ++h)
            for (int i = 0; i < 4; ++i) {
                Vec3 c = arch[h][i];
                Vec3 n = normalize(Vec3{c.x - centre.x, c.y - centre.y, 0.0f});
                // At the apex and its neighbours the strap is raised straight up, so the
                // rows' tangents there are collinear on both halves (G1 across the joint).
                if ((h == 0 && i >= 2) || (h == 1 && i <= 1)) n = {0, 1, 0};
                for (int j = 0; j < 4; ++j)
                    bag.patches[5 + h].p[i][j] = c + Vec3{0, 0, across[j]} + n * raise[j];
            }
    }
    // The clasp: two kiss-lock knobs on the frame.
    bag.clasp[0] = {{-0.05f, 0.95f, 0.012f}, 0.045f, -0.6f};
    bag.clasp[1] = {{0.05f, 0.95f, -0.012f}, 0.045f, -0.6f};
    return bag;
}

Status make_belt(const BeltDesign& d, std::vector<BezierPatch>& out) {
    if (!is_finite(d.width) || !is_finite(d.r0) || !is_finite(d.r1) || !is_finite(d.turns) ||
        !(d.width > 0) || !(d.r0 > 0) || !(d.r1 > d.r0))
        return Status::error(StatusCode::invalid_argument,
                             "belt: need width > 0 and 0 < r0 < r1 (got width %g, r0 %g, r1 %g)",
                             double(d.width), double(d.r0), double(d.r1));
    if (!(d.turns >= 0.25f && d.turns <= 8.0f))
        return Status::error(StatusCode::invalid_argument, "belt: turns must be 0.25..8 (got %g)",
                             double(d.turns));
    const int n = int(std::ceil(d.turns * 4.0f - 1e-4f));
    const float total = d.turns * kTwoPi, step = total / float(n);
    auto point = [&](float t) {  // the spiral r(t) = r0 + (r1 - r0) t / total
        float r = d.r0 + (d.r1 - d.r0) * t / total;
        return Vec3{r * det_cos(t), 0.0f, r * det_sin(t)};
    };
    auto tangent = [&](float t) {  // dP/dt
        float r = d.r0 + (d.r1 - d.r0) * t / total, dr = (d.r1 - d.r0) / total;
        return Vec3{dr * det_cos(t) - r * det_sin(t), 0.0f, dr * det_sin(t) + r * det_cos(t)};
    };
    out.assign(std::size_t(n), BezierPatch{});
    for (int k = 0; k < n; ++k) {
        float ta = step * float(k), tb = step * float(k + 1);
        // Hermite -> Bezier: the quarter turn with the spiral's end tangents (G1 joints).
        Vec3 row[4] = {point(ta), point(ta) + tangent(ta) * (step / 3.0f),
                       point(tb) - tangent(tb) * (step / 3.0f), point(tb)};
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)  // v runs down the belt so du x dv faces outward
                out[std::size_t(k)].p[i][j] = row[i] + Vec3{0, d.width * float(3 - j) / 3.0f, 0};
    }
    return Status::success();
}

Status make_spherical_segment(const SphericalSegment& s, int slices, int stacks,
                              TriangleMesh& out) {
    if (!(s.radius > 0) || !is_finite(s.radius) || !is_finite(s.center))
        return Status::error(StatusCode::invalid_argument,
                             "spherical segment: radius must be finite and > 0 (got %g)",
                             double(s.radius));
    if (!(s.cut_below >= -1.0f && s.cut_below < 1.0f))
        return Status::error(StatusCode::invalid_argument,
                             "spherical segment: cut_below must be in [-1, 1) (got %g)",
                             double(s.cut_below));
    if (slices < 3 || slices > 4096 || stacks < 1 || stacks > 4096)
        return Status::error(StatusCode::invalid_argument,
                             "spherical segment: slices 3..4096, stacks 1..4096 (got %d, %d)",
                             slices, stacks);
    out = TriangleMesh{};
    const float lat0 = det_asin(s.cut_below), lat1 = 0.5f * kPi;
    for (int j = 0; j <= stacks; ++j) {
        float lat = lat0 + (lat1 - lat0) * float(j) / float(stacks);
        for (int i = 0; i <= slices; ++i) {
            float lon = kTwoPi * float(i) / float(slices);
            Vec3 n{det_cos(lat) * det_cos(lon), det_sin(lat), -det_cos(lat) * det_sin(lon)};
            out.add_vertex(s.center + n * s.radius, n,
                            {float(i) / float(slices), float(j) / float(stacks)});
        }
    }
    for (int j = 0; j < stacks; ++j)
        for (int i = 0; i < slices; ++i) {
            std::uint32_t a = std::uint32_t(j * (slices + 1) + i), b = a + 1;
            std::uint32_t c = a + std::uint32_t(slices + 1), e = c + 1;
            out.add_triangle(a, b, e);
            if (j + 1 < stacks) out.add_triangle(a, e, c);  // the top row meets at the pole
        }
    return Status::success();
}

}  // namespace shitsukan
