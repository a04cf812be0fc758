// Tests for lib/shitsukan/render/bark_crack_map: crack_map_size, the unrolled map's size from
// the grown trunk (hirota1998 Table 1's strains), checked before it is allocated.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "shitsukan/bark/bark.hpp"
#include "shitsukan/core/memory_budget.hpp"
#include "shitsukan/render/bark_crack_map.hpp"

using namespace shitsukan;

namespace {
BarkCylinder cylinder(int N_R, int N_H, float T, float L0) {
    CylinderParams p;
    p.species = species_preset(Species::camphor);
    p.N_R = N_R, p.N_H = N_H, p.T = T;
    p.species.L0 = L0;
    BarkCylinder bark;
    REQUIRE(build_cylinder(p, bark).ok());
    return bark;
}
}  // namespace

TEST_CASE("crack_map_size: the grown circumference and height in pixels, at least 8 x 8") {
    const BarkCylinder bark = cylinder(16, 12, 100.0f, 0.33f);
    int w = 0, h = 0;
    REQUIRE(crack_map_size(bark, 100.0f, 24.0f, w, h).ok());
    const double C = double(bark.circumference) * (1.0 + double(hoop_strain(bark.params, 100)));
    const double H =
        double(initial_height(bark.params)) * (1.0 + double(axial_strain(bark.params, 100)));
    CHECK(w == int(std::ceil(C * 24.0)));
    CHECK(h == int(std::ceil(H * 24.0)));
    REQUIRE(crack_map_size(bark, 0.0f, 1.0f, w, h).ok());
    CHECK(w == 8);
    CHECK(h == 8);
    CHECK(crack_map_size(bark, 100.0f, 0.0f, w, h).code() == StatusCode::invalid_argument);
}

// `shitsukan bark --N_R 8 --N_H 4 --T 1000000` (in the flags' ranges) sized a 201982 x 182509
// map (110 GB) with an unchecked resize and died of std::bad_alloc; --N_R 32 --N_H 16 --L0 100
// reached 7.3 GB. The size now goes through the memory budget first.
TEST_CASE("crack_map_size: a trunk grown past the memory budget or INT_MAX is refused") {
    int w = -1, h = -1;
    Status s = crack_map_size(cylinder(8, 4, 1e6f, 0.33f), 1e6f, 24.0f, w, h);
    CHECK(s.code() == StatusCode::too_large);
    CHECK(std::string(s.message()).find("crack map") != std::string::npos);
    CHECK(w == -1);  // untouched on failure
    s = crack_map_size(cylinder(32, 16, 100.0f, 100.0f), 100.0f, 24.0f, w, h);
    CHECK(s.code() == StatusCode::too_large);
    // A side past INT_MAX (a float growth that a library caller may pass): out_of_range, not
    // undefined behaviour in the conversion.
    s = crack_map_size(cylinder(8, 4, 1e30f, 0.33f), 1e30f, 24.0f, w, h);
    CHECK(s.code() == StatusCode::out_of_range);
    // The budget decides: a smaller one refuses the default trunk's map too.
    set_memory_budget(1000);
    s = crack_map_size(cylinder(16, 12, 100.0f, 0.33f), 100.0f, 24.0f, w, h);
    set_memory_budget(0);
    CHECK(s.code() == StatusCode::too_large);
}
