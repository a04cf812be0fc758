// tests/bench/bench.hpp — the `make bench` harness.
//
// Manual
//   SHITSUKAN_BENCH(lattice_vs_stb) {
//       bench::Pair t = bench::in_turns([&] { ...one op of ours... },
//                                       [&] { ...the peer's op... });
//       bench::report("D(P) Type I per sample", t, "stb_perlin fbm-6", 15.0);  // goal >= 15
//   }
// report() prints exactly one line:
//   bench: <what>: shitsukan <median> ns (best <b>, spread <s>%), <peer> <median> ns (best
//   <b>, spread <s>%), ratio <peer median / ours median> (best to best <r>)[, goal ratio >=
//   <g>: met | NOT met]
// (ratio > 1 means shitsukan is faster; a goal is judged on the medians). Ours and the peer
// are timed in turns on the same inputs: many short rounds, one of each alternately, in the
// thread's CPU time, so a disturbance of the shared machine falls on both alike and the time
// slices other processes take are not counted. spread = (upper quartile - lower quartile) /
// median of the rounds. bench::sink(v) keeps the optimiser from deleting work.
// `build/bench --only <substring>` runs the matching benchmarks; --quick shortens timing.
#pragma once

#include <time.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "shitsukan/core/status.hpp"

namespace bench {

extern double g_min_seconds;  // the time budget of one pair is twice this (0.2 s; --quick 0.03)
extern volatile double g_sink;

template <class T>
inline void sink(T v) { g_sink = g_sink + double(v); }

// CPU time of the calling thread (clock_gettime(CLOCK_THREAD_CPUTIME_ID)), in nanoseconds.
inline double thread_cpu_ns() {
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) * 1e9 + double(ts.tv_nsec);
}

// Nanoseconds per call over the rounds of one side.
struct Timing {
    double best = 0, median = 0, spread = 0;  // spread: interquartile range / median
};
struct Pair {
    Timing ours, peer;
};

Timing summarize(std::vector<double> per_call_ns);

namespace detail {
// Calls per round so that a round lasts at least round_ns (the calibration also warms up).
template <class F> long calls_per_round(F& fn, double round_ns) {
    long n = 1;
    for (;;) {
        const double t0 = thread_cpu_ns();
        for (long i = 0; i < n; ++i) fn();
        if (thread_cpu_ns() - t0 >= round_ns || n > (1L << 40)) return n;
        n *= 2;
    }
}
template <class F> double round_ns_per_call(F& fn, long n) {
    const double t0 = thread_cpu_ns();
    for (long i = 0; i < n; ++i) fn();
    return (thread_cpu_ns() - t0) / double(n);
}
}  // namespace detail

// ours and peer timed in turns: rounds of about g_min_seconds / 100 each (one call when a
// call is longer), one round of each alternately, as many as fit in 2·g_min_seconds, at least
// 5 and at most 101 of each.
template <class A, class B> Pair in_turns(A&& ours, B&& peer) {
    const double round_ns = g_min_seconds * 1e9 / 100;
    const long na = detail::calls_per_round(ours, round_ns);
    const long nb = detail::calls_per_round(peer, round_ns);
    std::vector<double> ta, tb;
    const double budget = 2 * g_min_seconds * 1e9, start = thread_cpu_ns();
    while (ta.size() < 101 && (ta.size() < 5 || thread_cpu_ns() - start < budget)) {
        ta.push_back(detail::round_ns_per_call(ours, na));
        tb.push_back(detail::round_ns_per_call(peer, nb));
    }
    return Pair{summarize(ta), summarize(tb)};
}

// The pair's line; goal_ratio > 0 adds whether peer median / ours median reaches it.
void report(const std::string& what, const Pair& t, const std::string& peer,
            double goal_ratio = 0);
// Both sides divided by the same count (per point, per sample, ...).
Pair per(const Pair& t, double count);
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
