// Tests for lib/shitsukan/bark/bark_texture (and cylinder_lattice's periodic_along): the map
// tiles 2 x 2 without a seam in either direction, crack edges are anti-aliased at every
// power-of-two size, plates keep their own top and tone.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "shitsukan/bark/bark.hpp"
#include "shitsukan/bark/bark_texture.hpp"
#include "measured.hpp"
#include "tile_seams.hpp"

using namespace shitsukan;

namespace {

struct SmallBark {
    CylinderParams p;
    BarkCylinder bark;
    CrackRun run;
    RegionReport regions;
};

// A pine trunk of 24 x 21 nodes (a square period), periodic along the axis, grown to T.
void grow(SmallBark& b, Species species = Species::pine) {
    b.p.N_R = 24;
    b.p.N_H = 21;
    b.p.species = species_preset(species);
    b.p.delta_r *= 24.0f / 128.0f;  // Table 3's calibrated strains (as the tool keeps them)
    b.p.delta_h *= 21.0f / 64.0f;
    REQUIRE(build_cylinder(b.p, true, b.bark));
    REQUIRE(grow_and_crack(b.bark, CrackRunOptions{}, b.run));
    REQUIRE(measure_regions(b.bark, b.p.T, b.bark.net.W.data(), b.regions));
}

BarkTexture texture(const SmallBark& b, int size) {
    BarkTextureOptions o;
    o.width = o.height = size;
    BarkTexture t;
    REQUIRE(make_bark_texture(b.bark, b.p.T, b.bark.net.W.data(), &b.regions, o, t));
    return t;
}

}  // namespace

TEST_CASE("periodic_along: every node has its six springs, two triangles per node") {
    CylinderParams p;
    p.N_R = 8;
    p.N_H = 5;  // odd: the L0/2 shift of odd columns still closes
    BarkCylinder open, closed;
    REQUIRE(build_cylinder(p, open));
    REQUIRE(build_cylinder(p, true, closed));
    CHECK(closed.periodic_along);
    CHECK(closed.net.spring_count() == 3 * 8 * 5);
    CHECK(open.net.spring_count() < 3 * 8 * 5);
    CHECK(closed.triangles.size() == std::size_t(2 * 8 * 5));
    for (int s = 0; s < closed.net.spring_count(); ++s) {
        CHECK(closed.spring_triangles[2 * std::size_t(s)] >= 0);
        CHECK(closed.spring_triangles[2 * std::size_t(s) + 1] >= 0);
    }
    // every triangle's corners are L0 apart (seam-corrected in u and z)
    for (const ConnectionTriangle& t : closed.triangles)
        for (int k = 0; k < 3; ++k)
            CHECK(length(t.corner[k] - t.corner[(k + 1) % 3]) ==
                  doctest::Approx(p.species.L0).epsilon(1e-4));
    CylinderParams tiny = p;
    tiny.N_H = 2;
    const Status s = build_cylinder(tiny, true, closed);
    CHECK(!s);
    CHECK(std::string(s.message()).find("N_H >= 3") != std::string::npos);
}

TEST_CASE("bark texture: tiled 2 x 2, the seams are ordinary columns and rows") {
    SmallBark b;
    grow(b);
    CHECK(b.run.breaks.size() > 100);
    const BarkTexture t = texture(b, 128);
    CHECK(t.period_u == doctest::Approx(t.period_z).epsilon(0.05));  // square period
    for (bool rows : {false, true}) {
        const test::SeamMeasure m = test::measure_seams(t.height_cm.data(), 128, 128, rows);
        INFO("rows " << rows << ": seam " << m.seam_value << " / " << m.seam_gradient
                     << ", interior median " << m.median_value << " / " << m.median_gradient
                     << ", max " << m.max_value << " / " << m.max_gradient);
        MEASURED("bark 2x2 " << (rows ? "rows" : "columns") << ": seam value jump "
                             << m.seam_value << " cm (interior median " << m.median_value
                             << ", max " << m.max_value << "), second difference "
                             << m.seam_gradient << " (median " << m.median_gradient << ", max "
                             << m.max_gradient << ")");
        CHECK(m.seam_value <= m.max_value);
        CHECK(m.seam_gradient <= m.max_gradient);
        CHECK(m.seam_value <= 4.0 * m.median_value + 1e-3);
        CHECK(m.seam_gradient <= 4.0 * m.median_gradient + 1e-3);
    }
    // the measure sees a seam where there is one: the same map with a step at its edge
    std::vector<float> stepped = t.height_cm;
    for (int y = 0; y < 128; ++y)
        for (int x = 0; x < 128; ++x) stepped[std::size_t(y * 128 + x)] += 0.01f * float(x);
    const test::SeamMeasure bad = test::measure_seams(stepped.data(), 128, 128);
    CHECK(bad.seam_value > bad.max_value);
}

TEST_CASE("bark texture: crack edges anti-aliased at every power-of-two size") {
    SmallBark b;
    grow(b);
    for (int size : {16, 32, 64, 256, 1024}) {
        const BarkTexture t = texture(b, size);
        int crack = 0, edge = 0, plate = 0;
        for (float h : t.height_cm) {
            const float u = h / t.max_height;
            if (u < 0.02f) ++crack;
            else if (u < 0.75f) ++edge;
            else ++plate;
        }
        INFO("size " << size << ": crack " << crack << ", edge " << edge << ", plate " << plate);
        MEASURED("bark " << size << " px: " << edge << " of " << size * size
                         << " pixels between crack floor and plate (anti-aliased edges)");
        CHECK(edge > 0);  // intermediate values between crack and plate
        CHECK(plate > crack);
        // no hard step: neighbouring pixels differ by less than a plate's full height
        // wherever the crack is wider than the bevel (the profile is box-filtered)
        double largest = 0;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x + 1 < size; ++x)
                largest = std::fmax(largest, std::fabs(t.height_cm[std::size_t(y * size + x + 1)] -
                                                       t.height_cm[std::size_t(y * size + x)]));
        CHECK(largest < 0.99 * t.max_height);
    }
}

TEST_CASE("bark texture: the filtered crack profile") {
    const float r = 0.1f, b = 0.1f, top = 0.5f;
    // far from the crack: the plate's top; deep inside a wide crack: the floor
    CHECK(bark_crack_profile(1.0f, r, b, top, 0.01f) == doctest::Approx(top));
    CHECK(bark_crack_profile(0.0f, r, b, top, 0.01f) == doctest::Approx(0.0f));
    // monotone from the centre line outwards, and continuous
    float last = -1.0f;
    for (int i = 0; i <= 400; ++i) {
        const float v = bark_crack_profile(float(i) * 0.001f, r, b, top, 0.05f);
        CHECK(v >= last - 1e-6f);
        if (i > 0) CHECK(v - last < 0.05f * top);
        last = v;
    }
    // a crack far narrower than a pixel still darkens its pixel by its share
    const float px = 1.0f, thin = bark_crack_profile(0.0f, 0.01f, 0.001f, top, px);
    CHECK(thin < top);
    CHECK(thin == doctest::Approx(top * (1.0f - 0.02f)).epsilon(0.01));
}

TEST_CASE("bark texture: plates keep their own tone; the inputs are checked") {
    SmallBark b;
    grow(b, Species::camphor);
    const BarkTexture t = texture(b, 64);
    CHECK(t.plates == int(b.regions.regions.size()));
    CHECK(t.mean_crack_width > 0.0f);
    int distinct = 0;
    std::uint8_t first = 0;
    for (std::size_t i = 0; i < t.height_cm.size(); ++i)
        if (t.height_cm[i] > 0.9f * t.max_height) {
            if (!distinct) first = t.albedo[3 * i], distinct = 1;
            else if (t.albedo[3 * i] != first) distinct = 2;
        }
    CHECK(distinct == 2);
    BarkTextureOptions o;
    BarkTexture out;
    BarkCylinder open;
    REQUIRE(build_cylinder(b.p, open));
    CHECK(!make_bark_texture(open, b.p.T, open.net.W.data(), nullptr, o, out));
    CHECK(!make_bark_texture(b.bark, b.p.T, nullptr, nullptr, o, out));
    o.width = 4;
    CHECK(!make_bark_texture(b.bark, b.p.T, b.bark.net.W.data(), nullptr, o, out));
    o.width = 64;
    o.bevel = 0.0f;
    CHECK(!make_bark_texture(b.bark, b.p.T, b.bark.net.W.data(), nullptr, o, out));
}
