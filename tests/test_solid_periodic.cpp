// Tests for lib/shitsukan/solid/periodic_lattice: opposite faces equal at every level, the
// slice of D and of a layered marble tiled 2x2 is continuous across the seams (values and
// gradients), while the ordinary Type I lattice shows a seam.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "shitsukan/solid/okada1987_presets.hpp"
#include "shitsukan/solid/periodic_lattice.hpp"
#include "shitsukan/solid/turbulence.hpp"

using namespace shitsukan;

namespace {

// A size x size slice of f over one period [0, N)^2 (u along x, v along z, y fixed).
template <class F>
std::vector<float> slice(int size, int R, F f) {
    const float n = float(1 << R);
    std::vector<float> out(std::size_t(size) * size);
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i)
            out[std::size_t(j) * size + i] =
                f(Vec3{float(i) * n / float(size), 21.0f, float(j) * n / float(size)});
    return out;
}

struct SeamStats {
    float interior_step = 0, seam_step = 0;    // largest |first difference|
    float interior_curve = 0, seam_curve = 0;  // largest |second difference| (gradient jump)
};

// Tiles the slice 2x2 and compares first and second differences that straddle a seam with
// those entirely inside one tile, along rows and along columns.
SeamStats tile_2x2(const std::vector<float>& s, int size) {
    const int t = 2 * size;
    auto at = [&](int i, int j) { return s[std::size_t(j % size) * size + std::size_t(i % size)]; };
    SeamStats st;
    for (int j = 0; j < t; ++j)
        for (int i = 1; i + 1 < t; ++i)
            for (int axis = 0; axis < 2; ++axis) {
                auto v = [&](int k) { return axis == 0 ? at(k, j) : at(j, k); };
                const float step = std::fabs(v(i) - v(i - 1));
                const float curve = std::fabs(v(i + 1) - 2.0f * v(i) + v(i - 1));
                const bool step_seam = i % size == 0;
                const bool curve_seam = i % size == 0 || (i + 1) % size == 0;
                float& a = step_seam ? st.seam_step : st.interior_step;
                float& b = curve_seam ? st.seam_curve : st.interior_curve;
                if (step > a) a = step;
                if (curve > b) b = curve;
            }
    return st;
}

}  // namespace

TEST_CASE("periodic lattice: opposite faces are equal bit for bit, every axis and level") {
    for (int R : {1, 3, 5}) {
        FractalParams p;
        p.R = R;
        p.seed = 77;
        p.corners[0] = p.corners[1] = p.corners[2] = p.corners[3] = 0.5f;
        p.corners[4] = p.corners[5] = p.corners[6] = p.corners[7] = 0.5f;
        PeriodicLattice lattice;
        REQUIRE(lattice.build(p).ok());
        const LatticeView v = lattice.view();
        const int n = v.side - 1;
        int unequal = 0, nan = 0;
        for (int a = 0; a <= n; ++a)
            for (int b = 0; b <= n; ++b) {
                if (v.at(0, a, b) != v.at(n, a, b)) ++unequal;
                if (v.at(a, 0, b) != v.at(a, n, b)) ++unequal;
                if (v.at(a, b, 0) != v.at(a, b, n)) ++unequal;
                if (std::isnan(v.at(a, b, 0))) ++nan;
            }
        CHECK(unequal == 0);
        CHECK(nan == 0);
    }
}

TEST_CASE("periodic lattice: a real fractal (not flat), different from Type I on the faces") {
    FractalParams p;
    p.R = 4;
    PeriodicLattice periodic;
    FractalLattice type1;
    REQUIRE(periodic.build(p).ok());
    REQUIRE(type1.build(p).ok());
    float lo = 1e9f, hi = -1e9f;
    for (int z = 0; z <= 16; ++z)
        for (int x = 0; x <= 16; ++x) {
            lo = std::fmin(lo, periodic.view().at(x, 7, z));
            hi = std::fmax(hi, periodic.view().at(x, 7, z));
        }
    CHECK(hi - lo > 0.5f);
    CHECK(periodic.view().at(0, 3, 5) != type1.view().at(0, 3, 5));
}

TEST_CASE("periodic lattice: D tiled 2x2 has no seam (values and gradients); Type I has one") {
    FractalParams p;  // R = 6, beta 0.9
    PeriodicLattice periodic;
    FractalLattice type1;
    REQUIRE(periodic.build(p).ok());
    REQUIRE(type1.build(p).ok());
    const int size = 256;  // 4 pixels per lattice cell
    const SeamStats good = tile_2x2(
        slice(size, p.R, [&](Vec3 q) { return turbulence(periodic.view(), q); }), size);
    // Tolerance: a seam step or curvature no larger than the largest inside one tile.
    CHECK(good.seam_step <= good.interior_step);
    CHECK(good.seam_curve <= good.interior_curve);
    const SeamStats bad = tile_2x2(
        slice(size, p.R, [&](Vec3 q) { return turbulence(type1.view(), q); }), size);
    CHECK(bad.seam_step > 1.5f * bad.interior_step);  // the non-periodic lattice shows a seam
    // The wrapped sampler continues the field across the border continuously.
    const float n = 64.0f;
    CHECK(std::fabs(periodic_turbulence(periodic.view(), Vec3{n + 0.001f, 5.5f, 9.25f}) -
                    periodic_turbulence(periodic.view(), Vec3{n - 0.001f, 5.5f, 9.25f})) < 0.01f);
    CHECK(periodic_turbulence(periodic.view(), Vec3{-3.5f, 70.0f, 9.25f}) ==
          turbulence(periodic.view(), Vec3{60.5f, 6.0f, 9.25f}));
}

TEST_CASE("periodic lattice: okada1989 layered marble with a tileable period tiles 2x2") {
    FractalParams p;
    PeriodicLattice lattice;
    REQUIRE(lattice.build(p).ok());
    SolidMaterial m = okada1989_marble();
    m.layer_period = tileable_layer_period(kOkada1989LayerPeriod, p.R);
    CHECK(m.layer_period == doctest::Approx(64.0f / 5.0f));  // 12 -> 5 layers per period
    const int size = 256;
    const SeamStats st = tile_2x2(
        slice(size, p.R, [&](Vec3 q) { return solid_density(m, lattice.view(), q); }), size);
    CHECK(st.seam_step <= st.interior_step);
    CHECK(st.seam_curve <= st.interior_curve * 1.0001f);
}

TEST_CASE("periodic lattice: refuses sequential noise, unequal corners, R out of range") {
    PeriodicLattice lattice;
    FractalParams p;
    p.noise = NoiseSource::sequential;
    CHECK(lattice.build(p).code() == StatusCode::invalid_argument);
    p = FractalParams{};
    p.corners[5] = 1.0f;
    Status s = lattice.build(p);
    CHECK(s.code() == StatusCode::invalid_argument);
    CHECK(std::strstr(s.message(), "corner 5") != nullptr);
    p = FractalParams{};
    p.R = 11;
    CHECK(!lattice.build(p).ok());
    CHECK(lattice.empty());
    p.R = 9;
    CHECK(lattice.build(p, 1024).code() == StatusCode::too_large);
}
