// Tests for lib/shitsukan/wrinkly/wr_ist_axis with the WR surface: the IST plugged into
// eq. (15), and the locality contrast of fujimoto2000 §3.2 (IST-Bezier global, IST-B-spline
// local).
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "shitsukan/wrinkly/hierarchical_sampling.hpp"
#include "shitsukan/wrinkly/ist_formula.hpp"
#include "shitsukan/wrinkly/wr_ist_axis.hpp"
#include "shitsukan/wrinkly/superposition.hpp"
#include "shitsukan/wrinkly/wr_surface.hpp"
#include "shitsukan/wrinkly/wr_tessellation.hpp"

using namespace shitsukan;

namespace {

WrControlMesh flat_mesh(int cols, int rows) {
    WrControlMesh m = make_control_mesh(cols, rows);
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
            m.at(c, r).position = {float(c), 0.0f, -float(r)};
            m.at(c, r).height = 0.1f + 0.05f * float((c * 5 + r * 3) % 7);
        }
    return m;
}

}  // namespace

TEST_CASE("WrIstAxis: F^0 is the identity and F^k matches ist_inverse in base-interval units") {
    IstAxis ist;
    REQUIRE(ist_fully_connected_axis(3, 1, 6, IstEnds::translation, ist));
    WrIstAxis a;
    REQUIRE(make_wr_ist_axis(ist, 4, a));
    const WrAxis w = a.axis();
    CHECK(w.base_intervals == 6);
    CHECK(w.division == 3);
    for (float s : {0.0f, 0.7f, 2.31f, 5.99f}) {
        CHECK(w.inverse_at(s, 0) == s);
        IstAxis k3;
        REQUIRE(ist_with_iterations(ist, 3, k3));
        CHECK(w.inverse_at(s, 3) ==
              doctest::Approx(6.0 * ist_inverse_double(k3, s / 6.0)).epsilon(1e-5));
    }
    CHECK(!make_wr_ist_axis(ist, kMaxWrLevel + 1, a));
}

TEST_CASE("IST-B-spline: one control point changes the surface only where the IST can carry it") {
    // 16 x 9 points -> 13 x 6 spans. Fully-connected N = 3 (M = 1), K = 2: a parameter in base
    // interval b takes its height from base intervals b - K·M .. b + K·M (eq. 12), and the
    // cubic B-spline point (c, r) acts on spans c-3..c (r-3..r).
    WrControlMesh m = flat_mesh(16, 9);
    const int K = 2, c0 = 8, r0 = 4;
    WrSurface s0, s1;
    REQUIRE(make_wr_surface(m, SurfaceBasis::bspline, 3, s0));
    m.at(c0, r0).height += 0.5f;
    REQUIRE(make_wr_surface(m, SurfaceBasis::bspline, 3, s1));
    IstAxis iu, iv;
    REQUIRE(ist_fully_connected_axis(3, 1, s0.spans_u(), IstEnds::translation, iu));
    REQUIRE(ist_fully_connected_axis(3, 1, s0.spans_v(), IstEnds::translation, iv));
    WrIstAxis au, av;
    REQUIRE(make_wr_ist_axis(iu, K, au));
    REQUIRE(make_wr_ist_axis(iv, K, av));
    REQUIRE(s0.set_axes(au.axis(), av.axis()));
    REQUIRE(s1.set_axes(au.axis(), av.axis()));
    int changed_inside = 0, changed_outside = 0, inside = 0;
    const int steps = 260;
    for (int j = 0; j < steps; ++j)
        for (int i = 0; i < steps; ++i) {
            const float u = (float(i) + 0.5f) / float(steps), v = (float(j) + 0.5f) / float(steps);
            const int bu = int(u * float(s0.spans_u())), bv = int(v * float(s0.spans_v()));
            const bool in = bu >= c0 - 3 - K && bu <= c0 + K && bv >= r0 - 3 - K && bv <= r0 + K;
            const bool diff = s0.wr_attributes(u, v, K).height != s1.wr_attributes(u, v, K).height;
            if (in) {
                ++inside;
                changed_inside += diff;
            } else {
                changed_outside += diff;
            }
        }
    CHECK(changed_outside == 0);
    CHECK(changed_inside > inside / 4);  // and it does reach into the support
}

TEST_CASE("IST-Bezier: one control point changes the surface almost everywhere") {
    WrControlMesh m = flat_mesh(4, 4);
    WrSurface s0, s1;
    REQUIRE(make_wr_surface(m, SurfaceBasis::bezier, 3, s0));
    m.at(1, 2).height += 0.5f;
    REQUIRE(make_wr_surface(m, SurfaceBasis::bezier, 3, s1));
    IstAxis ist;
    REQUIRE(ist_unit_axis(3, 1, ist));
    WrIstAxis au, av;
    REQUIRE(make_wr_ist_axis(ist, 3, au));
    REQUIRE(make_wr_ist_axis(ist, 3, av));
    REQUIRE(s0.set_axes(au.axis(), av.axis()));
    REQUIRE(s1.set_axes(au.axis(), av.axis()));
    int changed = 0, total = 0;
    for (int j = 0; j < 100; ++j)
        for (int i = 0; i < 100; ++i) {
            const float u = (float(i) + 0.5f) / 100.0f, v = (float(j) + 0.5f) / 100.0f;
            changed += s0.wr_attributes(u, v, 3).height != s1.wr_attributes(u, v, 3).height;
            ++total;
        }
    CHECK(changed > total * 95 / 100);
}

TEST_CASE("WR surface with the real IST: zero heights give the base surface") {
    WrControlMesh m = flat_mesh(7, 7);
    for (auto& p : m.points) p.height = 0;
    WrSurface s;
    REQUIRE(make_wr_surface(m, SurfaceBasis::bspline, 3, s));
    IstAxis ist;
    REQUIRE(ist_fully_connected_axis(3, 1, 4, IstEnds::translation, ist));
    WrIstAxis a;
    REQUIRE(make_wr_ist_axis(ist, 4, a));
    REQUIRE(s.set_axes(a.axis(), a.axis()));
    for (float u : {0.0f, 0.21f, 0.5f, 0.83f, 1.0f})
        for (float v : {0.1f, 0.66f})
            CHECK(length(s.wr_point(u, v, 4) - s.base_point(u, v).position) < 1e-6f);
}

TEST_CASE("eq. (20) equals eq. (16) where every step samples (centres of base intervals, odd N)") {
    // For odd N the centre of a base interval is the midpoint of a small interval at every
    // step k, so H^k there is the sample H((F^k)^{-1}(u)) itself, linear or Hermite.
    WrControlMesh m = flat_mesh(8, 7);
    WrSurface s;
    REQUIRE(make_wr_surface(m, SurfaceBasis::bspline, 3, s));
    IstAxis iu, iv;
    REQUIRE(ist_fully_connected_axis(3, 1, s.spans_u(), IstEnds::translation, iu));
    REQUIRE(ist_fully_connected_axis(3, 1, s.spans_v(), IstEnds::translation, iv));
    WrIstAxis au, av;
    REQUIRE(make_wr_ist_axis(iu, 3, au));
    REQUIRE(make_wr_ist_axis(iv, 3, av));
    REQUIRE(s.set_axes(au.axis(), av.axis()));
    for (SampleInterpolation mode : {SampleInterpolation::linear, SampleInterpolation::hermite}) {
        HierarchicalOptions o;
        o.levels = 3;
        o.interpolation = mode;
        HierarchicalSampling hs;
        REQUIRE(sample_hierarchy(s, o, hs));
        for (int i = 0; i < s.spans_u(); ++i)
            for (int j = 0; j < s.spans_v(); ++j) {
                const float u = (float(i) + 0.5f) / float(s.spans_u());
                const float v = (float(j) + 0.5f) / float(s.spans_v());
                const SuperposedSample a = superposed_sampled(s, hs, u, v);
                const WrAttributes b = superposed_attributes_direct(s, u, v, 3);
                CHECK(a.attributes.height == doctest::Approx(b.height).epsilon(1e-4));
            }
    }
}

TEST_CASE("adaptive levels grow with the projected size and stop at the cap") {
    WrControlMesh m = flat_mesh(8, 7);
    for (auto& p : m.points) p.delta = 0.6f;
    WrSurface s;
    REQUIRE(make_wr_surface(m, SurfaceBasis::bspline, 3, s));
    IstAxis iu;
    REQUIRE(ist_fully_connected_axis(3, 1, s.spans_u(), IstEnds::translation, iu));
    WrIstAxis au, av;
    IstAxis iv;
    REQUIRE(ist_fully_connected_axis(3, 1, s.spans_v(), IstEnds::translation, iv));
    REQUIRE(make_wr_ist_axis(iu, 6, au));
    REQUIRE(make_wr_ist_axis(iv, 6, av));
    REQUIRE(s.set_axes(au.axis(), av.axis()));
    const AdaptiveLevels small = choose_adaptive_levels(s, m, 10.0f, 2.0f, 0.5f, 6);
    const AdaptiveLevels large = choose_adaptive_levels(s, m, 1000.0f, 2.0f, 0.5f, 6);
    CHECK(small.grid_level < large.grid_level);
    CHECK(small.sum_levels < large.sum_levels);
    CHECK(large.grid_level <= 6);
    // The rest of the sum after K steps projects below the tolerance (unless capped).
    if (small.sum_levels < 6)
        CHECK(std::pow(0.6, small.sum_levels + 1) * s.max_abs_height() * 10.0 < 0.5);
}

TEST_CASE("K beyond the IST steps the axes hold is a status, not an abort") {
    // The axes hold F^0 .. F^2; asking eq. (15) or eq. (20) for K = 3 used to reach
    // WrIstAxis::inverse with k = 3 and trip its assertion.
    WrControlMesh m = flat_mesh(7, 7);
    WrSurface s;
    REQUIRE(make_wr_surface(m, SurfaceBasis::bspline, 3, s));
    IstAxis iu, iv;
    REQUIRE(ist_fully_connected_axis(3, 1, s.spans_u(), IstEnds::translation, iu));
    REQUIRE(ist_fully_connected_axis(3, 1, s.spans_v(), IstEnds::translation, iv));
    WrIstAxis au, av;
    REQUIRE(make_wr_ist_axis(iu, 2, au));
    REQUIRE(make_wr_ist_axis(iv, 2, av));
    REQUIRE(s.set_axes(au.axis(), av.axis()));
    CHECK(s.max_level() == 2);
    HierarchicalOptions o;
    o.levels = 3;
    HierarchicalSampling hs;
    const Status st = sample_hierarchy(s, o, hs);
    CHECK(!st);
    CHECK(std::string(st.message()).find("K = 3") != std::string::npos);
    o.levels = 2;
    CHECK(sample_hierarchy(s, o, hs));
    WrTessellationOptions to;
    to.grid_level = 1;
    WrMesh wm;
    for (WrSurfaceForm f : {WrSurfaceForm::wr, WrSurfaceForm::superposed_direct}) {
        to.form = f;
        to.levels = 3;
        CHECK(!tessellate_wr_surface(s, nullptr, to, wm));
        to.levels = 2;
        CHECK(tessellate_wr_surface(s, nullptr, to, wm));
    }
    WrAxis bad = au.axis();
    bad.max_level = -1;
    CHECK(!s.set_axes(bad, av.axis()));
    CHECK(identity_axis(3).max_level == kMaxWrLevel);
}

TEST_CASE(
    "NaN or out-of-range (u, v) read the surface at the clamped parameter, never out of bounds") {
    // The manuals say parameters are clamped to [0, 1]; NaN used to pass clamp() unchanged and
    // became int(NaN) as a knot-span index (a read far outside the control grid).
    WrControlMesh m = flat_mesh(7, 7);
    WrSurface s;
    REQUIRE(make_wr_surface(m, SurfaceBasis::bspline, 3, s));
    IstAxis iu;
    REQUIRE(ist_fully_connected_axis(3, 1, s.spans_u(), IstEnds::translation, iu));
    WrIstAxis a;
    REQUIRE(make_wr_ist_axis(iu, 2, a));
    REQUIRE(s.set_axes(a.axis(), a.axis()));
    HierarchicalOptions o;
    o.levels = 2;
    o.interpolation = SampleInterpolation::hermite;
    HierarchicalSampling hs;
    REQUIRE(sample_hierarchy(s, o, hs));
    const float nan = std::nanf("");
    const float inf = INFINITY;
    CHECK(length(s.wr_point(nan, 0.5f, 2) - s.wr_point(0.0f, 0.5f, 2)) < 1e-6f);
    CHECK(length(s.wr_point(0.5f, nan, 2) - s.wr_point(0.5f, 0.0f, 2)) < 1e-6f);
    CHECK(length(s.wr_point(inf, -inf, 2) - s.wr_point(1.0f, 0.0f, 2)) < 1e-6f);
    CHECK(length(s.wr_point(-3.0f, 7.0f, 1) - s.wr_point(0.0f, 1.0f, 1)) < 1e-6f);
    const SuperposedSample p = superposed_sampled(s, hs, nan, 0.3f);
    const SuperposedSample q = superposed_sampled(s, hs, 0.0f, 0.3f);
    CHECK(length(p.position - q.position) < 1e-6f);
    CHECK(length(p.attributes.color - q.attributes.color) < 1e-6f);
}

namespace {

// A WrAxis that forwards to another and counts its (F^k)^{-1} evaluations.
struct CountedAxis {
    WrAxis inner;
    long calls = 0;
    static float inverse(const void* self, float s, int k) {
        auto* a = const_cast<CountedAxis*>(static_cast<const CountedAxis*>(self));
        ++a->calls;
        return a->inner.inverse_at(s, k);
    }
    WrAxis axis() const {
        WrAxis w = inner;
        w.inverse = &CountedAxis::inverse;
        w.context = this;
        return w;
    }
};

bool same_vec_bits(Vec3 a, Vec3 b) { return std::memcmp(&a, &b, sizeof(Vec3)) == 0; }

}  // namespace

TEST_CASE(
    "fuzz timeout_ist_inverse_per_vertex: (F^K)^{-1} once per grid column and row, same "
    "bits as the per-point eq. (15)") {
    // fuzz/corpus/fuzz_wr_tessellation/timeout_ist_inverse_per_vertex: a bicubic Bezier patch,
    // fully-connected IST N = 5, K = 2 on a translation axis (the digit-stepping inverse),
    // eq. (15) on a 53 x 53 grid (L = 2, 2 subdivisions). It timed out once on a loaded machine
    // under the sanitizers; measured, the IST inverse is < 0.1 % of its time (the tensor sums
    // are the rest): the grid evaluates it once per column and row, never per vertex.
    const float p[16][4] = {
        {0x0p+0f, 0x0p+0f, 0x0p+0f, 0x1.08p+11f},
        {0x0p+0f, 0x1.8p+1f, 0x1p+0f, 0x1.4p-2f},
        {-0x1.e5e8p+6f, -0x1.e5e8p+6f, -0x1.e5e8p+6f, -0x1.e5e8p+6f},
        {-0x1.e5e8p+6f, -0x1.e5e8p+6f, -0x1.e5e8p+6f, -0x1.e5e8p+6f},
        {0x1.452p+4f, 0x1p+13f, 0x0p+0f, -0x1.e5e8p+6f},
        {-0x1.e5e8p+6f, -0x1.e5e8p+6f, -0x1.e5e8p+6f, -0x1.e5e8p+6f},
        {-0x1.e5e8p+6f, -0x1.e5e8p+6f, -0x1.e5e8p+6f, -0x1.e5e8p+6f},
        {-0x1.e5e8p+6f, -0x1.e5e8p+6f, -0x1.e5e8p+6f, -0x1p-5f},
        {0x1p+11f, 0x1p+12f, 0x1.0008p+14f, 0x1p+14f},
        {0x1p+14f, 0x1p+6f, 0x1p+14f, 0x0p+0f},
        {0x1p+5f, 0x1p+11f, 0x1p+14f, 0x1p+6f},
        {0x1.8p+1f, 0x0p+0f, 0x1p-1f, 0x1.04p+12f},
        {0x1.8p+5f, 0x1p-3f, -0x1p-1f, 0x1.02p+13f},
        {0x1.8p+1f, 0x1.8p-3f, 0x1p-1f, 0x1.82p+13f},
        {0x1.02p-128f, 0x1.8p+1f, 0x1.8p-3f, 0x1p-1f},
        {0x1.8p+1f, 0x1.8p+1f, 0x1.4p-2f, -0x1p-1f},
    };
    WrControlMesh m = make_control_mesh(4, 4);
    for (int i = 0; i < 16; ++i) {
        m.points[std::size_t(i)].position = {p[i][0], p[i][1], p[i][2]};
        m.points[std::size_t(i)].height = p[i][3];
    }
    WrSurface s;
    REQUIRE(make_wr_surface(m, SurfaceBasis::bezier, 3, s));
    IstAxis iu, iv;
    REQUIRE(ist_fully_connected_axis(5, 1, s.spans_u(), IstEnds::translation, iu));
    REQUIRE(ist_fully_connected_axis(5, 1, s.spans_v(), IstEnds::translation, iv));
    WrIstAxis au, av;
    REQUIRE(make_wr_ist_axis(iu, 2, au));
    REQUIRE(make_wr_ist_axis(iv, 2, av));
    CountedAxis cu{au.axis()}, cv{av.axis()};
    REQUIRE(s.set_axes(cu.axis(), cv.axis()));
    WrTessellationOptions o;
    o.form = WrSurfaceForm::wr;
    o.levels = 2;
    o.grid_level = 2;
    o.subdivisions = 2;
    WrMesh wm;
    REQUIRE(tessellate_wr_surface(s, nullptr, o, wm));
    REQUIRE(wm.grid_u == 53);
    REQUIRE(wm.grid_v == 53);
    CHECK(cu.calls == wm.grid_u);  // one (F^2)^{-1}(u) per column (k = 0 is the identity)
    CHECK(cv.calls == wm.grid_v);  // one per row
    // The slow reference: eq. (15) point by point, the inverses evaluated at every vertex.
    int mismatches = 0;
    for (std::size_t id = 0; id < wm.mesh.positions.size(); ++id) {
        const float u = wm.mesh.uvs[id].x, v = wm.mesh.uvs[id].y;
        const Vec3 want = s.wr_point(u, v, 2);
        const WrAttributes a = s.wr_attributes(u, v, 2);
        const Vec3 colour = {clamp(a.color.x, 0.0f, 1.0f), clamp(a.color.y, 0.0f, 1.0f),
                             clamp(a.color.z, 0.0f, 1.0f)};
        if (!same_vec_bits(wm.mesh.positions[id], want) ||
            !same_vec_bits(wm.mesh.colors[id], colour))
            ++mismatches;
    }
    CHECK(mismatches == 0);
    CHECK(cu.calls == wm.grid_u + 2 * long(wm.mesh.positions.size()));  // + the reference's
}

namespace {

// Local maxima of the relief r = H(F^-k(u), F^-k(v)) - H(u, v) along u, per row, at the step-k
// vertex positions (i + 1/2)/(B·N^k) inside [u0, u1] x [v0, v1]: the wrinkles a view shows.
double wrinkles_across(const WrSurface& s, int k, float u0, float u1, float v0, float v1) {
    std::vector<float> us, vs;
    for (float p : hierarchical_sample_positions(s.axis_u().base_intervals, s.axis_u().division, k))
        if (p > 0.0f && p < 1.0f && p >= u0 && p <= u1) us.push_back(p);
    for (float p : hierarchical_sample_positions(s.axis_v().base_intervals, s.axis_v().division, k))
        if (p > 0.0f && p < 1.0f && p >= v0 && p <= v1) vs.push_back(p);
    double maxima = 0;
    for (float v : vs) {
        std::vector<float> r;
        for (float u : us) r.push_back(s.wr_attributes(u, v, k).height - s.attributes(u, v).height);
        for (std::size_t i = 1; i + 1 < r.size(); ++i)
            if (r[i] > r[i - 1] && r[i] >= r[i + 1]) maxima += 1;
    }
    return vs.empty() ? 0.0 : maxima / double(vs.size());
}

}  // namespace

TEST_CASE(
    "self-similarity (fujimoto2000 §3.2, figs. 14-15): a third at K + 1 repeats the whole at K") {
    // The zooms (d)(e)(f) magnify a third of (b) 3x and refine one IST step (adaptive sampling):
    // they must show as many wrinkles across as (b); without the extra step only a third.
    for (SurfaceBasis basis : {SurfaceBasis::bezier, SurfaceBasis::bspline}) {
        WrControlMesh m = flat_mesh(basis == SurfaceBasis::bezier ? 4 : 11,
                                    basis == SurfaceBasis::bezier ? 4 : 11);
        WrSurface s;
        REQUIRE(make_wr_surface(m, basis, 3, s));
        IstAxis iu, iv;
        if (basis == SurfaceBasis::bezier) {
            REQUIRE(ist_unit_axis(3, 1, iu));
            REQUIRE(ist_unit_axis(3, 1, iv));
        } else {
            REQUIRE(ist_fully_connected_axis(3, 1, s.spans_u(), IstEnds::translation, iu));
            REQUIRE(ist_fully_connected_axis(3, 1, s.spans_v(), IstEnds::translation, iv));
        }
        WrIstAxis au, av;
        REQUIRE(make_wr_ist_axis(iu, 4, au));
        REQUIRE(make_wr_ist_axis(iv, 4, av));
        REQUIRE(s.set_axes(au.axis(), av.axis()));
        const int K = basis == SurfaceBasis::bezier ? 3 : 2;
        const double whole = wrinkles_across(s, K, 0.0f, 1.0f, 0.0f, 1.0f);
        REQUIRE(whole >= 3.0);
        for (float uc : {1.0f / 6.0f, 0.5f, 5.0f / 6.0f}) {
            const float u0 = uc - 1.0f / 6.0f, u1 = uc + 1.0f / 6.0f;
            const double zoom = wrinkles_across(s, K + 1, u0, u1, 1.0f / 3.0f, 2.0f / 3.0f);
            const double same_k = wrinkles_across(s, K, u0, u1, 1.0f / 3.0f, 2.0f / 3.0f);
            INFO("basis " << int(basis) << " third at " << uc << ": " << zoom << " / " << same_k
                          << " wrinkles against " << whole);
            CHECK(zoom >= 0.7 * whole);
            CHECK(zoom <= 1.4 * whole);
            CHECK(same_k < 0.6 * whole);  // no refinement: not self-similar
        }
    }
}

TEST_CASE(
    "superposed unit-IST Bezier (fig. 17): step 1 is the identity; delta moves the surface off H") {
    // eq. (7): with one digit the unit-IST's reversal changes nothing, so step 1 samples H
    // itself and steps 0 and 1 hold 1 - delta^2 of eq. (19)'s weight. How far eq. (20) departs
    // from H (RMS over H's own variation) must grow with delta (§4.1: larger delta, rougher).
    WrControlMesh m = flat_mesh(4, 4);
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) m.at(c, r).height = 0.2f + 0.3f * float((c + r) % 3);
    WrSurface s;
    REQUIRE(make_wr_surface(m, SurfaceBasis::bezier, 3, s));
    IstAxis iu, iv;
    REQUIRE(ist_unit_axis(3, 1, iu));
    REQUIRE(ist_unit_axis(3, 1, iv));
    WrIstAxis au, av;
    REQUIRE(make_wr_ist_axis(iu, 4, au));
    REQUIRE(make_wr_ist_axis(iv, 4, av));
    REQUIRE(s.set_axes(au.axis(), av.axis()));
    for (float u : {0.1f, 0.45f, 0.8f})
        CHECK(s.inverse_u(u, 1) == doctest::Approx(u).epsilon(1e-6));
    double previous = 0;
    for (float delta : {0.35f, 0.5f, 0.75f}) {
        for (WrControlPoint& p : m.points) p.delta = delta;
        WrSurface sd;
        REQUIRE(make_wr_surface(m, SurfaceBasis::bezier, 3, sd));
        REQUIRE(sd.set_axes(au.axis(), av.axis()));
        HierarchicalOptions o;
        o.levels = 4;
        o.interpolation = SampleInterpolation::hermite;
        HierarchicalSampling hs;
        REQUIRE(sample_hierarchy(sd, o, hs));
        double sr = 0, sh = 0, mh = 0;
        const int n = 81;
        std::vector<double> h, r;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const float u = (float(i) + 0.5f) / float(n), v = (float(j) + 0.5f) / float(n);
                h.push_back(sd.attributes(u, v).height);
                r.push_back(superposed_sampled(sd, hs, u, v).attributes.height - h.back());
                mh += h.back();
            }
        mh /= double(h.size());
        for (std::size_t i = 0; i < h.size(); ++i)
            sr += r[i] * r[i], sh += (h[i] - mh) * (h[i] - mh);
        const double departure = std::sqrt(sr / sh);
        INFO("delta " << delta << ": departure " << departure);
        CHECK(departure > 1.3 * previous);
        previous = departure;
    }
    CHECK(previous > 0.3);
}

namespace {

// The terrace measure of fig. 18 (paper_figures/fujimoto2000/fig17_18_superposed.cpp): along
// profiles in v, sampled finer than the step-K small intervals, the share of steps |dh| below a
// tenth of the mean |dh|.
template <class Height> double flat_step_share_v(int n, Height height) {
    std::vector<double> d;
    for (int p = 0; p < 8; ++p) {
        const float u = (float(p) + 0.5f) / 8.0f;
        double prev = height(u, 0.5f / float(n));
        for (int i = 1; i < n; ++i) {
            const double h = height(u, (float(i) + 0.5f) / float(n));
            d.push_back(std::fabs(h - prev));
            prev = h;
        }
    }
    double mean = 0;
    for (double x : d) mean += x;
    mean /= double(d.size());
    long flat = 0;
    for (double x : d) flat += x < 0.1 * mean;
    return double(flat) / double(d.size());
}

}  // namespace

TEST_CASE("fully-connected superposition on a slope: eq. (20) has fewer flat steps than eq. (16)") {
    // A range across v (heights by row), as fig. 18's: fig. 19(b)'s staircase is eq. (16)'s
    // flat treads; §4.2's hierarchical sampling interpolates one sample per small region, and
    // §5's Gaussian jitter on the samples keeps the IST's teeth from lining up into terraces.
    WrControlMesh m = flat_mesh(11, 11);
    for (int r = 0; r < 11; ++r)
        for (int c = 0; c < 11; ++c) {
            const float x = -1.5f + 0.3f * float(c), z = 1.5f - 0.3f * float(r);
            const float d = z + 0.1f - 0.35f * std::sin(1.6f * x);  // a winding ridge
            m.at(c, r).position = {x, 0.0f, z};
            m.at(c, r).height = 0.05f + 0.55f * std::exp(-3.0f * d * d) *
                                            (0.65f + 0.15f * float((c * 7 + r * 3) % 5));
            m.at(c, r).delta = 0.75f;
        }
    WrSurface s;
    REQUIRE(make_wr_surface(m, SurfaceBasis::bspline, 3, s));
    const int K = 4;
    IstAxis iu, iv;
    REQUIRE(ist_fully_connected_axis(3, 1, s.spans_u(), IstEnds::translation, iu));
    REQUIRE(ist_fully_connected_axis(3, 1, s.spans_v(), IstEnds::translation, iv));
    WrIstAxis au, av;
    REQUIRE(make_wr_ist_axis(iu, K, au));
    REQUIRE(make_wr_ist_axis(iv, K, av));
    REQUIRE(s.set_axes(au.axis(), av.axis()));
    const int n = s.spans_v() * 81 * 3 / 2;  // 1.5 profile points per step-K small interval
    const double direct = flat_step_share_v(n, [&](float u, float v) {
        return double(superposed_attributes_direct(s, u, v, K).height);
    });
    double sampled[2] = {0, 0};
    for (int jitter = 0; jitter < 2; ++jitter) {
        HierarchicalOptions o;
        o.levels = K;
        o.interpolation = SampleInterpolation::hermite;
        o.jitter_height = jitter ? 0.12f : 0.0f;
        HierarchicalSampling hs;
        REQUIRE(sample_hierarchy(s, o, hs));
        sampled[jitter] = flat_step_share_v(n, [&](float u, float v) {
            return double(superposed_sampled(s, hs, u, v).attributes.height);
        });
    }
    INFO("flat-step share: eq. (16) " << direct << ", eq. (20) " << sampled[0] << ", with jitter "
                                      << sampled[1]);
    CHECK(direct > 0.15);  // the staircase is there to avoid
    CHECK(sampled[0] < direct);
    CHECK(sampled[1] < 0.75 * direct);
}
