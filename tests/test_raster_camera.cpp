// Tests for lib/shitsukan/raster/camera.cpp: look_at, perspective and orthographic cameras,
// project (screen conventions: x right, y down, depth 0 at near and 1 at far), the checked
// builders and validate_camera (and that draw_mesh / draw_edges refuse a bad camera).
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "shitsukan/raster/camera.hpp"
#include "shitsukan/raster/rasterizer.hpp"
#include "shitsukan/raster/wireframe.hpp"

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

namespace {

bool says(const Status& s, const char* text) {
    return !s.ok() && std::strstr(s.message(), text) != nullptr;
}

// What draw_mesh and draw_edges make of a camera: a triangle in front of it, one frame.
struct DrawResult {
    Status mesh, edges;
    int lit = 0;
};
DrawResult draw_with(const Camera& cam) {
    const int W = 16, H = 16;
    Rgb8 color[W * H];
    float depth[W * H];
    FrameBand band = make_band(RgbView{color, W, H, W}, FloatView{depth, W, H, W}, 0,
                               cam.width, cam.height);
    clear_band(band, Rgb8{0, 0, 0});
    const Vec3 positions[3] = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
    const std::uint32_t indices[3] = {0, 1, 2};
    MeshView mesh;
    mesh.positions = positions;
    mesh.vertex_count = 3;
    mesh.indices = indices;
    mesh.triangle_count = 1;
    DrawOptions opt;
    opt.cull = CullMode::none;
    DrawResult r;
    r.mesh = draw_mesh(cam, band, mesh, opt,
                       [](const Fragment&, void*) { return Rgb8{255, 255, 255}; }, nullptr);
    const WireEdge edges[3] = {{0, 1}, {1, 2}, {2, 0}};
    r.edges = draw_edges(cam, band, mesh, edges, 3, WireOptions{});
    for (int i = 0; i < W * H; ++i) r.lit += color[i].r != 0;
    return r;
}

}  // namespace

TEST_CASE("checked camera builders: the same camera for good input, a clear Status for bad") {
    const Vec3 eye{0, 0, 3}, target{0, 0, 0}, up{0, 1, 0};
    Camera checked;
    REQUIRE(make_perspective_camera(eye, target, up, 45.0f, 16, 16, 0.05f, 100.0f, checked)
                .ok());
    Camera plain = perspective_camera(eye, target, up, 45.0f, 16, 16);
    CHECK(std::memcmp(&checked.view, &plain.view, sizeof(Mat4)) == 0);
    CHECK(std::memcmp(&checked.projection, &plain.projection, sizeof(Mat4)) == 0);
    CHECK(validate_camera(plain).ok());
    DrawResult good = draw_with(plain);
    CHECK(good.mesh.ok());
    CHECK(good.edges.ok());
    CHECK(good.lit > 20);
    Camera ortho;
    REQUIRE(make_orthographic_camera(eye, target, up, 1.5f, 16, 16, 0.05f, 100.0f, ortho).ok());
    CHECK(validate_camera(ortho).ok());
    CHECK(ortho.orthographic);

    // Each bad input: the checked builder names it, the unchecked builder's camera fails
    // validate_camera, and draw_mesh / draw_edges refuse it and draw nothing.
    struct Bad {
        const char* what;
        Vec3 eye, target, up;
        float fov, near_plane, far_plane;
        const char* message;
    };
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const Bad bad[] = {
        {"eye == target", eye, eye, up, 45, 0.05f, 100, "coincide"},
        {"up parallel", eye, target, {0, 0, 2}, 45, 0.05f, 100, "parallel"},
        {"up zero", eye, target, {0, 0, 0}, 45, 0.05f, 100, "parallel"},
        {"fov 0", eye, target, up, 0, 0.05f, 100, "(0, 180)"},
        {"fov negative", eye, target, up, -30, 0.05f, 100, "(0, 180)"},
        {"fov 180", eye, target, up, 180, 0.05f, 100, "(0, 180)"},
        {"fov 200", eye, target, up, 200, 0.05f, 100, "(0, 180)"},
        {"near 0", eye, target, up, 45, 0, 100, "near plane 0"},
        {"near negative", eye, target, up, 45, -1, 100, "near plane -1"},
        {"far == near", eye, target, up, 45, 2, 2, "far plane 2"},
        {"far < near", eye, target, up, 45, 2, 1, "far plane 1"},
        {"NaN eye", {nan, 0, 3}, target, up, 45, 0.05f, 100, "NaN/inf"},
        {"NaN fov", eye, target, up, nan, 0.05f, 100, "(0, 180)"},
    };
    for (const Bad& b : bad) {
        INFO(b.what);
        Camera out = plain;
        out.width = 7;  // must stay untouched
        Status s = make_perspective_camera(b.eye, b.target, b.up, b.fov, 16, 16, b.near_plane,
                                           b.far_plane, out);
        CHECK(s.code() == StatusCode::invalid_argument);
        CHECK(says(s, b.message));
        CHECK(out.width == 7);
        Camera unchecked =
            perspective_camera(b.eye, b.target, b.up, b.fov, 16, 16, b.near_plane, b.far_plane);
        CHECK(!validate_camera(unchecked).ok());
        DrawResult r = draw_with(unchecked);
        CHECK(r.mesh.code() == StatusCode::invalid_argument);
        CHECK(r.edges.code() == StatusCode::invalid_argument);
        CHECK(r.lit == 0);
    }
    // The orthographic builder's own parameter, and its near/far order.
    CHECK(says(make_orthographic_camera(eye, target, up, 0, 16, 16, 0.05f, 100, ortho),
               "half_height 0"));
    CHECK(says(make_orthographic_camera(eye, target, up, 1, 16, 16, 5, 1, ortho), "far"));
    CHECK(!validate_camera(orthographic_camera(eye, target, up, -1, 16, 16)).ok());
    CHECK(!validate_camera(orthographic_camera(eye, target, up, 1, 16, 16, 5, 1)).ok());
    CHECK(says(make_perspective_camera(eye, target, up, 45, 0, 16, 0.05f, 100, ortho),
               "0 x 16"));
}

TEST_CASE("validate_camera: mirrored, skewed or mislabelled matrices are refused") {
    const Camera cam = perspective_camera({1, 2, 3}, {0, 0, 0}, {0, 1, 0}, 50.0f, 16, 16);
    REQUIRE(validate_camera(cam).ok());
    Camera c = cam;
    c.projection.m[0][0] = -c.projection.m[0][0];  // mirrored left-right
    CHECK(says(validate_camera(c), "scales x"));
    c = cam;
    for (int j = 0; j < 4; ++j) c.view.m[0][j] = -c.view.m[0][j];  // a mirrored view
    CHECK(says(validate_camera(c), "mirrored"));
    c = cam;
    c.view.m[0][0] *= 2.0f;  // not a rotation
    CHECK(says(validate_camera(c), "not a rotation"));
    c = cam;
    c.orthographic = true;  // a perspective matrix labelled orthographic
    CHECK(says(validate_camera(c), "last row"));
    c = cam;
    c.eye.y = INFINITY;
    CHECK(says(validate_camera(c), "NaN/inf"));
    c = cam;
    c.height = 0;
    CHECK(says(validate_camera(c), "16 x 0"));
    CHECK(!validate_camera(Camera{}).ok());  // identity projection: no perspective divide
    // A camera with near = 0 puts the eye itself on the near plane (w == 0 there): refused.
    CHECK(says(validate_camera(perspective_camera({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 45.0f, 16,
                                                  16, 0.0f, 10.0f)),
               "near"));
}
