// Lesson 1: the first triangle (lesson 0, 00_naive_triangle, in thirty naive lines; here the
// same thing made exact).
// Figure: paper_figures/foundation/coverage.cpp.
//
// A triangle is three points. The rasterizer's job is to find the pixels it covers and to
// ask a "shader" what colour each of them gets. Here the three corners carry a colour each
// (red, green, blue) and every pixel gets a blend of them, weighted by how close it is to
// each corner (barycentric interpolation).
//
// Build and run:  make examples   (writes build/examples/out/first_triangle.png)
#include <cstdio>

#include "shitsukan/geom/mesh.hpp"
#include "shitsukan/image/image.hpp"
#include "shitsukan/image/image_io.hpp"
#include "shitsukan/raster/rasterizer.hpp"
#include "shitsukan/raster/shading.hpp"

using namespace shitsukan;

int main() {
    // 1. The triangle: three corners, counter-clockwise seen from the camera (= front).
    TriangleMesh tri;
    tri.add_vertex({-1.0f, -0.8f, 0});  // bottom left
    tri.add_vertex({1.1f, -0.6f, 0});   // bottom right
    tri.add_vertex({-0.1f, 1.0f, 0});   // top
    tri.colors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};  // one colour per corner, linear [0, 1]
    tri.add_triangle(0, 1, 2);

    // 2. A camera: where the eye is, what it looks at, which way is up, the field of view
    //    and the picture size in pixels.
    Camera camera = perspective_camera({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 45.0f, 256, 256);

    // 3. Where the pixels go: a colour image and a depth buffer of the same size.
    RgbImage color(256, 256);
    FloatImage depth(256, 256);
    FrameBand frame = full_frame_band(color.view(), depth.view());
    clear_band(frame, Rgb8{30, 30, 40});  // background colour; depth = "infinitely far"

    // 4. The shader: called once per covered pixel with the interpolated surface point.
    //    f.color is the corners' colours blended by the pixel's (perspective-correct)
    //    barycentric weights.
    auto shader = [](const Fragment& f) { return to_rgb8(f.color); };

    // 5. Draw, check the status (bad input comes back as a message, never a crash), save.
    Status s = draw_mesh(camera, frame, tri.view(), DrawOptions{}, shader);
    if (!s) {
        std::fprintf(stderr, "draw_mesh: %s\n", s.message());
        return 1;
    }
    s = write_png("first_triangle.png", color.view());
    if (!s) {
        std::fprintf(stderr, "%s\n", s.message());
        return 1;
    }
    std::printf("wrote first_triangle.png (256 x 256)\n");
    return 0;
}
