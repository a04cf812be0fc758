// fujimoto2000 figs. 19 and 20: why the hierarchical sampling of §4.2 exists and where it
// samples.
// fig. 19: a height function on the u axis only. (a) H(u); (b) H((F_U^k)^{-1}(u)) after a unit-IST
// N = 3 up to k = 2: the staircase-like pieces, with the values at the midpoints of the 9 small
// intervals of the u^2 axis (dots); (c) the dots interpolated linearly, H^2(u); (d) the same by
// Hermite interpolation (higher order). The boundary samples at u = 0 and 1 (fig. 20: an open
// surface is sampled on its edges too) are the hollow dots.
// fig. 20: the sampling points of the unit-IST N = 3 at k = 1 and k = 2: one per small region
// ((3^k)^2 of them), plus points on the boundary of the open surface.
// Example: examples/31_superposed_mountains.cpp.
#include <cmath>
#include <vector>

#include "driver/figure.hpp"
#include "shitsukan/geom/basis.hpp"
#include "shitsukan/image/raster_canvas.hpp"
#include "shitsukan/wrinkly/hierarchical_sampling.hpp"
#include "shitsukan/wrinkly/ist_formula.hpp"

namespace shitsukan::fujimoto2000 {
namespace {

using figures::FigureContext;
using figures::fmt;

// Chosen: the 1D height function is a cubic Bezier curve with heights 0.15, 1.25, -0.35, 0.8.
constexpr float kHeights[4] = {0.15f, 1.25f, -0.35f, 0.8f};

float height_1d(float u) {
    float b[kMaxBasisDegree + 1];
    bernstein_basis(3, u, b);
    return b[0] * kHeights[0] + b[1] * kHeights[1] + b[2] * kHeights[2] + b[3] * kHeights[3];
}

struct Plot {
    int w, h, left = 50, right = 16, top = 24, bottom = 36;
    float ymin = -0.2f, ymax = 1.0f;
    Vec2 at(float u, float y) const {
        return {float(left) + u * float(w - left - right),
                float(top) + (ymax - y) / (ymax - ymin) * float(h - top - bottom)};
    }
};

void axes(RasterCanvas& c, const Plot& p, const char* title) {
    const Rgb8 grey{150, 150, 150}, black{0, 0, 0};
    c.rect_outline(p.at(0, p.ymax),
                   Vec2{float(p.w - p.left - p.right), float(p.h - p.top - p.bottom)}, black, 1.0f);
    c.line(p.at(0, 0), p.at(1, 0), grey, 1.0f);
    for (int i = 0; i <= 9; ++i) {  // the small intervals of u^2
        const float u = float(i) / 9.0f;
        c.line(p.at(u, p.ymin),
               Vec2{p.at(u, p.ymin).x, p.at(u, p.ymin).y + (i % 3 == 0 ? 8.0f : 4.0f)}, black,
               1.0f);
    }
    c.text({float(p.left), 6.0f}, title, black, 1);
    c.text({float(p.left) - 4, float(p.h - p.bottom) + 12}, "0", black, 1);
    c.text({float(p.w - p.right) - 4, float(p.h - p.bottom) + 12}, "1", black, 1);
    c.text({float(p.w) / 2, float(p.h - p.bottom) + 14}, "u", black, 1);
    c.text({8.0f, p.at(0, 0).y - 4}, "0", black, 1);
    c.text({8.0f, p.at(0, 1).y - 4}, "1", black, 1);
}

Status run19(FigureContext& ctx, char panel) {
    const bool quick = ctx.quick();
    const int w = quick ? 240 : 560, h = quick ? 150 : 320;
    ctx.given("IST", "unit-IST N = 3, k = 2 (9 small intervals)", "fig. 19 caption");
    ctx.chosen("H(u)", "cubic Bezier, heights 0.15, 1.25, -0.35, 0.8",
               "any smooth function; not printed");
    ctx.chosen("samples", "midpoints of the 9 small intervals + the ends u = 0, 1",
               "fig. 19(b), fig. 20");
    RgbImage img(w, h, Rgb8{255, 255, 255});
    RasterCanvas c(img.view());
    Plot p{w, h};
    p.ymin = -0.2f;
    p.ymax = 1.0f;
    const char* titles[4] = {"(a) H(u)", "(b) H((F^2)^-1(u)), unit-IST N = 3",
                             "(c) linear interpolation H^2(u)", "(d) Hermite interpolation"};
    axes(c, p, titles[panel - 'a']);
    IstAxis ist;
    SHITSUKAN_TRY(ist_unit_axis(3, 2, ist));
    const Rgb8 blue{30, 80, 200}, red{210, 40, 30}, light{170, 190, 235};
    const int n = quick ? 200 : 900;
    auto curve = [&](auto f, Rgb8 col, float width) {
        std::vector<Vec2> pts;
        for (int i = 0; i <= n; ++i) {
            const float u = float(i) / float(n);
            pts.push_back(p.at(u, f(u)));
        }
        c.polyline(pts.data(), int(pts.size()), col, width);
    };
    auto staircase = [&](Rgb8 col, float width) {  // one continuous piece per small interval
        for (int s = 0; s < 9; ++s) {
            std::vector<Vec2> pts;
            for (int i = 0; i <= 40; ++i) {
                const float u = (float(s) + float(i) / 40.0f * 0.9999f) / 9.0f;
                pts.push_back(p.at(u, height_1d(ist_inverse(ist, u))));
            }
            c.polyline(pts.data(), int(pts.size()), col, width);
        }
    };
    // The samples: positions of step 2 and their IST-transformed heights (eq. 20).
    const std::vector<float> x = hierarchical_sample_positions(1, 3, 2);
    std::vector<float> y;
    for (float u : x) y.push_back(height_1d(ist_inverse(ist, u)));
    if (panel == 'a') {
        curve([](float u) { return height_1d(u); }, blue, 2.0f);
    } else {
        staircase(panel == 'b' ? blue : light, panel == 'b' ? 2.0f : 1.5f);
        if (panel >= 'c') {
            const SampleInterpolation mode =
                panel == 'c' ? SampleInterpolation::linear : SampleInterpolation::hermite;
            curve(
                [&](float u) {
                    int first;
                    float wts[4];
                    sample_interpolation_weights(x.data(), int(x.size()), u, mode, &first, wts);
                    float s = 0;
                    for (int a = 0; a < 4; ++a)
                        if (wts[a] != 0) s += wts[a] * y[std::size_t(first + a)];
                    return s;
                },
                red, 2.0f);
        }
        const float ds = quick ? 3.0f : 7.0f;
        for (std::size_t i = 0; i < x.size(); ++i) {
            const bool boundary = i == 0 || i + 1 == x.size();
            if (boundary && panel == 'b') continue;
            c.marker(p.at(x[i], y[i]), boundary ? MarkerShape::circle : MarkerShape::dot, ds,
                     Rgb8{0, 0, 0});
        }
    }
    return ctx.save_png(img.view());
}

Status run20(FigureContext& ctx) {
    const bool quick = ctx.quick();
    const int cell = quick ? 110 : 300, pad = quick ? 14 : 40;
    RgbImage img(2 * cell + 3 * pad, cell + 2 * pad, Rgb8{255, 255, 255});
    RasterCanvas c(img.view());
    ctx.given("IST", "unit-IST N = 3, k = 1 and 2", "fig. 20 caption");
    ctx.given("sampling",
              "one point per small region ((3^k)^2), plus the boundary of the open surface",
              "fig. 20 caption");
    for (int k = 1; k <= 2; ++k) {
        const float x0 = float(pad + (k - 1) * (cell + pad)), y0 = float(pad);
        const int m = k == 1 ? 3 : 9;
        for (int i = 0; i <= m; ++i) {
            const float t = float(i) / float(m) * float(cell);
            const Rgb8 g = (i == 0 || i == m) ? Rgb8{0, 0, 0} : Rgb8{160, 160, 160};
            c.line({x0 + t, y0}, {x0 + t, y0 + float(cell)}, g, i == 0 || i == m ? 2.0f : 1.0f);
            c.line({x0, y0 + t}, {x0 + float(cell), y0 + t}, g, i == 0 || i == m ? 2.0f : 1.0f);
        }
        const std::vector<float> pos = hierarchical_sample_positions(1, 3, k);
        const float ds = quick ? (k == 1 ? 5.0f : 3.0f) : (k == 1 ? 10.0f : 6.0f);
        for (std::size_t j = 0; j < pos.size(); ++j)
            for (std::size_t i = 0; i < pos.size(); ++i) {
                const bool boundary =
                    i == 0 || j == 0 || i + 1 == pos.size() || j + 1 == pos.size();
                const Vec2 at{x0 + pos[i] * float(cell), y0 + (1.0f - pos[j]) * float(cell)};
                c.marker(at, boundary ? MarkerShape::circle : MarkerShape::dot, ds,
                         boundary ? Rgb8{200, 40, 30} : Rgb8{0, 0, 0});
            }
        if (!quick)
            c.text({x0, y0 + float(cell) + 10}, fmt("k = %d: %d regions", k, m * m), Rgb8{0, 0, 0},
                   2);
    }
    ctx.note(
        "Black dots: one sample per small region; red rings: samples on the boundary of the "
        "open surface.");
    return ctx.save_png(img.view());
}

}  // namespace

SHITSUKAN_FIGURE(fig19a_panel, "fujimoto2000", "fig19a",
                 "Height function on the u axis: (a) H(u)") {
    return run19(ctx, 'a');
}
SHITSUKAN_FIGURE(fig19b_panel, "fujimoto2000", "fig19b",
                 "(b) H((F^k)^-1(u)), unit-IST N = 3, k = 2, with the 9 midpoint values") {
    return run19(ctx, 'b');
}
SHITSUKAN_FIGURE(fig19c_panel, "fujimoto2000", "fig19c",
                 "(c) linear interpolation of the samples: H^2(u)") {
    return run19(ctx, 'c');
}
SHITSUKAN_FIGURE(fig19d_panel, "fujimoto2000", "fig19d",
                 "(d) higher-order (Hermite) interpolation of the samples") {
    return run19(ctx, 'd');
}
SHITSUKAN_FIGURE(fig20_sampling, "fujimoto2000", "fig20",
                 "Hierarchical sampling points, unit-IST N = 3, k = 1 and 2") {
    return run20(ctx);
}

}  // namespace shitsukan::fujimoto2000
