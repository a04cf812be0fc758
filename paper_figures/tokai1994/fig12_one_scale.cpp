// tokai1994 fig. 12: the relief of one scale. (a) top view: the polygon, its centroid m, the
// r axis from m through a point x to the edge point p, the height as grey; (b) the section
// along that r axis with the eq. (4) normals.
// Example: examples/50_leather_maps.cpp.
#include <cmath>
#include <vector>

#include "driver/figure.hpp"
#include "shitsukan/geom/polygon.hpp"
#include "shitsukan/image/canvas.hpp"
#include "shitsukan/leather/relief.hpp"
#include "shitsukan/core/detmath.hpp"
#include "tokai1994/fig11_19_common.hpp"

using namespace shitsukan;
using namespace shitsukan::figures;

namespace {

// Panel (a): the top view, the height as grey (white = high), the r axes with the x-y part of
// eq. (4), m, x and p. Returns the relief at x (its edge point is p).
ReliefSample draw_top_view(RgbImage& img, Canvas& cv, const Vec2* poly, int n, Vec2 m,
                           const BezierChain& section, const ReliefOptions& opt, int H,
                           int text_scale) {
    const float s = float(H) / 512.0f;
    const float view = 0.92f * float(H);
    auto top = [&](Vec2 q) {
        return Vec2{0.04f * float(H) + q.x * view, 0.96f * float(H) - q.y * view};
    };
    {
        RgbView panel = img.view().subview(0, 0, H, H);
        float top_h = 0.13f * scale_size(poly, n);
        for (int j = 0; j < panel.height; ++j)
            for (int i = 0; i < panel.width; ++i) {
                Vec2 q{(float(i) + 0.5f - 0.04f * float(H)) / view,
                       (0.96f * float(H) - float(j) - 0.5f) / view};
                ReliefSample r;
                EdgeHit hit = scale_edge_point(poly, n, m, q);
                if (!hit.inside) continue;
                scale_relief(poly, n, m, q, section, opt, &r);
                float g = clamp(r.height / top_h, 0.0f, 1.0f);
                panel.at(i, j) = Rgb8{to_byte(0.35f + 0.6f * g), to_byte(0.33f + 0.6f * g),
                                      to_byte(0.3f + 0.6f * g)};
            }
    }
    std::vector<Vec2> outline;
    for (int i = 0; i < n; ++i) outline.push_back(top(poly[i]));
    cv.polygon_outline(outline.data(), n, Rgb8{0, 0, 0}, 2.0f * s);
    Vec2 x = m + normalize(Vec2{0.9f, 0.35f}) * 0.22f;
    ReliefSample at_x;
    scale_relief(poly, n, m, x, section, opt, &at_x);
    Vec2 p = at_x.edge_point;
    for (int k = 0; k < 16; ++k) {  // more r axes, with the x-y part of eq. (4) on the slope
        float a = kTwoPi * (float(k) + 0.5f) / 16.0f;
        Vec2 dir{det_cos(a), det_sin(a)};
        EdgeHit hit = scale_edge_point(poly, n, m, m + dir * 0.01f);
        cv.line(top(m), top(hit.p), Rgb8{170, 170, 170}, 1.0f * s);
        Vec2 q = m + (hit.p - m) * 0.86f;
        ReliefSample r;
        scale_relief(poly, n, m, q, section, opt, &r);
        Vec2 tip = top(q) + Vec2{r.normal.x, -r.normal.y} * (70.0f * s);
        cv.line(top(q), tip, Rgb8{20, 90, 200}, 2.0f * s);
        cv.marker(top(q), MarkerShape::dot, 5 * s, Rgb8{20, 90, 200});
    }
    cv.line(top(m), top(p), Rgb8{200, 40, 30}, 2.5f * s);
    cv.marker(top(m), MarkerShape::dot, 10 * s, Rgb8{0, 0, 0});
    cv.text(top(m) + Vec2{-14 * s, 6 * s}, "m", Rgb8{0, 0, 0}, text_scale);
    cv.marker(top(x), MarkerShape::dot, 8 * s, Rgb8{200, 40, 30});
    cv.text(top(x) + Vec2{-4 * s, -22 * s}, "x", Rgb8{200, 40, 30}, text_scale);
    cv.marker(top(p), MarkerShape::dot, 10 * s, Rgb8{200, 40, 30});
    cv.text(top(p) + Vec2{8 * s, -8 * s}, "p", Rgb8{200, 40, 30}, text_scale);
    cv.text(top((m + p) * 0.5f) + Vec2{0, 10 * s}, "r axis", Rgb8{200, 40, 30}, text_scale);
    cv.text({8 * s, 6 * s},
            "(a) top view, grey = height; blue: (n_x, n_y) of eq. (4) at rho = 0.86, x70",
            Rgb8{0, 0, 0}, 1);

    return at_x;
}

// Panel (b): the section along the r axis, r = rho (0 at m, 1 at p), z in the same units,
// with its control polygon and the eq. (4) normals.
void draw_section_view(Canvas& cv, const BezierChain& section, int H, int text_scale) {
    const float s = float(H) / 512.0f;
    tokai_relief::PlotFrame f{float(H) + 0.10f * float(H), 0.62f * float(H), 0.82f * float(H)};
    cv.fill_rect({float(H), 0}, {float(H), float(H)}, Rgb8{255, 255, 255});
    tokai_relief::draw_axes(cv, f, {0.0f, 0.0f}, {1.05f, 0.45f}, 0.2f, "r", "z");
    std::vector<Vec2> curve;
    for (int k = 0; k <= 300; ++k) {
        float rho = float(k) / 300.0f;
        curve.push_back(f.to_pixel({rho, section_at_r(section, rho).z}));
    }
    cv.polyline(curve.data(), int(curve.size()), Rgb8{20, 60, 170}, 3.0f * s);
    Vec2 ctrl[4];
    for (int i = 0; i < 4; ++i) ctrl[i] = f.to_pixel(section.segments[0].p[i]);
    cv.polyline(ctrl, 4, Rgb8{160, 160, 160}, 1.0f * s);
    for (int i = 0; i < 4; ++i) cv.marker(ctrl[i], MarkerShape::square, 8 * s, Rgb8{90, 90, 90});
    for (int k = 1; k <= 11; ++k) {  // eq. (4) normals in the (r, z) plane
        float rho = float(k) / 12.0f * 0.92f;
        SectionSample q = section_at_r(section, rho);
        Vec2 nrm = normalize(Vec2{-q.dz, q.dr});  // (n_r, n_z) ∝ (1, -dr/dz)
        Vec2 a = f.to_pixel({q.r, q.z});
        cv.line(a, a + Vec2{nrm.x, -nrm.y} * (50.0f * s), Rgb8{20, 90, 200}, 1.5f * s);
    }
    cv.line(f.to_pixel({1.0f, 0.0f}), f.to_pixel({1.0f, 0.3f}), Rgb8{200, 40, 30}, 1.5f * s);
    cv.text(f.to_pixel({1.0f, 0.3f}) + Vec2{-8 * s, -22 * s}, "p", Rgb8{200, 40, 30}, text_scale);
    cv.text(f.to_pixel({0.0f, 0.0f}) + Vec2{4 * s, 24 * s}, "m", Rgb8{0, 0, 0}, text_scale);
    cv.text(f.to_pixel({0.86f, 0.0f}) + Vec2{-60 * s, 40 * s}, "groove floor", Rgb8{120, 120, 120},
            1);
    cv.text({float(H) + 8 * s, 6 * s}, "(b) section z(r) of Table 1 (fig. 13a), normals of eq. (4)",
            Rgb8{0, 0, 0}, 1);
}

}  // namespace

SHITSUKAN_FIGURE(tokai1994_fig12, "tokai1994", "fig12",
                 "One scale: centroid m, edge point p, the r axis, the section and its normals") {
    const int H = ctx.quick() ? 256 : 512, W = 2 * H;
    const int text_scale = ctx.quick() ? 1 : 2;
    // An irregular, slightly non-convex scale (chosen here), in pattern units.
    const Vec2 poly[7] = {{0.10f, 0.18f}, {0.55f, 0.08f}, {0.88f, 0.30f}, {0.84f, 0.62f},
                          {0.90f, 0.85f}, {0.40f, 0.92f}, {0.12f, 0.60f}};
    const int n = 7;
    const Vec2 m = to_float(polygon_centroid(poly, n));  // fig. 12's m: the area centroid
    const BezierChain section = table1_section(Table1Section::convex);
    const ReliefOptions opt;
    ctx.given("section", "fig. 13(a): (0.0, 0.1) (0.51, 0.1) (0.75, 0.13) (0.92, 0.0)", "Table 1");
    ctx.given("normal", "n = (p_x - m_x, p_y - m_y, -dr·n_r/dz)", "tokai1994 eq. (4)");
    ctx.chosen("polygon", "an irregular 7-gon, star-shaped from m", "illustration");
    ctx.chosen("edge_r", "1 (r = |x - m| / |p - m|; the section ends at 0.92: groove floor)",
               "README reading of Table 1");
    ctx.chosen("height unit", "S = 2·area/perimeter of the polygon",
               "flat sections give flat tops (relief.hpp)");
    RgbImage img(W, H, Rgb8{255, 255, 255});
    RasterCanvas canvas(img.view());
    Canvas& cv = canvas;

    const ReliefSample at_x = draw_top_view(img, cv, poly, n, m, section, opt, H, text_scale);
    const Vec2 p = at_x.edge_point;
    draw_section_view(cv, section, H, text_scale);
    ctx.note(
        fmt("The ray from m through x meets the edge at p = (%.3f, %.3f); x lies at "
            "rho = %.3f of the way, height %.4f. Past r = 0.92 the section has ended: the "
            "flat floor of the groove up to p (r = 1).",
            double(p.x), double(p.y), double(at_x.rho), double(at_x.height)));
    return ctx.save_png(img.view());
}
