// Tests for lib/shitsukan/solid: turbulence (eq. (6)), marble (eq. (8)), wood (eqs. (10),
// (11)), pixel_shift (okada1989 eq. (7)), color_lookup (eq. (12)), lattice_store.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <unistd.h>  // getpid, truncate (POSIX: the test files only)

#include "shitsukan/core/prng.hpp"
#include "shitsukan/solid/solid.hpp"

using namespace shitsukan;

namespace {
const FractalLattice& test_lattice() {
    static FractalLattice lattice;
    if (lattice.empty()) {
        FractalParams p;
        REQUIRE(lattice.build(p).ok());
    }
    return lattice;
}
bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }
}  // namespace

TEST_CASE("trilinear D(P): exact at nodes, linear along edges, continuous across faces") {
    const LatticeView v = test_lattice().view();
    for (int i = 0; i < 200; ++i) {
        int x = (i * 7) % 65, y = (i * 29) % 65, z = (i * 3) % 65;
        CHECK(same_bits(turbulence(v, Vec3{float(x), float(y), float(z)}), v.at(x, y, z)));
    }
    // Along an x edge between nodes (10, 20, 30) and (11, 20, 30): linear in t.
    const float a = v.at(10, 20, 30), b = v.at(11, 20, 30);
    for (float t = 0.0f; t <= 1.0f; t += 0.125f) {
        float d = turbulence(v, Vec3{10.0f + t, 20.0f, 30.0f});
        CHECK(d == doctest::Approx((1.0f - t) * a + t * b).epsilon(1e-5));
    }
    // Across the face x = 11: the limit from cell 10 (fx -> 1) equals cell 11 at fx = 0.
    float corners[8];
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i) corners[i + 2 * j + 4 * k] = v.at(10 + i, 20 + j, 30 + k);
    float from_left = trilinear_corners(corners, 1.0f, 0.3f, 0.6f);
    float at_face = turbulence(v, Vec3{11.0f, 20.3f, 30.6f});
    CHECK(from_left == doctest::Approx(at_face).epsilon(1e-6));
    // The weights of eq. (6) sum to 1: a constant lattice interpolates to the constant.
    const float ones[8] = {2.5f, 2.5f, 2.5f, 2.5f, 2.5f, 2.5f, 2.5f, 2.5f};
    CHECK(trilinear_corners(ones, 0.3f, 0.7f, 0.1f) == doctest::Approx(2.5f).epsilon(1e-6));
}

TEST_CASE("trilinear_corners is eq. (6) itself: sum of D_i times the opposite box volume V_i") {
    // The library evaluates eq. (6) factored (lerps along x, y, z); here it is written out
    // literally, in double: V_i = product over the axes of the extent of the box opposite P_i.
    Pcg32 rng(1987u, 6u);
    for (int t = 0; t < 2000; ++t) {
        float d[8];
        for (float& v : d) v = rng.uniform(-3.0f, 3.0f);
        const float f[3] = {rng.uniform(0.0f, 1.0f), rng.uniform(0.0f, 1.0f),
                            rng.uniform(0.0f, 1.0f)};
        double literal = 0.0;
        for (int corner = 0; corner < 8; ++corner) {
            double volume = 1.0;  // box between P_x and the corner opposite P_i
            for (int axis = 0; axis < 3; ++axis)
                volume *= ((corner >> axis) & 1) ? double(f[axis]) : 1.0 - double(f[axis]);
            literal += double(d[corner]) * volume;
        }
        // float rounding of a handful of operations on values up to 3: well under 1e-5.
        CHECK(std::fabs(double(trilinear_corners(d, f[0], f[1], f[2])) - literal) < 1e-5);
    }
    // Exactly the corner value when the fractions are 0 or 1 (the node is returned unchanged).
    const float d[8] = {0.1f, 0.7f, -0.3f, 1.9f, 2.2f, -1.1f, 0.3f, 0.9f};
    for (int corner = 0; corner < 8; ++corner)
        CHECK(same_bits(trilinear_corners(d, float(corner & 1), float((corner >> 1) & 1),
                                          float((corner >> 2) & 1)),
                        d[corner]));
}

TEST_CASE("turbulence outside the lattice: clamped, or refused by the checked form") {
    const LatticeView v = test_lattice().view();
    CHECK(same_bits(turbulence(v, Vec3{-5.0f, 3.0f, 3.0f}), turbulence(v, Vec3{0.0f, 3.0f, 3.0f})));
    CHECK(same_bits(turbulence(v, Vec3{70.0f, 3.0f, 3.0f}), v.at(64, 3, 3)));
    CHECK(std::isfinite(turbulence(v, Vec3{std::nanf(""), 3.0f, 3.0f})));
    float out = 0;
    Status s = turbulence_checked(v, Vec3{64.5f, 1.0f, 1.0f}, out);
    CHECK(s.code() == StatusCode::out_of_range);
    CHECK(std::string(s.message()).find("64.5") != std::string::npos);
    CHECK(turbulence_checked(v, Vec3{std::nanf(""), 1.0f, 1.0f}, out).code() ==
          StatusCode::invalid_argument);
    CHECK(turbulence_checked(v, Vec3{64.0f, 0.0f, 32.0f}, out).ok());
}

TEST_CASE("turbulence_row and turbulence_points: the same bits as single calls") {
    const LatticeView v = test_lattice().view();
    Pcg32 rng(18u, 3u);
    std::vector<float> row(700), want(700);
    int mismatches = 0, rows = 0;
    for (int r = 0; r < 400; ++r) {
        // Rows of every kind: inside, starting or ending outside (clamped), steps from tiny to
        // several cells, backwards, zero, on nodes, NaN in y or z, and odd lengths.
        float x0 = rng.uniform(-10.0f, 74.0f), y = rng.uniform(-5.0f, 69.0f);
        float z = rng.uniform(-5.0f, 69.0f), step = rng.uniform(-0.5f, 3.0f);
        if (r % 7 == 0) step = 1.0f / 8.0f;
        if (r % 11 == 0) step = 0.0f;
        if (r % 13 == 0) x0 = std::floor(x0), step = 1.0f;
        if (r % 17 == 0) y = std::nanf("");
        if (r % 19 == 0) z = 64.0f;
        const int n = 1 + int(rng.next_u32() % 700u);
        turbulence_row(v, Vec3{x0, y, z}, step, n, row.data());
        for (int i = 0; i < n; ++i)
            mismatches += !same_bits(row[std::size_t(i)],
                                     turbulence(v, Vec3{x0 + float(i) * step, y, z}));
        ++rows;
    }
    CHECK(rows == 400);
    CHECK(mismatches == 0);
    std::vector<Vec3> pts(5000);
    for (Vec3& p : pts)
        p = Vec3{rng.uniform(-3.0f, 67.0f), rng.uniform(-3.0f, 67.0f), rng.uniform(-3.0f, 67.0f)};
    pts[7].x = std::nanf("");
    std::vector<float> got(pts.size());
    turbulence_points(v, pts.data(), pts.size(), got.data());
    mismatches = 0;
    for (std::size_t i = 0; i < pts.size(); ++i)
        mismatches += !same_bits(got[i], turbulence(v, pts[i]));
    CHECK(mismatches == 0);
}

TEST_CASE("turbulence_row: whole 512 x 512 slices, the same bits as single calls") {
    const LatticeView v = test_lattice().view();
    std::vector<float> row(512), baseline(512);
    // Slices as the figures and the bench take them (1/8 cell per pixel), others with steps
    // that do not divide a cell, starting before the lattice or ending beyond it, and slices
    // on the faces z = 0 and z = 64 and just outside them; steps with many groups of four in a
    // cell, with groups straddling a face most of the time, and with every group spanning
    // faces; rows whose length leaves one to three samples after the last group of four.
    struct Slice {
        float x0, step, y0, y_step, z;
        int n;
    };
    const Slice slices[] = {{0.5f / 8.0f, 1.0f / 8.0f, 0.5f / 8.0f, 1.0f / 8.0f, 32.3f, 512},
                            {0.0f, 1.0f / 8.0f, 0.0f, 1.0f / 8.0f, 0.0f, 512},
                            {-3.3f, 0.15f, -2.0f, 0.14f, 64.0f, 512},
                            {-0.7f, 1.0f / 3.0f, 1.0f, 0.1f, 17.5f, 512},
                            {60.1f, 0.01f, 63.9f, 0.001f, -0.0f, 512},
                            {-0.0f, 0.0625f, 10.0f, 0.1f, 64.5f, 512},
                            {0.3f, 1.0f / 1024.0f, 0.2f, 0.125f, 5.25f, 511},
                            {1.05f, 0.3f, 0.0f, 0.126f, 40.7f, 510},
                            {-20.0f, 0.17f, 3.3f, 0.11f, 63.999f, 509},
                            {0.25f, 1.7f, 0.5f, 0.12f, 12.0f, 37}};
    long mismatches = 0, baseline_mismatches = 0, samples = 0;
    for (const Slice& s : slices)
        for (int y = 0; y < 512; ++y) {
            const float py = s.y0 + float(y) * s.y_step;
            turbulence_row(v, Vec3{s.x0, py, s.z}, s.step, s.n, row.data());
            detail::turbulence_row_baseline(v, Vec3{s.x0, py, s.z}, s.step, s.n,
                                            baseline.data());
            for (int x = 0; x < s.n; ++x, ++samples) {
                const float want = turbulence(v, Vec3{s.x0 + float(x) * s.step, py, s.z});
                mismatches += !same_bits(row[std::size_t(x)], want);
                baseline_mismatches += !same_bits(baseline[std::size_t(x)], want);
            }
        }
    CHECK(samples == 512L * (6 * 512 + 511 + 510 + 509 + 37));
    CHECK(mismatches == 0);
    CHECK(baseline_mismatches == 0);
}

TEST_CASE("turbulence: the fast path gives the clamped path's bits, on the faces and beside") {
    const LatticeView v = test_lattice().view();
    const float edges[] = {-2.0f, -1.5f, -1.0f,  -0.75f, -0.0f,         0.0f,
                           1e-30f, 0.5f, 63.99f, 64.0f,  64.0000076f,   65.0f,
                           1e9f,   -1e9f, std::nanf(""), -std::nanf(""), INFINITY, -INFINITY};
    int mismatches = 0;
    for (float x : edges)
        for (float y : edges)
            for (float z : {-0.5f, -0.0f, 0.25f, 31.5f, 64.0f, std::nanf("")})
                mismatches +=
                    !same_bits(turbulence(v, Vec3{x, y, z}), detail::turbulence_clamped(v, Vec3{x, y, z}));
    CHECK(mismatches == 0);
}

TEST_CASE("marble eq. (8): trapezoid with exponential skirt, sum of stripes, pixel shift") {
    const MarbleStripe s{10.0f, 4.0f, 0.5f};
    CHECK(trapezoid_skirt(10.0f, s) == 1.0f);
    CHECK(trapezoid_skirt(12.0f, s) == 1.0f);  // the edge of the flat top
    CHECK(trapezoid_skirt(13.0f, s) == doctest::Approx(std::exp(-0.5)).epsilon(1e-6));
    CHECK(trapezoid_skirt(5.0f, s) == doctest::Approx(std::exp(-1.5)).epsilon(1e-6));
    const MarbleStripe two[2] = {s, {30.0f, 2.0f, 1.0f}};
    CHECK(marble_original(20.0f, two, 2) ==
          doctest::Approx(std::exp(-0.5 * 8.0) + std::exp(-9.0)).epsilon(1e-6));
    MarbleParams m{two, 2, 16.0f};
    REQUIRE(validate_marble(m).ok());
    // P' = P + k·D·(0, 0, 1): the texture at z shows G at z + k·D.
    const Vec3 p{3.0f, 4.0f, 5.0f};
    CHECK(marble_texture(p, 0.25f, m) == doctest::Approx(marble_original(9.0f, two, 2)));
    // k = 0 gives G itself, whatever D is.
    m.k = 0.0f;
    for (float d : {-2.0f, 0.0f, 1.5f})
        CHECK(marble_texture(p, d, m) == marble_original(5.0f, two, 2));
    // bad stripes
    MarbleStripe zero_width{10.0f, 0.0f, 1.0f};
    Status bad = validate_marble(MarbleParams{&zero_width, 1, 16.0f});
    CHECK(bad.code() == StatusCode::invalid_argument);
    CHECK(std::string(bad.message()).find("width") != std::string::npos);
    MarbleStripe no_decay{10.0f, 1.0f, 0.0f};
    CHECK(!validate_marble(MarbleParams{&no_decay, 1, 16.0f}).ok());
    CHECK(!validate_marble(MarbleParams{nullptr, 0, 16.0f}).ok());
    MarbleStripe nan_c{std::nanf(""), 1.0f, 1.0f};
    CHECK(!validate_marble(MarbleParams{&nan_c, 1, 16.0f}).ok());
    CHECK(validate_marble(MarbleParams{two, 2, std::nanf("")}).code() ==
          StatusCode::invalid_argument);
    MarbleStripe inf_w{10.0f, INFINITY, 1.0f};
    CHECK(!validate_marble(MarbleParams{&inf_w, 1, 16.0f}).ok());
    Status bad2 = validate_marble(MarbleParams{two, -3, 16.0f});
    CHECK(bad2.code() == StatusCode::invalid_argument);
    CHECK(std::string(bad2.message()).find("got -3") != std::string::npos);
}

TEST_CASE("marble_density: G' = 1 - min(G, 1), solid_density_at's marble case bit for bit") {
    const MarbleStripe two[2] = {{10.0f, 4.0f, 0.5f}, {13.0f, 2.0f, 1.0f}};
    const MarbleParams m{two, 2, 16.0f};
    // inside a layer G >= 1: the impurity's colour end (G' = 0); overlapping skirts add up
    // past 1 and are clamped
    CHECK(marble_density(Vec3{0.0f, 0.0f, 10.0f}, 0.0f, m) == 0.0f);
    CHECK(marble_original(11.5f, two, 2) > 1.0f);
    CHECK(marble_density(Vec3{0.0f, 0.0f, 11.5f}, 0.0f, m) == 0.0f);
    // far from both: limestone, G' -> 1
    CHECK(marble_density(Vec3{0.0f, 0.0f, 60.0f}, 0.0f, m) > 0.999f);
    SolidMaterial material;
    material.pattern = SolidPattern::marble;
    material.marble = m;
    for (int i = 0; i < 200; ++i) {
        const Vec3 p{0.5f * float(i % 7), 0.25f * float(i % 5), 0.1f * float(i)};
        const float d = 0.01f * float(i % 37) - 0.18f;
        const float g = marble_density(p, d, m);
        CHECK(g == 1.0f - std::fmin(marble_texture(p, d, m), 1.0f));
        CHECK(g == solid_density_at(material, p, d));
    }
}

TEST_CASE("wood eqs. (10), (11): radial sine, radial displacement, r = 0") {
    WoodParams w;
    w.x0 = 10.0f;
    w.y0 = 20.0f;
    w.k2 = 0.5f;
    w.k = 1.6f;
    REQUIRE(validate_wood(w).ok());
    const float pi = 3.14159265f;
    // r = pi/(2 k2) = pi: the crest of the first ring.
    CHECK(wood_original(Vec3{10.0f + pi, 20.0f, 7.0f}, w) == doctest::Approx(1.0f).epsilon(1e-6));
    CHECK(wood_original(Vec3{10.0f, 20.0f - 2.0f * pi, -3.0f}, w) ==
          doctest::Approx(0.0f).epsilon(1e-5));
    Vec3 u;
    REQUIRE(wood_radial_direction(Vec3{13.0f, 24.0f, 0.0f}, w, u).ok());
    CHECK(u.x == doctest::Approx(0.6f));
    CHECK(u.y == doctest::Approx(0.8f));
    CHECK(u.z == 0.0f);
    // Shifted along the radius: r' = r + k·D.
    const Vec3 p{13.0f, 24.0f, 2.0f};  // r = 5
    CHECK(wood_texture(p, 0.5f, w) ==
          doctest::Approx(std::sin(0.5f * (5.0f + 0.8f))).epsilon(1e-5));
    w.k = 0.0f;
    CHECK(wood_texture(p, 3.0f, w) == wood_original(p, w));
    // On the axis: a degenerate status, and the texture stays defined (no displacement).
    Status s = wood_radial_direction(Vec3{10.0f, 20.0f, 5.0f}, w, u);
    CHECK(s.code() == StatusCode::degenerate);
    CHECK(u == Vec3{0.0f, 0.0f, 0.0f});
    w.k = 1.6f;
    CHECK(wood_texture(Vec3{10.0f, 20.0f, 5.0f}, 2.0f, w) == 0.0f);
    CHECK(wood_unit_range(-1.0f) == 0.0f);
    CHECK(wood_unit_range(1.0f) == 1.0f);
    w.k2 = 0.0f;
    CHECK(validate_wood(w).code() == StatusCode::invalid_argument);
    w.k2 = 1.0f;
    w.x0 = INFINITY;
    CHECK(!validate_wood(w).ok());
    w.x0 = 10.0f;
    w.k = std::nanf("");
    CHECK(validate_wood(w).code() == StatusCode::invalid_argument);
    w.k = 1.6f;
    w.k2 = -0.5f;
    CHECK(std::string(validate_wood(w).message()).find("-0.5") != std::string::npos);
}

TEST_CASE("colour lookup eq. (12) interpolates I_min..I_max and clamps G'") {
    const Vec3 lo{10, 20, 30}, hi{210, 220, 230};
    CHECK(lookup_color(0.0f, lo, hi) == lo);
    CHECK(lookup_color(1.0f, lo, hi) == hi);
    Vec3 mid = lookup_color(0.25f, lo, hi);
    CHECK(mid.x == doctest::Approx(60.0f));
    CHECK(lookup_color(1.7f, lo, hi) == hi);
    CHECK(lookup_color(std::nanf(""), lo, hi) == lo);
}

TEST_CASE("lattice file: save and load round trip, header and budget") {
    const FractalLattice& lattice = test_lattice();
    // One file per process: several worktrees run their tests at the same time.
    const char* tmp = std::getenv("TMPDIR");
    std::string path = std::string(tmp ? tmp : "/tmp") + "/shitsukan_test_lattice_" +
                       std::to_string(long(getpid())) + ".shl";
    REQUIRE(save_lattice(path, lattice).ok());
    FractalLattice back;
    REQUIRE(load_lattice(path, back).ok());
    CHECK(back.params().R == 6);
    CHECK(back.params().seed == lattice.params().seed);
    CHECK(back.params().beta == lattice.params().beta);
    CHECK(std::memcmp(back.view().values, lattice.view().values, lattice.bytes()) == 0);
    // File size: 56-byte header + 65^3 floats.
    std::FILE* f = std::fopen(path.c_str(), "rb");
    REQUIRE(f != nullptr);
    std::fseek(f, 0, SEEK_END);
    CHECK(std::ftell(f) == 56 + 65 * 65 * 65 * 4);
    std::fclose(f);
    FractalLattice small;
    Status s = load_lattice(path, small, 1000);
    CHECK(s.code() == StatusCode::too_large);
    // Damaged files: a status naming the problem, never a crash or a half-filled lattice.
    auto rewrite = [&](long offset, const void* bytes, std::size_t count) {
        std::FILE* g = std::fopen(path.c_str(), "r+b");
        REQUIRE(g != nullptr);
        std::fseek(g, offset, SEEK_SET);
        std::fwrite(bytes, 1, count, g);
        std::fclose(g);
    };
    const unsigned char noise_256[4] = {0, 1, 0, 0};  // little-endian 256: no such source
    rewrite(20, noise_256, 4);
    s = load_lattice(path, small);
    CHECK(s.code() == StatusCode::io_error);
    CHECK(std::string(s.message()).find("noise source 256") != std::string::npos);
    CHECK(small.empty());
    const unsigned char r_99[4] = {99, 0, 0, 0};  // R = 99: beyond Type I
    rewrite(20, "\0\0\0\0", 4);
    rewrite(8, r_99, 4);
    CHECK(load_lattice(path, small).code() == StatusCode::invalid_argument);
    rewrite(0, "SHKLAT02", 8);
    s = load_lattice(path, small);
    CHECK(s.code() == StatusCode::io_error);
    CHECK(std::string(s.message()).find("not a lattice file") != std::string::npos);
    REQUIRE(save_lattice(path, lattice).ok());
    REQUIRE(truncate(path.c_str(), 56 + 1000) == 0);  // header + 250 of the 65^3 values
    s = load_lattice(path, small);
    CHECK(s.code() == StatusCode::io_error);
    CHECK(std::string(s.message()).find("truncated") != std::string::npos);
    CHECK(small.empty());
    std::remove(path.c_str());
    CHECK(load_lattice(path, back).code() == StatusCode::io_error);
    FractalParams big;
    big.R = 9;
    Status b = small.build(big);
    CHECK(b.code() == StatusCode::too_large);
    CHECK(std::string(b.message()).find("540") != std::string::npos);  // 540,456,708 bytes
}
