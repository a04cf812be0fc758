// shitsukan/solid/fractal_params.hpp — the parameters of okada1987's 3D random fractal lattice.
//
// Manual
//   FractalParams p;                 // R = 6 (65^3 points), beta = 0.9, seed = 1987, corners 0
//   p.beta = 0.7f;
//   Status s = validate_fractal_params(p, kTypeIMaxDepth);
//   std::int64_t n = lattice_side(p.R);       // 2^R + 1 points a side (okada1987 §2.2)
//   float a = level_amplitude(3, p.beta);   // L_r^(3) = exp(-2·beta), eq. (2)
//   constexpr LevelAmplitudes amps = level_amplitudes(FractalParams{}.beta);  // at compile time
//   static_assert(amps.v[1] == 1.0f, "L^(1) = 1");
//   return s;
//
// Parameters and ranges
//   R        recursion depth, 0 <= R <= the type's limit (Type I: kTypeIMaxDepth = 10,
//            Type III: kTypeIIIMaxDepth = 24). Default 6: both papers' 65^3 lattice.
//   beta     decay constant of eq. (2), finite, >= 0. Default 0.9 (chosen here, the one value
//            of the library and of every figure: the papers print none; 0.9 puts the finest
//            of the R = 6 levels at e^-4.5 = 1 % of the first, so okada1987's k = 16 shift
//            folds the marble layers smoothly, where 0.5 (finest level 8 %) broke the k = 16
//            marble into fine noise).
//            Reading of eq. (2): it states both L^(n) = L^(n-1)·e^-beta with L^(0) = 1, which
//            gives L^(1) = e^-beta, and L^(n) = e^-(n-1)·beta, which gives L^(1) = 1. Taken here:
//            the closed form, L^(1) = 1 (eq. (5), eps^(n) = g·e^-(n-1)·beta, says the same).
//            The other reading scales every amplitude, hence D and the shift k·D, by e^-beta
//            (0.41 at beta = 0.9): the paper's "k = 16" under it is k = 6.5 here, and k = 16
//            here is k = 39 there. The figures use k = 16 in this reading (layers folded a few
//            layer spacings, as the paper's figures describe).
//   seed     selects the random numbers g. Default 1987 (chosen here).
//   corners  the eight initial values at the cube's corners (okada1987 §2.2 "given initial
//            values"), finite. Index = i + 2j + 4k for the corner (i, j, k) in {0, 1}^3.
//            Default 0 (chosen here: D then has mean 0 everywhere, so k alone sets the scale).
//   noise    where g comes from: NoiseSource::hash (default) draws g for the node (x, y, z)
//            as node_gaussian(seed, x, y, z) (fractal_node.hpp: the coordinate hash of stream 0
//            through gaussian_from_bits_float), so every lattice type gives every node the
//            same number whatever the order of evaluation (okada1989 Type III's idea);
//            NoiseSource::sequential draws from one Pcg32(seed) stream in build order, as a
//            1987 program calling a random-number routine would (Type I and II only).
#pragma once

#include <cstddef>
#include <cstdint>

#include "shitsukan/core/detmath.hpp"
#include "shitsukan/core/status.hpp"

namespace shitsukan {

enum class NoiseSource : std::uint8_t { hash = 0, sequential = 1 };

struct FractalParams {
    int R = 6;
    float beta = 0.9f;
    std::uint32_t seed = 1987u;
    float corners[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    NoiseSource noise = NoiseSource::hash;
};

constexpr int kTypeIMaxDepth = 10;    // 1025^3 floats = 4.3 GB: beyond that, use Type III
constexpr int kTypeIIIMaxDepth = 24;  // float coordinates still address single cells

// 2^R + 1 points a side (okada1989 prints 2^{R+1}: an OCR slip; R = 6 gives 65).
inline std::int64_t lattice_side(int R) { return (std::int64_t(1) << R) + 1; }

// Bytes of a Type I array of depth R (float32 values), as a 64-bit count.
inline std::uint64_t lattice_bytes(int R) {
    std::uint64_t n = std::uint64_t(lattice_side(R));
    return n * n * n * sizeof(float);
}

// okada1987 eq. (2): L_r^(n) = L_r^(n-1)·e^-beta = e^-(n-1)·beta, n = 1..R. Computed with
// det_exp so every platform and every lattice type uses the same float.
float level_amplitude(int n, float beta);

// The amplitudes of levels 1..kTypeIIIMaxDepth for one beta, as a constant expression:
// `constexpr LevelAmplitudes amps = level_amplitudes(beta);` holds level_amplitude(n, beta)'s
// bits (det_exp_constexpr: det_exp's steps; tests/test_solid_lattice.cpp compares them), so
// a lattice given them (TypeIIILattice::init(params, amps)) links no double arithmetic (with
// --gc-sections or link-time optimisation, which drop the unused init(params)): on a
// soft-float microcontroller about 3 KB of flash (make footprint-mcu measures it). Call it in
// a constant expression only (detmath.hpp's det_exp_constexpr says why). init(params, amps)
// refuses a table for another beta, and one that is not eq. (2)'s (L^(1) = 1, non-increasing,
// >= 0).
struct LevelAmplitudes {
    float beta = -1.0f;                  // the beta they are for (-1: none, so none accepts them)
    float v[kTypeIIIMaxDepth + 1] = {};  // v[n] = L^(n), n = 1..kTypeIIIMaxDepth (v[0] unused)
};
constexpr LevelAmplitudes level_amplitudes(float beta) {
    LevelAmplitudes a;
    a.beta = beta;
    for (int n = 1; n <= kTypeIIIMaxDepth; ++n) {
        const double d = det_exp_constexpr(-double(n - 1) * double(beta));  // level_amplitude's
        // At most half the smallest float subnormal (2^-150, a tie to even) the float is +0.
        // Said outright because clang's constant evaluation (LLVM 14 at least) rounds a
        // subnormal double up to 2^-149 where the run-time conversion gives 0.
        a.v[n] = d <= 0x1p-150 ? 0.0f : float(d);
    }
    return a;
}

// Largest |corner value| (chosen here: 1e30; the paper's corners are 0). Every point is a mean
// of at most eight earlier points plus the level's random value (|g| < 7, times e^{-(n-1)
// beta} <= 1, at most 13 levels), so with corners within 1e30 no sum leaves a float; nearer
// FLT_MAX the sums of the means overflowed to inf (fuzz_geometry: corners of -3.4e38 built an
// infinite quadtree lattice with an ok Status).
constexpr float kMaxFractalCorner = 1e30f;

// Checks R against [0, max_depth], beta >= 0 and finite, corners finite and within
// +-kMaxFractalCorner.
Status validate_fractal_params(const FractalParams& params, int max_depth);
// The same three rules for any random fractal of okada1987 §2 (the 3D lattice above, the 2D
// quadtree of fig. 1): `what` names it in the message.
Status validate_fractal_levels(const char* what, int R, int max_depth, float beta,
                               const float* corners, int corner_count);

}  // namespace shitsukan
