// Tests for lib/shitsukan/core: PRNG, Gaussian, coordinate hash, deterministic math,
// status, vectors and matrices.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "shitsukan/core/core.hpp"

using namespace shitsukan;

TEST_CASE("Pcg32 reproduces the reference pcg32 demo (seed 42, stream 54)") {
    Pcg32 rng(42u, 54u);
    const std::uint32_t expected[6] = {0xa15c02b7u, 0x7b47f409u, 0xba1d3330u,
                                       0x83d2f293u, 0xbfa4784bu, 0xcbed606eu};
    for (std::uint32_t e : expected) CHECK(rng.next_u32() == e);
}

TEST_CASE("Pcg32 uniform ranges and unbiased integers") {
    Pcg32 rng(7u, 1u);
    std::vector<int> counts(7, 0);
    for (int i = 0; i < 70000; ++i) {
        float u = rng.uniform();
        REQUIRE(u >= 0.0f);
        REQUIRE(u < 1.0f);
        float s = rng.signed_unit();
        REQUIRE(s >= -1.0f);
        REQUIRE(s < 1.0f);
        std::uint32_t k = rng.uniform_int(7);
        REQUIRE(k < 7u);
        ++counts[k];
    }
    for (int c : counts) CHECK(std::abs(c - 10000) < 500);  // ~5 sigma of a binomial
    CHECK(rng.uniform_int(0) == 0u);
    CHECK(rng.uniform_int(1) == 0u);
}

TEST_CASE("Gaussian: mean, variance, skewness, kurtosis of 1e6 draws") {
    Pcg32 rng(2024u, 3u);
    const int n = 1000000;
    double m1 = 0, m2 = 0, m3 = 0, m4 = 0;
    for (int i = 0; i < n; ++i) {
        double z = rng.gaussian();
        m1 += z;
        m2 += z * z;
        m3 += z * z * z;
        m4 += z * z * z * z;
    }
    m1 /= n;
    m2 /= n;
    m3 /= n;
    m4 /= n;
    double var = m2 - m1 * m1;
    // Standard errors at n = 1e6: mean 0.001, variance 0.0014, skew 0.0024, kurtosis 0.0049.
    CHECK(std::abs(m1) < 0.005);
    CHECK(std::abs(var - 1.0) < 0.007);
    CHECK(std::abs(m3) < 0.012);
    CHECK(std::abs(m4 - 3.0) < 0.025);
}

TEST_CASE("inverse_normal_cdf matches known quantiles and is monotone") {
    CHECK(inverse_normal_cdf(0.5) == doctest::Approx(0.0).epsilon(1e-12));
    CHECK(inverse_normal_cdf(0.975) == doctest::Approx(1.959963984540054).epsilon(1e-8));
    CHECK(inverse_normal_cdf(0.025) == doctest::Approx(-1.959963984540054).epsilon(1e-8));
    CHECK(inverse_normal_cdf(1e-10) == doctest::Approx(-6.361340902404056).epsilon(1e-7));
    CHECK(std::isnan(inverse_normal_cdf(0.0)));
    CHECK(std::isnan(inverse_normal_cdf(1.0)));
    double prev = -1e9;
    for (int i = 1; i < 10000; ++i) {
        double z = inverse_normal_cdf(i / 10000.0);
        REQUIRE(z > prev);
        prev = z;
    }
}

TEST_CASE("det_log and det_exp agree with the C library to within 3 ulp") {
    Pcg32 rng(5u);
    for (int i = 0; i < 100000; ++i) {
        double x = std::ldexp(0.5 + rng.uniform_double(), int(rng.uniform_int(200)) - 100);
        double a = det_log(x), b = std::log(x);
        REQUIRE(std::abs(a - b) <= 6.7e-16 * std::max(1.0, std::abs(b)));
        double y = (rng.uniform_double() - 0.5) * 1400.0;
        double c = det_exp(y), d = std::exp(y);
        REQUIRE(std::abs(c - d) <= 6.7e-16 * d);
    }
    CHECK(det_log(1.0) == 0.0);
    CHECK(det_exp(0.0) == 1.0);
    CHECK(std::isnan(det_log(-1.0)));
    CHECK(std::isinf(det_log(0.0)));
}

TEST_CASE("coordinate hash: same value in any call order, different per coordinate") {
    const int n = 9;
    std::vector<float> forward, backward(n * n * n);
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) forward.push_back(hash_gaussian(11u, 0u, x, y, z));
    for (int i = n * n * n - 1; i >= 0; --i)
        backward[std::size_t(i)] = hash_gaussian(11u, 0u, i % n, (i / n) % n, i / (n * n));
    CHECK(std::memcmp(forward.data(), backward.data(), forward.size() * sizeof(float)) == 0);
    // Streams and seeds are independent; neighbours differ.
    CHECK(hash_coords(11u, 0u, 1, 2, 3) != hash_coords(11u, 1u, 1, 2, 3));
    CHECK(hash_coords(11u, 0u, 1, 2, 3) != hash_coords(12u, 0u, 1, 2, 3));
    CHECK(hash_coords(11u, 0u, 1, 2, 3) != hash_coords(11u, 0u, 2, 1, 3));
    CHECK(hash_coords(11u, 0u, -1, 0, 0) != hash_coords(11u, 0u, 1, 0, 0));
    // A precomputed start gives the same hash as computing it per call.
    const std::uint64_t start = hash_start(11u, 0u);
    for (int i = -5; i <= 5; ++i)
        CHECK(hash_coords_from(start, i, 2 * i, -3 * i) == hash_coords(11u, 0u, i, 2 * i, -3 * i));
}

TEST_CASE("coordinate hash: uniform and Gaussian statistics over a lattice") {
    const int n = 64;
    double s = 0, s2 = 0, u = 0;
    int bins[10] = {0};
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                double g = hash_gaussian(3u, 7u, x, y, z);
                s += g;
                s2 += g * g;
                float v = hash_uniform(3u, 8u, x, y, z);
                REQUIRE(v >= 0.0f);
                REQUIRE(v < 1.0f);
                u += v;
                ++bins[int(v * 10)];
            }
    double count = double(n) * n * n;
    CHECK(std::abs(s / count) < 0.01);
    CHECK(std::abs(s2 / count - 1.0) < 0.01);
    CHECK(std::abs(u / count - 0.5) < 0.003);
    for (int b : bins) CHECK(std::abs(b - count / 10) < 5 * std::sqrt(count / 10));
}

TEST_CASE("Status carries code and formatted message") {
    Status ok;
    CHECK(ok.ok());
    CHECK(bool(ok));
    CHECK(std::strcmp(ok.message(), "ok") == 0);
    Status e = Status::error(StatusCode::too_large, "lattice needs %llu bytes", 1234ULL);
    CHECK_FALSE(e.ok());
    CHECK(e.code() == StatusCode::too_large);
    CHECK(std::strcmp(e.message(), "lattice needs 1234 bytes") == 0);
    CHECK(std::strcmp(status_code_name(StatusCode::io_error), "i/o error") == 0);
    std::string longtext(500, 'x');
    Status t = Status::error(StatusCode::invalid_argument, "%s", longtext.c_str());
    CHECK(std::strlen(t.message()) == std::size_t(Status::kArgumentBytes - 1));
}

TEST_CASE("vectors and matrices") {
    Vec3 a{1, 2, 3}, b{4, 5, 6};
    CHECK(dot(a, b) == 32.0f);
    CHECK(cross(Vec3{1, 0, 0}, Vec3{0, 1, 0}) == Vec3{0, 0, 1});
    CHECK(length(normalize(b)) == doctest::Approx(1.0f));
    CHECK(normalize(Vec3{0, 0, 0}) == Vec3{0, 0, 0});
    Mat4 m = Mat4::translate({1, 2, 3}) * Mat4::rotate_y(0.7f) * Mat4::scale({2, 3, 4});
    bool ok = false;
    Mat4 inv = inverse(m, &ok);
    REQUIRE(ok);
    Vec3 p{0.3f, -0.4f, 2.0f};
    Vec3 q = transform_point(inv, transform_point(m, p));
    CHECK(q.x == doctest::Approx(p.x).epsilon(1e-5));
    CHECK(q.y == doctest::Approx(p.y).epsilon(1e-5));
    CHECK(q.z == doctest::Approx(p.z).epsilon(1e-5));
    Mat4 zero;
    inverse(zero, &ok);
    CHECK_FALSE(ok);
    CHECK(clamp(5, 0, 3) == 3);
    CHECK(lerp(2.0f, 4.0f, 0.25f) == 2.5f);
    CHECK(smoothstep(0.0f, 1.0f, 0.5f) == 0.5f);
    CHECK_FALSE(is_finite(Vec3{0, NAN, 0}));
}
