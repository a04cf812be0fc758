// okada1989 figs. 6 and 7: the two fundamental textures (original functions) before any
// pixel shift: the trapezoid with exponential skirts and the coaxial sine wave.
// Examples: examples/12_marble_slab.cpp, examples/13_wood_slab.cpp.
#include <cmath>

#include "okada1987/okada_common.hpp"
#include "okada1987/okada_plot.hpp"
#include "shitsukan/image/raster_canvas.hpp"
#include "shitsukan/core/detmath.hpp"

using namespace shitsukan;
using figures::fmt;

SHITSUKAN_FIGURE(okada1989_fig06, "okada1989", "fig06", "Trapezoid fundamental texture") {
    const MarbleStripe s = okada::kSingleStripe;
    ctx.given("G", "exp(-alpha·d) for d > 0, 1 for d <= 0, d = |z - c| - w/2", "okada1989 eq. (8)");
    ctx.chosen("stripe", fmt("c = %g, w = %g, alpha = %g (the figures' stripe)", double(s.c),
                             double(s.w), double(s.alpha)), "not given");
    RgbImage img(640, 320, Rgb8{255, 255, 255});
    RasterCanvas c(img.view());
    // Left: G(z) as a curve. Right: the texture on a vertical slice (x right, z up).
    const Axes axes = okada::panel_axes(50, 30, 320, 240, 0.0, 64.0, 0.0, 1.1);
    SHITSUKAN_TRY(draw_axes(c, axes, {"", "z (lattice units)", "G(z)"}));
    SHITSUKAN_TRY(plot_function(c, axes, [&](double z) { return trapezoid_skirt(float(z), s); },
                                601, Rgb8{30, 60, 180}, 2.0f));
    const okada::Material m = okada::Material::marble_single;
    for (int j = 0; j < 240; ++j)
        for (int i = 0; i < 240; ++i) {
            float z = 64.0f * (1.0f - (float(j) + 0.5f) / 240.0f);
            Vec3 col = okada::material_color(m, 1.0f - std::fmin(trapezoid_skirt(z, s), 1.0f));
            img.at(390 + i, 30 + j) =
                Rgb8{std::uint8_t(col.x), std::uint8_t(col.y), std::uint8_t(col.z)};
        }
    c.text({390, 14}, "slice, x right, z up (k = 0)", okada::kInk);
    ctx.note("G is 1 inside the layer (width w) and falls off as exp(-alpha·d) beyond its edges; "
             "the slice shows it with the figures' colours (G' = 1 - G).");
    return ctx.save_png(img.view());
}

SHITSUKAN_FIGURE(okada1989_fig07, "okada1989", "fig07",
                 "Coaxial sine wave fundamental texture (slice)") {
    ctx.given("G", "sin(k2·r), r = distance from the axis (x0, y0)", "okada1989 eq. (10)");
    ctx.chosen("k2", fmt("%g", double(okada::kWoodK2)), "the figures' value");
    ctx.chosen("axis",
               fmt("(%g, %g) lattice", double(okada::kWoodAxis.x), double(okada::kWoodAxis.y)),
               "the figures' value (off the objects' centre)");
    ctx.chosen("G'", "(sin + 1)/2", "maps [-1, 1] to eq. (12)'s [0, 1]");
    RgbImage img(640, 320, Rgb8{255, 255, 255});
    RasterCanvas c(img.view());
    WoodParams w;
    w.x0 = okada::kWoodAxis.x, w.y0 = okada::kWoodAxis.y, w.k2 = okada::kWoodK2, w.k = 0.0f;
    // Left: the slice z = const (x right, y up) over the lattice; right: G along a radius.
    for (int j = 0; j < 260; ++j)
        for (int i = 0; i < 260; ++i) {
            Vec3 p{64.0f * (float(i) + 0.5f) / 260.0f, 64.0f * (1.0f - (float(j) + 0.5f) / 260.0f),
                   32.0f};
            Vec3 col =
                okada::material_color(okada::Material::wood, wood_unit_range(wood_original(p, w)));
            img.at(20 + i, 40 + j) =
                Rgb8{std::uint8_t(col.x), std::uint8_t(col.y), std::uint8_t(col.z)};
        }
    c.text({20, 22}, "slice z = 32: x right, y up, 0..64", okada::kInk);
    const Axes axes = okada::panel_axes(340, 40, 280, 220, 0.0, 24.0, -1.1, 1.1);
    SHITSUKAN_TRY(draw_axes(c, axes, {"", "r (lattice units)", "G = sin(k2 r)"}));
    SHITSUKAN_TRY(plot_function(
        c, axes, [](double r) { return det_sin(okada::kWoodK2 * float(r)); }, 401,
        Rgb8{150, 80, 30}, 2.0f));
    ctx.note("Concentric rings about the axis; wood displaces the point along the radius "
             "(u of eq. (11)) before this function is read.");
    return ctx.save_png(img.view());
}
