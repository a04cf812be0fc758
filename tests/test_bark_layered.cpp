// Tests for lib/shitsukan/bark: layer_schedule (§4.1, Fig. 7) and layered_bark (§4.2-4.3,
// Table 4): the radii over time, the peeling rules on synthetic surfaces, the repeat of cycles.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>

#include "shitsukan/bark/bark.hpp"

using namespace shitsukan;

TEST_CASE("the layer schedule: continuous through each role change, middle (2) reaches D at kT") {
    LayerSchedule s;
    for (int k = 1; k <= 6; ++k) {
        const float t = s.T * float(k);
        const LayerRadii before = layer_radii(s, t, true), after = layer_radii(s, t);
        CHECK(before.cycle == k - 1);
        CHECK(after.cycle == k);
        CHECK(before.middle2_thickness == doctest::Approx(s.D));  // the cycle's definition
        CHECK(after.middle2_thickness == 0.0f);                   // a new middle (2)
        // middle (1) -> surface, middle (2) -> middle (1): same radius across the change.
        CHECK(std::fabs(before.middle1 - after.surface) < 1e-5f);
        CHECK(std::fabs(before.middle2 - after.middle1) < 1e-5f);
        CHECK(std::fabs(before.inner - after.inner) < 1e-5f);
    }
    // Per cycle a layer moves out by delta_R + D (middle (1) at 1.5 T is the surface at 2.5 T),
    // the inner layer by delta_R.
    const LayerRadii a = layer_radii(s, 1.5f * s.T), b = layer_radii(s, 2.5f * s.T);
    CHECK(b.surface - a.middle1 == doctest::Approx(s.delta_R + s.D).epsilon(1e-4));
    // Middle (2)'s node rises by delta_R + D/2 over its cycle (born at r_in, ends at r_in + D/2).
    CHECK(layer_radii(s, 2 * s.T, true).middle2 - layer_radii(s, s.T).middle2 ==
          doctest::Approx(s.delta_R + 0.5f * s.D).epsilon(1e-4));
    CHECK(b.inner - a.inner == doctest::Approx(s.delta_R).epsilon(1e-4));
    CHECK(layer_radii(s, 0.5f * s.T).middle2_thickness == doctest::Approx(0.5f * s.D));
}

namespace {

LayeredParams small_params() {
    LayeredParams p;
    p.N_R = 16, p.N_H = 12, p.cycles = 2, p.spin_up_cycles = 1, p.steps_per_cycle = 10;
    return p;
}

}  // namespace

TEST_CASE("peeling rules: a region falls when region / bonded area > A, always when unbonded") {
    LayeredBark bark;
    REQUIRE(bark.build(small_params()).ok());
    const BarkCylinder& lat = bark.lattice();
    // Nothing debonded, no crack: one region, fully bonded: stays.
    CHECK(bark.peel_regions(0.0f) == 0);
    // Cut a block of 4 columns x 4 rows out of the surface by breaking every spring across its
    // boundary.
    auto inside = [&](int p) {
        const int c = lat.column_of(p), r = lat.row_of(p);
        return c >= 4 && c < 8 && r >= 4 && r < 8;
    };
    for (int s = 0; s < lat.net.spring_count(); ++s) {
        const BarkSpring& sp = lat.net.springs[std::size_t(s)];
        if (inside(int(sp.i)) != inside(int(sp.j))) bark.break_surface_spring(s, 0.0f);
    }
    CHECK(bark.peel_regions(0.0f) == 0);  // both regions still bonded
    // Debond 40 % of the block: region / bonded = 1 / 0.6 < 2: stays.
    int block[16], nb = 0;
    for (int p = 0; p < lat.net.node_count(); ++p)
        if (inside(p)) block[nb++] = p;
    REQUIRE(nb == 16);
    for (int i = 0; i < 6; ++i) bark.debond(block[i]);
    CHECK(bark.peel_regions(0.0f) == 0);
    CHECK(bark.surface_alive(block[0]));
    // Debond 60 %: 1 / 0.4 > 2: falls; the rest of the surface stays.
    for (int i = 6; i < 10; ++i) bark.debond(block[i]);
    CHECK(bark.peel_regions(0.0f) == 1);
    for (int i = 0; i < 16; ++i) CHECK(!bark.surface_alive(block[i]));
    CHECK(bark.surface_alive(lat.node(0, 0)));
    // A fully debonded node region falls even when tiny.
}

TEST_CASE("drying: only within eta of a crack; kappa_h falls by (1 - gamma) per dt_ref") {
    LayeredParams p = small_params();
    LayeredBark bark;
    REQUIRE(bark.build(p).ok());
    const BarkCylinder& lat = bark.lattice();
    const int s = lat.spring(8, 6, 0);  // a vertical spring in the middle
    REQUIRE(s >= 0);
    bark.break_surface_spring(s, 0.0f);
    bark.update_drying_zone();
    const BarkSpring& sp = lat.net.springs[std::size_t(s)];
    const Vec3 mid = lat.net.X[sp.i] + sp.n * (0.5f * sp.l0);
    const float period = float(p.N_R) * lat.a_h;
    int dry = 0;
    for (int q = 0; q < lat.net.node_count(); ++q) {
        Vec3 d = lat.net.X[std::size_t(q)] - mid;
        d.x -= period * std::round(d.x / period);
        CAPTURE(q);
        CHECK(bark.in_drying_zone(q) == (length(d) <= p.peeling.eta));
        dry += bark.in_drying_zone(q);
    }
    CHECK(dry >= 2);
    const int in = int(sp.i), out = lat.node(0, 0);
    const float k_in = bark.critical_shear_strain(in), k_out = bark.critical_shear_strain(out);
    const float dt_ref = p.schedule.T / float(p.peeling.dt_ref_steps);
    bark.apply_drying(2.0f * dt_ref);
    CHECK(bark.critical_shear_strain(in) ==
          doctest::Approx(k_in * (1 - p.peeling.gamma) * (1 - p.peeling.gamma)).epsilon(1e-5));
    CHECK(bark.critical_shear_strain(out) == k_out);
}

TEST_CASE("four layers over cycles: the process repeats (fig. 8's checks on a small patch)") {
    LayeredParams p;
    p.N_R = 32, p.N_H = 24, p.cycles = 4, p.spin_up_cycles = 2;
    LayeredBark bark;
    REQUIRE(bark.build(p).ok());
    const FrameRequest frames[] = {{3.0f * p.schedule.T, true}, {3.0f * p.schedule.T, false}};
    REQUIRE(bark.run(frames, 2).ok());
    REQUIRE(bark.frames().size() == 2);
    // Before the role change much of the surface is gone; after it, all of it is back on.
    int before = 0, after = 0;
    for (std::uint8_t a : bark.frames()[0].surface_alive) before += a;
    for (std::uint8_t a : bark.frames()[1].surface_alive) after += a;
    CHECK(after == 32 * 24);
    CHECK(before < after);
    for (int k = 2; k < 4; ++k) {
        float at06 = 0, at_end = 0;
        int surface = 0, middle = 0;
        for (const LayeredStep& s : bark.record()) {
            const float tau = s.t / p.schedule.T - float(k);
            if (!s.role_change && std::fabs(tau - 0.6f) < 0.011f) at06 = s.alive_fraction;
            if (!s.role_change && std::fabs(tau - 1.0f) < 1e-4f)
                at_end = s.alive_fraction, surface = s.surface_broken, middle = s.middle1_broken;
        }
        CAPTURE(k);
        CHECK(at06 >= 0.9f);     // most of the surface is on early in the cycle
        CHECK(at_end <= 0.8f);   // much of it has fallen by the end
        CHECK(bark.regions_peeled_in_cycle(k) >= 3);
        CHECK(float(middle) < 0.75f * float(surface));  // the covered layer is less cracked
    }
    // Deterministic: the same run twice gives the same record.
    LayeredBark again;
    REQUIRE(again.build(p).ok());
    REQUIRE(again.run(nullptr, 0).ok());
    REQUIRE(again.record().size() == bark.record().size());
    bool same = true;
    for (std::size_t i = 0; i < again.record().size(); ++i)
        same = same && again.record()[i].alive_fraction == bark.record()[i].alive_fraction &&
               again.record()[i].surface_broken == bark.record()[i].surface_broken;
    CHECK(same);
}

TEST_CASE("layered bark: bad Table 4 values and sizes get a Status") {
    LayeredParams p;
    CHECK(validate(p).ok());
    LayeredParams q = p;
    q.peeling.A = 0.5f;
    CHECK(validate(q).code() == StatusCode::invalid_argument);
    q = p, q.peeling.gamma = 1.0f;
    CHECK(validate(q).code() == StatusCode::invalid_argument);
    q = p, q.peeling.kappa_h = std::nanf("");
    CHECK(validate(q).code() == StatusCode::invalid_argument);
    q = p, q.peeling.eta = -1.0f;
    CHECK(validate(q).code() == StatusCode::invalid_argument);
    q = p, q.N_R = 63;
    CHECK(validate(q).code() == StatusCode::invalid_argument);
    q = p, q.spin_up_cycles = 5;
    CHECK(validate(q).code() == StatusCode::invalid_argument);
    q = p, q.schedule.D = 0;
    CHECK(validate(q).code() == StatusCode::invalid_argument);
    LayeredBark bark;
    CHECK(bark.run(nullptr, 0).code() == StatusCode::invalid_argument);  // not built
    REQUIRE(bark.build(small_params()).ok());
    const FrameRequest late[] = {{1e6f, false}};
    CHECK(bark.run(late, 1).code() == StatusCode::invalid_argument);
}

// eta is any finite value >= 0: eta / L0 past INT_MAX was converted to int (undefined) and the
// window loops ran over billions of cells; the window is now the lattice at most.
TEST_CASE("drying: an eta wider than the patch dries every node, at once") {
    for (float eta : {1e3f, 1e30f}) {
        LayeredParams p = small_params();
        p.peeling.eta = eta;
        LayeredBark bark;
        REQUIRE(bark.build(p).ok());
        const int s = bark.lattice().spring(8, 6, 0);
        REQUIRE(s >= 0);
        bark.break_surface_spring(s, 0.0f);
        bark.update_drying_zone();
        for (int q = 0; q < bark.lattice().net.node_count(); ++q) CHECK(bark.in_drying_zone(q));
    }
}
