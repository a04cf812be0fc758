// Tests for lib/shitsukan/raster: a small golden render of an asymmetric scene, compared by
// an FNV-1a hash of the image bytes, so that flips, transposes and channel swaps show.
//
// To regenerate after an intended change of the rasterizer's output: run
//   build/tests -tc='*golden*'
// read the hash it prints in the failure message, LOOK at the image it writes to
// build/golden_raster.png (it must show: a red box on the left, a green sphere top right, a
// blue floor reaching under both, lit from the upper left), then paste the hash below.
//
// Platform: the hash holds for IEEE-754 binary32 float without FMA contraction (the
// Makefile's -ffp-contract=off, no -ffast-math) and glibc's libm. The rasterizer itself is
// plain float arithmetic, but the inputs are not: the camera uses std::tan (perspective_camera)
// and the sphere std::sin / std::cos (raster_test_scenes.hpp), and another libm (musl, newlib,
// a vendor's) may round those differently in the last bit, which moves a few pixels. On such
// a platform the semantic checks below still apply; regenerate the hash there as described
// above instead of trusting this one.
#include <doctest/doctest.h>

#include <cstdio>

#include "raster_test_scenes.hpp"
#include "shitsukan/image/image_io.hpp"

using namespace shitsukan;
using namespace raster_test;

namespace {

constexpr std::uint32_t kGoldenHash = 0xfa60cdebu;

struct Paint {
    Vec3 base;
};

Rgb8 lambert(const Fragment& f, void* user) {
    Vec3 base = static_cast<const Paint*>(user)->base;
    Vec3 light = normalize(Vec3{-0.6f, 0.7f, 0.4f});
    float d = dot(f.normal, light);
    float k = 0.2f + 0.8f * (d > 0 ? d : 0.0f);
    // A uv stripe so that the texture orientation is part of the picture.
    float stripe = f.uv.x < 0.25f ? 0.6f : 1.0f;
    return Rgb8{to_byte(base.x * k * stripe), to_byte(base.y * k * stripe),
                to_byte(base.z * k * stripe)};
}

}  // namespace

TEST_CASE("golden render of an asymmetric scene (hash of the bytes)") {
    const int W = 64, H = 48;
    Camera cam = perspective_camera({0.5f, 1.2f, 4.0f}, {0, 0, 0}, {0, 1, 0}, 40.0f, W, H);
    RgbImage color(W, H);
    FloatImage depth(W, H);
    FrameBand band = full_frame_band(color.view(), depth.view());
    clear_band(band, Rgb8{0, 0, 0});

    TriangleMesh box = box_mesh({-0.4f, -0.5f, -0.4f}, {0.4f, 0.7f, 0.4f});
    TriangleMesh sphere = sphere_mesh(0.5f, 16, 8);
    TriangleMesh floor;
    floor.add_vertex({-2, -0.5f, 1.5f}, {0, 1, 0}, {0, 0});
    floor.add_vertex({2, -0.5f, 1.5f}, {0, 1, 0}, {1, 0});
    floor.add_vertex({2, -0.5f, -2}, {0, 1, 0}, {1, 1});
    floor.add_vertex({-2, -0.5f, -2}, {0, 1, 0}, {0, 1});
    floor.add_triangle(0, 1, 2);
    floor.add_triangle(0, 2, 3);

    Paint red{{1, 0.1f, 0.1f}}, green{{0.1f, 1, 0.2f}}, blue{{0.2f, 0.3f, 1}};
    DrawOptions opt;
    opt.model = Mat4::translate({-0.9f, 0, 0}) * Mat4::rotate_y(0.5f);
    REQUIRE(draw_mesh(cam, band, box.view(), opt, lambert, &red).ok());
    opt.model = Mat4::translate({0.8f, 0.5f, -0.5f});
    REQUIRE(draw_mesh(cam, band, sphere.view(), opt, lambert, &green).ok());
    opt.model = Mat4::identity();
    REQUIRE(draw_mesh(cam, band, floor.view(), opt, lambert, &blue).ok());

    // Coarse semantic checks first, so a failure says what went wrong.
    long red_left = 0, red_right = 0, green_top_right = 0, blue_bottom = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            Rgb8 p = color.at(x, y);
            if (p.r > p.g && p.r > p.b) (x < W / 2 ? red_left : red_right)++;
            if (p.g > p.r && p.g > p.b && x >= W / 2 && y < H / 2) ++green_top_right;
            if (p.b > p.r && p.b > p.g && y >= H / 2) ++blue_bottom;
        }
    CHECK(red_left > 100);
    CHECK(red_right == 0);
    CHECK(green_top_right > 50);
    CHECK(blue_bottom > 300);

    std::uint32_t hash = fnv1a(color.data(), sizeof(Rgb8) * std::size_t(W) * std::size_t(H));
    if (hash != kGoldenHash) {
        CHECK(write_png("build/golden_raster.png", color.view()).ok());
        char text[64];
        std::snprintf(text, sizeof text, "0x%08xu", unsigned(hash));
        FAIL_CHECK("golden hash differs: got " << text << " (image in build/golden_raster.png)");
    }
}
