// ports/web/api/api_hirota1998.cpp — the C API of the hirota1998 panel (§3, the two-layer
// model): the trunk grown and cracked by the library's event-driven run (grow_and_crack,
// bark/crack_events.hpp), then replayed one break at a time: the crack map (Fig. 4's widths,
// render/bark_crack_map.hpp draw_crack_map) at the time of any event, the trunk's unrolled
// surface growing with t. State: the last run (the cylinder, its events, the displacement
// field at the frames' times).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "api_common.hpp"
#include "shitsukan/bark/bark.hpp"
#include "shitsukan/image/raster_canvas.hpp"
#include "shitsukan/render/bark_crack_map.hpp"

using namespace shitsukan;

namespace {

BarkCylinder g_bark;
CrackRun g_run;
std::vector<float> g_frame_times;  // the snapshots' times, ascending (g_run.snapshots)
bool g_have_run = false;

// Chosen here: the frames' displacement fields may hold at most this many bytes (one W per
// distinct break time while it fits; else evenly chosen break times, the others drawn with the
// latest W before them — the set of cracks is always exact, their widths then approximate).
constexpr std::size_t kFrameBudgetBytes = std::size_t(192) << 20;

const Species kSpecies[3] = {Species::camphor, Species::chinese_tallow, Species::pine};

std::string number(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}

Status species_of(int species, Species* out) {
    if (species < 0 || species > 2)
        return Status::error(StatusCode::invalid_argument,
                             "species must be 0 (camphor), 1 (Chinese tallow) or 2 (pine) (got %d)", species);
    *out = kSpecies[species];
    return Status::success();
}

}  // namespace

// Table 2's column for a species (species_preset) and the cylinder's defaults (CylinderParams):
// text {name, L0, E1, E2, G, kappa1, kappa2, sigma, N_R, N_H, T, D}.
SK_API int sk_hirota1998_species(int species) {
    Species sp = Species::camphor;
    Status s = species_of(species, &sp);
    if (!s) return skweb::finish(s);
    CylinderParams p;
    p.species = species_preset(sp);
    const SpeciesParams& q = p.species;
    skweb::text() = "{\"name\":" + skweb::json_string(q.name) + ",\"L0\":" + number(q.L0) +
                    ",\"E1\":" + number(q.E1) + ",\"E2\":" + number(q.E2) + ",\"G\":" + number(q.G) +
                    ",\"kappa1\":" + number(q.kappa1) + ",\"kappa2\":" + number(q.kappa2) +
                    ",\"sigma\":" + number(p.sigma) + ",\"N_R\":" + std::to_string(p.N_R) +
                    ",\"N_H\":" + std::to_string(p.N_H) + ",\"T\":" + number(p.T) + ",\"D\":" + number(p.D) + "}";
    return skweb::finish(Status::success());
}

// Grows and cracks the two-layer cylinder of a species (Table 2) with sigma, kappa1, kappa2
// and N_R x N_H nodes (the library validates them: build_cylinder). Two runs of the same
// deterministic model: the first lists the breaks, the second keeps W at the frames' times
// (run_cracking's snapshots); their break sequences must hash the same.
// Floats: the time of every break, in order. Text: {events, hash (break_sequence_hash of all
// events, hex), cascade, frames, T, circumference and height at T, and Table 3's measure at T:
// regions bounded by cracks (measure_regions), how many span the full height, their mean and
// largest width x height in cm}.
SK_API int sk_hirota1998_run(int species, float sigma, float kappa1, float kappa2, int n_r, int n_h) {
    g_have_run = false;
    Species sp = Species::camphor;
    Status s = species_of(species, &sp);
    if (!s) return skweb::finish(s);
    CylinderParams p;
    p.species = species_preset(sp);
    p.sigma = sigma;
    p.species.kappa1 = kappa1;
    p.species.kappa2 = kappa2;
    p.N_R = n_r;
    p.N_H = n_h;
    BarkCylinder first;
    s = build_cylinder(p, first);
    CrackRun listing;
    Progress progress = skweb::progress();
    CrackRunOptions o1;
    o1.progress = progress.fn;
    o1.progress_user = progress.user;
    if (s) s = grow_and_crack(first, o1, listing);
    if (!s) return skweb::finish(s);
    // The frames: the distinct break times (a cascade shares one time), thinned to the budget.
    std::vector<float> times;
    for (const BreakEvent& e : listing.breaks)
        if (e.t > 0.0f && (times.empty() || e.t > times.back())) times.push_back(e.t);
    const std::size_t per = std::size_t(n_r) * std::size_t(n_h) * sizeof(Vec3);
    const std::size_t most = std::max<std::size_t>(2, kFrameBudgetBytes / per);
    if (times.size() > most) {
        std::vector<float> thin;
        for (std::size_t i = 0; i < most; ++i) thin.push_back(times[(i * (times.size() - 1)) / (most - 1)]);
        thin.erase(std::unique(thin.begin(), thin.end()), thin.end());
        times.swap(thin);
    }
    if (times.empty() || times.back() < p.T) times.push_back(p.T);
    s = build_cylinder(p, g_bark);
    CrackRunOptions o2;
    o2.snapshot_times = times.data();
    o2.snapshot_count = int(times.size());
    if (s) s = grow_and_crack(g_bark, o2, g_run);
    if (!s) return skweb::finish(s);
    const int n = int(g_run.breaks.size());
    const std::uint64_t h = break_sequence_hash(g_bark.net, g_run, n);
    if (n != int(listing.breaks.size()) || h != break_sequence_hash(first.net, listing, n))
        return skweb::finish(Status::error(StatusCode::degenerate,
                                           "hirota1998: the two runs broke different springs (%d vs %d events)",
                                           n, int(listing.breaks.size())));
    g_frame_times = times;
    g_have_run = true;
    std::vector<float>& out = skweb::floats();
    out.clear();
    for (const BreakEvent& e : g_run.breaks) out.push_back(e.t);
    // Table 3's measure on the result at T: the regions bounded by cracks (measure_regions).
    RegionReport regions;
    s = measure_regions(g_bark, p.T, g_bark.net.W.data(), regions);
    if (!s) return skweb::finish(s);
    char hex[20];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
    const float T = p.T;
    skweb::text() = "{\"events\":" + std::to_string(n) + ",\"hash\":\"" + hex + "\",\"cascade\":" +
                    std::to_string(g_run.cascade_breaks) + ",\"frames\":" + std::to_string(times.size()) +
                    ",\"T\":" + number(T) +
                    ",\"C_T\":" + number(g_bark.circumference * (1.0f + hoop_strain(p, T))) +
                    ",\"H_T\":" + number(g_bark.H0 * (1.0f + axial_strain(p, T))) +
                    ",\"regions\":" + std::to_string(regions.regions.size()) +
                    ",\"full_height\":" + std::to_string(regions.full_height) +
                    ",\"mean_w\":" + number(regions.mean_width) + ",\"mean_h\":" + number(regions.mean_height) +
                    ",\"max_w\":" + number(regions.max_width) + ",\"max_h\":" + number(regions.max_height) + "}";
    return skweb::finish(Status::success());
}

// The crack map after `event` breaks (0: the intact trunk at t = 0; n: all, at T): drawn by
// draw_crack_map at the time of that break with the displacement field of the latest frame at
// or before it, on a canvas the size of the grown trunk at T (so the trunk's growth shows), the
// spring of that break ringed in red. Text: {event, t, drawn (breaks at or before t), exact
// (W is the field at t), circumference, height}.
SK_API int sk_hirota1998_frame(int event, float px_per_cm) {
    Status s = g_have_run ? Status::success()
                          : Status::error(StatusCode::invalid_argument,
                                          "no run yet: call sk_hirota1998_run (grow_and_crack) first");
    const int n = g_have_run ? int(g_run.breaks.size()) : 0;
    if (s && (event < 0 || event > n))
        s = Status::error(StatusCode::out_of_range, "event must be in 0..%d (got %d)", n, event);
    if (s && !(px_per_cm >= 2.0f && px_per_cm <= 48.0f))
        s = Status::error(StatusCode::invalid_argument, "px_per_cm must be in 2..48 (got %g)", double(px_per_cm));
    if (!s) return skweb::finish(s);
    const CylinderParams& p = g_bark.params;
    const float T = p.T;
    const float t = event == 0 ? 0.0f : event == n ? std::max(T, g_run.breaks[std::size_t(n - 1)].t)
                                                   : g_run.breaks[std::size_t(event - 1)].t;
    // The latest frame at or before t (W = 0 at t = 0: the trunk before any growth).
    const Vec3* W = nullptr;
    bool exact = false;
    std::vector<Vec3> zero;
    for (std::size_t i = 0; i < g_run.snapshots.size(); ++i)
        if (g_run.snapshots[i].t <= t) {
            W = g_run.snapshots[i].W.data();
            exact = g_run.snapshots[i].t == t;
        }
    if (!W) {
        zero.assign(g_bark.net.W.size(), Vec3{0, 0, 0});
        W = zero.data();
        exact = t == 0.0f;
    }
    const float C_T = g_bark.circumference * (1.0f + hoop_strain(p, T));
    const float H_T = g_bark.H0 * (1.0f + axial_strain(p, T));
    const int w = int(std::ceil(C_T * px_per_cm)) + 2, h = int(std::ceil(H_T * px_per_cm)) + 2;
    RgbImage map(w, h, Rgb8{250, 250, 248});
    RasterCanvas canvas(map.view());
    CrackMapStyle style;
    style.origin = {0.0f, float(h - 1)};
    style.px_per_cm = px_per_cm;
    style.min_width_cm = 1.0f / px_per_cm;
    style.plate = Rgb8{150, 128, 104};
    style.crack = Rgb8{28, 20, 14};
    s = draw_crack_map(canvas, g_bark, t, W, style);
    if (!s) return skweb::finish(s);
    if (event > 0) {
        const CrackRibbon r = crack_ribbon(g_bark, g_run.breaks[std::size_t(event - 1)].spring, t, W);
        const float C_t = g_bark.circumference * (1.0f + hoop_strain(p, t));
        float u = r.midpoint.x;  // around the trunk: wrapped as draw_crack_map wraps the map
        if (u >= C_t) u -= C_t;
        const Vec2 at{style.origin.x + u * px_per_cm, style.origin.y - r.midpoint.y * px_per_cm};
        canvas.rect_outline({at.x - 6.0f, at.y - 6.0f}, {12.0f, 12.0f}, Rgb8{220, 30, 30}, 2.0f);
    }
    int drawn = 0;
    while (drawn < n && g_run.breaks[std::size_t(drawn)].t <= t) ++drawn;
    skweb::set_picture(map);
    skweb::text() = "{\"event\":" + std::to_string(event) + ",\"t\":" + number(t) + ",\"drawn\":" +
                    std::to_string(drawn) + ",\"exact\":" + (exact ? "true" : "false") +
                    ",\"C\":" + number(g_bark.circumference * (1.0f + hoop_strain(p, t))) +
                    ",\"H\":" + number(g_bark.H0 * (1.0f + axial_strain(p, t))) + "}";
    return skweb::finish(Status::success());
}
