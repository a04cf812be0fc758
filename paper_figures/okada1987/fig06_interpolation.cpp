// okada1987 fig. 6: trilinear interpolation — D along a line against the lattice samples.
// Examples: examples/04_plot.cpp, examples/11_turbulence_line.cpp.
#include <cmath>
#include <vector>

#include "okada1987/okada_common.hpp"
#include "okada1987/okada_plot.hpp"
#include "shitsukan/image/raster_canvas.hpp"

using namespace shitsukan;
using figures::fmt;

SHITSUKAN_FIGURE(okada1987_fig06, "okada1987", "fig06",
                 "Trilinear interpolation: D along a line vs. the lattice samples") {
    okada::record_lattice(ctx);
    ctx.given("D(P)", "sum of the 8 neighbours weighted by the opposite box volumes", "eq. (6)");
    ctx.chosen("lines", "x = 24..40 at (y, z) = (20, 33) through nodes, and (20.5, 33.3) between",
               "one line through nodes, one off them; 16 cells so the straight pieces show");
    const LatticeView v = okada::shared_lattice().view();
    const float xa = 24.0f, xb = 40.0f;
    auto on = [&](double x) { return turbulence(v, Vec3{float(x), 20.0f, 33.0f}); };
    auto off = [&](double x) { return turbulence(v, Vec3{float(x), 20.5f, 33.3f}); };
    float lo = 1e9f, hi = -1e9f;
    for (int i = 0; i <= 160; ++i) {
        const double x = xa + (xb - xa) * i / 160.0;
        lo = std::fmin(lo, std::fmin(on(x), off(x)));
        hi = std::fmax(hi, std::fmax(on(x), off(x)));
    }
    const float pad = 0.2f * (hi - lo);
    RgbImage img(640, 400, Rgb8{255, 255, 255});
    RasterCanvas c(img.view());
    const Axes axes = axes_in(c, xa, xb, lo - pad, hi + pad);
    SHITSUKAN_TRY(
        draw_axes(c, axes, {"D along two lines (eq. 6)", "x (lattice units)", "D(x, y, z)"}));
    const Rgb8 blue{30, 90, 200}, orange{220, 110, 20};
    SHITSUKAN_TRY(plot_function(c, axes, off, 641, orange, 1.5f));
    SHITSUKAN_TRY(plot_function(c, axes, on, 641, blue, 1.5f));
    std::vector<float> xs, ys;
    for (int x = int(xa); x <= int(xb); ++x) xs.push_back(float(x)), ys.push_back(v.at(x, 20, 33));
    SHITSUKAN_TRY(
        plot_scatter(c, axes, xs.data(), ys.data(), int(xs.size()), MarkerShape::dot, 6.0f, blue));
    c.text({axes.corner.x + 8, axes.corner.y + 6},
           "D(x, 20, 33): straight between the lattice samples (dots)", blue);
    c.text({axes.corner.x + 8, axes.corner.y + 18},
           "D(x, 20.5, 33.3): between four lines of samples", orange);
    ctx.note("Between two nodes the blue line is straight (eq. (6) is linear along cell edges) "
             "and passes through every node value exactly.");
    return ctx.save_png(img.view());
}
