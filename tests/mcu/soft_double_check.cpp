// tests/mcu/soft_double_check.cpp — checks ports/cortex-m/soft_double.hpp (and, on the
// Cortex-M0, signed_divide.hpp) against the device's libgcc, bit for bit (NaNs included), on
// the Cortex-M0 and the RV32 under QEMU (run by `make test-mcu`; built WITHOUT the port's
// replacements of libgcc's routines, so `x + y` and `a / b` here are libgcc's). Operands: special values crossed with each other, then
// pseudo-random pairs biased to cancellation, subnormals, underflow and overflow.
#include <cstdint>
#include <cstring>

#include "semihosting.hpp"
#include "soft_double.hpp"
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

long g_bad = 0, g_count = 0;

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
#if defined(__ARM_ARCH_6M__)
        const std::int32_t ia = std::int32_t(a >> (a % 32)), ib = std::int32_t(b >> (b % 40));
        check_divide(ia, ib);
        check_divide(ia, std::int32_t(i % 19) - 9);
        check_divide(INT32_MIN, ib);
#endif
    }
    put(g_bad == 0 ? "soft-double: all " : "soft-double: MISMATCHES in ");
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
