// shitsukan/bark/layered_bark.hpp — hirota1998 §4: the four-layer bark growing over several
// cycles: cracking, peeling (Table 4), falling off, new layers.
//
// Manual
//   LayeredParams p;                          // pine, a 64 x 48 patch of a 30 cm trunk
//   p.N_R = 24, p.N_H = 16, p.cycles = 4, p.spin_up_cycles = 1;   // smaller, to be quick
//   LayeredBark bark;
//   Status s = bark.build(p);
//   const FrameRequest frames[] = {{2.6f * p.schedule.T, false}, {3.0f * p.schedule.T, true}};
//   if (s) s = bark.run(frames, 2);           // every cycle, 50 steps each
//   // bark.record(): per step: time, alive and bonded fractions, breaks, peels
//   // bark.frames(): the requested states (which nodes are alive, bonded, which springs broke)
//   return s;
//
// The model (§4.1-4.2; radii over time in layer_schedule.hpp). Two layers are mechanical:
// the surface and middle (1), each a lattice of nodes and springs like the two-layer cylinder
// (cylinder_lattice.hpp), here a patch N_R columns wide, periodic around the trunk, free at
// top and bottom. Middle (1) is tied to middle (2) below by unbreakable shear springs; the
// surface is tied to middle (1) by shear springs that break (peeling): "a critical shear
// strain is set between the surface and middle (1); peeling is represented by cutting shear
// springs on the basis of the interlayer shear stress caused by growth". Middle (2) and the
// inner layer are moved by the growth. Both mechanical layers crack with Table 2's thresholds.
//
// Each mechanical layer is born stress-free when it becomes middle (1) (chosen here: cork is
// dead tissue; it only follows its substrate) and is pulled by the growth of the layer below:
// its spring s feels the growth strain
//     g_s(t) = (r(t)/r_b - 1)·n_u^2 + (s_z(t)/s_b - 1)·n_z^2,
// r(t) the radius of its current role, r_b the radius at birth, s_z = 1 + (axial growth)·t/T.
// With w the displacement from the affinely grown position, spring s has strain
// e_s = g_s + n·(w_j - w_i)/l0, and a surface node's shear strain is |w_surface - w_middle1|/D.
//
// Peeling (§4.2, Table 4; values chosen here, see LayeredParams):
//   - a surface node's shear spring breaks when its shear strain passes kappa_h,i, drawn around
//     the mean kappa_h with spread sigma (coordinate hash, stream 12, per generation);
//   - drying: within eta of a crack or a peeled or debonded place, kappa_h,i falls by the
//     fraction gamma per dt_ref ("over a time dt the critical shear strain decreases by the
//     fraction gamma"; dt_ref = T/50 is the paper's dt, chosen here);
//   - a region of the surface bounded by cracks falls off when its area over its still-bonded
//     area exceeds A (A >= 1; A_bonded = 0 always falls); the layer below is then exposed.
// At each role change (t = kT) what is left of the surface falls off (脱落), middle (1) becomes
// the surface (fully bonded, fresh kappa_h, its cracks kept) and a new middle (1) is born.
//
// Driver (chosen here): quasi-static in fixed steps of T/steps_per_cycle (drying, area rules
// and role changes do not fit an event list); within a step, springs past their threshold
// break one at a time (largest ratio first, the equilibrium re-solved around each), shear
// springs past theirs debond together: the two-layer cylinder's loop (break_loop.hpp), with
// ratios for times. Deterministic: hashed thresholds, canonical ties. An observer (set after
// build) sees each of these events after its re-solve: item < 2·(springs per layer) is that
// network spring broken (the surface's slot: frames' generation tells which), otherwise the
// debonding of every surface node then past its critical shear strain (seeds: their nodes).
// Springs cut when a region falls off are not loop events (the frames and record show them).
#pragma once

#include <cstdint>
#include <vector>

#include "shitsukan/bark/cylinder_lattice.hpp"
#include "shitsukan/bark/break_loop.hpp"
#include "shitsukan/bark/layer_schedule.hpp"
#include "shitsukan/bark/spring_network.hpp"

namespace shitsukan {

// Table 4: the names are given, the values are not (chosen here, docs/papers/hirota1998.md §5).
struct PeelingParams {
    // Mean critical shear strain. Measured interface shear strains: ~0.002 before cracking,
    // mean 0.02, max 0.05 after; 0.08 lets plates lift only where drying has weakened them.
    float kappa_h = 0.08f;
    float eta = 0.33f;    // drying range [cm]: one cell (L0); the front advances a cell per decay
    float gamma = 0.03f;  // drying: fraction of kappa_h lost per dt_ref (0.22 left per cycle)
    float A = 2.0f;       // peel-area ratio region / bonded: a plate falls once half has lifted
    int dt_ref_steps = 50;  // dt_ref = T / 50 (the paper's unnamed dt)
};

struct LayeredParams {
    SpeciesParams species = species_preset(Species::pine);  // Table 3 *3: pine bark peels
    int N_R = 64;               // columns of the patch (periodic around), chosen here
    int N_H = 48;               // rows (free top and bottom), chosen here
    LayerSchedule schedule;     // R_in0 30 cm, D 0.55 cm, delta_R 0.1 cm, T 100 s (chosen here)
    float axial_growth = 0.025f;  // s_z grows by this per cycle (chosen here: a layer that is
                                  // two cycles old reaches 5 % > kappa1 - 1: plates, not strips)
    float sigma = 0.0175f;      // as the two-layer cylinder
    PeelingParams peeling;
    int cycles = 5;             // chosen here: 2 spin-up cycles + 3 shown
    int spin_up_cycles = 2;
    int steps_per_cycle = 50;
    float tolerance = 1e-2f;    // relative to L0 times a cycle's strain (0.02)
    std::uint32_t seed = 1998;
};

Status validate(const LayeredParams& p);

// A state to keep: at time t; at t = kT, before (true) or after the role change.
struct FrameRequest {
    float t = 0;
    bool before_role_change = false;
};

struct LayerFrame {
    float t = 0;
    bool before_role_change = false;
    int generation_surface = 0, generation_middle1 = 0;
    std::vector<std::uint8_t> surface_alive, surface_bonded;      // per lattice node
    std::vector<std::uint8_t> surface_broken, middle1_broken;     // per lattice spring
    std::vector<Vec3> surface_position, middle1_position;         // unrolled (u, z) [cm]
    float surface_period = 0, middle1_period = 0;  // the patch's width in each layer (grown)
};

struct LayeredStep {
    float t = 0;
    float alive_fraction = 0;   // surface area still on the trunk / patch area
    float bonded_fraction = 0;  // of it still bonded to middle (1)
    int surface_broken = 0, middle1_broken = 0;  // broken springs in each layer now
    int peeled_regions = 0;     // regions that fell off in this step
    int debonded = 0;           // shear springs that broke in this step
    bool role_change = false;   // the step ended with a role change
};

class LayeredBark {
public:
    Status build(const LayeredParams& params);
    // Runs every cycle; frames requested in time order. progress: fraction of the run.
    Status run(const FrameRequest* frames, int frame_count,
               void (*progress)(float, void*) = nullptr, void* user = nullptr);

    const LayeredParams& params() const { return params_; }
    const BarkCylinder& lattice() const { return lattice_; }  // topology, areas (one layer)
    const std::vector<LayeredStep>& record() const { return record_; }
    const std::vector<LayerFrame>& frames() const { return frames_; }
    // Every break and debonding of the loop, in order, after its re-solve (call after build).
    void observe(const BreakObserver& observer) { observer_ = observer; }
    int loop_events() const { return loop_.events(); }
    int surface_slot() const { return surface_slot_; }  // network nodes [slot·n, (slot+1)·n)
    int regions_peeled_in_cycle(int cycle) const;

    // Pieces, public for the tests and for teaching:
    // s_z(t) = 1 + (axial growth)·t/T: the axial scale every layer's growth strain uses
    float axial_scale(float t) const;
    // regions of the surface (strong connectivity among alive nodes) that fall off now
    int peel_regions(float t);
    void debond(int node);                  // breaks node's shear spring to middle (1)
    void break_surface_spring(int spring, float t);
    bool in_drying_zone(int node) const { return dry_[std::size_t(node)] != 0; }
    float critical_shear_strain(int node) const { return kappa_h_[std::size_t(node)]; }
    bool surface_alive(int node) const { return alive_[std::size_t(node)] != 0; }
    bool surface_bonded(int node) const { return bonded_[std::size_t(node)] != 0; }
    void update_drying_zone();
    void apply_drying(float dt);

private:
    int lattice_node(int slot, int p) const { return slot * n_ + p; }
    int lattice_spring(int slot, int s) const { return slot * m_ + s; }
    int tie_spring(int p, int axis) const { return 2 * m_ + 2 * p + axis; }
    Status step(float t, float dt);
    void set_loads(float t);
    Status relax_all();
    Status break_until_stable(float t);
    void role_change(float t);
    void reset_middle1(int slot, float t);
    void keep_frame(float t, bool before);
    void keep_record(float t, int peeled, int debonded, bool role_change);
    float tension_ratio(int network_spring) const;
    float shear_ratio(int node) const;

    LayeredParams params_;
    BarkCylinder lattice_;  // one layer's topology, areas and constants
    SpringNetwork net_;     // both mechanical layers + ties
    int n_ = 0, m_ = 0;     // nodes and springs per layer
    int surface_slot_ = 0;  // which slot is the surface (the other is middle (1))
    int generation_[2] = {0, 1};
    float birth_radius_[2] = {0, 0}, birth_scale_[2] = {1, 1};
    float tol_ = 0;
    std::vector<std::uint8_t> alive_, bonded_, dry_;  // surface nodes
    std::vector<float> kappa_h_;                      // surface nodes' critical shear strain
    std::vector<std::uint8_t> source_done_;           // drying sources already spread
    std::vector<LayeredStep> record_;
    std::vector<LayerFrame> frames_;
    std::vector<std::uint32_t> touched_;
    struct Events;                          // this bark as break_loop.hpp's model
    BreakLoop loop_;                        // break_until_stable's loop, its tree kept across calls
    BreakObserver observer_;
    int step_peeled_ = 0, step_debonded_ = 0;
};

}  // namespace shitsukan
