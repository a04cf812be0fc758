// ports/riscv/soft_double.cpp — libgcc's double addition, multiplication and division for
// RV32IMAC without D, from ../cortex-m/soft_double.hpp (the same bits as libgcc: make test-mcu
// runs tests/mcu/soft_double_check.cpp against it on the device). Subtraction is the addition
// of the negated operand (soft_float_sub.cpp). `used`: the compiler calls these after
// link-time optimisation has run.
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
}
