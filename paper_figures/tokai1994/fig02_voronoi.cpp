// tokai1994 fig. 2: Voronoi division of scattered seeds, drawn with its seeds.
// Example: examples/40_exact_voronoi.cpp.
#include "driver/figure.hpp"
#include "shitsukan/core/prng.hpp"
#include "shitsukan/leather/scale_division.hpp"
#include "tokai1994/scale_drawing.hpp"

using namespace shitsukan;
using namespace shitsukan::figures;
using namespace shitsukan::figures::tokai;

SHITSUKAN_FIGURE(tokai_fig02, "tokai1994", "fig02",
                 "Voronoi division of scattered seeds (with the seeds)") {
    const int seeds_n = 40;
    const std::uint32_t seed = 2;
    ctx.chosen("seeds", fmt("%d, uniform in the unit square (Pcg32 seed %u)", seeds_n, seed),
               "fig. 2 only illustrates the division; the count is not given");
    ctx.given("division", "nearest-seed rule in the continuous plane", "§3.1 processing 3");
    Pcg32 rng(seed, 1);
    std::vector<Vec2d> seeds;
    for (int i = 0; i < seeds_n; ++i) seeds.push_back({rng.uniform_double(), rng.uniform_double()});
    PlanarSubdivision sub;
    SHITSUKAN_TRY(divide_single_stage(seeds.data(), seeds_n, 1.0f, 1.0f, sub));
    const int size = ctx.quick() ? 256 : 512, margin = size / 32;
    const Frame f{float(margin), float(margin), float(size - 2 * margin)};
    ctx.note(fmt("%d seeds, %d Voronoi polygons, %zu edges (each stored once).", seeds_n,
                 sub.face_count(), sub.edges.size()));
    return save_png_and_svg(ctx, size, size, [&](Canvas& c) {
        draw_subdivision(c, sub, f, kInk, 1.2f);
        draw_border(c, f, 1, 1, kInk, 1.5f);
        draw_seeds(c, seeds, f, MarkerShape::dot, size / 80.0f, kInk, {0, 0}, {1, 1});
    });
}
