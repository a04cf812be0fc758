// build/bench — runs every SHITSUKAN_BENCH in tests/bench/, printing "bench:" lines.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <thread>
#include <string>
#include <utility>
#include <vector>

#include "bench.hpp"

namespace bench {

double g_min_seconds = 0.2;
volatile double g_sink = 0.0;

namespace {
std::vector<std::pair<const char*, BenchFunction>>& registry() {
    static std::vector<std::pair<const char*, BenchFunction>> list;
    return list;
}
}  // namespace

bool register_bench(const char* name, BenchFunction fn) {
    registry().push_back({name, fn});
    return true;
}

Timing summarize(std::vector<double> v) {
    Timing t;
    if (v.empty()) return t;
    std::sort(v.begin(), v.end());
    auto at = [&](double q) {  // the q-quantile, linear between ranks
        const double r = q * double(v.size() - 1);
        const std::size_t k = std::size_t(r);
        return k + 1 < v.size() ? v[k] + (r - double(k)) * (v[k + 1] - v[k]) : v[k];
    };
    t.best = v.front();
    t.median = at(0.5);
    t.spread = t.median > 0 ? (at(0.75) - at(0.25)) / t.median : 0.0;
    return t;
}

Pair per(const Pair& t, double count) {
    Pair p = t;
    for (Timing* s : {&p.ours, &p.peer}) s->best /= count, s->median /= count;
    return p;
}

void report(const std::string& what, const Pair& t, const std::string& peer, double goal_ratio) {
    const double ratio = t.ours.median > 0 ? t.peer.median / t.ours.median : 0.0;
    const double best_ratio = t.ours.best > 0 ? t.peer.best / t.ours.best : 0.0;
    std::printf("bench: %s: shitsukan %.1f ns (best %.1f, spread %.0f%%), %s %.1f ns (best %.1f, "
                "spread %.0f%%), ratio %.2f (best to best %.2f)",
                what.c_str(), t.ours.median, t.ours.best, 100 * t.ours.spread, peer.c_str(),
                t.peer.median, t.peer.best, 100 * t.peer.spread, ratio, best_ratio);
    if (goal_ratio > 0)
        std::printf(", goal ratio >= %.2f: %s", goal_ratio, ratio >= goal_ratio ? "met" : "NOT met");
    std::printf("\n");
    std::fflush(stdout);
}

void info(const std::string& what, const std::string& text) {
    std::printf("bench: %s: %s\n", what.c_str(), text.c_str());
    std::fflush(stdout);
}

bool set_up(const shitsukan::Status& s, const char* what) {
    if (!s) info(what, std::string("set-up failed: ") + s.message());
    return s.ok();
}

bool timed_calls_ok(bool ok, const char* what) {
    if (!ok) info(what, "a call inside the timed loop failed: no timing");
    return ok;
}

}  // namespace bench

namespace {
// "bench: machine: <n> cores, load average <1 min> <5 min> <15 min> <when>": timings under
// load are not a quiet machine's (docs/MEASUREMENTS.md shows this line beside them).
void machine_line(const char* when) {
    char load[64] = "unknown";
    if (std::FILE* f = std::fopen("/proc/loadavg", "r")) {
        double a = 0, b = 0, c = 0;
        if (std::fscanf(f, "%lf %lf %lf", &a, &b, &c) == 3)
            std::snprintf(load, sizeof load, "%.2f %.2f %.2f", a, b, c);
        std::fclose(f);
    }
    std::printf("bench: machine: %u cores, load average %s %s\n",
                std::thread::hardware_concurrency(), load, when);
    std::fflush(stdout);
}
}  // namespace

int main(int argc, char** argv) {
    std::string only;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--quick"))
            bench::g_min_seconds = 0.03;
        else if (!std::strcmp(argv[i], "--only") && i + 1 < argc)
            only = argv[++i];
        else {
            std::fprintf(stderr, "usage: bench [--quick] [--only SUBSTRING]\n");
            return 2;
        }
    }
    auto list = bench::registry();
    machine_line("at the start");
    std::sort(list.begin(), list.end(),
              [](auto& a, auto& b) { return std::strcmp(a.first, b.first) < 0; });
    for (auto& [name, fn] : list)
        if (only.empty() || std::string(name).find(only) != std::string::npos) fn();
    machine_line("at the end");
    return 0;
}
