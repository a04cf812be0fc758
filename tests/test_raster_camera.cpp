// Tests for lib/shitsukan/raster/camera.cpp: look_at, perspective and orthographic cameras,
// project (screen conventions: x right, y down, depth 0 at near and 1 at far).
#include <doctest/doctest.h>

#include <cmath>

#include "shitsukan/raster/camera.hpp"

using namespace shitsukan;

TEST_CASE("look_at is a rigid motion taking the eye to the origin, looking down -z") {
    Vec3 eye{3, 2, 4}, target{0.5f, -0.2f, 0.1f};
    Mat4 v = look_at(eye, target, {0, 1, 0});
    Vec3 e = transform_point(v, eye);
    CHECK(length(e) < 1e-5f);
    Vec3 t = transform_point(v, target);
    CHECK(std::fabs(t.x) < 1e-5f);
    CHECK(std::fabs(t.y) < 1e-5f);
    CHECK(t.z == doctest::Approx(-length(target - eye)).epsilon(1e-5));
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            float d = v.m[i][0] * v.m[j][0] + v.m[i][1] * v.m[j][1] + v.m[i][2] * v.m[j][2];
            CHECK(d == doctest::Approx(i == j ? 1.0f : 0.0f).epsilon(1e-5));
        }
    // World up stays up: a point above the target is above it in eye space.
    CHECK(transform_point(v, target + Vec3{0, 1, 0}).y > 0.5f);
}

TEST_CASE("perspective camera: centre, orientation, depth range and field of view") {
    Camera cam = perspective_camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 90.0f, 200, 100, 1.0f, 10.0f);
    Vec3 c = project(cam, {0, 0, 0});
    CHECK(c.x == doctest::Approx(100.0f));
    CHECK(c.y == doctest::Approx(50.0f));
    CHECK(project(cam, {1, 0, 0}).x > c.x);  // x right
    CHECK(project(cam, {0, 1, 0}).y < c.y);  // y down on screen: world up goes up
    CHECK(project(cam, {0, 0, 4}).z == doctest::Approx(0.0f).epsilon(1e-5));  // near plane
    CHECK(std::fabs(project(cam, {0, 0, -5}).z - 1.0f) < 1e-5f);               // far plane
    // fov 90: at distance 5 the half height is 5, so y = 5 is the top row.
    CHECK(project(cam, {0, 5, 0}).y == doctest::Approx(0.0f).epsilon(1e-4));
    // aspect 2: at distance 5 the half width is 10.
    CHECK(project(cam, {10, 0, 0}).x == doctest::Approx(200.0f).epsilon(1e-4));
    // Nearer is smaller depth.
    CHECK(project(cam, {0, 0, 1}).z < project(cam, {0, 0, -1}).z);
    CHECK(!cam.orthographic);
    CHECK(cam.eye == Vec3{0, 0, 5});
}

TEST_CASE("orthographic camera: size does not change with distance") {
    Camera cam = orthographic_camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 2.0f, 100, 100);
    CHECK(cam.orthographic);
    Vec3 a = project(cam, {1, 1, 0}), b = project(cam, {1, 1, -3});
    CHECK(a.x == doctest::Approx(b.x));
    CHECK(a.y == doctest::Approx(b.y));
    CHECK(a.x == doctest::Approx(75.0f));
    CHECK(a.y == doctest::Approx(25.0f));
    CHECK(a.z < b.z);
    Vec4 clip = cam.projection * (cam.view * Vec4{1, 1, 0, 1});
    Vec3 s = clip_to_screen(cam, clip);
    CHECK(s.x == a.x);
    CHECK(s.y == a.y);
}
