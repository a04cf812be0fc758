// Tests for lib/shitsukan/raster/blinn1977 (the reflection model of tokai1994 §5) and
// raster/bump_mapping (Blinn 1978 in an orthonormal tangent frame).
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <initializer_list>

#include "shitsukan/core/prng.hpp"
#include "shitsukan/raster/blinn1977.hpp"
#include "shitsukan/raster/bump_mapping.hpp"

using namespace shitsukan;

TEST_CASE("blinn1977: D1, D2, D3 are 1 at alpha = 0 and fall off; D3 c3 = 1 is flat") {
    for (BlinnDistribution d : {BlinnDistribution::d1_phong, BlinnDistribution::d2_gaussian,
                                BlinnDistribution::d3_trowbridge_reitz}) {
        Blinn1977Material m;
        m.distribution = d;
        CHECK(blinn1977_distribution(m, 1.0f) == doctest::Approx(1.0f));
        float prev = 1.0f;
        for (int k = 1; k <= 20; ++k) {
            float c = std::cos(float(k) * 0.05f);
            float v = blinn1977_distribution(m, c);
            CHECK(v < prev);
            CHECK(v >= 0.0f);
            prev = v;
        }
    }
    Blinn1977Material flat;
    flat.c3 = 1.0f;
    CHECK(blinn1977_distribution(flat, 0.3f) == doctest::Approx(1.0f));
}

TEST_CASE("blinn1977: F is 1 head-on and grows to 1/F0 at grazing; G = 1 head-on") {
    CHECK(blinn1977_fresnel(1.0f, 1.5f) == doctest::Approx(1.0f));
    CHECK(blinn1977_fresnel(0.0f, 1.5f) == doctest::Approx(25.0f).epsilon(1e-3));  // F0 = 0.04
    CHECK(blinn1977_fresnel(0.5f, 1.5f) > 1.0f);
    CHECK(blinn1977_geometry(1.0f, 1.0f, 1.0f, 1.0f) == 1.0f);
    CHECK(blinn1977_geometry(0.9f, 0.05f, 0.9f, 0.5f) < 1.0f);  // masked at grazing view
}

TEST_CASE("blinn1977: specular peaks at the mirror direction, DGF is reciprocal") {
    Blinn1977Material m;
    Vec3 n{0, 0, 1}, l = normalize(Vec3{1, 0, 1});
    float mirror = blinn1977_specular(m, n, l, normalize(Vec3{-1, 0, 1}));
    // Same elevation (same N·E), other azimuths: dimmer. (Toward grazing elevations the
    // 1/(N·E) and Fresnel factors give Torrance-Sparrow's off-specular peak instead.)
    for (float phi : {0.2f, 0.5f, 1.0f, 2.0f, 3.0f}) {
        Vec3 e = normalize(Vec3{-std::cos(phi), std::sin(phi), 1.0f});
        CHECK(blinn1977_specular(m, n, l, e) < mirror);
    }
    Pcg32 rng(7);
    for (int k = 0; k < 200; ++k) {
        Vec3 a = normalize(Vec3{rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform()});
        Vec3 b = normalize(Vec3{rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform()});
        if (a.z < 0.1f || b.z < 0.1f) continue;
        float ab = blinn1977_specular(m, n, a, b) * b.z;  // D G F, symmetric in L and E
        float ba = blinn1977_specular(m, n, b, a) * a.z;
        CHECK(ab == doctest::Approx(ba).epsilon(1e-4));
    }
    // Light behind the surface: ambient only.
    PointLight light{{0, 0, -5}, {1, 1, 1}};
    Vec3 c = shade_blinn1977(m, {0, 0, 0}, n, {0, 0, 5}, &light, 1);
    CHECK(c.x == doctest::Approx(m.color.x * m.ka));
    light.position = {0, 0, 5};
    Vec3 lit = shade_blinn1977(m, {0, 0, 0}, n, {0, 0, 5}, &light, 1);
    CHECK(lit.x == doctest::Approx(m.color.x * (m.ka + m.kd) + m.ks));  // head-on: D=G=F=1
}

TEST_CASE("bump mapping: texture tangents, an orthonormal frame, and the perturbed normal") {
    // A triangle in the plane z = 1 with texture point = 2·(x, y) + (3, 4).
    Vec3 p0{0, 0, 1}, p1{1, 0, 1}, p2{0, 1, 1};
    Vec3 dpdx, dpdy;
    REQUIRE(triangle_texture_tangents(p0, p1, p2, {3, 4}, {5, 4}, {3, 6}, &dpdx, &dpdy));
    CHECK(length(dpdx - Vec3{0.5f, 0, 0}) < 1e-6f);
    CHECK(length(dpdy - Vec3{0, 0.5f, 0}) < 1e-6f);
    CHECK(!triangle_texture_tangents(p0, p1, p2, {1, 1}, {1, 1}, {2, 2}, &dpdx, &dpdy));
    Pcg32 rng(11);
    for (int k = 0; k < 300; ++k) {
        auto rnd = [&] {
            return Vec3{rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform() - 0.5f};
        };
        Vec3 n = normalize(rnd()), tx = rnd(), ty = rnd();  // sheared, not perpendicular to n
        TangentFrame f = orthonormal_tangent_frame(n, tx, ty);
        CHECK(std::fabs(dot(f.t, f.b)) < 1e-5f);
        CHECK(std::fabs(dot(f.t, f.n)) < 1e-5f);
        CHECK(std::fabs(dot(f.b, f.n)) < 1e-5f);
        CHECK(length(f.t) == doctest::Approx(1.0f).epsilon(1e-5));
        CHECK(length(f.b) == doctest::Approx(1.0f).epsilon(1e-5));
        CHECK(dot(f.t, tx) >= 0.0f);
        CHECK(dot(f.b, ty) >= 0.0f);
        CHECK(length(perturb_normal(f, {0, 0, 1}) - f.n) < 1e-5f);
        Vec3 m = normalize(Vec3{0.3f, -0.2f, 1.0f});
        Vec3 q = perturb_normal(f, m);
        CHECK(length(q) == doctest::Approx(1.0f).epsilon(1e-5));
        CHECK(dot(q, f.t) == doctest::Approx(m.x).epsilon(1e-4));  // angles are kept
        CHECK(dot(q, f.b) == doctest::Approx(m.y).epsilon(1e-4));
    }
    TangentFrame degenerate = orthonormal_tangent_frame({0, 0, 1}, {0, 0, 2}, {0, 1, 0});
    CHECK(std::fabs(dot(degenerate.t, degenerate.n)) < 1e-6f);
    CHECK(length(degenerate.t) == doctest::Approx(1.0f));
}

TEST_CASE("bump mapping: mesh_texture_tangents = triangle_texture_tangents per triangle") {
    // Two triangles of the plane z = 0 with texture = 2·(x, y), and a third with no texture area.
    const Vec3 p[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    const Vec2 uv[4] = {{0, 0}, {2, 0}, {2, 2}, {2, 2}};
    const std::uint32_t idx[9] = {0, 1, 2, 0, 2, 3, 1, 2, 3};
    MeshView m;
    m.positions = p;
    m.uvs = uv;
    m.vertex_count = 4;
    m.indices = idx;
    m.triangle_count = 3;
    Vec3 dx[3], dy[3];
    REQUIRE(mesh_texture_tangents(m, dx, dy, 3).ok());
    CHECK(length(dx[0] - Vec3{0.5f, 0, 0}) < 1e-6f);
    CHECK(length(dy[0] - Vec3{0, 0.5f, 0}) < 1e-6f);
    Vec3 ex, ey;
    triangle_texture_tangents(p[1], p[2], p[3], uv[1], uv[2], uv[3], &ex, &ey);
    CHECK(length(dx[2] - ex) == 0.0f);  // both 0: that texture triangle has no area
    CHECK(length(dy[2] - ey) == 0.0f);
    // Bad input: too small buffers, no uvs, an index past the vertices.
    CHECK(mesh_texture_tangents(m, dx, dy, 2).code() == StatusCode::invalid_argument);
    MeshView no_uv = m;
    no_uv.uvs = nullptr;
    CHECK(!mesh_texture_tangents(no_uv, dx, dy, 3).ok());
    const std::uint32_t bad_idx[3] = {0, 1, 7};
    MeshView bad = m;
    bad.indices = bad_idx;
    bad.triangle_count = 1;
    Status s = mesh_texture_tangents(bad, dx, dy, 3);
    CHECK(!s.ok());
    CHECK(std::strstr(s.message(), "vertex 7") != nullptr);
}
