// ports/web/api/api_hirota1998_layers.cpp — the C API of the hirota1998 four-layer panel (§4,
// figs. 6-8): the library's LayeredBark run once (build, run) with a frame kept at the end of
// every step of the run (and before each role change), then any of them drawn as fig. 8 draws
// its frames (paper_figures/hirota1998/layer_frame_draw.cpp). The run's own record per step
// (alive and bonded fractions, broken springs per layer, plates peeled, shear springs
// debonded, role changes) is returned in order, so the page replays the run step by step.
// Every event of the run's break loop is also kept, in order, by the library's observer
// (LayeredBark::observe, bark/break_loop.hpp): a spring of the surface or of middle (1) broken,
// or surface nodes debonded; the page replays them one at a time. State: the last run.
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

// One loop event as the observer saw it: kind 0 a surface spring broke, 1 a spring of middle
// (1), 2 surface nodes debonded (nodes[first, first + count) of g_debonded); frame: the frame
// index at whose step end the event is included (frames kept before it: the state before).
struct LayerEvent {
    float t = 0;
    int kind = 0;
    int spring = -1;  // lattice spring (kinds 0, 1)
    int frame = 0;
    int first = 0, count = 0;  // kind 2
};
std::vector<LayerEvent> g_events;
std::vector<int> g_debonded;  // lattice nodes of the debonding events, in order

void observe_event(const BreakLoopEvent& e, const SpringNetwork&, void*) {
    const int m = g_layers.lattice().net.spring_count(), n = int(g_layers.lattice().net.X.size());
    LayerEvent ev;
    ev.t = e.t;
    ev.frame = int(g_layers.frames().size());
    if (int(e.item) < 2 * m) {
        ev.kind = int(e.item) / m == g_layers.surface_slot() ? 0 : 1;
        ev.spring = int(e.item) % m;
    } else {
        ev.kind = 2;
        ev.first = int(g_debonded.size());
        for (int i = 0; i < e.seed_count; ++i) {
            const int p = int(e.seeds[i]) % n;
            if (std::find(g_debonded.begin() + ev.first, g_debonded.end(), p) == g_debonded.end())
                g_debonded.push_back(p);
        }
        ev.count = int(g_debonded.size()) - ev.first;
    }
    g_events.push_back(ev);
}

std::string number(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}

// Draws f as fig. 8 draws a frame, on a canvas as wide as the widest layer of the run, with the
// spring `ring` of layer `ring_kind` (0 surface, 1 middle (1)) ringed in red (-1: none).
void draw_frame(const LayerFrame& f, float px_per_cm, int ring_kind, int ring) {
    const LayeredParams& p = g_layers.params();
    float widest = 0.0f;
    for (const LayerFrame& q : g_layers.frames()) widest = std::max({widest, q.surface_period, q.middle1_period});
    const int w = int(std::ceil(widest * px_per_cm)) + 4;
    const float height_px = float(p.N_H) * p.species.L0 * 1.1f * px_per_cm;
    const int h = int(std::ceil(height_px)) + 4;
    RgbImage img(w, h, Rgb8{250, 250, 248});
    RasterCanvas canvas(img.view());
    draw_layer_frame(canvas, g_layers, f, {2.0f, 2.0f}, px_per_cm);
    if (ring >= 0) {
        const BarkSpring& sp = g_layers.lattice().net.springs[std::size_t(ring)];
        const std::vector<Vec3>& pos = ring_kind == 0 ? f.surface_position : f.middle1_position;
        const Vec3 m = (pos[sp.i] + pos[sp.j]) * 0.5f;  // as draw_layer_frame's px()
        const Vec2 at{2.0f + m.x * px_per_cm, 2.0f + height_px - m.y * px_per_cm};
        canvas.rect_outline({at.x - 6.0f, at.y - 6.0f}, {12.0f, 12.0f}, Rgb8{220, 30, 30}, 2.0f);
    }
    skweb::set_picture(img);
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
    g_events.clear();
    g_debonded.clear();
    s = g_layers.build(p);
    BreakObserver watch;
    watch.on_event = observe_event;
    g_layers.observe(watch);
    if (s) s = g_layers.run(frames.data(), int(frames.size()), progress.fn, progress.user);
    if (!s) return skweb::finish(s);
    const std::vector<LayeredStep>& rec = g_layers.record();
    // record()[0] is the state at t = 0; record()[i + 1] the step (or role change) of frame i.
    if (rec.size() != g_layers.frames().size() + 1)
        return skweb::finish(Status::error(StatusCode::degenerate,
                                           "hirota1998 layers: %d records but %d frames kept",
                                           int(rec.size()), int(g_layers.frames().size())));
    if (int(g_events.size()) != g_layers.loop_events())
        return skweb::finish(Status::error(StatusCode::degenerate,
                                           "hirota1998 layers: the observer saw %d events, the loop applied %d",
                                           int(g_events.size()), g_layers.loop_events()));
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
                    ",\"peeled\":" + std::to_string(peeled) + ",\"role_changes\":" + std::to_string(changes) +
                    ",\"events\":" + std::to_string(g_events.size()) + "}";
    return skweb::finish(Status::success());
}

// The loop events of the last run, in order (the observer's): floats, one row of 4 per event:
// t, kind (0 surface spring broke, 1 middle (1) spring broke, 2 surface nodes debonded),
// lattice spring (kinds 0, 1) or nodes debonded (kind 2), frame index the event belongs to.
SK_API int sk_hirota1998_layers_events(void) {
    if (!g_have_layers)
        return skweb::finish(Status::error(StatusCode::invalid_argument,
                                           "no four-layer run yet: call sk_hirota1998_layers_run first"));
    std::vector<float>& out = skweb::floats();
    out.clear();
    for (const LayerEvent& e : g_events)
        out.insert(out.end(), {e.t, float(e.kind), float(e.kind == 2 ? e.count : e.spring), float(e.frame)});
    skweb::set_float_columns(4);
    return skweb::finish(Status::success());
}

// The state after `event` loop events (0 .. events) drawn as a frame: the frame kept before the
// event's step (the surface's positions, alive and bonded flags, both layers' cracks then; the
// intact patch before the first step), with the events of the step up to this one applied
// (springs broken, nodes debonded), the event's spring ringed in red. Widths and positions are
// the step's start (the field is kept per step); plates fall and roles change between steps,
// so they show at the step's frame. Text: {event, t, kind, frame, generation_surface,
// generation_middle1}.
SK_API int sk_hirota1998_layers_event(int event, float px_per_cm) {
    Status s = g_have_layers ? Status::success()
                             : Status::error(StatusCode::invalid_argument,
                                             "no four-layer run yet: call sk_hirota1998_layers_run first");
    const int n = g_have_layers ? int(g_events.size()) : 0;
    if (s && (event < 0 || event > n))
        s = Status::error(StatusCode::out_of_range, "event must be in 0..%d (got %d)", n, event);
    if (s && !(px_per_cm >= 2.0f && px_per_cm <= 48.0f))
        s = Status::error(StatusCode::invalid_argument, "px_per_cm must be in 2..48 (got %g)", double(px_per_cm));
    if (!s) return skweb::finish(s);
    const std::vector<LayerFrame>& frames = g_layers.frames();
    const int frame = event == 0 ? 0 : g_events[std::size_t(event - 1)].frame;
    LayerFrame f = frames[std::size_t(std::max(0, frame - 1))];
    if (frame == 0) {  // before the first step: nothing broken, all on the trunk and bonded
        std::fill(f.surface_broken.begin(), f.surface_broken.end(), 0);
        std::fill(f.middle1_broken.begin(), f.middle1_broken.end(), 0);
        std::fill(f.surface_alive.begin(), f.surface_alive.end(), 1);
        std::fill(f.surface_bonded.begin(), f.surface_bonded.end(), 1);
    }
    int first = event;
    while (first > 0 && g_events[std::size_t(first - 1)].frame == frame) --first;
    for (int i = first; i < event; ++i) {
        const LayerEvent& e = g_events[std::size_t(i)];
        if (e.kind == 0) f.surface_broken[std::size_t(e.spring)] = 1;
        if (e.kind == 1) f.middle1_broken[std::size_t(e.spring)] = 1;
        for (int k = 0; k < e.count; ++k) f.surface_bonded[std::size_t(g_debonded[std::size_t(e.first + k)])] = 0;
    }
    const LayerEvent* last = event > 0 ? &g_events[std::size_t(event - 1)] : nullptr;
    draw_frame(f, px_per_cm, last && last->kind < 2 ? last->kind : -1, last && last->kind < 2 ? last->spring : -1);
    skweb::text() = "{\"event\":" + std::to_string(event) + ",\"t\":" + number(last ? last->t : 0.0f) +
                    ",\"kind\":" + std::to_string(last ? last->kind : -1) + ",\"frame\":" + std::to_string(frame) +
                    ",\"generation_surface\":" + std::to_string(f.generation_surface) +
                    ",\"generation_middle1\":" + std::to_string(f.generation_middle1) + "}";
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
    const LayerFrame& f = g_layers.frames()[std::size_t(index)];
    draw_frame(f, px_per_cm, -1, -1);
    skweb::text() = "{\"t\":" + number(f.t) + ",\"before_role_change\":" + (f.before_role_change ? "true" : "false") +
                    ",\"generation_surface\":" + std::to_string(f.generation_surface) +
                    ",\"generation_middle1\":" + std::to_string(f.generation_middle1) +
                    ",\"surface_period\":" + number(f.surface_period) + ",\"middle1_period\":" + number(f.middle1_period) + "}";
    return skweb::finish(Status::success());
}
