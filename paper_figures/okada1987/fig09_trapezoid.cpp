// okada1987 fig. 9: one stripe g(z), the trapezoid with exponential skirts of eq. (8).
// Example: examples/12_marble_slab.cpp.
#include <cmath>

#include "okada1987/okada_common.hpp"
#include "okada1987/okada_plot.hpp"
#include "shitsukan/core/detmath.hpp"
#include "shitsukan/image/raster_canvas.hpp"

using namespace shitsukan;
using figures::fmt;

SHITSUKAN_FIGURE(okada1987_fig09, "okada1987", "fig09", "Trapezoid with exponential skirt g(z)") {
    const MarbleStripe s{32.0f, 12.0f, 0.35f};
    ctx.given("g(z)", "1 for d <= 0, exp(-alpha·d) for d > 0, d = |z - c| - w/2", "eq. (8)");
    ctx.chosen("stripe", "c = 32, w = 12, alpha = 0.35; thin: alpha = 1.0 and 0.15",
               "to show the flat top and the skirt");
    RgbImage img(640, 360, Rgb8{255, 255, 255});
    RasterCanvas c(img.view());
    const Axes axes = axes_in(c, 0.0, 64.0, 0.0, 1.15);
    SHITSUKAN_TRY(draw_axes(c, axes, {"g(z), eq. (8)", "z", "g(z)"}));
    auto curve = [&](MarbleStripe st, Rgb8 col, float width) {
        return plot_function(c, axes, [&](double z) { return trapezoid_skirt(float(z), st); }, 801,
                             col, width);
    };
    SHITSUKAN_TRY(curve({32.0f, 12.0f, 1.0f}, Rgb8{150, 150, 210}, 1.0f));
    SHITSUKAN_TRY(curve({32.0f, 12.0f, 0.15f}, Rgb8{140, 200, 140}, 1.0f));
    SHITSUKAN_TRY(curve(s, Rgb8{30, 60, 180}, 2.0f));
    // Annotate c and w.
    const Vec2 a = axes.to_pixel(26.0, 1.07), b = axes.to_pixel(38.0, 1.07);
    c.line(a, b, okada::kInk, 1.0f);
    c.text({(a.x + b.x) * 0.5f - 3, a.y - 12}, "w", okada::kInk);
    const Vec2 cc = axes.to_pixel(32.0, 0.0);
    c.line(cc, axes.to_pixel(32.0, 1.0), Rgb8{120, 120, 120}, 1.0f);
    c.text({cc.x + 3, cc.y - 12}, "c", okada::kInk);
    c.text({axes.corner.x + 8, axes.corner.y + 6}, "alpha = 0.35 (bold), 1.0, 0.15", okada::kInk);
    ctx.note(fmt("At d = 1/alpha beyond the edge the skirt is e^-1 = %.3f.", det_exp(-1.0)));
    return ctx.save_png(img.view());
}
