// fujimoto2000 figs 6-9: the connected IST (§2.2.2) — fully-connected N = 5 with the
// u^{k.5} axes (fig 6a), the fig 6b shuffle, other external shuffles (fig 7), the
// fully-connected external shuffles for N = 1, 3, 7 (fig 8) and the ends of a translation
// axis (fig 9).
// Example: examples/20_ist_table.cpp.
#include "driver/figure.hpp"
#include "ist_diagram.hpp"

using namespace shitsukan;
using namespace shitsukan::figures;

namespace {

// A stretch of a long axis: 13 base intervals 0..12 (cyclic), the window shows 4..8. After
// K = 3 iterations of N = 5 a window interval holds parts from at most 6 intervals away.
constexpr int kBases = 13;

bool family_of_6(const DiagramPiece& p) {
    if (p.origin_base != 6 || p.digits.empty()) return false;
    for (std::size_t i = 0; i + 1 < p.digits.size(); ++i)
        if (p.digits[i] != 0) return false;
    return true;
}

Status draw_single(FigureContext& ctx, const IstDiagram& d, DiagramLayout layout, int width) {
    layout.width = float(width) - layout.left - 20.0f;
    RgbImage image(width, int(diagram_height(d, layout)), Rgb8{255, 255, 255});
    RasterCanvas canvas(image.view());
    draw_ist_diagram(canvas, d, layout);
    return ctx.save_png(image.view());
}

Status draw_panels(FigureContext& ctx, const std::vector<IstDiagram>& panels,
                   DiagramLayout layout, int width) {
    layout.width = float(width) - layout.left - 20.0f;
    float height = 0;
    for (const IstDiagram& d : panels) height += diagram_height(d, layout);
    RgbImage image(width, int(height), Rgb8{255, 255, 255});
    RasterCanvas canvas(image.view());
    float top = layout.top;
    for (const IstDiagram& d : panels) {
        DiagramLayout l = layout;
        l.top = top;
        draw_ist_diagram(canvas, d, l);
        top += diagram_height(d, layout);
    }
    return ctx.save_png(image.view());
}

// Figs 6a/6b: base interval 6 drawn wider (as the paper does "for the drawing"), numbers
// only inside it, u^* on top.
Status connected_figure(FigureContext& ctx, const IstShuffle& shuffle, bool half_axes,
                        const char* title) {
    const int k_max = 3;
    const double wide = 6.0;  // base interval 6 is this many times wider than the others
    IstDiagram d;
    SHITSUKAN_TRY(ist_connected_axis(shuffle, k_max, kBases, IstEnds::cyclic, d.ist.axis));
    double total = double(kBases - 1) + wide, x = 0;
    d.ist.edges.push_back(0.0);
    for (int b = 0; b < kBases; ++b) {
        x += (b == 6 ? wide : 1.0) / total;
        d.ist.edges.push_back(b + 1 == kBases ? 1.0 : x);
    }
    SHITSUKAN_TRY(ist_check_edges(d.ist.axis, d.ist.edge_data()));
    d.window0 = d.ist.edges[4];
    d.window1 = d.ist.edges[9];
    const double in6_0 = d.ist.edges[6], in6_1 = d.ist.edges[7];
    auto inside_6 = [in6_0, in6_1](const DiagramPiece& p) {
        return p.start >= in6_0 - 1e-12 && p.end <= in6_1 + 1e-12;
    };
    DiagramRow star = diagram_row(d.ist, "u*", k_max, DiagramStage{0, false});
    star.show_label = inside_6;
    d.rows.push_back(star);
    for (int k = 0; k <= k_max; ++k) {
        DiagramRow row = diagram_row(d.ist, fmt("u^%d", k), k, DiagramStage{k, false});
        row.show_label = inside_6;
        if (k < k_max) row.tick_depth = k + 1;
        d.rows.push_back(row);
        if (half_axes && k < k_max - 1) {
            DiagramRow half = diagram_row(d.ist, fmt("u^%d.5", k), k + 1, DiagramStage{k, true});
            half.show_label = inside_6;
            d.rows.push_back(half);
        }
    }
    d.follow = family_of_6;
    d.title = title;
    d.first_label = 0;
    DiagramLayout layout;
    return draw_single(ctx, d, layout, ctx.quick() ? 1800 : 3000);
}

void shuffle_params(FigureContext& ctx) {
    ctx.given("N", "5", "fig 6 caption");
    ctx.given("base intervals", "4 .. 8 shown, 6 drawn wider", "fig 6 caption and §2.2.2(1)");
    ctx.given("numbers", "inside base interval 6 only", "fig 6 caption");
    ctx.chosen("axis", "13 base intervals 0..12, cyclic, window 4..8; base 6 six times wider",
               "a stretch of a long axis; parts travel at most K·M = 6 intervals");
    ctx.chosen("followed moves", "6.00x and their ancestors",
               "the paper marks the moves inside base interval 6 with symbols");
}

// Figs 7, 8: one iteration's external shuffle, u^0.5 -> u^1, with every move drawn.
IstDiagram shuffle_panel(const IstAxis& axis, const std::string& title) {
    IstDiagram d;
    d.ist.axis = axis;
    d.window0 = 4.0 / kBases;
    d.window1 = 9.0 / kBases;
    d.rows.push_back(diagram_row(d.ist, "u^0.5", 1, DiagramStage{0, true}));
    d.rows.push_back(diagram_row(d.ist, "u^1", 1, DiagramStage{1, false}));
    d.follow = [](const DiagramPiece& p) { return p.origin_base >= 3 && p.origin_base <= 9; };
    d.title = title;
    return d;
}

}  // namespace

SHITSUKAN_FIGURE(fig06a_fully_connected, "fujimoto2000", "fig06a",
                 "Fully-connected IST, N = 5, with the intermediate axes u^{k.5}") {
    shuffle_params(ctx);
    ctx.given("external shuffle", "fully-connected: group g -> base + g - 2, slot 4 - g",
              "fig 6a, eq. (26)");
    ctx.given("axes", "u*, u^0, u^0.5, u^1, u^1.5, u^2, u^3", "fig 6a caption");
    ctx.note("u^{k.5}: after in-shf, before ex-shf. On u^3 the numbers inside base interval 6 "
             "step by 0.400 between neighbours, 0.440 between runs of 5 and 0.444 between runs "
             "of 25 (§2.2.2(2), fractions in base 5; checked in tests/test_wrinkly_ist.cpp).");
    IstShuffle s;
    SHITSUKAN_TRY(ist_shuffle_fully_connected(5, s));
    return connected_figure(ctx, s, true, "fig 6(a)  fully-connected IST  N = 5");
}

SHITSUKAN_FIGURE(fig06b_connected, "fujimoto2000", "fig06b",
                 "Another connected IST, N = 5 (external shuffle inferred from §2.2.2(2))") {
    shuffle_params(ctx);
    ctx.given("number differences on u^3",
              "0.200 0.100 0.100 0.200 / 0.420 0.010 0.010 0.420 / 0.442 0.001 0.001 0.442",
              "§2.2.2(2)");
    ctx.chosen("external shuffle", "offsets (-1, 0, 0, 0, +1), slots (4, 1, 2, 3, 0)",
               "the table is not printed; inferred from the differences (unique slots; offsets "
               "up to a common shift, fixed by the exchange: groups 1-3 stay), ist_axis.cpp");
    ctx.given("axes", "u*, u^0 .. u^3 (u^{k.5} omitted for space)", "fig 6b caption");
    ctx.note("Groups 1-3 stay home; group 0 goes to the left neighbour's last slot and group 4 "
             "to the right neighbour's first. The u^3 differences of §2.2.2(2) hold for this "
             "table (tests/test_wrinkly_ist.cpp).");
    return connected_figure(ctx, ist_shuffle_fig6b(), false, "fig 6(b)  connected IST  N = 5");
}

SHITSUKAN_FIGURE(fig07_external_shuffles, "fujimoto2000", "fig07",
                 "Other external shuffles, N = 5; (b) is no external shuffle") {
    ctx.given("N", "5", "fig 7 caption");
    ctx.given("(b)", "no external shuffle", "fig 7 caption");
    ctx.chosen("(a)", "nearest neighbours only: offsets (-1,-1,0,1,1), slots (4,3,2,1,0)",
               "fig 7's tables are not printed; an exchange (works on both kinds of axis)");
    ctx.chosen("(c)", "crossed pairs: offsets (-1,1,0,1,-1), slots (3,4,2,0,1)",
               "as (a): an exchange between neighbours with the groups crossed");
    ctx.chosen("shown", "u^0.5 -> u^1 of 13 cyclic base intervals, window 4..8",
               "the external shuffle is the same at every iteration");
    std::vector<IstDiagram> panels;
    const char* names[3] = {"fig7a", "none", "fig7c"};
    const char* titles[3] = {"fig 7(a)  nearest neighbours", "fig 7(b)  no external shuffle",
                             "fig 7(c)  crossed pairs"};
    for (int i = 0; i < 3; ++i) {
        IstShuffle s;
        SHITSUKAN_TRY(ist_shuffle_named(names[i], 5, s));
        IstAxis axis;
        SHITSUKAN_TRY(ist_connected_axis(s, 1, kBases, IstEnds::cyclic, axis));
        panels.push_back(shuffle_panel(axis, titles[i]));
    }
    DiagramLayout layout;
    layout.gap = 80;
    return draw_panels(ctx, panels, layout, ctx.quick() ? 1200 : 1800);
}

SHITSUKAN_FIGURE(fig08_fully_connected_shuffles, "fujimoto2000", "fig08",
                 "External shuffles of the fully-connected IST for N = 1, 3, 7") {
    ctx.given("N", "1, 3, 7 (panels a-c)", "fig 8 caption");
    ctx.given("external shuffle", "group g -> base + g - M, slot N - 1 - g", "eq. (26)");
    ctx.chosen("shown", "u^0.5 -> u^1 of 13 cyclic base intervals, window 4..8",
               "as fig 7");
    std::vector<IstDiagram> panels;
    const int ns[3] = {1, 3, 7};
    const char* titles[3] = {"fig 8(a)  N = 1 (no actual change)", "fig 8(b)  N = 3 (= fig 1)",
                             "fig 8(c)  N = 7"};
    for (int i = 0; i < 3; ++i) {
        IstAxis axis;
        SHITSUKAN_TRY(ist_fully_connected_axis(ns[i], 1, kBases, IstEnds::cyclic, axis));
        panels.push_back(shuffle_panel(axis, titles[i]));
    }
    DiagramLayout layout;
    layout.gap = 80;
    return draw_panels(ctx, panels, layout, ctx.quick() ? 1200 : 1800);
}

SHITSUKAN_FIGURE(fig09_translation_ends, "fujimoto2000", "fig09",
                 "Ends of a translation axis: fully-connected IST, N = 3, base intervals 0..4") {
    const int k_max = 3;
    ctx.given("N", "3", "fig 9 caption");
    ctx.given("base intervals", "0 .. 4, translation (open) axis", "fig 9 caption");
    ctx.given("end rule", "no external shuffle past an end; division always into N",
              "§2.2.2(1)");
    ctx.chosen("iterations", "3, with the u^{k.5} axes", "fig 9's depth is not stated");
    IstDiagram d;
    SHITSUKAN_TRY(ist_fully_connected_axis(3, k_max, 5, IstEnds::translation, d.ist.axis));
    for (int k = 0; k <= k_max; ++k) {
        DiagramRow row = diagram_row(d.ist, fmt("u^%d", k), k, DiagramStage{k, false});
        if (k < k_max) row.tick_depth = k + 1;
        d.rows.push_back(row);
        if (k < k_max)
            d.rows.push_back(diagram_row(d.ist, fmt("u^%d.5", k), k + 1, DiagramStage{k, true}));
    }
    d.follow = [](const DiagramPiece& p) {
        if (p.origin_base != 0 && p.origin_base != 4) return false;
        for (std::size_t i = 0; i + 1 < p.digits.size(); ++i)
            if (p.digits[i] != (p.origin_base == 0 ? 0 : 2)) return false;
        return !p.digits.empty();
    };
    d.title = "fig 9  translation axis  fully-connected IST  N = 3";
    ctx.note("At the left end group 0 of base interval 0 has no neighbour to go to and stays in "
             "its slot (its exchange partner does not exist); likewise group 2 of base interval "
             "4. Every base interval is still divided into exactly N parts, and the map stays a "
             "bijection. Lines follow the parts of the two end intervals.");
    DiagramLayout layout;
    return draw_single(ctx, d, layout, ctx.quick() ? 1500 : 2500);
}
