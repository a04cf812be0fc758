// tests/bench/bench.hpp — the `make bench` harness.
//
// Manual
//   SHITSUKAN_BENCH(lattice_vs_stb) {
//       double ours = bench::ns_per_op([&] { ...one op... });   // or per batch, then divide
//       double peer = bench::ns_per_op([&] { ...the peer's op... });
//       bench::report("D(P) Type I per sample", ours, "stb_perlin fbm-6", peer);
//   }
// report() prints exactly one line:
//   bench: <what>: shitsukan <x> ns, <peer> <y> ns, ratio <y/x>
// (ratio > 1 means shitsukan is faster). Ours and the peer are timed in the same run on
// the same inputs. bench::sink(v) keeps the optimiser from deleting work.
// `build/bench --only <substring>` runs the matching benchmarks; --quick shortens timing.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

#include "shitsukan/core/status.hpp"

namespace bench {

extern double g_min_seconds;  // time each measurement for at least this long (0.2 s)
extern volatile double g_sink;

template <class T>
inline void sink(T v) { g_sink = g_sink + double(v); }

// Nanoseconds per call of fn: calls fn in growing batches until a round lasts min_seconds/7,
// runs seven rounds and keeps the fastest (the least disturbed by other processes: on a
// shared machine the slow rounds measure the neighbours, not the code).
template <class F>
double ns_per_op(F&& fn) {
    using clock = std::chrono::steady_clock;
    double best = 1e300;
    for (int rep = 0; rep < 7; ++rep) {
        long n = 1;
        for (;;) {
            auto t0 = clock::now();
            for (long i = 0; i < n; ++i) fn();
            double s = std::chrono::duration<double>(clock::now() - t0).count();
            if (s >= g_min_seconds / 7 || n > (1L << 40)) {
                double per = s * 1e9 / double(n);
                if (per < best) best = per;
                break;
            }
            n *= 2;
        }
    }
    return best;
}

// Two operations timed in turns, for ratios near 1: calibrated so that a round lasts about
// 1 ms, then 7·20 rounds of each, alternating, each keeping its fastest round. A disturbance
// on the shared machine lasting longer than a round falls on both sides alike, where
// ns_per_op's long rounds, one side after the other, let it fall on one side only
// (the D(P) single sample against the raw lookup measured 1.27x one way, 1.13x this way).
template <class A, class B>
void ns_per_op_interleaved(A&& a, B&& b, double* a_ns, double* b_ns) {
    using clock = std::chrono::steady_clock;
    auto round = [](auto& fn, long n) {
        auto t0 = clock::now();
        for (long i = 0; i < n; ++i) fn();
        return std::chrono::duration<double>(clock::now() - t0).count();
    };
    const double round_seconds = g_min_seconds / 200;
    long na = 1, nb = 1;
    while (round(a, na) < round_seconds && na < (1L << 40)) na *= 2;
    while (round(b, nb) < round_seconds && nb < (1L << 40)) nb *= 2;
    double best_a = 1e300, best_b = 1e300;
    for (int rep = 0; rep < 140; ++rep) {
        const double sa = round(a, na) * 1e9 / double(na);
        const double sb = round(b, nb) * 1e9 / double(nb);
        if (sa < best_a) best_a = sa;
        if (sb < best_b) best_b = sb;
    }
    *a_ns = best_a;
    *b_ns = best_b;
}

void report(const std::string& what, double ours_ns, const std::string& peer, double peer_ns);
void info(const std::string& what, const std::string& text);  // "bench: <what>: <text>"

// A failed set-up must not print a timing: it would measure nothing. Reports the failure
// ("bench: <what>: set-up failed: <message>") and returns false.
bool set_up(const shitsukan::Status& s, const char* what);
// The same for calls inside a timed loop: ok is the AND of their results.
bool timed_calls_ok(bool ok, const char* what);

using BenchFunction = void (*)();
bool register_bench(const char* name, BenchFunction fn);

}  // namespace bench

#define SHITSUKAN_BENCH(name)                                                   \
    static void bench_##name();                                                 \
    static const bool bench_##name##_registered_ = bench::register_bench(#name, &bench_##name); \
    static void bench_##name()
