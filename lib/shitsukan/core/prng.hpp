// shitsukan/core/prng.hpp — the one pseudo-random generator of shitsukan: PCG32.
//
// Manual
//   std::uint64_t seed = 42, stream = 54;
//   Pcg32 rng(seed, stream);          // stream selects one of 2^63 independent sequences
//   uint32_t u = rng.next_u32();      // PCG-XSH-RR: 64-bit LCG state, 32-bit output
//   float f = rng.uniform();          // [0, 1), 24 random bits
//   float g = rng.uniform(-2.0f, 3.0f);  // [lo, hi)
//   double d = rng.uniform_double();  // [0, 1), 53 random bits
//   uint32_t k = rng.uniform_int(6);  // [0, n), unbiased (rejection), n >= 1
//   float z = rng.gaussian();         // N(0, 1), inverse CDF of 53 bits (gaussian.hpp)
//   float s = rng.signed_unit();      // [-1, 1): tokai1994's "Rnd"
//
// Algorithm: M. E. O'Neill, "PCG: A Family of Simple Fast Space-Efficient Statistically Good
// Algorithms for Random Number Generation" (2014), pcg32 with the reference seeding
// (pcg32_srandom_r), so Pcg32(42, 54) yields 0xa15c02b7, 0x7b47f409, ... exactly as the
// reference demo. State: 16 bytes. All arithmetic is unsigned (wrapping is defined).
#pragma once

#include <cstdint>

#include "shitsukan/core/gaussian.hpp"

namespace shitsukan {

class Pcg32 {
public:
    explicit Pcg32(std::uint64_t seed = 0x853c49e6748fea9bULL,
                   std::uint64_t stream = 0xda3e39cb94b95bdbULL) {
        state_ = 0u;
        inc_ = (stream << 1u) | 1u;
        next_u32();
        state_ += seed;
        next_u32();
    }

    std::uint32_t next_u32() {
        std::uint64_t old = state_;
        state_ = old * 6364136223846793005ULL + inc_;
        std::uint32_t xorshifted = std::uint32_t(((old >> 18u) ^ old) >> 27u);
        std::uint32_t rot = std::uint32_t(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
    }

    std::uint64_t next_u64() {
        std::uint64_t hi = next_u32();
        return (hi << 32) | next_u32();
    }

    float uniform() { return float(next_u32() >> 8) * (1.0f / 16777216.0f); }
    float uniform(float lo, float hi) { return lo + (hi - lo) * uniform(); }
    double uniform_double() { return double(next_u64() >> 11) * (1.0 / 9007199254740992.0); }
    float signed_unit() { return 2.0f * uniform() - 1.0f; }

    std::uint32_t uniform_int(std::uint32_t n) {
        if (n <= 1u) return 0u;
        std::uint32_t threshold = (0u - n) % n;  // 2^32 mod n: values below are biased
        for (;;) {
            std::uint32_t r = next_u32();
            if (r >= threshold) return r % n;
        }
    }

    float gaussian() { return gaussian_from_bits(next_u64()); }

private:
    std::uint64_t state_;
    std::uint64_t inc_;
};

}  // namespace shitsukan
