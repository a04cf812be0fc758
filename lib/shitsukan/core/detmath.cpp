// small-device: yes (no allocation, no exceptions)
#include "shitsukan/core/detmath.hpp"

#include <cmath>

namespace shitsukan {

namespace {
constexpr double kLn2Hi = 6.93147180369123816490e-01;  // ln 2 split in two (fdlibm), so
constexpr double kLn2Lo = 1.90821492927058770002e-10;  // e·ln2 is exact in the high part
}  // namespace

double det_log(double x) {
    if (!(x > 0.0)) return x == 0.0 ? -HUGE_VAL : NAN;
    if (std::isinf(x)) return x;
    int e = 0;
    double m = std::frexp(x, &e);      // x = m·2^e, m in [0.5, 1): exact
    if (m < 0.70710678118654752440) {  // bring m into [sqrt(1/2), sqrt(2))
        m *= 2.0;
        e -= 1;
    }
    // log(m) = 2·atanh(s) = 2(s + s^3/3 + s^5/5 + ...), s = (m-1)/(m+1), |s| <= 0.1716
    double s = (m - 1.0) / (m + 1.0);
    double s2 = s * s;
    double term = s, sum = 0.0;
    for (int k = 1; k <= 25; k += 2) {  // s^27/27 < 1e-22: the series has converged
        sum += term / k;
        term *= s2;
    }
    return (2.0 * sum + e * kLn2Lo) + e * kLn2Hi;
}

double det_exp(double x) {
    if (std::isnan(x)) return x;
    if (x > 709.0) return HUGE_VAL;
    if (x < -745.0) return 0.0;
    // x = k·ln2 + r, |r| <= ln2/2; e^x = 2^k · e^r, e^r by its Taylor series.
    double kd = std::floor(x / (kLn2Hi + kLn2Lo) + 0.5);
    int k = int(kd);
    double r = (x - kd * kLn2Hi) - kd * kLn2Lo;
    // Horner form of 1 + r(1 + r/2(1 + r/3(... (1 + r/20)))): (ln2/2)^21/21! < 1e-28.
    double sum = 1.0;
    for (int n = 20; n >= 1; --n) sum = 1.0 + sum * r / n;
    return std::ldexp(sum, k);
}

}  // namespace shitsukan
