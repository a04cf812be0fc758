// core/status: a small value that formats its message on demand with the library's own
// formatter; every printf conversion the library uses, cutting, numbers that survive.
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>

#include <doctest/doctest.h>
#include "shitsukan/core/status.hpp"

using namespace shitsukan;

// The size the header states: format pointer, code, used bytes, narrow bits, arguments.
static_assert(sizeof(Status) == sizeof(void*) + 8 + Status::kArgumentBytes, "padding crept in");
#if defined(SHITSUKAN_SMALL_DEVICE)
static_assert(sizeof(void*) != 4 || sizeof(Status) == 92, "sizeof(Status) on a 32-bit device");
#else
static_assert(sizeof(void*) != 8 || sizeof(Status) == 200, "sizeof(Status) on a 64-bit host");
#endif

#define EXPECT_SAME_AS_PRINTF(...)                                            \
    do {                                                                      \
        char expected_[400];                                                  \
        std::snprintf(expected_, sizeof expected_, __VA_ARGS__);              \
        Status s_ = Status::error(StatusCode::invalid_argument, __VA_ARGS__); \
        CHECK(std::string(s_.message()) == std::string(expected_));           \
    } while (0)

TEST_CASE("Status messages equal printf's for every conversion the library uses") {
    int i = -42;
    unsigned u = 4000000000u;
    // Near the ends of long and unsigned long, whatever their width (32 bits on WASM).
    long l = -(std::numeric_limits<long>::max() / 7);
    unsigned long ul = std::numeric_limits<unsigned long>::max() - 12345u;
    long long ll = -9000000000000000000LL;
    unsigned long long ull = 1234ULL;
    std::size_t z = 77;
    float f = 0.3f;
    double d = 0.1;
    const char* s = "stripe";
    EXPECT_SAME_AS_PRINTF("%d %i %u %x %X %o %c", i, i, u, u, u, u, 'q');
    EXPECT_SAME_AS_PRINTF("%ld %lu %lld %llu %zu", l, ul, ll, ull, z);
    EXPECT_SAME_AS_PRINTF("%hhd %hd %hu %5d|%-5d|%05d|%+d|% d", 300, 70000, 70000, i, i, i, 7, 7);
    EXPECT_SAME_AS_PRINTF("%g %g %.3g %.9g %.17g", double(f), d, d, double(f), d);
    EXPECT_SAME_AS_PRINTF("%e %E %G %f %.0f %.6f %F", d, 1e300, 1e-300, 2.5, 2.5, -1.0 / 3.0, 1e20);
    EXPECT_SAME_AS_PRINTF("%g %g %g %g", 1.0 / 0.0, -1.0 / 0.0, 0.0, -0.0);
    EXPECT_SAME_AS_PRINTF("%s: %.3s, %10s|%-10s|", s, s, s, s);
    EXPECT_SAME_AS_PRINTF("%*d|%-*d|%.*f|%.*s", 6, 42, 6, 42, 2, 3.14159, 2, s);
    EXPECT_SAME_AS_PRINTF("100%% sure, %s", "yes");
    EXPECT_SAME_AS_PRINTF("%s", static_cast<const char*>("no conversions at all"));
    // 9 floats and an int, as geom/isotropic_remesh.cpp reports a degenerate triangle.
    EXPECT_SAME_AS_PRINTF("triangle %d: (%g, %g, %g), (%g, %g, %g), (%g, %g, %g)", 3, 0.1f, 0.2f,
                          0.3f, 1e-7f, 2.5f, -3.f, 1e30f, 7.f, 8.f);
    // 6 doubles at full precision, as geom/voronoi.cpp does.
    EXPECT_SAME_AS_PRINTF("(%.17g, %.17g), (%.17g, %.17g), (%.17g, %.17g)", 0.1, 0.2, 0.3,
                          1.0 / 3.0, 2.0 / 3.0, 1e-16);
}

// %p on its own: the library writes a null pointer as glibc does, "(nil)" (musl, as in the
// WASM build, prints "0"), so this case is glibc's text, not a rule of the format.
TEST_CASE("Status messages equal printf's for %p (glibc's pointer text)") {
    int i = -42;
    EXPECT_SAME_AS_PRINTF("%p %p", static_cast<void*>(&i), static_cast<void*>(nullptr));
}

TEST_CASE("Status: long strings are cut with ..., numbers after them survive") {
    std::string longtext(500, 'x');
    Status t = Status::error(StatusCode::invalid_argument, "%s", longtext.c_str());
    std::string m = t.message();
    CHECK(m.size() == std::size_t(Status::kArgumentBytes - 1));
    CHECK(m.substr(m.size() - 3) == "...");
    Status n = Status::error(StatusCode::io_error, "cannot open %s (R = %d, beta %g)",
                             longtext.c_str(), 7, 2.25);
    char whole_n[400];
    (void)n.format_message(whole_n, sizeof whole_n);
    std::string mn = whole_n;
    CHECK(mn.find("...") != std::string::npos);
    CHECK(mn.substr(mn.size() - 22) == "... (R = 7, beta 2.25)");
    // Two strings share the room fairly: a short one is kept whole.
    Status two = Status::error(StatusCode::io_error, "%s: %s", "short", longtext.c_str());
    CHECK(std::string(two.message()).rfind("short: xxx", 0) == 0);
    // More 8-byte numbers than kArgumentBytes holds: the rest prints as '?'.
    Status many = Status::error(
        StatusCode::invalid_argument,
        "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g "
        "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %d",
        0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1,
        0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 5);
    char whole[800];
    const int kept = Status::kArgumentBytes / 8;
    CHECK(many.format_message(whole, sizeof whole) == kept * 20 + 2 * (24 - kept) + 1);
    std::string mm = whole;
    CHECK(mm.substr(mm.size() - 4) == " ? ?");
    CHECK(mm.rfind("0.10000000000000001 ", 0) == 0);
}

TEST_CASE("Status: the message is cut at the buffer, format_message returns the full length") {
    Status s = Status::error(StatusCode::too_large, "lattice needs %llu bytes", 1234ULL);
    char small[10];
    CHECK(s.format_message(small, sizeof small) == 24);
    CHECK(std::string(small) == "lattice n");
    CHECK(s.format_message(nullptr, 0) == 24);
    // A message longer than kMessageCapacity (numbers make it long) is cut by message().
    Status w = Status::error(StatusCode::invalid_argument, "%300d|", 1);
    CHECK(std::strlen(w.message()) == std::size_t(Status::kMessageCapacity - 1));
    // message() uses kMessageSlots buffers in turn: earlier pointers stay valid.
    Status a = Status::error(StatusCode::invalid_argument, "a %d", 1);
    Status b = Status::error(StatusCode::invalid_argument, "b %d", 2);
    const char* ma = a.message();
    const char* mb = b.message();
    CHECK(std::string(ma) == "a 1");
    CHECK(std::string(mb) == "b 2");
    // Copies are plain values; ok is "ok"; an ok code becomes invalid_argument.
    Status c = b;
    CHECK(std::string(c.message()) == "b 2");
    CHECK(std::string(Status::success().message()) == "ok");
    CHECK(Status::error(StatusCode::ok, "x").code() == StatusCode::invalid_argument);
}
