// Tests for lib/shitsukan/raster/rasterizer.cpp: perspective-correct interpolation against
// an analytic plane, and depth order of intersecting triangles.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "raster_test_scenes.hpp"

using namespace shitsukan;
using namespace raster_test;

namespace {

TriangleMesh quad_mesh() {
    TriangleMesh m;
    std::uint32_t a = m.add_vertex({-1, -1, 0}, {0, 0, 1}, {0, 0});
    std::uint32_t b = m.add_vertex({1, -1, 0}, {0, 0, 1}, {1, 0});
    std::uint32_t c = m.add_vertex({1, 1, 0}, {0, 0, 1}, {1, 1});
    std::uint32_t d = m.add_vertex({-1, 1, 0}, {0, 0, 1}, {0, 1});
    m.colors = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};  // colour = (u, v, 0)
    m.add_triangle(a, b, c);
    m.add_triangle(a, c, d);
    return m;
}

}  // namespace

TEST_CASE("perspective-correct interpolation matches the analytic plane (< 1e-3 of range)") {
    const int W = 128, H = 96;
    const float fov = 60.0f;
    const Vec3 eye{0, 0, 2.2f};
    Camera cam = perspective_camera(eye, {0, 0, 0}, {0, 1, 0}, fov, W, H);
    // A strongly slanted quad: the depth changes a lot across it, so screen-linear
    // interpolation would be far off.
    Mat4 model = Mat4::rotate_y(1.0f) * Mat4::rotate_x(-0.5f);
    TriangleMesh quad = quad_mesh();
    RgbImage color(W, H);
    FloatImage depth(W, H);
    FrameBand band = full_frame_band(color.view(), depth.view());
    clear_band(band, Rgb8{0, 0, 0});

    // The plane in world space, in double: through the origin with normal model·(0, 0, 1).
    Vec3 n = transform_vector(model, {0, 0, 1});
    Vec3 ex = transform_vector(model, {1, 0, 0}), ey = transform_vector(model, {0, 1, 0});
    double tan_half = std::tan(double(fov) * kPiD / 360.0), aspect = double(W) / H;
    double max_uv = 0, max_pos = 0, max_depth = 0, max_affine = 0;
    long fragments = 0;
    auto check = [&](const Fragment& f) {
        // The ray through the pixel centre (the camera looks down -z from `eye`).
        double dx = ((f.x + 0.5) / W * 2 - 1) * tan_half * aspect;
        double dy = (1 - (f.y + 0.5) / H * 2) * tan_half;
        double dz = -1;
        double t = -(eye.z * n.z) / (dx * n.x + dy * n.y + dz * n.z);
        double hx = t * dx, hy = t * dy, hz = eye.z + t * dz;  // hit point, world
        // Object coordinates: the model is a rotation, so project onto its axes.
        double ox = hx * ex.x + hy * ex.y + hz * ex.z, oy = hx * ey.x + hy * ey.y + hz * ey.z;
        double u = (ox + 1) / 2, v = (oy + 1) / 2;
        max_uv = std::fmax(max_uv, std::fmax(std::fabs(f.uv.x - u), std::fabs(f.uv.y - v)));
        max_uv = std::fmax(max_uv, std::fmax(std::fabs(f.color.x - u), std::fabs(f.color.y - v)));
        max_pos = std::fmax(max_pos, std::fmax(std::fabs(f.object_position.x - ox),
                                               std::fabs(f.object_position.y - oy)));
        max_pos = std::fmax(max_pos, std::fabs(f.world_position.x - hx));
        Vec3 s = project(cam, {float(hx), float(hy), float(hz)});
        max_depth = std::fmax(max_depth, std::fabs(f.depth - s.z));
        ++fragments;
        return Rgb8{to_byte(f.uv.x), to_byte(f.uv.y), 0};
    };
    DrawOptions opt;
    opt.model = model;
    opt.cull = CullMode::none;
    REQUIRE(draw_mesh(cam, band, quad.view(), opt, check).ok());
    CHECK(fragments > W * H / 8);
    CHECK(max_uv < 1e-3);   // uv and colour range: 1
    CHECK(max_pos < 2e-3);  // position range: 2
    CHECK(max_depth < 1e-4);

    // The test can tell: screen-linear (affine) interpolation of u between the quad's
    // projected corners is off by far more than the tolerance in the middle of the quad.
    Vec3 pa = project(cam, transform_point(model, {-1, 0, 0}));
    Vec3 pb = project(cam, transform_point(model, {1, 0, 0}));
    Vec3 pm = project(cam, transform_point(model, {0, 0, 0}));
    double affine_u_at_centre = (pm.x - pa.x) / (pb.x - pa.x);
    max_affine = std::fabs(affine_u_at_centre - 0.5);
    CHECK(max_affine > 0.05);
}

TEST_CASE("normals are interpolated, transformed by the normal matrix and normalised") {
    Camera cam = perspective_camera({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 40.0f, 64, 64);
    TriangleMesh sphere = sphere_mesh(1.0f, 32, 16);
    RgbImage color(64, 64);
    FloatImage depth(64, 64);
    FrameBand band = full_frame_band(color.view(), depth.view());
    clear_band(band, Rgb8{0, 0, 0});
    // Non-uniform scale: the world normal must follow the inverse transpose.
    Mat4 model = Mat4::scale({2.0f, 0.5f, 1.0f});
    double max_len = 0, max_dev = 0;
    auto check = [&](const Fragment& f) {
        max_len = std::fmax(max_len, std::fabs(length(f.normal) - 1.0f));
        // Ellipsoid x²/4 + y²/0.25 + z² = 1: gradient (x/4, 4y, z) at the world point.
        Vec3 p = f.world_position;
        Vec3 g = normalize(Vec3{p.x / 4.0f, 4.0f * p.y, p.z});
        max_dev = std::fmax(max_dev, 1.0 - dot(g, f.normal));
        return Rgb8{255, 255, 255};
    };
    DrawOptions opt;
    opt.model = model;
    REQUIRE(draw_mesh(cam, band, sphere.view(), opt, check).ok());
    CHECK(max_len < 1e-5);
    CHECK(max_dev < 0.02);  // tessellation error of a 32 x 16 sphere
}

TEST_CASE("normals keep unit length under a model that scales them to denormals") {
    // A model scaling z by 1e22 leaves the quad z = 0 where it is, but its normal matrix
    // scales z by 1e-22: the normal (0, 0, 1e-22) squares to a denormal and loses its
    // digits (a fuzz finding, fuzz_raster: normals of length 0.9 before normalize_or
    // rescaled such vectors).
    Camera cam = perspective_camera({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 40.0f, 32, 32);
    TriangleMesh quad = quad_mesh();
    RgbImage color(32, 32);
    FloatImage depth(32, 32);
    FrameBand band = full_frame_band(color.view(), depth.view());
    for (bool with_normals : {true, false}) {  // interpolated, and the plane's (flat)
        clear_band(band, Rgb8{0, 0, 0});
        double max_dev = 0;
        long fragments = 0;
        auto check = [&](const Fragment& f) {
            max_dev = std::fmax(max_dev, std::fabs(f.normal.x) + std::fabs(f.normal.y) +
                                             std::fabs(f.normal.z - 1.0f));
            ++fragments;
            return Rgb8{255, 255, 255};
        };
        DrawOptions opt;
        opt.model = Mat4::scale({1.0f, 1.0f, 1.0e22f});
        MeshView view = quad.view();
        if (!with_normals) view.normals = nullptr;
        REQUIRE(draw_mesh(cam, band, view, opt, check).ok());
        CHECK(fragments > 100);
        CHECK(max_dev < 1e-6);  // the world normal is (0, 0, 1), of length 1
    }
}

TEST_CASE("depth order of intersecting triangles does not depend on drawing order") {
    // Two triangles crossing along x = 0: A lies in z = 0.5·x, B in z = -0.5·x. Seen from +z,
    // A is in front for x > 0 and B for x < 0.
    TriangleMesh m;
    std::uint32_t a0 = m.add_vertex({-1, -1, -0.5f}), a1 = m.add_vertex({1, -1, 0.5f}),
                  a2 = m.add_vertex({0, 1.2f, 0});
    std::uint32_t b0 = m.add_vertex({-1, -1.1f, 0.5f}), b1 = m.add_vertex({1, -1.1f, -0.5f}),
                  b2 = m.add_vertex({0.1f, 1, -0.05f});
    m.add_triangle(a0, a1, a2);
    m.add_triangle(b0, b1, b2);
    Camera cam = perspective_camera({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 50.0f, 96, 96);
    auto paint = [](const Fragment& f) {
        return f.triangle == 0 ? Rgb8{255, 0, 0} : Rgb8{0, 255, 0};
    };
    RgbImage images[2] = {RgbImage(96, 96), RgbImage(96, 96)};
    for (int order = 0; order < 2; ++order) {
        TriangleMesh mm = m;
        if (order == 1) {  // B first; triangle indices swap, so swap the colours back
            mm.indices = {b0, b1, b2, a0, a1, a2};
        }
        FloatImage depth(96, 96);
        FrameBand band = full_frame_band(images[order].view(), depth.view());
        clear_band(band, Rgb8{0, 0, 0});
        auto paint_ordered = [&](const Fragment& f) {
            Fragment g = f;
            if (order == 1) g.triangle = 1 - f.triangle;
            return paint(g);
        };
        DrawOptions opt;
        opt.cull = CullMode::none;
        REQUIRE(draw_mesh(cam, band, mm.view(), opt, paint_ordered).ok());
    }
    // Only pixels both triangles cover, away from the seam, can tell the order.
    Counts both = coverage_per_triangle(cam, m.view(), CullMode::none);
    int wrong = 0, checked = 0, differ = 0;
    for (int y = 0; y < 96; ++y)
        for (int x = 0; x < 96; ++x) {
            Rgb8 p = images[0].at(x, y);
            differ += !(p == images[1].at(x, y));
            if (both.at(x, y) != 2 || std::abs(x - 48) < 3) continue;
            ++checked;
            bool right = x >= 48;
            wrong += right ? !(p == Rgb8{255, 0, 0}) : !(p == Rgb8{0, 255, 0});
        }
    CHECK(checked > 1000);
    CHECK(wrong == 0);
    CHECK(differ == 0);
}

TEST_CASE("facing: counter-clockwise is front; culling and Fragment::front_facing agree") {
    Camera cam = perspective_camera({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 45.0f, 32, 32);
    TriangleMesh ccw;
    ccw.positions = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
    ccw.indices = {0, 1, 2};
    TriangleMesh cw = ccw;
    cw.indices = {0, 2, 1};
    for (CullMode cull : {CullMode::none, CullMode::back, CullMode::front}) {
        for (int m = 0; m < 2; ++m) {
            RgbImage color(32, 32);
            FloatImage depth(32, 32);
            FrameBand band = full_frame_band(color.view(), depth.view());
            clear_band(band, Rgb8{});
            long front = 0, back = 0;
            auto count = [&](const Fragment& f) {
                (f.front_facing ? front : back)++;
                return Rgb8{1, 1, 1};
            };
            DrawOptions opt;
            opt.cull = cull;
            REQUIRE(draw_mesh(cam, band, (m == 0 ? ccw : cw).view(), opt, count).ok());
            bool is_front = m == 0;
            bool drawn = cull == CullMode::none || (cull == CullMode::back) == is_front;
            CHECK((is_front ? front : back) > (drawn ? 50 : -1));
            CHECK((is_front ? back : front) == 0);
            if (!drawn) CHECK(front + back == 0);
        }
    }
}
