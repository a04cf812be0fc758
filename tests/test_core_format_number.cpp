// core/format_number: the library's own number formatter against glibc's printf, and the
// shortest round-trip form against strtof.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include <doctest/doctest.h>
#include "shitsukan/core/format_number.hpp"
#include "shitsukan/core/prng.hpp"

using namespace shitsukan;

namespace {

std::string printf_spec(const NumberFormat& f, const char* length) {
    std::string s = "%";
    if (f.left) s += '-';
    if (f.plus) s += '+';
    if (f.space) s += ' ';
    if (f.zero) s += '0';
    if (f.alternate) s += '#';
    if (f.width > 0) s += std::to_string(f.width);
    if (f.precision >= 0) s += "." + std::to_string(f.precision);
    s += length;
    s += f.conversion;
    return s;
}

double random_double(std::uint64_t bits, int mode) {
    double v;
    switch (mode) {
        case 0:  // any bit pattern: NaN, infinities, subnormals, huge and tiny
            std::memcpy(&v, &bits, 8);
            return v;
        case 1:  // a float
        {
            std::uint32_t u = std::uint32_t(bits);
            float f;
            std::memcpy(&f, &u, 4);
            return double(f);
        }
        case 2:  // halves: exact ties for every rounding position
            return double(std::int64_t(bits % 200001) - 100000) * 0.5;
        default:  // short decimals, as user values are
            return double(std::int64_t(bits % 2000001) - 1000000) / double(1 + (bits >> 40) % 1000);
    }
}

}  // namespace

TEST_CASE("format_double equals glibc printf for every conversion, flag, width and precision") {
    Pcg32 rng(12);
    const char conversions[] = "gGeEfF";
    const int precisions[] = {-1, 0, 1, 3, 6, 9, 17, 25};
    int checked = 0, wrong = 0;
    for (int i = 0; i < 100000; ++i) {
        std::uint64_t bits = (std::uint64_t(rng.next_u32()) << 32) | rng.next_u32();
        double v = random_double(bits, i % 4);
        NumberFormat f;
        f.conversion = conversions[rng.next_u32() % 6];
        f.precision = precisions[rng.next_u32() % 8];
        if ((f.conversion == 'f' || f.conversion == 'F') && !(v > -1e40 && v < 1e40)) continue;
        std::uint32_t flags = rng.next_u32();
        f.width = flags % 3 == 0 ? int(flags >> 8) % 30 : 0;
        f.left = flags & 16u;
        f.plus = flags & 32u;
        f.zero = flags & 64u;
        f.alternate = flags & 128u;
        f.space = (flags >> 20) % 5 == 0;
        char expected[512], got[512];
        int n = std::snprintf(expected, sizeof expected, printf_spec(f, "").c_str(), v);
        int m = format_double(got, sizeof got, v, f);
        ++checked;
        if (n != m || std::strcmp(expected, got) != 0) {
            if (++wrong <= 5)
                MESSAGE(printf_spec(f, "")
                        << " of " << v << ": glibc " << expected << ", ours " << got);
        }
    }
    CHECK(checked > 90000);
    CHECK(wrong == 0);
}

TEST_CASE("format_double: known values, ties to even, NaN and infinity, and cutting") {
    char buf[64];
    NumberFormat g;
    CHECK(format_double(buf, 64, 0.1, g) == 3);
    CHECK(std::string(buf) == "0.1");
    NumberFormat f3;
    f3.conversion = 'f';
    f3.precision = 1;
    (void)format_double(buf, 64, 0.25, f3);  // exactly between 0.2 and 0.3: the even one
    CHECK(std::string(buf) == "0.2");
    (void)format_double(buf, 64, 0.35, f3);  // 0.35 is 0.34999999999999997...
    CHECK(std::string(buf) == "0.3");
    (void)format_double(buf, 64, -1.0 / 0.0, g);
    CHECK(std::string(buf) == "-inf");
    NumberFormat g17;
    g17.precision = 17;
    (void)format_double(buf, 64, 0.1, g17);
    CHECK(std::string(buf) == "0.10000000000000001");
    (void)format_double(buf, 64, 5e-324, g17);
    CHECK(std::string(buf) == "4.9406564584124654e-324");
    char small[5];
    CHECK(format_double(small, 5, 3.14159, g) == 7);  // the full length, as snprintf
    CHECK(std::string(small) == "3.14");
    CHECK(format_double(nullptr, 0, 3.14159, g) == 7);
}

TEST_CASE("format_integer equals glibc printf") {
    Pcg32 rng(13);
    const char conversions[] = "diuxXo";
    int wrong = 0;
    for (int i = 0; i < 50000; ++i) {
        std::uint64_t bits = (std::uint64_t(rng.next_u32()) << 32) | rng.next_u32();
        long long x = (long long)(bits) >> (rng.next_u32() % 64);
        NumberFormat f;
        f.conversion = conversions[rng.next_u32() % 6];
        std::uint32_t flags = rng.next_u32();
        f.precision = flags % 3 == 0 ? int(flags >> 4) % 10 : -1;
        f.width = int(flags >> 12) % 20;
        f.left = flags & 1u << 24;
        f.plus = flags & 1u << 25;
        f.zero = flags & 1u << 26;
        f.alternate = flags & 1u << 27;
        bool is_signed = f.conversion == 'd' || f.conversion == 'i';
        std::uint64_t magnitude = is_signed && x < 0 ? 0u - std::uint64_t(x) : std::uint64_t(x);
        char expected[64], got[64];
        std::snprintf(expected, sizeof expected, printf_spec(f, "ll").c_str(), x);
        (void)format_integer(got, sizeof got, magnitude, is_signed && x < 0, f);
        if (std::strcmp(expected, got) != 0 && ++wrong <= 5)
            MESSAGE(printf_spec(f, "ll") << " of " << x << ": " << expected << " vs " << got);
    }
    CHECK(wrong == 0);
}

TEST_CASE("format_float_round_trip: every float reads back to itself, and short") {
    Pcg32 rng(14);
    int wrong = 0, longer = 0;
    for (int i = 0; i < 200000; ++i) {
        std::uint32_t u = rng.next_u32();
        if (i % 2 == 1) u = (u & 0x807fffffu) | ((100u + u % 56u) << 23);  // 1e-8 .. 1e8
        float v;
        std::memcpy(&v, &u, 4);
        if (v != v) continue;
        char buf[32], g9[32];
        (void)format_float_round_trip(buf, sizeof buf, v);
        float back = std::strtof(buf, nullptr);
        if (std::memcmp(&back, &v, 4) != 0 && ++wrong <= 5)
            MESSAGE(buf << " does not read back to " << v);
        std::snprintf(g9, sizeof g9, "%.9g", double(v));
        if (std::strlen(buf) > std::strlen(g9) + 4) ++longer;  // fixed notation may add zeros
    }
    CHECK(wrong == 0);
    CHECK(longer == 0);
    char buf[32];
    (void)format_float_round_trip(buf, sizeof buf, 0.1f);
    CHECK(std::string(buf) == "0.1");
    (void)format_float_round_trip(buf, sizeof buf, -2.5f);
    CHECK(std::string(buf) == "-2.5");
    (void)format_float_round_trip(buf, sizeof buf, 100.0f);
    CHECK(std::string(buf) == "100");
    (void)format_float_round_trip(buf, sizeof buf, 0.0f);
    CHECK(std::string(buf) == "0");
    (void)format_float_round_trip(buf, sizeof buf, 1e-7f);
    CHECK(std::string(buf) == "1e-07");
    (void)format_float_round_trip(buf, sizeof buf, 3e20f);
    CHECK(std::string(buf) == "3e+20");
}
