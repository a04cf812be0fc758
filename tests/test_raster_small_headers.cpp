// Tests for lib/shitsukan/raster/*.hpp as small-device headers: they must not pull in the
// host-side image.hpp (std::vector) and must be usable on caller memory alone. This file
// includes nothing but the raster headers (no raster_test_scenes.hpp, no image.hpp).
#include "shitsukan/raster/camera.hpp"
#include "shitsukan/raster/clip.hpp"
#include "shitsukan/raster/rasterizer.hpp"
#include "shitsukan/raster/shading.hpp"
#include "shitsukan/raster/wireframe.hpp"

#include <doctest/doctest.h>

#include <cstdint>
#include <type_traits>

// If image.hpp had come in through the headers above, shitsukan::RgbImage would name its
// Image<Rgb8>; otherwise qualified lookup falls through to the probe's type below.
namespace image_hpp_probe {
struct RgbImage {};
struct FloatImage {};
}  // namespace image_hpp_probe
namespace shitsukan {
using namespace image_hpp_probe;
}  // namespace shitsukan
static_assert(std::is_same<shitsukan::RgbImage, image_hpp_probe::RgbImage>::value,
              "a small-device raster header includes shitsukan/image/image.hpp");
static_assert(std::is_same<shitsukan::FloatImage, image_hpp_probe::FloatImage>::value,
              "a small-device raster header includes shitsukan/image/image.hpp");

using namespace shitsukan;

TEST_CASE("the raster headers alone draw into caller memory (no image.hpp)") {
    const int W = 24, H = 24;
    Rgb8 color[W * H];
    float depth[W * H];
    FrameBand band = full_frame_band(RgbView{color, W, H, W}, FloatView{depth, W, H, W});
    clear_band(band, Rgb8{0, 0, 0});
    Camera cam;
    REQUIRE(make_perspective_camera({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 45.0f, W, H, 0.05f, 100.0f,
                                    cam)
                .ok());
    const Vec3 positions[3] = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
    const std::uint32_t indices[3] = {0, 1, 2};
    MeshView mesh;
    mesh.positions = positions;
    mesh.vertex_count = 3;
    mesh.indices = indices;
    mesh.triangle_count = 1;
    RasterStats stats;
    Status s = draw_mesh(cam, band, mesh, DrawOptions{},
                         [](const Fragment&, void*) { return Rgb8{200, 0, 0}; }, nullptr, &stats);
    REQUIRE(s.ok());
    int lit = 0;
    for (int i = 0; i < W * H; ++i) lit += color[i].r == 200;
    CHECK(lit == stats.fragments_shaded);
    CHECK(lit > W * H / 8);
    // The centre pixel is inside the triangle; the top corners are not.
    CHECK(color[(H / 2) * W + W / 2].r == 200);
    CHECK(color[0].r == 0);
    CHECK(color[W - 1].r == 0);
}
