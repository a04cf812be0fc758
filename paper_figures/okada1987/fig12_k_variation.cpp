// okada1987 fig. 12: the turbulence contribution k, 16 cubes each (marble k = 0..30 step 2,
// wood k = 0..6 step 0.4).
// Example: examples/12_marble_slab.cpp.
#include "okada1987/okada_common.hpp"
#include "shitsukan/image/raster_canvas.hpp"

using namespace shitsukan;
using figures::fmt;

namespace shitsukan::okada {

// Renders the 4 x 4 grid (row by row, k = k_step·i) into a (4·tile) square image.
Status render_k_grid(Material m, float k_step, int tile, RgbImage* out) {
    Scene scene;
    SHITSUKAN_TRY(build_scene("cube", tile < 100, &scene));
    scene.eye = {3.9f, 3.3f, 5.0f};  // a little farther than fig10: room for the label
    out->resize(4 * tile, 4 * tile, kBackground);
    RasterCanvas canvas(out->view());
    for (int i = 0; i < 16; ++i) {
        const float k = k_step * float(i);
        RgbImage cell;
        SHITSUKAN_TRY(render_scene(scene, m, k, tile, &cell));
        const int ox = (i % 4) * tile, oy = (i / 4) * tile;
        for (int y = 0; y < tile; ++y)
            for (int x = 0; x < tile; ++x) out->at(ox + x, oy + y) = cell.at(x, y);
        canvas.text({float(ox + 4), float(oy + 4)}, fmt("k = %g", double(k)), Rgb8{255, 255, 255},
                    1);
    }
    return Status::success();
}

}  // namespace shitsukan::okada

namespace {
Status k_figure(figures::FigureContext& ctx, okada::Material m, float k_step) {
    okada::record_lattice(ctx);
    okada::record_material(ctx, m);  // k is the 16 values below, not one
    ctx.given("k", m == okada::Material::marble ? "0, 2, ..., 30" : "0, 0.4, ..., 6.0",
              "okada1987 §4.4, fig. 12");
    ctx.chosen("layout", "4 x 4 cubes, k increasing left to right, top to bottom",
               "16 values of k");
    ctx.chosen("camera", "perspective, eye (3.9, 3.3, 5), target (0, 0, 0), fov 30 deg per tile",
               "as fig. 10, a little farther");
    ctx.note("k = 0 (top left) shows the undisturbed original function: straight layers / "
             "exact circles about the axis.");
    RgbImage img;
    SHITSUKAN_TRY(okada::render_k_grid(m, k_step, ctx.quick() ? 40 : 128, &img));
    return ctx.save_png(img.view());
}
}  // namespace

SHITSUKAN_FIGURE(okada1987_fig12a, "okada1987", "fig12a",
                 "Marble cubes for k = 0, 2, ..., 30") {
    return k_figure(ctx, okada::Material::marble, 2.0f);
}
SHITSUKAN_FIGURE(okada1987_fig12b, "okada1987", "fig12b",
                 "Wood cubes for k = 0, 0.4, ..., 6.0") {
    return k_figure(ctx, okada::Material::wood, 0.4f);
}
