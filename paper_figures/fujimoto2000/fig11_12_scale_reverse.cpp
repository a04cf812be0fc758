// fujimoto2000 figs 11 and 12: the scale reverse rule — every sub-interval number alpha^0
// plotted against its image alpha^3 (unit-IST N = 5, eq. 7; fully-connected IST N = 5 on
// base interval 6, eq. 12), the points joined in the order of alpha^0 (eq. 5) and coloured
// by the shift copy (sc1, sc2, sc3) that creates them from the group G1 = (000, 000).
// Example: examples/20_ist_table.cpp.
#include <cmath>
#include <string>
#include <vector>

#include "driver/figure.hpp"
#include "shitsukan/image/canvas.hpp"
#include "shitsukan/image/font.hpp"
#include "shitsukan/wrinkly/ist.hpp"

using namespace shitsukan;
using namespace shitsukan::figures;

namespace {

struct Plot {
    float left, top, size_x, size_y;
    double x0, x1, y0, y1;  // data ranges; y grows upwards
    Vec2 at(double x, double y) const {
        return {float(left + (x - x0) / (x1 - x0) * size_x),
                float(top + size_y - (y - y0) / (y1 - y0) * size_y)};
    }
};

std::string digits_of(std::uint64_t index, int n, int k) {
    std::string s(std::size_t(k), '0');
    for (int i = k - 1; i >= 0; --i) {
        s[std::size_t(i)] = char('0' + index % std::uint64_t(n));
        index /= std::uint64_t(n);
    }
    return s;
}

// The shift copy that creates alpha^0 from G1: sc_j for the highest digit position j (from
// the least significant, eq. 5's fastest digit) that is not 0; 0 for G1 itself.
int shift_copy_level(std::uint64_t index, int n) {
    int level = 0, j = 0;
    while (index > 0) {
        ++j;
        if (index % std::uint64_t(n) != 0) level = j;
        index /= std::uint64_t(n);
    }
    return level;
}

const Rgb8 kLevelColour[4] = {Rgb8{0, 0, 0}, Rgb8{220, 40, 40}, Rgb8{30, 150, 60},
                              Rgb8{40, 80, 220}};

struct ScalePlotInput {
    IstAxis axis;
    int base = 0;        // base interval of alpha^0
    int first_label = 0;  // number of base interval 0 in labels
    std::string title, y_label;
};

Status scale_plot(FigureContext& ctx, const ScalePlotInput& in) {
    const int n = in.axis.n, k = in.axis.iterations;
    const std::uint64_t count = ist_sub_interval_count(in.axis);
    // Points: x = index of alpha^0 in base `base`, y = alpha^K as a real number b + i/N^K.
    std::vector<double> ys(static_cast<std::size_t>(count));
    double y_min = 1e300, y_max = -1e300;
    for (std::uint64_t i = 0; i < count; ++i) {
        IstDigits a, b;
        ist_digits_from_index(in.axis, in.base, i, &a);
        ist_digits_forward(in.axis, a, &b);
        double y = double(b.base) + double(ist_digits_index(in.axis, b)) / double(count);
        ys[std::size_t(i)] = y;
        y_min = std::fmin(y_min, y);
        y_max = std::fmax(y_max, y);
    }
    const bool connected = in.axis.kind != IstKind::unit;
    double y0 = connected ? std::floor(y_min) : 0.0, y1 = connected ? std::floor(y_max) + 1.0 : 1.0;
    const int size = ctx.quick() ? 560 : 1000;
    RgbImage image(size + 260, size + 130, Rgb8{255, 255, 255});
    RasterCanvas canvas(image.view());
    const Rgb8 black{0, 0, 0}, grid{225, 225, 225}, arrow{150, 150, 150};
    Plot p{130.0f, 60.0f, float(size), float(size), -0.5, double(count) - 0.5, y0, y1};
    canvas.text({p.left, 8.0f}, in.title, black, 2);

    // Grid and ticks: x every N numbers (labels every N^2), y every base interval (connected)
    // or every N^{K-1}/N^K (unit).
    for (std::uint64_t i = 0; i < count; i += std::uint64_t(n)) {
        Vec2 a = p.at(double(i), y0), b = p.at(double(i), y1);
        bool major = i % std::uint64_t(n * n) == 0;
        canvas.line(a, b, major ? Rgb8{200, 200, 200} : grid, 1.0f);
        if (major) {
            std::string label = fmt("%d.", in.base + in.first_label) + digits_of(i, n, k);
            if (!connected) label = digits_of(i, n, k);
            canvas.text({a.x - 0.5f * float(text_width(label, 1)), a.y + 8.0f}, label, black, 1);
        }
    }
    const int y_steps = connected ? int(y1 - y0) : n;
    for (int s = 0; s <= y_steps; ++s) {
        double y = y0 + (y1 - y0) * double(s) / double(y_steps);
        Vec2 a = p.at(-0.5, y), b = p.at(double(count) - 0.5, y);
        canvas.line(a, b, Rgb8{200, 200, 200}, 1.0f);
        std::string label = connected ? fmt("%d.000", int(std::lround(y)) + in.first_label)
                                      : digits_of(std::uint64_t(s) * (count / std::uint64_t(n)),
                                                  n, k);
        if (s < y_steps || connected)
            canvas.text({a.x - float(text_width(label, 1)) - 12.0f, a.y - 4.0f}, label, black, 1);
    }
    canvas.rect_outline({p.left, p.top}, {p.size_x, p.size_y}, black, 1.5f);
    canvas.text({p.left + 0.5f * p.size_x - 60.0f, p.top + p.size_y + 30.0f},
                "\xce\xb1^0 on u^0 (order of eq. 5)", black, 1);
    canvas.text({8.0f, p.top - 16.0f}, in.y_label, black, 1);

    // The jumps in the order of alpha^0 (eq. 5 -> eq. 6).
    for (std::uint64_t i = 0; i + 1 < count; ++i)
        canvas.line(p.at(double(i), ys[std::size_t(i)]),
                    p.at(double(i + 1), ys[std::size_t(i + 1)]), arrow, 0.8f);
    // Groups G1 (a point), G2 (N points), G3 (N^2 points): outlined.
    for (int g = 1; g <= 3 && g <= k; ++g) {
        std::uint64_t members = 1;
        for (int j = 1; j < g; ++j) members *= std::uint64_t(n);
        double lo = 1e300, hi = -1e300;
        for (std::uint64_t i = 0; i < members; ++i) {
            lo = std::fmin(lo, ys[std::size_t(i)]);
            hi = std::fmax(hi, ys[std::size_t(i)]);
        }
        float pad = 5.0f + 3.0f * float(g);
        Vec2 a = p.at(-0.5 + 0.5, hi), b = p.at(double(members) - 1.0, lo);
        canvas.rect_outline({a.x - pad, a.y - pad}, {b.x - a.x + 2 * pad, b.y - a.y + 2 * pad},
                            kLevelColour[g - 1], g == 3 ? 2.0f : 1.5f);
        canvas.text({a.x - pad, a.y - pad - 11.0f}, fmt("G%d", g), kLevelColour[g - 1], 1);
    }
    for (std::uint64_t i = 0; i < count; ++i)
        canvas.marker(p.at(double(i), ys[std::size_t(i)]), MarkerShape::dot, 6.0f,
                      kLevelColour[shift_copy_level(i, n)]);
    // Legend.
    const char* legend[4] = {"G1", "sc1 copies", "sc2 copies", "sc3 copies"};
    for (int l = 0; l < 4; ++l) {
        Vec2 c{p.left + p.size_x + 20.0f, p.top + 20.0f + 18.0f * float(l)};
        canvas.marker(c, MarkerShape::dot, 7.0f, kLevelColour[l]);
        canvas.text({c.x + 8.0f, c.y - 4.0f}, legend[l], black, 1);
    }
    return ctx.save_png(image.view());
}

}  // namespace

SHITSUKAN_FIGURE(fig11_scale_reverse_unit, "fujimoto2000", "fig11",
                 "Scale reverse rule of the unit-IST: alpha^0 against alpha^3, N = 5") {
    ctx.given("N, K", "5, 3", "fig 11 (the u^*, u^3 axes of fig 3)");
    ctx.given("rule", "alpha^3 = alpha^0 with its digits reversed", "eq. (7)");
    ctx.chosen("u^0 scale", "uniform", "the paper compresses parts of u^0 to fit the page");
    ScalePlotInput in;
    SHITSUKAN_TRY(ist_unit_axis(5, 3, in.axis));
    in.title = "fig 11  unit-IST scale reverse rule  N = 5";
    in.y_label = "\xce\xb1^3 on u^3";
    ctx.note("Walking along u^0 (eq. 5, the last digit fastest) the image jumps by 100 (sc1), "
             "then a run of five is repeated shifted by 010 (sc2), then a run of 25 shifted by "
             "001 (sc3): eq. (6). G1 = (000, 000), G2 = its 5 sc1 copies, G3 = 25 points.");
    return scale_plot(ctx, in);
}

SHITSUKAN_FIGURE(fig12_scale_reverse_fully, "fujimoto2000", "fig12",
                 "Scale reverse rule of the fully-connected IST, base interval 6, N = 5") {
    ctx.given("N, K", "5, 3", "fig 12 (the u^*, u^3 axes of fig 6a)");
    ctx.given("base interval", "6", "fig 12 caption");
    ctx.given("rule", "alpha^3_0 = alpha^0_0 + sum (alpha_j - M), alpha^3_i = N-1-alpha^0_{K-i+1}",
              "eq. (12)");
    ctx.chosen("axis", "13 base intervals 0..12, cyclic", "images reach 6 intervals away");
    ScalePlotInput in;
    SHITSUKAN_TRY(ist_fully_connected_axis(5, 3, 13, IstEnds::cyclic, in.axis));
    in.base = 6;
    in.title = "fig 12  fully-connected IST scale reverse rule  N = 5  base 6";
    in.y_label = "\xce\xb1^3 (base.digits, fraction base 5)";
    ctx.note("Same grouping and shift copies as fig 11, with steps 0.400, 0.440, 0.444 "
             "(§2.2.2(2)): each shift moves one base interval right and reverses a digit.");
    return scale_plot(ctx, in);
}
