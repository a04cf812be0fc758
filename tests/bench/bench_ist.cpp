// bench_ist — fujimoto2000 Table 1 in one line: the scale reverse formula eq. (14) against the
// step-by-step procedure of §2.1 (ref. 13's way), fully-connected IST N = 5, K = 6, the same
// pseudo-random coordinates. Table 1 in full: `make figures FIGURES_ARGS="--only
// fujimoto2000/table01"`.
#include <cstddef>
#include <vector>

#include "bench.hpp"
#include "shitsukan/core/prng.hpp"
#include "shitsukan/wrinkly/ist.hpp"

using namespace shitsukan;

SHITSUKAN_BENCH(ist_formula_vs_procedure) {
    IstAxis axis;
    if (!ist_fully_connected_axis(5, 6, 5, IstEnds::cyclic, axis)) return;
    IstOriginal original;
    original.base_intervals = 5;
    original.crossing_all = 2;
    original.iterations = 6;
    original.ends = IstEnds::cyclic;
    Pcg32 rng(2000u, 1u);
    std::vector<float> u(4096);
    for (float& x : u) x = rng.uniform();
    std::size_t i = 0, j = 0;
    const bench::Pair t = bench::in_turns(
        [&] {
            bench::sink(ist_forward(axis, u[i]));
            i = (i + 1) & 4095u;
        },
        [&] {
            bench::sink(ist_original_forward(original, double(u[j])));
            j = (j + 1) & 4095u;
        });
    bench::report("IST fully-connected N=5 K=6 per coordinate (formula eq. 14)", t,
                  "step-by-step procedure §2.1");
}
