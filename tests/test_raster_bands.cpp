// Tests for lib/shitsukan/raster/rasterizer.cpp: band rendering. Rendering a frame band by
// band (any band height) and stacking the bands gives the full frame bit for bit, colour and
// depth; so does binning the meshes once (bin_mesh) and drawing each band with
// draw_binned_mesh, which hands a band only the triangles whose rows meet it.
#include <doctest/doctest.h>

#include <cstring>
#include <string>
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

// The scene's three draws; with `bins` (three arrays, one per mesh, from bin_scene) each goes
// through draw_binned_mesh.
DrawOptions scene_options(int mesh, CullMode cull) {
    DrawOptions opt;
    opt.cull = cull;
    if (mesh == 0) opt.model = Mat4::translate({-0.6f, 0, 0}) * Mat4::rotate_y(0.4f);
    if (mesh == 1)
        opt.model = Mat4::translate({0.7f, 0, -0.3f}) * Mat4::rotate_x(0.3f) * Mat4::rotate_y(-0.6f);
    return opt;
}
const TriangleMesh& scene_mesh(const Scene& s, int mesh) {
    return mesh == 0 ? s.sphere : (mesh == 1 ? s.box : s.floor);
}
RasterStats draw_scene(const Scene& s, const FrameBand& band, CullMode cull = CullMode::back,
                       const std::vector<TriangleRows>* bins = nullptr) {
    RasterStats stats;
    clear_band(band, Rgb8{10, 20, 30});
    for (int m = 0; m < 3; ++m) {
        const MeshView mesh = scene_mesh(s, m).view();
        const DrawOptions opt = scene_options(m, cull);
        if (bins != nullptr)
            CHECK(draw_binned_mesh(s.cam, band, mesh, opt, bins[m].data(), int(bins[m].size()),
                                   shade, nullptr, &stats)
                      .ok());
        else
            CHECK(draw_mesh(s.cam, band, mesh, opt, shade, nullptr, &stats).ok());
    }
    return stats;
}
void bin_scene(const Scene& s, CullMode cull, std::vector<TriangleRows> bins[3]) {
    for (int m = 0; m < 3; ++m) {
        const MeshView mesh = scene_mesh(s, m).view();
        bins[m].assign(std::size_t(mesh.triangle_count), TriangleRows{});
        REQUIRE(bin_mesh(s.cam, mesh, scene_options(m, cull), bins[m].data(), int(bins[m].size())).ok());
    }
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

TEST_CASE("binned bands == full frame, bit for bit, and a band is handed only its triangles") {
    Scene scene;
    const int W = scene.cam.width, H = scene.cam.height;
    for (CullMode cull : {CullMode::back, CullMode::none, CullMode::front}) {
        RgbImage full(W, H);
        FloatImage full_depth(W, H);
        const RasterStats full_stats =
            draw_scene(scene, full_frame_band(full.view(), full_depth.view()), cull);
        std::vector<TriangleRows> bins[3];
        bin_scene(scene, cull, bins);
        // The floor reaches behind the eye: clipped, it keeps every row.
        CHECK(bins[2][0].begin == 0);
        CHECK(bins[2][0].end == H);
        for (int band_height : {16, 7, 1}) {
            RgbImage band_color(W, band_height);
            FloatImage band_depth(W, band_height);
            long fragments = 0, handed = 0, unbinned_handed = 0;
            bool same = true;
            for (int y0 = 0; y0 < H; y0 += band_height) {
                const int h = std::min(band_height, H - y0);
                const FrameBand band = make_band(band_color.view().subview(0, 0, W, h),
                                                 band_depth.view().subview(0, 0, W, h), y0, W, H);
                const RasterStats st = draw_scene(scene, band, cull, bins);
                fragments += st.fragments_shaded;
                handed += st.triangles_in;
                unbinned_handed += full_stats.triangles_in;
                for (int y = 0; y < h; ++y)
                    same = same &&
                           std::memcmp(band.color.row(y), full.view().row(y0 + y), sizeof(Rgb8) * W) == 0 &&
                           std::memcmp(band.depth.row(y), full_depth.view().row(y0 + y), sizeof(float) * W) == 0;
            }
            INFO("cull " << int(cull) << ", band height " << band_height);
            CHECK(same);
            CHECK(fragments == full_stats.fragments_shaded);
            CHECK(handed * 2 < unbinned_handed);  // most triangles miss most bands
        }
    }
}

TEST_CASE("bin_mesh and draw_binned_mesh refuse too few rows") {
    Scene scene;
    const MeshView box = scene.box.view();
    std::vector<TriangleRows> rows(std::size_t(box.triangle_count - 1));
    const Status s = bin_mesh(scene.cam, box, DrawOptions{}, rows.data(), int(rows.size()));
    CHECK(s.code() == StatusCode::invalid_argument);
    CHECK(std::string(s.message()).find("room for 11 triangles' rows, the mesh has 12") != std::string::npos);
    RgbImage color(scene.cam.width, scene.cam.height);
    FloatImage depth(scene.cam.width, scene.cam.height);
    const Status d = draw_binned_mesh(scene.cam, full_frame_band(color.view(), depth.view()), box,
                                      DrawOptions{}, nullptr, 0, shade, nullptr);
    CHECK(d.code() == StatusCode::invalid_argument);
}
