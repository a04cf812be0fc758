// fujimoto2000 fig. 16: IST-B-spline surfaces (n = 3, N = 5) built on one control mesh with
// different external shuffles. (a) control mesh, (b) the conventional surface (c) coloured by
// parameter interval (= base interval, 5 x 5 = 25 spans), (c) conventional B-spline surface,
// (d) fig. 6a (fully-connected), (e) fig. 6b, (f) fig. 7b (no external shuffle).
//
// (d)(e)(f) are coloured like (b), but by the base interval each point's height comes from,
// span_color(floor(F^{-1}(u,v))): it shows how densely the 25 IST-Bezier pieces are joined,
// "(f) -> (e) -> (d) the connection becomes denser" (§3.2). In (f) every span keeps its own
// colour (25 independent unit-ISTs); in (e) only groups 0 and 4 are exchanged with the
// neighbours; in (d) every group moves.
// Example: examples/30_wrinkly_surface.cpp.
#include <cmath>

#include "driver/figure.hpp"
#include "fujimoto2000/wr_figure_common.hpp"
#include "shitsukan/core/hash.hpp"
#include "shitsukan/core/detmath.hpp"

namespace shitsukan::fujimoto2000 {
namespace {

using figures::FigureContext;
using figures::fmt;

// Chosen: 8 x 8 control points on [-1.5, 1.5]^2 (5 x 5 spans), a saddle-free dome 0.3 high,
// heights 0.05..0.40 (smooth pattern + hashed variation, seed 16), neutral colour.
WrControlMesh fig16_mesh() {
    return square_control_mesh(8, 1.5f, [](int c, int r, float x, float z, WrControlPoint& p) {
        p.position.y = 0.3f * (1.0f - (x * x + z * z) / 4.5f);
        p.height = 0.22f + 0.1f * det_sin(1.3f * float(c) - 0.8f * float(r)) +
                   0.14f * (hash_uniform(16, 0, c, r) - 0.5f);
        p.color = {0.85f, 0.82f, 0.74f};
    });
}

const Shot kShot{{0.0f, 3.4f, 2.8f}, {0.0f, 0.1f, 0.1f}, {0, 1, 0}, 34.0f};

Status run_panel(FigureContext& ctx, char panel) {
    const bool quick = ctx.quick();
    const int size = quick ? 128 : 512;
    const int K = 2;  // 5 x 25 = 125 small intervals per axis: 3-4 pixels each
    ctx.given("base surface", "uniform B-spline, n = 3, 5 x 5 = 25 spans", "fig. 16 caption, §3.2");
    ctx.given("IST", "N = 5; (d) fig. 6a fully-connected, (e) fig. 6b, (f) fig. 7b (none)",
              "fig. 16 caption");
    ctx.chosen("image size", fmt("%d x %d", size, size), "not given");
    ctx.chosen("control mesh", "8 x 8, dome 0.3 high, heights 0.05..0.40", "not printed");
    ctx.chosen("K", fmt("%d", K), "small intervals of 3-4 pixels");
    ctx.chosen("colouring of (d)-(f)", "span colour of the source parameter F^-1(u, v)",
               "shows the external shuffle's connection density, as (b) shows the spans");
    WrControlMesh mesh = fig16_mesh();
    WrSurface surface;
    SHITSUKAN_TRY(make_wr_surface(mesh, SurfaceBasis::bspline, 3, surface));
    RgbImage img(size, size);
    Shading shading;
    const Camera camera = shot_camera(kShot, size, size);
    AxisPair axes;
    const char* shuffle = panel == 'd' ? "fully" : (panel == 'e' ? "fig6b" : "none");
    SHITSUKAN_TRY(make_axes(surface, panel == 'd' ? IstKind::fully_connected : IstKind::connected,
                            shuffle, 5, K, &axes));
    SHITSUKAN_TRY(surface.set_axes(axes.u.axis(), axes.v.axis()));
    if (panel == 'a') {
        draw_control_mesh(img.view(), camera, mesh, surface, true, shading.background);
        return ctx.save_png(img.view());
    }
    WrTessellationOptions o;
    o.form = panel <= 'c' ? WrSurfaceForm::plain : WrSurfaceForm::wr;
    o.levels = K;
    o.grid_level = K;
    o.subdivisions = quick ? 1 : 2;
    WrMesh wm;
    SHITSUKAN_TRY(tessellate_wr_surface(surface, nullptr, o, wm));
    if (panel == 'b') color_by_source_span(&wm, surface, 0);
    if (panel >= 'd') color_by_source_span(&wm, surface, K);
    RasterStats stats;
    SHITSUKAN_TRY(render_opaque(camera, wm.mesh, img.view(), shading, &stats));
    ctx.note(fmt("%d triangles.", wm.mesh.triangle_count()));
    return ctx.save_png(img.view());
}

}  // namespace

SHITSUKAN_FIGURE(fig16a_panel, "fujimoto2000", "fig16a",
                 "IST-B-spline, different external shuffles: (a) control mesh") {
    return run_panel(ctx, 'a');
}
SHITSUKAN_FIGURE(fig16b_panel, "fujimoto2000", "fig16b",
                 "(b) conventional surface coloured per parameter interval (25 spans)") {
    return run_panel(ctx, 'b');
}
SHITSUKAN_FIGURE(fig16c_panel, "fujimoto2000", "fig16c", "(c) conventional B-spline surface") {
    return run_panel(ctx, 'c');
}
SHITSUKAN_FIGURE(fig16d_panel, "fujimoto2000", "fig16d",
                 "(d) IST-B-spline, fully-connected IST (fig. 6a), N = 5") {
    return run_panel(ctx, 'd');
}
SHITSUKAN_FIGURE(fig16e_panel, "fujimoto2000", "fig16e",
                 "(e) IST-B-spline, connected IST of fig. 6b, N = 5") {
    return run_panel(ctx, 'e');
}
SHITSUKAN_FIGURE(fig16f_panel, "fujimoto2000", "fig16f",
                 "(f) IST-B-spline, no external shuffle (fig. 7b), N = 5") {
    return run_panel(ctx, 'f');
}

}  // namespace shitsukan::fujimoto2000
