// Tests for lib/shitsukan/raster/clip.cpp and the rasterizer's use of it: near-plane
// clipping of triangles crossing the near plane or having a vertex behind the eye, compared
// with a reference made by subdividing the triangle and keeping only the pieces in front.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>

#include "raster_test_scenes.hpp"
#include "shitsukan/raster/clip.hpp"

using namespace shitsukan;
using namespace raster_test;

namespace {

// The triangle p0 p1 p2 (uv (0,0), (1,0), (0,1)) split into n² pieces on a barycentric grid
// (shared vertices, computed in double), keeping only pieces whose corners are all at least
// `margin` in front of the eye along the view direction.
TriangleMesh subdivided(Vec3 p0, Vec3 p1, Vec3 p2, int n, const Camera& cam, float margin) {
    TriangleMesh m;
    auto id = [&](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            double a = double(i) / n, b = double(j) / n;
            Vec3 p{float(p0.x + (p1.x - p0.x) * a + (p2.x - p0.x) * b),
                   float(p0.y + (p1.y - p0.y) * a + (p2.y - p0.y) * b),
                   float(p0.z + (p1.z - p0.z) * a + (p2.z - p0.z) * b)};
            m.add_vertex(p, {0, 0, 1}, {float(a), float(b)});
        }
    auto in_front = [&](std::uint32_t v) {
        return transform_point(cam.view, m.positions[v]).z < -margin;
    };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i + j < n; ++i) {
            std::uint32_t t[2][3] = {{id(i, j), id(i + 1, j), id(i, j + 1)},
                                     {id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)}};
            for (int k = 0; k < (i + j + 1 < n ? 2 : 1); ++k)
                if (in_front(t[k][0]) && in_front(t[k][1]) && in_front(t[k][2]))
                    m.add_triangle(t[k][0], t[k][1], t[k][2]);
        }
    return m;
}

struct Render {
    RgbImage color;
    long fragments = 0;
    RasterStats stats;
};

Render render(const Camera& cam, const MeshView& mesh) {
    Render r;
    r.color.resize(cam.width, cam.height);
    FloatImage depth(cam.width, cam.height);
    FrameBand band = full_frame_band(r.color.view(), depth.view());
    clear_band(band, Rgb8{0, 0, 0});
    auto uv_shader = [&](const Fragment& f) {
        ++r.fragments;
        return Rgb8{to_byte(0.1f + 0.8f * f.uv.x), to_byte(0.1f + 0.8f * f.uv.y), 200};
    };
    DrawOptions opt;
    opt.cull = CullMode::none;
    Status s = draw_mesh(cam, band, mesh, opt, uv_shader, &r.stats);
    CHECK(s.ok());
    return r;
}

// The clipped render against the subdivided reference: same pixels covered (up to the
// rounding of the subdivided boundary) and the same colours.
void compare_with_reference(const Camera& cam, Vec3 p0, Vec3 p1, Vec3 p2) {
    TriangleMesh one;
    one.add_vertex(p0, {0, 0, 1}, {0, 0});
    one.add_vertex(p1, {0, 0, 1}, {1, 0});
    one.add_vertex(p2, {0, 0, 1}, {0, 1});
    one.add_triangle(0, 1, 2);
    TriangleMesh ref = subdivided(p0, p1, p2, 64, cam, 0.06f);
    Render a = render(cam, one.view());
    Render b = render(cam, ref.view());
    CHECK(a.stats.triangles_clipped == 1);
    CHECK(a.stats.triangles_drawn == 1);
    int only_one = 0, covered = 0, max_diff = 0;
    for (int y = 0; y < cam.height; ++y)
        for (int x = 0; x < cam.width; ++x) {
            Rgb8 p = a.color.at(x, y), q = b.color.at(x, y);
            bool pa = p.b != 0, pb = q.b != 0;
            covered += pa;
            if (pa != pb) {
                ++only_one;
                continue;
            }
            if (!pa) continue;
            max_diff = std::max(max_diff, std::max(std::abs(p.r - q.r), std::abs(p.g - q.g)));
        }
    INFO("covered " << covered << ", in one image only " << only_one);
    CHECK(covered > cam.width * cam.height / 5);
    CHECK(only_one <= covered / 500);  // pixel centres within ~1/256 px of the boundary
    CHECK(max_diff <= 1);
}

}  // namespace

TEST_CASE("clip_triangle: a vertex behind the near plane gives a quadrilateral in front") {
    ClipSpaceVertex t[3] = {{{0, 0, 0.5f, 1}, {1, 0, 0}},     // in front
                       {{1, 0, -3, -2}, {0, 1, 0}},      // behind the eye (w < 0)
                       {{0, 1, 0.2f, 1}, {0, 0, 1}}};    // in front
    ClipPolygon poly;
    ClipResult r = clip_triangle(t, &poly);
    CHECK(!r.outside);
    CHECK(!r.not_finite);
    CHECK(r.clipped_near);
    REQUIRE(poly.count == 4);
    for (int i = 0; i < poly.count; ++i) {
        const ClipSpaceVertex& v = poly.v[i];
        CHECK(v.clip.z + v.clip.w >= -1e-6f);
        CHECK(v.clip.w > 0.0f);
        CHECK(v.bary.x + v.bary.y + v.bary.z == doctest::Approx(1.0f));
        // Clipping is linear: the clip position is the barycentric mix of the corners.
        Vec4 mix = t[0].clip * v.bary.x + t[1].clip * v.bary.y + t[2].clip * v.bary.z;
        CHECK(std::fabs(mix.x - v.clip.x) < 1e-5f);
        CHECK(std::fabs(mix.w - v.clip.w) < 1e-5f);
    }
}

TEST_CASE("clip_triangle: two triangles sharing a crossing edge get the same cut point") {
    ClipSpaceVertex shared_front{{0.3f, 0.1f, 0.7f, 2.1f}, {}};
    ClipSpaceVertex shared_back{{-0.7f, 0.4f, -1.3f, -0.9f}, {}};
    ClipSpaceVertex t1[3] = {shared_front, shared_back, {{1, 1, 0.5f, 1.5f}, {}}};
    ClipSpaceVertex t2[3] = {shared_back, shared_front, {{-1, -1, 0.5f, 1.5f}, {}}};  // reversed
    ClipPolygon p1, p2;
    clip_triangle(t1, &p1);
    clip_triangle(t2, &p2);
    // The cut point on the shared edge: the vertex with z + w == 0 (up to rounding) in both.
    int found = 0;
    for (int i = 0; i < p1.count; ++i)
        for (int j = 0; j < p2.count; ++j)
            if (std::fabs(p1.v[i].clip.z + p1.v[i].clip.w) < 1e-6f &&
                std::memcmp(&p1.v[i].clip, &p2.v[j].clip, sizeof(Vec4)) == 0)
                ++found;
    CHECK(found == 1);
}

TEST_CASE("clip_triangle: wholly behind or beside the view is outside, NaN is not finite") {
    ClipPolygon poly;
    ClipSpaceVertex behind[3] = {{{0, 0, -3, -1}, {}}, {{1, 0, -3, -1}, {}}, {{0, 1, -3, -1}, {}}};
    CHECK(clip_triangle(behind, &poly).outside);
    CHECK(poly.count == 0);
    ClipSpaceVertex right[3] = {{{2, 0, 0, 1}, {}}, {{3, 0, 0, 1}, {}}, {{2, 1, 0, 1}, {}}};
    CHECK(clip_triangle(right, &poly).outside);
    ClipSpaceVertex nan[3] = {{{NAN, 0, 0, 1}, {}}, {{3, 0, 0, 1}, {}}, {{2, 1, 0, 1}, {}}};
    CHECK(clip_triangle(nan, &poly).not_finite);
}

TEST_CASE("near-plane clipping: a floor with vertices behind the eye matches the subdivided "
          "reference") {
    Camera cam = perspective_camera({0, 0.5f, 0}, {0, 0.3f, -3}, {0, 1, 0}, 60.0f, 96, 72);
    // Two corners behind the eye (z = +2 > eye z 0), one far in front.
    compare_with_reference(cam, {-3, 0, 2}, {3, 0, 2}, {0.4f, 0, -10});
}

TEST_CASE("near-plane clipping: a wall crossing the near plane beside the eye matches the "
          "subdivided reference") {
    Camera cam = perspective_camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60.0f, 96, 72);
    compare_with_reference(cam, {0.6f, -1, 2}, {0.6f, -1, -6}, {0.6f, 1.5f, -6});
}

TEST_CASE("near-plane clipping never draws a wrapped-around image of the hidden part") {
    // A triangle entirely behind the eye except a thin part in front, seen looking away:
    // only pixels of the in-front part may appear, all below the horizon.
    Camera cam = perspective_camera({0, 1, 0}, {0, 1, -1}, {0, 1, 0}, 60.0f, 64, 64);
    TriangleMesh m;
    m.add_vertex({-50, 0, 30});
    m.add_vertex({50, 0, 30});
    m.add_vertex({0, 0, -4});
    m.add_triangle(0, 1, 2);
    Render r = render(cam, m.view());
    int above = 0, below = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
            if (r.color.at(x, y).b != 0) (y < 32 ? above : below)++;
    CHECK(above == 0);
    CHECK(below > 100);
}

namespace {

// One triangle drawn with the given culling: the pixels written and how many fragments
// said front_facing.
struct Facing {
    int pixels = 0, front = 0;
};
Facing draw_facing(const Camera& cam, const MeshView& mesh, CullMode cull) {
    Facing r;
    RgbImage color(cam.width, cam.height);
    FloatImage depth(cam.width, cam.height);
    FrameBand band = full_frame_band(color.view(), depth.view());
    clear_band(band, Rgb8{0, 0, 0});
    auto count = [&](const Fragment& f) {
        ++r.pixels;
        r.front += f.front_facing;
        return Rgb8{255, 255, 255};
    };
    DrawOptions opt;
    opt.cull = cull;
    CHECK(draw_mesh(cam, band, mesh, opt, count).ok());
    return r;
}

}  // namespace

TEST_CASE("facing is decided once per mesh triangle: near-plane slivers are not flipped apart") {
    // A corner just behind the near plane: the two cut points lie within a small fraction of
    // a pixel of each other, so the fan piece between them is a sliver whose snapped area
    // can change sign. The whole visible part must still be front or back as one: the same
    // front_facing on every fragment, culled all or nothing, and the facing the triangle
    // really has (its normal against the direction to the eye).
    Camera cam = perspective_camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60.0f, 64, 64);
    Pcg32 rng(20261121);
    int mixed = 0, split_culls = 0, wrong = 0, drawn = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        float za = rng.uniform(-4.0f, -0.3f), zb = rng.uniform(-4.0f, -0.3f);
        Vec3 a{rng.signed_unit() * -za * 0.5f, rng.signed_unit() * -za * 0.5f, za};
        Vec3 b{rng.signed_unit() * -zb * 0.5f, rng.signed_unit() * -zb * 0.5f, zb};
        float behind = std::pow(10.0f, rng.uniform(-8.0f, -5.0f));  // inside the near plane
        Vec3 c{rng.signed_unit() * 0.02f, rng.signed_unit() * 0.02f, -0.05f + behind};
        if (rng.uniform() < 0.5f) std::swap(a, b);
        TriangleMesh m;
        m.positions = {a, b, c};
        m.indices = {0, 1, 2};
        Facing none = draw_facing(cam, m.view(), CullMode::none);
        if (none.pixels == 0) continue;
        ++drawn;
        Facing back = draw_facing(cam, m.view(), CullMode::back);    // keeps front faces
        Facing front = draw_facing(cam, m.view(), CullMode::front);  // keeps back faces
        bool is_front = none.front == none.pixels;
        mixed += none.front != 0 && !is_front;
        split_culls += back.pixels != (is_front ? none.pixels : 0) ||
                       front.pixels != (is_front ? 0 : none.pixels);
        // The eye is at the origin: front when the normal points towards it.
        Vec3d n = cross(Vec3d{b.x - a.x, b.y - a.y, b.z - a.z},
                        Vec3d{c.x - a.x, c.y - a.y, c.z - a.z});
        double towards_eye = -(n.x * a.x + n.y * a.y + n.z * a.z);
        if (std::fabs(towards_eye) > 1e-6 * std::sqrt(length_squared(n)))
            wrong += (towards_eye > 0) != is_front;
    }
    CHECK(drawn > 1000);
    CHECK(mixed == 0);
    CHECK(split_culls == 0);
    CHECK(wrong == 0);
}
