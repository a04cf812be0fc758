// okada1987 figs. 10, 11, 13, 14, 15: the marble (a) and wood (b) objects.
// Examples: examples/13_wood_slab.cpp, examples/15_marble_on_your_mesh.cpp.
#include "okada1987/okada_common.hpp"

using namespace shitsukan;
using okada::Material;

SHITSUKAN_FIGURE(okada1987_fig10a, "okada1987", "fig10a", "Cube, marble (k = 16)") {
    ctx.note("Look for: the stripes continue across the cube's edges (one solid, not three maps).");
    return okada::object_figure(ctx, "cube", Material::marble);
}
SHITSUKAN_FIGURE(okada1987_fig10b, "okada1987", "fig10b", "Cube, wood (k = 1.6)") {
    ctx.note("Look for: rings continue across the cube's edges; end grain on the top face.");
    return okada::object_figure(ctx, "cube", Material::wood);
}
SHITSUKAN_FIGURE(okada1987_fig11a, "okada1987", "fig11a", "Cube cut into parallel slices, marble") {
    ctx.note("Five slabs of the same cube moved apart: each cut face shows the inside of the "
             "same solid, and neighbouring faces continue each other.");
    return okada::object_figure(ctx, "slices", Material::marble);
}
SHITSUKAN_FIGURE(okada1987_fig11b, "okada1987", "fig11b", "Cube cut into parallel slices, wood") {
    return okada::object_figure(ctx, "slices", Material::wood);
}
SHITSUKAN_FIGURE(okada1987_fig13a, "okada1987", "fig13a", "Sphere with a part cut away, marble") {
    ctx.note("The three quarter-disc cut faces show the inside of the same solid texture.");
    return okada::object_figure(ctx, "cut_sphere", Material::marble);
}
SHITSUKAN_FIGURE(okada1987_fig13b, "okada1987", "fig13b", "Sphere with a part cut away, wood") {
    return okada::object_figure(ctx, "cut_sphere", Material::wood);
}
SHITSUKAN_FIGURE(okada1987_fig14a, "okada1987", "fig14a",
                 "Pot: solid of revolution of a spline curve, marble") {
    ctx.given("profile", "spline curve revolved about the axis, computed in double",
              "okada1987 §4.4");
    ctx.chosen("spline", "Catmull-Rom through 8 control points (r, y), 16 samples per segment",
               "the paper names no spline type");
    return okada::object_figure(ctx, "pot", Material::marble);
}
SHITSUKAN_FIGURE(okada1987_fig14b, "okada1987", "fig14b",
                 "Pot: solid of revolution of a spline curve, wood") {
    ctx.given("profile", "spline curve revolved about the axis, computed in double",
              "okada1987 §4.4");
    ctx.chosen("spline", "Catmull-Rom through 8 control points (r, y), 16 samples per segment",
               "the paper names no spline type");
    return okada::object_figure(ctx, "pot", Material::wood);
}
SHITSUKAN_FIGURE(okada1987_fig15a, "okada1987", "fig15a", "\"NAGOYA\" built from planes, marble") {
    ctx.chosen("letters", "block capitals extruded (depth 0.45 of the letter height)",
               "the paper's letter shapes are not given");
    return okada::object_figure(ctx, "nagoya", Material::marble);
}
SHITSUKAN_FIGURE(okada1987_fig15b, "okada1987", "fig15b", "\"NAGOYA\" built from planes, wood") {
    ctx.chosen("letters", "block capitals extruded (depth 0.45 of the letter height)",
               "the paper's letter shapes are not given");
    return okada::object_figure(ctx, "nagoya", Material::wood);
}
