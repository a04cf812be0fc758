// tokai1994 fig. 16: a bicubic Bezier patch (eq. 5) with its 16-point control net.
// Example: examples/52_bump_mapped_patch.cpp.
#include <vector>

#include "driver/figure.hpp"
#include "shitsukan/geom/bezier_patch.hpp"
#include "shitsukan/geom/bezier_patch_mesh.hpp"
#include "shitsukan/image/canvas.hpp"
#include "shitsukan/raster/camera.hpp"
#include "shitsukan/raster/rasterizer.hpp"
#include "shitsukan/raster/wireframe.hpp"
#include "tokai1994/fig11_19_common.hpp"

using namespace shitsukan;
using namespace shitsukan::figures;

SHITSUKAN_FIGURE(tokai1994_fig16, "tokai1994", "fig16",
                 "Bicubic Bezier patch (eq. 5) with its 16 control points P00-P33") {
    const int size = ctx.quick() ? 192 : 512;
    const float s = float(size) / 512.0f;
    // The control net (chosen here: the paper's fig. 16 is an illustration): a 4 x 4 grid in
    // x-z with heights h_ij.
    const float h[4][4] = {{0.00f, 0.25f, 0.20f, 0.00f},
                           {0.15f, 0.75f, 0.45f, 0.05f},
                           {0.05f, 0.40f, 0.85f, 0.25f},
                           {0.00f, 0.15f, 0.30f, 0.10f}};
    BezierPatch patch;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            patch.p[i][j] = {-1.0f + 2.0f * float(i) / 3.0f, h[i][j],
                             1.0f - 2.0f * float(j) / 3.0f};
    SHITSUKAN_TRY(validate_patch(patch));
    ctx.given("surface", "P(u,v) = sum_ij P_ij B_i(u) B_j(v), B_k = 3!/(k!(3-k)!) u^k (1-u)^(3-k)",
              "tokai1994 eq. (5)");
    ctx.chosen("control net", "x = -1 + 2i/3, z = 1 - 2j/3, heights h_ij in [0, 0.85]",
               "illustration; no coordinates printed");
    ctx.chosen("tessellation", "32 x 32 quads, per-pixel Blinn 1977 shading", "smooth at 512 px");
    tokai_relief::record_shading(ctx);

    PatchStripOptions opt;
    opt.segments_u = opt.segments_v = 32;
    tokai_relief::BumpSurface surface;
    SHITSUKAN_TRY(tessellate_patch_strip(&patch, 1, opt, surface.mesh));
    Camera cam =
        perspective_camera({2.6f, 2.7f, 3.6f}, {0.0f, 0.2f, 0.0f}, {0, 1, 0}, 36.0f, size, size);
    RgbImage img(size, size);
    FloatImage depth(size, size);
    FrameBand band = full_frame_band(img.view(), depth.view());
    clear_band(band, Rgb8{255, 255, 255});
    tokai_relief::LeatherShader shader;
    shader.camera = &cam;
    shader.front = tokai_relief::leather_material();
    shader.front.color = {0.55f, 0.55f, 0.6f};  // a neutral grey for the geometry figure
    shader.back = shader.front;
    tokai_relief::scene_lights(shader.lights);
    DrawOptions draw;
    draw.cull = CullMode::none;
    SHITSUKAN_TRY(draw_mesh(cam, band, surface.mesh.view(), draw, shader));

    // The control net: 24 segments, drawn over everything.
    TriangleMesh net;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) net.positions.push_back(patch.p[i][j]);
    std::vector<WireEdge> edges;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 3; ++j) {
            edges.push_back({std::uint32_t(i * 4 + j), std::uint32_t(i * 4 + j + 1)});
            edges.push_back({std::uint32_t(j * 4 + i), std::uint32_t((j + 1) * 4 + i)});
        }
    WireOptions wire;
    wire.color = Rgb8{200, 40, 30};
    SHITSUKAN_TRY(draw_edges(cam, band, net.view(), edges.data(), int(edges.size()), wire));
    RasterCanvas canvas(img.view());
    Canvas& cv = canvas;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            Vec3 q = project(cam, patch.p[i][j]);
            cv.marker({q.x, q.y}, MarkerShape::dot, 8.0f * s, Rgb8{200, 40, 30});
            if ((i == 0 || i == 3) && (j == 0 || j == 3))
                cv.text({q.x + 6 * s, q.y - 18 * s}, fmt("P%d%d", i, j), Rgb8{0, 0, 0},
                        ctx.quick() ? 1 : 2);
        }
    cv.text({8 * s, 8 * s}, "red: control net P_ij (i along u, j along v); grey: P(u, v)",
            Rgb8{0, 0, 0}, 1);
    ctx.note(
        "The patch passes through its four corner points only; the 12 others pull it. "
        "Each boundary is the cubic Bezier curve of its 4 boundary control points.");
    return ctx.save_png(img.view());
}
