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
// small-device: yes (no allocation)
#pragma once

namespace shitsukan {

double det_log(double x);  // natural log, x > 0 (NaN for x < 0 or NaN, -inf for 0)
double det_exp(double x);  // e^x (0 below -745, +inf above 709)
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
