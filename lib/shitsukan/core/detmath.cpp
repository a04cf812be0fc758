// small-device: yes (no allocation, no exceptions)
#include "shitsukan/core/detmath.hpp"

#include <cmath>
#include <cstdint>

// Every operation here is meant in the format of its type, rounded once (the bits the
// compiler's constant evaluation gives too: det_exp_constexpr). A target that evaluates
// float and double in a wider format (FLT_EVAL_METHOD 1 or 2: x87 without SSE2) would give
// other bits: refused here rather than differing silently.
#if defined(__FLT_EVAL_METHOD__) && __FLT_EVAL_METHOD__ > 0
#error "shitsukan's deterministic maths needs FLT_EVAL_METHOD 0 (e.g. -msse2 -mfpmath=sse on i386)"
#endif

namespace shitsukan {

namespace {
using detail::kLn2Hi;  // ln 2 split in two (detmath.hpp)
using detail::kLn2Lo;

// Series coefficients, computed by the compiler (IEEE double, the same on every host).
constexpr int kLogTerms = 12;  // 1/1, 1/3, ..., 1/23

struct Coefficients {
    double v[16];
};

constexpr Coefficients inverse_odd() {
    Coefficients c{};
    for (int j = 0; j < kLogTerms; ++j) c.v[j] = 1.0 / double(2 * j + 1);
    return c;
}

constexpr Coefficients kInvOddTable = inverse_odd();
constexpr const double* kInvOdd = kInvOddTable.v;
}  // namespace

double det_log(double x) {
    if (!(x > 0.0)) return x == 0.0 ? -HUGE_VAL : double(NAN);
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
    // detmath.hpp's exp_steps with the C library's floor and ldexp (both exact or correctly
    // rounded: det_exp_constexpr's own give the same bits).
    return detail::exp_steps(
        x, [](double v) { return std::floor(v); }, [](double s, int k) { return std::ldexp(s, k); });
}

// ---- float functions: evaluated in double from exact reductions, rounded once to float ----
// Each result below is an IEEE double within a few double ulps (about 2^-50 relative) of the
// exact value, then rounded once to float: the float is the correctly rounded one except
// when the exact value lies within 2^-26 float ulp of a halfway point, and never more than
// 1 float ulp away (tests/test_core_detmath.cpp measures it against long double).

namespace {

constexpr double kPio2 = 0x1.921fb54442d18p+0;       // pi/2 rounded to double
constexpr double kPi = 0x1.921fb54442d18p+1;         // pi
constexpr double kTwoOverPi = 0x1.45f306dc9c883p-1;  // 2/pi
// pi/2 = kPio2_1 + kPio2_2 + kPio2_3 (+ < 2^-120): the first two have 33 significant bits,
// so k·kPio2_1 and k·kPio2_2 are exact for |k| < 2^20 (Cody & Waite's reduction).
constexpr double kPio2_1 = 0x1.921fb544p+0;
constexpr double kPio2_2 = 0x1.0b4611a6p-34;
constexpr double kPio2_3 = 0x1.3198a2e037073p-69;

// The bits of 2/pi after the binary point, 32 a word (computed with integer arithmetic from
// Machin's formula; enough for every float exponent: bits up to 104 + 96 + 32 are used).
constexpr std::uint32_t kTwoOverPiBits[] = {
    0xA2F9836E, 0x4E441529, 0xFC2757D1, 0xF534DDC0, 0xDB629599,
    0x3C439041, 0xFE5163AB, 0xDEBBC561, 0xB7246E3A, 0x424DD2E0};

// 32 bits of 2/pi starting at bit `first` (1-based: bit 1 is the 2^-1 digit).
std::uint32_t two_over_pi_word(int first) {
    const int w = (first - 1) / 32, o = (first - 1) % 32;
    const std::uint64_t pair =
        (std::uint64_t(kTwoOverPiBits[w]) << 32) | std::uint64_t(kTwoOverPiBits[w + 1]);
    return std::uint32_t(pair >> (32 - o));
}

// x = q·pi/2 + r for a finite float x, |r| <= pi/4 (about), q mod 4 returned in *quadrant.
double reduce_quadrant(float xf, int* quadrant) {
    const double x = xf;
    const double ax = x < 0 ? -x : x;
    if (ax <= 0x1.921fb6p-1) {  // |x| <= pi/4: nothing to do
        *quadrant = 0;
        return x;
    }
    if (ax < 0x1p19) {  // Cody-Waite: every product below is exact, the sums nearly so
        const double k = std::floor(x * kTwoOverPi + 0.5);
        *quadrant = int(static_cast<long>(k) & 3);
        return ((x - k * kPio2_1) - k * kPio2_2) - k * kPio2_3;
    }
    // Payne-Hanek: |x| = m·2^e with a 24-bit integer m, e >= -4. x·2/pi modulo 4 needs only
    // the bits of 2/pi from position e-1 on (earlier ones give multiples of 4): multiply m by
    // 96 of them exactly (a 120-bit integer) and read the quarter turns and the fraction.
    std::uint32_t bits;
    __builtin_memcpy(&bits, &xf, sizeof bits);
    const std::uint32_t m = (bits & 0x7fffffu) | 0x800000u;
    const int e = int((bits >> 23) & 0xffu) - 150;
    const int first = e - 1 > 1 ? e - 1 : 1;
    const std::uint32_t w0 = two_over_pi_word(first), w1 = two_over_pi_word(first + 32),
                        w2 = two_over_pi_word(first + 64);
    // p = m·(w0 w1 w2), as four 32-bit words p3 p2 p1 p0 (most significant first).
    const std::uint64_t a2 = std::uint64_t(m) * w2, a1 = std::uint64_t(m) * w1,
                        a0 = std::uint64_t(m) * w0;
    const std::uint32_t p0 = std::uint32_t(a2);
    std::uint64_t t = (a2 >> 32) + std::uint32_t(a1);
    const std::uint32_t p1 = std::uint32_t(t);
    t = (t >> 32) + (a1 >> 32) + std::uint32_t(a0);
    const std::uint32_t p2 = std::uint32_t(t);
    const std::uint32_t p3 = std::uint32_t((t >> 32) + (a0 >> 32));
    // value = p · 2^(e - first - 95): the binary point sits s = first + 95 - e bits up
    // (94 <= s <= 100). Bring it to 96 bits up (the boundary between p3 and p2).
    const int shift = 96 - (first + 95 - e);  // -4 .. 2: shift p left by this much
    std::uint64_t hi = (std::uint64_t(p3) << 32) | p2, lo = (std::uint64_t(p1) << 32) | p0;
    if (shift > 0) {
        hi = (hi << shift) | (lo >> (64 - shift));
        lo <<= shift;
    } else if (shift < 0) {
        lo = (lo >> -shift) | (hi << (64 + shift));
        hi >>= -shift;
    }
    // Now the integer part is hi >> 32, the fraction (hi & 0xffffffff) · 2^-32 + lo · 2^-96.
    int q = int((hi >> 32) & 3u);
    const std::uint64_t frac64 = (hi << 32) | (lo >> 32);  // the fraction's first 64 bits
    double f = double(frac64) * 0x1p-64;                     // in [0, 1)
    if (f >= 0.5) {
        f -= 1.0;
        q = (q + 1) & 3;
    }
    double r = f * kPio2;
    if (x < 0) {
        r = -r;
        q = (4 - q) & 3;
    }
    *quadrant = q;
    return r;
}

// sin and cos of |r| <= 0.79 by their Taylor series (the first omitted term is < 2^-60).
double sin_kernel(double r) {
    const double r2 = r * r;
    double s = -1.0 / 1307674368000.0;  // -1/15!
    s = s * r2 + 1.0 / 6227020800.0;    // 1/13!
    s = s * r2 - 1.0 / 39916800.0;
    s = s * r2 + 1.0 / 362880.0;
    s = s * r2 - 1.0 / 5040.0;
    s = s * r2 + 1.0 / 120.0;
    s = s * r2 - 1.0 / 6.0;
    return r + r * (r2 * s);
}
double cos_kernel(double r) {
    const double r2 = r * r;
    double c = 1.0 / 20922789888000.0;  // 1/16!
    c = c * r2 - 1.0 / 87178291200.0;   // -1/14!
    c = c * r2 + 1.0 / 479001600.0;
    c = c * r2 - 1.0 / 3628800.0;
    c = c * r2 + 1.0 / 40320.0;
    c = c * r2 - 1.0 / 720.0;
    c = c * r2 + 1.0 / 24.0;
    c = c * r2 - 0.5;
    return 1.0 + r2 * c;
}

// atan of t in [0, 1]: atan(t) = pi/6 + atan((t·sqrt3 - 1)/(t + sqrt3)) above tan(pi/12),
// then the Taylor series for |u| <= 0.268 (u^2 <= 0.072: 16 terms reach 2^-60).
double atan_unit(double t) {
    constexpr double kSqrt3 = 0x1.bb67ae8584caap+0;
    constexpr double kPi6 = 0x1.0c152382d7366p-1;
    double base = 0.0;
    if (t > 0.2679491924311227) {
        t = (t * kSqrt3 - 1.0) / (t + kSqrt3);
        base = kPi6;
    }
    const double t2 = t * t;
    double s = 1.0 / 33.0;  // Horner in -t^2: 1 - t^2/3 + t^4/5 - ... + t^32/33
    for (int j = 16; j >= 1; --j) s = 1.0 / double(2 * j - 1) - t2 * s;
    return base + t * s;
}

// atan2 in double for finite or infinite y, x (not NaN).
double atan2_double(double y, double x) {
    const double ay = y < 0 ? -y : y, ax = x < 0 ? -x : x;
    double a;
    if (ay == 0.0 && ax == 0.0) {
        a = 0.0;
    } else if (std::isinf(ay) && std::isinf(ax)) {
        a = kPio2 / 2.0;
    } else if (ay <= ax) {
        a = atan_unit(ay / ax);
    } else {
        a = kPio2 - atan_unit(ax / ay);
    }
    if (std::signbit(x)) a = kPi - a;
    return std::signbit(y) ? -a : a;
}

}  // namespace

double det_sin(double x) {
    if (!std::isfinite(x)) return x - x;
    const double k = std::floor(x * kTwoOverPi + 0.5);
    const double r = ((x - k * kPio2_1) - k * kPio2_2) - k * kPio2_3;
    const int q = int(static_cast<long long>(k) & 3);
    const double s = (q & 1) ? cos_kernel(r) : sin_kernel(r);
    return q & 2 ? -s : s;
}

double det_cos(double x) {
    if (!std::isfinite(x)) return x - x;
    const double k = std::floor(x * kTwoOverPi + 0.5);
    const double r = ((x - k * kPio2_1) - k * kPio2_2) - k * kPio2_3;
    const int q = int(static_cast<long long>(k) & 3);
    const double c = (q & 1) ? sin_kernel(r) : cos_kernel(r);
    return ((q + 1) & 2) ? -c : c;
}

float det_sinf(float x) {
    if (!std::isfinite(x)) return x - x;  // NaN (and NaN for +-inf)
    if (x == 0.0f) return x;              // keeps the sign of zero
    int q;
    const double r = reduce_quadrant(x, &q);
    const double s = (q & 1) ? cos_kernel(r) : sin_kernel(r);
    return float(q & 2 ? -s : s);
}

float det_cosf(float x) {
    if (!std::isfinite(x)) return x - x;
    int q;
    const double r = reduce_quadrant(x, &q);
    const double c = (q & 1) ? sin_kernel(r) : cos_kernel(r);
    return float(((q + 1) & 2) ? -c : c);
}

float det_tanf(float x) {
    if (!std::isfinite(x)) return x - x;
    if (x == 0.0f) return x;
    int q;
    const double r = reduce_quadrant(x, &q);
    const double s = sin_kernel(r), c = cos_kernel(r);
    return float((q & 1) ? -c / s : s / c);
}

float det_expf(float x) {
    if (std::isnan(x)) return x;
    if (x > 89.0f) return HUGE_VALF;
    if (x < -104.0f) return 0.0f;
    return float(det_exp(double(x)));
}

float det_logf(float x) { return float(det_log(double(x))); }

float det_powf(float x, float y) {
    // C99 Annex F special cases first (pow(x, +-0) = 1, pow(1, y) = 1, NaN, zeros, inf).
    if (y == 0.0f || x == 1.0f) return 1.0f;
    if (std::isnan(x) || std::isnan(y)) return x + y;
    const float ay = std::fabs(y);
    const bool y_integer = std::floor(y) == y;
    const bool y_odd = y_integer && ay < 0x1p24f && (long(ay) & 1) == 1;
    if (std::isinf(y)) {
        const float ax = std::fabs(x);
        if (ax == 1.0f) return 1.0f;
        return (ax > 1.0f) == (y > 0) ? HUGE_VALF : 0.0f;
    }
    if (x == 0.0f || std::isinf(x)) {
        // |x| = 0: 0^y is 0 (y > 0) or inf (y < 0); |x| = inf the other way round. The sign
        // is x's for odd integer y.
        const bool big = (x == 0.0f) == (y < 0);
        const float mag = big ? HUGE_VALF : 0.0f;
        return y_odd && std::signbit(x) ? -mag : mag;
    }
    if (x < 0.0f && !y_integer) return NAN;
    // |x|^y = e^(y·log|x|): log in double is within ~2^-52 relative, y·log|x| within
    // 2^-46 absolute for any result in float range, so e^ of it is within 2^-45 relative.
    const double t = double(y) * det_log(double(std::fabs(x)));
    double r;
    if (t > 89.0)
        r = HUGE_VAL;
    else if (t < -104.0)
        r = 0.0;
    else
        r = det_exp(t);
    const float f = float(r);
    return x < 0.0f && y_odd ? -f : f;
}

float det_atan2f(float y, float x) {
    if (std::isnan(x) || std::isnan(y)) return x + y;
    return float(atan2_double(y, x));
}

float det_atanf(float x) { return det_atan2f(x, 1.0f); }

float det_acosf(float x) {
    if (!(x >= -1.0f && x <= 1.0f)) return NAN;
    // acos x = atan2(sqrt((1 - x)(1 + x)), x): both factors and their product are exact in
    // double for a float x, and sqrt is correctly rounded.
    const double xd = x;
    return float(atan2_double(std::sqrt((1.0 - xd) * (1.0 + xd)), xd));
}

float det_asinf(float x) {
    if (!(x >= -1.0f && x <= 1.0f)) return NAN;
    const double xd = x;
    return float(atan2_double(xd, std::sqrt((1.0 - xd) * (1.0 + xd))));
}


// ---- double versions (deterministic; accuracy stated in the header) ----
double det_tan(double x) {
    if (!std::isfinite(x)) return x - x;
    if (x == 0.0) return x;
    const double k = std::floor(x * kTwoOverPi + 0.5);
    const double r = ((x - k * kPio2_1) - k * kPio2_2) - k * kPio2_3;
    const double s = sin_kernel(r), c = cos_kernel(r);
    return (static_cast<long long>(k) & 1) ? -c / s : s / c;
}

double det_atan2(double y, double x) {
    if (std::isnan(x) || std::isnan(y)) return x + y;
    return atan2_double(y, x);
}

double det_atan(double x) {
    if (std::isnan(x)) return x;
    return atan2_double(x, 1.0);
}

double det_acos(double x) {
    if (!(x >= -1.0 && x <= 1.0)) return NAN;
    return atan2_double(std::sqrt((1.0 - x) * (1.0 + x)), x);
}

double det_asin(double x) {
    if (!(x >= -1.0 && x <= 1.0)) return NAN;
    return atan2_double(x, std::sqrt((1.0 - x) * (1.0 + x)));
}

double det_pow(double x, double y) {
    if (y == 0.0 || x == 1.0) return 1.0;
    if (std::isnan(x) || std::isnan(y)) return x + y;
    const double ay = std::fabs(y);
    if (std::floor(y) == y && ay <= 64.0) {  // small integer powers by squaring: exact when
        double result = 1.0, base = x;       // every product is representable
        for (long n = long(ay); n > 0; n >>= 1) {
            if (n & 1) result *= base;
            base *= base;
        }
        return y < 0 ? 1.0 / result : result;
    }
    const bool y_integer = std::floor(y) == y;
    const bool y_odd = y_integer && ay < 0x1p53 && std::fmod(ay, 2.0) == 1.0;
    if (std::isinf(y)) {
        const double ax = std::fabs(x);
        if (ax == 1.0) return 1.0;
        return (ax > 1.0) == (y > 0) ? HUGE_VAL : 0.0;
    }
    if (x == 0.0 || std::isinf(x)) {
        const bool big = (x == 0.0) == (y < 0);
        const double mag = big ? HUGE_VAL : 0.0;
        return y_odd && std::signbit(x) ? -mag : mag;
    }
    if (x < 0.0 && !y_integer) return NAN;
    const double r = det_exp(y * det_log(std::fabs(x)));
    return x < 0.0 && y_odd ? -r : r;
}


// ---- float arithmetic only (hot paths on a single-precision FPU) ----
float det_expf_fast(float x) {
    if (x != x) return x;
    if (x > 88.7228394f) return HUGE_VALF;
    if (x < -103.972084f) return 0.0f;
    // x = k·ln2 + r, |r| <= ln2/2 (about): ln2 = hi + lo with hi of 12 significant bits, so
    // k·hi is exact for |k| <= 2^12 and x - k·hi is exact (Sterbenz) near the reduction.
    constexpr float kLn2HiF = 0x1.62ep-1f;
    constexpr float kLn2LoF = 0x1.0bfbe8p-15f;
    const float k = std::floor(x * 1.44269502f + 0.5f);
    const float r = (x - k * kLn2HiF) - k * kLn2LoF;
    // e^r by Taylor to r^7/7! (the next term is < 3e-9 relative for |r| <= 0.35), Horner.
    float p = 1.0f / 5040.0f;
    p = p * r + 1.0f / 720.0f;
    p = p * r + 1.0f / 120.0f;
    p = p * r + 1.0f / 24.0f;
    p = p * r + 1.0f / 6.0f;
    p = p * r + 0.5f;
    p = p * r + 1.0f;
    p = p * r + 1.0f;
    // times 2^k, built from its bits (k = 128 and subnormal results in two exact steps).
    int ki = int(k);
    if (ki > 127) {
        p *= 2.0f;
        ki -= 1;
    } else if (ki < -126) {
        p *= 0x1p-64f;
        ki += 64;
    }
    const std::uint32_t bits = std::uint32_t(ki + 127) << 23;
    float scale;
    __builtin_memcpy(&scale, &bits, sizeof scale);
    return p * scale;
}

// log x in float arithmetic alone. x = 2^k·m with m in [sqrt(1/2), sqrt(2)), f = m - 1 (exact,
// Sterbenz), log m = log(1 + f) = 2·atanh(s) with s = f / (2 + f), |s| <= 0.1716. Written as
// log(1 + f) = f - (f^2/2 - s·(f^2/2 + R)), R = 2s^2/3 + 2s^4/5 + 2s^6/7 + 2s^8/9 (the next
// term is below 7e-10, 0.02 ulp of log m): s, whose division rounds, only multiplies the small
// correction f^2/2 + R, and f itself enters exactly. k·ln2 = k·hi + k·lo with hi of 15
// significant bits, so k·hi is exact for |k| <= 152; hi is added last.
float det_logf_fast(float x) {
    if (x != x) return x;
    if (x < 0.0f) return NAN;
    if (x == 0.0f) return -HUGE_VALF;
    if (x == HUGE_VALF) return x;
    constexpr float kLn2HiF = 0x1.62e4p-1f;     // ln 2 to 15 significant bits
    constexpr float kLn2LoF = 0x1.7f7d1cp-20f;  // ln 2 - hi, rounded to float
    std::uint32_t u;
    __builtin_memcpy(&u, &x, sizeof u);
    int k = 0;
    if (u < 0x00800000u) {  // subnormal: scale by 2^25 (exact) first
        const float y = x * 0x1p25f;
        __builtin_memcpy(&u, &y, sizeof u);
        k = -25;
    }
    k += int(u >> 23) - 127;
    std::uint32_t mb = (u & 0x007fffffu) | 0x3f800000u;  // m in [1, 2)
    if (mb >= 0x3fb504f3u) {  // m >= sqrt(2) rounded to float (just below it): m / 2
        mb -= 0x00800000u;
        k += 1;
    }
    float m;
    __builtin_memcpy(&m, &mb, sizeof m);
    const float f = m - 1.0f;
    const float s = f / (2.0f + f), z = s * s;
    const float r = z * (2.0f / 3.0f + z * (2.0f / 5.0f + z * (2.0f / 7.0f + z * (2.0f / 9.0f))));
    const float hfsq = 0.5f * f * f;
    const float kf = float(k);
    return kf * kLn2HiF - ((hfsq - (s * (hfsq + r) + kf * kLn2LoF)) - f);
}

// sin x in float arithmetic alone for |x| <= 4096 (beyond: det_sinf). Cody & Waite in float:
// x = k·pi/2 + r with pi/2 = P1 + P2 + P3 + P4 (P1, P2, P3 of 12 significant bits, so their
// products with k <= 2^12 are exact and x - k·P1 is exact; the split is good to 2^-68). r is
// kept as r + lo (exact two-sums collect the subtractions' rounding errors; k·P4 < 2^-32 is the
// only rounded product), then sin(r + lo) = sin r + lo·cos r and cos(r + lo) = cos r - lo·sin r
// to first order, by the Taylor kernels on |r| <= pi/4 (first omitted terms below 0.03 ulp);
// cos's 1 - r^2/2 carries its rounding error too (as fdlibm's kernel does).
float det_sinf_fast(float x) {
    if (!(std::fabs(x) <= 4096.0f)) return det_sinf(x);  // NaN, inf and large |x| too
    if (x == 0.0f) return x;                                // keeps the sign of zero
    constexpr float kP1 = 0x1.922p+0f, kP2 = -0x1.2aep-18f, kP3 = -0x1.deap-31f,
                    kP4 = 0x1.184698p-44f;
    const float k = std::floor(x * 0x1.45f306p-1f + 0.5f);  // x·2/pi, rounded
    // Knuth's two-sum: s + e = a + b exactly, in float.
    auto two_sum = [](float a, float b, float* e) {
        const float s = a + b, bv = s - a;
        *e = (a - (s - bv)) + (b - bv);
        return s;
    };
    float e0, e1;
    const float r0 = two_sum(x - k * kP1, -(k * kP2), &e0);
    const float r1 = two_sum(r0, -(k * kP3), &e1);
    const float lo0 = (e0 + e1) - k * kP4;
    const float r = r1 + lo0, lo = lo0 - (r - r1);  // renormalized: |lo| <= ulp(r)/2
    const float r2 = r * r;
    const int q = int(k) & 3;
    float v;
    if (q & 1) {  // cos r = 1 - r^2/2 + r^4/4! - ... + r^10/10!
        float c = -1.0f / 3628800.0f;
        c = c * r2 + 1.0f / 40320.0f;
        c = c * r2 - 1.0f / 720.0f;
        c = c * r2 + 1.0f / 24.0f;
        const float hz = 0.5f * r2, w = 1.0f - hz;
        v = w + (((1.0f - w) - hz) + (r2 * r2 * c - r * lo));
    } else {  // sin r = r - r^3/3! + ... + r^9/9!
        float s = 1.0f / 362880.0f;
        s = s * r2 - 1.0f / 5040.0f;
        s = s * r2 + 1.0f / 120.0f;
        s = s * r2 - 1.0f / 6.0f;
        v = r + (r * (r2 * s) + lo * (1.0f - 0.5f * r2));
    }
    return q & 2 ? -v : v;
}

}  // namespace shitsukan
