// okada1987 figs. 1 and 2: the random fractal lattice, level by level (2D quadtree, 3D octree).
// Examples: examples/10_lattice_levels.cpp, examples/16_lattice_rules.cpp.
#include <cmath>
#include <vector>

#include "okada1987/okada_common.hpp"
#include "okada1987/okada_plot.hpp"
#include "shitsukan/image/raster_canvas.hpp"

using namespace shitsukan;
using figures::fmt;

namespace {

constexpr int kPanel = 160;

// Six panels (levels 1..6): panel n shows only the nodes defined after level n, each drawn
// as the square it is nearest to (the blocks shrink by half per level).
template <class ValueAt>
Status level_panels(figures::FigureContext& ctx, int R, const char* what, float kRange,
                    ValueAt value_at) {
    RgbImage img(3 * (kPanel + 10) + 10, 2 * (kPanel + 30) + 40, Rgb8{255, 255, 255});
    RasterCanvas canvas(img.view());
    const int cells = 1 << R;
    for (int n = 1; n <= R; ++n) {
        const int col = (n - 1) % 3, row = (n - 1) / 3;
        const int x0 = 10 + col * (kPanel + 10), y0 = 30 + row * (kPanel + 30);
        const int s = cells >> n;  // node spacing after level n
        okada::paint_field(
            img.view(), x0, y0, kPanel, kPanel,
            [&](float u, float v) {
                int i = int(std::lround(u * float(cells) / float(s))) * s;
                int j = int(std::lround((1.0f - v) * float(cells) / float(s))) * s;
                return value_at(n, i, j);
            },
            -kRange, kRange);
        canvas.text({float(x0), float(y0 - 14)},
                    fmt("level %d: %d x %d", n, (1 << n) + 1, (1 << n) + 1), okada::kInk);
    }
    canvas.text({10.0f, float(img.height() - 16)},
                fmt("%s   colour: blue -%g .. white 0 .. red +%g", what, double(kRange),
                    double(kRange)),
                okada::kInk);
    return ctx.save_png(img.view());
}

}  // namespace

SHITSUKAN_FIGURE(okada1987_fig01, "okada1987", "fig01",
                 "2D random fractal lattice by quadtree: the height field level by level") {
    QuadtreeParams q;
    q.R = 6;
    q.beta = okada::kBeta;
    q.seed = okada::kSeed;
    ctx.given("scheme", "each square cut in four; 5 new points = linear interpolation of the 4 "
                        "vertices + random value", "okada1987 §2.1, fig. 1");
    ctx.given("R", "6 (65 x 65 points)", "the papers' depth");
    ctx.chosen("beta", fmt("%g", double(q.beta)), "the same as the 3D lattice");
    ctx.chosen("seed", fmt("%u (hash stream 1)", q.seed), "any");
    ctx.chosen("corners", "0", "not given");
    std::vector<std::vector<float>> levels(7, std::vector<float>(65 * 65));
    int side = 0;
    for (int n = 1; n <= 6; ++n)
        SHITSUKAN_TRY(build_quadtree_lattice(q, levels[std::size_t(n)].data(),
                                             levels[std::size_t(n)].size() * sizeof(float), side,
                                             n));
    ctx.note("Each panel shows the heights defined after level n, each as the square around it; "
             "a level halves the spacing and adds corrections of amplitude exp(-(n-1)·beta).");
    return level_panels(ctx, 6, "2D heights h(x, y)", 1.2f, [&](int n, int i, int j) {
        return levels[std::size_t(n)][std::size_t(j * side + i)];
    });
}

SHITSUKAN_FIGURE(okada1987_fig02, "okada1987", "fig02",
                 "3D lattice by octree: the z = 32 slice of the 65^3 lattice after levels 1..6") {
    okada::record_lattice(ctx);
    ctx.given("steps", "edge midpoints (1), face centres from edge midpoints (3), cube centre "
                       "from face centres (4)", "okada1987 §2.2, eqs. (1)-(4)");
    ctx.chosen("slice", "z = 32 (the plane added at level 1)", "shows every level");
    FractalParams p = okada::shared_lattice().params();
    std::vector<std::vector<float>> levels(7, std::vector<float>(65 * 65 * 65));
    std::vector<LatticeView> views(7);
    for (int n = 1; n <= 6; ++n)
        SHITSUKAN_TRY(build_fractal_lattice(p, levels[std::size_t(n)].data(),
                                            levels[std::size_t(n)].size() * sizeof(float),
                                            views[std::size_t(n)], n));
    // The finished partial build equals the shared lattice (same rules, same numbers).
    const LatticeView full = okada::shared_lattice().view();
    int differ = 0;
    for (int i = 0; i < 65 * 65 * 65; ++i)
        if (levels[6][std::size_t(i)] != full.values[i]) ++differ;
    if (differ != 0)
        return Status::error(StatusCode::invalid_argument,
                             "fig02: level-6 build differs at %d nodes", differ);
    ctx.note("After level 6 the slice is the z = 32 plane of the lattice every figure uses "
             "(checked: 0 of 274625 nodes differ).");
    return level_panels(ctx, 6, "3D lattice D(x, y, 32)", 2.0f, [&](int n, int i, int j) {
        return views[std::size_t(n)].at(i, j, 32);
    });
}
