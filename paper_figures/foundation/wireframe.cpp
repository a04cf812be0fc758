// Foundation demo figure: a hidden-line wireframe. The torus and the sphere are first drawn
// into the Z-buffer with a flat fill, then each unique edge is drawn as a line that shows
// only where it is not behind a surface.
// Example: none of its own; examples/01_first_triangle.cpp teaches the rasterizer the wireframe is
//   drawn with.
#include <vector>

#include "driver/figure.hpp"
#include "shitsukan/geom/mesh_builders.hpp"
#include "shitsukan/image/image.hpp"
#include "shitsukan/raster/rasterizer.hpp"
#include "shitsukan/raster/wireframe.hpp"

using namespace shitsukan;
using namespace shitsukan::figures;

SHITSUKAN_FIGURE(foundation_wireframe, "foundation", "wireframe",
                 "Hidden-line wireframe of a torus around a sphere (each edge drawn once)") {
    const int size = ctx.quick() ? 128 : 512;
    TriangleMesh torus, sphere;
    SHITSUKAN_TRY(make_torus(1.0f, 0.35f, 40, 16, torus));
    SHITSUKAN_TRY(make_uv_sphere(0.5f, 24, 12, sphere));
    Camera cam =
        perspective_camera({0.3f, 2.0f, 3.4f}, {0, -0.1f, 0}, {0, 1, 0}, 40.0f, size, size);
    ctx.chosen("torus", "R 1, r 0.35, 40 x 16 segments, tilted 0.35 rad",
               "edges readable at 512 px");
    ctx.chosen("sphere", "radius 0.5, 24 x 12", "hides the far side of the ring");
    ctx.chosen("depth_tolerance", "0.01 (relative eye distance)",
               "the library default: lines on the surface pass, lines behind it do not");

    RgbImage color(size, size);
    FloatImage depth(size, size);
    FrameBand band = full_frame_band(color.view(), depth.view());
    clear_band(band, Rgb8{250, 250, 246});
    auto fill = [](const Fragment&) { return Rgb8{250, 250, 246}; };  // paper white

    DrawOptions torus_opt, sphere_opt;
    torus_opt.model = Mat4::rotate_x(0.35f);
    SHITSUKAN_TRY(draw_mesh(cam, band, torus.view(), torus_opt, fill));
    SHITSUKAN_TRY(draw_mesh(cam, band, sphere.view(), sphere_opt, fill));

    long pixels = 0;
    int edge_total = 0;
    const struct {
        const TriangleMesh* mesh;
        const DrawOptions* opt;
        Rgb8 ink;
    } parts[2] = {{&torus, &torus_opt, Rgb8{20, 40, 110}},
                  {&sphere, &sphere_opt, Rgb8{150, 30, 30}}};
    for (const auto& part : parts) {
        MeshView mesh = part.mesh->view();
        std::vector<WireEdge> edges(std::size_t(3 * mesh.triangle_count));
        int n = 0;
        SHITSUKAN_TRY(collect_edges(mesh, edges.data(), int(edges.size()), n));
        WireOptions w;
        w.model = part.opt->model;
        w.color = part.ink;
        w.depth_test = true;
        SHITSUKAN_TRY(draw_edges(cam, band, mesh, edges.data(), n, w, &pixels));
        edge_total += n;
    }
    ctx.note(fmt("%d unique edges (torus %d triangles, sphere %d), %ld line pixels drawn.",
                 edge_total, torus.triangle_count(), sphere.triangle_count(), pixels));
    return ctx.save_png(color.view());
}
