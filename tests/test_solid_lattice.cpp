// Tests for lib/shitsukan/solid: fractal_lattice (Type I), lattice_type2, lattice_type3,
// fractal_node, fractal_params, quadtree_lattice.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <ios>
#include <string>
#include <vector>

#include "shitsukan/solid/solid.hpp"

using namespace shitsukan;

namespace {

std::vector<float> build_type1(const FractalParams& p, LatticeView* view, int levels = -1) {
    std::vector<float> values(std::size_t(lattice_bytes(p.R) / sizeof(float)));
    Status s = build_fractal_lattice(p, values.data(), values.size() * sizeof(float), *view, levels);
    REQUIRE_MESSAGE(s.ok(), s.message());
    return values;
}

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// value minus the mean of its parents (eqs. (1)-(4) with g = 0): the correction eps^(n), eq. (5)
float correction(const LatticeView& v, int x, int y, int z, int* level) {
    NodeClass c = classify_node(v.R, x, y, z);
    *level = c.level;
    const int h = c.half;
    auto at = [&](int ax, int sign) {
        return v.at(x + (ax == 0 ? sign * h : 0), y + (ax == 1 ? sign * h : 0),
                    z + (ax == 2 ? sign * h : 0));
    };
    float parents[6];  // the parent rule of fractal_node.hpp
    for (int k = 0; k < 2 * c.odd_count; ++k) {
        const ParentStep p = parent_step(c.odd_axes, k);
        parents[k] = at(p.axis, p.sign);
    }
    const float mean = c.odd_count ? node_from_parents(c.odd_count, parents, 0.0f) : v.at(x, y, z);
    return v.at(x, y, z) - mean;
}

struct Moments {
    double n = 0, sum = 0, sum2 = 0;
    void add(double x) { n += 1, sum += x, sum2 += x * x; }
    double mean() const { return sum / n; }
    double sd() const { return std::sqrt(sum2 / n - mean() * mean()); }
};

}  // namespace

TEST_CASE("the parent rule: odd axes in order x-, x+, y-, y+, z-, z+") {
    // An edge midpoint on y (mask 2): y-, y+.
    CHECK(parent_step(2, 0).axis == 1);
    CHECK(parent_step(2, 0).sign == -1);
    CHECK(parent_step(2, 1).axis == 1);
    CHECK(parent_step(2, 1).sign == +1);
    // A face centre on x and z (mask 5): x-, x+, z-, z+.
    const int face[4] = {0, 0, 2, 2};
    for (int k = 0; k < 4; ++k) {
        CHECK(parent_step(5, k).axis == face[k]);
        CHECK(parent_step(5, k).sign == (k % 2 ? 1 : -1));
    }
    // The cube centre (mask 7): x-, x+, y-, y+, z-, z+.
    for (int k = 0; k < 6; ++k) CHECK(parent_step(7, k).axis == k / 2);
    const float p6[6] = {1, 2, 3, 4, 5, 6};
    CHECK(node_from_parents(1, p6, 0.5f) == 2.0f);   // (1 + 2)/2 + 0.5, eq. (1)
    CHECK(node_from_parents(2, p6, 0.0f) == 2.5f);   // (1+2+3+4)/4, eq. (3)
    CHECK(node_from_parents(3, p6, 0.0f) == 3.5f);   // 21/6, eq. (4)
}

TEST_CASE("lattice side is 2^R + 1 and the node classes follow eqs. (1)-(4)") {
    CHECK(lattice_side(6) == 65);
    CHECK(lattice_bytes(6) == 65ull * 65 * 65 * 4);
    CHECK(classify_node(6, 0, 64, 0).level == 0);
    NodeClass e = classify_node(6, 32, 0, 64);  // level 1 edge midpoint along x
    CHECK(e.level == 1);
    CHECK(e.half == 32);
    CHECK(e.odd_count == 1);
    CHECK(classify_node(6, 32, 32, 0).odd_count == 2);
    CHECK(classify_node(6, 32, 32, 32).odd_count == 3);
    NodeClass fine = classify_node(6, 3, 8, 12);
    CHECK(fine.level == 6);
    CHECK(fine.odd_axes == 1);
    CHECK(level_amplitude(1, 0.5f) == 1.0f);
    CHECK(level_amplitude(3, 0.5f) == doctest::Approx(std::exp(-1.0)).epsilon(1e-6));
}

TEST_CASE("Types I, II and III give the same float at all 65^3 nodes (hash noise)") {
    FractalParams p;  // R = 6, beta 0.9, seed 1987
    p.corners[3] = 0.75f;
    p.corners[6] = -1.25f;
    LatticeView v;
    std::vector<float> values = build_type1(p, &v);
    TypeIILattice t2;
    REQUIRE(t2.init(p).ok());
    TypeIIILattice t3;
    REQUIRE(t3.init(p).ok());
    long mismatches2 = 0, mismatches3 = 0;
    for (int z = 0; z <= 64; ++z)
        for (int y = 0; y <= 64; ++y)
            for (int x = 0; x <= 64; ++x) {
                float a = v.at(x, y, z);
                if (!same_bits(a, t2.node_value(x, y, z))) ++mismatches2;
                if (!same_bits(a, t3.node_value(x, y, z))) ++mismatches3;
            }
    CHECK(mismatches2 == 0);
    CHECK(mismatches3 == 0);
    CHECK(t2.list_size() == std::size_t(65 * 65 * 65 - 8));
    // Type III in an incoherent order (reversed, strided) still agrees.
    long mismatches3b = 0;
    for (int i = 0; i < 20000; ++i) {
        int x = (i * 37) % 65, y = (i * 11 + 5) % 65, z = 64 - (i % 65);
        if (!same_bits(v.at(x, y, z), t3.node_value(x, y, z))) ++mismatches3b;
    }
    CHECK(mismatches3b == 0);
    // D(P) away from the nodes agrees too (same trilinear code on the same corners).
    for (int i = 0; i < 500; ++i) {
        Vec3 q{float(i % 64) + 0.37f, float((i * 7) % 64) + 0.81f, float((i * 13) % 64) + 0.05f};
        float a = turbulence(v, q);
        CHECK(same_bits(a, t3.turbulence(q)));
        CHECK(same_bits(a, t2.turbulence(q)));
    }
}

TEST_CASE("corrections at each level have mean 0 and sd exp(-(n-1) beta) (eq. (5))") {
    const float beta = 0.5f;
    // Fine levels 5..6 from one 65^3 lattice; coarse levels 1..4 pooled over 400 seeds of
    // R = 4 lattices (a level-1 cube has only 19 new nodes).
    Moments m[7];
    {
        FractalParams p;
        p.beta = beta;
        LatticeView v;
        std::vector<float> values = build_type1(p, &v);
        for (int z = 0; z <= 64; ++z)
            for (int y = 0; y <= 64; ++y)
                for (int x = 0; x <= 64; ++x) {
                    int level;
                    if (classify_node(6, x, y, z).level < 5) continue;
                    float c = correction(v, x, y, z, &level);
                    m[level].add(c / level_amplitude(level, beta));
                }
    }
    for (std::uint32_t seed = 1; seed <= 400; ++seed) {
        FractalParams p;
        p.R = 4;
        p.beta = beta;
        p.seed = seed;
        LatticeView v;
        std::vector<float> values = build_type1(p, &v);
        for (int z = 0; z <= 16; ++z)
            for (int y = 0; y <= 16; ++y)
                for (int x = 0; x <= 16; ++x) {
                    int level;
                    if (classify_node(4, x, y, z).level == 0) continue;
                    float c = correction(v, x, y, z, &level);
                    m[level].add(c / level_amplitude(level, beta));
                }
    }
    for (int n = 1; n <= 6; ++n) {
        INFO("level " << n << ": samples " << m[n].n << " mean " << m[n].mean() << " sd "
                      << m[n].sd());
        REQUIRE(m[n].n > 5000);
        // Tolerances: 5 standard errors of the mean (1/sqrt(N)) and of the sd (1/sqrt(2N)).
        CHECK(std::fabs(m[n].mean()) < 5.0 / std::sqrt(m[n].n));
        CHECK(std::fabs(m[n].sd() - 1.0) < 5.0 / std::sqrt(2.0 * m[n].n));
    }
}

TEST_CASE("partial builds and the sequential noise source") {
    FractalParams p;
    LatticeView v;
    std::vector<float> values = build_type1(p, &v, 2);
    CHECK(std::isfinite(v.at(16, 48, 32)));  // spacing 16 grid: level <= 2
    CHECK(std::isnan(v.at(8, 0, 0)));        // level 3: not built yet
    std::vector<float> full = build_type1(p, &v);
    CHECK(same_bits(values[std::size_t(32 * 65 * 65 + 16 * 65 + 48)],
                    full[std::size_t(32 * 65 * 65 + 16 * 65 + 48)]));

    FractalParams q = p;
    q.noise = NoiseSource::sequential;
    LatticeView vs;
    std::vector<float> seq = build_type1(q, &vs);
    CHECK(!same_bits(vs.at(32, 32, 32), v.at(32, 32, 32)));
    // Type II with a sequential stream: the values depend on the order of the queries.
    TypeIILattice a, b;
    REQUIRE(a.init(q).ok());
    REQUIRE(b.init(q).ok());
    float a1 = a.node_value(5, 9, 17);
    (void)b.node_value(40, 3, 60);
    float b1 = b.node_value(5, 9, 17);
    CHECK(!same_bits(a1, b1));
    TypeIIILattice t3;
    CHECK(t3.init(q).code() == StatusCode::not_supported);
}

TEST_CASE("Type I at R = 7: every node is eq. (1), (3) or (4) of its parents and its own g") {
    // Rows of 64 and 65 nodes: longer than the build's runs along x, so runs are split.
    FractalParams p;
    p.R = 7;
    p.corners[1] = 0.5f;
    p.corners[7] = -0.75f;
    LatticeView v;
    std::vector<float> values = build_type1(p, &v);
    long mismatches = 0, nodes = 0;
    for (int z = 0; z <= 128; ++z)
        for (int y = 0; y <= 128; ++y)
            for (int x = 0; x <= 128; ++x) {
                const NodeClass c = classify_node(p.R, x, y, z);
                if (c.level == 0) continue;
                float parents[6];
                for (int k = 0; k < 2 * c.odd_count; ++k) {
                    const ParentStep s = parent_step(c.odd_axes, k);
                    parents[k] = v.at(x + (s.axis == 0 ? s.sign * c.half : 0),
                                      y + (s.axis == 1 ? s.sign * c.half : 0),
                                      z + (s.axis == 2 ? s.sign * c.half : 0));
                }
                const float g = node_gaussian(p.seed, x, y, z) * level_amplitude(c.level, p.beta);
                mismatches += !same_bits(v.at(x, y, z), node_from_parents(c.odd_count, parents, g));
                ++nodes;
            }
    CHECK(nodes == 129L * 129 * 129 - 8);
    CHECK(mismatches == 0);
}

TEST_CASE("NoiseSource::sequential draws g in the documented order") {
    // fractal_lattice.hpp: level by level; step (1), (2), (3); pattern by pattern in increasing
    // odd-axis mask; each pattern z, y, x upwards; one Pcg32(seed, kLatticeStream) draw a node.
    for (int R : {3, 7}) {
        FractalParams p;
        p.R = R;
        p.noise = NoiseSource::sequential;
        p.corners[2] = 1.5f;
        LatticeView v;
        std::vector<float> values = build_type1(p, &v);
        const int side = (1 << R) + 1;
        std::vector<float> want(values.size());
        auto at = [&](int x, int y, int z) -> float& {
            return want[(std::size_t(z) * std::size_t(side) + std::size_t(y)) * std::size_t(side) +
                        std::size_t(x)];
        };
        for (int k = 0; k < 8; ++k)
            at((k & 1) * (side - 1), ((k >> 1) & 1) * (side - 1), (k >> 2) * (side - 1)) =
                p.corners[k];
        Pcg32 rng(p.seed, kLatticeStream);
        for (int n = 1; n <= R; ++n) {
            const int h = 1 << (R - n);
            const float L = level_amplitude(n, p.beta);
            for (int odd = 1; odd <= 3; ++odd)
                for (int mask = 1; mask < 8; ++mask) {
                    if ((mask & 1) + ((mask >> 1) & 1) + ((mask >> 2) & 1) != odd) continue;
                    for (int z = (mask & 4) ? h : 0; z < side; z += 2 * h)
                        for (int y = (mask & 2) ? h : 0; y < side; y += 2 * h)
                            for (int x = (mask & 1) ? h : 0; x < side; x += 2 * h) {
                                float parents[6];
                                for (int k = 0; k < 2 * odd; ++k) {
                                    const ParentStep s = parent_step(mask, k);
                                    parents[k] = at(x + (s.axis == 0 ? s.sign * h : 0),
                                                    y + (s.axis == 1 ? s.sign * h : 0),
                                                    z + (s.axis == 2 ? s.sign * h : 0));
                                }
                                at(x, y, z) = node_from_parents(odd, parents, rng.gaussian() * L);
                            }
                }
        }
        long mismatches = 0;
        for (std::size_t i = 0; i < values.size(); ++i)
            mismatches += !same_bits(values[i], want[i]);
        CHECK(mismatches == 0);
    }
}

TEST_CASE("Type III works at R = 20 in O(R) memory and agrees with Type II there") {
    FractalParams p;
    p.R = 20;
    TypeIIILattice t3;
    REQUIRE(t3.init(p).ok());
    TypeIILattice t2;
    REQUIRE(t2.init(p).ok());
    // 25 levels of 27 floats (O(R)) plus the fixed 64-block row cache, no allocation
    CHECK(TypeIIILattice::object_bytes() < 4096 + 64 * 120);
    // The size lattice_type3.hpp's manual states (64-bit host and 32-bit Cortex-M alike).
    if (kTypeIIIRowCache == 64 || kTypeIIIRowCache == 0)
        CHECK(TypeIIILattice::object_bytes() == (kTypeIIIRowCache > 0 ? 10888u : 3328u));
    CHECK(t3.ancestry_bytes() == 20 * (12 + 27 * 4));
    const std::int32_t last = 1 << 20;
    const std::int32_t probes[5][3] = {{0, 0, 0}, {last, 17, 123457}, {524288, 524288, 524288},
                                       {999999, 3, 77}, {1, last - 1, 262145}};
    for (auto& q : probes) {
        float a = t3.node_value(q[0], q[1], q[2]);
        CHECK(same_bits(a, t2.node_value(q[0], q[1], q[2])));
    }
    // A coherent scan along x recomputes about one subdivision per cell crossed.
    long before = t3.subdivisions();
    float prev = t3.turbulence(Vec3{1000.0f, 5000.0f, 7000.0f});
    float max_step = 0;
    for (int i = 1; i <= 4000; ++i) {
        float d = t3.turbulence(Vec3{1000.0f + 0.25f * float(i), 5000.0f, 7000.0f});
        max_step = std::fmax(max_step, std::fabs(d - prev));
        prev = d;
    }
    long per_cell = (t3.subdivisions() - before) / 1000;
    CHECK(per_cell <= 3);
    CHECK(max_step < 0.05f);  // continuous: level-20 amplitude is e^-9.5 ~ 7.5e-5 per cell
    float out;
    CHECK(t3.node_value_checked(0, last + 1, 0, out).code() == StatusCode::out_of_range);
    CHECK(t3.turbulence_checked(Vec3{-1.0f, 0.0f, 0.0f}, out).code() == StatusCode::out_of_range);
}

TEST_CASE("bad lattice parameters get a clear status") {
    FractalParams p;
    p.R = -1;
    std::vector<float> buf(65 * 65 * 65);
    LatticeView v;
    Status s = build_fractal_lattice(p, buf.data(), buf.size() * 4, v);
    CHECK(s.code() == StatusCode::invalid_argument);
    CHECK(std::string(s.message()).find("got -1") != std::string::npos);
    p.R = 11;
    CHECK(build_fractal_lattice(p, buf.data(), buf.size() * 4, v).code() ==
          StatusCode::invalid_argument);
    p = FractalParams();
    p.beta = -0.1f;
    CHECK(build_fractal_lattice(p, buf.data(), buf.size() * 4, v).code() ==
          StatusCode::invalid_argument);
    p.beta = std::nanf("");
    CHECK(build_fractal_lattice(p, buf.data(), buf.size() * 4, v).code() ==
          StatusCode::invalid_argument);
    p = FractalParams();
    p.corners[5] = INFINITY;
    CHECK(!build_fractal_lattice(p, buf.data(), buf.size() * 4, v).ok());
    p = FractalParams();
    s = build_fractal_lattice(p, buf.data(), 1000, v);
    CHECK(s.code() == StatusCode::buffer_too_small);
    CHECK(std::string(s.message()).find("1098500") != std::string::npos);
    p.R = 25;
    TypeIIILattice t3;
    CHECK(t3.init(p).code() == StatusCode::invalid_argument);
    // Type II: R beyond its 21-bit packing, and nodes outside the lattice.
    TypeIILattice t2;
    p.R = kTypeIIMaxDepth + 1;
    s = t2.init(p);
    CHECK(s.code() == StatusCode::invalid_argument);
    CHECK(std::string(s.message()).find("got 21") != std::string::npos);
    float out = 0.0f;
    CHECK(t2.node_value_checked(0, 0, 0, out).code() == StatusCode::invalid_argument);   // no init
    p.R = 3;
    REQUIRE(t2.init(p).ok());
    s = t2.node_value_checked(9, 0, 0, out);
    CHECK(s.code() == StatusCode::out_of_range);
    CHECK(std::string(s.message()).find("(9, 0, 0)") != std::string::npos);
    CHECK(t2.node_value_checked(0, -1, 0, out).code() == StatusCode::out_of_range);
    CHECK(t2.node_value_checked(8, 8, 8, out).ok());
    CHECK(out == p.corners[7]);
    // Type III before init.
    TypeIIILattice fresh;
    CHECK(fresh.node_value_checked(0, 0, 0, out).code() == StatusCode::invalid_argument);
    CHECK(fresh.turbulence_checked(Vec3{0.0f, 0.0f, 0.0f}, out).code() ==
          StatusCode::invalid_argument);
}

TEST_CASE("quadtree lattice (okada1987 §2.1): midpoints and centres, level by level") {
    QuadtreeParams q;
    q.R = 4;
    q.corners[1] = 2.0f;
    float h[17 * 17];
    int side = 0;
    REQUIRE(build_quadtree_lattice(q, h, sizeof h, side, 1).ok());
    CHECK(side == 17);
    CHECK(std::isnan(h[4]));
    // Level 1 centre = mean of the four corners + g·1
    float g = hash_gaussian(q.seed, kQuadtreeStream, 8, 8, 0);
    CHECK(h[8 * 17 + 8] == doctest::Approx(0.5f + g).epsilon(1e-6));
    REQUIRE(build_quadtree_lattice(q, h, sizeof h, side).ok());
    for (float v : h) CHECK(std::isfinite(v));
    CHECK(build_quadtree_lattice(q, h, 10, side).code() == StatusCode::buffer_too_small);
    q.R = 13;
    CHECK(build_quadtree_lattice(q, h, sizeof h, side).code() == StatusCode::invalid_argument);
}

TEST_CASE("tiny lattices (R = 0, 1, 2): the three types still agree") {
    for (int R = 0; R <= 2; ++R) {
        FractalParams p;
        p.R = R;
        for (int i = 0; i < 8; ++i) p.corners[i] = 0.25f * float(i) - 1.0f;
        LatticeView v;
        std::vector<float> values = build_type1(p, &v);
        TypeIILattice t2;
        REQUIRE(t2.init(p).ok());
        TypeIIILattice t3;
        REQUIRE(t3.init(p).ok());
        const int last = 1 << R;
        for (int z = 0; z <= last; ++z)
            for (int y = 0; y <= last; ++y)
                for (int x = 0; x <= last; ++x) {
                    CHECK(same_bits(v.at(x, y, z), t2.node_value(x, y, z)));
                    CHECK(same_bits(v.at(x, y, z), t3.node_value(x, y, z)));
                }
        CHECK(v.at(last, 0, last) == p.corners[5]);  // corner (1, 0, 1)
        const Vec3 mid{0.5f * float(last), 0.25f * float(last), 0.75f * float(last)};
        CHECK(same_bits(turbulence(v, mid), t3.turbulence(mid)));
    }
}

TEST_CASE("eqs. (1)-(4) by hand on an R = 2 lattice: face centres from the EDGE MIDPOINTS") {
    // Written out from the paper without the library's node helpers: g of node (x, y, z) is
    // node_gaussian(seed, x, y, z) (hash noise), L_r^(n) = exp(-(n-1)·beta).
    FractalParams p;
    p.R = 2;
    p.beta = 0.7f;
    for (int i = 0; i < 8; ++i) p.corners[i] = float(i * i) * 0.5f - 3.0f;  // unequal corners
    LatticeView v;
    std::vector<float> values = build_type1(p, &v);
    auto g = [&](int x, int y, int z) { return double(node_gaussian(p.seed, x, y, z)); };
    auto at = [&](int x, int y, int z) { return double(v.at(x, y, z)); };
    const double tol = 1e-5;
    for (int n = 1; n <= 2; ++n) {
        const int h = 1 << (2 - n);  // half spacing of level n
        const double L = std::exp(-double(n - 1) * double(p.beta));  // eq. (2)
        // eq. (1): the edge midpoint (h, 0, 0) from its two ends.
        CHECK(at(h, 0, 0) == doctest::Approx((at(0, 0, 0) + at(2 * h, 0, 0)) / 2 +
                                             g(h, 0, 0) * L).epsilon(tol));
        // eq. (3): the face centre (h, h, 0) from the four edge midpoints of the same level.
        const double edges = (at(0, h, 0) + at(2 * h, h, 0) + at(h, 0, 0) + at(h, 2 * h, 0)) / 4;
        CHECK(at(h, h, 0) == doctest::Approx(edges + g(h, h, 0) * L).epsilon(tol));
        // ... which is not the mean of the face's corners (the trap of the reading notes).
        const double corners =
            (at(0, 0, 0) + at(2 * h, 0, 0) + at(0, 2 * h, 0) + at(2 * h, 2 * h, 0)) / 4;
        CHECK(std::fabs(corners - edges) > 1e-3);
        // eq. (4): the cube centre (h, h, h) from the six face centres.
        const double faces = (at(0, h, h) + at(2 * h, h, h) + at(h, 0, h) + at(h, 2 * h, h) +
                              at(h, h, 0) + at(h, h, 2 * h)) / 6;
        CHECK(at(h, h, h) == doctest::Approx(faces + g(h, h, h) * L).epsilon(tol));
    }
    // The amplitudes themselves: level 1 is 1, each level e^-beta of the one before.
    CHECK(level_amplitude(1, 0.7f) == 1.0f);
    CHECK(level_amplitude(2, 0.7f) == doctest::Approx(std::exp(-0.7)).epsilon(1e-6));
    CHECK(level_amplitude(6, 0.7f) == doctest::Approx(std::exp(-3.5)).epsilon(1e-6));
}

TEST_CASE("Type III as okada1989 has it (no reuse): the same values, R subdivisions a query") {
    FractalParams p;
    TypeIIILattice cached, paper;
    REQUIRE(cached.init(p).ok());
    REQUIRE(paper.init(p).ok());
    paper.set_reuse(false);
    CHECK(!paper.reuse());
    const int n = 300;
    for (int i = 0; i < n; ++i) {
        const Vec3 q{float(i % 64) + 0.25f, float((i * 7) % 64) + 0.5f, 31.75f};
        CHECK(same_bits(cached.turbulence(q), paper.turbulence(q)));
    }
    CHECK(paper.subdivisions() == long(n) * p.R);  // every query descends all R levels
    CHECK(cached.subdivisions() < paper.subdivisions());
}

TEST_CASE("Type II's container memory counts the hash map, not only the payload") {
    FractalParams p;
    TypeIILattice t2;
    REQUIRE(t2.init(p).ok());
    for (int i = 0; i < 200; ++i) (void)t2.turbulence(Vec3{float(i % 64) + 0.5f, 10.5f, 20.5f});
    REQUIRE(t2.list_size() > 0);
    CHECK(t2.container_bytes() >= t2.list_size() * 32);  // one heap node of >= 32 bytes each
    CHECK(t2.container_bytes() > 2 * t2.list_bytes());
}

// fuzz_geometry: corners of -3.4e38 built a quadtree lattice full of -inf with an ok Status
// (the sums of the means overflowed); the 3D lattice sums the same way.
TEST_CASE("fractal lattices refuse corners beyond kMaxFractalCorner, build finite ones there") {
    QuadtreeParams q;
    q.R = 3;
    q.beta = 0.0f;
    q.corners[0] = 127.0f;
    q.corners[2] = -3.3895e38f;
    std::vector<float> buffer(9 * 9);
    int side = 0;
    const Status s = build_quadtree_lattice(q, buffer.data(), buffer.size() * 4, side);
    CHECK(s.code() == StatusCode::invalid_argument);
    CHECK(std::string(s.message()).find("corner value 2") != std::string::npos);
    for (float c : {kMaxFractalCorner, -kMaxFractalCorner}) {
        for (float& v : q.corners) v = c;
        REQUIRE(build_quadtree_lattice(q, buffer.data(), buffer.size() * 4, side).ok());
        for (float v : buffer) CHECK(std::isfinite(v));
    }
    FractalParams p;
    p.R = 2;
    p.corners[5] = 1e31f;
    CHECK(validate_fractal_params(p, 12).code() == StatusCode::invalid_argument);
    p.corners[5] = -kMaxFractalCorner;
    CHECK(validate_fractal_params(p, 12).ok());
}

// level_amplitudes: eq. (2) computed by the compiler (det_exp_constexpr), for a lattice on a
// device that should link no double arithmetic. Over many betas (the presets' among them,
// steps from 0 to 40, and betas whose deepest levels fall below the smallest float and
// double) every level's float must be level_amplitude's at run time, bit for bit. make
// test-wasm runs it under clang too, whose constant evaluation once rounded the subnormal
// doubles of beta 34.5's deepest levels up to the smallest float (level_amplitudes now says +0
// outright there).
namespace {
constexpr int kBetaCount = 420;
struct AmplitudeSamples {
    LevelAmplitudes a[kBetaCount];
};
constexpr AmplitudeSamples make_amplitude_samples() {
    AmplitudeSamples s{};
    for (int i = 0; i < kBetaCount; ++i) {
        float beta = float(i) * 0.0953f + float(i % 5) * 1.0e-5f;  // 0 .. 40
        if (i == 0) beta = kOkada1987Beta;
        if (i == 1) beta = FractalParams{}.beta;
        if (i == 2) beta = 0.0f;
        if (i == 3) beta = 30.85f;  // level 24 at e^-709.6: a subnormal double
        if (i == 4) beta = 1.0e30f;  // every level past the first: 0
        s.a[i] = level_amplitudes(beta);
    }
    return s;
}
constexpr AmplitudeSamples kAmplitudes = make_amplitude_samples();
}  // namespace

TEST_CASE("level_amplitudes: eq. (2) at compile time, level_amplitude's bits for every beta") {
    int differ = 0;
    for (const LevelAmplitudes& a : kAmplitudes.a) {
        for (int n = 1; n <= kTypeIIIMaxDepth; ++n) {
            const float run = level_amplitude(n, a.beta);
            std::uint32_t x, y;
            std::memcpy(&x, &a.v[n], 4);
            std::memcpy(&y, &run, 4);
            if (x != y && ++differ <= 5)
                MESSAGE("beta " << a.beta << " level " << n << ": compile time bits " << std::hex
                                << x << ", run time " << y);
        }
    }
    CHECK(differ == 0);
    CHECK(kOkada1987Amplitudes.beta == kOkada1987Beta);
    for (int n = 1; n <= kTypeIIIMaxDepth; ++n)
        CHECK(kOkada1987Amplitudes.v[n] == level_amplitude(n, kOkada1987Beta));
    static_assert(level_amplitudes(0.5f).v[1] == 1.0f, "L^(1) = 1 (eq. (2)'s closed form)");
}

TEST_CASE("Type III with amplitudes computed at compile time: the same lattice") {
    const FractalParams p = okada1987_lattice_params();
    TypeIIILattice at_run_time, precomputed;
    REQUIRE(at_run_time.init(p).ok());
    REQUIRE(precomputed.init(p, kOkada1987Amplitudes).ok());
    for (int i = 0; i < 2000; ++i) {
        const Vec3 q{float(i % 61) + 0.3f, float((i * 7) % 64) + 0.6f, float((i * 13) % 64)};
        const float a = at_run_time.turbulence(q), b = precomputed.turbulence(q);
        REQUIRE(std::memcmp(&a, &b, 4) == 0);
    }
    // Amplitudes for another beta are refused, naming both.
    FractalParams other = p;
    other.beta = 0.5f;
    const Status s = precomputed.init(other, kOkada1987Amplitudes);
    CHECK(s.code() == StatusCode::invalid_argument);
    CHECK(std::string(s.message()) ==
          "Type III lattice: the amplitudes are for beta 0.9, the parameters' beta is 0.5");
    CHECK(precomputed.init(p, LevelAmplitudes{}).code() == StatusCode::invalid_argument);
    // A table marked with the right beta but not filled by level_amplitudes is refused too
    // (all zero: a flat lattice; a level above the one before; a first level other than 1).
    LevelAmplitudes unfilled;
    unfilled.beta = p.beta;
    const Status z = precomputed.init(p, unfilled);
    CHECK(z.code() == StatusCode::invalid_argument);
    CHECK(std::string(z.message()) ==
          "Type III lattice: the amplitudes are not eq. (2)'s (level 1 is 0): fill them with "
          "level_amplitudes(beta)");
    LevelAmplitudes rising = kOkada1987Amplitudes;
    rising.v[4] = rising.v[3] * 1.5f;
    CHECK(precomputed.init(p, rising).code() == StatusCode::invalid_argument);
    LevelAmplitudes scaled = kOkada1987Amplitudes;
    scaled.v[1] = 0.5f;
    CHECK(precomputed.init(p, scaled).code() == StatusCode::invalid_argument);
    LevelAmplitudes negative = kOkada1987Amplitudes;
    negative.v[p.R] = -0.0001f;
    CHECK(precomputed.init(p, negative).code() == StatusCode::invalid_argument);
    CHECK(precomputed.init(p, kOkada1987Amplitudes).ok());
}
