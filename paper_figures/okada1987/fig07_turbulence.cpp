// okada1987 fig. 7: the original function G and the same G disturbed by D, side by side.
// Example: examples/11_turbulence_line.cpp.
#include "okada1987/okada_common.hpp"
#include "okada1987/okada_plot.hpp"
#include "shitsukan/image/raster_canvas.hpp"

using namespace shitsukan;
using figures::fmt;

SHITSUKAN_FIGURE(okada1987_fig07, "okada1987", "fig07",
                 "Turbulence of G by D: a slice of G, of D and of the displaced G") {
    okada::record_lattice(ctx);
    okada::record_material(ctx, okada::Material::marble, okada::kMarbleK);
    ctx.chosen("slice", "the plane y = 32 of the lattice, x right, z up, 0..64", "a vertical cut");
    ctx.given("P'", "P + k·D(P)·u (pixel shift, backward form)", "okada1989 eq. (7)");
    const int panel = 200;
    RgbImage img(3 * panel + 40, panel + 60, Rgb8{255, 255, 255});
    RasterCanvas c(img.view());
    auto at = [](float u, float v) { return Vec3{64.0f * u, 32.0f, 64.0f * (1.0f - v)}; };
    const okada::Material m = okada::Material::marble;
    auto paint_density = [&](int x0, float k) {
        for (int j = 0; j < panel; ++j)
            for (int i = 0; i < panel; ++i) {
                Vec3 p = at((float(i) + 0.5f) / panel, (float(j) + 0.5f) / panel);
                Vec3 col = okada::material_color(m, okada::density(m, k, p));
                img.at(x0 + i, 30 + j) =
                    Rgb8{std::uint8_t(col.x), std::uint8_t(col.y), std::uint8_t(col.z)};
            }
    };
    paint_density(10, 0.0f);
    const LatticeView v = okada::shared_lattice().view();
    okada::paint_field(img.view(), 20 + panel, 30, panel, panel,
                       [&](float u, float w) { return turbulence(v, at(u, w)); }, -2.0f, 2.0f);
    paint_density(30 + 2 * panel, okada::kMarbleK);
    c.text({10, 12}, "G(P): the stripes (k = 0)", okada::kInk);
    c.text({float(20 + panel), 12}, "D(P): blue -2 .. red +2", okada::kInk);
    c.text({float(30 + 2 * panel), 12}, "G(P + 16 D(P) (0,0,1))", okada::kInk);
    ctx.note("Left: the layers of eq. (8) undisturbed. Middle: the turbulence D on the same "
             "plane. Right: each point shows G at the point moved by k·D along z.");
    return ctx.save_png(img.view());
}
