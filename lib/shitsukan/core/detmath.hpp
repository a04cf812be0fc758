// shitsukan/core/detmath.hpp — elementary functions that give the same bits on every machine.
//
// Manual
//   float s = det_sinf(0.5f), c = det_cosf(0.5f), t = det_tanf(0.5f);
//   float e = det_expf(-2.0f), l = det_logf(3.0f), p = det_powf(0.8f, 32.0f);
//   float a = det_acosf(0.3f), b = det_asinf(0.3f), u = det_atanf(2.0f);
//   float w = det_atan2f(-1.0f, 2.0f);
//   float ef = det_expf_fast(-2.0f), lf = det_logf_fast(3.0f), sf = det_sinf_fast(0.5f);
//                              // float arithmetic only (no software double on a Cortex-M4F)
//   double d = det_exp(0.25), g = det_log(10.0), sn = det_sin(0.1), cs = det_cos(0.1);
//   constexpr double ec = det_exp_constexpr(-0.9);  // det_exp(-0.9)'s bits, at compile time
//   float h = det_sin(0.5f);   // det_sin, det_cos, det_tan, det_acos, det_asin, det_atan,
//                              // det_atan2, det_pow: float and double overloads, like
//                              // std::sin & co. (the float ones are the ...f functions)
//
// Why: the C library's sin, pow, exp, ... are not required to be correctly rounded, so two
// libms (glibc on a PC, newlib on a microcontroller, MSVC) differ in the last bit on many
// inputs, and a texture, a lit pixel or a mesh vertex computed through them differs too
// (newlib's sinf/powf are 1-2 ulp off glibc's on a Cortex-M4F). These use only
// IEEE +, -, *, /, sqrt, floor and exact bit manipulation, so with -ffp-contract=off (the
// library's flag; no -ffast-math) they give the same bits with gcc or clang, at -O0 or -O2,
// on a PC or a Cortex-M (tests/test_core_detmath.cpp, and make test-mcu compares the
// transcripts of a host, a Cortex-M4F and a Cortex-M7).
//
// Accuracy: the float functions evaluate in double from an exact argument reduction (Cody &
// Waite below 2^19, Payne & Hanek with the bits of 2/pi above) and round once to float: at most
// 1 ulp from the correctly rounded result over the whole float domain (correctly rounded
// except within ~2^-26 ulp of a halfway case); measured against long double in the tests.
// det_exp / det_log (double) are about 1 ulp; det_sin, det_cos, det_tan (double) are within
// a few double ulps for |x| < 2^19 (Cody & Waite; beyond, still deterministic but less
// accurate), det_atan2, det_atan, det_acos, det_asin (double) within a few double ulps;
// det_pow (double) is exact-by-squaring for integer |y| <= 64, otherwise e^(y·log x) with
// an error of about |y·log x| double ulps. There is no float det_exp/det_log overload (a
// float argument keeps meaning the double function, as before); use det_expf/det_logf.
// Domains and special values follow C99 Annex F (NaN in, NaN out; sin(+-inf) = NaN;
// acos/asin outside [-1, 1] = NaN; pow's zeros, infinities, negative bases with integer y).
// Cost: double arithmetic (software on a single-precision FPU such as the Cortex-M4F).
// det_exp_constexpr: det_exp as a constant expression (below), for values known when the
// program is built: no double arithmetic is linked for them.
// small-device: yes (no allocation)
#pragma once

#include <limits>

namespace shitsukan {

double det_log(double x);  // natural log, x > 0 (NaN for x < 0 or NaN, -inf for 0)
double det_exp(double x);  // e^x (0 below -745, +inf above 709)

namespace detail {
constexpr double kLn2Hi = 6.93147180369123816490e-01;  // ln 2 split in two (fdlibm), so
constexpr double kLn2Lo = 1.90821492927058770002e-10;  // k·ln2 is exact in the high part
constexpr int kExpTerms = 14;                          // 1/0!, 1/1!, ..., 1/13!

struct ExpCoefficients {
    double v[kExpTerms];
};
// Computed by the compiler (IEEE double, the same on every host).
constexpr ExpCoefficients inverse_factorials() {
    ExpCoefficients c{};
    double f = 1.0;
    for (int n = 0; n < kExpTerms; ++n) {
        if (n > 0) f *= double(n);  // n! is exact in double up to 22!
        c.v[n] = 1.0 / f;
    }
    return c;
}
inline constexpr ExpCoefficients kInverseFactorials = inverse_factorials();

// det_exp's steps, given a floor and a scaling s·2^k: det_exp passes std::floor and
// std::ldexp, det_exp_constexpr its own below. Both pairs are exact (floor) or correctly
// rounded (ldexp: one rounding), and every other step is one IEEE operation in the same
// order, so both give the same bits.
template <class Floor, class ScaleByPow2>
constexpr double exp_steps(double x, Floor floor_of, ScaleByPow2 scale) {
    if (x != x) return x;  // NaN
    if (x > 709.0) return std::numeric_limits<double>::infinity();
    if (x < -745.0) return 0.0;
    // x = k·ln2 + r, |r| <= ln2/2; e^x = 2^k · e^r, e^r by its Taylor series.
    const double kd = floor_of(x / (kLn2Hi + kLn2Lo) + 0.5);
    const int k = int(kd);
    const double r = (x - kd * kLn2Hi) - kd * kLn2Lo;
    // e^r = sum r^n/n!, n = 0..13, by Horner with compile-time 1/n!: for |r| <= ln2/2 the first
    // omitted term r^14/14! is < 5e-18, below half an ulp.
    double sum = kInverseFactorials.v[kExpTerms - 1];
    for (int n = kExpTerms - 2; n >= 0; --n) sum = sum * r + kInverseFactorials.v[n];
    return scale(sum, k);
}

// floor(v) for |v| < 2^53: the truncation is exact, one step down for a negative fraction.
constexpr double exact_floor(double v) {
    const double t = double(static_cast<long long>(v));
    return t > v ? t - 1.0 : t;
}
// 2^k for -1022 <= k <= 1023, by squaring (every factor and product an exact power of 2).
constexpr double exact_pow2(int k) {
    double p = 1.0, b = k < 0 ? 0.5 : 2.0;
    for (int n = k < 0 ? -k : k; n != 0;) {
        if (n & 1) p *= b;
        n >>= 1;
        if (n != 0) b *= b;  // at most 2^512 (no overflow: a constant expression must not)
    }
    return p;
}
// s·2^k rounded once, as ldexp does, for s in [0.5, 2) and -1086 <= k <= 1023 (det_exp's k
// is in [-1075, 1023]): below 2^-1022 the product by 2^(k + 64) is still normal, so exact,
// and the product by 2^-64 is the one rounding.
constexpr double exact_scale_by_pow2(double s, int k) {
    if (k >= -1022) return s * exact_pow2(k);
    return (s * exact_pow2(k + 64)) * exact_pow2(-64);
}
}  // namespace detail

// det_exp as a constant expression, with det_exp's bits (tests/test_core_detmath.cpp compares
// them over the whole domain). For values known when the program is built, e.g.
// `constexpr double e = det_exp_constexpr(-0.9);`: a small device then links no double
// arithmetic for them (solid/fractal_params.hpp's level_amplitudes). At run time call det_exp:
// evaluated in your own code this would follow your compiler's flags (an a·b + c contracted
// into an FMA without -ffp-contract=off gives other bits).
constexpr double det_exp_constexpr(double x) {
    return detail::exp_steps(
        x, [](double v) { return detail::exact_floor(v); },
        [](double s, int k) { return detail::exact_scale_by_pow2(s, k); });
}

double det_sin(double x);
double det_cos(double x);
double det_tan(double x);
double det_acos(double x);
double det_asin(double x);
double det_atan(double x);
double det_atan2(double y, double x);
double det_pow(double x, double y);

float det_sinf(float x);
float det_cosf(float x);
float det_tanf(float x);
float det_expf(float x);
float det_logf(float x);
float det_powf(float x, float y);
float det_acosf(float x);
float det_asinf(float x);
float det_atanf(float x);
float det_atan2f(float y, float x);

// e^x in float arithmetic alone (no double: a few instructions on a Cortex-M4F instead of a
// software-double series), deterministic like the rest, within 2 ulp of the correctly rounded
// result (measured; det_expf is within 1). For per-pixel hot paths (marble's skirts).
float det_expf_fast(float x);

// log x in float arithmetic alone (no double), deterministic like the rest, within 1 ulp of
// the correctly rounded result over all positive floats (every one measured: 0.858); det_logf
// is the double-evaluated one. For per-node hot paths (the lattice's Gaussian tails).
float det_logf_fast(float x);

// sin x in float arithmetic alone for |x| <= 4096 (larger |x|, NaN and inf: det_sinf),
// deterministic like the rest, within 1 ulp of the correctly rounded result there (every
// float of [-4096, 4096] measured: 0.781). For per-pixel hot paths (wood's rings, okada1987
// eq. (10)).
float det_sinf_fast(float x);

// Float overloads under the std:: names, so det_sin(x) picks the float or the double function
// exactly as std::sin(x) does.
inline float det_sin(float x) { return det_sinf(x); }
inline float det_cos(float x) { return det_cosf(x); }
inline float det_tan(float x) { return det_tanf(x); }
inline float det_acos(float x) { return det_acosf(x); }
inline float det_asin(float x) { return det_asinf(x); }
inline float det_atan(float x) { return det_atanf(x); }
inline float det_atan2(float y, float x) { return det_atan2f(y, x); }
inline float det_pow(float x, float y) { return det_powf(x, y); }

}  // namespace shitsukan
