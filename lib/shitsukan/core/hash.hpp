// shitsukan/core/hash.hpp — randomness addressed by integer coordinates, not by call order.
//
// Manual
//   std::uint32_t seed = 1987, stream = 0;
//   std::int32_t x = 3, y = -4, z = 5;
//   std::uint64_t h = hash_coords(seed, stream, x, y, z);  // any int32 x, y, z
//   float u = hash_uniform(seed, stream, x, y, z);         // [0, 1), 24 bits
//   float g = hash_gaussian(seed, stream, x, y, z);        // N(0, 1)
//   // Custom keys: a Voronoi edge hashes the bit patterns of its two end points, sorted, so
//   // both polygons that share it draw the same numbers.
//   std::uint64_t k = hash_add(hash_add(hash_start(seed, stream), 0x3f800000u), 0x40000000u);
//   float v = uniform_from_bits(k);
//
// Why: the Type III lattice (okada1989) must give a node the same random number whether it
// is reached first or last, and a shared polygon edge (tokai1994) must be perturbed the same
// way from both sides. A PRNG stream depends on call order; a hash of the coordinates does
// not. `stream` separates independent uses (e.g. stream 0 lattice, 1 jitter).
//
// Algorithm: each 32-bit word is added with a distinct odd multiplier and passed through the
// SplitMix64 / MurmurHash3 fmix64 finaliser (full avalanche). Unsigned arithmetic only.
#pragma once

#include <cstdint>

#include "shitsukan/core/gaussian.hpp"

namespace shitsukan {

// SplitMix64 finaliser (Steele, Lea, Flood 2014): a bijection of 64-bit words.
inline std::uint64_t mix64(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

inline std::uint64_t hash_start(std::uint32_t seed, std::uint32_t stream) {
    return mix64((std::uint64_t(seed) << 32 | stream) + 0x9e3779b97f4a7c15ULL);
}

inline std::uint64_t hash_add(std::uint64_t h, std::uint64_t word) {
    return mix64(h ^ (word * 0xd6e8feb86659fd93ULL + 0x9e3779b97f4a7c15ULL));
}

// The coordinates' hash from a precomputed start = hash_start(seed, stream): callers drawing
// millions of numbers with one seed (a lattice) compute the start once.
// The words are added x, then y, then z: hash_coords_after_x(hash_add(start, x), y, z) is the
// same hash, for callers that reuse one x's partial hash across many (y, z).
inline std::uint64_t hash_coords_after_x(std::uint64_t hx, std::int32_t y, std::int32_t z) {
    return hash_add(hash_add(hx, std::uint32_t(y)), std::uint32_t(z));
}

inline std::uint64_t hash_coords_from(std::uint64_t start, std::int32_t x, std::int32_t y = 0,
                                      std::int32_t z = 0) {
    return hash_coords_after_x(hash_add(start, std::uint32_t(x)), y, z);
}

inline std::uint64_t hash_coords(std::uint32_t seed, std::uint32_t stream, std::int32_t x,
                                 std::int32_t y = 0, std::int32_t z = 0) {
    return hash_coords_from(hash_start(seed, stream), x, y, z);
}

inline float uniform_from_bits(std::uint64_t bits) {
    return float(bits >> 40) * (1.0f / 16777216.0f);  // top 24 bits -> [0, 1)
}

inline float hash_uniform(std::uint32_t seed, std::uint32_t stream, std::int32_t x,
                          std::int32_t y = 0, std::int32_t z = 0) {
    return uniform_from_bits(hash_coords(seed, stream, x, y, z));
}

inline float hash_gaussian(std::uint32_t seed, std::uint32_t stream, std::int32_t x,
                           std::int32_t y = 0, std::int32_t z = 0) {
    return gaussian_from_bits(hash_coords(seed, stream, x, y, z));
}

}  // namespace shitsukan
