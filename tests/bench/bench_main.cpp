// build/bench — runs every SHITSUKAN_BENCH in tests/bench/, printing "bench:" lines.
#include <algorithm>
#include <cstring>
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

void report(const std::string& what, double ours_ns, const std::string& peer, double peer_ns) {
    std::printf("bench: %s: shitsukan %.1f ns, %s %.1f ns, ratio %.2f\n", what.c_str(), ours_ns,
                peer.c_str(), peer_ns, ours_ns > 0 ? peer_ns / ours_ns : 0.0);
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
    std::sort(list.begin(), list.end(),
              [](auto& a, auto& b) { return std::strcmp(a.first, b.first) < 0; });
    for (auto& [name, fn] : list)
        if (only.empty() || std::string(name).find(only) != std::string::npos) fn();
    return 0;
}
