// core/detmath.hpp: the float functions are within 1 ulp of the correctly rounded result over
// their domains (measured against long double), follow C99's special values, and give
// fixed bits (a digest the host, the sanitizer build and the Cortex-M transcripts share).
#include <doctest/doctest.h>
#include "measured.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <ios>
#include <initializer_list>
#include <limits>

#include "shitsukan/core/detmath.hpp"
#include "shitsukan/core/prng.hpp"

using namespace shitsukan;

namespace {

std::uint32_t float_bits(float f) {
    std::uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    return u;
}

// FNV-1a over the bytes of each float, low byte first (the transcript's digest).
struct FloatDigest {
    std::uint64_t h = 0xcbf29ce484222325ull;
    void add(float v) {
        const std::uint32_t u = float_bits(v);
        for (int i = 0; i < 4; ++i) h = (h ^ ((u >> (8 * i)) & 0xffu)) * 0x100000001b3ull;
    }
};
float from_bits(std::uint32_t u) {
    float f;
    std::memcpy(&f, &u, sizeof f);
    return f;
}

// |f - exact| in units of the float ulp at the exact value (long double as "exact": 11 more
// bits than double, so a correctly rounded float measures <= 0.5 + 2^-39).
double ulp_error(float f, long double exact) {
    if (std::isnan(exact)) return std::isnan(f) ? 0.0 : 1e9;
    if (std::isinf(exact)) return f == float(exact) ? 0.0 : 1e9;
    long double a = std::fabs(exact);
    int e = 0;
    std::frexp(a, &e);  // a in [2^(e-1), 2^e)
    long double ulp = std::ldexp(1.0L, (e - 1) - 23 < -149 ? -149 : (e - 1) - 23);
    if (a >= std::ldexp(1.0L, 128)) return std::isinf(f) ? 0.0 : 1e9;  // rounds to inf
    return double(std::fabs((long double)f - exact) / ulp);
}

struct Worst {
    double err = 0;
    float x = 0, y = 0;
    void add(double e, float a, float b = 0) {
        if (e > err) {
            err = e;
            x = a;
            y = b;
        }
    }
};

// Every 'stride'-th float bit pattern in [lo, hi] (both signs when symmetric is true) plus
// random floats of every exponent: the domain of a one-argument function.
template <class F, class R>
Worst scan(F f, R ref, float lo, float hi, std::uint32_t stride) {
    Worst w;
    for (std::uint32_t u = float_bits(lo); u <= float_bits(hi); u += stride) {
        const float x = from_bits(u);
        w.add(ulp_error(f(x), ref((long double)x)), x);
        w.add(ulp_error(f(-x), ref(-(long double)x)), -x);
        if (u > 0xffffffffu - stride) break;
    }
    return w;
}

}  // namespace

TEST_CASE("det_sinf, det_cosf, det_tanf: within 1 ulp over all finite floats") {
    auto s = [](float x) { return det_sinf(x); };
    auto c = [](float x) { return det_cosf(x); };
    auto t = [](float x) { return det_tanf(x); };
    auto rs = [](long double x) { return sinl(x); };
    auto rc = [](long double x) { return cosl(x); };
    auto rt = [](long double x) { return tanl(x); };
    // [0, 2^19): the Cody-Waite range, densely; [2^19, FLT_MAX]: the Payne-Hanek range.
    for (int which = 0; which < 3; ++which) {
        Worst a = which == 0   ? scan(s, rs, 0.0f, 0x1p19f, 1031)
                  : which == 1 ? scan(c, rc, 0.0f, 0x1p19f, 1031)
                               : scan(t, rt, 0.0f, 0x1p19f, 1031);
        Worst b = which == 0   ? scan(s, rs, 0x1p19f, 3.4e38f, 8191)
                  : which == 1 ? scan(c, rc, 0x1p19f, 3.4e38f, 8191)
                               : scan(t, rt, 0x1p19f, 3.4e38f, 8191);
        MEASURED("sin/cos/tan #" << which << ": worst " << a.err << " ulp at " << a.x
                                << " (below 2^19), " << b.err << " ulp at " << b.x << " (above)");
        CHECK(a.err < 1.0);
        CHECK(b.err < 1.0);
    }
    // Known hard cases for reduction: floats nearest to multiples of pi/2.
    for (float x : {3.14159274f, 1.57079637f, 6.28318548f, 1.0e22f, 8.5e37f, 3.4e38f}) {
        CHECK(ulp_error(det_sinf(x), sinl((long double)x)) < 1.0);
        CHECK(ulp_error(det_cosf(x), cosl((long double)x)) < 1.0);
    }
    CHECK(std::isnan(det_sinf(INFINITY)));
    CHECK(std::isnan(det_cosf(NAN)));
    CHECK(std::signbit(det_sinf(-0.0f)));
    CHECK(det_cosf(0.0f) == 1.0f);
}

TEST_CASE("det_expf, det_logf: within 1 ulp over their domains") {
    Worst e = scan([](float x) { return det_expf(x); }, [](long double x) { return expl(x); }, 0.0f,
                   104.0f, 1021);
    Worst l = scan([](float x) { return det_logf(x); }, [](long double x) { return logl(x); },
                   from_bits(1), 3.4e38f, 4093);
    MEASURED("exp worst " << e.err << " ulp at " << e.x << ", log worst " << l.err << " ulp at "
                         << l.x);
    CHECK(e.err < 1.0);
    CHECK(l.err < 1.0);
    CHECK(det_expf(0.0f) == 1.0f);
    CHECK(std::isinf(det_expf(89.0f)));
    CHECK(det_expf(-110.0f) == 0.0f);
}

TEST_CASE("det_expf_fast: float arithmetic only, within 2 ulp over its domain") {
    Worst e = scan([](float x) { return det_expf_fast(x); },
                   [](long double x) { return expl(x); }, 0.0f, 104.0f, 257);
    MEASURED("exp (float arithmetic) worst " << e.err << " ulp at " << e.x);
    CHECK(e.err < 2.0);
    CHECK(det_expf_fast(0.0f) == 1.0f);
    CHECK(std::isinf(det_expf_fast(89.0f)));
    CHECK(det_expf_fast(-104.0f) == 0.0f);
    CHECK(det_expf_fast(88.5f) > 2.0e38f);
    CHECK(det_expf_fast(-100.0f) > 0.0f);  // subnormal results are not flushed
}

TEST_CASE("det_logf_fast: float arithmetic only, within 1 ulp over all positive floats") {
    auto f = [](float x) { return det_logf_fast(x); };
    auto ref = [](long double x) { return logl(x); };
    Worst all = scan(f, ref, from_bits(1), 3.4e38f, 1021);  // every exponent
    Worst near1 = scan(f, ref, 0.5f, 2.0f, 7);              // k = 0, +-1: f = m - 1
    Worst tails = scan(f, ref, 0x1p-55f, 0.0243f, 509);     // the Gaussian tails' t
    MEASURED("log (float arithmetic) worst " << all.err << " ulp at " << all.x << ", " << near1.err
                                            << " near 1, " << tails.err
                                            << " on the Gaussian tails' range");
    CHECK(all.err < 1.0);
    CHECK(near1.err < 1.0);
    CHECK(tails.err < 1.0);
    CHECK(det_logf_fast(1.0f) == 0.0f);
    CHECK(det_logf_fast(0.0f) == -HUGE_VALF);
    CHECK(det_logf_fast(-0.0f) == -HUGE_VALF);
    CHECK(std::isnan(det_logf_fast(-1.0f)));
    CHECK(std::isnan(det_logf_fast(NAN)));
    CHECK(det_logf_fast(HUGE_VALF) == HUGE_VALF);
    CHECK(ulp_error(det_logf_fast(from_bits(1)), logl((long double)from_bits(1))) < 1.0);
}

TEST_CASE("det_sinf_fast: float arithmetic only, within 1 ulp for |x| <= 4096") {
    auto f = [](float x) { return det_sinf_fast(x); };
    auto ref = [](long double x) { return sinl(x); };
    Worst all = scan(f, ref, 0.0f, 4096.0f, 331);
    Worst small = scan(f, ref, 0.0f, 8.0f, 13);  // the first quadrants, densely
    MEASURED("sin (float arithmetic) worst " << all.err << " ulp at " << all.x << ", "
                                            << small.err << " on [0, 8]");
    CHECK(all.err < 1.0);
    CHECK(small.err < 1.0);
    // Floats nearest to multiples of pi/2 (the reduction's hard cases) and the edge.
    for (float x : {3.14159274f, 1.57079637f, 6.28318548f, 1608.49536f, 4095.99976f, 4096.0f})
        CHECK(ulp_error(det_sinf_fast(x), sinl((long double)x)) < 1.0);
    for (float x : {4096.5f, 1.0e6f, 3.4e38f, -5000.0f})  // beyond: det_sinf's bits
        CHECK(float_bits(det_sinf_fast(x)) == float_bits(det_sinf(x)));
    CHECK(std::isnan(det_sinf_fast(INFINITY)));
    CHECK(std::isnan(det_sinf_fast(NAN)));
    CHECK(std::signbit(det_sinf_fast(-0.0f)));
    CHECK(det_sinf_fast(0.0f) == 0.0f);
}

TEST_CASE("det_powf: within 1 ulp, exact powers exact, C99 special values") {
    Pcg32 rng(12, 7);
    Worst w;
    for (int i = 0; i < 400000; ++i) {
        const float x = from_bits(rng.next_u32() & 0x7fffffffu);
        const float y = float(rng.uniform() * 60.0 - 30.0);
        if (!std::isfinite(x)) continue;
        const long double r = powl((long double)x, (long double)y);
        if (r > 3.0e38L || r < 1e-44L) continue;  // overflow / deep underflow: checked below
        w.add(ulp_error(det_powf(x, y), r), x, y);
        const float x2 = float(rng.uniform() * 4.0);  // the shading range: n·h in [0, 4)
        const float y2 = float(1.0 + rng.uniform() * 127.0);
        w.add(ulp_error(det_powf(x2, y2), powl((long double)x2, (long double)y2)), x2, y2);
    }
    MEASURED("pow worst " << w.err << " ulp at x = " << w.x << ", y = " << w.y);
    CHECK(w.err < 1.0);
    CHECK(det_powf(2.0f, 3.0f) == 8.0f);
    CHECK(det_powf(-2.0f, 3.0f) == -8.0f);
    CHECK(det_powf(-2.0f, 2.0f) == 4.0f);
    CHECK(det_powf(0.5f, 10.0f) == 0x1p-10f);
    CHECK(det_powf(9.0f, 0.5f) == 3.0f);
    CHECK(det_powf(0.0f, 0.0f) == 1.0f);
    CHECK(det_powf(NAN, 0.0f) == 1.0f);
    CHECK(det_powf(1.0f, NAN) == 1.0f);
    CHECK(std::isnan(det_powf(-2.0f, 0.5f)));
    CHECK(det_powf(0.0f, 3.0f) == 0.0f);
    CHECK(std::isinf(det_powf(0.0f, -1.0f)));
    CHECK(std::signbit(det_powf(-0.0f, 3.0f)));
    CHECK(det_powf(0.5f, INFINITY) == 0.0f);
    CHECK(std::isinf(det_powf(10.0f, 40.0f)));
    CHECK(det_powf(10.0f, -50.0f) == 0.0f);
}

TEST_CASE("det_acosf, det_asinf, det_atanf, det_atan2f: within 1 ulp") {
    Worst ac = scan([](float x) { return det_acosf(x); }, [](long double x) { return acosl(x); },
                    0.0f, 1.0f, 2039);
    Worst as = scan([](float x) { return det_asinf(x); }, [](long double x) { return asinl(x); },
                    0.0f, 1.0f, 2039);
    Worst at = scan([](float x) { return det_atanf(x); }, [](long double x) { return atanl(x); },
                    0.0f, 3.4e38f, 16381);
    Pcg32 rng(5, 9);
    Worst a2;
    for (int i = 0; i < 100000; ++i) {
        const float y = from_bits(rng.next_u32()), x = from_bits(rng.next_u32());
        if (!std::isfinite(x) || !std::isfinite(y)) continue;
        a2.add(ulp_error(det_atan2f(y, x), atan2l((long double)y, (long double)x)), y, x);
        const float y2 = float(rng.uniform() * 2 - 1), x2 = float(rng.uniform() * 2 - 1);
        a2.add(ulp_error(det_atan2f(y2, x2), atan2l((long double)y2, (long double)x2)), y2, x2);
    }
    MEASURED("acos " << ac.err << ", asin " << as.err << ", atan " << at.err << ", atan2 "
                    << a2.err << " ulp (worst)");
    CHECK(ac.err < 1.0);
    CHECK(as.err < 1.0);
    CHECK(at.err < 1.0);
    CHECK(a2.err < 1.0);
    CHECK(std::isnan(det_acosf(1.5f)));
    CHECK(det_acosf(1.0f) == 0.0f);
    CHECK(det_atan2f(0.0f, -0.0f) == float(M_PI));
    CHECK(det_atan2f(-0.0f, -1.0f) == -float(M_PI));
    CHECK(det_atan2f(1.0f, INFINITY) == 0.0f);
    CHECK(det_atan2f(INFINITY, INFINITY) == float(M_PI / 4));
}

TEST_CASE("det_sin, det_cos (double) within 4 double ulps for mesh angles") {
    double worst = 0;
    for (int i = -200000; i <= 200000; ++i) {
        const double x = i * 1e-4 * 3.7;
        const long double rs = sinl((long double)x), rc = cosl((long double)x);
        const double us = std::nextafter(double(std::fabs(rs)), INFINITY) - double(std::fabs(rs));
        const double uc = std::nextafter(double(std::fabs(rc)), INFINITY) - double(std::fabs(rc));
        worst = std::fmax(worst, double(std::fabs(det_sin(x) - rs)) / us);
        worst = std::fmax(worst, double(std::fabs(det_cos(x) - rc)) / uc);
    }
    MEASURED("det_sin/det_cos worst " << worst << " double ulp on [-74, 74]");
    CHECK(worst < 4.0);
}

// The same bits everywhere: this digest of det_* over fixed inputs is also in
// ports/cortex-m's transcript (host gcc -O2, host clang -O0, Cortex-M4F and M7 at -Os), and
// this file runs at -O2 (make test) and -O1 with sanitizers (make test-sanitize).
TEST_CASE("detmath digest: fixed bits at every optimisation level and on every target") {
    FloatDigest digest;
    auto add = [&](float v) { digest.add(v); };
    for (int i = 0; i < 4096; ++i) {
        const float x = float(i - 2048) * 0.0123f, u = float(i) / 4096.0f;
        add(det_sinf(x * 37.0f));
        add(det_cosf(x));
        add(det_tanf(x));
        add(det_expf(x * 0.5f));
        add(det_logf(u + 0.001f));
        add(det_powf(u * 1.7f, 1.0f + float(i % 97)));
        add(det_acosf(u * 2.0f - 1.0f));
        add(det_atan2f(x, u - 0.5f));
    }
    CHECK(digest.h == 0x6baa0d5c02c1a86dull);  // ports/cortex-m transcript line "detmath"
}

TEST_CASE("detmath float-arithmetic digest: fixed bits at every optimisation level and target") {
    FloatDigest digest;
    auto add = [&](float v) { digest.add(v); };
    for (int i = 0; i < 4096; ++i) {
        const float x = float(i - 2048) * 0.0123f, u = float(i) / 4096.0f;
        add(det_expf_fast(x * 0.5f));
        add(det_logf_fast(u + 0.001f));
        add(det_logf_fast(float(i + 1) * 1.0e-9f));
        add(det_sinf_fast(x * 37.0f));
    }
    CHECK(digest.h == 0x2c5acc37dd3d0b04ull);  // ports/cortex-m transcript line "detmath fast"
}

// det_exp_constexpr: det_exp's steps evaluated by the compiler. Arguments over det_exp's whole
// domain, with its edges: results that are subnormal doubles (x below -708, where ldexp
// rounds: det_exp_constexpr's own scaling must round once, as ldexp does), the cut-offs at
// -745 and 709, zeros, infinities; every one computed at compile time and compared bit for
// bit with det_exp at run time.
namespace {
constexpr int kExpSamples = 6000;
struct ExpSamples {
    double x[kExpSamples] = {}, e[kExpSamples] = {};
};
constexpr ExpSamples make_exp_samples() {
    ExpSamples s;
    for (int i = 0; i < kExpSamples; ++i) {
        double x = 0.0;
        if (i < 4000)  // the whole domain, at irregular steps
            x = -746.0 + double(i) * (1456.0 / 4000.0) + double(i % 7) * 1.0e-3;
        else if (i < 5500)  // the subnormal results, densely
            x = -745.0 + double(i - 4000) * (37.0 / 1500.0) + double(i % 11) * 1.0e-9;
        else  // near 0, where r is everything
            x = double(i - 5750) * 1.0e-3 + double(i % 3) * 1.0e-17;
        s.x[i] = x;
    }
    const double edges[] = {0.0, -0.0, -745.0, -744.99, 709.0, 708.99, -708.4, -709.1,
                            std::numeric_limits<double>::infinity(),
                            -std::numeric_limits<double>::infinity()};
    for (int i = 0; i < int(sizeof edges / sizeof edges[0]); ++i) s.x[i] = edges[i];
    for (int i = 0; i < kExpSamples; ++i) s.e[i] = det_exp_constexpr(s.x[i]);
    return s;
}
constexpr ExpSamples kExpAtCompileTime = make_exp_samples();
static_assert(det_exp_constexpr(0.0) == 1.0, "e^0 = 1");
}  // namespace

TEST_CASE("det_exp_constexpr: det_exp's bits, computed by the compiler, over det_exp's domain") {
    int differ = 0, subnormal = 0;
    for (int i = 0; i < kExpSamples; ++i) {
        const double x = kExpAtCompileTime.x[i], at_run_time = det_exp(x);
        std::uint64_t a, b;
        std::memcpy(&a, &kExpAtCompileTime.e[i], 8);
        std::memcpy(&b, &at_run_time, 8);
        if (a != b && ++differ <= 5)
            MESSAGE("x = " << x << ": compile time bits " << std::hex << a << ", run time "
                           << b);
        if (at_run_time > 0.0 && at_run_time < 0x1p-1022) ++subnormal;
    }
    CHECK(differ == 0);
    CHECK(subnormal > 1000);  // the rounding ldexp does was really exercised
    const double nan = det_exp_constexpr(std::numeric_limits<double>::quiet_NaN());
    CHECK(nan != nan);
}
