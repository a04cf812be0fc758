// hirota1998 figs. 6-8: the four-layer model (a radial section), the layers' radii over time,
// and the bark growing over several cycles (cracking, lifting, peeling, new layers). One run of
// the four-layer model feeds all three (memoised).
// Example: none of its own; examples/60_two_layer_bark.cpp teaches the two-layer model the four
//   layers extend.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "hirota1998/bark_common.hpp"
#include "hirota1998/layer_frame_draw.hpp"
#include "shitsukan/image/image.hpp"
#include "shitsukan/image/plot.hpp"
#include "shitsukan/image/raster_canvas.hpp"

using namespace shitsukan;
using namespace shitsukan::figures;
using namespace shitsukan::figures::bark;

namespace {

// Frames: t/T = base + these (base = the spin-up cycles), and fig. 6's mid-cycle section.
const float kFrameOffsets[8] = {0.6f, 0.8f, 1.0f, 1.0f, 1.6f, 1.8f, 2.0f, 2.5f};
const bool kFrameBefore[8] = {false, false, true, false, false, false, true, false};
const char* kFrameLabel[8] = {"", "", "-", "+", "", "", "-", ""};
constexpr float kSectionOffset = 1.5f;

struct LayeredRun {
    LayeredParams params;
    LayeredBark bark;
    double seconds = 0;
};

LayeredParams layered_params(bool quick) {
    LayeredParams p;
    if (quick) p.N_R = 24, p.N_H = 16, p.cycles = 4, p.spin_up_cycles = 1;  // chosen here
    return p;
}

Status layered_run(bool quick, const LayeredRun** out, FigureContext* ctx = nullptr) {
    return memoised<LayeredRun>(quick ? 1 : 0, [&](LayeredRun& r) {
        r.params = layered_params(quick);
        const float T = r.params.schedule.T, base = float(r.params.spin_up_cycles);
        std::vector<FrameRequest> frames;
        for (int i = 0; i < 8; ++i) {
            frames.push_back({(base + kFrameOffsets[i]) * T, kFrameBefore[i]});
            if (i == 3) frames.push_back({(base + kSectionOffset) * T, false});  // fig. 6
        }
        // Progress on stderr (through the driver) at every fifth of the run.
        struct Progress {
            FigureContext* ctx;
            int last = -1;
        } prog{ctx};
        auto report = [](float fraction, void* user) {
            auto* pr = static_cast<Progress*>(user);
            const int fifth = int(fraction * 5.0f);
            if (pr->ctx && fifth != pr->last) {
                pr->last = fifth;
                pr->ctx->progress("four-layer run: %3.0f %%", double(fraction) * 100.0);
            }
        };
        const auto t0 = std::chrono::steady_clock::now();
        SHITSUKAN_TRY(r.bark.build(r.params));
        SHITSUKAN_TRY(r.bark.run(frames.data(), int(frames.size()), report, &prog));
        r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        return Status::success();
    }, out);
}

const LayerFrame& frame_at(const LayeredBark& bark, float t, bool before) {
    for (const LayerFrame& f : bark.frames())
        if (std::fabs(f.t - t) < 1e-3f * bark.params().schedule.T && f.before_role_change == before)
            return f;
    return bark.frames().front();
}

void record_layered(FigureContext& ctx, const LayeredParams& p) {
    const LayerSchedule& s = p.schedule;
    ctx.given("layers", "surface (cracks, peels), middle (1) (exposed by peeling), middle (2) "
                        "(new cork, thickens), inner",
              "§4.1, Fig. 6");
    ctx.given("cycle", "middle (2) grows to middle (1)'s thickness in T; then the roles shift "
                       "outward",
              "§4.1, Fig. 7");
    ctx.given("Table 4 names", "kappa_h, eta, gamma, A", "Table 4 (no values printed)");
    ctx.chosen("species", "pine (Table 2)", "Table 3 *3: pine bark peels");
    ctx.chosen("patch", fmt("%d x %d nodes, periodic around, free top and bottom", p.N_R, p.N_H),
               "a patch of a large trunk: the cork's push (delta_R + D per cycle) is ~2 %/cycle "
               "on R_in0 = 30 cm, near kappa - 1");
    ctx.chosen("R_in0, D, delta_R, T", fmt("%.0f cm, %.2f cm, %.2f cm per cycle, %.0f s",
                                           double(s.R_in0), double(s.D), double(s.delta_R),
                                           double(s.T)),
               "Table 3 *3: larger trees make larger plates; the new cork dominates the push");
    ctx.chosen("axial growth", fmt("%.3f per cycle", double(p.axial_growth)),
               "a layer two cycles old reaches 5 % > kappa1 - 1 = 3.8 %: plates, not strips");
    ctx.chosen("kappa_h", fmt("%.2f (spread sigma %.4f)", double(p.peeling.kappa_h), double(p.sigma)),
               "interface shear strains: ~0.002 before cracking, mean 0.02, max 0.05 after: "
               "only dried places lift");
    ctx.chosen("eta", fmt("%.2f cm (one cell)", double(p.peeling.eta)),
               "the drying front advances about a cell per decay time");
    ctx.chosen("gamma", fmt("%.2f per dt_ref = T/%d", double(p.peeling.gamma), p.peeling.dt_ref_steps),
               "kappa_h falls to 0.22 of itself per cycle in the drying zone");
    ctx.chosen("A", fmt("%.1f (region / bonded area; = detached fraction %.2f)", double(p.peeling.A),
                        double(1.0f - 1.0f / p.peeling.A)),
               "a plate falls once half of it has lifted");
    ctx.chosen("driver", fmt("%d cycles (%d spin-up), %d steps per cycle, tolerance %.0e",
                             p.cycles, p.spin_up_cycles, p.steps_per_cycle, double(p.tolerance)),
               "drying and area rules need steps; both layers are born stress-free at t = 0, so "
               "the first cycles are transitional");
}

}  // namespace

SHITSUKAN_FIGURE(hirota_fig07, "hirota1998", "fig07",
                 "Temporal change of the layers: node radii over several cycles") {
    const LayeredRun* run;
    SHITSUKAN_TRY(layered_run(ctx.quick(), &run));
    const LayeredParams& p = run->params;
    record_layered(ctx, p);
    const LayerSchedule& s = p.schedule;
    const int W = ctx.quick() ? 640 : 960, H = ctx.quick() ? 400 : 560;
    RgbImage img(W, H, Rgb8{255, 255, 255});
    RasterCanvas c(img.view());
    const float cycles = float(p.cycles);
    const double y_hi = double(s.delta_R * cycles + 2.5f * s.D + s.D * 0.5f);
    PlotMargins margins;
    margins.right = 200;
    Axes axes = axes_in(c, 0.0, double(cycles), -double(s.D) * 0.9, y_hi, margins);
    // Spin-up cycles shaded.
    const Vec2 a0 = axes.to_pixel(0.0, axes.y_hi), a1 = axes.to_pixel(double(p.spin_up_cycles), axes.y_lo);
    c.fill_rect(a0, a1 - a0, Rgb8{238, 238, 238});
    SHITSUKAN_TRY(draw_axes(c, axes, {"Fig. 7: node radius - R_in0 over time", "t / T", "cm"}));
    // Layer bands and node tracks from the one schedule function, sampled per cycle so the
    // jumps at role changes are not joined.
    struct Track {
        const char* name;
        Rgb8 color;
        float LayerRadii::*radius;
    };
    const Track tracks[4] = {{"inner", Rgb8{110, 110, 110}, &LayerRadii::inner},
                             {"middle (2)", Rgb8{200, 160, 40}, &LayerRadii::middle2},
                             {"middle (1)", Rgb8{200, 90, 30}, &LayerRadii::middle1},
                             {"surface", Rgb8{90, 60, 40}, &LayerRadii::surface}};
    double worst_jump = 0;
    for (int k = 0; k < p.cycles; ++k) {
        const int samples = 64;
        for (const Track& tr : tracks) {
            std::vector<double> xs, ys;
            for (int i = 0; i <= samples; ++i) {
                const float t = s.T * (float(k) + float(i) / samples);
                const LayerRadii r = layer_radii(s, t, i == samples);
                xs.push_back(double(t / s.T));
                ys.push_back(double(r.*(tr.radius) - s.R_in0));
            }
            SHITSUKAN_TRY(plot_series(c, axes, xs.data(), ys.data(), int(xs.size()), tr.color, 2.0f));
        }
        if (k + 1 < p.cycles) {
            const float t = s.T * float(k + 1);
            const LayerRadii before = layer_radii(s, t, true), after = layer_radii(s, t);
            // Continuity of the roles: middle (1) -> surface, middle (2) -> middle (1).
            worst_jump = std::max({worst_jump, double(std::fabs(before.middle1 - after.surface)),
                                   double(std::fabs(before.middle2 - after.middle1))});
            const Vec2 top = axes.to_pixel(double(k + 1), axes.y_hi), bot = axes.to_pixel(double(k + 1), axes.y_lo);
            for (float y = top.y; y < bot.y; y += 8) c.line({top.x, y}, {top.x, std::min(y + 4, bot.y)}, Rgb8{120, 120, 160}, 1.0f);
            // Arrows: each track's end continues as the next role; the old surface falls off (x).
            const Vec2 e2 = axes.to_pixel(double(k + 1), double(before.middle2 - s.R_in0));
            const Vec2 e1 = axes.to_pixel(double(k + 1), double(before.middle1 - s.R_in0));
            const Vec2 es = axes.to_pixel(double(k + 1), double(before.surface - s.R_in0));
            c.marker(es, MarkerShape::cross, 9.0f, Rgb8{200, 0, 0});
            c.marker(e2, MarkerShape::circle, 7.0f, Rgb8{200, 160, 40});
            c.marker(e1, MarkerShape::circle, 7.0f, Rgb8{200, 90, 30});
        }
    }
    // ΔR (§4.1: the growth of the inner layer's radius during T), marked on every cycle: the
    // inner radius at the cycle's start carried across (dotted), the rise to its end bracketed.
    for (int k = 0; k < p.cycles; ++k) {
        const double r0 = double(layer_radii(s, s.T * float(k)).inner - s.R_in0);
        const double r1 = double(layer_radii(s, s.T * float(k + 1), true).inner - s.R_in0);
        const Vec2 from = axes.to_pixel(double(k), r0), to = axes.to_pixel(double(k + 1), r0);
        for (float x = from.x; x < to.x; x += 6) c.line({x, from.y}, {std::min(x + 2, to.x), from.y}, Rgb8{60, 60, 60}, 1.0f);
        const Vec2 top = axes.to_pixel(double(k + 1) - 0.04, r1), bot = axes.to_pixel(double(k + 1) - 0.04, r0);
        c.line(top, bot, Rgb8{20, 20, 20}, 1.5f);
        c.line({top.x - 3, top.y}, {top.x + 3, top.y}, Rgb8{20, 20, 20}, 1.5f);
        c.line({bot.x - 3, bot.y}, {bot.x + 3, bot.y}, Rgb8{20, 20, 20}, 1.5f);
        c.text({top.x - 20, 0.5f * (top.y + bot.y) + 4}, "ΔR", Rgb8{20, 20, 20}, 1);
    }
    for (int i = 0; i < 4; ++i) {
        const float y = axes.corner.y + 12.0f + 16.0f * float(i);
        const float x = axes.corner.x + axes.size.x + 12.0f;
        c.line({x, y + 4}, {x + 20, y + 4}, tracks[3 - i].color, 2.0f);
        c.text({x + 26, y}, tracks[3 - i].name, Rgb8{20, 20, 20}, 1);
    }
    c.text({axes.corner.x + axes.size.x + 12.0f, axes.corner.y + 84.0f}, "x: old surface falls off",
           Rgb8{200, 0, 0}, 1);
    c.text({axes.corner.x + axes.size.x + 12.0f, axes.corner.y + 100.0f}, "o: continues outward",
           Rgb8{20, 20, 20}, 1);
    c.text({axes.corner.x + axes.size.x + 12.0f, axes.corner.y + 116.0f}, "grey: spin-up",
           Rgb8{20, 20, 20}, 1);
    c.text({axes.corner.x + axes.size.x + 12.0f, axes.corner.y + 132.0f},
           fmt("ΔR = %.3f cm: the inner", double(s.delta_R)), Rgb8{20, 20, 20}, 1);
    c.text({axes.corner.x + axes.size.x + 12.0f, axes.corner.y + 144.0f},
           "layer's radius growth", Rgb8{20, 20, 20}, 1);
    c.text({axes.corner.x + axes.size.x + 12.0f, axes.corner.y + 156.0f},
           "during T (sec. 4.1)", Rgb8{20, 20, 20}, 1);
    const LayerRadii mid = layer_radii(s, s.T * 0.5f), end = layer_radii(s, s.T, true);
    const LayerRadii r1 = layer_radii(s, s.T * 1.5f);
    ctx.note(fmt("From the one schedule function the simulation uses (layer_schedule.hpp). "
                 "Continuity at every role change: largest jump %.1e cm. Middle (2) is %.4f cm "
                 "thick at mid-cycle and %.4f cm = D at the end of the cycle (the cycle's "
                 "definition, §4.1). Per cycle a layer moves out by %.3f cm (delta_R + D: middle "
                 "(1) at mid-cycle is the surface one cycle later), middle (2)'s node rises by "
                 "%.3f cm over its cycle (delta_R + D/2), the inner layer by %.3f cm (delta_R).",
                 worst_jump, double(mid.middle2_thickness), double(end.middle2_thickness),
                 double(r1.surface - mid.middle1),
                 double(layer_radii(s, 2 * s.T, true).middle2 - layer_radii(s, s.T).middle2),
                 double(s.delta_R)));
    return ctx.save_png(img.view());
}

SHITSUKAN_FIGURE(hirota_fig08, "hirota1998", "fig08",
                 "The bark over several cycles: cracking, lifting, peeling, new layers") {
    const LayeredRun* run;
    SHITSUKAN_TRY(layered_run(ctx.quick(), &run, &ctx));
    const LayeredBark& bark = run->bark;
    const LayeredParams& p = run->params;
    record_layered(ctx, p);
    const float T = p.schedule.T, base = float(p.spin_up_cycles);
    const float scale = ctx.quick() ? 10.0f : 15.0f;  // px per cm
    const float pw = float(p.N_R) * bark.lattice().a_h * 1.07f * scale;
    const float ph = float(p.N_H) * p.species.L0 * 1.1f * scale;
    const int cols = 4, gap = 14, label = 20;
    const int plot_h = ctx.quick() ? 180 : 240;
    const int W = int(float(cols) * (pw + gap)) + gap;
    const int H = int(2 * (ph + label + gap)) + plot_h + 40;
    RgbImage img(W, H, Rgb8{252, 252, 250});
    RasterCanvas c(img.view());
    for (int i = 0; i < 8; ++i) {
        const float t = (base + kFrameOffsets[i]) * T;
        const LayerFrame& f = frame_at(bark, t, kFrameBefore[i]);
        const Vec2 o{float(gap) + float(i % cols) * (pw + gap), float(label) + float(i / cols) * (ph + label + gap)};
        // Each frame in its own image (the periodic copies must not spill into the next one).
        RgbImage panel(int(pw), int(ph), Rgb8{252, 252, 250});
        RasterCanvas pcanvas(panel.view());
        draw_layer_frame(pcanvas, bark, f, {0.02f * pw, 0.0f}, scale);
        for (int y = 0; y < panel.height(); ++y)
            for (int x = 0; x < panel.width(); ++x) img.at(int(o.x) + x, int(o.y) + y) = panel.at(x, y);
        c.text({o.x, o.y - 14}, fmt("t/T = %.1f%s", double(base + kFrameOffsets[i]), kFrameLabel[i]),
               Rgb8{20, 20, 20}, 1);
    }
    // The alive and bonded fractions of the surface over the whole run.
    RgbImage plot(W, plot_h, Rgb8{255, 255, 255});
    RasterCanvas pc(plot.view());
    PlotMargins m;
    m.top = 30, m.right = 160;
    Axes axes = axes_in(pc, 0.0, double(p.cycles), 0.0, 1.05, m);
    const Vec2 s0 = axes.to_pixel(0.0, axes.y_hi), s1 = axes.to_pixel(base, axes.y_lo);
    pc.fill_rect(s0, s1 - s0, Rgb8{238, 238, 238});
    SHITSUKAN_TRY(draw_axes(pc, axes, {"", "t / T", "fraction of the surface"}));
    std::vector<float> xs, alive, bonded;
    for (const LayeredStep& st : bark.record()) {
        xs.push_back(st.t / T);
        alive.push_back(st.alive_fraction);
        bonded.push_back(st.bonded_fraction);
    }
    SHITSUKAN_TRY(plot_series(pc, axes, xs.data(), alive.data(), int(xs.size()), Rgb8{90, 60, 40}, 2.0f));
    SHITSUKAN_TRY(plot_series(pc, axes, xs.data(), bonded.data(), int(xs.size()), Rgb8{200, 90, 30}, 1.5f));
    const float lx = axes.corner.x + axes.size.x + 10;
    pc.line({lx, axes.corner.y + 10}, {lx + 18, axes.corner.y + 10}, Rgb8{90, 60, 40}, 2.0f);
    pc.text({lx + 24, axes.corner.y + 6}, "on the trunk", Rgb8{20, 20, 20}, 1);
    pc.line({lx, axes.corner.y + 26}, {lx + 18, axes.corner.y + 26}, Rgb8{200, 90, 30}, 1.5f);
    pc.text({lx + 24, axes.corner.y + 22}, "still bonded", Rgb8{20, 20, 20}, 1);
    pc.text({lx, axes.corner.y + 44}, "grey: spin-up", Rgb8{20, 20, 20}, 1);
    const int py = H - plot_h - 10;
    for (int y = 0; y < plot_h; ++y)
        for (int x = 0; x < W; ++x) img.at(x, py + y) = plot.at(x, y);
    const float ly = float(py) - 18.0f;
    c.fill_rect({float(gap), ly}, {10, 10}, Rgb8{92, 70, 52});
    c.text({float(gap) + 14, ly + 1}, "surface, bonded", Rgb8{20, 20, 20}, 1);
    c.fill_rect({float(gap) + 130, ly}, {10, 10}, Rgb8{150, 124, 98});
    c.text({float(gap) + 144, ly + 1}, "surface, lifted (debonded)", Rgb8{20, 20, 20}, 1);
    c.fill_rect({float(gap) + 320, ly}, {10, 10}, Rgb8{196, 120, 62});
    c.text({float(gap) + 334, ly + 1}, "middle (1) exposed (surface fell off)", Rgb8{20, 20, 20}, 1);

    // Checks over the shown cycles.
    std::string per_cycle;
    bool repeat = true;
    for (int k = p.spin_up_cycles; k < p.cycles; ++k) {
        float at06 = 1, at_end = 1, after = 0;
        int surface_end = 0, middle_end = 0;
        for (const LayeredStep& st : bark.record()) {
            const float tau = st.t / T - float(k);
            if (!st.role_change && std::fabs(tau - 0.6f) < 0.011f) at06 = st.alive_fraction;
            if (!st.role_change && std::fabs(tau - 1.0f) < 1e-4f)
                at_end = st.alive_fraction, surface_end = st.surface_broken, middle_end = st.middle1_broken;
            if (st.role_change && std::fabs(tau) < 1e-4f) after = st.alive_fraction;
        }
        if (k == p.spin_up_cycles) after = 1.0f;  // the cycle starts after a role change
        const int peeled = bark.regions_peeled_in_cycle(k);
        per_cycle += fmt("%scycle %d: alive %.2f at 0.6 T, %.2f at the end; %d regions fell; "
                         "broken springs at the end: surface %d, middle (1) %d",
                         k == p.spin_up_cycles ? "" : "; ", k + 1, double(at06), double(at_end),
                         peeled, surface_end, middle_end);
        repeat = repeat && at06 >= 0.95f && at_end <= 0.7f && after == 1.0f && peeled >= 30 &&
                 float(middle_end) < 0.75f * float(surface_end);
    }
    ctx.note(fmt("What to see (§4.3): each shown cycle starts with an intact, bonded surface; "
                 "cracks open, the drying zones around them lift the plates (light), plates fall "
                 "and expose middle (1) (orange), and at the role change what is left falls off "
                 "and the old middle (1), already cracked, becomes the surface: the process "
                 "repeats. %s. %s (checks: alive >= 0.95 at 0.6 T, <= 0.7 at the end, >= 30 "
                 "regions fall, middle (1) < 0.75 x the surface's broken springs; surface counts "
                 "include the springs of fallen plates). Run: %.2f s.",
                 per_cycle.c_str(), repeat ? "All checks pass" : "Some checks FAIL",
                 run->seconds));
    SHITSUKAN_TRY(ctx.save_png(img.view()));
    if (!ctx.quick() && !repeat)
        return Status::error(StatusCode::not_supported, "fig08: the cycles do not repeat as §4.3 says");
    return Status::success();
}

SHITSUKAN_FIGURE(hirota_fig06, "hirota1998", "fig06",
                 "The four-layer model: a radial section at mid-cycle, to scale") {
    const LayeredRun* run;
    SHITSUKAN_TRY(layered_run(ctx.quick(), &run, &ctx));
    const LayeredBark& bark = run->bark;
    const LayeredParams& p = run->params;
    record_layered(ctx, p);
    const LayerSchedule& s = p.schedule;
    const float t = (float(p.spin_up_cycles) + kSectionOffset) * s.T;
    const LayerFrame& f = frame_at(bark, t, false);
    const LayerRadii r = layer_radii(s, t);
    const BarkCylinder& lat = bark.lattice();
    const int columns = 16, row = p.N_H / 2;
    const float scale = ctx.quick() ? 90.0f : 160.0f;  // px per cm, both axes (to scale)
    const float width_cm = float(columns) * lat.a_h;
    const float r_lo = r.inner_boundary - s.D, r_hi = r.surface + 0.5f * s.D;
    const int left = 30, right = 240, top = 50, bottom = 60;
    const int W = left + int(width_cm * scale) + right, H = top + int((r_hi - r_lo) * scale) + bottom;
    RgbImage img(W, H, Rgb8{252, 252, 250});
    RasterCanvas c(img.view());
    auto px = [&](float u, float radius) {
        return Vec2{float(left) + u * scale, float(top) + (r_hi - radius) * scale};
    };
    // Find a window with a crack and a peeled place if there is one (the first column where
    // the surface is gone, minus a few).
    int c0 = 0;
    for (int cc = 0; cc < p.N_R; ++cc)
        if (!f.surface_alive[std::size_t(lat.node(cc, row))]) {
            c0 = (cc - 6 + p.N_R) % p.N_R;
            break;
        }
    auto node = [&](int k) { return lat.node((c0 + k) % p.N_R, row); };
    // Bands: inner, middle (2) half grown, middle (1), surface (where still on).
    const Rgb8 inner{170, 170, 170}, m2{236, 212, 140}, m1{214, 150, 90}, surf{120, 88, 62};
    c.fill_rect(px(0, r.inner_boundary), px(width_cm, r.inner_boundary - s.D) - px(0, r.inner_boundary), inner);
    c.fill_rect(px(0, r.inner_boundary + r.middle2_thickness),
                px(width_cm, r.inner_boundary) - px(0, r.inner_boundary + r.middle2_thickness), m2);
    const float m1_lo = r.inner_boundary + r.middle2_thickness;
    c.fill_rect(px(0, m1_lo + s.D), px(width_cm, m1_lo) - px(0, m1_lo + s.D), m1);
    // Per column: the surface cell, gaps where the ring's springs broke.
    for (int k = 0; k < columns; ++k) {
        const float u0 = float(k) * lat.a_h, u1 = u0 + lat.a_h;
        if (f.surface_alive[std::size_t(node(k))])
            c.fill_rect(px(u0, m1_lo + 2 * s.D), px(u1, m1_lo + s.D) - px(u0, m1_lo + 2 * s.D),
                        f.surface_bonded[std::size_t(node(k))] ? surf : Rgb8{160, 130, 100});
    }
    // Springs along the ring (the diagonals from (c, row) to the next column), nodes, shear.
    int cracks_s = 0, cracks_m = 0;
    for (int k = 0; k + 1 <= columns; ++k) {
        const int cc = (c0 + k) % p.N_R;
        const int s1 = lat.spring(cc, row, 1), s2 = lat.spring(cc, row, 2);
        const float u = (float(k) + 0.5f) * lat.a_h;
        const bool m_broken = (s1 >= 0 && f.middle1_broken[std::size_t(s1)]) ||
                              (s2 >= 0 && f.middle1_broken[std::size_t(s2)]);
        const bool s_broken = (s1 >= 0 && f.surface_broken[std::size_t(s1)]) ||
                              (s2 >= 0 && f.surface_broken[std::size_t(s2)]);
        const bool s_on = f.surface_alive[std::size_t(node(k))] &&
                          f.surface_alive[std::size_t(lat.node((cc + 1) % p.N_R, row))];
        if (k + 1 < columns) {
            c.line(px(u, r.middle1), px(u + lat.a_h, r.middle1), m_broken ? Rgb8{252, 252, 250} : Rgb8{60, 40, 20}, 1.5f);
            if (s_on) c.line(px(u, r.surface), px(u + lat.a_h, r.surface), s_broken ? Rgb8{252, 252, 250} : Rgb8{30, 20, 10}, 1.5f);
            c.line(px(u, r.middle2), px(u + lat.a_h, r.middle2), Rgb8{140, 120, 60}, 1.0f);
            c.line(px(u, r.inner), px(u + lat.a_h, r.inner), Rgb8{110, 110, 110}, 1.0f);
        }
        if (m_broken && k + 1 < columns) {
            c.fill_rect(px(u + 0.5f * lat.a_h - 0.02f, m1_lo + s.D), {0.04f * scale, s.D * scale}, Rgb8{40, 25, 15});
            ++cracks_m;
        }
        if (s_broken && s_on && k + 1 < columns) {
            c.fill_rect(px(u + 0.5f * lat.a_h - 0.03f, m1_lo + 2 * s.D), {0.06f * scale, s.D * scale}, Rgb8{40, 25, 15});
            ++cracks_s;
        }
        // Shear springs: surface - middle (1) (dashed when debonded), middle (1) - middle (2),
        // middle (2) - inner (moved by growth).
        const bool alive = f.surface_alive[std::size_t(node(k))];
        if (alive) {
            if (f.surface_bonded[std::size_t(node(k))])
                c.line(px(u, r.surface), px(u, r.middle1), Rgb8{30, 150, 60}, 1.5f);
            else
                for (float y = 0; y < 1.0f; y += 0.25f)
                    c.line(px(u, r.surface - y * s.D), px(u, r.surface - (y + 0.12f) * s.D), Rgb8{30, 150, 60}, 1.5f);
        }
        c.line(px(u, r.middle1), px(u, r.middle2), Rgb8{30, 150, 60}, 1.5f);
        c.line(px(u, r.middle2), px(u, r.inner), Rgb8{130, 130, 130}, 1.0f);
        if (alive) c.marker(px(u, r.surface), MarkerShape::dot, 6.0f, Rgb8{20, 20, 20});
        c.marker(px(u, r.middle1), MarkerShape::dot, 6.0f, Rgb8{20, 20, 20});
        c.marker(px(u, r.middle2), MarkerShape::dot, 5.0f, Rgb8{90, 90, 90});
        c.marker(px(u, r.inner), MarkerShape::dot, 5.0f, Rgb8{90, 90, 90});
    }
    const float lx = float(left) + width_cm * scale + 12.0f;
    c.text({lx, px(0, r.surface).y - 4}, "surface: cracks, peels", Rgb8{20, 20, 20}, 1);
    c.text({lx, px(0, r.middle1).y - 4}, "middle (1): exposed when", Rgb8{20, 20, 20}, 1);
    c.text({lx, px(0, r.middle1).y + 6}, "the surface peels", Rgb8{20, 20, 20}, 1);
    c.text({lx, px(0, r.middle2).y - 8}, fmt("middle (2): new cork, %.3f cm", double(r.middle2_thickness)),
           Rgb8{20, 20, 20}, 1);
    c.text({lx, px(0, r.middle2).y + 2}, "(grows to D in a cycle)", Rgb8{20, 20, 20}, 1);
    c.text({lx, px(0, r.inner).y - 4}, "inner: moves out with the wood", Rgb8{20, 20, 20}, 1);
    c.text({10, 10}, fmt("Fig. 6: four layers at t/T = %.1f (mid-cycle), radial section, to scale "
                         "(%.0f px/cm), unrolled around the trunk",
                         double(t / s.T), double(scale)),
           Rgb8{20, 20, 20}, 1);
    c.text({10, float(H - 40)}, "green: shear springs (dashed: broken, the surface lifted); dark "
                                "gaps: cracks; dots: nodes at the layers' mid-planes",
           Rgb8{60, 60, 60}, 1);
    ctx.note(fmt("Radii from the schedule at t/T = %.1f: inner node %.3f, middle (2) %.3f (thickness "
                 "%.4f cm = D/2), middle (1) %.3f, surface %.3f cm; the section's ring (row %d, "
                 "%d columns from the fig08 run at that time) shows %d surface and %d middle (1) "
                 "cracks.",
                 double(t / s.T), double(r.inner), double(r.middle2), double(r.middle2_thickness),
                 double(r.middle1), double(r.surface), row, columns, cracks_s, cracks_m));
    return ctx.save_png(img.view());
}
