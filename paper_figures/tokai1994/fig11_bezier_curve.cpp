// tokai1994 fig. 11: a cubic Bezier curve (eq. 2) with its control polygon, and the
// derivative of eq. (3) drawn as tangents at a few t.
// Example: examples/51_bezier_section.cpp.
#include <cstdio>
#include <vector>

#include "driver/figure.hpp"
#include "shitsukan/geom/bezier_curve.hpp"
#include "shitsukan/image/canvas.hpp"
#include "tokai1994/fig11_19_common.hpp"

using namespace shitsukan;
using namespace shitsukan::figures;

SHITSUKAN_FIGURE(tokai1994_fig11, "tokai1994", "fig11",
                 "Cubic Bezier curve (eq. 2) with its control polygon P0-P3 and eq. (3) tangents") {
    const int w = ctx.quick() ? 320 : 640, h = ctx.quick() ? 240 : 480;
    const float s = float(w) / 640.0f;
    // An S-shaped example (chosen here: the paper's fig. 11 is a generic illustration).
    CubicBezier2 c{{{0.08f, 0.15f}, {0.25f, 0.92f}, {0.72f, 0.95f}, {0.93f, 0.25f}}};
    ctx.given("curve", "P(t) = (1-t)^3 P0 + 3t(1-t)^2 P1 + 3t^2(1-t) P2 + t^3 P3, 0 <= t <= 1",
              "tokai1994 eq. (2)");
    ctx.chosen("control points", "(0.08, 0.15) (0.25, 0.92) (0.72, 0.95) (0.93, 0.25)",
               "an illustration: the paper's fig. 11 prints no coordinates");
    RgbImage img(w, h, Rgb8{255, 255, 255});
    RasterCanvas canvas(img.view());
    Canvas& cv = canvas;
    auto px = [&](Vec2 q) {
        return Vec2{(0.05f + 0.9f * q.x) * float(w), (0.95f - 0.9f * q.y) * float(h)};
    };
    Vec2 poly[4];
    for (int i = 0; i < 4; ++i) poly[i] = px(c.p[i]);
    cv.polyline(poly, 4, Rgb8{150, 150, 150}, 1.5f * s);
    std::vector<Vec2> curve;
    for (int k = 0; k <= 200; ++k) curve.push_back(px(bezier_point(c, float(k) / 200.0f)));
    cv.polyline(curve.data(), int(curve.size()), Rgb8{20, 60, 170}, 3.0f * s);
    for (float t : {0.25f, 0.5f, 0.75f}) {
        Vec2 q = bezier_point(c, t), d = bezier_derivative(c, t);  // eq. (3)
        Vec2 a = px(q), b = px(q + d * 0.12f);
        cv.line(a, b, Rgb8{200, 60, 40}, 2.0f * s);
        cv.marker(a, MarkerShape::dot, 7.0f * s, Rgb8{20, 60, 170});
        cv.text(a + Vec2{6 * s, 6 * s}, fmt("t=%.2f", double(t)), Rgb8{20, 60, 170},
                ctx.quick() ? 1 : 2);
    }
    const char* names[4] = {"P0", "P1", "P2", "P3"};
    for (int i = 0; i < 4; ++i) {
        cv.marker(poly[i], MarkerShape::square, 10.0f * s, Rgb8{0, 0, 0});
        cv.text(poly[i] + Vec2{8 * s, -18 * s}, names[i], Rgb8{0, 0, 0}, ctx.quick() ? 1 : 2);
    }
    cv.text({8 * s, 8 * s}, "blue: eq. (2), grey: control polygon, red: dP/dt of eq. (3) x 0.12",
            Rgb8{60, 60, 60}, 1);
    ctx.note(
        "The curve starts at P0 and ends at P3, tangent there to P0P1 and P2P3 (eq. (3) at "
        "t = 0 and 1 gives 3(P1 - P0) and 3(P3 - P2)); it stays inside the control polygon's "
        "convex hull.");
    return ctx.save_png(img.view());
}
