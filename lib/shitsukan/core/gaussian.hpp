// shitsukan/core/gaussian.hpp — our own N(0,1): the inverse normal CDF.
//
// Manual
//   double z = inverse_normal_cdf(0.975);   // p in (0, 1) -> z with Phi(z) = p: 1.95996...
//   std::uint64_t bits = 0x123456789abcdULL;  // 53 random bits (a PRNG's or a hash's)
//   float g = gaussian_from_bits(bits);       // -> one N(0, 1) draw
//   float h = gaussian_from_bits_float(bits); // the same draw in float arithmetic alone
//                                             // (det_logf_fast and sqrtf in the tails): within
//                                             // 8 float ulps of gaussian_from_bits (worst
//                                             // measured 7), about 10x fewer instructions on a
//                                             // single-precision FPU (the fractal lattice's
//                                             // noise, solid/fractal_node.hpp)
//   const std::uint64_t many[3] = {bits, 7u << 11, ~std::uint64_t(0)};
//   float gs[3];
//   gaussians_from_bits_float(many, 3, gs);   // gs[i] == gaussian_from_bits_float(many[i]),
//                                             // bit for bit, four at a time where it can
// Why not the C++ library's normal distribution: its algorithm is implementation-defined, so
// the same seed gives different numbers under libstdc++, libc++ and MSVC. Why not Box-Muller: it
// consumes two uniforms and keeps state. The inverse CDF maps one uniform to one Gaussian,
// needs no rejection loop (so a hash of a lattice node gives its Gaussian directly), and is
// monotone. Algorithm: P. J. Acklam's rational approximation (relative error < 1.15e-9),
// using det_log so the result is the same bits everywhere.
// Range: 53-bit uniforms in (0, 1) reach about ±8.3 sigma.
#pragma once

#include <cstdint>

namespace shitsukan {

double inverse_normal_cdf(double p);
float gaussian_from_bits(std::uint64_t bits);
float gaussian_from_bits_float(std::uint64_t bits);

// n draws at once: out[i] == gaussian_from_bits_float(bits[i]) bit for bit, for every i in
// [0, n). With a four-lane SIMD unit (SSE2, AArch64) four draws of the central region go through
// its rational function as one vector: the same IEEE operations in the same order in each lane,
// so the same bits, with the latency of one draw (the rational function is a chain of ~15
// dependent float operations and a division; one draw at a time, the Type I lattice build
// waited on it). A group holding a draw in the tails (2.4 % each side) redoes that draw alone.
// Without SIMD it is the loop of single draws.
void gaussians_from_bits_float(const std::uint64_t* bits, int n, float* out);

// 53 random bits -> a double strictly inside (0, 1): (k + 0.5) / 2^53, rounded to double
// (above 2^52, k + 0.5 rounds to the even one of k and k + 1), except that k = 2^53 - 1, whose
// k + 0.5 rounds to 2^53, gives the largest double below 1 instead of 1.
inline double open_unit_from_bits(std::uint64_t bits) {
    const double p = (double(bits >> 11) + 0.5) * (1.0 / 9007199254740992.0);
    return p < 1.0 ? p : 1.0 - 1.0 / 9007199254740992.0;
}

}  // namespace shitsukan
