// ports/riscv/soft_single.cpp — libgcc's float addition, multiplication and division for
// RV32IMAC without F, from ../cortex-m/soft_single.hpp (in place of libgcc's 2.0 KB; the same
// bits: make test-mcu runs tests/mcu/soft_double_check.cpp against libgcc on the device).
// Subtraction is the addition of the negated operand (soft_float_sub.cpp). `used`: the
// compiler calls these after link-time optimisation has run.
#include <cstring>

#include "soft_single.hpp"

namespace {
namespace ss = shitsukan::port::soft_single;
ss::u32 bits(float f) {
    ss::u32 u;
    std::memcpy(&u, &f, sizeof u);
    return u;
}
float from(ss::u32 u) {
    float f;
    std::memcpy(&f, &u, sizeof f);
    return f;
}
}  // namespace

extern "C" {
__attribute__((used)) float __addsf3(float a, float b) {
    return from(ss::add(bits(a), bits(b)));
}
__attribute__((used)) float __mulsf3(float a, float b) {
    return from(ss::mul(bits(a), bits(b)));
}
__attribute__((used)) float __divsf3(float a, float b) {
    return from(ss::div(bits(a), bits(b)));
}
}
