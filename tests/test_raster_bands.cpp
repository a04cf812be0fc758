// Tests for lib/shitsukan/raster/rasterizer.cpp: band rendering. Rendering a frame band by
// band (any band height) and stacking the bands gives the full frame bit for bit, colour and
// depth.
#include <doctest/doctest.h>

#include <cstring>
#include <vector>

#include "raster_test_scenes.hpp"

using namespace shitsukan;
using namespace raster_test;

namespace {

struct Scene {
    TriangleMesh sphere = sphere_mesh(0.8f, 24, 12);
    TriangleMesh box = box_mesh({-0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, 0.5f});
    TriangleMesh floor;
    Camera cam = perspective_camera({0.4f, 0.9f, 3.2f}, {0, 0, 0}, {0, 1, 0}, 50.0f, 101, 77);
    Scene() {
        // A floor reaching behind the eye: exercises near-plane clipping in every band.
        floor.add_vertex({-6, -0.8f, 6}, {0, 1, 0}, {0, 0});
        floor.add_vertex({6, -0.8f, 6}, {0, 1, 0}, {1, 0});
        floor.add_vertex({0, -0.8f, -8}, {0, 1, 0}, {0.5f, 1});
        floor.add_triangle(0, 1, 2);
    }
};

Rgb8 shade(const Fragment& f, void*) {
    // Depends on every interpolated quantity, so any difference shows.
    return Rgb8{to_byte(0.5f + 0.5f * f.normal.x), to_byte(f.uv.x * 0.5f + f.depth * 0.5f),
                to_byte(0.5f + 0.3f * f.object_position.z + 0.2f * f.uv.y)};
}

RasterStats draw_scene(const Scene& s, const FrameBand& band) {
    RasterStats stats;
    clear_band(band, Rgb8{10, 20, 30});
    DrawOptions opt;
    opt.model = Mat4::translate({-0.6f, 0, 0}) * Mat4::rotate_y(0.4f);
    CHECK(draw_mesh(s.cam, band, s.sphere.view(), opt, shade, nullptr, &stats).ok());
    opt.model = Mat4::translate({0.7f, 0, -0.3f}) * Mat4::rotate_x(0.3f) * Mat4::rotate_y(-0.6f);
    CHECK(draw_mesh(s.cam, band, s.box.view(), opt, shade, nullptr, &stats).ok());
    opt.model = Mat4::identity();
    CHECK(draw_mesh(s.cam, band, s.floor.view(), opt, shade, nullptr, &stats).ok());
    return stats;
}

}  // namespace

TEST_CASE("bands == full frame, bit for bit (band heights 16, 7 and 1)") {
    Scene scene;
    const int W = scene.cam.width, H = scene.cam.height;
    RgbImage full(W, H);
    FloatImage full_depth(W, H);
    RasterStats full_stats = draw_scene(scene, full_frame_band(full.view(), full_depth.view()));
    CHECK(full_stats.triangles_clipped >= 1);
    CHECK(full_stats.fragments_shaded > W * H / 3);

    for (int band_height : {16, 7, 1}) {
        RgbImage stacked(W, H);
        FloatImage stacked_depth(W, H);
        RgbImage band_color(W, band_height);  // the only frame memory a band render needs
        FloatImage band_depth(W, band_height);
        long fragments = 0;
        for (int y0 = 0; y0 < H; y0 += band_height) {
            int h = std::min(band_height, H - y0);
            FrameBand band = make_band(band_color.view().subview(0, 0, W, h),
                                       band_depth.view().subview(0, 0, W, h), y0, W, H);
            fragments += draw_scene(scene, band).fragments_shaded;
            for (int y = 0; y < h; ++y) {
                std::memcpy(stacked.view().row(y0 + y), band.color.row(y), sizeof(Rgb8) * W);
                std::memcpy(stacked_depth.view().row(y0 + y), band.depth.row(y), sizeof(float) * W);
            }
        }
        INFO("band height " << band_height);
        CHECK(std::memcmp(stacked.data(), full.data(), sizeof(Rgb8) * W * H) == 0);
        CHECK(std::memcmp(stacked_depth.data(), full_depth.data(), sizeof(float) * W * H) == 0);
        CHECK(fragments == full_stats.fragments_shaded);
    }
}
