// fujimoto2000 figs 1 and 2: the original IST of §2.1 — constant M = 1 over u^0 .. u^3, and
// M_i = 2 for the centre base interval (u^0 -> u^1), drawn from the library's procedure.
// Example: none of its own; examples/20_ist_table.cpp teaches the later ISTs; the original IST has
//   no lesson.
#include "driver/figure.hpp"
#include "ist_diagram.hpp"

using namespace shitsukan;
using namespace shitsukan::figures;

namespace {

Status render(FigureContext& ctx, const IstDiagram& d, DiagramLayout layout, int width) {
    layout.width = float(width) - layout.left - 20.0f;
    RgbImage image(width, int(diagram_height(d, layout)), Rgb8{255, 255, 255});
    RasterCanvas canvas(image.view());
    draw_ist_diagram(canvas, d, layout);
    return ctx.save_png(image.view());
}

// The figures show a stretch of a long axis: 13 base intervals numbered 0..12 on a cyclic
// axis, of which the window shows 4..7; after K <= 3 iterations a window interval holds parts
// from at most K·M = 3 intervals away, so the wrap never shows.
constexpr int kBases = 13;

}  // namespace

SHITSUKAN_FIGURE(fig01_original_ist, "fujimoto2000", "fig01",
                 "Original IST, M = 1 for every base interval, u^0 -> u^3") {
    const int k_max = 3;
    ctx.given("M_i", "1 for all base intervals", "fig 1 caption");
    ctx.given("iterations", "u^0 -> u^3", "fig 1");
    ctx.given("base intervals shown", "4, 5, 6, 7", "§2.1(1): the numbers on u^0");
    ctx.chosen("axis", "13 base intervals 0..12, cyclic, window 4..7",
               "a stretch of a long axis as the paper draws it; the wrap is 6 intervals away");
    ctx.chosen("followed moves", "the parts of base interval 6",
               "the paper marks moves with symbols; 6 is its running example (6 -> 6.0 ...)");
    IstDiagram d;
    d.ist.original = true;
    d.ist.original_ist.base_intervals = kBases;
    d.ist.original_ist.crossing_all = 1;
    d.ist.original_ist.iterations = k_max;
    d.ist.original_ist.ends = IstEnds::cyclic;
    SHITSUKAN_TRY(ist_original_check(d.ist.original_ist));
    d.window0 = 4.0 / kBases;
    d.window1 = 8.0 / kBases;
    for (int k = 0; k <= k_max; ++k) {
        DiagramRow row = diagram_row(d.ist, fmt("u^%d", k), k, DiagramStage{k, false});
        if (k < k_max) row.tick_depth = k + 1;
        d.rows.push_back(row);
    }
    d.follow = [](const DiagramPiece& p) { return p.origin_base == 6; };
    d.title = "fig 1  original IST with M = 1 (u^0 -> u^3)";
    DiagramLayout layout;
    ctx.note(
        "Each box is a sub-interval, coloured by its base interval of origin (lighter = "
        "further left inside it) and numbered base.digits (base-3 digits, most significant "
        "first). Lines follow the parts of base interval 6. On u^2 the ranges "
        "{3.22 .. 7.00}, {4.22 .. 8.00}, {5.22 .. 9.00} of §2.1(2) fill base intervals 5, 6, 7.");
    return render(ctx, d, layout, ctx.quick() ? 1400 : 2000);
}

SHITSUKAN_FIGURE(
    fig02_original_ist_unequal, "fujimoto2000", "fig02",
    "Original IST with M_i = 2 for the centre base interval, 1 elsewhere: u^0 -> u^1") {
    ctx.given("M_i", "2 for the centre base interval, 1 for the others", "fig 2 caption");
    ctx.given("iterations", "u^0 -> u^1 only", "fig 2 caption");
    ctx.chosen("axis", "13 base intervals 0..12, cyclic, window 4..8, centre 6",
               "the figure's base intervals are not numbered; 6 as in fig 1");
    ctx.chosen("placing of unequal parts", "groups arriving in a base interval are laid out by "
                                           "source from left to right and scaled together to "
                                           "fill it, keeping their relative widths",
               "not stated; with a constant M it is exactly the fully-connected IST "
               "(ist_original.hpp)");
    int crossing[kBases];
    for (int& m : crossing) m = 1;
    crossing[6] = 2;
    IstDiagram d;
    d.ist.original = true;
    d.ist.original_ist.base_intervals = kBases;
    d.ist.original_ist.crossing = crossing;
    d.ist.original_ist.iterations = 1;
    d.ist.original_ist.ends = IstEnds::cyclic;
    SHITSUKAN_TRY(ist_original_check(d.ist.original_ist));
    d.window0 = 4.0 / kBases;
    d.window1 = 9.0 / kBases;
    DiagramRow top = diagram_row(d.ist, "u^0", 1, DiagramStage{0, false});
    d.rows.push_back(top);
    d.rows.push_back(diagram_row(d.ist, "u^1", 1, DiagramStage{1, false}));
    d.follow = [](const DiagramPiece& p) { return p.origin_base >= 4 && p.origin_base <= 8; };
    d.title = "fig 2  original IST with M_6 = 2 and M_i = 1 elsewhere (u^0 -> u^1)";
    ctx.note("u^0 shows the division: base interval 6 into 2·2+1 = 5 parts, the others into 3. "
             "Each part is dealt symmetrically to itself and M_i neighbours on each side, so "
             "base intervals 4 and 8 receive 4 groups and 5, 6, 7 receive 3: the parts come out "
             "with unequal widths.");
    DiagramLayout layout;
    layout.gap = 90;
    return render(ctx, d, layout, ctx.quick() ? 1200 : 1600);
}
