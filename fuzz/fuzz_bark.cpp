// fuzz/fuzz_bark.cpp — the bark pipeline of hirota1998 §3 on any parameters, small sizes:
// build_cylinder (N_R, N_H, Table 1/2 values, each raw or near its preset), grow_and_crack
// with snapshots, measure_regions at T and at a snapshot, crack_map_size and draw_crack_map
// onto a map of at most 64 x 64 pixels (the memory budget is 16 MiB, so a grown trunk too big
// for it is refused by crack_map_size, the bark tool's failure of old: a crash on bad_alloc).
// Contracts: a non-ok Status, or
//   cylinder: N_R·N_H nodes, finite positive circumference;
//   run: breaks in time order within [0, T], each spring at most once, at most every spring;
//     W finite; snapshots in order with break counts that never decrease;
//   regions: one label per node, each -1 or a region index; region node counts sum to the
//     labelled nodes; sizes finite and >= 0;
//   map: crack_map_size's sides >= 8 and within the budget; drawing ok on that canvas.
#include <cmath>
#include <vector>

#include "fuzz_input.hpp"
#include "shitsukan/bark/bark.hpp"
#include "shitsukan/core/memory_budget.hpp"
#include "shitsukan/image/image.hpp"
#include "shitsukan/image/raster_canvas.hpp"
#include "shitsukan/render/bark_crack_map.hpp"

using namespace shitsukan;

namespace {

// Near a preset value (scaled by 2^(k/8), k in -64..63) most of the time, raw bits sometimes.
float near(fuzz::Input& in, float preset) {
    const std::uint8_t mode = in.take<std::uint8_t>();
    if ((mode & 15) == 15) return in.take<float>();
    return preset * std::exp2(float(std::int8_t(in.take<std::uint8_t>())) / 8.0f);
}

bool finite3(Vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void check_regions(const BarkCylinder& bark, const RegionReport& rep) {
    const std::size_t nodes = std::size_t(bark.params.N_R) * std::size_t(bark.params.N_H);
    FUZZ_REQUIRE(rep.label.size() == nodes);
    std::vector<int> count(rep.regions.size(), 0);
    for (std::int32_t l : rep.label) {
        FUZZ_REQUIRE(l >= -1 && l < std::int32_t(rep.regions.size()));
        if (l >= 0) ++count[std::size_t(l)];
    }
    for (std::size_t i = 0; i < rep.regions.size(); ++i) {
        const BarkRegion& r = rep.regions[i];
        FUZZ_REQUIRE(r.nodes == count[i]);
        FUZZ_REQUIRE(std::isfinite(r.width) && r.width >= 0 && std::isfinite(r.height) &&
                     r.height >= 0);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    set_memory_budget(std::uint64_t(16) << 20);
    fuzz::Input in(data, size);
    CylinderParams p;
    p.species = species_preset(Species(in.take<std::uint8_t>() % 3));
    p.N_R = 2 * int(in.take<std::uint8_t>() % 9);        // 0 .. 16 (below 4 is refused)
    p.N_H = int(in.take<std::uint8_t>() % 12);           // 0 .. 11
    p.species.L0 = near(in, p.species.L0);
    p.species.E1 = near(in, p.species.E1);
    p.species.E2 = near(in, p.species.E2);
    p.species.G = near(in, p.species.G);
    p.species.kappa1 = 1.0f + near(in, p.species.kappa1 - 1.0f);
    p.species.kappa2 = 1.0f + near(in, p.species.kappa2 - 1.0f);
    p.D = near(in, p.D);
    p.sigma = near(in, p.sigma);
    p.T = near(in, p.T);
    p.delta_r = near(in, p.delta_r);
    p.delta_h = near(in, p.delta_h);
    p.tolerance = near(in, p.tolerance);
    p.seed = in.take<std::uint32_t>();
    BarkCylinder bark;
    if (!build_cylinder(p, bark)) return 0;
    FUZZ_REQUIRE(bark.net.W.size() == std::size_t(p.N_R) * std::size_t(p.N_H));
    FUZZ_REQUIRE(std::isfinite(bark.circumference) && bark.circumference > 0);
    const float snaps[2] = {0.5f * p.T, p.T};
    CrackRunOptions opt;
    opt.snapshot_times = snaps;
    opt.snapshot_count = in.take<std::uint8_t>() % 3;
    CrackRun run;
    if (!grow_and_crack(bark, opt, run)) return 0;
    const std::size_t springs = bark.net.springs.size();
    FUZZ_REQUIRE(run.breaks.size() <= springs);
    std::vector<std::uint8_t> broken(springs, 0);
    float last = 0.0f;
    for (const BreakEvent& b : run.breaks) {
        FUZZ_REQUIRE(b.spring < springs && !broken[b.spring]);
        broken[b.spring] = 1;
        FUZZ_REQUIRE(b.t >= last && b.t <= p.T);
        last = b.t;
    }
    for (const Vec3& w : bark.net.W) FUZZ_REQUIRE(finite3(w));
    FUZZ_REQUIRE(run.snapshots.size() == std::size_t(opt.snapshot_count));
    for (std::size_t i = 0; i < run.snapshots.size(); ++i) {
        FUZZ_REQUIRE(run.snapshots[i].W.size() == bark.net.W.size());
        if (i > 0) FUZZ_REQUIRE(run.snapshots[i].break_count >= run.snapshots[i - 1].break_count);
    }
    RegionReport rep;
    if (measure_regions(bark, p.T, bark.net.W.data(), rep)) check_regions(bark, rep);
    if (!run.snapshots.empty()) {
        RegionReport at;
        const CrackSnapshot& s = run.snapshots[0];
        if (measure_regions(bark, s.t, s.W.data(), at)) check_regions(bark, at);
    }
    // The map: its size from the grown trunk, checked; drawn on at most 64 x 64 pixels.
    const float px_per_cm = near(in, 4.0f);
    int w = 0, h = 0;
    if (!crack_map_size(bark, p.T, px_per_cm, w, h)) return 0;
    FUZZ_REQUIRE(w >= 8 && h >= 8);
    FUZZ_REQUIRE(std::uint64_t(w) * std::uint64_t(h) * 3 <= memory_budget());
    RgbImage map;
    FUZZ_REQUIRE(map.try_resize(w < 64 ? w : 64, h < 64 ? h : 64).ok());
    RasterCanvas canvas(map.view());
    CrackMapStyle style;
    style.origin = {0.0f, float(map.height())};
    style.px_per_cm = px_per_cm;
    style.min_width_cm = 1.0f / px_per_cm;
    style.regions = (in.take<std::uint8_t>() & 1) ? &rep : nullptr;
    if (style.regions && rep.label.empty()) style.regions = nullptr;
    if (!draw_crack_map(canvas, bark, p.T, bark.net.W.data(), style)) return 0;
    return 0;
}
