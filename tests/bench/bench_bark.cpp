// bench_bark — hirota1998 §3: the camphor run at the fig05 size (128 x 64 nodes), event-driven
// (one local re-solve per break) against the naive way: a full relaxation of the lattice after
// every break. The naive cost is measured as one full solve of the intact lattice from rest
// times the number of breaks (a lower bound: a cracked lattice relaxes more slowly).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

#include "bench.hpp"
#include "shitsukan/bark/bark.hpp"

using namespace shitsukan;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

SHITSUKAN_BENCH(bark_species) {
    double total = 0, camphor_run = 0, camphor_breaks = 0;
    CylinderParams camphor;
    camphor.species = species_preset(Species::camphor);
    for (Species sp : {Species::camphor, Species::chinese_tallow, Species::pine}) {
        CylinderParams p;
        p.species = species_preset(sp);
        double best = 1e30;
        std::size_t breaks = 0;
        const int rounds = bench::g_min_seconds < 0.1 ? 1 : 3;
        for (int round = 0; round < rounds; ++round) {
            const auto t0 = std::chrono::steady_clock::now();
            BarkCylinder bark;
            CrackRun run;
            if (!build_cylinder(p, bark).ok() || !grow_and_crack(bark, CrackRunOptions{}, run).ok()) {
                bench::info("bark", "run failed");
                return;
            }
            best = std::min(best, seconds_since(t0));
            breaks = run.breaks.size();
        }
        total += best;
        if (sp == Species::camphor) camphor_run = best, camphor_breaks = double(breaks);
        bench::info(std::string("bark two-layer run, ") + species_name(sp),
                    std::to_string(best).substr(0, 5) + " s, " + std::to_string(breaks) +
                        " breaks, " + std::to_string(best / double(breaks) * 1e6).substr(0, 5) +
                        " us per break");
    }
    bench::info("bark all three species (fig05 + table03)",
                std::to_string(total).substr(0, 5) + " s (goal < 3 s)");
    // The naive way: re-solve the whole lattice after each break.
    BarkCylinder bark;
    if (!build_cylinder(camphor, bark).ok()) return;
    float g_max = 0;
    for (const BarkSpring& s : bark.net.springs) g_max = std::max(g_max, s.growth_rate);
    const float tol = camphor.tolerance * camphor.species.L0 * g_max;
    const auto t0 = std::chrono::steady_clock::now();
    if (!solve_full(bark.net, tol, 100000).ok()) return;
    const double full_solve = seconds_since(t0);
    // Runs of seconds each, timed once (not in turns): an info line, not a ratio.
    char text[160];
    std::snprintf(text, sizeof text,
                  "event-driven local re-solve %.0f ns per break, a full Gauss-Seidel solve %.0f "
                  "ns (single wall-clock runs, not timed in turns)",
                  camphor_run / camphor_breaks * 1e9, full_solve * 1e9);
    bench::info("bark camphor 128x64, per break", text);
}

// hirota1998 §4 and §5: fig. 8's four-layer run (5 cycles) and fig. 11's growth run.
SHITSUKAN_BENCH(bark_layered_and_branch) {
    const bool quick = bench::g_min_seconds < 0.1;
    LayeredParams lp;
    if (quick) lp.N_R = 24, lp.N_H = 16, lp.cycles = 3, lp.spin_up_cycles = 1;
    auto t0 = std::chrono::steady_clock::now();
    LayeredBark layered;
    if (!layered.build(lp).ok() || !layered.run(nullptr, 0).ok()) {
        bench::info("bark layered", "run failed");
        return;
    }
    const double layered_s = seconds_since(t0);
    int breaks = 0;
    for (const LayeredStep& s : layered.record()) breaks += s.debonded;
    bench::info(std::string("bark four-layer run (fig08), ") + std::to_string(lp.N_R) + " x " +
                    std::to_string(lp.N_H) + " x 2 layers, " + std::to_string(lp.cycles) + " cycles",
                std::to_string(layered_s).substr(0, 5) + " s, " + std::to_string(breaks) +
                    " debonds");
    BranchBarkParams bp;
    if (quick) bp.edge_length = 0.6f;
    t0 = std::chrono::steady_clock::now();
    BranchBark branch;
    if (!build_branch_bark(bp, branch).ok()) return;
    const double mesh_s = seconds_since(t0);
    t0 = std::chrono::steady_clock::now();
    CrackRun run;
    if (!grow_branch_bark(branch, CrackRunOptions{}, run).ok()) return;
    const double crack_s = seconds_since(t0);
    bench::info("bark branch growth run (fig11), " + std::to_string(branch.mesh.vertex_count()) +
                    " nodes",
                "mesh " + std::to_string(mesh_s).substr(0, 5) + " s, cracking " +
                    std::to_string(crack_s).substr(0, 5) + " s, " +
                    std::to_string(run.breaks.size()) + " breaks, " +
                    std::to_string(crack_s / double(std::max<std::size_t>(1, run.breaks.size())) * 1e6)
                        .substr(0, 5) +
                    " us per break");
}
