// ports/cortex-m/soft_double.cpp — the Arm run-time ABI's double addition, multiplication,
// division and float-to-double conversion for the FPU-less Cortex-M0 from soft_double.hpp (1.2 KB of flash in place of
// libgcc's 4.7 KB; the same bits: make test-mcu runs tests/mcu/soft_double_check.cpp against
// libgcc on the device). Subtraction is the addition of the negated operand
// (soft_float_sub.cpp). Linked on Armv6-M only (mcu.mk): Armv7-M's libgcc has hand-written
// assembly for these. `used`: the compiler calls these after link-time optimisation has run.
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
__attribute__((used)) double __aeabi_dadd(double a, double b) {
    return from(sd::add(bits(a), bits(b)));
}
__attribute__((used)) double __aeabi_dmul(double a, double b) {
    return from(sd::mul(bits(a), bits(b)));
}
__attribute__((used)) double __aeabi_ddiv(double a, double b) {
    return from(sd::div(bits(a), bits(b)));
}
__attribute__((used)) double __aeabi_f2d(float f) {
    sd::u32 u;
    std::memcpy(&u, &f, sizeof u);
    return from(sd::from_float(u));
}
}
