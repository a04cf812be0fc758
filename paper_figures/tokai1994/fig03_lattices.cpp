// tokai1994 fig. 3: patterns from triangular-lattice seeds (a-d) and square-lattice seeds
// (e-h) with increasing relative displacement a; (b) looks like snake skin, (f) like crocodile.
// Example: examples/40_exact_voronoi.cpp.
#include "driver/figure.hpp"
#include "shitsukan/leather/scale_division.hpp"
#include "tokai1994/scale_drawing.hpp"

using namespace shitsukan;
using namespace shitsukan::figures;
using namespace shitsukan::figures::tokai;

namespace {

const float kLatticeD = 0.125f;                             // chosen: 8 seeds a side
const float kDisplacements[4] = {0.0f, 0.1f, 0.25f, 0.5f};  // chosen: a for panels a-d / e-h

Status lattice_figure(FigureContext& ctx, bool triangular, int panel) {
    const float a = kDisplacements[panel];
    const std::uint32_t seed = 3;
    PerturbationParams prm;  // processing 4 with the fig. 7 amplitude
    ctx.given("seeds", triangular ? "triangular lattice" : "square lattice", "§3.1, fig. 3");
    ctx.chosen("D", fmt("%g", double(kLatticeD)), "8 seeds along a side; not printed");
    ctx.chosen("a", fmt("%g", double(a)),
               "fig. 3 shows a increasing over 0, 0.1, 0.25, 0.5 (values not printed)");
    ctx.chosen("displacement", "along x and y, independently, M = D a Rnd each",
               "fig. 3 does not restrict the direction");
    ctx.chosen("p", fmt("%g (%d levels, decay %g)", double(prm.p), prm.levels, double(prm.decay)),
               "the fig. 7 value; processing 4 applies to fig. 3 as well");
    ctx.chosen("random seed", fmt("%u", seed), "any");
    SeedLayout layout;
    if (triangular)
        SHITSUKAN_TRY(triangular_lattice_seeds(1, 1, kLatticeD, a, seed, layout));
    else
        SHITSUKAN_TRY(square_lattice_seeds(1, 1, kLatticeD, a, seed, layout));
    PlanarSubdivision sub;
    SHITSUKAN_TRY(divide_single_stage(layout.moved.data(), int(layout.moved.size()), 1, 1, sub));
    ScalePattern pattern;
    SHITSUKAN_TRY(perturb_subdivision(sub, prm, seed, 1, 1, pattern));
    // interior cell vertex counts: the exactness shows at a = 0 (4 or 6 everywhere)
    int interior = 0, vertex_sum = 0;
    for (int fc = 0; fc < sub.face_count(); ++fc) {
        bool inner = true;
        for (int k = sub.face_offsets[std::size_t(fc)]; k < sub.face_offsets[std::size_t(fc) + 1];
             ++k) {
            Vec2d v = sub.vertices[std::size_t(sub.face_vertex(sub.face_edges[std::size_t(k)]))];
            inner = inner && v.x > 0 && v.x < 1 && v.y > 0 && v.y < 1;
        }
        if (!inner) continue;
        ++interior;
        vertex_sum += sub.face_offsets[std::size_t(fc) + 1] - sub.face_offsets[std::size_t(fc)];
    }
    ctx.note(fmt(
        "%d polygons; the %d interior ones have %.3f vertices on average before perturbation%s.",
        sub.face_count(), interior, interior ? double(vertex_sum) / interior : 0.0,
        a == 0.0f ? (triangular ? " (exactly 6: regular hexagons)" : " (exactly 4: squares)")
                  : ""));
    const int size = ctx.quick() ? 200 : 400, margin = size / 25;
    const Frame f{float(margin), float(margin), float(size - 2 * margin)};
    return save_png_and_svg(ctx, size, size, [&](Canvas& c) {
        draw_pattern(c, pattern, f, kInk, 1.2f);
        draw_border(c, f, 1, 1, kInk, 1.5f);
    });
}

}  // namespace

SHITSUKAN_FIGURE(tokai_fig03a, "tokai1994", "fig03a", "Triangular-lattice seeds, a = 0") {
    return lattice_figure(ctx, true, 0);
}
SHITSUKAN_FIGURE(tokai_fig03b, "tokai1994", "fig03b",
                 "Triangular-lattice seeds, a = 0.1 (snake-like)") {
    return lattice_figure(ctx, true, 1);
}
SHITSUKAN_FIGURE(tokai_fig03c, "tokai1994", "fig03c", "Triangular-lattice seeds, a = 0.25") {
    return lattice_figure(ctx, true, 2);
}
SHITSUKAN_FIGURE(tokai_fig03d, "tokai1994", "fig03d", "Triangular-lattice seeds, a = 0.5") {
    return lattice_figure(ctx, true, 3);
}
SHITSUKAN_FIGURE(tokai_fig03e, "tokai1994", "fig03e", "Square-lattice seeds, a = 0") {
    return lattice_figure(ctx, false, 0);
}
SHITSUKAN_FIGURE(tokai_fig03f, "tokai1994", "fig03f",
                 "Square-lattice seeds, a = 0.1 (crocodile-like)") {
    return lattice_figure(ctx, false, 1);
}
SHITSUKAN_FIGURE(tokai_fig03g, "tokai1994", "fig03g", "Square-lattice seeds, a = 0.25") {
    return lattice_figure(ctx, false, 2);
}
SHITSUKAN_FIGURE(tokai_fig03h, "tokai1994", "fig03h", "Square-lattice seeds, a = 0.5") {
    return lattice_figure(ctx, false, 3);
}
