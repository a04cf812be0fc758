// Lesson 3: rendering in bands.
// Figure: paper_figures/foundation/lit_objects.cpp.
//
// A 512 x 512 frame needs 512·512·3 bytes of colour and 512·512·4 bytes of depth: 1.75 MiB,
// more than most microcontrollers have. But a scanline rasterizer only ever touches the rows
// it is working on. So we render the frame 16 rows at a time into a small band buffer, and
// hand each finished band on (to a display, a file, a network) before drawing the next one.
// The rasterizer guarantees that the stacked bands equal the full frame bit for bit.
//
// Build and run:  make examples   (writes build/examples/out/bands.png)
#include <cstdio>
#include <cstring>

#include "shitsukan/geom/mesh_builders.hpp"
#include "shitsukan/image/image.hpp"
#include "shitsukan/image/image_io.hpp"
#include "shitsukan/raster/rasterizer.hpp"
#include "shitsukan/raster/shading.hpp"

using namespace shitsukan;

int main() {
    const int W = 512, H = 512, kBandRows = 16;

    TriangleMesh torus, sphere;
    if (!make_torus(1.0f, 0.35f, 96, 48, torus) || !make_uv_sphere(0.55f, 64, 32, sphere)) {
        std::fprintf(stderr, "mesh builders failed\n");
        return 1;
    }
    Camera camera = perspective_camera({0, 2.2f, 3.6f}, {0, -0.1f, 0}, {0, 1, 0}, 40.0f, W, H);
    Light light = directional_light({-0.4f, 1.0f, 0.6f});
    Material material;
    material.specular = 0.4f;
    // One lighting function, two base colours: a shader per object.
    auto shade = [&](const Fragment& f, Vec3 base) {
        return to_rgb8(shade_blinn_phong(material, base, f.world_position, f.normal, camera.eye,
                                         &light, 1));
    };
    auto gold = [&](const Fragment& f) { return shade(f, {0.9f, 0.7f, 0.25f}); };
    auto teal = [&](const Fragment& f) { return shade(f, {0.2f, 0.6f, 0.65f}); };

    // The only frame memory the renderer uses: one band of colour and depth.
    RgbImage band_color(W, kBandRows);
    FloatImage band_depth(W, kBandRows);
    // Only to write a PNG at the end; a device would send each band to its display instead.
    RgbImage picture(W, H);

    DrawOptions torus_options, sphere_options;
    torus_options.model = Mat4::rotate_x(0.35f);
    sphere_options.model = Mat4::translate({0, 0.05f, 0});
    for (int y0 = 0; y0 < H; y0 += kBandRows) {
        int rows = H - y0 < kBandRows ? H - y0 : kBandRows;
        // The band: rows [y0, y0 + rows) of the W x H frame.
        FrameBand band = make_band(band_color.view().subview(0, 0, W, rows),
                                   band_depth.view().subview(0, 0, W, rows), y0, W, H);
        clear_band(band, Rgb8{20, 22, 30});
        // Every mesh is submitted for every band; triangles that miss it cost a few tests.
        Status s = draw_mesh(camera, band, torus.view(), torus_options, gold);
        if (s) s = draw_mesh(camera, band, sphere.view(), sphere_options, teal);
        if (!s) return std::fprintf(stderr, "draw_mesh: %s\n", s.message()), 1;
        for (int y = 0; y < rows; ++y)  // "send" the band
            std::memcpy(picture.view().row(y0 + y), band.color.row(y), sizeof(Rgb8) * W);
    }

    double band_bytes = double(W) * kBandRows * (sizeof(Rgb8) + sizeof(float));
    double full_bytes = double(W) * H * (sizeof(Rgb8) + sizeof(float));
    std::printf("frame %d x %d in %d bands of %d rows\n", W, H, (H + kBandRows - 1) / kBandRows,
                kBandRows);
    std::printf("memory: band buffers %.1f KiB vs a full frame %.1f KiB (%.1f %%)\n",
                band_bytes / 1024, full_bytes / 1024, 100.0 * band_bytes / full_bytes);
    Status s = write_png("bands.png", picture.view());
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;
    std::printf("wrote bands.png\n");
    return 0;
}
