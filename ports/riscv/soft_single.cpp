// ports/riscv/soft_single.cpp — libgcc's float addition, multiplication and division for
// RV32IMAC without F, from ../cortex-m/soft_single.hpp (in place of libgcc's 2.0 KB; the same
// bits: make test-mcu runs tests/mcu/soft_double_check.cpp against libgcc on the device).
// Subtraction is the addition of the negated operand (../cortex-m/soft_float_sub.cpp). `used`:
// the compiler calls these after link-time optimisation has run.
#include "soft_float_abi.hpp"
#include "soft_single.hpp"

namespace {
namespace ss = shitsukan::port::soft_single;
using shitsukan::port::float_bits;
using shitsukan::port::float_from_bits;
}  // namespace

extern "C" {
__attribute__((used)) float __addsf3(float a, float b) {
    return float_from_bits(ss::add(float_bits(a), float_bits(b)));
}
__attribute__((used)) float __mulsf3(float a, float b) {
    return float_from_bits(ss::mul(float_bits(a), float_bits(b)));
}
__attribute__((used)) float __divsf3(float a, float b) {
    return float_from_bits(ss::div(float_bits(a), float_bits(b)));
}
}
