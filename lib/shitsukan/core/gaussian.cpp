// small-device: yes (no allocation, no exceptions)
#include "shitsukan/core/gaussian.hpp"

#include <cmath>
#include <cstring>

#include "shitsukan/core/detmath.hpp"

namespace shitsukan {

double inverse_normal_cdf(double p) {
    // Acklam's coefficients: central rational function and tail rational function.
    static const double a[6] = {-3.969683028665376e+01, 2.209460984245205e+02,
                                -2.759285104469687e+02, 1.383577518672690e+02,
                                -3.066479806614716e+01, 2.506628277459239e+00};
    static const double b[5] = {-5.447609879822406e+01, 1.615858368580409e+02,
                                -1.556989798598866e+02, 6.680131188771972e+01,
                                -1.328068155288572e+01};
    static const double c[6] = {-7.784894002430293e-03, -3.223964580411365e-01,
                                -2.400758277161838e+00, -2.549732539343734e+00,
                                4.374664141464968e+00,  2.938163982698783e+00};
    static const double d[4] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00,
                                3.754408661907416e+00};
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
float int53_to_float(std::int64_t n) {
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
}
}  // namespace

float gaussian_from_bits_float(std::uint64_t bits) {
    // p = open_unit_from_bits(bits) = (double(m) + 0.5)·2^-53 with m = bits >> 11, a
    // non-decreasing function of m; the tails p < 0.02425 and p > 1 - 0.02425 are exactly
    // m < kLowTail and m > kHighTail (found by bisection on that double expression, checked
    // at both edges by tests/test_core_gaussian.cpp). No double arithmetic in the centre:
    // on a Cortex-M4F the int64 -> double conversion, the compares and p - 0.5 were
    // software double per lattice node.
    constexpr std::uint64_t kLowTail = 218424581927469ull, kHighTail = 8788774672813522ull;
    const std::uint64_t m = bits >> 11;
    if (m < kLowTail || m > kHighTail)  // the tails (4.85 %): det_log and sqrt in double
        return float(inverse_normal_cdf(open_unit_from_bits(bits)));
    // p - 0.5 = n·2^-54 exactly: below 2^52, m + 0.5 is exact (n = 2m + 1 - 2^53); from
    // 2^52 on, double(m) + 0.5 ties to the even one of m and m + 1 (n = 2·that - 2^53).
    const std::int64_t two53 = std::int64_t(1) << 53;
    const std::int64_t n = m < (std::uint64_t(1) << 52)
                               ? std::int64_t(2 * m + 1) - two53
                               : std::int64_t(2 * (m + (m & 1u))) - two53;
    const float q = int53_to_float(n) * 0x1p-54f, r = q * q;  // one rounding, as float(p - 0.5)
    // The central region (95.15 % of draws): Acklam's same rational function, in float.
    static const float a[6] = {-3.969683028665376e+01f, 2.209460984245205e+02f,
                               -2.759285104469687e+02f, 1.383577518672690e+02f,
                               -3.066479806614716e+01f, 2.506628277459239e+00f};
    static const float b[5] = {-5.447609879822406e+01f, 1.615858368580409e+02f,
                               -1.556989798598866e+02f, 6.680131188771972e+01f,
                               -1.328068155288572e+01f};
    return (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
           (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1.0f);
}

}  // namespace shitsukan
