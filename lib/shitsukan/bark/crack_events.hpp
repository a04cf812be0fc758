// shitsukan/bark/crack_events.hpp — hirota1998 §3: growth and cracking, one break at a time.
//
// Manual
//   CylinderParams params;  params.N_R = 16;  params.N_H = 12;  // chosen 128 x 64
//   BarkCylinder bark;  Status s = build_cylinder(params, bark);
//   CrackRun run;
//   const float snaps[] = {0.6f * params.T};
//   CrackRunOptions opt;  opt.snapshot_times = snaps;  opt.snapshot_count = 1;
//   if (s) s = grow_and_crack(bark, opt, run);     // run.breaks: (spring, time) in order
//   return s;
//
// The paper grows the inner layer and lets a spring break "when its elongation passes its
// critical value" (§3.1, Table 1 kappa, sigma); a broken spring is gone for good. Here
// (quasi-static, linear: spring_network.hpp) spring s has strain e_s(t) = t·E_s for the
// current set of intact springs, so the next spring to break is the one with the smallest
//     t_s = eps_c,s / E_s     (E_s > 0: tension only; compression never breaks)
// and there is no time step: jump to it, break it, re-solve around it (relax), update the t_s
// of the springs that moved, repeat until T. A spring already past its threshold after a
// re-solve breaks "now" (a cascade). Ties go to the smaller canonical key, never to storage
// order. The loop (next event, break, relax, update) is break_loop.hpp's, shared with the
// four-layer bark; a min-tree over the springs gives the next event in O(log n).
//
// Snapshots: the displacement field W valid at each requested time (before the breaks that
// come later), so a figure can draw the bark at 0.6 T, 0.75 T, ... from one run. An observer
// (break_loop.hpp) sees every break after its re-solve, in the order of `breaks`, one call
// each (item = the spring, t = its time): W then is the field valid until the next break.
#pragma once

#include <cstdint>
#include <vector>

#include "shitsukan/bark/break_loop.hpp"
#include "shitsukan/bark/cylinder_lattice.hpp"
#include "shitsukan/bark/spring_network.hpp"

namespace shitsukan {

struct BreakEvent {
    std::uint32_t spring = 0;
    float t = 0;  // time of the break
};

struct CrackSnapshot {
    float t = 0;
    int break_count = 0;   // breaks at or before t
    std::vector<Vec3> W;   // displacement field valid at t
};

// Progress callback: fraction of T reached (the library never prints).
using BarkProgress = void (*)(float fraction, void* user);

struct CrackRunOptions {
    const float* snapshot_times = nullptr;  // ascending, in (0, T]
    int snapshot_count = 0;
    BarkProgress progress = nullptr;
    void* progress_user = nullptr;
    BreakObserver observer;  // optional: each break, after its re-solve
};

struct CrackRun {
    std::vector<BreakEvent> breaks;
    std::vector<CrackSnapshot> snapshots;
    int cascade_breaks = 0;             // breaks whose threshold was passed during a re-solve
    std::uint64_t node_updates = 0;     // solver work
    float tolerance = 0;                // absolute tolerance used (cm/s of W)
};

// Generic driver: a network whose strains grow as t·E_s, from t = 0 to T. tol is the
// relaxation tolerance on W.
Status run_cracking(SpringNetwork& net, float T, float tol, const CrackRunOptions& options,
                    CrackRun& out);

// Both return out_of_range when the displacement field (at T or at a snapshot) overflows a
// float: growth rates or moduli far beyond the bark's; never a non-finite W with an ok Status.
// The two-layer cylinder from t = 0 to params.T, tolerance tau·L0·max g_s.
Status grow_and_crack(BarkCylinder& bark, const CrackRunOptions& options, CrackRun& out);

// A 64-bit hash of the break sequence (canonical keys in order): determinism checks.
std::uint64_t break_sequence_hash(const SpringNetwork& net, const CrackRun& run, int count);

}  // namespace shitsukan
