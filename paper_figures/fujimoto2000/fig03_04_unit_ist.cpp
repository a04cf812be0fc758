// fujimoto2000 figs 3 and 4: the unit-IST (§2.2.1) — N = 5 over u^0 .. u^3 with the
// sub-interval numbers, and the internal shuffle of iteration 2 for N = 1, 2, 3, 4.
// Example: examples/20_ist_table.cpp.
#include "driver/figure.hpp"
#include "ist_diagram.hpp"

using namespace shitsukan;
using namespace shitsukan::figures;

namespace {

// The paper marks the moves of the parts that start out together (000, 001, .., 004 on u^0):
// follow the pieces whose digits are all 0 but the last.
bool first_family(const DiagramPiece& p) {
    if (p.digits.empty()) return false;
    for (std::size_t i = 0; i + 1 < p.digits.size(); ++i)
        if (p.digits[i] != 0) return false;
    return true;
}

}  // namespace

SHITSUKAN_FIGURE(fig03_unit_ist, "fujimoto2000", "fig03",
                 "Unit-IST, N = 5: u^* and u^0 -> u^3 with the sub-interval numbers") {
    const int n = 5, k_max = 3;
    ctx.given("N", "5", "fig 3 caption");
    ctx.given("iterations", "K = 3 (u^3 shown alone for k = 3)", "fig 3 caption");
    ctx.given("u^*", "the divisions only, no shuffle: the arrangement on u^0", "§2.2.1(1)");
    ctx.chosen("followed moves", "000 .. 004 and their ancestors",
               "the paper marks 000, 001, .., 004 with symbols (§2.2.1(1))");
    IstDiagram d;
    SHITSUKAN_TRY(ist_unit_axis(n, k_max, d.ist.axis));
    d.unit_labels = true;
    d.rows.push_back(diagram_row(d.ist, "u*", k_max, DiagramStage{0, false}));
    for (int k = 0; k <= k_max; ++k) {
        DiagramRow row = diagram_row(d.ist, fmt("u^%d", k), k, DiagramStage{k, false});
        if (k < k_max) row.tick_depth = k + 1;
        d.rows.push_back(row);
    }
    d.follow = first_family;
    d.title = "fig 3  unit-IST  N = 5  (div + in-shf per iteration)";
    ctx.note("u* is u^0 divided three times without shuffling. Each iteration divides every "
             "sub-interval into 5 (ticks under the axis) and groups the parts at the same place "
             "in their parents (in-shf). On u^3 the number found at u*-position abc is cba "
             "(eq. 7): inside each run of 5 the numbers step by 100, runs of 5 by 010, runs of "
             "25 by 001 (§2.2.1(2)).");
    DiagramLayout layout;
    const int width = ctx.quick() ? 1500 : 2700;
    layout.width = float(width) - layout.left - 20.0f;
    RgbImage image(width, int(diagram_height(d, layout)), Rgb8{255, 255, 255});
    RasterCanvas canvas(image.view());
    draw_ist_diagram(canvas, d, layout);
    return ctx.save_png(image.view());
}

SHITSUKAN_FIGURE(fig04_unit_ist_n, "fujimoto2000", "fig04",
                 "Unit-IST for N = 1, 2, 3, 4: the internal shuffle of iteration k = 2") {
    ctx.given("N", "1, 2, 3, 4 (panels a-d)", "fig 4 caption");
    ctx.given("shown", "the in-shf of iteration k = 2: u^1 (divided) -> u^2", "fig 4 caption");
    ctx.chosen("layout", "panels stacked top to bottom, all moves drawn", "one image per figure");
    const int width = ctx.quick() ? 1000 : 1400;
    DiagramLayout layout;
    layout.width = float(width) - layout.left - 20.0f;
    layout.gap = 70;
    std::vector<IstDiagram> panels;
    const char* names[4] = {"(a) N = 1 (no actual change)", "(b) N = 2", "(c) N = 3", "(d) N = 4"};
    float height = 0;
    for (int n = 1; n <= 4; ++n) {
        IstDiagram d;
        SHITSUKAN_TRY(ist_unit_axis(n, 2, d.ist.axis));
        d.unit_labels = true;
        d.rows.push_back(diagram_row(d.ist, "u^1", 2, DiagramStage{1, false}));
        d.rows.push_back(diagram_row(d.ist, "u^2", 2, DiagramStage{2, false}));
        d.follow = [](const DiagramPiece&) { return true; };
        d.title = fmt("fig 4%s", names[n - 1]);
        height += diagram_height(d, layout);
        panels.push_back(d);
    }
    RgbImage image(width, int(height), Rgb8{255, 255, 255});
    RasterCanvas canvas(image.view());
    float top = layout.top;
    for (const IstDiagram& d : panels) {
        DiagramLayout l = layout;
        l.top = top;
        draw_ist_diagram(canvas, d, l);
        top += diagram_height(d, layout);
    }
    ctx.note("The u^1 row shows the parts of the second division in place (ab = part b of "
             "sub-interval a); the in-shf gathers the parts with the same b: u^2 reads ba.");
    return ctx.save_png(image.view());
}
