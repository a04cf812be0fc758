// okada1989 figs. 8-10: cup, ashtray and torus, marble (a, single stripe) and wood (b).
// Example: examples/15_marble_on_your_mesh.cpp.
#include "okada1987/okada_common.hpp"

using namespace shitsukan;
using okada::Material;

SHITSUKAN_FIGURE(okada1989_fig08a, "okada1989", "fig08a", "A marble cup") {
    ctx.chosen("cup", "revolved profile (outer wall up, rim, inner wall down) + a torus handle",
               "the paper's solid modeller is not described");
    return okada::object_figure(ctx, "cup", Material::marble_single);
}
SHITSUKAN_FIGURE(okada1989_fig08b, "okada1989", "fig08b", "A woody cup") {
    ctx.chosen("cup", "revolved profile (outer wall up, rim, inner wall down) + a torus handle",
               "the paper's solid modeller is not described");
    return okada::object_figure(ctx, "cup", Material::wood);
}
SHITSUKAN_FIGURE(okada1989_fig09a, "okada1989", "fig09a", "A marble ashtray") {
    ctx.chosen("ashtray", "low revolved profile with a rounded rim and a shallow bowl",
               "shape not given");
    return okada::object_figure(ctx, "ashtray", Material::marble_single);
}
SHITSUKAN_FIGURE(okada1989_fig09b, "okada1989", "fig09b", "A woody ashtray") {
    ctx.chosen("ashtray", "low revolved profile with a rounded rim and a shallow bowl",
               "shape not given");
    return okada::object_figure(ctx, "ashtray", Material::wood);
}
SHITSUKAN_FIGURE(okada1989_fig10a, "okada1989", "fig10a", "A marble torus") {
    ctx.chosen("torus", "major radius 0.64, minor 0.28 (before fitting into [-0.92, 0.92]^3)",
               "proportions not given (the body text says \"toast\", the captions torus)");
    return okada::object_figure(ctx, "torus", Material::marble_single);
}
SHITSUKAN_FIGURE(okada1989_fig10b, "okada1989", "fig10b", "A woody torus") {
    ctx.chosen("torus", "major radius 0.64, minor 0.28 (before fitting into [-0.92, 0.92]^3)",
               "proportions not given (the body text says \"toast\", the captions torus)");
    return okada::object_figure(ctx, "torus", Material::wood);
}
