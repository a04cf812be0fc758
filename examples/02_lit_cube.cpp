// Lesson 2: a lit cube.
// Figure: paper_figures/foundation/lit_objects.cpp.
//
// Lighting turns a flat silhouette into a solid. For each pixel the shader gets the surface
// normal n (the direction the surface faces) and computes, per light, how directly the
// light falls on it: Lambert's cosine law, brightness ~ max(0, n·l). Blinn-Phong adds a
// highlight where the half vector between light and eye lines up with the normal.
//
// Build and run:  make examples   (writes build/examples/out/lit_cube.png)
#include <cstdio>

#include "shitsukan/geom/mesh_builders.hpp"
#include "shitsukan/image/image.hpp"
#include "shitsukan/image/image_io.hpp"
#include "shitsukan/raster/rasterizer.hpp"
#include "shitsukan/raster/shading.hpp"

using namespace shitsukan;

int main() {
    // 1. A unit cube from the mesh builders: 6 faces, each with its own outward normal.
    TriangleMesh cube;
    Status s = make_box({-1, -1, -1}, {1, 1, 1}, cube);
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;

    // 2. Camera above and to the right, looking at the centre.
    Camera camera = perspective_camera({3.0f, 2.4f, 4.2f}, {0, 0, 0}, {0, 1, 0}, 40.0f, 320, 320);

    // 3. Two lights: a warm key light from the upper left (directional: like the sun) and a
    //    cool, weaker fill light from the right (a point light: a lamp at a position).
    Light lights[2] = {directional_light({-0.4f, 1.0f, 0.45f}, {1.0f, 0.95f, 0.85f}, 1.0f),
                       point_light({5, 0, 2}, {0.6f, 0.7f, 1.0f}, 0.4f)};
    Material material;
    material.ambient = 0.12f;   // light that comes from everywhere: no face is pitch black
    material.diffuse = 0.8f;
    material.specular = 0.35f;  // a little shine
    material.shininess = 40.0f;
    Vec3 base_color{0.85f, 0.45f, 0.2f};  // terracotta

    // 4. The shader: Blinn-Phong with the interpolated normal, in world space.
    auto shader = [&](const Fragment& f) {
        Vec3 c = shade_blinn_phong(material, base_color, f.world_position, f.normal, camera.eye,
                                   lights, 2);
        return to_rgb8(c);
    };

    RgbImage color(320, 320);
    FloatImage depth(320, 320);
    FrameBand frame = full_frame_band(color.view(), depth.view());
    clear_band(frame, Rgb8{24, 26, 32});

    // 5. Turn the cube a little (object -> world); back faces are culled by default.
    DrawOptions options;
    options.model = Mat4::rotate_y(-0.3f);
    RasterStats stats;
    s = draw_mesh(camera, frame, cube.view(), options, shader, &stats);
    if (!s) return std::fprintf(stderr, "draw_mesh: %s\n", s.message()), 1;
    s = write_png("lit_cube.png", color.view());
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;
    std::printf("wrote lit_cube.png: %ld of %ld triangles drawn, %ld pixels shaded\n",
                stats.triangles_drawn, stats.triangles_in, stats.fragments_shaded);
    return 0;
}
