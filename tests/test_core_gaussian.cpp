// core/gaussian: gaussian_from_bits_float, all in float arithmetic, stays within 8
// float ulps of gaussian_from_bits (the double definition) at the region edges, deep in both
// tails and everywhere else; its integer tail test is the double one's; many draws at once
// (gaussians_from_bits_float) are the single draws bit for bit.
#include <doctest/doctest.h>
#include "measured.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <initializer_list>

#include "shitsukan/core/gaussian.hpp"
#include "shitsukan/core/prng.hpp"

using namespace shitsukan;

namespace {
constexpr std::uint64_t kLowTail = 218424581927469ull, kHighTail = 8788774672813522ull;
constexpr std::uint64_t kTop = std::uint64_t(1) << 53;  // m = bits >> 11 is below it

// Distance in float ulps (the floats between them, across zero too); NaN is far from all.
// 64-bit throughout: long is 32 bits on WASM (and Windows), where 1L << 40 and the difference of
// two far floats would overflow.
long long ulps_apart(float a, float b) {
    if (std::isnan(a) || std::isnan(b)) return 1LL << 40;
    std::int32_t x, y;
    std::memcpy(&x, &a, sizeof x);
    std::memcpy(&y, &b, sizeof y);
    const long long lx = x < 0 ? -static_cast<long long>(x & 0x7fffffff) : static_cast<long long>(x);
    const long long ly = y < 0 ? -static_cast<long long>(y & 0x7fffffff) : static_cast<long long>(y);
    return std::llabs(lx - ly);
}

struct Worst {
    long long ulps = 0;
    std::uint64_t m = 0;
    long draws = 0;
    void add(std::uint64_t mm, std::uint64_t low_bits = 0) {
        const std::uint64_t bits = (mm << 11) | low_bits;
        const long long u = ulps_apart(gaussian_from_bits_float(bits), gaussian_from_bits(bits));
        draws += 1;
        if (u > ulps) {
            ulps = u;
            m = mm;
        }
    }
};
}  // namespace

TEST_CASE("gaussian_from_bits_float: its integer tail bounds are the double definition's") {
    // p = open_unit_from_bits(m << 11); the float path's tails are m < kLowTail, m > kHighTail.
    for (std::int64_t d = -3; d <= 3; ++d) {
        const std::uint64_t lo = kLowTail + std::uint64_t(d), hi = kHighTail + std::uint64_t(d);
        CHECK((open_unit_from_bits(lo << 11) < 0.02425) == (lo < kLowTail));
        CHECK((open_unit_from_bits(hi << 11) > 1.0 - 0.02425) == (hi > kHighTail));
    }
    // The largest m: (2^53 - 1) + 0.5 rounds to 2^53 in double; p stays below 1.
    CHECK(open_unit_from_bits(~std::uint64_t(0)) < 1.0);
    CHECK(open_unit_from_bits(0) > 0.0);
}

TEST_CASE("gaussian_from_bits_float: within 8 float ulps of gaussian_from_bits everywhere") {
    Worst edges, deep, tails, uniform;
    for (std::uint64_t e :
         {std::uint64_t(0), kLowTail, kTop / 2, std::uint64_t(1) << 52, kHighTail, kTop - 1})
        for (std::int64_t d = -3; d <= 3; ++d) {
            const std::uint64_t m = e + std::uint64_t(d);
            if (m >= kTop) continue;
            for (std::uint64_t low : {0ull, 1ull, 2047ull}) edges.add(m, low);
        }
    for (std::uint64_t m = 0; m < 100000; ++m) {  // the extreme tails, every m: |z| > 8
        deep.add(m);
        deep.add(kTop - 1 - m);
    }
    Pcg32 rng(99);
    for (int i = 0; i < 500000; ++i) {  // the tails, log-uniformly in m (p from 2^-54 up)
        const double u = double(rng.next_u32()) * 0x1p-32;
        std::uint64_t m = std::uint64_t(std::exp(u * std::log(double(kLowTail))));
        if (m >= kLowTail) m = kLowTail - 1;
        tails.add(m);
        tails.add(kTop - 1 - m);
    }
    for (int i = 0; i < 1000000; ++i) {  // uniform draws (95 % central)
        const std::uint64_t bits = (std::uint64_t(rng.next_u32()) << 32) | rng.next_u32();
        uniform.add(bits >> 11, bits & 2047u);
    }
    MEASURED("float vs double Gaussian, worst ulps: edges "
            << edges.ulps << ", deep tails " << deep.ulps << " (m " << deep.m << "), tails "
            << tails.ulps << " (m " << tails.m << "), uniform " << uniform.ulps << " (m "
            << uniform.m << ")");
    CHECK(edges.ulps <= 8);
    CHECK(deep.ulps <= 8);
    CHECK(tails.ulps <= 8);
    CHECK(uniform.ulps <= 8);
    CHECK(std::isfinite(gaussian_from_bits_float(~std::uint64_t(0))));
    CHECK(gaussian_from_bits_float(~std::uint64_t(0)) > 8.0f);
    CHECK(gaussian_from_bits_float(0) < -8.0f);
}

TEST_CASE("gaussians_from_bits_float: the single draws bit for bit, tails in every lane") {
    // Draws at the region edges and deep in both tails, placed at every position of a group of
    // four and in the leftover draws of a batch whose length is not a multiple of four, among
    // uniform draws; batches of every length 0..9 and a long one.
    const std::uint64_t special[] = {0,
                                     (kLowTail - 1) << 11,
                                     kLowTail << 11,
                                     ((kLowTail + 1) << 11) | 2047u,
                                     (kTop / 2) << 11,
                                     ((std::uint64_t(1) << 52) - 1) << 11,
                                     (std::uint64_t(1) << 52) << 11,
                                     kHighTail << 11,
                                     (kHighTail + 1) << 11,
                                     ~std::uint64_t(0)};
    Pcg32 rng(2024u, 5u);
    auto uniform_bits = [&rng] { return (std::uint64_t(rng.next_u32()) << 32) | rng.next_u32(); };
    long mismatches = 0, draws = 0, tail_draws = 0;
    std::uint64_t bits[4099];
    float got[4099];
    auto check_batch = [&](int n) {
        gaussians_from_bits_float(bits, n, got);
        for (int i = 0; i < n; ++i, ++draws) {
            const float want = gaussian_from_bits_float(bits[i]);
            mismatches += std::memcmp(&want, &got[i], sizeof want) != 0;
            const std::uint64_t m = bits[i] >> 11;
            tail_draws += m < kLowTail || m > kHighTail;
        }
    };
    for (std::uint64_t s : special)
        for (int n = 1; n <= 9; ++n)
            for (int at = 0; at < n; ++at) {
                for (int i = 0; i < n; ++i) bits[i] = uniform_bits();
                bits[at] = s;
                check_batch(n);
            }
    for (int i = 0; i < 4099; ++i) bits[i] = uniform_bits();
    check_batch(4099);
    check_batch(0);
    CHECK(draws == 10 * 285 + 4099);  // 285 = 1^2 + ... + 9^2
    CHECK(tail_draws >= 4 * 45);      // four of the special draws are in the tails
    CHECK(mismatches == 0);
}
