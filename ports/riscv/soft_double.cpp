// ports/riscv/soft_double.cpp — libgcc's double addition, multiplication and division, and
// the conversions to double, for RV32IMAC without D, from ../cortex-m/soft_double.hpp (the
// same bits as libgcc: make test-mcu runs tests/mcu/soft_double_check.cpp against it on the
// device). Subtraction is the addition of the negated operand (soft_float_sub.cpp). `used`:
// the compiler calls these after link-time optimisation has run.
#include <cstring>

#include "soft_double.hpp"

namespace {
namespace sd = shitsukan::port::soft_double;
sd::u64 bits(double d) {
    sd::u64 u;
    std::memcpy(&u, &d, sizeof u);
    return u;
}
double from(sd::u64 u) {
    double d;
    std::memcpy(&d, &u, sizeof d);
    return d;
}
}  // namespace

extern "C" {
__attribute__((used)) double __adddf3(double a, double b) {
    return from(sd::add(bits(a), bits(b)));
}
__attribute__((used)) double __muldf3(double a, double b) {
    return from(sd::mul(bits(a), bits(b)));
}
__attribute__((used)) double __divdf3(double a, double b) {
    return from(sd::div(bits(a), bits(b)));
}
__attribute__((used)) double __extendsfdf2(float f) {
    sd::u32 u;
    std::memcpy(&u, &f, sizeof u);
    return from(sd::from_float(u));
}
// long double (binary128 on RV32: the Status formatter reads %Lg arguments) to double, rounded
// once: libgcc's is 594 bytes.
__attribute__((used)) double __trunctfdf2(long double q) {
    sd::u64 w[2];  // little-endian: w[1] holds the sign, the 15-bit exponent, 48 fraction bits
    static_assert(sizeof q == sizeof w, "binary128 long double");
    std::memcpy(w, &q, sizeof w);
    return from(sd::from_quad(w[1], w[0]));
}
// libgcc's is 330 bytes and pulls a 256-byte count-leading-zeros table
__attribute__((used)) double __floatundidf(unsigned long long n) {
    return from(sd::from_unsigned(n));
}
}
