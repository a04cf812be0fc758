// tests/mcu/soft_double_check.cpp — checks ports/cortex-m/soft_double.hpp, soft_single.hpp
// (and, on the Cortex-M0, signed_divide.hpp) against the device's libgcc, bit for bit (NaNs included), on
// the Cortex-M0 and the RV32 under QEMU (run by `make test-mcu`; built WITHOUT the port's
// replacements of libgcc's routines, so `x + y` and `a / b` here are libgcc's). Operands: special values crossed with each other, then
// pseudo-random pairs biased to cancellation, subnormals, underflow and overflow.
#include <cstdint>
#include <cstring>

#include "semihosting.hpp"
#include "soft_double.hpp"
#include "soft_single.hpp"
#if defined(__ARM_ARCH_6M__)
#include "signed_divide.hpp"
#endif

namespace sd = shitsukan::port::soft_double;
using sd::u64;

namespace {
double from(u64 u) {
    double d;
    std::memcpy(&d, &u, sizeof d);
    return d;
}
u64 bits(double d) {
    u64 u;
    std::memcpy(&u, &d, sizeof u);
    return u;
}
void put(const char* s) {
    int n = 0;
    while (s[n]) ++n;
    shitsukan::port::semihosting_write(s, n);
}
void put_hex(u64 v) {
    char text[17];
    for (int i = 0; i < 16; ++i) text[i] = "0123456789abcdef"[(v >> (60 - 4 * i)) & 15u];
    text[16] = 0;
    put(text);
}
u64 g_state = 0x9e3779b97f4a7c15ull;
u64 next() {  // xorshift64*
    g_state ^= g_state >> 12;
    g_state ^= g_state << 25;
    g_state ^= g_state >> 27;
    return g_state * 0x2545f4914f6cdd1dull;
}
u64 with_exponent(u64 v, unsigned e) { return (v & ~(u64(0x7ff) << 52)) | (u64(e & 0x7ffu) << 52); }
// the marble firmware's uses of the operators, on the same operands
__attribute__((noinline)) double lib_add(double a, double b) { return a + b; }
__attribute__((noinline)) double lib_mul(double a, double b) { return a * b; }
__attribute__((noinline)) double lib_div(double a, double b) { return a / b; }
__attribute__((noinline)) double lib_u64_to_double(u64 n) { return double(n); }
__attribute__((noinline)) double lib_float_to_double(float f) { return double(f); }
#if defined(__riscv)
__attribute__((noinline)) double lib_quad_to_double(long double q) { return double(q); }
#endif

long g_bad = 0, g_count = 0;

namespace ss = shitsukan::port::soft_single;
float from32(ss::u32 u) {
    float f;
    std::memcpy(&f, &u, sizeof f);
    return f;
}
ss::u32 bits32(float f) {
    ss::u32 u;
    std::memcpy(&u, &f, sizeof u);
    return u;
}
__attribute__((noinline)) float lib_fadd(float a, float b) { return a + b; }
__attribute__((noinline)) float lib_fmul(float a, float b) { return a * b; }
__attribute__((noinline)) float lib_fdiv(float a, float b) { return a / b; }
void check_single(ss::u32 a, ss::u32 b) {
    const ss::u32 mine[3] = {ss::add(a, b), ss::mul(a, b), ss::div(a, b)};
    const ss::u32 theirs[3] = {bits32(lib_fadd(from32(a), from32(b))),
                               bits32(lib_fmul(from32(a), from32(b))),
                               bits32(lib_fdiv(from32(a), from32(b)))};
    for (int k = 0; k < 3; ++k) {
        ++g_count;
        if (mine[k] != theirs[k] && g_bad++ < 8) {
            put("soft-single: op ");
            put(k == 0 ? "add" : k == 1 ? "mul" : "div");
            put(" a ");
            put_hex(a);
            put(" b ");
            put_hex(b);
            put(" soft_single ");
            put_hex(mine[k]);
            put(" libgcc ");
            put_hex(theirs[k]);
            put("\n");
        }
    }
}

#if defined(__ARM_ARCH_6M__)
__attribute__((noinline)) std::int32_t lib_idiv(std::int32_t a, std::int32_t b) { return a / b; }
__attribute__((noinline)) std::int32_t lib_imod(std::int32_t a, std::int32_t b) { return a % b; }
void check_divide(std::int32_t a, std::int32_t b) {
    if (b == 0 || (a == INT32_MIN && b == -1)) return;  // undefined in C++
    const std::int32_t q = shitsukan::port::signed_quotient(a, b);
    g_count += 2;
    if (q != lib_idiv(a, b) || shitsukan::port::signed_remainder(a, b, q) != lib_imod(a, b)) {
        if (g_bad++ < 8) put("signed divide: a mismatch\n");
    }
}
#endif
void check(u64 a, u64 b) {
    const u64 mine[3] = {sd::add(a, b), sd::mul(a, b), sd::div(a, b)};
    const u64 theirs[3] = {bits(lib_add(from(a), from(b))), bits(lib_mul(from(a), from(b))),
                           bits(lib_div(from(a), from(b)))};
    for (int k = 0; k < 3; ++k) {
        ++g_count;
        if (mine[k] == theirs[k]) continue;
        if (g_bad++ < 8) {
            put("soft-double: op ");
            put(k == 0 ? "add" : k == 1 ? "mul" : "div");
            put(" a ");
            put_hex(a);
            put(" b ");
            put_hex(b);
            put(" soft_double ");
            put_hex(mine[k]);
            put(" libgcc ");
            put_hex(theirs[k]);
            put("\n");
        }
    }
}
}  // namespace

int main() {
    const u64 special[] = {0, 1, sd::kHidden - 1, sd::kHidden, sd::kHidden + 1,
                           0x3ff0000000000000ull, 0x3ff0000000000001ull, 0x3fefffffffffffffull,
                           0x7fefffffffffffffull, 0x7fe0000000000000ull, sd::kInf,
                           0x7ff8000000000000ull, 0x7ff0000000000001ull, 0x7ffc000000000123ull,
                           0x0020000000000000ull, 0x3cb0000000000000ull};
    const ss::u32 special32[] = {0, 1, 0x007fffffu, 0x00800000u, 0x3f800000u, 0x3f800001u,
                                 0x3f7fffffu, 0x7f7fffffu, 0x7f800000u, 0x7fc00000u, 0x7f800001u,
                                 0x7fe00123u, 0x33800000u};
    for (ss::u32 a : special32)
        for (ss::u32 b : special32)
            for (int s = 0; s < 4; ++s)
                check_single(a ^ ((s & 1) ? ss::kSign : 0), b ^ ((s & 2) ? ss::kSign : 0));
    for (u64 a : special)
        for (u64 b : special)
            for (int s = 0; s < 4; ++s)
                check(a ^ ((s & 1) ? sd::kSign : 0), b ^ ((s & 2) ? sd::kSign : 0));
    for (long i = 0; i < 40000; ++i) {
        u64 a = next(), b = next();
        switch (i % 6) {
            case 1: b = (a & ~u64(0xfffff)) ^ (b & 0xfffff); break;
            case 2: a = with_exponent(a, unsigned(b % 3)); break;
            case 3: a = with_exponent(a, 1003 + unsigned(a % 40)), b = with_exponent(b, 1003 + unsigned(b % 40)); break;
            case 4: a = with_exponent(a, unsigned(a % 80)), b = with_exponent(b, 980 + unsigned(b % 80)); break;
            case 5: a = with_exponent(a, 2000 + unsigned(a % 47)), b = with_exponent(b, 1000 + unsigned(b % 60)); break;
            default: break;
        }
        check(a, b);
        check(b, a);
        const u64 integers[4] = {a, a >> (b % 64), a & ~u64(0x3ff), a >> 11};  // ties, exact
        for (const u64 n : integers) {
            ++g_count;
            if (sd::from_unsigned(n) != bits(lib_u64_to_double(n)) && g_bad++ < 8)
                put("soft-double: unsigned 64-bit to double: a mismatch\n");
        }
#if defined(__riscv)
        {  // binary128 (RV32's long double) to double: the Status formatter's %Lg
            u64 w[2] = {b, (a & ~(u64(0x7fff) << 48)) | (u64(15360 + a % 2048) << 48)};
            if (i % 7 == 0) w[1] = a;  // any exponent: overflow, subnormal
            if (i % 11 == 0) w[1] |= u64(0x7fff) << 48;  // NaN (and inf below)
            if (i % 13 == 0) w[1] &= ~(u64(0x7fff) << 48);  // subnormal
            if (i % 17 == 0) w[0] = 0, w[1] &= ~((u64(1) << 48) - 1);  // inf, zero, powers of 2
            long double q;
            std::memcpy(&q, w, sizeof q);
            ++g_count;
            if (sd::from_quad(w[1], w[0]) != bits(lib_quad_to_double(q)) && g_bad++ < 8) {
                put("soft-double: binary128 ");
                put_hex(w[1]);
                put_hex(w[0]);
                put(" to double: ");
                put_hex(sd::from_quad(w[1], w[0]));
                put(" libgcc ");
                put_hex(bits(lib_quad_to_double(q)));
                put("\n");
            }
        }
#endif
        const sd::u32 floats[3] = {sd::u32(a), sd::u32(b) & 0x80ffffffu, sd::u32(b) | 0x7f800000u};
        for (const sd::u32 f : floats) {  // any, tiny and subnormal, inf and NaN
            ++g_count;
            if (sd::from_float(f) != bits(lib_float_to_double(from32(f))) && g_bad++ < 8) {
                put("soft-double: float to double of ");
                put_hex(f);
                put(": ");
                put_hex(sd::from_float(f));
                put(" libgcc ");
                put_hex(bits(lib_float_to_double(from32(f))));
                put("\n");
            }
        }
        // the float ones: the two halves, and the top halves' exponents moved like the doubles'
        const ss::u32 fa = ss::u32(a), fb = ss::u32(b >> 32);
        const ss::u32 ga = (ss::u32(a >> 32) & 0x807fffffu) | (ss::u32(a % 254) << 23);
        check_single(fa, fb);
        check_single(fb, fa);
        check_single(ga, fb & 0x81ffffffu);
        check_single(fa & 0x80ffffffu, ga);
#if defined(__ARM_ARCH_6M__)
        const std::int32_t ia = std::int32_t(a >> (a % 32)), ib = std::int32_t(b >> (b % 40));
        check_divide(ia, ib);
        check_divide(ia, std::int32_t(i % 19) - 9);
        check_divide(INT32_MIN, ib);
#endif
    }
    put(g_bad == 0 ? "soft-float: all " : "soft-float: MISMATCHES in ");
    char digits[12];
    int n = 0;
    for (unsigned long v = (unsigned long)g_count; v != 0 || n == 0; v /= 10) digits[n++] = char('0' + v % 10);
    while (n > 0) {
        const char c[2] = {digits[--n], 0};
        put(c);
    }
    put(" results equal libgcc's\n");
    return g_bad == 0 ? 0 : 1;
}
