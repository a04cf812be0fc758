// tests/bench/bench_voronoi_timing.hpp — how the Voronoi and Delaunay benchmarks time a call
// (ours and the peers' alike): the THREAD CPU time (clock_gettime(CLOCK_THREAD_CPUTIME_ID)),
// not the wall clock, so that the other sessions sharing this machine's two cores do not
// decide the ratio (chosen here: on a load of 5 the wall-clock ratios of two runs differed by
// up to 1.6x; CPU time still counts the caches the neighbours evict, but not the time slices
// they take). Best of 7 rounds of at least g_min_seconds / 7 below 1e5 sites, best of 3
// single calls from 1e5 sites up (7 rounds of 1e6 sites for four timings would take minutes).
//
// Manual
//   double ns = voronoi_time_call(n, [&] { voronoi_cells(...); });   // ns per call
#pragma once

#include <time.h>

#include <algorithm>

#include "bench.hpp"

inline double thread_cpu_ns() {
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) * 1e9 + double(ts.tv_nsec);
}

template <class F> double voronoi_time_call(int n, F&& fn) {
    const int rounds = n < 100000 ? 7 : 3;
    double best = 1e300;
    for (int r = 0; r < rounds; ++r) {
        long calls = 1;
        for (;;) {
            const double t0 = thread_cpu_ns();
            for (long i = 0; i < calls; ++i) fn();
            const double ns = thread_cpu_ns() - t0;
            if (n >= 100000 || ns >= bench::g_min_seconds / 7 * 1e9 || calls > (1L << 30)) {
                best = std::min(best, ns / double(calls));
                break;
            }
            calls *= 2;
        }
    }
    return best;
}
