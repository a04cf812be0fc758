// core/gaussian: gaussian_from_bits_float's integer tail test and p - 0.5 give the same
// floats as the double expressions they replace, at the tail edges and everywhere else.
#include <doctest/doctest.h>

#include <cstring>
#include <initializer_list>

#include "shitsukan/core/gaussian.hpp"
#include "shitsukan/core/prng.hpp"

using namespace shitsukan;

namespace {
// The definition in double (before issue 12 moved it to integers).
float reference(std::uint64_t bits) {
    const double p = open_unit_from_bits(bits);
    if (p < 0.02425 || p > 1.0 - 0.02425) return float(inverse_normal_cdf(p));
    static const float a[6] = {-3.969683028665376e+01f, 2.209460984245205e+02f,
                               -2.759285104469687e+02f, 1.383577518672690e+02f,
                               -3.066479806614716e+01f, 2.506628277459239e+00f};
    static const float b[5] = {-5.447609879822406e+01f, 1.615858368580409e+02f,
                               -1.556989798598866e+02f, 6.680131188771972e+01f,
                               -1.328068155288572e+01f};
    const float q = float(p - 0.5), r = q * q;
    return (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
           (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1.0f);
}
bool same(float x, float y) { return std::memcmp(&x, &y, sizeof x) == 0; }
}  // namespace

TEST_CASE("gaussian_from_bits_float equals its double definition bit for bit") {
    int wrong = 0;
    const std::uint64_t edges[] = {0, 218424581927469ull, 8788774672813522ull,
                                   std::uint64_t(1) << 52, (std::uint64_t(1) << 53) - 1};
    for (std::uint64_t e : edges)
        for (std::int64_t d = -3; d <= 3; ++d) {
            const std::uint64_t m = e + std::uint64_t(d);
            if (m >= (std::uint64_t(1) << 53)) continue;
            for (std::uint64_t low : {0ull, 1ull, 2047ull}) {
                const std::uint64_t bits = (m << 11) | low;
                wrong += !same(gaussian_from_bits_float(bits), reference(bits));
            }
        }
    Pcg32 rng(99);
    for (int i = 0; i < 1000000; ++i) {
        const std::uint64_t bits = (std::uint64_t(rng.next_u32()) << 32) | rng.next_u32();
        wrong += !same(gaussian_from_bits_float(bits), reference(bits));
    }
    CHECK(wrong == 0);
}
