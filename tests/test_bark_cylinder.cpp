// Tests for lib/shitsukan/bark: bark_params (Table 2, validation), connection_area (Fig. 9),
// cylinder_lattice (Fig. 3's layout), spacing_estimate.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "shitsukan/bark/bark.hpp"

using namespace shitsukan;

TEST_CASE("the three presets are Table 2 to the printed digits") {
    const SpeciesParams c = species_preset(Species::camphor);
    const SpeciesParams t = species_preset(Species::chinese_tallow);
    const SpeciesParams p = species_preset(Species::pine);
    for (const SpeciesParams* s : {&c, &t, &p}) {
        CHECK(s->L0 == 0.33f);
        CHECK(s->E2 == 117.3e7f);
    }
    CHECK(c.E1 == 107.1e7f);
    CHECK(t.E1 == 117.3e7f);
    CHECK(p.E1 == 117.3e7f);
    CHECK(c.G == 47.7e7f);
    CHECK(t.G == 53.3e7f);
    CHECK(p.G == 53.3e7f);
    CHECK(c.kappa1 == 1.040f);
    CHECK(t.kappa1 == 1.033f);
    CHECK(p.kappa1 == 1.038f);
    CHECK(c.kappa2 == 1.015f);
    CHECK(t.kappa2 == 1.015f);
    CHECK(p.kappa2 == 1.023f);
    CHECK(std::string(species_name(Species::pine)) == "pine");
}

TEST_CASE("Table 1's R0 = sqrt(3) L0 N_R / (4 pi) and H0 = L0 N_H; the final strains") {
    CylinderParams p;
    CHECK(initial_radius(p) == doctest::Approx(std::sqrt(3.0) * 0.33 * 128 / (4 * M_PI)));
    CHECK(initial_height(p) == doctest::Approx(0.33 * 64));
    CHECK(hoop_strain(p, p.T) == doctest::Approx(0.023).epsilon(1e-4));
    CHECK(axial_strain(p, p.T) == doctest::Approx(0.036).epsilon(1e-4));
}

TEST_CASE("bad parameters get a Status that names the value") {
    auto code = [](CylinderParams p) { return validate(p).code(); };
    CylinderParams p;
    CHECK(validate(p).ok());
    CylinderParams q = p;
    q.N_R = 127;
    CHECK(code(q) == StatusCode::invalid_argument);
    CHECK(std::strstr(validate(q).message(), "127") != nullptr);
    q = p, q.N_R = 2;
    CHECK(code(q) == StatusCode::invalid_argument);
    q = p, q.N_H = 1;
    CHECK(code(q) == StatusCode::invalid_argument);
    q = p, q.species.kappa2 = 1.0f;
    CHECK(code(q) == StatusCode::invalid_argument);
    q = p, q.species.kappa1 = 0.99f;
    CHECK(code(q) == StatusCode::invalid_argument);
    q = p, q.sigma = -0.01f;
    CHECK(code(q) == StatusCode::invalid_argument);
    q = p, q.D = 0.0f;
    CHECK(code(q) == StatusCode::invalid_argument);
    q = p, q.delta_r = std::nanf("");
    CHECK(code(q) == StatusCode::invalid_argument);
    q = p, q.delta_h = std::numeric_limits<float>::infinity();
    CHECK(code(q) == StatusCode::invalid_argument);
    q = p, q.species.G = -1.0f;
    CHECK(code(q) == StatusCode::invalid_argument);
    q = p, q.N_R = 4096, q.N_H = 4096;
    CHECK(code(q) == StatusCode::too_large);
    CHECK(std::strstr(validate(q).message(), "bytes") != nullptr);
    BarkCylinder bark;
    CHECK(build_cylinder(q, bark).code() == StatusCode::too_large);
    CHECK(bark.net.X.empty());  // refused before anything was allocated
}

TEST_CASE("the cylinder: counts, every spring L0 long, the seam closes the circumference") {
    CylinderParams p;
    p.N_R = 36, p.N_H = 10;
    BarkCylinder bark;
    REQUIRE(build_cylinder(p, bark).ok());
    const int n = p.N_R * p.N_H;
    CHECK(bark.net.node_count() == n);
    CHECK(bark.net.spring_count() == p.N_R * (3 * p.N_H - 2));
    CHECK(int(bark.triangles.size()) == 2 * p.N_R * (p.N_H - 1));
    CHECK(bark.circumference / float(p.N_R) == doctest::Approx(std::sqrt(3.0) / 2 * 0.33));
    CHECK(bark.circumference == doctest::Approx(2 * M_PI * bark.R0));
    int axial = 0;
    for (const BarkSpring& s : bark.net.springs) {
        // Reference lengths from the node positions, seam-corrected.
        Vec3 d = bark.net.X[s.j] - bark.net.X[s.i];
        if (d.x < -0.5f * bark.circumference) d.x += bark.circumference;
        CHECK(length(d) == doctest::Approx(0.33).epsilon(1e-5));
        CHECK(dot(d, s.n) == doctest::Approx(0.33).epsilon(1e-5));
        CHECK(s.family == (s.n.x == 0.0f ? 1 : 2));  // vertical = axial = family 1
        axial += s.family == 1;
        // growth strain rate g = (dr/R0) n_u^2 + (dh/H0) n_z^2
        const float g = p.delta_r / bark.R0 * s.n.x * s.n.x + p.delta_h / bark.H0 * s.n.y * s.n.y;
        CHECK(s.growth_rate == doctest::Approx(g));
    }
    CHECK(axial == p.N_R * (p.N_H - 1));
}

TEST_CASE("connection areas on the regular lattice: S = D L0 / sqrt(3), A = (sqrt(3)/2) L0^2") {
    CylinderParams p;
    p.N_R = 16, p.N_H = 8;
    BarkCylinder bark;
    REQUIRE(build_cylinder(p, bark).ok());
    const double L0 = 0.33, tri_area = std::sqrt(3.0) / 4 * L0 * L0;
    double total = 0;
    for (float a : bark.node_area) total += a;
    CHECK(total == doctest::Approx(tri_area * bark.triangles.size()).epsilon(1e-5));
    const SpeciesParams& sp = p.species;
    for (int c = 0; c < p.N_R; ++c)
        for (int r = 0; r < p.N_H; ++r) {
            const float A = bark.node_area[std::size_t(bark.node(c, r))];
            const bool interior = r > 0 && r < p.N_H - 1;
            if (interior) {
                CHECK(A == doctest::Approx(std::sqrt(3.0) / 2 * L0 * L0).epsilon(1e-5));
                CHECK(bark.net.k_anchor[std::size_t(bark.node(c, r))] ==
                      doctest::Approx(sp.G * std::sqrt(3.0) / 2 * L0 * L0 / p.D).epsilon(1e-5));
            } else {
                CHECK(A < std::sqrt(3.0) / 2 * L0 * L0);  // the free edge: a partial element
                CHECK(A > 0.0f);
            }
        }
    for (std::size_t s = 0; s < bark.net.springs.size(); ++s) {
        const bool two = bark.spring_triangles[2 * s + 1] >= 0;
        const double face = two ? L0 / std::sqrt(3.0) : L0 / (2 * std::sqrt(3.0));
        CHECK(bark.spring_face[s] == doctest::Approx(face).epsilon(1e-5));
        const BarkSpring& spring = bark.net.springs[s];
        const double E = spring.family == 1 ? sp.E1 : sp.E2;
        CHECK(spring.k == doctest::Approx(E * face * p.D / L0).epsilon(1e-5));
    }
}

TEST_CASE("connection areas refuse bad triangles") {
    ConnectionTriangle t{{0, 1, 2}, {0, 1, 2}, {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}};
    float area[3], face[3];
    CHECK(connection_areas(&t, 1, 3, 3, area, face).code() == StatusCode::degenerate);
    t.corner[2] = {0, 1, 0};
    CHECK(connection_areas(&t, 1, 3, 3, area, face).ok());
    CHECK(area[0] + area[1] + area[2] == doctest::Approx(0.5));
    t.node[1] = 7;
    CHECK(connection_areas(&t, 1, 3, 3, area, face).code() == StatusCode::invalid_argument);
    t.node[1] = 1, t.corner[0].x = std::nanf("");
    CHECK(connection_areas(&t, 1, 3, 3, area, face).code() == StatusCode::invalid_argument);
}

TEST_CASE("thresholds come from the spring's coordinates: eps_c around kappa - 1, spread sigma") {
    CylinderParams p;
    p.N_R = 32, p.N_H = 16;
    BarkCylinder bark;
    REQUIRE(build_cylinder(p, bark).ok());
    double sum = 0, sum2 = 0;
    int n = 0;
    for (const BarkSpring& s : bark.net.springs)
        if (s.family == 2) {
            const double rel = s.eps_c / (p.species.kappa2 - 1.0) - 1.0;
            sum += rel, sum2 += rel * rel, ++n;
            CHECK(std::fabs(rel) <= 3 * p.sigma + 1e-5);
        }
    const double mean = sum / n, sd = std::sqrt(sum2 / n - mean * mean);
    CHECK(std::fabs(mean) < 0.1 * p.sigma);
    CHECK(sd == doctest::Approx(p.sigma).epsilon(0.1));
}

TEST_CASE("the shear-lag spacing estimate (reconstructed) reproduces Table 3's observed spacings") {
    const float a_h = 0.33f * std::sqrt(3.0f) / 2, ratio = 1.689f;
    CHECK(std::isinf(crack_spacing_estimate(a_h, ratio, 0.04f, 0.0381f)));  // camphor: "(>20)"
    CHECK(crack_spacing_estimate(a_h, ratio, 0.015f, 0.0252f) == doctest::Approx(1.50).epsilon(1e-2));
    CHECK(crack_spacing_estimate(0.33f, ratio, 0.033f, 0.03815f) == doctest::Approx(3.00).epsilon(1e-2));
    CHECK(crack_spacing_estimate(a_h, ratio, 0.023f, 0.0252f) > 3.0f);  // pine: wider
    CHECK(std::isnan(crack_spacing_estimate(-1.0f, ratio, 0.01f, 0.02f)));
}

// fuzz_bark: E2 = 4.8e12 on L0 = 2.2e-4 cm (a spring 2.6e7 times stiffer than its shear
// spring) gave NaN displacements with an ok Status; a tolerance of 9.5e-41 ran 21 s.
TEST_CASE("build_cylinder refuses springs float cannot solve against their shear springs") {
    CylinderParams p;
    p.species = species_preset(Species::camphor);
    p.N_R = 8, p.N_H = 6;
    p.species.L0 *= std::exp2(-10.5f);
    p.species.E2 *= std::exp2(12.0f);
    p.sigma *= std::exp2(3.375f);
    p.delta_h *= std::exp2(6.25f);
    p.seed = 16777472u;
    BarkCylinder bark;
    const Status s = build_cylinder(p, bark);
    CHECK(s.code() == StatusCode::out_of_range);
    CHECK(std::string(s.message()).find("times the shear spring") != std::string::npos);
    // The bark tool's smallest L0 with Table 2's values stays solvable, and solves finite.
    p = CylinderParams{};
    p.N_R = 16, p.N_H = 12;
    p.species.L0 = 0.001f;
    REQUIRE(build_cylinder(p, bark).ok());
    CrackRun run;
    REQUIRE(grow_and_crack(bark, CrackRunOptions{}, run).ok());
    for (const Vec3& w : bark.net.W) REQUIRE((std::isfinite(w.x) && std::isfinite(w.y)));
    p.tolerance = 9.46e-41f;
    CHECK(build_cylinder(p, bark).code() == StatusCode::invalid_argument);
}

// fuzz_bark: delta_h = 3.7e19 cm/s overflowed the displacement field; grow_and_crack returned
// ok with NaN W.
TEST_CASE("grow_and_crack refuses a displacement field that overflows a float") {
    CylinderParams p;
    p.species = species_preset(Species::chinese_tallow);
    p.N_R = 8, p.N_H = 4;
    p.species.L0 *= std::exp2(0.5f);
    p.species.G *= std::exp2(15.875f);
    p.species.kappa1 = 1.0f + (p.species.kappa1 - 1.0f) * std::exp2(4.375f);
    p.species.kappa2 = 1.0f + (p.species.kappa2 - 1.0f) * std::exp2(12.0f);
    p.delta_h = 3.693296501290277e+19f;
    p.seed = 1625620480u;
    BarkCylinder bark;
    REQUIRE(build_cylinder(p, bark).ok());
    CrackRun run;
    const Status s = grow_and_crack(bark, CrackRunOptions{}, run);
    CHECK(s.code() == StatusCode::out_of_range);
    CHECK(std::string(s.message()).find("overflowed a float") != std::string::npos);
}
