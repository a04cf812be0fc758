// hirota1998 fig. 3 (the two-layer model on a cylinder) and fig. 4 (how a broken spring is drawn
// as a crack).
// Example: examples/60_two_layer_bark.cpp.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "hirota1998/bark_common.hpp"
#include "shitsukan/image/image.hpp"
#include "shitsukan/image/raster_canvas.hpp"
#include "shitsukan/raster/camera.hpp"
#include "shitsukan/core/detmath.hpp"

using namespace shitsukan;
using namespace shitsukan::figures;
using namespace shitsukan::figures::bark;

namespace {

struct Segment {
    Vec3 a, b;  // world
    Rgb8 color;
    float width;
    float depth = 0;  // of the midpoint, for the painter's order
};

Rgb8 mix(Rgb8 a, Rgb8 b, float t) {
    auto ch = [t](std::uint8_t x, std::uint8_t y) {
        return std::uint8_t(std::lround(float(x) + (float(y) - float(x)) * t));
    };
    return {ch(a.r, b.r), ch(a.g, b.g), ch(a.b, b.b)};
}

}  // namespace

SHITSUKAN_FIGURE(hirota_fig03, "hirota1998", "fig03",
                 "The two-layer model: surface and inner layer, springs and shear springs") {
    CylinderParams p;
    p.N_R = 36, p.N_H = 10;  // chosen here: reduced so every spring can be seen
    BarkCylinder bark;
    SHITSUKAN_TRY(build_cylinder(p, bark));
    ctx.chosen("N_R x N_H", "36 x 10", "a reduced cylinder: every node and spring visible");
    ctx.given("R0", fmt("sqrt(3) L0 N_R / (4 pi) = %.3f cm", double(bark.R0)), "Table 1");
    ctx.given("H0", fmt("L0 N_H = %.2f cm", double(bark.H0)), "Table 1");
    ctx.given("L0", "0.33 cm", "Table 2");
    ctx.chosen("D", fmt("%.2f cm (inner layer at R0 - D = %.3f cm, true scale)", double(p.D),
                        double(bark.R0 - p.D)),
               "the layer thickness of the fig05 runs");
    ctx.chosen("cut", "the surface layer removed over a 90 degree wedge at the front left; only the "
                      "half facing the viewer drawn (hidden lines)",
               "so the inner layer and the shear springs show");
    const int size = ctx.quick() ? 384 : 768;
    const float R0 = bark.R0, Ri = bark.R0 - p.D, H0 = bark.H0;
    auto world = [&](std::uint32_t node, float radius) {
        const Vec3 x = bark.net.X[node];
        const float angle = x.x / R0;
        return Vec3{radius * det_sin(angle), x.y, radius * det_cos(angle)};
    };
    auto angle_of = [&](std::uint32_t node) {
        float angle = bark.net.X[node].x / R0;
        return angle > kPi ? angle - kTwoPi : angle;  // (-pi, pi], 0 faces the viewer (+z)
    };
    auto in_wedge = [&](std::uint32_t node) {  // the 90 degree wedge at the front left
        const float a = angle_of(node);
        return a > -0.55f * kPi && a < -0.05f * kPi;
    };
    auto front = [&](std::uint32_t node) {  // hidden-line rule: the half facing the viewer
        return det_cos(angle_of(node)) > -0.05f;
    };
    const Rgb8 axial{40, 90, 200}, diagonal{200, 50, 40}, shear{30, 150, 60}, inner{120, 120, 120};
    std::vector<Segment> segs;
    for (const BarkSpring& s : bark.net.springs) {
        if (!front(s.i) || !front(s.j)) continue;
        segs.push_back({world(s.i, Ri), world(s.j, Ri), inner, 1.0f});  // the inner layer
        if (in_wedge(s.i) || in_wedge(s.j)) continue;
        segs.push_back({world(s.i, R0), world(s.j, R0), s.family == 1 ? axial : diagonal, 1.6f});
    }
    for (int q = 0; q < bark.net.node_count(); ++q)
        if (!in_wedge(std::uint32_t(q)) && front(std::uint32_t(q)))
            segs.push_back({world(std::uint32_t(q), R0), world(std::uint32_t(q), Ri), shear, 1.4f});
    Camera cam = perspective_camera({0.0f, H0 * 0.5f + 4.0f, 9.5f}, {0.0f, H0 * 0.45f, 0.0f},
                                    {0, 1, 0}, 30.0f, size, size);
    float dmin = 1e30f, dmax = -1e30f;
    for (Segment& s : segs) {
        s.depth = project(cam, (s.a + s.b) * 0.5f).z;
        dmin = std::min(dmin, s.depth), dmax = std::max(dmax, s.depth);
    }
    std::stable_sort(segs.begin(), segs.end(),
                     [](const Segment& a, const Segment& b) { return a.depth > b.depth; });
    const Rgb8 paper{252, 252, 250};
    RgbImage img(size, size, paper);
    RasterCanvas c(img.view());
    const float k = float(size) / 768.0f;
    for (const Segment& s : segs) {
        // Depth cue (chosen here): the far side fades toward the paper.
        const float fade = 0.6f * (s.depth - dmin) / (dmax - dmin);
        const Vec3 a = project(cam, s.a), b = project(cam, s.b);
        c.line({a.x, a.y}, {b.x, b.y}, mix(s.color, paper, fade), s.width * k);
    }
    const int ts = ctx.quick() ? 1 : 2;
    c.text({10, 10}, "two-layer model (Fig. 3)", Rgb8{20, 20, 20}, ts);
    const char* legend[4] = {"surface springs, family 1 (axial)", "surface springs, family 2 (diagonal)",
                             "shear springs (surface - inner)", "inner layer (moved by growth)"};
    const Rgb8 colors[4] = {axial, diagonal, shear, inner};
    for (int i = 0; i < 4; ++i) {
        const float y = float(size) - (4.5f - float(i)) * 11.0f * float(ts);
        c.fill_rect({10, y + 2}, {14.0f * float(ts), 4.0f * float(ts)}, colors[i]);
        c.text({14.0f + 16.0f * float(ts), y}, legend[i], Rgb8{30, 30, 30}, ts > 1 ? 1 : 1);
    }
    c.text({10, 10 + 12.0f * float(ts)},
           fmt("N_R = %d, N_H = %d, L0 = 0.33 cm, R0 = sqrt(3) L0 N_R / 4pi = %.2f cm, H0 = "
               "%.2f cm",
               p.N_R, p.N_H, double(R0), double(H0)),
           Rgb8{30, 30, 30}, 1);
    // Checks: counts, the circumference, every spring L0 long.
    float worst = 0;
    for (const BarkSpring& s : bark.net.springs) {
        Vec3 d = bark.net.X[s.j] - bark.net.X[s.i];
        if (d.x < -0.5f * bark.circumference) d.x += bark.circumference;
        worst = std::max(worst, std::fabs(length(d) - 0.33f));
    }
    ctx.note(fmt("Per layer %d nodes and %d springs (N_R (3 N_H - 2) = %d); circumference / N_R "
                 "= %.6f cm = (sqrt(3)/2) L0 = %.6f; every in-layer spring L0 long (largest "
                 "deviation %.1e cm). No spring is horizontal: the lattice lines run along the "
                 "trunk, which is what Table 1's R0 formula says.",
                 bark.net.node_count(), bark.net.spring_count(), p.N_R * (3 * p.N_H - 2),
                 double(bark.circumference / float(p.N_R)), 0.866025403784 * 0.33, double(worst)));
    return ctx.save_png(img.view());
}

namespace {

// The widest broken diagonal away from the free edges that separates two large regions (a
// crack between two strips, not a crumb); quick mode's small cylinder may have no such pair:
// then any broken diagonal will do. Returns false when there is none.
bool widest_vertical_crack(const SpeciesRun& run, std::uint32_t* pick) {
    const BarkCylinder& bark = run.bark;
    const RegionReport& regions = run.regions;
    auto big = [&](std::uint32_t node) {
        const std::int32_t l = regions.label[node];
        return l >= 0 && regions.regions[std::size_t(l)].nodes >= 40;
    };
    float widest = -1;
    for (int pass = 0; pass < 2 && widest < 0; ++pass)
        for (const BreakEvent& e : run.run.breaks) {
            const BarkSpring& s = bark.net.springs[e.spring];
            const int r = bark.row_of(int(s.i));
            if (s.family != 2 || r < 3 || r > run.params.N_H - 4) continue;
            if (pass == 0 &&
                (!big(s.i) || !big(s.j) || regions.label[s.i] == regions.label[s.j]))
                continue;
            const float w = crack_ribbon(bark, e.spring, run.params.T, bark.net.W.data()).width;
            if (w > widest) widest = w, *pick = e.spring;
        }
    return widest >= 0;
}

// Fig. 4's window: 7 x 6 cells around the focus crack, in pixels.
struct CrackWindow {
    CrackRibbon focus;
    float C = 0, scale = 0, half_w = 0, half_h = 0;
    int side_w = 0, side_h = 0;
    Vec2 centre_px;
    Vec3 near(Vec3 x) const {  // the periodic copy next to the focus
        while (x.x - focus.midpoint.x > 0.5f * C) x.x -= C;
        while (focus.midpoint.x - x.x > 0.5f * C) x.x += C;
        return x;
    }
    Vec2 px(Vec3 x) const {
        x = near(x);
        return Vec2{centre_px.x + (x.x - focus.midpoint.x) * scale,
                    centre_px.y - (x.y - focus.midpoint.y) * scale};
    }
    bool inside(Vec3 x) const {
        x = near(x);
        return std::fabs(x.x - focus.midpoint.x) < half_w + 0.4f &&
               std::fabs(x.y - focus.midpoint.y) < half_h + 0.4f;
    }
};

// Plates (the lattice triangles at T), cracks (ribbons), springs (broken ones dashed red) and
// nodes inside the window.
Status draw_crack_window(RasterCanvas& c, const BarkCylinder& bark, float T, const Vec3* W,
                         const CrackWindow& win) {
    for (const ConnectionTriangle& tri : bark.triangles) {
        Vec3 x[3];
        bool any = false;
        for (int k = 0; k < 3; ++k) {
            x[k] = corner_position(bark, tri.corner[k], tri.node[k], T, W);
            any = any || win.inside(x[k]);
        }
        if (!any) continue;
        // Keep a seam triangle together: move every corner by the first one's period shift.
        const Vec3 shift = win.near(x[0]) - x[0];
        const Vec2 pts[3] = {win.px(x[0] + shift), win.px(x[1] + shift), win.px(x[2] + shift)};
        c.fill_polygon(pts, 3, Rgb8{205, 186, 160});
    }
    std::vector<CrackRibbon> cracks;
    SHITSUKAN_TRY(crack_ribbons(bark, T, W, cracks));
    for (const CrackRibbon& r : cracks) {
        if (!win.inside(r.midpoint)) continue;
        Vec3 q[2][4];
        ribbon_quads(r, q);
        const Vec3 shift = win.near(r.midpoint) - r.midpoint;
        for (auto& quad : q) {
            const Vec2 pts[4] = {win.px(quad[0] + shift), win.px(quad[1] + shift),
                                 win.px(quad[2] + shift), win.px(quad[3] + shift)};
            c.fill_polygon(pts, 4, kCrack);
        }
    }
    for (std::size_t s = 0; s < bark.net.springs.size(); ++s) {
        const BarkSpring& sp = bark.net.springs[s];
        const CrackRibbon r = crack_ribbon(bark, std::uint32_t(s), T, W);
        if (!win.inside(r.midpoint)) continue;
        const Vec3 shift = win.near(r.midpoint) - r.midpoint;
        const Vec2 a = win.px(r.node[0] + shift), b = win.px(r.node[1] + shift);
        if (intact_at(sp, T)) {
            c.line(a, b, Rgb8{120, 110, 100}, 1.0f);
        } else {  // dashed red
            const int dashes = 9;
            for (int d = 0; d < dashes; d += 2)
                c.line(a + (b - a) * (float(d) / dashes), a + (b - a) * (float(d + 1) / dashes),
                       Rgb8{220, 40, 30}, 2.0f);
        }
    }
    for (int q = 0; q < bark.net.node_count(); ++q) {
        const Vec3 x = node_position(bark, std::uint32_t(q), T, W);
        if (win.inside(x)) c.marker(win.px(x), MarkerShape::dot, 6.0f, Rgb8{40, 40, 40});
    }
    return Status::success();
}

// The window's frame (the margins and the text band blanked), the focus spring annotated, and
// l, l0 and w printed below.
void annotate_crack_window(RasterCanvas& c, const CrackWindow& win) {
    const Rgb8 paper{252, 252, 250};
    const float wx0 = win.centre_px.x - win.half_w * win.scale,
                wx1 = win.centre_px.x + win.half_w * win.scale;
    const float wy0 = win.centre_px.y - win.half_h * win.scale,
                wy1 = win.centre_px.y + win.half_h * win.scale;
    c.fill_rect({0, 0}, {float(win.side_w), wy0}, paper);
    c.fill_rect({0, wy1}, {float(win.side_w), float(win.side_h) - wy1}, paper);
    c.fill_rect({0, 0}, {wx0, float(win.side_h)}, paper);
    c.fill_rect({wx1, 0}, {float(win.side_w) - wx1, float(win.side_h)}, paper);
    c.rect_outline({wx0, wy0}, {wx1 - wx0, wy1 - wy0}, Rgb8{60, 60, 60}, 1.0f);
    c.text({wx0, 8}, "camphor at t = T: 7 x 6 cells around a vertical crack", Rgb8{20, 20, 20}, 2);
    const CrackRibbon& focus = win.focus;
    const Vec2 a = win.px(focus.node[0]), b = win.px(focus.node[1]), m = win.px(focus.midpoint);
    c.marker(a, MarkerShape::circle, 16.0f, Rgb8{220, 40, 30});
    c.marker(b, MarkerShape::circle, 16.0f, Rgb8{220, 40, 30});
    c.line(m, m + Vec2{60, -70}, Rgb8{20, 20, 20}, 1.2f);
    c.text(m + Vec2{64, -84}, "crack: centred on the spring's middle", Rgb8{20, 20, 20}, 1);
    const float ty = wy1 + 12;
    c.text({12, ty}, fmt("l  = %.4f cm  (node distance at T)", double(focus.l)), Rgb8{20, 20, 20}, 2);
    c.text({12, ty + 18}, fmt("l0 = %.4f cm  (natural length)", double(focus.l0)), Rgb8{20, 20, 20},
           2);
    c.text({12, ty + 36}, fmt("w  = l - l0 = %.4f cm = %.1f px", double(focus.width),
                              double(focus.width * win.scale)),
           Rgb8{20, 20, 20}, 2);
}

}  // namespace

SHITSUKAN_FIGURE(hirota_fig04, "hirota1998", "fig04",
                 "How a crack is drawn: at the middle of the broken spring, width l - l0") {
    const SpeciesRun* run;
    SHITSUKAN_TRY(species_run(Species::camphor, ctx.quick(), &run));
    const BarkCylinder& bark = run->bark;
    const float T = run->params.T;
    const Vec3* W = bark.net.W.data();
    ctx.given("crack", "at the middle of the connection, width = l - l0", "§3.1, Fig. 4");
    ctx.chosen("window", "7 x 6 cells of the camphor run at t = T around the widest crack of a "
                         "vertical crack (a broken diagonal)",
               "the paper's Fig. 4 is a sketch; this one is measured");
    std::uint32_t pick = 0;
    if (!widest_vertical_crack(*run, &pick))
        return Status::error(StatusCode::not_supported, "fig04: no broken diagonal to show");
    CrackWindow win;
    win.focus = crack_ribbon(bark, pick, T, W);
    win.C = bark.circumference * (1.0f + hoop_strain(run->params, T));
    win.scale = ctx.quick() ? 200.0f : 400.0f;  // px per cm (chosen here)
    win.half_w = 3.5f * bark.a_h, win.half_h = 3.0f * 0.33f;
    const int margin = int(win.scale * 0.25f);
    win.side_w = int(2 * win.half_w * win.scale) + 2 * margin;
    win.side_h = int(2 * win.half_h * win.scale) + margin + 80;
    win.centre_px = Vec2{float(win.side_w) * 0.5f, float(margin) + win.half_h * win.scale};
    RgbImage img(win.side_w, win.side_h, Rgb8{252, 252, 250});
    RasterCanvas c(img.view());
    SHITSUKAN_TRY(draw_crack_window(c, bark, T, W, win));
    annotate_crack_window(c, win);
    const CrackRibbon& focus = win.focus;
    Vec3 q[2][4];
    ribbon_quads(focus, q);
    ctx.note(fmt("The widest crack of a vertical camphor crack at T: l = %.4f cm, l0 = %.4f cm, "
                 "drawn width %.6f cm (l - l0 = %.6f cm), centre offset from the spring's "
                 "midpoint %.1e cm. Dashed red: broken springs; grey: intact springs; dark: the "
                 "cracks, each along the face the spring represents (centroid - midpoint - "
                 "centroid), so neighbouring cracks meet. %.0f px per cm.",
                 double(focus.l), double(focus.l0), double(length(q[0][2] - q[0][1])),
                 double(focus.l - focus.l0),
                 double(length(focus.midpoint - (focus.node[0] + focus.node[1]) * 0.5f)),
                 double(win.scale)));
    return ctx.save_png(img.view());
}
