// small-device: yes (no allocation, no exceptions)
#include "shitsukan/core/detmath.hpp"

#include <cmath>

namespace shitsukan {

namespace {
constexpr double kLn2Hi = 6.93147180369123816490e-01;  // ln 2 split in two (fdlibm), so
constexpr double kLn2Lo = 1.90821492927058770002e-10;  // e·ln2 is exact in the high part

// Series coefficients, computed by the compiler (IEEE double, the same on every host).
constexpr int kLogTerms = 12;  // 1/1, 1/3, ..., 1/23
constexpr int kExpTerms = 14;  // 1/0!, 1/1!, ..., 1/13!

struct Coefficients {
    double v[16];
};

constexpr Coefficients inverse_odd() {
    Coefficients c{};
    for (int j = 0; j < kLogTerms; ++j) c.v[j] = 1.0 / double(2 * j + 1);
    return c;
}

constexpr Coefficients inverse_factorial() {
    Coefficients c{};
    double f = 1.0;
    for (int n = 0; n < kExpTerms; ++n) {
        if (n > 0) f *= double(n);  // n! is exact in double up to 22!
        c.v[n] = 1.0 / f;
    }
    return c;
}

constexpr Coefficients kInvOddTable = inverse_odd();
constexpr Coefficients kInvFactorialTable = inverse_factorial();
constexpr const double* kInvOdd = kInvOddTable.v;
constexpr const double* kInvFactorial = kInvFactorialTable.v;
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
    // log(m) = 2·atanh(s) = 2s(1 + s^2/3 + s^4/5 + ...), s = (m-1)/(m+1), |s| <= 0.1716:
    // with s^2 <= 0.0295 the terms up to s^22/23 reach double precision (the next is < 1e-18
    // of the sum). Horner in s^2 with compile-time reciprocals: no division in the loop.
    double s = (m - 1.0) / (m + 1.0);
    double s2 = s * s;
    double poly = kInvOdd[kLogTerms - 1];
    for (int j = kLogTerms - 2; j >= 0; --j) poly = poly * s2 + kInvOdd[j];
    double sum = s * poly;
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
    // e^r = sum r^n/n!, n = 0..13, by Horner with compile-time 1/n!: for |r| <= ln2/2 the first
    // omitted term r^14/14! is < 5e-18, below half an ulp.
    double sum = kInvFactorial[kExpTerms - 1];
    for (int n = kExpTerms - 2; n >= 0; --n) sum = sum * r + kInvFactorial[n];
    return std::ldexp(sum, k);
}

}  // namespace shitsukan
