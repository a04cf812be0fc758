// Tests for lib/shitsukan/bark/break_loop: the one break-relax-update loop of both bark models,
// and its observer (every event, in order, with the field valid after it).
#include <doctest/doctest.h>

#include <cstring>
#include <vector>

#include "shitsukan/bark/bark.hpp"
#include "shitsukan/core/hash.hpp"

using namespace shitsukan;

namespace {

struct Seen {
    std::vector<BreakLoopEvent> events;
    std::vector<std::vector<Vec3>> W;     // the field at each event (cylinder only)
    std::vector<std::uint8_t> was_broken;  // the item's spring broken when observed
    bool keep_W = false;
    int layer_springs = 0;                 // layered: items below are lattice springs
};

void see(const BreakLoopEvent& e, const SpringNetwork& net, void* user) {
    Seen& s = *static_cast<Seen*>(user);
    BreakLoopEvent copy = e;
    copy.seeds = nullptr, copy.touched = nullptr;  // valid only during the call
    s.events.push_back(copy);
    if (s.keep_W) s.W.push_back(net.W);
    const bool spring = s.layer_springs == 0 || int(e.item) < s.layer_springs;
    s.was_broken.push_back(spring ? std::uint8_t(!net.springs[e.item].intact()) : 1);
}

CylinderParams small_cylinder() {
    CylinderParams p;
    p.N_R = 16, p.N_H = 12;
    return p;
}

}  // namespace

TEST_CASE("the cylinder's observer sees every break of run.breaks, in order, once each") {
    BarkCylinder bark;
    REQUIRE(build_cylinder(small_cylinder(), bark).ok());
    Seen seen;
    seen.keep_W = true;
    CrackRunOptions opt;
    opt.observer.on_event = see;
    opt.observer.user = &seen;
    CrackRun run;
    REQUIRE(grow_and_crack(bark, opt, run).ok());
    REQUIRE(run.breaks.size() > 20);
    REQUIRE(seen.events.size() == run.breaks.size());
    for (std::size_t k = 0; k < run.breaks.size(); ++k) {
        CHECK(seen.events[k].index == int(k));
        CHECK(seen.events[k].item == run.breaks[k].spring);
        CHECK(seen.events[k].t == run.breaks[k].t);
        CHECK(seen.was_broken[k] == 1);
        CHECK(seen.events[k].seed_count == 2);
    }
    // The field after the last break is the final one.
    CHECK(std::memcmp(seen.W.back().data(), bark.net.W.data(), bark.net.W.size() * sizeof(Vec3)) ==
          0);
    // The field the observer saw after break k is the one a snapshot between k and k + 1 keeps
    // (replaying a run from its observer draws what the snapshots draw).
    std::vector<float> times;
    std::vector<std::size_t> after;
    for (std::size_t k = 0; k + 1 < run.breaks.size() && times.size() < 8; k += 3)
        if (run.breaks[k].t < run.breaks[k + 1].t && (times.empty() || run.breaks[k].t > times.back()))
            times.push_back(run.breaks[k].t), after.push_back(k);
    REQUIRE(times.size() >= 3);
    BarkCylinder again;
    REQUIRE(build_cylinder(small_cylinder(), again).ok());
    CrackRunOptions snap;
    snap.snapshot_times = times.data();
    snap.snapshot_count = int(times.size());
    CrackRun rerun;
    REQUIRE(grow_and_crack(again, snap, rerun).ok());
    REQUIRE(rerun.snapshots.size() == times.size());
    for (std::size_t i = 0; i < times.size(); ++i) {
        CHECK(rerun.snapshots[i].break_count == int(after[i] + 1));
        CHECK(std::memcmp(rerun.snapshots[i].W.data(), seen.W[after[i]].data(),
                          seen.W[after[i]].size() * sizeof(Vec3)) == 0);
    }
}

TEST_CASE("an observer changes nothing: the same breaks with and without it") {
    BarkCylinder a, b;
    REQUIRE(build_cylinder(small_cylinder(), a).ok());
    REQUIRE(build_cylinder(small_cylinder(), b).ok());
    Seen seen;
    CrackRunOptions opt;
    opt.observer.on_event = see;
    opt.observer.user = &seen;
    CrackRun ra, rb;
    REQUIRE(grow_and_crack(a, CrackRunOptions{}, ra).ok());
    REQUIRE(grow_and_crack(b, opt, rb).ok());
    const int n = int(ra.breaks.size());
    CHECK(int(rb.breaks.size()) == n);
    CHECK(break_sequence_hash(a.net, ra, n) == break_sequence_hash(b.net, rb, n));
    CHECK(ra.node_updates == rb.node_updates);
}

TEST_CASE("the four-layer bark's observer: every break and debonding of its loop, in order") {
    LayeredParams p;
    p.N_R = 16, p.N_H = 12, p.cycles = 2, p.spin_up_cycles = 1, p.steps_per_cycle = 10;
    auto run = [&](Seen* seen, std::uint64_t* hash) {
        LayeredBark bark;
        REQUIRE(bark.build(p).ok());
        if (seen) {
            seen->layer_springs = 2 * bark.lattice().net.spring_count();
            bark.observe(BreakObserver{see, seen});
        }
        REQUIRE(bark.run(nullptr, 0).ok());
        std::uint64_t h = hash_start(1, 2);
        for (const LayeredStep& s : bark.record())
            h = hash_add(h, std::uint64_t(s.surface_broken) * 65536u + std::uint64_t(s.debonded));
        *hash = h;
        return bark.loop_events();
    };
    Seen seen;
    std::uint64_t with = 0, without = 0;
    const int events = run(&seen, &with);
    run(nullptr, &without);
    CHECK(with == without);  // observing changes nothing
    REQUIRE(events > 50);
    REQUIRE(int(seen.events.size()) == events);
    int springs = 0, debonds = 0;
    for (std::size_t k = 0; k < seen.events.size(); ++k) {
        const BreakLoopEvent& e = seen.events[k];
        CHECK(e.index == int(k));
        CHECK(e.value < 1.0f);  // a ratio past its threshold
        CHECK(seen.was_broken[k] == 1);
        CHECK(e.seed_count >= 2);
        if (k > 0) CHECK(e.t >= seen.events[k - 1].t);
        (int(e.item) < seen.layer_springs ? springs : debonds) += 1;
    }
    CHECK(springs > 0);
    CHECK(debonds > 0);
}
