// shitsukan/core/detmath.hpp — log and exp that give the same bits on every machine.
//
// Manual
//   double det_log(double x);   natural log, x > 0 (returns NaN for x <= 0 or NaN)
//   double det_exp(double x);   e^x for |x| < 700 (0 / +inf beyond)
// Why: the C library's log/exp are not required to be correctly rounded, so two libms
// (glibc, newlib on a microcontroller, MSVC) may differ in the last bit, and a Gaussian
// drawn through them would differ too. These use only +, -, *, / and frexp/ldexp (exact),
// so with -ffp-contract=off they are bit-identical wherever IEEE double is. Accuracy is
// about 1 ulp, plenty for random numbers and per-level amplitudes.
#pragma once

namespace shitsukan {

double det_log(double x);
double det_exp(double x);

}  // namespace shitsukan
