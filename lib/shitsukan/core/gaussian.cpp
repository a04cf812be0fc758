// small-device: yes (no allocation, no exceptions)
#include "shitsukan/core/gaussian.hpp"

#include <cmath>
#include <cstring>

#include "shitsukan/core/detmath.hpp"

namespace shitsukan {

namespace {
// P. J. Acklam's coefficients, highest power first: the central rational function A(r)/B(r)
// in r = (p - 0.5)^2 and the tail one C(q)/D(q) in q = sqrt(-2 log p).
struct Poly {
    double v[6];
};
constexpr Poly kA = {{-3.969683028665376e+01, 2.209460984245205e+02, -2.759285104469687e+02,
                      1.383577518672690e+02, -3.066479806614716e+01, 2.506628277459239e+00}};
constexpr Poly kB = {{-5.447609879822406e+01, 1.615858368580409e+02, -1.556989798598866e+02,
                      6.680131188771972e+01, -1.328068155288572e+01, 1.0}};
constexpr Poly kC = {{-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00,
                      -2.549732539343734e+00, 4.374664141464968e+00, 2.938163982698783e+00}};
constexpr Poly kD = {{0.0, 7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00,
                      3.754408661907416e+00, 1.0}};  // degree 4: v[0] unused
}  // namespace

double inverse_normal_cdf(double p) {
    const double *a = kA.v, *b = kB.v, *c = kC.v, *d = kD.v + 1;
    const double p_low = 0.02425, p_high = 1.0 - p_low;
    if (!(p > 0.0 && p < 1.0)) return NAN;
    if (p < p_low) {  // lower tail
        double q = std::sqrt(-2.0 * det_log(p));
        return (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
               ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
    }
    if (p <= p_high) {  // central region
        double q = p - 0.5, r = q * q;
        return (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
               (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1.0);
    }
    double q = std::sqrt(-2.0 * det_log(1.0 - p));  // upper tail, by symmetry
    return -(((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
           ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
}

float gaussian_from_bits(std::uint64_t bits) {
    return float(inverse_normal_cdf(open_unit_from_bits(bits)));
}

namespace {
// float(n) for |n| < 2^53, rounded as the conversion rounds (to nearest, ties to even), with
// the FPU's int32 conversion only (a Cortex-M4F has no int64 one: libgcc's __aeabi_l2f costs
// flash and ~40 instructions). The top 30 bits, with a sticky bit for anything below them,
// round to 24 bits exactly as the whole number does (the sticky bit lies 6 bits below the
// rounding position, so ties stay ties and near-ties stay on their side).
// On a 64-bit host the conversion is one instruction (x86-64 cvtsi2ss, AArch64 scvtf), rounding
// the same way; the int32 path cost 30 instructions per lattice node there (callgrind).
float int53_to_float(std::int64_t n) {
#if defined(__x86_64__) || defined(__aarch64__) || defined(_M_X64) || defined(_M_ARM64)
    return float(n);
#else
    const bool negative = n < 0;
    std::uint64_t u = negative ? 0u - std::uint64_t(n) : std::uint64_t(n);
    float f;
    if (u < (std::uint64_t(1) << 30)) {
        f = float(std::int32_t(u));
    } else {
#if defined(__GNUC__)
        const int shift = 64 - __builtin_clzll(u) - 30;  // 1 .. 23
#else
        int shift = 0;
        while ((u >> shift) >= (std::uint64_t(1) << 30)) shift += 1;
#endif
        std::uint32_t top = std::uint32_t(u >> shift);
        if ((u & ((std::uint64_t(1) << shift) - 1u)) != 0) top |= 1u;
        const std::uint32_t scale_bits = std::uint32_t(127 + shift) << 23;  // 2^shift, exact
        float scale;
        std::memcpy(&scale, &scale_bits, sizeof scale);
        f = float(std::int32_t(top)) * scale;
    }
    return negative ? -f : f;
#endif
}

// A polynomial p(r) rewritten in powers of t = r - r0: p(r0 + t) (Taylor shift by repeated
// synthetic division, in double by the compiler), rounded to float.
struct PolyF {
    float v[6];
};
constexpr PolyF shifted_to_float(Poly p, double r0) {
    PolyF out{};
    for (int k = 5; k >= 0; --k) {  // p(r0) is the remainder of p / (r - r0); the quotient
        double acc = 0.0;           // stays in p.v[0 .. k-1] for the next coefficient
        for (int i = 0; i <= k; ++i) p.v[i] = acc = acc * r0 + p.v[i];
        out.v[k] = float(acc);
    }
    return out;
}

// The central function in float, in powers of t = r - 29/128: A and B both nearly vanish at the
// region's edge r = 0.47575^2 = 0.22634 (A = 0.0108 from terms up to 2.5, B = 0.0026), so in
// powers of r their float evaluation cancelled up to 11 bits there (3316 ulps off the double
// one, measured); about r0 = 29/128, just beyond the edge, every term of A(r0 + t) and of
// B(r0 + t) has the sign of the sum for t in [-r0, 0] (condition number 1.0), so the float
// Horner sums are good to a few ulps (chosen here: r0 = 29/128 is exact in float).
constexpr float kCentreR0 = 0.2265625f;
constexpr PolyF kAShifted = shifted_to_float(kA, double(kCentreR0));
constexpr PolyF kBShifted = shifted_to_float(kB, double(kCentreR0));
constexpr PolyF kCf = shifted_to_float(kC, 0.0), kDf = shifted_to_float(kD, 0.0);

float horner(const PolyF& p, float x) {
    return ((((p.v[0] * x + p.v[1]) * x + p.v[2]) * x + p.v[3]) * x + p.v[4]) * x + p.v[5];
}

// Acklam's tail function in float for t = min(p, 1 - p) < 0.02425: the value of the lower tail
// (negative). t arrives as float(t) (one rounding, relative 2^-24: log t moves by 2^-24 against
// |log t| >= 3.7); det_logf_fast is within 1 ulp and uses float arithmetic only, sqrt is the
// FPU's (IEEE, correctly rounded), -2·log t is exact. C and D are well conditioned on q in
// [2.72, 8.7] (condition numbers 1.0 and at most 1.43: C's two lowest terms have the other sign).
float lower_tail_float(float t) {
    const float q = std::sqrt(-2.0f * det_logf_fast(t));
    return horner(kCf, q) / horner(kDf, q);
}

// p = open_unit_from_bits(bits) = (double(m) + 0.5)·2^-53 with m = bits >> 11, a
// non-decreasing function of m; the tails p < 0.02425 and p > 1 - 0.02425 are exactly
// m < kLowTail and m > kHighTail (found by bisection on that double expression, checked at both
// edges by tests/test_core_gaussian.cpp). No double arithmetic anywhere: on a Cortex-M4F the
// int64 -> double conversion, the compares, p - 0.5 and the tails' det_log were software double
// per lattice node. p, 1 - p and p - 0.5 are formed exactly from m in integers and rounded once
// to float, as float(p), float(1 - p), float(p - 0.5) would be.
constexpr std::uint64_t kLowTail = 218424581927469ull, kHighTail = 8788774672813522ull;
constexpr std::int64_t kTwo53 = std::int64_t(1) << 53;

inline bool in_tails(std::uint64_t m) { return m < kLowTail || m > kHighTail; }

// The draw of a tail m (in_tails(m)): Acklam's tail function, lower or upper.
float tails_float(std::uint64_t m) {
    if (m < kLowTail)  // lower tail: p = (m + 0.5)·2^-53 = (2m + 1)·2^-54, m < 2^48
        return lower_tail_float(int53_to_float(std::int64_t(2 * m + 1)) * 0x1p-54f);
    // upper tail, by symmetry: m > 2^52, so double(m) + 0.5 is the even one of m and m + 1 (a
    // tie) and 1 - p = (2^53 - that)·2^-53, exact; m = 2^53 - 1 would give p = 1, which
    // open_unit_from_bits turns into 1 - 2^-53 (1 - p = 2^-53).
    const std::int64_t n = kTwo53 - std::int64_t(m + (m & 1u));
    return -lower_tail_float(int53_to_float(n > 0 ? n : 1) * 0x1p-53f);
}

// q = float(p - 0.5), the central region's variable before squaring: p - 0.5 = n·2^-54
// exactly: below 2^52, m + 0.5 is exact (n = 2m + 1 - 2^53); from 2^52 on, double(m) + 0.5 ties
// to the even one of m and m + 1 (n = 2·that - 2^53). Any m gives a finite q.
inline float centre_q(std::uint64_t m) {
    const std::int64_t n = m < (std::uint64_t(1) << 52)
                               ? std::int64_t(2 * m + 1) - kTwo53
                               : std::int64_t(2 * (m + (m & 1u))) - kTwo53;
    return int53_to_float(n) * 0x1p-54f;  // one rounding, as float(p - 0.5)
}
}  // namespace

float gaussian_from_bits_float(std::uint64_t bits) {
    const std::uint64_t m = bits >> 11;
    if (in_tails(m)) return tails_float(m);
    const float q = centre_q(m);
    const float t = q * q - kCentreR0;  // r - r0, the central region's variable
    return q * horner(kAShifted, t) / horner(kBShifted, t);
}

#if (defined(__GNUC__) || defined(__clang__)) && (defined(__SSE2__) || defined(__aarch64__))
namespace {
// Four lanes of plain IEEE float arithmetic (GCC/Clang vector extension; SSE2 and AArch64's
// NEON are IEEE in every lane, 32-bit Arm's NEON is not and is not used). No contraction:
// -ffp-contract=off.
typedef float Float4 __attribute__((vector_size(16)));
inline Float4 splat(float v) { return Float4{v, v, v, v}; }
// horner() in four lanes: the same operations in the same order.
inline Float4 horner4(const PolyF& p, Float4 x) {
    Float4 r = splat(p.v[0]);
    for (int k = 1; k < 6; ++k) r = r * x + splat(p.v[k]);
    return r;
}
}  // namespace

void gaussians_from_bits_float(const std::uint64_t* bits, int n, float* out) {
    int i = 0;
    for (; i + 4 <= n; i += 4) {
        const std::uint64_t m[4] = {bits[i] >> 11, bits[i + 1] >> 11, bits[i + 2] >> 11,
                                    bits[i + 3] >> 11};
        // A tail lane's q is finite but its value below is not the draw: redone alone.
        const Float4 q{centre_q(m[0]), centre_q(m[1]), centre_q(m[2]), centre_q(m[3])};
        const Float4 t = q * q - splat(kCentreR0);
        const Float4 g = q * horner4(kAShifted, t) / horner4(kBShifted, t);
        std::memcpy(out + i, &g, sizeof g);
        if (in_tails(m[0]) || in_tails(m[1]) || in_tails(m[2]) || in_tails(m[3]))
            for (int l = 0; l < 4; ++l)
                if (in_tails(m[l])) out[i + l] = tails_float(m[l]);
    }
    for (; i < n; ++i) out[i] = gaussian_from_bits_float(bits[i]);
}
#else
void gaussians_from_bits_float(const std::uint64_t* bits, int n, float* out) {
    for (int i = 0; i < n; ++i) out[i] = gaussian_from_bits_float(bits[i]);
}
#endif

}  // namespace shitsukan
