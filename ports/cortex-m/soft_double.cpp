// ports/cortex-m/soft_double.cpp — double addition, multiplication, division and float-to-double
// conversion for the FPU-less cores from soft_double.hpp (soft_float_abi.hpp names the entry
// points: the Arm run-time ABI's on the Cortex-M0, libgcc's on RV32IMAC). 1.2-1.5 KB of flash
// in place of libgcc's 4.0-4.7 KB, the same bits: make test-mcu runs
// tests/mcu/soft_double_check.cpp against libgcc on both devices. Subtraction is the addition
// of the negated operand (soft_float_sub.cpp). On RV32 also long double (binary128) and
// unsigned 64-bit integers to double. Linked on Armv6-M and RV32 only (mcu.mk): Armv7-M's
// libgcc has hand-written assembly for these. `used`: the compiler calls these after
// link-time optimisation has run.
#include "soft_double.hpp"
#include "soft_float_abi.hpp"

namespace {
namespace sd = shitsukan::port::soft_double;
using shitsukan::port::double_bits;
using shitsukan::port::double_from_bits;
}  // namespace

extern "C" {
__attribute__((used)) double SOFT_DADD(double a, double b) {
    return double_from_bits(sd::add(double_bits(a), double_bits(b)));
}
__attribute__((used)) double SOFT_DMUL(double a, double b) {
    return double_from_bits(sd::mul(double_bits(a), double_bits(b)));
}
__attribute__((used)) double SOFT_DDIV(double a, double b) {
    return double_from_bits(sd::div(double_bits(a), double_bits(b)));
}
__attribute__((used)) double SOFT_F2D(float f) {
    return double_from_bits(sd::from_float(shitsukan::port::float_bits(f)));
}
#if defined(__riscv)
// long double (binary128 on RV32: the Status formatter reads %Lg arguments) to double, rounded
// once: libgcc's is 594 bytes.
__attribute__((used)) double __trunctfdf2(long double q) {
    sd::u64 w[2];  // little-endian: w[1] holds the sign, the 15-bit exponent, 48 fraction bits
    static_assert(sizeof q == sizeof w, "binary128 long double");
    std::memcpy(w, &q, sizeof w);
    return double_from_bits(sd::from_quad(w[1], w[0]));
}
// libgcc's is 330 bytes and pulls a 256-byte count-leading-zeros table
__attribute__((used)) double __floatundidf(unsigned long long n) {
    return double_from_bits(sd::from_unsigned(n));
}
#endif
}
