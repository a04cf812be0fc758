// Tests for lib/shitsukan/raster/shading.cpp and gouraud.cpp: Lambert + ambient, Blinn-Phong,
// lights, face_forward, flat normals, Gouraud vertex lighting, to_rgb8.
#include <doctest/doctest.h>

#include <cmath>

#include "raster_test_scenes.hpp"
#include "shitsukan/raster/gouraud.hpp"
#include "shitsukan/raster/shading.hpp"

using namespace shitsukan;
using namespace raster_test;

namespace {
bool near3(Vec3 a, Vec3 b, float eps = 1e-5f) {
    return std::fabs(a.x - b.x) < eps && std::fabs(a.y - b.y) < eps && std::fabs(a.z - b.z) < eps;
}
}  // namespace

TEST_CASE("Lambert + ambient: k_a·base + I·C·k_d·base·max(0, n·l), summed over lights") {
    Material m;
    m.ambient = 0.2f;
    m.diffuse = 0.6f;
    Vec3 base{1.0f, 0.5f, 0.25f};
    Light sun = directional_light({0, 0, 5}, {1, 1, 1}, 1.0f);  // not unit: normalised on use
    Vec3 n{0, 0, 1};
    // Facing the light: ambient + full diffuse.
    CHECK(near3(shade_lambert(m, base, {0, 0, 0}, n, &sun, 1), base * 0.8f));
    // At 60 degrees: n·l = 1/2.
    Light tilted = directional_light({std::sqrt(3.0f), 0, 1});
    CHECK(near3(shade_lambert(m, base, {0, 0, 0}, n, &tilted, 1), base * (0.2f + 0.3f)));
    // Behind the surface: ambient only.
    Light behind = directional_light({0, 0, -1});
    CHECK(near3(shade_lambert(m, base, {0, 0, 0}, n, &behind, 1), base * 0.2f));
    // A coloured point light straight above a point off the origin, intensity 2.
    Light lamp = point_light({3, 1, 4}, {1, 0, 0.5f}, 2.0f);
    Vec3 c = shade_lambert(m, base, {3, 1, 0}, n, &lamp, 1);
    CHECK(near3(c, base * 0.2f + Vec3{1, 0, 0.5f} * base * (2.0f * 0.6f)));
    // Two lights add.
    Light two[2] = {sun, tilted};
    CHECK(near3(shade_lambert(m, base, {0, 0, 0}, n, two, 2), base * (0.2f + 0.6f + 0.3f)));
    CHECK(near3(shade_lambert(m, base, {0, 0, 0}, n, nullptr, 0), base * 0.2f));
}

TEST_CASE("Blinn-Phong: the highlight peaks when the half vector is the normal") {
    Material m;
    m.ambient = 0.0f;
    m.diffuse = 0.0f;
    m.specular = 0.5f;
    m.shininess = 20.0f;
    Vec3 n{0, 0, 1}, base{1, 1, 1};
    Light l = directional_light({1, 0, 1});
    // Mirror direction: eye along (-1, 0, 1) -> h = n: full highlight k_s.
    Vec3 mirror = shade_blinn_phong(m, base, {0, 0, 0}, n, {-1, 0, 1}, &l, 1);
    CHECK(near3(mirror, {0.5f, 0.5f, 0.5f}));
    // Eye along the normal: h at 22.5 degrees from n -> cos(22.5°)^20.
    Vec3 off = shade_blinn_phong(m, base, {0, 0, 0}, n, {0, 0, 3}, &l, 1);
    float expected = 0.5f * std::pow(std::cos(kPi / 8.0f), 20.0f);
    CHECK(off.x == doctest::Approx(expected).epsilon(1e-4));
    // No highlight when the light is behind the surface.
    Light under = directional_light({1, 0, -1});
    CHECK(near3(shade_blinn_phong(m, base, {0, 0, 0}, n, {-1, 0, 1}, &under, 1), {0, 0, 0}));
    // Specular 0: exactly Lambert.
    Material lam;
    CHECK(near3(shade_blinn_phong(lam, base, {0, 0, 0}, n, {0, 0, 1}, &l, 1),
                shade_lambert(lam, base, {0, 0, 0}, n, &l, 1)));
}

TEST_CASE("to_rgb8 clamps and rounds without gamma; face_forward; flat_normal") {
    Rgb8 c = to_rgb8({1.5f, -0.2f, 0.5f});
    CHECK(c.r == 255);
    CHECK(c.g == 0);
    CHECK(c.b == 128);
    CHECK(to_rgb8({NAN, 0.25f, 1}).r == 0);
    CHECK(face_forward({0, 0, 1}, {0, 0, 0}, {0, 0, -5}) == Vec3{0, 0, -1});
    CHECK(face_forward({0, 0, 1}, {0, 0, 0}, {0, 0, 5}) == Vec3{0, 0, 1});

    TriangleMesh tri;
    tri.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    tri.indices = {0, 1, 2};
    CHECK(near3(flat_normal(tri.view(), 0, Mat4::identity()), {0, 0, 1}));
    CHECK(near3(flat_normal(tri.view(), 0, Mat4::rotate_y(kPi / 2)), {1, 0, 0}));
}

TEST_CASE("Gouraud: vertices lit once, colours interpolated by the rasterizer") {
    TriangleMesh sphere = sphere_mesh(1.0f, 24, 12);
    Material m;
    m.specular = 0.3f;
    Light l = directional_light({1, 1, 1});
    Vec3 eye{0, 0, 4};
    Mat4 model = Mat4::translate({0.1f, 0, 0});
    REQUIRE(apply_gouraud(sphere, model, m, {0.8f, 0.6f, 0.4f}, eye, &l, 1).ok());
    REQUIRE(sphere.colors.size() == sphere.positions.size());
    for (std::size_t i = 0; i < sphere.positions.size(); i += 17) {
        Vec3 expected = shade_blinn_phong(m, {0.8f, 0.6f, 0.4f},
                                          transform_point(model, sphere.positions[i]),
                                          sphere.normals[i], eye, &l, 1);
        CHECK(near3(sphere.colors[i], expected));
    }
    // Errors: no normals, too small a buffer, singular model.
    TriangleMesh bare;
    bare.positions = {{0, 0, 0}};
    CHECK(!apply_gouraud(bare, model, m, {1, 1, 1}, eye, &l, 1).ok());
    Vec3 out[2];
    CHECK(light_vertices(sphere.view(), model, m, {1, 1, 1}, eye, &l, 1, out, 2).code() ==
          StatusCode::buffer_too_small);
    CHECK(!apply_gouraud(sphere, Mat4::scale({0, 1, 1}), m, {1, 1, 1}, eye, &l, 1).ok());

    // The rasterizer interpolates the lit colours: a smooth picture with the lit side bright.
    Camera cam = perspective_camera(eye, {0, 0, 0}, {0, 1, 0}, 40.0f, 48, 48);
    RgbImage color(48, 48);
    FloatImage depth(48, 48);
    FrameBand band = full_frame_band(color.view(), depth.view());
    clear_band(band, Rgb8{0, 0, 0});
    auto shader = [](const Fragment& f) { return to_rgb8(f.color); };
    DrawOptions opt;
    opt.model = model;
    REQUIRE(draw_mesh(cam, band, sphere.view(), opt, shader).ok());
    CHECK(color.at(30, 16).r > color.at(17, 31).r + 60);  // upper right (lit) vs lower left
}
