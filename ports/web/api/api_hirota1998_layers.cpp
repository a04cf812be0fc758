// ports/web/api/api_hirota1998_layers.cpp — the C API of the hirota1998 four-layer panel (§4,
// figs. 6-8): the library's LayeredBark run once (build, run) with a frame kept at the end of
// every step of the run (and before each role change), then any of them drawn as fig. 8 draws
// its frames (paper_figures/hirota1998/layer_frame_draw.cpp). The run's own record per step
// (alive and bonded fractions, broken springs per layer, plates peeled, shear springs
// debonded, role changes) is returned in order, so the page replays the run step by step.
// State: the last run.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "api_common.hpp"
#include "hirota1998/layer_frame_draw.hpp"
#include "shitsukan/bark/layered_bark.hpp"

using namespace shitsukan;
using namespace shitsukan::figures::bark;

namespace {

LayeredBark g_layers;
bool g_have_layers = false;

std::string number(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}

}  // namespace

// Builds and runs the four-layer bark (LayeredParams' defaults: pine, Table 4's values chosen
// in layered_bark.hpp) on n_r x n_h nodes for `cycles` cycles, kappa_h the mean critical shear
// strain of peeling (Table 4). Frames: one at the end of every step (T / steps_per_cycle), and
// one before each role change (t = kT). Floats: one row of 8 per frame, in the run's order:
// t, alive fraction, bonded fraction, broken springs in the surface and in middle (1), plates
// peeled in the step, shear springs debonded in the step, 1 at a role change (the run's
// record() after its t = 0 entry). Text: {frames, steps, cycles, T, N_R, N_H, peeled (total), role_changes}.
SK_API int sk_hirota1998_layers_run(int n_r, int n_h, int cycles, float kappa_h) {
    g_have_layers = false;
    LayeredParams p;
    p.N_R = n_r;
    p.N_H = n_h;
    p.cycles = cycles;
    p.spin_up_cycles = std::min(p.spin_up_cycles, std::max(0, cycles - 1));
    p.peeling.kappa_h = kappa_h;
    Status s = validate(p);
    if (!s) return skweb::finish(s);
    const int steps = p.steps_per_cycle;
    std::vector<FrameRequest> frames;
    for (int k = 0; k < cycles; ++k)
        for (int i = 1; i <= steps; ++i) {
            const float t = p.schedule.T * float(k * steps + i) / float(steps);
            const bool change = i == steps && k + 1 < cycles;
            if (change) frames.push_back({t, true});
            frames.push_back({t, false});
        }
    Progress progress = skweb::progress();
    s = g_layers.build(p);
    if (s) s = g_layers.run(frames.data(), int(frames.size()), progress.fn, progress.user);
    if (!s) return skweb::finish(s);
    const std::vector<LayeredStep>& rec = g_layers.record();
    // record()[0] is the state at t = 0; record()[i + 1] the step (or role change) of frame i.
    if (rec.size() != g_layers.frames().size() + 1)
        return skweb::finish(Status::error(StatusCode::degenerate,
                                           "hirota1998 layers: %d records but %d frames kept",
                                           int(rec.size()), int(g_layers.frames().size())));
    g_have_layers = true;
    std::vector<float>& out = skweb::floats();
    out.clear();
    int peeled = 0, changes = 0;
    for (std::size_t i = 1; i < rec.size(); ++i) {
        const LayeredStep& r = rec[i];
        out.insert(out.end(), {r.t, r.alive_fraction, r.bonded_fraction, float(r.surface_broken),
                               float(r.middle1_broken), float(r.peeled_regions), float(r.debonded),
                               r.role_change ? 1.0f : 0.0f});
        peeled += r.peeled_regions;
        changes += r.role_change;
    }
    skweb::set_float_columns(8);
    skweb::text() = "{\"frames\":" + std::to_string(g_layers.frames().size()) + ",\"steps\":" + std::to_string(steps) +
                    ",\"cycles\":" + std::to_string(cycles) + ",\"T\":" + number(p.schedule.T) +
                    ",\"N_R\":" + std::to_string(n_r) + ",\"N_H\":" + std::to_string(n_h) +
                    ",\"peeled\":" + std::to_string(peeled) + ",\"role_changes\":" + std::to_string(changes) + "}";
    return skweb::finish(Status::success());
}

// Frame `index` of the last run drawn as fig. 8 draws a frame, px_per_cm pixels per cm, on a
// canvas as wide as the widest layer of the run (so the growth shows). Text: {t,
// before_role_change, generation_surface, generation_middle1, surface_period, middle1_period}.
SK_API int sk_hirota1998_layers_frame(int index, float px_per_cm) {
    Status s = g_have_layers ? Status::success()
                             : Status::error(StatusCode::invalid_argument,
                                             "no four-layer run yet: call sk_hirota1998_layers_run first");
    const int n = g_have_layers ? int(g_layers.frames().size()) : 0;
    if (s && (index < 0 || index >= n))
        s = Status::error(StatusCode::out_of_range, "frame must be in 0..%d (got %d)", n - 1, index);
    if (s && !(px_per_cm >= 2.0f && px_per_cm <= 48.0f))
        s = Status::error(StatusCode::invalid_argument, "px_per_cm must be in 2..48 (got %g)", double(px_per_cm));
    if (!s) return skweb::finish(s);
    const LayeredParams& p = g_layers.params();
    float widest = 0.0f;
    for (const LayerFrame& f : g_layers.frames()) widest = std::max({widest, f.surface_period, f.middle1_period});
    const int w = int(std::ceil(widest * px_per_cm)) + 4;
    const int h = int(std::ceil(float(p.N_H) * p.species.L0 * 1.1f * px_per_cm)) + 4;
    RgbImage img(w, h, Rgb8{250, 250, 248});
    RasterCanvas canvas(img.view());
    const LayerFrame& f = g_layers.frames()[std::size_t(index)];
    draw_layer_frame(canvas, g_layers, f, {2.0f, 2.0f}, px_per_cm);
    skweb::set_picture(img);
    skweb::text() = "{\"t\":" + number(f.t) + ",\"before_role_change\":" + (f.before_role_change ? "true" : "false") +
                    ",\"generation_surface\":" + std::to_string(f.generation_surface) +
                    ",\"generation_middle1\":" + std::to_string(f.generation_middle1) +
                    ",\"surface_period\":" + number(f.surface_period) + ",\"middle1_period\":" + number(f.middle1_period) + "}";
    return skweb::finish(Status::success());
}
